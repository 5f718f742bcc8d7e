# The programs of docs/RECIPES.md (docs/recipes/*.c): each is built with the project's warnings
# and run; it checks what it prints and exits 1 when a check fails, so a recipe that stops
# working (or stops saying the truth) fails the suite.
foreach(_recipe pool_shot lockstep)
  add_executable(recipe_${_recipe} ${PROJECT_SOURCE_DIR}/docs/recipes/${_recipe}.c)
  target_link_libraries(recipe_${_recipe} PRIVATE circlecollide_static cc_warnings)
  if(NOT MSVC)
    target_link_libraries(recipe_${_recipe} PRIVATE m)
  endif()
  add_test(NAME recipe_${_recipe} COMMAND recipe_${_recipe})
  set_tests_properties(recipe_${_recipe} PROPERTIES LABELS "recipes")
endforeach()

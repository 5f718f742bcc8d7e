# The programs of docs/RECIPES.md (docs/recipes/*.c): each is built with the project's warnings
# and run; it checks what it prints and exits 1 when a check fails, so a recipe that stops
# working (or stops saying the truth) fails the suite.
foreach(_recipe pool_shot lockstep air_hockey newtons_cradle bullet mcu_loop)
  add_executable(recipe_${_recipe} ${PROJECT_SOURCE_DIR}/docs/recipes/${_recipe}.c)
  target_link_libraries(recipe_${_recipe} PRIVATE circlecollide_static cc_warnings)
  # mcu_loop is the microcontroller's: float only (an implicit promotion to double is an error)
  # and no libm of its own (linked without it; the library's float path brings what it needs)
  if(_recipe STREQUAL "mcu_loop")
    if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
      target_compile_options(recipe_${_recipe} PRIVATE -Wdouble-promotion)
    endif()
  elseif(NOT MSVC)
    target_link_libraries(recipe_${_recipe} PRIVATE m)
  endif()
  add_test(NAME recipe_${_recipe} COMMAND recipe_${_recipe})
  set_tests_properties(recipe_${_recipe} PROPERTIES LABELS "recipes")
endforeach()

# A program built against the 1.0 header runs unchanged against this library (the 1.1 promise):
# tests/compat/program_1_0.c is built against the 1.0 header kept in tests/compat/v1_0/ (a copy
# of include/circlecollide.h as released at 1.0.0) and against today's header, both linked to
# this build's shared library, and each must print the digest that the 1.0.0 library printed for
# the same program (every result bit, every return code, every callback; recorded below from a
# build of the 1.0.0 sources). abi_abidiff checks the symbols and types; this checks behaviour:
# defaults, the reading of a 1.0-sized def, results to the bit. Host builds only: the digest is
# x86-64's (a cross build's results may round differently, and it has no shared library to swap).
# 1.2 changed one thing on purpose (API.md 1.2 lets a world's results differ from an earlier
# version's): walls keep their side in SWEPT and DISCRETE (src/world/sides.c), which gives the
# program's SWEPT and DISCRETE walls 16 more contacts. 1.0.0 printed "digest f51fc4d23ce097ea, 911
# contacts", and so does this library with sides.c's pass made to do nothing (checked when the
# digest below was taken): nothing else differs.
set(CC_COMPAT_1_0_DIGEST "digest 2209c9000356546c, 927 contacts")
if(TARGET circlecollide AND NOT CMAKE_CROSSCOMPILING AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
  foreach(_h 1_0 1_1)
    add_executable(compat_program_${_h} compat/program_1_0.c)
    target_link_libraries(compat_program_${_h} PRIVATE circlecollide cc_warnings)
    if(UNIX)
      target_link_libraries(compat_program_${_h} PRIVATE m)
    endif()
  endforeach()
  # BEFORE: the 1.0 header must win over the include directory the library target brings.
  target_include_directories(compat_program_1_0 BEFORE PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/compat/v1_0)
  foreach(_h 1_0 1_1)
    add_test(NAME compat_program_${_h} COMMAND compat_program_${_h})
    set_tests_properties(compat_program_${_h} PROPERTIES LABELS "abi;compat"
      PASS_REGULAR_EXPRESSION "${CC_COMPAT_1_0_DIGEST}")
  endforeach()
  set_tests_properties(compat_program_1_0 PROPERTIES PASS_REGULAR_EXPRESSION "header 1\\.0, .*${CC_COMPAT_1_0_DIGEST}")
endif()

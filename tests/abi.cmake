# ABI checks of the shared library (ELF platforms): the exported symbols are exactly the header's
# CC_API functions with the right version node and SONAME, and abidiff finds no change against
# the committed baseline in abi/ (see abi/README.md). Both scripts need Python 3 and readelf;
# abi_abidiff reports itself skipped without abidiff or without debug information.
if(TARGET circlecollide AND CMAKE_SYSTEM_NAME STREQUAL "Linux")
  find_package(Python3 COMPONENTS Interpreter QUIET)
  find_program(CC_READELF readelf)
  if(Python3_Interpreter_FOUND AND CC_READELF)
    add_test(NAME abi_symbols COMMAND Python3::Interpreter
      ${CMAKE_CURRENT_SOURCE_DIR}/abi/check_symbols.py ${PROJECT_SOURCE_DIR}/include/circlecollide.h
      $<TARGET_FILE:circlecollide>)
    add_test(NAME abi_abidiff COMMAND Python3::Interpreter
      ${CMAKE_CURRENT_SOURCE_DIR}/abi/check_abidiff.py ${PROJECT_SOURCE_DIR}
      $<TARGET_FILE:circlecollide>)
    set_tests_properties(abi_symbols abi_abidiff PROPERTIES LABELS "abi")
    set_tests_properties(abi_abidiff PROPERTIES SKIP_RETURN_CODE 77)
  else()
    message(STATUS "circlecollide: Python 3 or readelf missing: the ABI tests are left out")
  endif()
endif()

# Infrastructure tests: the test runner itself, the public header under strict C and C++
# compilers, and a consumer built against an installed copy (CMake package and pkg-config).

# ---- The runner (ours or the real Unity) behaves like Unity ------------------------------------
add_executable(unity_runner_selftest runner/selftest.c)
target_link_libraries(unity_runner_selftest PRIVATE cc_unity cc_warnings)
if(UNIX)
  target_link_libraries(unity_runner_selftest PRIVATE m)
endif()
add_test(NAME unity_runner_selftest COMMAND ${CMAKE_COMMAND}
  -DEXE=$<TARGET_FILE:unity_runner_selftest> -DSRC=${CMAKE_CURRENT_SOURCE_DIR}/runner/selftest.c
  -P ${CMAKE_CURRENT_SOURCE_DIR}/runner/check_selftest.cmake)
set_tests_properties(unity_runner_selftest PROPERTIES LABELS "packaging")

# ---- The public header as C99/C11/C17 and as C++98 up to the newest C++ -----------------------
# Warnings beyond the project's own set, always as errors: the header lands in users' builds.
set(CC_HEADER_C_WARNINGS -Wall -Wextra -Wpedantic -Werror -Wshadow -Wundef -Wconversion
  -Wsign-conversion -Wcast-qual -Wstrict-prototypes -Wmissing-prototypes -Wredundant-decls
  -Wdouble-promotion -Wc++-compat)
set(CC_HEADER_CXX_WARNINGS -Wall -Wextra -Wpedantic -Werror -Wshadow -Wundef -Wconversion
  -Wsign-conversion -Wcast-qual -Wold-style-cast -Wzero-as-null-pointer-constant
  -Wredundant-decls -Wdouble-promotion)

if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
  foreach(_std 99 11 17)
    add_library(cc_header_c${_std} OBJECT compile/header_c.c)
    set_target_properties(cc_header_c${_std} PROPERTIES C_STANDARD ${_std} C_STANDARD_REQUIRED ON
      C_EXTENSIONS OFF)
    target_include_directories(cc_header_c${_std} PRIVATE ${PROJECT_SOURCE_DIR}/include)
    target_compile_options(cc_header_c${_std} PRIVATE ${CC_HEADER_C_WARNINGS})
  endforeach()

  include(CheckLanguage)
  check_language(CXX)
  if(CMAKE_CXX_COMPILER)
    enable_language(CXX)
    set(_cc_cxx_stds 98 11 17)
    foreach(_std 20 23)
      if("cxx_std_${_std}" IN_LIST CMAKE_CXX_COMPILE_FEATURES)
        list(APPEND _cc_cxx_stds ${_std})
      endif()
    endforeach()
    foreach(_std IN LISTS _cc_cxx_stds)
      set(_t header_cxx${_std})
      add_executable(${_t} compile/header_cxx.cpp $<TARGET_OBJECTS:cc_header_c99>)
      set_target_properties(${_t} PROPERTIES CXX_STANDARD ${_std} CXX_STANDARD_REQUIRED ON
        CXX_EXTENSIONS OFF)
      target_compile_options(${_t} PRIVATE ${CC_HEADER_CXX_WARNINGS})
      if(TARGET circlecollide)
        target_link_libraries(${_t} PRIVATE circlecollide)
      else()
        target_link_libraries(${_t} PRIVATE circlecollide_static)
      endif()
      add_test(NAME ${_t} COMMAND ${_t})
      set_tests_properties(${_t} PROPERTIES LABELS "packaging")
    endforeach()
  else()
    message(STATUS "circlecollide: no C++ compiler: the header's C++ compile tests are left out")
  endif()
endif()

# ---- A consumer of the installed package ------------------------------------------------------
# Installs this build into a prefix inside the build folder, then builds tests/consumer with
# find_package(circlecollide) (shared and static) and, when pkg-config exists, with the
# compiler and `pkg-config --cflags --libs circlecollide` alone, and runs every program.
find_program(CC_PKG_CONFIG pkg-config)
set(_cc_consumer_flags "")
if(CC_SANITIZE)
  set(_cc_consumer_flags "-fsanitize=address,undefined -fno-sanitize-recover=all")
endif()
add_test(NAME package_consumer COMMAND ${CMAKE_COMMAND}
  -DBUILD_DIR=${PROJECT_BINARY_DIR}
  -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/package_consumer
  -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer
  -DGENERATOR=${CMAKE_GENERATOR}
  -DC_COMPILER=${CMAKE_C_COMPILER}
  -DC_FLAGS=${_cc_consumer_flags}
  -DCONFIG=$<CONFIG>
  -DSHARED=$<TARGET_EXISTS:circlecollide>
  -DPKG_CONFIG=${CC_PKG_CONFIG}
  -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/run.cmake)
set_tests_properties(package_consumer PROPERTIES LABELS "packaging" TIMEOUT 300
  RUN_SERIAL ON)

# ---- The README's quick-start example compiles, runs and prints what the README says ----------
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/README.md)
file(READ ${PROJECT_SOURCE_DIR}/README.md _cc_readme)
string(REGEX MATCH "\n```c\n(.*)```\n\nIt prints `([^`]*)`" _cc_m "${_cc_readme}")
if(_cc_m)
  # the example's own text, up to its closing fence (the regex above is greedy)
  string(FIND "${CMAKE_MATCH_1}" "\n```" _cc_end)
  string(SUBSTRING "${CMAKE_MATCH_1}" 0 ${_cc_end} _cc_example)
  set(_cc_expected "${CMAKE_MATCH_2}")
  file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/readme_example.c CONTENT "${_cc_example}\n"
    @ONLY)
  add_executable(readme_example ${CMAKE_CURRENT_BINARY_DIR}/readme_example.c)
  target_link_libraries(readme_example PRIVATE circlecollide_static cc_warnings)
  add_test(NAME readme_example COMMAND readme_example)
  string(REGEX REPLACE "([][.*+?^$()|\\])" "\\\\\\1" _cc_expected_re "${_cc_expected}")
  set_tests_properties(readme_example PROPERTIES LABELS "packaging"
    PASS_REGULAR_EXPRESSION "^${_cc_expected_re}\n$")
else()
  message(FATAL_ERROR "README.md: no ```c quick-start block followed by \"It prints `...`\"")
endif()

# Fuzzing (included by tests/numerics.cmake). Always: test_fuzz_replay runs every file of
# tests/fuzz/corpus/ through the fuzz checks, with the ordinary compiler. With clang and
# -DCC_FUZZ=ON: the libFuzzer targets fuzz_pair and fuzz_world (scripts/test.d/30-fuzz.sh builds and runs it;
# configure with CMAKE_C_FLAGS=-fsanitize=fuzzer-no-link,address,undefined so that the library
# is instrumented too).
option(CC_FUZZ "Build the libFuzzer target fuzz_pair (clang only)" OFF)

file(GLOB _cc_fuzz_corpus CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/*)
add_executable(test_fuzz_replay fuzz/replay.c fuzz/fuzz_checks.c)
target_link_libraries(test_fuzz_replay PRIVATE circlecollide_static cc_unity cc_warnings)
if(UNIX)
  target_link_libraries(test_fuzz_replay PRIVATE m)
endif()
# the files as arguments, relative to the corpus folder (short command lines)
set(_cc_fuzz_args "")
foreach(_f ${_cc_fuzz_corpus})
  get_filename_component(_n ${_f} NAME)
  list(APPEND _cc_fuzz_args ${_n})
endforeach()
add_test(NAME test_fuzz_replay COMMAND test_fuzz_replay ${_cc_fuzz_args})
set_tests_properties(test_fuzz_replay PROPERTIES WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus
  LABELS "numerics;fuzz" TIMEOUT 120)

# The world fuzzer's corpus (tests/fuzz/corpus_world/), replayed the same way: sequences of world
# calls checked against the header (fuzz_world_checks.c).
file(GLOB _cc_fuzz_world_corpus CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus_world/*)
add_executable(test_fuzz_world_replay fuzz/replay_world.c fuzz/fuzz_world_checks.c)
target_link_libraries(test_fuzz_world_replay PRIVATE circlecollide_static cc_warnings)
if(UNIX)
  target_link_libraries(test_fuzz_world_replay PRIVATE m)
endif()
set(_cc_fuzz_world_args "")
foreach(_f ${_cc_fuzz_world_corpus})
  get_filename_component(_n ${_f} NAME)
  list(APPEND _cc_fuzz_world_args ${_n})
endforeach()
add_test(NAME test_fuzz_world_replay COMMAND test_fuzz_world_replay ${_cc_fuzz_world_args})
set_tests_properties(test_fuzz_world_replay PROPERTIES WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus_world
  LABELS "numerics;fuzz" TIMEOUT 120)

if(CC_FUZZ)
  if(NOT CMAKE_C_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "CC_FUZZ needs clang (CC=clang)")
  endif()
  add_executable(fuzz_pair fuzz/fuzz_pair.c fuzz/fuzz_checks.c)
  target_link_libraries(fuzz_pair PRIVATE circlecollide_static cc_warnings m)
  target_compile_options(fuzz_pair PRIVATE -fsanitize=fuzzer)
  target_link_options(fuzz_pair PRIVATE -fsanitize=fuzzer)
  add_executable(fuzz_world fuzz/fuzz_world.c fuzz/fuzz_world_checks.c)
  target_link_libraries(fuzz_world PRIVATE circlecollide_static cc_warnings m)
  target_compile_options(fuzz_world PRIVATE -fsanitize=fuzzer)
  target_link_options(fuzz_world PRIVATE -fsanitize=fuzzer)
endif()

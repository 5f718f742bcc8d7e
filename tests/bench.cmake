# The benchmarks build, and run at a tiny size (the full run is bench/run.sh, outside CI).
# bench/ is added after tests/, so its targets are named here before they exist (add_test
# resolves them at generate time).
if(CC_BUILD_BENCH AND EXISTS ${PROJECT_SOURCE_DIR}/bench/CMakeLists.txt)
  add_test(NAME bench_pair_tiny COMMAND bench_pair --pairs 2000 --rounds 1)
  set_tests_properties(bench_pair_tiny PROPERTIES LABELS bench TIMEOUT 60
    PASS_REGULAR_EXPRESSION "figure sweep_ns_per_pair ")
endif()

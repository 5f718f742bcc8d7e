# The benchmarks build, and run at a tiny size (the full run is bench/run.sh, outside CI).
# bench/ is added after tests/, so its targets are named here before they exist (add_test
# resolves them at generate time). No timing is asserted here: only that the programs run and
# that EXACT mode tunnels nowhere on a small gas, judged by the benchmark's own step checker.
if(CC_BUILD_BENCH AND EXISTS ${PROJECT_SOURCE_DIR}/bench/CMakeLists.txt)
  add_test(NAME bench_pair_tiny COMMAND bench_pair --pairs 2000 --rounds 1)
  set_tests_properties(bench_pair_tiny PROPERTIES LABELS bench TIMEOUT 120
    PASS_REGULAR_EXPRESSION "figure sweep_ns_per_pair ")
  # the rolling pair (issue 12): 2000 pool pairs, one round
  add_test(NAME bench_pair_rolling_tiny COMMAND bench_pair_rolling run 2000 bench_pair_rolling_tiny.bin)
  set_tests_properties(bench_pair_rolling_tiny PROPERTIES LABELS bench TIMEOUT 120
    PASS_REGULAR_EXPRESSION "figure rolling_pair_over_sweep ")
  if(EXISTS ${PROJECT_SOURCE_DIR}/src/world/sources.cmake)
    # 300 circles, half a simulated second in steps of 1/60
    add_test(NAME bench_world_tiny COMMAND bench_world peer 300 0.3 0.5 0.016666666666666666)
    set_tests_properties(bench_world_tiny PROPERTIES LABELS bench TIMEOUT 120
      PASS_REGULAR_EXPRESSION "tunnelling=0 escaped=0 ")
    # a step with nothing to do (10,000 circles at rest, or moving slowly, against an empty world)
    add_test(NAME bench_idle_tiny COMMAND bench_idle --quick)
    set_tests_properties(bench_idle_tiny PROPERTIES LABELS bench TIMEOUT 120
      PASS_REGULAR_EXPRESSION "figure idle_rest_n10000_over_empty ")
    # the walls benchmark at its quick size: it runs, and the two variants have the same collisions
    add_test(NAME bench_queries_walls_tiny COMMAND bench_queries walls --quick)
    set_tests_properties(bench_queries_walls_tiny PROPERTIES LABELS bench TIMEOUT 120
      PASS_REGULAR_EXPRESSION "walls_10000_cost_ratio " FAIL_REGULAR_EXPRESSION "different collisions")
    # the 1.2 calls at their quick sizes: they run, the batch add's world is the single adds'
    # (the same hash), and the filter that passes everything finds what the 1.1 calls find
    add_test(NAME bench_bulk_tiny COMMAND bench_bulk add --quick)
    set_tests_properties(bench_bulk_tiny PROPERTIES LABELS bench TIMEOUT 120
      PASS_REGULAR_EXPRESSION "figure add_circles_over_singles_n10000 " FAIL_REGULAR_EXPRESSION "worlds differ")
    add_test(NAME bench_queries_filter_tiny COMMAND bench_queries filter --quick)
    set_tests_properties(bench_queries_filter_tiny PROPERTIES LABELS bench TIMEOUT 120
      PASS_REGULAR_EXPRESSION "figure filter_query_ignore_near_over_plain " FAIL_REGULAR_EXPRESSION "different answers")
  endif()
endif()

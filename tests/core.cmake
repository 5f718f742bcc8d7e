# The core suite: the pair functions, each suite built twice, for the double API (cc_*) and,
# with -DTEST_FLOAT, for the float API (cc_*f); plus the Box2D cross-check when Box2D is found.

foreach(_t sweep sweep_segment detect respond segment invalid properties)
  cc_add_test(NAME test_${_t} SOURCES test_${_t}.c LABELS core TIMEOUT 120)
  cc_add_test(NAME test_${_t}_float SOURCES test_${_t}.c LABELS core TIMEOUT 120)
  target_compile_definitions(test_${_t}_float PRIVATE TEST_FLOAT)
endforeach()
# rolling to rest: double and float twins in one suite (the brute force compares against long double)
cc_add_test(NAME test_rolling SOURCES test_rolling.c LABELS core TIMEOUT 300)
# a touch without approach (fuzz_pair's R1) and its neighbours, in both precisions
cc_add_test(NAME test_rolling_touch SOURCES test_rolling_touch.c LABELS core TIMEOUT 60)
cc_add_test(NAME test_rolling_touch_float SOURCES test_rolling_touch.c LABELS core TIMEOUT 60)
target_compile_definitions(test_rolling_touch_float PRIVATE TEST_FLOAT)
# the argument checks of the pairs that skip the full ones (cc_sweep_rolling's ordinary pairs)
cc_add_test(NAME test_rolling_checks SOURCES test_rolling_checks.c LABELS core TIMEOUT 60)
cc_add_test(NAME test_rolling_checks_float SOURCES test_rolling_checks.c LABELS core TIMEOUT 60)
target_compile_definitions(test_rolling_checks_float PRIVATE TEST_FLOAT)
# the version is what the loaded library says: check it against the shared one
cc_add_test(NAME test_version SOURCES test_version.c LABELS core SHARED)

# Box2D 3.1 (the pyb2d3 wheel), found by cmake/box2d.cmake (CC_HAVE_BOX2D, target box2d::box2d)
if(CC_HAVE_BOX2D AND TARGET box2d::box2d)
  cc_add_test(NAME test_box2d_toi SOURCES box2d/test_box2d_toi.c LIBS box2d::box2d LABELS core box2d
              TIMEOUT 300)
else()
  # without Box2D the cross-check reports itself skipped (ctest shows "Not Run (Skipped)")
  add_executable(test_box2d_toi box2d/skipped.c)
  add_test(NAME test_box2d_toi COMMAND test_box2d_toi)
  set_tests_properties(test_box2d_toi PROPERTIES SKIP_RETURN_CODE 77 LABELS "core;box2d")
endif()

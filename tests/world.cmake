# The world's tests (issue 4). Everything here runs in seconds in a Release build.
cc_add_test(NAME test_world_api SOURCES test_world_api.c LABELS world)
cc_add_test(NAME test_world_exact SOURCES test_world_exact.c LABELS world)
cc_add_test(NAME test_world_modes SOURCES test_world_modes.c LABELS world)
cc_add_test(NAME test_world_near SOURCES test_world_near.c LABELS world)
# 1e6 collisions in a box; built with sanitizers it simulates a smaller share of them
cc_add_test(NAME test_world_soak SOURCES test_world_soak.c LABELS world TIMEOUT 300)
if(CC_SANITIZE)
  target_compile_definitions(test_world_soak PRIVATE TW_SOAK_COLLISIONS=200000)
endif()

# The world's tests (issue 4). Everything here runs in seconds in a Release build, and within
# a few times that with ASan + UBSan (the soak's million collisions: ~1 s optimised, ~3 s
# with sanitizers, ~9 s with sanitizers and no optimisation).
cc_add_test(NAME test_world_api SOURCES test_world_api.c LABELS world)
cc_add_test(NAME test_world_bulk SOURCES test_world_bulk.c LABELS world)
cc_add_test(NAME test_world_exact SOURCES test_world_exact.c LABELS world)
cc_add_test(NAME test_world_modes SOURCES test_world_modes.c LABELS world)
cc_add_test(NAME test_world_sides SOURCES test_world_sides.c LABELS world)
cc_add_test(NAME test_world_modes_grid SOURCES test_world_modes_grid.c LABELS world)
cc_add_test(NAME test_world_near SOURCES test_world_near.c LABELS world)
cc_add_test(NAME test_world_reentry SOURCES test_world_reentry.c LABELS world)
cc_add_test(NAME test_world_props SOURCES test_world_props.c LABELS world)
cc_add_test(NAME test_world_queries SOURCES test_world_queries.c LABELS world)
cc_add_test(NAME test_world_filter SOURCES test_world_filter.c LABELS world)
cc_add_test(NAME test_world_promises SOURCES test_world_promises.c LABELS world)
cc_add_test(NAME test_world_codes SOURCES test_world_codes.c LABELS world)
cc_add_test(NAME test_world_periodic SOURCES test_world_periodic.c LABELS world)
cc_add_test(NAME test_world_rolling SOURCES test_world_rolling.c LABELS world)
cc_add_test(NAME test_world_fuzz_defects SOURCES test_world_fuzz_defects.c LABELS world)
cc_add_test(NAME test_world_step SOURCES test_world_step.c LABELS world)
cc_add_test(NAME test_world_def_compat SOURCES test_world_def_compat.c LABELS world)
cc_add_test(NAME test_world_uses SOURCES test_world_uses.c LABELS world)
cc_add_test(NAME test_world_event_cap SOURCES test_world_event_cap.c LABELS world)
cc_add_test(NAME test_world_calendar SOURCES test_world_calendar.c LABELS world)
cc_add_test(NAME test_world_gas_scans SOURCES test_world_gas_scans.c LABELS world)
cc_add_test(NAME test_world_soak SOURCES test_world_soak.c LABELS world TIMEOUT 300)
# The world against the plain reference simulator (issue 11): 4,000 random scenes against the
# reference and 800 all-pairs against grid (about 2 min optimised: a third of the scenes roll,
# and a rolling pair's sweep isolates the roots of a quartic; labelled slow, the ASan build runs
# the short registration instead); scripts/test.d/35-world-reference.sh runs 10,000 more.
cc_add_test(NAME test_world_reference SOURCES test_world_reference.c reference_world/reference_world.c
            reference_world/differential.c LABELS world slow TIMEOUT 600)
add_test(NAME test_world_reference_short COMMAND test_world_reference --scenes 200 --seed 7000001)
set_tests_properties(test_world_reference_short PROPERTIES LABELS world)

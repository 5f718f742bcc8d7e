# Simultaneous impacts (issue 5): the cluster model (src/world/cluster.c) tested on its own, and
# the same scenes run through the world (EXACT mode).
cc_add_test(NAME test_cluster SOURCES test_cluster.c LABELS simultaneous)
cc_add_test(NAME test_world_simultaneous SOURCES test_world_simultaneous.c LABELS simultaneous world)

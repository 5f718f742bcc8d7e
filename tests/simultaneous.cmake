# Simultaneous impacts: the cluster model (src/world/cluster.c) tested on its own.
# cluster.c is compiled into the test directly until the world's library sources list it.
cc_add_test(NAME test_cluster
  SOURCES test_cluster.c ${PROJECT_SOURCE_DIR}/src/world/cluster.c
  LABELS simultaneous)

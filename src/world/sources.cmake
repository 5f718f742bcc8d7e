# The world's sources (included by src/CMakeLists.txt).
list(APPEND CC_WORLD_SOURCES
  world/world.c     # API, def handshake, memory layout, ids
  world/events.c    # indexed 4-ary heap of predicted events; prefetch of the next ones
  world/calendar.c  # EXACT's queue in large worlds: an event calendar in front of the heap
  world/grid.c      # hashed uniform cell list
  world/predict.c   # EXACT: a body's earliest event (its circles; the whole prediction)
  world/predict_walls.c # EXACT: a body's earliest wall
  world/crossing.c  # EXACT: when a body leaves its grid cell
  world/resolve.c   # every impulse and push-apart
  world/overlap.c   # overlaps made by the caller; the full rebuild
  world/sort.c      # storage in Morton order of the cells; ids <-> storage indices
  world/near.c      # what touches a circle now (for simultaneous-impact resolvers)
  world/cluster.c   # the simultaneous-impact model (generalized reflections)
  world/simultaneous.c # EXACT: gathers the cluster of an impact and resolves it with the model
  world/step.c      # cc_world_step: validation, what a step may reach (one pass), dispatch; stats
  world/exact.c     # EXACT stepping
  world/swept.c     # SWEPT stepping
  world/discrete.c  # DISCRETE stepping
  world/sides.c     # SWEPT and DISCRETE: a centre that crossed a wall comes back to its side
  world/props.c     # per-body properties: the API, filters, restitution mixing
  world/sensor.c    # sensor circles: overlaps begun and ended
  world/query.c     # overlap queries: the circles in a disc or a box
  world/cast.c      # casts: the first circle or wall a moving circle or ray touches
  world/hash.c      # the state hash
  world/walls.c     # the walls' tree: the walls near a circle, a path or a box
  world/roll.c      # rolling to rest: the motion, and the times rolling circles meet
)

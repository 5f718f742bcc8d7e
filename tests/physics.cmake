# Physics validation (issue 15): the world simulates a hard-disk fluid (equation of state from
# the virial against Henderson's, collision rate against Enskog's, Maxwell-Boltzmann velocities,
# conservation). About 3 s CPU optimised (6 s wall on the shared 2 cores), 8.5 s CPU with ASan +
# UBSan; docs/PHYSICS.md has the formulas and the figures.
cc_add_test(NAME test_physics_hard_disks SOURCES test_physics_hard_disks.c LABELS physics TIMEOUT 300)

# The slow figures of docs/PHYSICS.md (the equation of state up to eta 0.72 against Kolafa and
# Rottner's fit and Engel et al.'s coexistence pressure; 1e7 impacts of conservation): a program,
# not a test, run by scripts/physics-report.sh.
add_executable(physics_eos physics_eos.c)
target_link_libraries(physics_eos PRIVATE circlecollide_static cc_warnings)
if(UNIX)
  target_link_libraries(physics_eos PRIVATE m)
endif()

# Physics validation (issue 15): the world simulates a hard-disk fluid (equation of state from
# the virial against Henderson's, collision rate against Enskog's, Maxwell-Boltzmann velocities,
# conservation). About 2 s optimised; docs/PHYSICS.md has the formulas and the figures.
cc_add_test(NAME test_physics_hard_disks SOURCES test_physics_hard_disks.c LABELS physics TIMEOUT 300)

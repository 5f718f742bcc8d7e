/* The world benchmark's scenes (gas, pool break, air hockey), built reproducibly from a seed so
 * that every mode, step size and peer engine starts from the very same state. */
#ifndef CC_BENCH_SCENES_H
#define CC_BENCH_SCENES_H

#include "circlecollide.h"

#include <stdint.h>

#define BENCH_MAX_WALLS 8

typedef struct bench_scene {
    char name[48];
    int n;                 /* circles */
    cc_circle *c;          /* their initial state (malloc'ed) */
    int n_walls;
    cc_segment walls[BENCH_MAX_WALLS];
    double x0, y0, x1, y1; /* the box the walls enclose: a centre outside it has tunnelled */
    double r_typ;          /* the radius that errors and overlaps are measured in */
    double t_end;          /* simulated time of one run */
} bench_scene;

/* n equal discs of radius 0.5 at area fraction phi in a square box with four walls: jittered
 * triangular-lattice sites (so that even phi = 0.6, beyond random packing, starts without
 * overlap), Gaussian velocities of unit spread per component, zero total momentum. */
void bench_scene_gas(bench_scene *s, int n, double phi, unsigned long long seed);
/* A pool break: 15 balls racked 1e-6 m apart, the cue ball at 10 m/s, four cushions. */
void bench_scene_pool(bench_scene *s);
/* Air hockey: a puck at 30 m/s (half a metre per 1/60 s step, 8 puck radii) and two immovable
 * mallets on a 2 m x 1 m table. */
void bench_scene_hockey(bench_scene *s);
void bench_scene_free(bench_scene *s);

/* n hard disks of diameter 1 on a square lattice in a periodic square box at area fraction phi,
 * velocities uniform in [-0.5, 0.5) per component (xorshift64 from seed), no walls. The box's
 * side, the world's period along x and y, goes to *side. */
void bench_scene_disks(bench_scene *s, int n, double phi, uint64_t seed, double *side);

/* cc_world_step through its event caps (each CC_EVENT_LIMIT continued at once to the same end
 * time); a failure ends the program with `who` in the message. */
void bench_step(cc_world *w, double dt, const char *who);

/* The world's counters (cc_world_get_stats with struct_size set). */
cc_world_stats bench_stats(const cc_world *w);

/* Kinetic energy of the movable circles. */
double bench_energy(const cc_circle *c, int n);

#endif

/* What a step did wrong, engine-independent: given every circle's state before and after one
 * step of length dt, count tunnelling (a contact that the straight pre-step motion makes within
 * the step, between bodies whose velocities the step left unchanged, and that do not overlap
 * at its end: they passed through each other; a contact merely resolved late shows as overlap),
 * escapes from the walls' box and the deepest overlap left behind. Used on our world and on
 * Box2D's, so that both are judged by the same rule. */
#ifndef CC_BENCH_CHECK_H
#define CC_BENCH_CHECK_H

#include "bench_scenes.h"

typedef struct bench_check {
    long tunnel_circle; /* circle pairs passing through each other unresolved */
    long tunnel_wall;   /* circles passing through a wall unresolved */
    long escaped;       /* circles whose centre left the box (counted once each) */
    double max_overlap; /* deepest overlap after any step, in units of the scene's r_typ */
    /* scratch */
    int n;
    int *order, *flag;
    double *key;
} bench_check;

void bench_check_init(bench_check *k, int n);
void bench_check_step(bench_check *k, const bench_scene *s, const cc_circle *pre, const cc_circle *post, double dt);
void bench_check_free(bench_check *k);

#endif

/* The demo's own seeded random numbers (SplitMix64): the same seed gives the same scene on every
 * platform, which rand() does not promise. */
#ifndef DEMO_PRNG_H
#define DEMO_PRNG_H

#include <stdint.h>

typedef struct demo_rng {
    uint64_t state;
} demo_rng;

void demo_rng_seed(demo_rng *r, uint64_t seed);
uint64_t demo_rng_next(demo_rng *r);
/* Uniform in [0, 1), 53 random bits. */
double demo_rng_unit(demo_rng *r);
/* A uniformly distributed unit vector, found without sin/cos so that no libm rounding can make
 * two platforms disagree: a point rejected until it falls in the unit disc, then normalised. */
void demo_rng_direction(demo_rng *r, double *x, double *y);

#endif

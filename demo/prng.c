/* SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", 2014):
 * a Weyl sequence scrambled by two multiply-xorshift rounds. Tiny, fast and good enough to place
 * circles; not for cryptography. */
#include "prng.h"

#include <math.h>

void demo_rng_seed(demo_rng *r, uint64_t seed)
{
    r->state = seed;
}

uint64_t demo_rng_next(demo_rng *r)
{
    uint64_t z = (r->state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

double demo_rng_unit(demo_rng *r)
{
    return (double)(demo_rng_next(r) >> 11) * (1.0 / 9007199254740992.0); /* 2^-53 */
}

void demo_rng_direction(demo_rng *r, double *x, double *y)
{
    for (;;) {
        double u = 2.0 * demo_rng_unit(r) - 1.0;
        double v = 2.0 * demo_rng_unit(r) - 1.0;
        double q = u * u + v * v;
        if (q > 1e-4 && q <= 1.0) { /* away from 0 so that the direction is well defined */
            double len = sqrt(q);   /* sqrt is correctly rounded everywhere (IEEE 754) */
            *x = u / len;
            *y = v / len;
            return;
        }
    }
}

/* The pair benchmark's accuracy yardstick: the high-precision reference of tests/reference/
 * (MPFR) when this build has it. */
#include "bench_pair_methods.h"

int bench_reference(const bench_pair_data *d, int single, double *t, int *code)
{
    (void)d;
    (void)single;
    (void)t;
    (void)code;
    return 0;
}

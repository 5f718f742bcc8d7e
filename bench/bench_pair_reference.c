/* The pair benchmark's accuracy yardstick: the exact reference of tests/reference/ (GMP and
 * MPFR) on the very inputs each method saw (the double pairs, or their float roundings).
 * Without those libraries this build has no reference and the accuracy columns stay empty. */
#include "bench_pair_methods.h"

#ifdef CC_BENCH_HAVE_REFERENCE
#include "reference.h"

int bench_reference(const bench_pair_data *d, int single, double *t, double *t_lo, int *code)
{
    size_t i;
    for (i = 0; i < d->n; i++) {
        ref_problem p;
        ref_result r;
        if (single)
            ref_circlesf(&p, &d->af[i], &d->bf[i], (float)d->t_max);
        else
            ref_circles(&p, &d->a[i], &d->b[i], d->t_max);
        code[i] = ref_solve(&p, &r);
        t[i] = r.t_hi;
        t_lo[i] = r.t_lo;
    }
    return 1;
}
#else
int bench_reference(const bench_pair_data *d, int single, double *t, double *t_lo, int *code)
{
    (void)d, (void)single, (void)t, (void)t_lo, (void)code;
    return 0;
}
#endif

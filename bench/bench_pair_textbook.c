/* The pair benchmark's textbook peer: tb_sweep / tb_sweepf of tests/reference/textbook.h, the
 * formula most code uses, with the same signatures and outputs as cc_sweep / cc_sweepf. */
#include "bench_pair_methods.h"
#include "textbook.h"

#include <math.h>

void bench_run_textbook(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code);
void bench_run_textbookf(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code);

void bench_run_textbook(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code)
{
    size_t i;
    for (i = lo; i < hi; i++) {
        cc_contact c;
        int r = tb_sweep(&d->a[i], &d->b[i], d->t_max, &c);
        t[i] = r == CC_HIT ? c.t : INFINITY;
        code[i] = r;
    }
}

void bench_run_textbookf(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code)
{
    size_t i;
    for (i = lo; i < hi; i++) {
        cc_contactf c;
        int r = tb_sweepf(&d->af[i], &d->bf[i], (float)d->t_max, &c);
        t[i] = r == CC_HIT ? (double)c.t : INFINITY;
        code[i] = r;
    }
}

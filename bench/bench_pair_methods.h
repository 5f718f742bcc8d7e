/* The pair benchmark's inputs (one set of pairs in every layout a method needs) and its
 * methods: each sweeps pairs [lo, hi) and writes a time and a result code per pair. */
#ifndef CC_BENCH_PAIR_METHODS_H
#define CC_BENCH_PAIR_METHODS_H

#include "circlecollide.h"

#include <stddef.h>
#include <stdint.h>

#define BENCH_MAX_METHODS 8
#define BENCH_BLOCK 1024 /* pairs per cache-resident block: 2 x 48 KiB of double inputs */

typedef struct bench_pair_data {
    size_t n;
    double t_max;
    cc_circle *a, *b;          /* the pairs, as cc_sweep takes them */
    cc_circlef *af, *bf;       /* the same rounded to float, for every float method */
    double *col[10];           /* columns px, py, vx, vy, radius of a then of b */
    cc_circle_soa soa_a, soa_b; /* views of col for cc_sweep_many */
} bench_pair_data;

/* t[i] = time of impact for CC_HIT (unspecified otherwise), code[i] = CC_HIT, CC_MISS or
 * CC_OVERLAP (a method's other outcomes, e.g. a solver failure, map to CC_MISS). */
typedef void (*bench_run_fn)(const bench_pair_data *d, size_t lo, size_t hi, double *t, int *code);

typedef struct bench_method {
    const char *name;
    const char *note;
    bench_run_fn run;
    int single;  /* 1: takes the float inputs (compare with the reference of af, bf) */
    int compare; /* 1: accuracy columns make sense */
    double *t;
    int *code;
} bench_method;

/* n random pairs (seeded): about half hit within t_max = 1, none overlap at t = 0 (bench_pair's
 * inputs; bench_exact times cc_sweep on the same kind of pairs) */
void bench_make_pairs(size_t n, uint64_t seed, cc_circle *a, cc_circle *b);
void bench_pair_data_init(bench_pair_data *d, size_t n);
void bench_pair_data_free(bench_pair_data *d);
/* fills af, bf and the columns from a, b */
void bench_pair_data_derive(const bench_pair_data *d);
/* the methods available in this build, with output arrays for pairs pairs; returns how many */
int bench_methods(bench_method *out, size_t pairs);
/* exact reference of every pair (of the float inputs when single): code, and for hits the time
 * t + t_lo to ~106 bits; returns 0 when this build has no reference */
int bench_reference(const bench_pair_data *d, int single, double *t, double *t_lo, int *code);

#endif

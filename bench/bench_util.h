/* Shared by the benchmark programs: a monotonic clock, a reproducible random stream, medians
 * and the `figure NAME VALUE` output that bench/run.sh collects. Header-only, benchmarks only. */
#ifndef CC_BENCH_UTIL_H
#define CC_BENCH_UTIL_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Seconds on a monotonic clock: wall time, because the world's cost includes its memory traffic. */
static inline double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* splitmix64: tiny, reproducible on every platform, good enough to scatter test inputs. */
typedef struct bench_rng {
    uint64_t s;
} bench_rng;

static inline uint64_t bench_next(bench_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* uniform in [lo, hi) with 53 random bits */
static inline double bench_uniform(bench_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * ((double)(bench_next(r) >> 11) * 0x1p-53);
}

static int bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median of v[0..n) (sorts v in place); NaN for n == 0. */
static inline double bench_median(double *v, size_t n)
{
    if (n == 0)
        return NAN;
    qsort(v, n, sizeof *v, bench_cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Minimum and maximum of v[0..n): the spread reported next to every median. */
static inline void bench_range(const double *v, size_t n, double *lo, double *hi)
{
    size_t i;
    *lo = INFINITY;
    *hi = -INFINITY;
    for (i = 0; i < n; i++) {
        if (v[i] < *lo)
            *lo = v[i];
        if (v[i] > *hi)
            *hi = v[i];
    }
}

/* The line bench/run.sh greps for: one headline number per line. */
static inline void bench_figure(const char *name, double value) { printf("figure %s %.6g\n", name, value); }

static inline void *bench_alloc(size_t bytes)
{
    void *p = calloc(1, bytes ? bytes : 1);
    if (p == NULL) {
        fprintf(stderr, "bench: out of memory (%zu bytes)\n", bytes);
        exit(2);
    }
    return p;
}

#endif

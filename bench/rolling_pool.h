/* The pool pairs of bench_pair_rolling, loaded for the CPU-time scripts (bench/rolling_cputime.sh,
 * bench/rolling_ab.sh, which compile a small program around this header): the pairs, this
 * thread's CPU time, and the medians and spreads they print. */
#ifndef ROLLING_POOL_H
#define ROLLING_POOL_H

#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "circlecollide.h"

typedef struct {
    cc_circle a, b;
    double da, db, tm;
} pool_pair;

static pool_pair pool_q[1 << 20];

/* This thread's CPU time (on a shared machine the waits for a core stay out). */
static double pool_cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int pool_cmp(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return a < b ? -1 : a > b;
}

/* The median and the spread (min - max) of v[0..n) (sorted in place). */
static void pool_show(const char *name, double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, pool_cmp);
    printf("  %-26s %8.3f  (%.3f - %.3f)\n", name, v[n / 2], v[0], v[n - 1]);
}

/* The rounds split by the machine's state (docs/BENCHMARKS.md section 8, stop 28: the ratio to
 * cc_sweep moves between ~2.3 and ~3.2 with it, from outside): the median (min - max) of v over
 * the rounds in which cc_sweep ran within 15 % of its fastest in this run, and over the others;
 * with cc_sweep's own median in each, which tells the state (on the machine of those notes,
 * ~23 ns per pool pair on a quiet core, 31-44 on a busy one). */
static void pool_show_states(const char *name, const double *v, const double *sweep, int n)
{
    double fast[99], slow[99], fs[99], ss[99], lo = sweep[0];
    int i, nf = 0, ns = 0;
    char label[96];
    for (i = 1; i < n; i++)
        lo = sweep[i] < lo ? sweep[i] : lo;
    for (i = 0; i < n; i++) {
        if (sweep[i] <= 1.15 * lo)
            fs[nf] = sweep[i], fast[nf++] = v[i];
        else
            ss[ns] = sweep[i], slow[ns++] = v[i];
    }
    qsort(fs, (size_t)nf, sizeof *fs, pool_cmp);
    snprintf(label, sizeof label, "%s, %d fastest rounds", name, nf);
    pool_show(label, fast, nf);
    printf("    (cc_sweep %.1f ns in those)\n", fs[nf / 2]);
    if (ns > 0) {
        qsort(ss, (size_t)ns, sizeof *ss, pool_cmp);
        snprintf(label, sizeof label, "%s, %d other rounds", name, ns);
        pool_show(label, slow, ns);
        printf("    (cc_sweep %.1f ns in those)\n", ss[ns / 2]);
    }
}

/* The pairs of the file pool (14 doubles each: bench_pair_rolling's format) into pool_q; with
 * answers (a FILE.ours of `bench_pair_rolling time`) and class (hits-rest, hits-moving,
 * misses-rest or misses-moving), only the pairs of that class: by that answer, and by whether a
 * circle is at rest. How many, or -1 when a file cannot be read. */
static long pool_load(const char *pool, const char *answers, const char *class_name)
{
    FILE *f = fopen(pool, "rb"), *g = answers != NULL ? fopen(answers, "rb") : NULL;
    int hits = class_name != NULL && !strncmp(class_name, "hits", 4);
    int rest = class_name != NULL && strstr(class_name, "-rest") != NULL;
    long n = 0;
    double x[14], t;
    if (f == NULL || (answers != NULL && g == NULL))
        return -1;
    while (n < (1 << 20) && fread(x, sizeof x, 1, f) == 1) {
        pool_pair *p;
        if (g != NULL) {
            if (fread(&t, sizeof t, 1, g) != 1)
                return -1;
            if ((t < HUGE_VAL) != hits || ((x[3] == 0.0 && x[4] == 0.0) || (x[8] == 0.0 && x[9] == 0.0)) != rest)
                continue;
        }
        p = &pool_q[n++];
        memset(p, 0, sizeof *p);
        p->a.pos.x = x[1], p->a.pos.y = x[2], p->a.vel.x = x[3], p->a.vel.y = x[4], p->a.radius = x[5], p->a.mass = 1.0;
        p->b.pos.x = x[6], p->b.pos.y = x[7], p->b.vel.x = x[8], p->b.vel.y = x[9], p->b.radius = x[10], p->b.mass = 1.0;
        p->da = x[11], p->db = x[12], p->tm = x[13];
    }
    fclose(f);
    if (g != NULL)
        fclose(g);
    return n;
}

#endif

#!/usr/bin/env bash
# CPU time per pair of cc_sweep_rolling and of cc_sweep on the same pairs, in file order (hits
# and misses mixed as bench_pair_rolling runs them), the two alternating in every round
# (docs/BENCHMARKS.md section 8). This thread's CPU time (CLOCK_THREAD_CPUTIME_ID): on a shared
# machine the waits for a core stay out, where bench_pair_rolling's wall time counts them.
#   bench/rolling_cputime.sh BUILD POOL [ROUNDS [ANSWERS CLASS]]
# BUILD: a build folder (its src/libcirclecollide.a is linked); POOL: from
# `bench_pair_rolling dump 20000 pool.bin`; ROUNDS: 15 unless given. Prints the medians and the
# spreads (min - max) over the rounds of each, and of the per-round ratio. With ANSWERS (a
# FILE.ours of `bench_pair_rolling time`, as bench/rolling_callgrind.sh takes it) and CLASS
# (hits-rest, hits-moving, misses-rest or misses-moving: by that answer, and by whether a
# circle is at rest), only the pairs of that class are timed.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$1 pool=$2 rounds=${3:-15} answers=${4:-} class=${5:-all}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/cpu.c" <<'C'
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "circlecollide.h"
typedef struct { cc_circle a, b; double da, db, tm; } pair;
static pair q[1 << 20];
static double cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
static int cmp(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return a < b ? -1 : a > b;
}
static void show(const char *name, double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp);
    printf("  %-20s %8.2f  (%.2f - %.2f)\n", name, v[n / 2], v[0], v[n - 1]);
}
int main(int argc, char **argv) /* POOL ROUNDS [ANSWERS CLASS] */
{
    FILE *f = fopen(argv[1], "rb"), *g = argc > 4 ? fopen(argv[3], "rb") : NULL;
    int rounds = atoi(argv[2]), r, hits = argc > 4 && !strncmp(argv[4], "hits", 4);
    int rest = argc > 4 && strstr(argv[4], "-rest") != NULL;
    long n = 0, i;
    double x[14], roll[99], sweep[99], ratio[99], t;
    volatile double acc = 0.0;
    if (f == NULL || rounds < 1 || rounds > 99 || (argc > 4 && g == NULL))
        return 2;
    while (n < (1 << 20) && fread(x, sizeof x, 1, f) == 1) {
        pair *p;
        if (g != NULL) { /* one class only: by the answer, and by a circle at rest */
            if (fread(&t, sizeof t, 1, g) != 1)
                return 2;
            if ((t < HUGE_VAL) != hits || ((x[3] == 0.0 && x[4] == 0.0) || (x[8] == 0.0 && x[9] == 0.0)) != rest)
                continue;
        }
        p = &q[n++];
        memset(p, 0, sizeof *p);
        p->a.pos.x = x[1], p->a.pos.y = x[2], p->a.vel.x = x[3], p->a.vel.y = x[4], p->a.radius = x[5], p->a.mass = 1.0;
        p->b.pos.x = x[6], p->b.pos.y = x[7], p->b.vel.x = x[8], p->b.vel.y = x[9], p->b.radius = x[10], p->b.mass = 1.0;
        p->da = x[11], p->db = x[12], p->tm = x[13];
    }
    for (r = 0; r < rounds; r++) {
        double t0 = cpu();
        for (i = 0; i < n; i++) {
            cc_contact k;
            if (cc_sweep_rolling(&q[i].a, q[i].da, &q[i].b, q[i].db, q[i].tm, &k) == CC_HIT)
                acc += k.t;
        }
        roll[r] = (cpu() - t0) / (double)n * 1e9;
        t0 = cpu();
        for (i = 0; i < n; i++) {
            cc_contact k;
            if (cc_sweep(&q[i].a, &q[i].b, q[i].tm, &k) == CC_HIT)
                acc += k.t;
        }
        sweep[r] = (cpu() - t0) / (double)n * 1e9;
        ratio[r] = roll[r] / sweep[r];
    }
    printf("%ld pairs, %d rounds; CPU ns per pair: median (min - max)\n", n, rounds);
    show("cc_sweep_rolling", roll, rounds);
    show("cc_sweep", sweep, rounds);
    show("ratio (per round)", ratio, rounds);
    return 0;
}
C
cc -O2 -std=c99 -I"$root/include" "$tmp/cpu.c" "$build/src/libcirclecollide.a" -lm -o "$tmp/cpu"
case $class in
all) "$tmp/cpu" "$pool" "$rounds" ;;
hits-rest | hits-moving | misses-rest | misses-moving) "$tmp/cpu" "$pool" "$rounds" "$answers" "$class" ;;
*) echo "rolling_cputime.sh: CLASS is hits-rest, hits-moving, misses-rest or misses-moving" >&2; exit 2 ;;
esac

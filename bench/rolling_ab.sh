#!/usr/bin/env bash
# Two builds of cc_sweep_rolling in one process, on the same pool pairs, with A's cc_sweep beside
# them: the three alternate in every round (the order rotating), so that the machine's state,
# which on this shared machine moves the ratio to cc_sweep by 10 % between runs minutes apart,
# is the same for both (docs/BENCHMARKS.md section 8). Each build's static library is linked
# into one relocatable object whose exports are renamed (A_cc_..., B_cc_...) and whose hidden
# symbols are made local (binutils' ld -r and objcopy).
#   bench/rolling_ab.sh BUILD_A BUILD_B POOL [ROUNDS [ANSWERS CLASS]]
# POOL, ROUNDS, ANSWERS and CLASS as for bench/rolling_cputime.sh. Prints each one's CPU ns per
# pair and the per-round ratios A / cc_sweep, B / cc_sweep and B / A: medians (min - max). Swap
# A and B in a second run: a layout effect of the order then shows.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_a=$1 build_b=$2 pool=$3 rounds=${4:-15} answers=${5:-} class=${6:-all}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for x in A B; do
    if [ $x = A ]; then lib=$build_a/src/libcirclecollide.a; else lib=$build_b/src/libcirclecollide.a; fi
    ld -r --whole-archive "$lib" -o "$tmp/$x.o"
    objcopy --localize-hidden "$tmp/$x.o"
    nm --defined-only -g "$tmp/$x.o" | awk -v p=$x '{print $3 " " p "_" $3}' >"$tmp/$x.syms"
    objcopy --redefine-syms="$tmp/$x.syms" "$tmp/$x.o"
done
cat >"$tmp/ab.c" <<'C'
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "circlecollide.h"
int A_cc_sweep_rolling(const cc_circle *, double, const cc_circle *, double, double, cc_contact *);
int B_cc_sweep_rolling(const cc_circle *, double, const cc_circle *, double, double, cc_contact *);
int A_cc_sweep(const cc_circle *, const cc_circle *, double, cc_contact *);
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
    printf("  %-26s %8.3f  (%.3f - %.3f)\n", name, v[n / 2], v[0], v[n - 1]);
}
static int sweep(const cc_circle *a, double da, const cc_circle *b, double db, double tm, cc_contact *k)
{
    (void)da, (void)db;
    return A_cc_sweep(a, b, tm, k);
}
typedef int (*fn)(const cc_circle *, double, const cc_circle *, double, double, cc_contact *);
int main(int argc, char **argv) /* POOL ROUNDS [ANSWERS CLASS] */
{
    FILE *f = fopen(argv[1], "rb"), *g = argc > 4 ? fopen(argv[3], "rb") : NULL;
    int rounds = atoi(argv[2]), r, m, hits = argc > 4 && !strncmp(argv[4], "hits", 4);
    int rest = argc > 4 && strstr(argv[4], "-rest") != NULL;
    long n = 0, i, z, reps;
    double x[14], ns[3][99], ra[99], rb[99], rba[99], t;
    fn F[3] = {A_cc_sweep_rolling, B_cc_sweep_rolling, sweep};
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
    if (n == 0)
        return 2;
    reps = 200000 / n + 1; /* (a round of at least 200,000 calls each: small classes too) */
    for (r = 0; r < rounds; r++) {
        for (m = 0; m < 3; m++) {
            int w = (m + r) % 3; /* (the order rotating with the round) */
            double t0 = cpu();
            for (z = 0; z < reps; z++)
                for (i = 0; i < n; i++) {
                    cc_contact k;
                    if (F[w](&q[i].a, q[i].da, &q[i].b, q[i].db, q[i].tm, &k) == CC_HIT)
                        acc += k.t;
                }
            ns[w][r] = (cpu() - t0) / (double)(n * reps) * 1e9;
        }
        ra[r] = ns[0][r] / ns[2][r], rb[r] = ns[1][r] / ns[2][r], rba[r] = ns[1][r] / ns[0][r];
    }
    printf("%ld pairs, %d rounds of %ld calls each; CPU ns per pair: median (min - max)\n", n, rounds, n * reps);
    show("A cc_sweep_rolling", ns[0], rounds);
    show("B cc_sweep_rolling", ns[1], rounds);
    show("cc_sweep", ns[2], rounds);
    show("A / cc_sweep (per round)", ra, rounds);
    show("B / cc_sweep (per round)", rb, rounds);
    show("B / A (per round)", rba, rounds);
    return 0;
}
C
cc -O2 -std=c99 -I"$root/include" "$tmp/ab.c" "$tmp/A.o" "$tmp/B.o" -lm -o "$tmp/ab"
case $class in
all) "$tmp/ab" "$pool" "$rounds" ;;
hits-rest | hits-moving | misses-rest | misses-moving) "$tmp/ab" "$pool" "$rounds" "$answers" "$class" ;;
*) echo "rolling_ab.sh: CLASS is hits-rest, hits-moving, misses-rest or misses-moving" >&2; exit 2 ;;
esac

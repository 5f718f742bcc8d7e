#!/usr/bin/env bash
# Two builds of cc_sweep_rolling in one process, on the same pool pairs, with A's cc_sweep beside
# them: the three alternate in every round (the order rotating), so that the machine's state,
# which on this shared machine moves the ratio to cc_sweep by 10 % between runs minutes apart,
# is the same for both (docs/BENCHMARKS.md section 8). Each build's static library is linked
# into one relocatable object whose exports are renamed (A_cc_..., B_cc_...) and whose hidden
# symbols are made local (binutils' ld -r and objcopy).
#   bench/rolling_ab.sh BUILD_A BUILD_B POOL [ROUNDS [ANSWERS CLASS]]
# POOL, ROUNDS, ANSWERS and CLASS as for bench/rolling_cputime.sh (the pairs loaded by
# bench/rolling_pool.h, as there). Prints each one's CPU ns per pair and the per-round ratios
# A / cc_sweep, B / cc_sweep and B / A: medians (min - max), then B's two ratios over the rounds
# in which cc_sweep ran within 15 % of its fastest and over the others (the machine's two
# states; bench/rolling_pool.h). Swap A and B in a second run: a layout effect of the order then
# shows.
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
#include "rolling_pool.h"
int A_cc_sweep_rolling(const cc_circle *, double, const cc_circle *, double, double, cc_contact *);
int B_cc_sweep_rolling(const cc_circle *, double, const cc_circle *, double, double, cc_contact *);
int A_cc_sweep(const cc_circle *, const cc_circle *, double, cc_contact *);
static int sweep(const cc_circle *a, double da, const cc_circle *b, double db, double tm, cc_contact *k)
{
    (void)da, (void)db;
    return A_cc_sweep(a, b, tm, k);
}
typedef int (*fn)(const cc_circle *, double, const cc_circle *, double, double, cc_contact *);
int main(int argc, char **argv) /* POOL ROUNDS [ANSWERS CLASS] */
{
    int rounds = atoi(argv[2]), r, m;
    long n = pool_load(argv[1], argc > 4 ? argv[3] : NULL, argc > 4 ? argv[4] : NULL), i, z, reps;
    double ns[3][99], ra[99], rb[99], rba[99], rb2[99], rba2[99], sw[99];
    fn F[3] = {A_cc_sweep_rolling, B_cc_sweep_rolling, sweep};
    volatile double acc = 0.0;
    if (n < 1 || rounds < 1 || rounds > 99)
        return 2;
    reps = 200000 / n + 1; /* (a round of at least 200,000 calls each: small classes too) */
    for (r = 0; r < rounds; r++) {
        for (m = 0; m < 3; m++) {
            int w = (m + r) % 3; /* (the order rotating with the round) */
            double t0 = pool_cpu();
            for (z = 0; z < reps; z++)
                for (i = 0; i < n; i++) {
                    cc_contact k;
                    pool_pair *q = &pool_q[i];
                    if (F[w](&q->a, q->da, &q->b, q->db, q->tm, &k) == CC_HIT)
                        acc += k.t;
                }
            ns[w][r] = (pool_cpu() - t0) / (double)(n * reps) * 1e9;
        }
        ra[r] = ns[0][r] / ns[2][r], rb[r] = ns[1][r] / ns[2][r], rba[r] = ns[1][r] / ns[0][r];
        rb2[r] = rb[r], rba2[r] = rba[r], sw[r] = ns[2][r];
    }
    printf("%ld pairs, %d rounds of %ld calls each; CPU ns per pair: median (min - max)\n", n, rounds, n * reps);
    pool_show("A cc_sweep_rolling", ns[0], rounds);
    pool_show("B cc_sweep_rolling", ns[1], rounds);
    pool_show("cc_sweep", ns[2], rounds);
    pool_show("A / cc_sweep (per round)", ra, rounds);
    pool_show("B / cc_sweep (per round)", rb, rounds);
    pool_show("B / A (per round)", rba, rounds);
    /* (pool_show sorts what it shows: the split by state takes the copies made per round) */
    pool_show_states("B / cc_sweep", rb2, sw, rounds);
    pool_show_states("B / A", rba2, sw, rounds);
    return 0;
}
C
cc -O2 -std=c99 -I"$root/include" -I"$root/bench" "$tmp/ab.c" "$tmp/A.o" "$tmp/B.o" -lm -o "$tmp/ab"
case $class in
all) "$tmp/ab" "$pool" "$rounds" ;;
hits-rest | hits-moving | misses-rest | misses-moving) "$tmp/ab" "$pool" "$rounds" "$answers" "$class" ;;
*) echo "rolling_ab.sh: CLASS is hits-rest, hits-moving, misses-rest or misses-moving" >&2; exit 2 ;;
esac

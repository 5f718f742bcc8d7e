#!/usr/bin/env bash
# CPU time per pair of cc_sweep_rolling and of cc_sweep on the same pairs, in file order (hits
# and misses mixed as bench_pair_rolling runs them), the two alternating in every round
# (docs/BENCHMARKS.md section 8). This thread's CPU time (CLOCK_THREAD_CPUTIME_ID): on a shared
# machine the waits for a core stay out, where bench_pair_rolling's wall time counts them.
#   bench/rolling_cputime.sh BUILD POOL [ROUNDS [ANSWERS CLASS]]
# BUILD: a build folder (its src/libcirclecollide.a is linked); POOL: from
# `bench_pair_rolling dump 20000 pool.bin`; ROUNDS: 15 unless given. Prints the medians and the
# spreads (min - max) over the rounds of each, and of the per-round ratio, then that ratio over
# the rounds in which cc_sweep ran within 15 % of its fastest and over the others (the machine's
# two states; bench/rolling_pool.h). With ANSWERS (a
# FILE.ours of `bench_pair_rolling time`, as bench/rolling_callgrind.sh takes it) and CLASS
# (hits-rest, hits-moving, misses-rest or misses-moving: by that answer, and by whether a
# circle is at rest), only the pairs of that class are timed.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$1 pool=$2 rounds=${3:-15} answers=${4:-} class=${5:-all}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/cpu.c" <<'C'
#include "rolling_pool.h"
int main(int argc, char **argv) /* POOL ROUNDS [ANSWERS CLASS] */
{
    int rounds = atoi(argv[2]), r;
    long n = pool_load(argv[1], argc > 4 ? argv[3] : NULL, argc > 4 ? argv[4] : NULL), i;
    double roll[99], sweep[99], ratio[99], ratio2[99], sweep2[99];
    volatile double acc = 0.0;
    if (n < 1 || rounds < 1 || rounds > 99)
        return 2;
    for (r = 0; r < rounds; r++) {
        double t0 = pool_cpu();
        for (i = 0; i < n; i++) {
            cc_contact k;
            pool_pair *q = &pool_q[i];
            if (cc_sweep_rolling(&q->a, q->da, &q->b, q->db, q->tm, &k) == CC_HIT)
                acc += k.t;
        }
        roll[r] = (pool_cpu() - t0) / (double)n * 1e9;
        t0 = pool_cpu();
        for (i = 0; i < n; i++) {
            cc_contact k;
            pool_pair *q = &pool_q[i];
            if (cc_sweep(&q->a, &q->b, q->tm, &k) == CC_HIT)
                acc += k.t;
        }
        sweep[r] = (pool_cpu() - t0) / (double)n * 1e9;
        ratio[r] = roll[r] / sweep[r];
        ratio2[r] = ratio[r], sweep2[r] = sweep[r]; /* (pool_show sorts: copies for the split) */
    }
    printf("%ld pairs, %d rounds; CPU ns per pair: median (min - max)\n", n, rounds);
    pool_show("cc_sweep_rolling", roll, rounds);
    pool_show("cc_sweep", sweep, rounds);
    pool_show("ratio (per round)", ratio, rounds);
    pool_show_states("ratio", ratio2, sweep2, rounds);
    return 0;
}
C
cc -O2 -std=c99 -I"$root/include" -I"$root/bench" "$tmp/cpu.c" "$build/src/libcirclecollide.a" -lm -o "$tmp/cpu"
case $class in
all) "$tmp/cpu" "$pool" "$rounds" ;;
hits-rest | hits-moving | misses-rest | misses-moving) "$tmp/cpu" "$pool" "$rounds" "$answers" "$class" ;;
*) echo "rolling_cputime.sh: CLASS is hits-rest, hits-moving, misses-rest or misses-moving" >&2; exit 2 ;;
esac

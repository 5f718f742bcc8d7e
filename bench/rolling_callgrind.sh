#!/usr/bin/env bash
# Instructions per call of cc_sweep_rolling (and cc_sweep on the same pairs), split into the
# pairs that hit and those that miss (docs/BENCHMARKS.md section 8): deterministic, where the
# wall time of a shared machine is not.
#   bench/rolling_callgrind.sh BUILD POOL ANSWERS
# BUILD: a build folder (its src/libcirclecollide.a is linked); POOL: from
# `bench_pair_rolling dump 20000 pool.bin`; ANSWERS: a FILE.ours written by `bench_pair_rolling
# time` (which pairs hit: keep one copy, so that before and after count the same pairs).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$1 pool=$2 ours=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/split.c" <<'C'
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "circlecollide.h"
int main(int argc, char **argv) /* POOL ANSWERS hits|misses [sweep] */
{
    FILE *f = fopen(argv[1], "rb"), *g = fopen(argv[2], "rb");
    int hits = !strcmp(argv[3], "hits"), sweep = argc > 4;
    double x[14], t, acc = 0.0;
    long used = 0;
    if (f == NULL || g == NULL)
        return 2;
    while (fread(x, sizeof x, 1, f) == 1 && fread(&t, sizeof t, 1, g) == 1) {
        cc_circle a, b;
        cc_contact k;
        int r;
        if ((t < HUGE_VAL) != hits)
            continue;
        a.pos.x = x[1], a.pos.y = x[2], a.vel.x = x[3], a.vel.y = x[4], a.radius = x[5], a.mass = 1.0;
        b.pos.x = x[6], b.pos.y = x[7], b.vel.x = x[8], b.vel.y = x[9], b.radius = x[10], b.mass = 1.0;
        r = sweep ? cc_sweep(&a, &b, x[13], &k) : cc_sweep_rolling(&a, x[11], &b, x[12], x[13], &k);
        acc += r == CC_HIT ? k.t : 0.0;
        used++;
    }
    printf("%ld calls %.17g\n", used, acc);
    return 0;
}
C
cc -O2 -std=c99 -I"$root/include" "$tmp/split.c" "$build/src/libcirclecollide.a" -lm -o "$tmp/split"
for mode in hits misses; do
  for fn in cc_sweep_rolling cc_sweep; do
    extra=()
    [ $fn = cc_sweep ] && extra=(sweep)
    out=$(valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" --toggle-collect=$fn \
      "$tmp/split" "$pool" "$ours" $mode "${extra[@]}" 2>&1)
    n=$(echo "$out" | sed -n 's/^\([0-9]*\) calls.*/\1/p')
    ir=$(echo "$out" | sed -n 's/.*Collected : \([0-9]*\).*/\1/p')
    awk -v m=$mode -v f=$fn -v n="$n" -v ir="$ir" 'BEGIN { printf "%-6s %-16s %6d calls %10d instructions, %7.1f per call\n", m, f, n, ir, ir / n }'
  done
done

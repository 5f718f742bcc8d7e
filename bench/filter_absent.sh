#!/usr/bin/env bash
# What the query filter (1.2) costs a program that sets none: the 1.1 casts and queries
# (`bench_queries casts --quick`: a ray, a cast of radius 0.5 and a disc query from the same random
# points of the gas at N = 1e3, 1e4, 1e5) of a build from before the filter (OLD) against this
# one's (NEW), the two programs run alternately ROUNDS times each (the order swapped every round),
# so that a slow moment of the shared machine hits both alike; per round the ratio NEW / OLD of
# each row, then the medians (min - max) over the rounds (docs/BENCHMARKS.md section 10).
#   bench/filter_absent.sh OLD NEW/bench/bench_queries [ROUNDS]
# OLD: a bench_queries program, or a commit of this repository (e.g. 73eb23c, main before the
# filter's merge), which is then built in a scratch folder (Release, bench_queries only).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
old=$1 new=$2 rounds=${3:-9}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ ! -x "$old" ]; then
  mkdir -p "$tmp/old-src"
  git -C "$root" archive "$old" | tar -x -C "$tmp/old-src"
  cmake -S "$tmp/old-src" -B "$tmp/old-build" -DCMAKE_BUILD_TYPE=Release -DCC_BUILD_TESTS=OFF \
    -DCC_BUILD_DEMO=OFF -DCC_BUILD_BENCH=ON >/dev/null
  cmake --build "$tmp/old-build" --target bench_queries -j 2 >/dev/null
  old=$tmp/old-build/bench/bench_queries
fi
for r in $(seq 1 "$rounds"); do
  if [ $((r % 2)) = 1 ]; then order="old new"; else order="new old"; fi
  for x in $order; do
    if [ $x = old ]; then exe=$old; else exe=$new; fi
    "$exe" casts --quick | awk -v r="$r" -v x="$x" '$1 ~ /^[0-9]+$/ {print x, r, $1, $2, $3, $4}' >>"$tmp/rows"
  done
done
python3 - "$tmp/rows" "$rounds" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
t = {}
for x, r, n, ray, cast, query in rows:
    for k, v in (("ray", ray), ("cast r 0.5", cast), ("disc query r 1.5", query)):
        t.setdefault((int(n), k), {}).setdefault(x, {})[int(r)] = float(v)
print("%8s %-18s %12s %12s %30s" % ("N", "1.1 call", "old ns", "new ns", "new / old, median (min - max)"))
for (n, k), v in sorted(t.items()):
    ratio = [v["new"][r] / v["old"][r] for r in v["old"]]
    print("%8d %-18s %12.1f %12.1f %14.3f (%.3f - %.3f)" % (n, k, statistics.median(v["old"].values()),
          statistics.median(v["new"].values()), statistics.median(ratio), min(ratio), max(ratio)))
print("(%s rounds of each program, alternating; ns per call, medians over the rounds)" % sys.argv[2])
PY

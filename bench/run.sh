#!/usr/bin/env bash
# The benchmarks in one run: bench/run.sh [--quick]
#
# Full run (several minutes): builds the benchmarks (Release) in build-bench/, installs the
# peers it can (Box2D 3.1 from the pyb2d3 wheel; billiards, pymunk and matplotlib in a venv
# there), runs the pair, world, scaling, feature and peer benchmarks, and writes
# docs/BENCHMARKS.md with its plots (docs/bench_*.png).
# --quick (under a minute once built): small sizes, prints the headline `figure NAME VALUE`
# lines only, writes nothing in docs/.
# Environment: BENCH_BUILD (build folder, default build-bench), CC_JOBS (default 2),
# BENCH_COMMIT (the commit named on the page, when the tree is not a git checkout).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BENCH_BUILD:-$root/build-bench}
jobs=${CC_JOBS:-2}
quick=0
case "${1:-}" in
  --quick) quick=1 ;;
  "") ;;
  *) echo "usage: bench/run.sh [--quick]" >&2; exit 2 ;;
esac
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_ROOT_USER_ACTION=ignore
mkdir -p "$build"
log=$build/run.log
: >"$log"

# Box2D 3.1's C library, headers and CMake package from the pyb2d3 wheel (as scripts/test.sh)
b2d=$build/_deps/pyb2d3
if [ ! -f "$b2d/lib64/cmake/box2d/box2dConfig.cmake" ]; then
  python3 -m pip install -q --no-deps --target "$b2d" pyb2d3==0.11.1 >>"$log" 2>&1 ||
    echo "bench: pyb2d3 did not install; Box2D columns are skipped" >&2
fi

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$b2d" \
  -DCC_BUILD_TESTS=OFF -DCC_BUILD_DEMO=OFF >>"$log" 2>&1
targets=(bench_pair bench_pair_rolling bench_world bench_idle bench_queries bench_exact bench_bulk)
grep -q "Box2D found" "$log" && targets+=(bench_box2d_world)
cmake --build "$build" -j"$jobs" --target "${targets[@]}" >>"$log" 2>&1 || {
  tail -30 "$log" >&2
  exit 1
}
bin=$build/bench

if [ $quick = 1 ]; then
  # 2e5 pairs are enough for stable ratios; the reference is skipped (it is the slow part)
  "$bin/bench_pair" --pairs 200000 --rounds 9 --no-reference | tee -a "$log" | grep '^figure '
  "$bin/bench_world" headline --quick | tee -a "$log" | grep '^figure '
  "$bin/bench_world" features --quick | tee -a "$log" | grep '^figure '
  "$bin/bench_idle" --quick | tee -a "$log" | grep '^figure '
  "$bin/bench_queries" casts --quick | tee -a "$log" | grep '^figure '
  "$bin/bench_queries" walls --quick | tee -a "$log" | grep '^figure '
  "$bin/bench_queries" periodic --quick | tee -a "$log" | grep '^figure '
  "$bin/bench_queries" filter --quick | tee -a "$log" | grep '^figure '
  "$bin/bench_bulk" add --quick | tee -a "$log" | grep '^figure '
  "$bin/bench_exact" --quick | tee -a "$log" | grep '^figure '
  echo "(details: $log)"
  exit 0
fi

# Python peers and the plots: a venv in the build folder
venv=$build/venv
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv" >>"$log" 2>&1
fi
"$venv/bin/python" -m pip install -q matplotlib billiards pymunk >>"$log" 2>&1 ||
  echo "bench: some Python peers did not install (see $log); their rows are skipped" >&2
# pooltool (issue 12's rolling peer) pulls numba, scipy, pandas and panda3d: installed apart so
# that its failure costs only its rows
"$venv/bin/python" -m pip install -q pooltool-billiards >>"$log" 2>&1 ||
  echo "bench: pooltool-billiards did not install (see $log); its rolling row is skipped" >&2

out=$build/results
rm -rf "$out"
mkdir -p "$out"
{
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2 | sed 's/^ //') ($(nproc) cores)"
  echo "os: $(uname -sr)"
  echo "compiler: $(${CC:-cc} --version | head -1)"
  echo "commit: ${BENCH_COMMIT:-$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)}"
  echo "load: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)"
} >"$out/machine.txt"

echo "== pair level" | tee -a "$log"
"$bin/bench_pair" --pairs 1000000 --rounds 9 --csv "$out/pair.csv" | tee "$out/pair.txt"
echo "== world: scenes x modes x steps" | tee -a "$log"
"$bin/bench_world" matrix --csv "$out/matrix.csv" | tee "$out/matrix.txt"
echo "== world: EXACT headline" | tee -a "$log"
"$bin/bench_world" headline | tee "$out/headline.txt"
echo "== world: scaling" | tee -a "$log"
"$bin/bench_world" scaling --csv "$out/scaling.csv" | tee "$out/scaling.txt"
echo "== world: features a scene does not use" | tee -a "$log"
"$bin/bench_world" features --csv "$out/features.csv" | tee "$out/features.txt"
echo "== world: worlds that reserve only what they use (def.uses)" | tee -a "$log"
"$bin/bench_world" uses --csv "$out/uses.csv" | tee "$out/uses.txt"
echo "== world: a step with nothing to do (N circles at rest, or moving slowly, against an empty world)" | tee -a "$log"
"$bin/bench_idle" --csv "$out/idle.csv" | tee "$out/idle.txt"
echo "== queries and walls at scale" | tee -a "$log"
"$bin/bench_queries" casts | tee "$out/casts.txt"
"$bin/bench_queries" walls | tee "$out/walls.txt"
"$bin/bench_queries" periodic | tee "$out/periodic_casts.txt"
echo "== the 1.2 calls: the batch add against single adds, the query filter against the 1.1 calls" | tee -a "$log"
"$bin/bench_bulk" add | tee "$out/bulk.txt"
"$bin/bench_queries" filter | tee "$out/filter.txt"

echo "== EXACT at research speed (issue 16)" | tee -a "$log"
"$bin/bench_exact" | tee "$out/exact.txt"

echo "== peers on the gas (n = 1000, phi = 0.3)" | tee -a "$log"
dt=0.016666666666666666
{
  "$bin/bench_world" peer 1000 0.3 10 $dt
  [ -x "$bin/bench_box2d_world" ] && "$bin/bench_box2d_world" 1000 0.3 10 $dt 4
  "$venv/bin/python" "$root/bench/peers.py" "$bin/bench_world" 1000 0.3 10 $dt "$out" pymunk
  # billiards needs ~15 s of wall time per simulated second here: a shorter run, same rate
  "$bin/bench_world" peer 1000 0.3 1 $dt
  "$venv/bin/python" "$root/bench/peers.py" "$bin/bench_world" 1000 0.3 1 $dt "$out" billiards
} 2>>"$log" | tee "$out/peers.txt"
rm -f "$out"/trace-*.bin

echo "== the Python path (bench/python_path.py)" | tee -a "$log"
# the binding from the source tree on this build's shared library: Python and C run the same code
cmake --build "$build" -j"$jobs" --target circlecollide >>"$log" 2>&1
CIRCLECOLLIDE_LIBRARY=$(ls "$build"/src/libcirclecollide.so* | head -1) PYTHONPATH=$root/bindings/python/src \
  "$venv/bin/python" "$root/bench/python_path.py" "$bin" 2>>"$log" | tee "$out/python_path.txt" ||
  echo "bench: the Python path did not run (see $log)" >&2
CIRCLECOLLIDE_LIBRARY=$(ls "$build"/src/libcirclecollide.so* | head -1) PYTHONPATH=$root/bindings/python/src \
  "$venv/bin/python" "$root/bench/python_bulk.py" 2>>"$log" | tee "$out/python_bulk.txt" ||
  echo "bench: the Python batch add did not run (see $log)" >&2

echo "== rolling pair: cc_sweep_rolling, cc_sweep, textbook quartic, pooltool (same pairs, same run)" | tee -a "$log"
"$bin/bench_pair_rolling" dump 20000 "$out/pool_pairs.bin" >>"$log"
"$venv/bin/python" "$root/bench/pooltool_rolling.py" "$bin/bench_pair_rolling" "$out/pool_pairs.bin" --rounds 5 \
  --time-limit 5000 2>>"$log" | tee "$out/rolling.txt"

"$venv/bin/python" "$root/bench/report.py" "$out" "$root/docs" "bench/run.sh"
grep -h '^figure ' "$out"/*.txt
echo "wrote docs/BENCHMARKS.md"

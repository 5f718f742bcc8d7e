#!/usr/bin/env bash
# CI step: fuzzing (docs/NUMERICS.md). Builds the libFuzzer target fuzz_pair with clang, the
# library and the harness instrumented alike (libFuzzer coverage, ASan, UBSan), and runs it for
# CC_FUZZ_SECONDS (default 60) starting from the committed corpus tests/fuzz/corpus/ (read only:
# what the run finds goes to a scratch folder). A contract violation (tests/fuzz/fuzz_checks.c),
# a sanitizer report or a crash fails the step and prints the input. To keep an input, copy it
# into tests/fuzz/corpus/: test_fuzz_replay replays every file there on every ctest run.
# To grow the corpus: run longer, then `fuzz_pair -merge=1 tests/fuzz/corpus <scratch folder>`.
# Then the world fuzzer fuzz_world (sequences of world calls, tests/fuzz/fuzz_world_checks.c) for
# CC_FUZZ_WORLD_SECONDS (default 60) from tests/fuzz/corpus_world/, with the same rules; its
# corpus replay is test_fuzz_world_replay.
# Both runs start from a fixed seed (CC_FUZZ_SEED, default 20261126): CI's bounded run is then the
# same sequence of inputs on every machine (a slower machine runs a prefix of it), so that a
# submission passes or fails for what it changed, not for the luck of the draw. The search for new
# finds is done by hand with other seeds and longer runs (CC_FUZZ_SEED=0: libFuzzer draws one;
# tests/fuzz/world_defects/README.md lists those runs and what they found).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
dir=${CC_FUZZ_BUILD_DIR:-$root/build-fuzz}
secs=${CC_FUZZ_SECONDS:-60}
seed=${CC_FUZZ_SEED:-20261126}
command -v clang >/dev/null || { echo "30-fuzz: clang not found (apt-get install clang libclang-rt-14-dev)"; exit 1; }

mkdir -p "$dir"
cmake -S "$root" -B "$dir" -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCC_WERROR=ON \
  -DCC_FUZZ=ON -DCC_BUILD_SHARED=OFF -DCC_BUILD_DEMO=OFF -DCC_BUILD_BENCH=OFF \
  -DCMAKE_C_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
  >"$dir/configure.log" 2>&1 || { cat "$dir/configure.log"; exit 1; }
cmake --build "$dir" -j "${CC_JOBS:-2}" --target fuzz_pair test_fuzz_replay fuzz_world test_fuzz_world_replay

run=$dir/run
rm -rf "$run"
mkdir -p "$run/new" "$run/crashes"
rc=0
# The six rolling functions are fuzzed too (CC_FUZZ_ROLLING=1, the default since R1 of
# tests/fuzz/pair_defects/ was resolved: three 60 s runs with different seeds found nothing
# more); CC_FUZZ_ROLLING=0 leaves them out of the timed run (their corpus is still replayed below
# in full), for when a new rolling find is open there.
skip=()
[ "${CC_FUZZ_ROLLING:-1}" = 0 ] && skip=(FUZZ_PAIR_SKIP_ROLLING=1)
env "${skip[@]}" ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  "$dir/tests/fuzz_pair" -seed="$seed" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$run/crashes/" "$run/new" "$root/tests/fuzz/corpus" >"$run/log.txt" 2>&1 || rc=$?
grep -E "^fuzz:|ERROR|SUMMARY|runtime error|stat::number_of_executed_units|stat::new_units_added|Done" "$run/log.txt" || true
if [ $rc -ne 0 ] || [ -n "$(ls -A "$run/crashes")" ]; then
  tail -n 40 "$run/log.txt"
  for f in "$run/crashes"/*; do
    [ -e "$f" ] || continue
    echo "30-fuzz: failing input $f:"
    od -A d -t x1 "$f" | head -n 20
  done
  echo "30-fuzz: FAILED (exit $rc); keep the input in tests/fuzz/corpus/ once fixed"
  exit 1
fi
# the replay of the committed corpus, built with the same sanitizers (no libFuzzer)
(cd "$root/tests/fuzz/corpus" && "$dir/tests/test_fuzz_replay" * | tail -n 3)
echo "30-fuzz: ${secs}s of fuzz_pair, no violation"

# the world fuzzer, the same way, when CC_FUZZ_WORLD_SECONDS > 0 (default 60; 0 leaves only the
# replay of its corpus under the sanitizers, below). Its finds D1..D19 are in
# tests/fuzz/world_defects/README.md: the open ones (D7, D10, D11, D12, D14, D18: scenes beyond
# the header's Range) are stepped around by the harness; with D16, D17 and D19 fixed, a 300 s run
# and three of 60 s found nothing new (2026-11-26). Longer by hand: CC_FUZZ_WORLD_SECONDS=600.
wsecs=${CC_FUZZ_WORLD_SECONDS:-60}
wrun=$dir/run_world
rm -rf "$wrun"
mkdir -p "$wrun/new" "$wrun/crashes"
rc=0
if [ "$wsecs" -gt 0 ]; then
ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  "$dir/tests/fuzz_world" -seed="$seed" -max_total_time="$wsecs" -timeout=30 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$wrun/crashes/" "$wrun/new" "$root/tests/fuzz/corpus_world" >"$wrun/log.txt" 2>&1 || rc=$?
grep -E "^fuzz_world:|ERROR|SUMMARY|runtime error|stat::number_of_executed_units|stat::new_units_added|Done" "$wrun/log.txt" || true
if [ $rc -ne 0 ] || [ -n "$(ls -A "$wrun/crashes" | grep -v '^slow-unit-' || true)" ]; then
  tail -n 40 "$wrun/log.txt"
  for f in "$wrun/crashes"/*; do
    [ -e "$f" ] || continue
    echo "30-fuzz: failing input $f (FUZZ_WORLD_TRACE=1 $dir/tests/fuzz_world $f traces it):"
    od -A d -t x1 "$f" | head -n 20
  done
  echo "30-fuzz: fuzz_world FAILED (exit $rc); keep the input in tests/fuzz/corpus_world/ once fixed"
  exit 1
fi
fi
(cd "$root/tests/fuzz/corpus_world" && "$dir/tests/test_fuzz_world_replay" * | tail -n 1)
echo "30-fuzz: ${secs}s of fuzz_pair and ${wsecs}s of fuzz_world, no violation"

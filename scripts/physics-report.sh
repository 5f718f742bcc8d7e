#!/usr/bin/env bash
# The figures of docs/PHYSICS.md (issue 15). Not part of CI (minutes of CPU). Builds in
# build-physics/ (or $CC_BUILD_DIR), RelWithDebInfo.
#
#   scripts/physics-report.sh [test] [blocks] [per-block]
#       tests/test_physics_hard_disks (N = 400 at eta 0.1, 0.3, 0.5, 0.65) with more statistics
#       than ctest (default 20 blocks of 1000 collisions per disk, about 40 s), then twice broken
#       on purpose (compared with the ideal gas Z = 1; the virial scaled by 0.97): must fail.
#   scripts/physics-report.sh eos [outdir]
#       The equation of state from eta 0.05 to 0.72 (tests/physics_eos.c): N = 400 at 21 area
#       fractions, N = 1600 and 6400 at some for the finite-size effect, the dense end with long
#       equilibration; tables as TSV in outdir (default docs/physics/) and the figure
#       docs/physics_eos.svg (scripts/physics-plot.py). About 15 minutes on the shared machine.
#   scripts/physics-report.sh long [outdir]
#       1e7 impacts at eta 0.5 with N = 4000 and N = 1000: kinetic energy, momentum and centre of
#       mass every 1e6 impacts, and the rounding model of the energy drift. About 1 minute.
#   scripts/physics-report.sh vacf [outdir]
#       The velocity autocorrelation at eta 0.3 and 0.5 (N = 1600) against Enskog's exponential,
#       and the running diffusion coefficient. About 30 s.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CC_BUILD_DIR:-$root/build-physics}
mode=test
if [[ $# -gt 0 && ! $1 =~ ^[0-9] ]]; then
  mode=$1
  shift
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCC_BUILD_TESTS=ON >/dev/null
cmake --build "$build" --target test_physics_hard_disks physics_eos -j "${CC_JOBS:-2}" >/dev/null
eos=$build/tests/physics_eos

case $mode in
test)
  blocks=${1:-20}
  per=${2:-1000}
  exe=$build/tests/test_physics_hard_disks
  echo "== $blocks blocks of $per collisions per disk, after 100 per disk of equilibration"
  "$exe" --blocks "$blocks" --per-block "$per"
  status=0
  for broken in "--ideal" "--virial-scale 0.97"; do
    echo "== broken on purpose ($broken): must fail"
    # shellcheck disable=SC2086
    if out=$("$exe" $broken); then echo "ERROR: $broken passed"; status=1; fi
    grep -E "FAIL|Tests" <<<"$out" || true
  done
  exit $status
  ;;
eos)
  out=${1:-$root/docs/physics}
  mkdir -p "$out"
  run() { # file, then physics_eos arguments; prints the table as it grows
    local f=$out/$1
    shift
    echo "== physics_eos eos $* > $f"
    "$eos" eos "$@" | tee "$f"
  }
  # the fluid: 200 collisions per disk from the lattice, 20 blocks of 1000
  run eos_n400_fluid.tsv --n 400 --eta 0.05,0.1,0.15,0.2,0.25,0.3,0.35,0.4,0.45,0.5,0.55,0.6,0.65,0.67,0.68,0.69 \
    --equil 200 --blocks 20 --per-block 1000
  # the dense end: 2000 collisions per disk from the lattice, 20 blocks of 2000
  run eos_n400_dense.tsv --n 400 --eta 0.70,0.705,0.71,0.715,0.72 --equil 2000 --blocks 20 --per-block 2000
  # the finite-size effect
  run eos_n1600_fluid.tsv --n 1600 --eta 0.3,0.5,0.65,0.69 --equil 200 --blocks 20 --per-block 500
  run eos_n6400_fluid.tsv --n 6400 --eta 0.5,0.65 --equil 200 --blocks 20 --per-block 250
  run eos_n1600_dense.tsv --n 1600 --eta 0.70,0.71,0.72 --equil 2000 --blocks 20 --per-block 1000
  python3 "$root/scripts/physics-plot.py" "$root/docs/physics_eos.svg" "$out"/eos_n*.tsv
  echo "== wrote $root/docs/physics_eos.svg"
  ;;
long)
  out=${1:-$root/docs/physics}
  mkdir -p "$out"
  for n in 4000 1000; do
    echo "== physics_eos long --n $n --eta 0.5 --collisions 1e7 --every 1e6 > $out/long_n$n.tsv"
    "$eos" long --n "$n" --eta 0.5 --collisions 1e7 --every 1e6 | tee "$out/long_n$n.tsv"
  done
  ;;
vacf)
  out=${1:-$root/docs/physics}
  mkdir -p "$out"
  for eta in 0.3 0.5; do
    echo "== physics_eos vacf --n 1600 --eta $eta --lags 160 --origins 4000 > $out/vacf_n1600_eta$eta.tsv"
    "$eos" vacf --n 1600 --eta "$eta" --lags 160 --origins 4000 | tee "$out/vacf_n1600_eta$eta.tsv"
  done
  ;;
*)
  echo "usage: $0 [test] [blocks] [per-block] | eos [outdir] | long [outdir] | vacf [outdir]" >&2
  exit 2
  ;;
esac

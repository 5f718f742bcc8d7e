#!/usr/bin/env bash
# The figures of docs/PHYSICS.md: runs tests/test_physics_hard_disks (issue 15, N = 400 hard
# disks at eta 0.1, 0.3, 0.5) with more statistics than ctest does, then twice broken on purpose
# (compared with the ideal gas Z = 1; the virial scaled by 0.97), which must fail.
# Usage: scripts/physics-report.sh [blocks] [collisions per disk per block]   (default 20 1000,
# about 25 s optimised). Builds in build-physics/ (or $CC_BUILD_DIR), RelWithDebInfo.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CC_BUILD_DIR:-$root/build-physics}
blocks=${1:-20}
per=${2:-1000}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCC_BUILD_TESTS=ON >/dev/null
cmake --build "$build" --target test_physics_hard_disks -j "${CC_JOBS:-2}" >/dev/null
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

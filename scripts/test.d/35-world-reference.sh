#!/usr/bin/env bash
# CI step: the world against the reference world (tests/reference_world/, issue 11) on many more
# random scenes than ctest's 4,000, from seeds ctest does not use: CC_REFERENCE_SCENES (default
# 10,000; about 5 min) against the reference and a fifth of that all-pairs against grid, in the optimised
# build of test.sh (build/). A failure prints the scene's seed: replay it with
#   build/tests/test_world_reference --scenes 1 --seed <seed> --trace
set -euo pipefail
build=${CC_BUILD_DIR:-build}
scenes=${CC_REFERENCE_SCENES:-10000}
exe=$build/tests/test_world_reference
[ -x "$exe" ] || { echo "35-world-reference: $exe not built"; exit 1; }
"$exe" --scenes "$scenes" --seed 1000001 | grep -vE ':PASS$'

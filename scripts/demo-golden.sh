#!/usr/bin/env bash
# Refreshes the demo's golden checksums (tests/demo_golden/*.sha256) from the current code, for
# when the world's behaviour changed on purpose. Look at the frames it prints the folders of
# before committing the new values. Run it on the tree you commit (it builds the working tree,
# uncommitted library changes included). Builds in build-demo/ (or $CC_BUILD_DIR).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CC_BUILD_DIR:-$root/build-demo}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCC_BUILD_TESTS=ON \
  -DCC_BUILD_DEMO=ON >/dev/null
cmake --build "$build" --target cc_demo -j "${CC_JOBS:-2}" >/dev/null
CC_DEMO_UPDATE_GOLDEN=1 ctest --test-dir "$build" -L demo-golden -V | grep -E "updated|Failed|Error" || true
git -C "$root" diff --stat -- tests/demo_golden

#!/usr/bin/env bash
# The README's first command: builds the demo (cc_demo) in build/ and runs it. Needs only a C
# compiler and CMake. With the full demo it writes the frames of a pool break to frames/pool.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
if [ ! -f build/CMakeCache.txt ]; then
  gen=()
  if command -v ninja >/dev/null; then gen=(-G Ninja); fi
  cmake -S . -B build "${gen[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build build --target cc_demo -j "${CC_JOBS:-2}" >/dev/null
demo=build/demo/cc_demo
if "$demo" --help 2>&1 | grep -q -- '--scene'; then
  mkdir -p frames/pool
  "$demo" --scene pool --frames 120 --out frames/pool
else
  "$demo"
fi

#!/usr/bin/env bash
# CI step: the pool page (demo/web/) in a real browser. Builds the WebAssembly module
# (scripts/wasm.sh) and the native replay program (web_replay, against the native library of
# the CI build), installs selenium (pinned: tests/web/requirements.txt) into a venv, then
# tests/web/browser_test.py serves demo/web/ on 127.0.0.1, drives the page in headless Chromium
# (Debian's chromium and chromium-driver) and checks the version string, a shot fired through
# the page's mouse handlers, the balls at rest, no console error, and that the native replay of
# the page's journal gives the same world bit for bit. Leaves build/web/pool.png (screenshot),
# the journal and both states. About 30 s. Environment: CC_BUILD_DIR (build), CC_WEB_OUT
# (build/web), CC_WEB_REPLAY (a web_replay program to use instead of building one).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${CC_BUILD_DIR:-$root/build}
out=${CC_WEB_OUT:-$root/build/web}
for tool in clang wasm-ld chromium chromedriver python3; do
  command -v "$tool" >/dev/null ||
    { echo "70-web: $tool not found (apt-get install clang lld chromium chromium-driver)"; exit 1; }
done
mkdir -p "$out"

# with the size table: docs/WEB.md's sizes are checked against it (80-doc-figures.sh)
bash "$root/scripts/wasm.sh" --sizes

replay=${CC_WEB_REPLAY:-}
if [ -z "$replay" ]; then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    gen=()
    command -v ninja >/dev/null && gen=(-G Ninja)
    cmake -S "$root" -B "$build" "${gen[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCC_WERROR=ON >/dev/null
  fi
  cmake --build "$build" -j "${CC_JOBS:-2}" --target web_replay >/dev/null
  replay=$build/tests/web_replay
fi

venv=$out/venv
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv" 2>/dev/null || { rm -rf "$venv"; apt-get install -y -q python3-venv >/dev/null; python3 -m venv "$venv"; }
fi
"$venv/bin/python" -m pip install -q --disable-pip-version-check -r "$root/tests/web/requirements.txt"

version=$(sed -n 's/^#define CC_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\).*/\2/p' "$root/include/circlecollide.h" | paste -sd.)
"$venv/bin/python" "$root/tests/web/browser_test.py" --replay "$replay" --version "$version" --out "$out"

#!/usr/bin/env bash
# CI step: the figures of README.md and docs/WEB.md that a tool prints (the WebAssembly sizes,
# the tests run against the amalgamation, the demo's pool break, the browser test's run, ...)
# agree with what the tools print now: scripts/doc_figures.py --check, after 70-web (which writes
# build/wasm/figures.txt and build/web/figures.txt) and the configure of build/ (build/figures.txt);
# it runs cc_demo itself (a second). A stale figure fails, naming it; the fix is
# `python3 scripts/doc_figures.py --update` after those steps.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${CC_BUILD_DIR:-$root/build}
python3 "$root/scripts/doc_figures.py" --check --build "$build" --wasm "${CC_WASM_OUT:-$root/build/wasm}" \
  --web "${CC_WEB_OUT:-$root/build/web}"

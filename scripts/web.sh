#!/usr/bin/env bash
# The README's third command: builds the WebAssembly module (scripts/wasm.sh) and serves the
# pool page of demo/web/ on http://127.0.0.1:8000/ (python3 -m http.server; CC_WEB_PORT to
# change the port). Ctrl-C stops it.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
port=${CC_WEB_PORT:-8000}
bash "$root/scripts/wasm.sh"
echo "web.sh: open http://127.0.0.1:$port/ (Ctrl-C to stop)"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$root/demo/web"

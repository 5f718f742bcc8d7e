#!/usr/bin/env bash
# Writes the two-file distribution dist/circlecollide.c + dist/circlecollide.h (or into the
# folder given as $1): every library source in build order, private names static. The work is
# done by scripts/amalgamate.py, which explains the rules; tests/amalgamation.cmake tests it.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exec python3 "$root/scripts/amalgamate.py" --out "${1:-$root/dist}"

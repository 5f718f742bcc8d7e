#!/usr/bin/env bash
# Builds the Python sdist and, from that sdist, the wheel (python -m build's default): the sdist
# holds the C library's sources (the repository's CMakeLists.txt, include/, src/, cmake/, copied
# into csrc/ of a staging copy of this folder), so pip can build the library from the sdist alone.
# Usage: build_dist.sh OUTDIR [python [build options]]   (python: one with the `build` package,
# default python3; options go to `python -m build`, e.g. --sdist for the sdist alone)
# Needs nothing but the pip registry (build isolation fetches scikit-build-core; the system's
# cmake >= 3.20 and C compiler are used, or pip fetches cmake).
set -euo pipefail
out=${1:?usage: build_dist.sh OUTDIR [python]}
py=${2:-python3}
shift $(( $# < 2 ? $# : 2 ))
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)
stage=$(mktemp -d "${TMPDIR:-/tmp}/circlecollide-sdist.XXXXXX")
trap 'rm -rf "$stage"' EXIT
# the package folder without generated files, then the C sources beside it
tar -C "$here" --exclude=__pycache__ --exclude=.hypothesis --exclude='*.egg-info' --exclude=build \
  --exclude=dist --exclude=csrc -cf - . | tar -C "$stage" -xf -
mkdir -p "$stage/csrc"
cp "$root/CMakeLists.txt" "$stage/csrc/"
cp -r "$root/include" "$root/src" "$root/cmake" "$stage/csrc/"
"$py" -m build "$@" --outdir "$out" "$stage"
ls -l "$out"

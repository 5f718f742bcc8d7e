#!/usr/bin/env bash
# Regenerates the ABI baseline abi/libcirclecollide.so.<major>.abi from a fresh RelWithDebInfo
# build of the shared library, with abidw (Debian: abigail-tools). Read abi/README.md first: the
# baseline may change only with a version bump (see there), because the abi_abidiff test exists
# to catch changes nobody meant to make.
#   abi/update.sh            build in a temporary folder, write the baseline, show what changed
#   abi/update.sh <build>    use (and build) that build folder instead
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
command -v abidw >/dev/null || { echo "abi/update.sh: abidw not found (apt-get install abigail-tools)" >&2; exit 1; }

ver() { sed -n "s/^#define CC_VERSION_$1 \([0-9][0-9]*\).*/\1/p" "$root/include/circlecollide.h"; }
major=$(ver MAJOR) minor=$(ver MINOR) patch=$(ver PATCH)
[ -n "$major" ] || { echo "abi/update.sh: no CC_VERSION_MAJOR in include/circlecollide.h" >&2; exit 1; }

if [ $# -ge 1 ]; then
  build=$1
else
  build=$(mktemp -d)
  trap 'rm -rf "$build"' EXIT
fi
# Debug information is what abidw reads the types from; the build type must keep it.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCC_BUILD_TESTS=OFF \
  -DCC_BUILD_DEMO=OFF -DCC_BUILD_BENCH=OFF -DCC_SANITIZE=OFF >/dev/null
cmake --build "$build" --target circlecollide -j 2 >/dev/null
lib=$(find "$build" -name "libcirclecollide.so.$major" -print -quit)
[ -n "$lib" ] || { echo "abi/update.sh: no libcirclecollide.so.$major in $build" >&2; exit 1; }

out="$root/abi/libcirclecollide.so.$major.abi"
new="$build/libcirclecollide.so.$major.abi"
# Only types reachable from the public header; no source locations or build paths, so that the
# file changes only when the ABI does (paths of this machine must not enter the repository).
abidw --headers-dir "$root/include" --no-corpus-path --no-comp-dir-path --no-show-locs \
  --drop-undefined-syms --no-elf-needed --type-id-style hash "$lib" --out-file "$new.raw"
sed -e "s|path='[^']*/src/|path='src/|g" "$new.raw" > "$new"

if [ -f "$out" ]; then
  echo "== changes from the previous baseline (abidiff old new):"
  set +e
  abidiff "$out" "$new"
  rc=$?
  set -e
  if [ $rc -eq 0 ]; then
    echo "(none: the ABI is unchanged)"
  else
    echo "== abidiff exit code $rc. Check that version $major.$minor.$patch allows this (abi/README.md):"
    echo "   additions only (new functions, fields at the end of a struct_size struct): minor bump;"
    echo "   anything else (removed/changed functions, changed layout): major bump, new SONAME."
  fi
fi
cp "$new" "$out"
echo "wrote abi/$(basename "$out") for version $major.$minor.$patch ($(grep -c '<elf-symbol ' "$out") symbols)"

#!/usr/bin/env bash
# CI step: the whole C test suite on a 32-bit ARM Linux target (armhf: 32-bit pointers and
# size_t, 8-byte malloc alignment, a different ABI for doubles), cross-built with Debian's
# gcc-arm-linux-gnueabihf (cmake/toolchains/arm-linux-gnueabihf.cmake) and run under qemu-arm,
# which ctest calls as CMAKE_CROSSCOMPILING_EMULATOR. Host-only tests (ABI, packaging) and the
# x86-64 demo checksums are left out by the test files themselves; the numerics and Box2D
# tests skip, as GMP/MPFR and Box2D are installed for the host only.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
dir=${CC_ARMHF_BUILD_DIR:-$root/build-armhf}
for tool in arm-linux-gnueabihf-gcc qemu-arm; do
  command -v "$tool" >/dev/null ||
    { echo "45-arm-linux: $tool not found (apt-get install gcc-arm-linux-gnueabihf libc6-dev-armhf-cross qemu-user)"; exit 1; }
done
gen=()
if [ ! -f "$dir/CMakeCache.txt" ] && command -v ninja >/dev/null; then gen=(-G Ninja); fi
cmake -S "$root" -B "$dir" "${gen[@]}" --toolchain "$root/cmake/toolchains/arm-linux-gnueabihf.cmake" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCC_WERROR=ON -DCC_BUILD_BENCH=OFF >"$dir.configure.log" 2>&1 ||
  { cat "$dir.configure.log"; exit 1; }
cmake --build "$dir" -j "${CC_JOBS:-2}"
# tests labelled slow (minutes natively) run in their short registrations only: under qemu they
# would take the better part of an hour
ctest --test-dir "$dir" --output-on-failure --timeout 600 -j "${CC_JOBS:-2}" -LE slow

#!/usr/bin/env bash
# CI step: the Cortex-M4F build (cmake/toolchains/cortex-m4f.cmake, Debian's gcc-arm-none-eabi
# and newlib). Cross-builds circlecollide_static (MinSizeRel), then
#   1. prints the .text bytes of every pair function and its private helpers, float and double
#      (arm-none-eabi-nm on the pair objects; a static helper appears once per object using it),
#      with the totals, and fails when the float total exceeds CC_M4F_FLOAT_LIMIT;
#   2. checks the library's external references: only sqrt/fabs-like math (sqrt, fabs, frexp,
#      ldexp, floor, ceil, float or double), mem* and the compiler's own runtime (__aeabi_*:
#      the software double arithmetic of a single-precision FPU), nothing else of libc.
# The target for the float pair functions is 4 KiB (docs/NUMERICS.md), enforced as the limit:
# one translation unit per precision (src/pair_float.c) keeps the shared helpers single.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
dir=${CC_M4F_BUILD_DIR:-$root/build-m4f}
limit=${CC_M4F_FLOAT_LIMIT:-4096}
target=4096
command -v arm-none-eabi-gcc >/dev/null ||
  { echo "40-embedded: arm-none-eabi-gcc not found (apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi)"; exit 1; }

mkdir -p "$dir"
# CC_WERROR stays off here: warnings are printed below, but one only this compiler sees (int32_t
# is long on arm-none-eabi) should not hide the size figures
cmake -S "$root" -B "$dir" --toolchain "$root/cmake/toolchains/cortex-m4f.cmake" -DCC_WERROR=OFF \
  >"$dir/configure.log" 2>&1 || { cat "$dir/configure.log"; exit 1; }
cmake --build "$dir" -j "${CC_JOBS:-2}" --target circlecollide_static 2>&1 | tee "$dir/build.log" | grep -E "warning|error" || true
lib=$dir/src/libcirclecollide.a
objs=$(find "$dir/src/CMakeFiles/circlecollide_static.dir" -maxdepth 1 \
  \( -name 'pair_double.c.o*' -o -name 'pair_float.c.o*' \) ! -name '*.d' | sort)

echo "== Cortex-M4F (-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -mthumb, MinSizeRel): .text bytes"
# every code symbol of the pair objects; names ending in f belong to the float path (CC_FN)
# shellcheck disable=SC2086
arm-none-eabi-nm -S -t d $objs | awk '
  /:$/ { obj = $1; sub(/.*\//, "", obj); sub(/\.c\.o.*:$/, "", obj); next }
  NF == 4 && ($3 == "T" || $3 == "t") {
    s = $2 + 0; name = $4; prec = (name ~ /f$/) ? "float" : "double"
    printf "  %-7s %-38s %5d  (%s.c%s)\n", prec, name, s, obj, ($3 == "t" ? ", private" : "")
    total[prec] += s
    if (!((prec, name) in seen)) { seen[prec, name] = 1; uniq[prec] += s }
  }
  END {
    printf "  total float  %5d bytes (%d with each private helper counted once)\n", total["float"], uniq["float"]
    printf "  total double %5d bytes (%d with each private helper counted once)\n", total["double"], uniq["double"]
    print total["float"] > "'"$dir"'/float-bytes.txt"
  }' | sort -s -k1,1
float=$(cat "$dir/float-bytes.txt")

echo "== external references of libcirclecollide.a"
defined=$(arm-none-eabi-nm --defined-only "$lib" 2>/dev/null | awk 'NF == 3 { print $3 }' | sort -u)
undefined=$(arm-none-eabi-nm -u "$lib" 2>/dev/null | awk 'NF == 2 && $1 == "U" { print $2 }' | sort -u)
external=$(comm -23 <(echo "$undefined") <(echo "$defined"))
echo "  $(echo "$external" | tr '\n' ' ')"
bad=$(echo "$external" | grep -vE '^(sqrtf?|fabsf?|frexpf?|ldexpf?|floorf?|ceilf?|mem(cpy|set|move|cmp)|__aeabi_[a-z0-9]+)$' || true)
status=0
if [ -n "$bad" ]; then
  echo "40-embedded: FAILED: the library calls more of libc than math and mem*: $bad"
  status=1
fi
if [ "$float" -gt "$limit" ]; then
  echo "40-embedded: FAILED: float pair functions take $float bytes of .text, above the limit $limit"
  status=1
elif [ "$float" -gt "$target" ]; then
  echo "40-embedded: float pair functions take $float bytes of .text: the 4 KiB target is missed by $((float - target)) bytes (limit $limit)"
else
  echo "40-embedded: float pair functions take $float bytes of .text (target $target)"
fi
exit $status

#!/usr/bin/env bash
# Builds the library as freestanding WebAssembly (no emscripten, no WASI, no libc: Debian's
# clang --target=wasm32 and wasm-ld, packages clang and lld) from the two-file amalgamation:
#   demo/web/circlecollide.wasm   the page's module: every cc_ function, demo/web/glue.c (the
#                                 callbacks passed on to the page, by-value structs), -O2
# With --sizes it also prints the module sizes (raw and gzip -9) of the pair functions alone,
# the whole library and the page's module, at -O2 and -Os (into build/wasm/sizes.txt too). The math and string functions the
# library needs come from demo/wasm/ (include/ maps sqrt, fabs, floor, ceil to WebAssembly
# instructions; libc.c has memcpy, memset, frexp, ldexp). Environment: CC_WASM_CC (clang),
# WASM_LD (wasm-ld), CC_WASM_OUT (build/wasm).
set -euo pipefail
sizes_too=0
[ "${1:-}" = --sizes ] && sizes_too=1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${CC_WASM_OUT:-$root/build/wasm}
cc=${CC_WASM_CC:-clang}
ld=${WASM_LD:-wasm-ld}
for tool in "$cc" "$ld" python3 gzip; do
  command -v "$tool" >/dev/null || { echo "wasm.sh: $tool not found (apt-get install clang lld)" >&2; exit 1; }
done
mkdir -p "$out"
python3 "$root/scripts/amalgamate.py" --out "$out/dist" >/dev/null

flags=(--target=wasm32 -ffreestanding -nostdlib -std=c99 -fvisibility=hidden -fno-math-errno
       -Wall -Wextra -Wpedantic -Werror -isystem "$root/demo/wasm/include" -I "$out/dist")
# the stack first: an overflow traps instead of running into the data; 256 KiB is ample
ldflags=(--no-entry -z stack-size=262144 --stack-first --strip-all)

# the public functions, from the header
mapfile -t public < <(sed -n 's/^CC_API[^;{(]*\b\(cc_[a-z0-9_]*\)(.*/\1/p' "$root/include/circlecollide.h")
pair=()
for f in detect_static separate sweep sweep_segment respond respond_segment closest_point_on_segment; do
  pair+=("--export=cc_$f" "--export=cc_${f}f")
done
library=()
for f in "${public[@]}"; do library+=("--export=$f"); done

sizes=$out/sizes.txt
figures=$out/figures.txt # the same as `name value` lines, for scripts/doc_figures.py
if [ $sizes_too = 1 ]; then
  printf '%-44s %9s %9s\n' "module" "bytes" "gzip -9" >"$sizes"
  printf 'wasm.functions %d\nwasm.pair_functions %d\n' "${#public[@]}" $(( ${#pair[@]} )) >"$figures"
fi
opts=(O2)
[ $sizes_too = 1 ] && opts=(O2 Os)
for opt in "${opts[@]}"; do
  "$cc" "${flags[@]}" -"$opt" -c "$out/dist/circlecollide.c" -o "$out/cc-$opt.o"
  "$cc" "${flags[@]}" -"$opt" -c "$root/demo/wasm/libc.c" -o "$out/libc-$opt.o"
  "$cc" "${flags[@]}" -"$opt" -c "$root/demo/web/glue.c" -o "$out/glue-$opt.o"
  "$cc" "${flags[@]}" -"$opt" -c "$root/demo/web/calls.c" -o "$out/calls-$opt.o"
  # the page's module: the library's exports and the glue's and calls' (visibility default)
  "$ld" "${ldflags[@]}" "${library[@]}" --export-dynamic "$out/cc-$opt.o" "$out/libc-$opt.o" \
    "$out/glue-$opt.o" "$out/calls-$opt.o" -o "$out/page-$opt.wasm"
  [ $sizes_too = 1 ] || continue
  "$ld" "${ldflags[@]}" "${pair[@]}" "$out/cc-$opt.o" "$out/libc-$opt.o" -o "$out/pair-$opt.wasm"
  "$ld" "${ldflags[@]}" "${library[@]}" "$out/cc-$opt.o" "$out/libc-$opt.o" -o "$out/library-$opt.wasm"
  for m in pair library page; do
    case $m in
      pair) what="pair functions (14: double and float)";;
      library) what="library (all ${#public[@]} cc_ functions)";;
      page) what="page module (library + glue.c, calls.c)";;
    esac
    bytes=$(stat -c %s "$out/$m-$opt.wasm") gz=$(gzip -9 -c "$out/$m-$opt.wasm" | wc -c)
    printf '%-44s %9d %9d\n' "$what, -$opt" "$bytes" "$gz" >>"$sizes"
    printf 'wasm.%s.%s.bytes %d\nwasm.%s.%s.gzip %d\n' "$m" "$opt" "$bytes" "$m" "$opt" "$gz" >>"$figures"
  done
done
cp "$out/page-O2.wasm" "$root/demo/web/circlecollide.wasm"
[ $sizes_too = 1 ] && cat "$sizes"
echo "wasm.sh: demo/web/circlecollide.wasm ($(stat -c %s "$root/demo/web/circlecollide.wasm") bytes)"

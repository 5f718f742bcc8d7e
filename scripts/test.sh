#!/usr/bin/env bash
# The README's test command: installs what the tests need, then runs all of them.
#   1. apt packages of scripts/apt-packages.txt (only as root, only when one is missing)
#   2. Box2D 3.1 for the cross-check: the pyb2d3==0.11.1 wheel into build/_deps/pyb2d3
#   3. build/      : -Werror build (RelWithDebInfo), Box2D required, the whole ctest suite
#   4. build-asan/ : the same with ASan + UBSan, the whole suite (tests labelled `slow` excepted)
#   5. every scripts/test.d/NN-name.sh in sorted order (each area's own steps)
# Every step runs even after a failure; the last line says PASSED or FAILED and the exit code is
# non-zero on any failure. Environment: CC_JOBS (default 2) build and test jobs.
set -uo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
jobs=${CC_JOBS:-2}
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_ROOT_USER_ACTION=ignore
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

failed=()
summary=()
start_all=$SECONDS

# step NAME COMMAND...: runs one step, records its result and time
step() {
  local name=$1 t0=$SECONDS rc
  shift
  echo
  echo "==== [$name] $*"
  "$@"
  rc=$?
  if [ $rc -eq 0 ]; then
    summary+=("ok      $(printf '%4d' $((SECONDS - t0)))s  $name")
  else
    summary+=("FAILED  $(printf '%4d' $((SECONDS - t0)))s  $name (exit $rc)")
    failed+=("$name")
  fi
  return $rc
}

apt_packages() {
  local list=() missing=() p
  while read -r p; do
    p=${p%%#*}
    p=${p//[[:space:]]/}
    [ -n "$p" ] && list+=("$p")
  done < scripts/apt-packages.txt
  for p in "${list[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    echo "all ${#list[@]} apt packages present"
    return 0
  fi
  if [ "$(id -u)" -ne 0 ]; then
    echo "not root: cannot install missing apt packages: ${missing[*]} (tests that need them skip or fail)"
    return 0
  fi
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq && apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

box2d_prefix=$root/build/_deps/pyb2d3
box2d() {
  if [ -f "$box2d_prefix/lib64/cmake/box2d/box2dConfig.cmake" ]; then
    echo "Box2D already in $box2d_prefix"
    return 0
  fi
  rm -rf "$box2d_prefix"
  python3 -m pip install -q --no-deps --target "$box2d_prefix" pyb2d3==0.11.1 &&
    test -f "$box2d_prefix/lib64/cmake/box2d/box2dConfig.cmake"
}

# configure DIR ARGS...: configures a build folder (Ninja when present and the folder is new)
configure() {
  local dir=$1
  shift
  local gen=()
  if [ ! -f "$dir/CMakeCache.txt" ] && command -v ninja >/dev/null; then gen=(-G Ninja); fi
  cmake -S "$root" -B "$dir" "${gen[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCC_WERROR=ON \
    -DCC_REQUIRE_BOX2D=ON -DCC_REQUIRE_MPFR=ON -DCC_BUILD_TESTS=ON -DCC_BUILD_DEMO=ON -DCC_BUILD_BENCH=ON \
    -DCMAKE_PREFIX_PATH="$box2d_prefix" "$@"
}

build_and_test() {
  local dir=$1 ctest_extra=$2
  shift 2
  step "configure $dir" configure "$dir" "$@" || return 1
  step "build $dir" cmake --build "$dir" -j "$jobs" || return 1
  # --timeout: a default for tests without their own TIMEOUT, so that a hang cannot stall CI
  # shellcheck disable=SC2086
  step "ctest $dir" ctest --test-dir "$dir" --output-on-failure --timeout 300 -j "$jobs" $ctest_extra
}

step "apt packages" apt_packages
step "Box2D (pyb2d3 wheel)" box2d
build_and_test build ""
# Under ASan the suite runs whole, except tests labelled slow (minutes under ASan).
build_and_test build-asan "-LE slow" -DCC_SANITIZE=ON

for f in scripts/test.d/*.sh; do
  [ -e "$f" ] || continue
  step "$f" env CC_ROOT="$root" CC_BUILD_DIR="$root/build" CC_ASAN_BUILD_DIR="$root/build-asan" \
    CC_BOX2D_PREFIX="$box2d_prefix" bash "$f"
done

echo
echo "==== summary"
printf '  %s\n' "${summary[@]}"
total=$((SECONDS - start_all))
if [ ${#failed[@]} -eq 0 ]; then
  echo "scripts/test.sh: ALL PASSED (${#summary[@]} steps in ${total}s)"
  exit 0
fi
echo "scripts/test.sh: FAILED: ${failed[*]} (${#summary[@]} steps in ${total}s)"
exit 1

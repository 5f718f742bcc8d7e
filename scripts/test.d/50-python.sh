#!/usr/bin/env bash
# CI step: builds the Python wheel (scikit-build-core runs CMake on the repository), installs it
# into a fresh venv and runs the pytest suite from outside the source tree, so that the installed
# package, with the C library inside it, is what gets tested (mypy --strict on it too: test_typing).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${CC_PYTHON_OUT:-$root/build/python}  # CI: inside the clone; developers may point it elsewhere
rm -rf "$out/venv" "$out/wheels" "$out/run"
mkdir -p "$out/run"
# Debian's own python3 needs python3-venv for this; a python3 from elsewhere brings it along
if ! python3 -m venv "$out/venv" 2>/dev/null; then
  rm -rf "$out/venv"
  apt-get install -y -q python3-venv >/dev/null
  python3 -m venv "$out/venv"
fi
py=$out/venv/bin/python
"$py" -m pip install -q --disable-pip-version-check scikit-build-core numpy pytest hypothesis mypy
# no build isolation: the venv already has the build backend; the system's cmake is used
"$py" -m pip wheel -q --disable-pip-version-check --no-build-isolation --no-deps \
  "$root/bindings/python" -w "$out/wheels"
"$py" -m pip install -q --disable-pip-version-check --no-deps "$out"/wheels/circlecollide-*.whl
cd "$out/run"
"$py" -c 'import circlecollide, sys; print("testing", circlecollide.library_path()); sys.exit("site-packages" not in circlecollide.__file__)'
CIRCLECOLLIDE_HEADER=$root/include/circlecollide.h \
  "$py" -m pytest -q -p no:cacheprovider "$root/bindings/python/tests"

# The sdist, by the standard command (python -m build: pyproject.toml's sdist.force-include puts
# the C sources into its csrc/), checked to hold them, installed by pip into a fresh venv (pip
# builds the library from the sdist alone, fetching only the build backend from the registry),
# then a smoke test from outside the source tree. The wheel above was built from the checkout
# itself, as `pip install ./bindings/python` and pip's git+...#subdirectory=bindings/python
# installs build it (in a fresh clone, as CI's: only what git holds).
"$py" -m pip install -q --disable-pip-version-check build
rm -rf "$out/dist" "$out/sdist-venv"
"$py" -m build --sdist --outdir "$out/dist" "$root/bindings/python" >"$out/dist.log" 2>&1 || {
  cat "$out/dist.log" >&2
  exit 1
}
sdist=$(ls "$out"/dist/circlecollide-*.tar.gz)
tar -tzf "$sdist" >"$out/dist/contents.txt"
for f in csrc/CMakeLists.txt csrc/include/circlecollide.h csrc/src/CMakeLists.txt csrc/src/world/sources.cmake \
  csrc/cmake/circlecollideConfig.cmake.in; do
  grep -qx "circlecollide-[0-9.]*/$f" "$out/dist/contents.txt" || { echo "50-python: the sdist lacks $f" >&2; exit 1; }
done
echo "sdist: $(basename "$sdist"), $(grep -c /csrc/ "$out/dist/contents.txt") files in csrc/"
python3 -m venv "$out/sdist-venv"
"$out/sdist-venv/bin/python" -m pip install -q --disable-pip-version-check "$sdist"
"$out/sdist-venv/bin/python" "$root/bindings/python/tests/smoke.py"

# pip's install from a git URL of the checkout, as a user's `pip install
# "git+https://...#subdirectory=bindings/python"` makes it: pip clones the repository (its HEAD:
# what is committed), builds the wheel from the subdirectory against the sources two folders up
# in that clone, and installs it into a throwaway venv; then the smoke test (a tiny world) from
# outside the source tree, and pip's record says it came from this commit by git. The build
# backend and numpy come from the registry first (pip's cache holds them after the venv above):
# --no-build-isolation, so that the build itself needs nothing from the network.
t0=$(date +%s)
rm -rf "$out/git-venv"
python3 -m venv "$out/git-venv"
"$out/git-venv/bin/python" -m pip install -q --disable-pip-version-check scikit-build-core numpy
CMAKE_BUILD_PARALLEL_LEVEL=${CC_JOBS:-2} "$out/git-venv/bin/python" -m pip install -q --disable-pip-version-check \
  --no-build-isolation --no-deps "git+file://$root#subdirectory=bindings/python"
"$out/git-venv/bin/python" "$root/bindings/python/tests/smoke.py"
"$out/git-venv/bin/python" - "$(git -C "$root" rev-parse HEAD)" <<'PY'
import json, sys
from importlib import metadata
d = metadata.distribution("circlecollide")
url = json.loads(d.read_text("direct_url.json"))
assert url.get("vcs_info", {}).get("vcs") == "git" and url["vcs_info"]["commit_id"] == sys.argv[1], url
assert url.get("subdirectory") == "bindings/python", url
import circlecollide
assert "git-venv" in circlecollide.__file__, circlecollide.__file__
print("git install ok: %s at commit %s" % (url["url"], url["vcs_info"]["commit_id"][:12]))
PY
echo "50-python: the install from a git URL took $(( $(date +%s) - t0 )) s"

#!/usr/bin/env bash
# CI step: the Python binding's science extras (pip install circlecollide[science]: gsd,
# freud-analysis, dask, distributed, matplotlib) in a venv of their own, with the wheel that
# 50-python built (built here when it is missing), then the science tests: GSD trajectories read
# back with gsd and freud, the freud recipe, and the Dask ensemble CLI on a LocalCluster and on
# a dask scheduler with two dask workers that the test starts on 127.0.0.1 and stops (small N:
# about a minute on two quiet cores). The core tests of 50-python run without these packages.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${CC_PYTHON_OUT:-$root/build/python}
venv=$out/science-venv
rm -rf "$venv" "$out/science-run"
mkdir -p "$out/science-run"
if ! python3 -m venv "$venv" 2>/dev/null; then
  rm -rf "$venv"
  apt-get install -y -q python3-venv >/dev/null
  python3 -m venv "$venv"
fi
py=$venv/bin/python
"$py" -m pip install -q --disable-pip-version-check pytest
if ! ls "$out"/wheels/circlecollide-*.whl >/dev/null 2>&1; then
  "$py" -m pip install -q --disable-pip-version-check scikit-build-core numpy
  "$py" -m pip wheel -q --disable-pip-version-check --no-build-isolation --no-deps \
    "$root/bindings/python" -w "$out/wheels"
fi
# the extras as a user gets them: the wheel with [science]
wheel=$(ls "$out"/wheels/circlecollide-*.whl | head -n 1)
"$py" -m pip install -q --disable-pip-version-check "$wheel[science]"
cd "$out/science-run"
"$py" -c 'import circlecollide, sys; sys.exit("site-packages" not in circlecollide.__file__)'
start=$(date +%s)
"$py" -m pytest -q -p no:cacheprovider "$root/bindings/python/tests/science"
echo "55-science: the science tests took $(( $(date +%s) - start )) s"

"""The package's type hints pass ``mypy --strict`` (skipped where mypy is not installed)."""

import os

import pytest

import circlecollide


def test_mypy_strict_is_clean():
    api = pytest.importorskip("mypy.api")
    package = os.path.dirname(os.path.abspath(circlecollide.__file__))
    out, err, status = api.run(["--strict", "--no-incremental", "--cache-dir", os.devnull, package])
    assert status == 0, out + err

"""The package's type hints pass ``mypy --strict`` (skipped where mypy is not installed)."""

import os

import pytest


def test_mypy_strict_is_clean():
    api = pytest.importorskip("mypy.api")
    # by package name, not by path: a path inside site-packages would make mypy check
    # numpy's stubs next to it as if they were ours
    out, err, status = api.run(["--strict", "--no-incremental", "--cache-dir", os.devnull, "-p", "circlecollide"])
    assert status == 0, out + err
    assert "Success" in out

"""The Python examples of the READMEs run as written (the repository's and the package's)."""

import os
import re

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
READMES = [os.path.join(HERE, "..", "..", "..", "README.md"), os.path.join(HERE, "..", "README.md")]


def python_blocks(path):
    with open(path) as f:
        return re.findall(r"```python\n(.*?)```", f.read(), flags=re.S)


@pytest.mark.parametrize("path", READMES, ids=["README.md", "bindings/python/README.md"])
def test_readme_python_examples_run(path):
    if not os.path.exists(path):
        pytest.skip("README not reachable from here")
    blocks = python_blocks(path)
    assert blocks, f"no python example in {path}"
    for code in blocks:
        exec(compile(code, path, "exec"), {"__name__": "readme"})

"""The science extras (gsd, freud, dask, distributed, matplotlib), imported when first used.

Importing circlecollide imports none of them: the core binding needs numpy only. They come with
``pip install circlecollide[science]``. Imported by name, so that the modules are plain ``Any``
to the type checker, which then needs neither them nor their stubs.
"""

from __future__ import annotations

import importlib
from typing import Any

#: the PyPI package of each module the extras provide
PACKAGES = {
    "gsd": "gsd",
    "freud": "freud-analysis",
    "dask": "dask",
    "distributed": "distributed",
    "matplotlib": "matplotlib",
}


def extra(module: str) -> Any:
    """The module (e.g. ``"gsd.hoomd"``), or ImportError saying which package to install."""
    try:
        return importlib.import_module(module)
    except ImportError as e:
        package = PACKAGES.get(module.split(".")[0], module)
        raise ImportError(
            f"circlecollide: {module} is needed here: pip install 'circlecollide[science]' (or {package})"
        ) from e

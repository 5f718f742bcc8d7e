"""circlecollide: exact continuous collision of moving circles.

Python bindings over the C library's stable ABI (ctypes only, no compiled glue). The shared
library ships inside this package; at import its major version is checked against the one
these bindings were written for, and a mismatch is refused with ``LibraryVersionError``.

Pair functions work on ``Circle`` values::

    >>> from circlecollide import Circle, sweep
    >>> a = Circle(pos=(0, 0), vel=(1, 0), radius=1)
    >>> b = Circle(pos=(10, 0), vel=(-1, 0), radius=1)
    >>> sweep(a, b, t_max=10).t   # the gap of 8 closes at speed 2
    4.0

Each takes ``precision="float"`` to run the single-precision C functions instead.
``World`` simulates many circles and walls; ``sweep_many`` sweeps numpy columns of pairs.
"""


from ._lib import EXPECTED_MAJOR, LibraryVersionError
from ._lib import lib as _clib
from ._errors import CircleCollideError
from ._types import Circle, Contact, Vec2
from ._pair import (
    closest_point_on_segment,
    detect_static,
    respond,
    respond_segment,
    rolling_advance,
    separate,
    sweep,
    sweep_rolling,
    sweep_segment,
    sweep_segment_rolling,
)
from ._batch import sweep_many
from ._lib import USES_ALL, USES_CLOTH, USES_PROPS, USES_ROLLING, USES_SENSORS
from ._world import CastHit, CircleProps, ContactEvent, SegmentProps, SensorEvent, World, WorldStats

__version__ = "1.2.0"


def library_version() -> str:
    """Version string of the C library loaded ("MAJOR.MINOR.PATCH")."""
    return str(_clib.cc_version_string().decode())


def library_path() -> str:
    """File the C library was loaded from."""
    return str(_clib.path)


__all__ = [
    "CastHit",
    "Circle",
    "CircleProps",
    "CircleCollideError",
    "Contact",
    "ContactEvent",
    "EXPECTED_MAJOR",
    "LibraryVersionError",
    "SegmentProps",
    "SensorEvent",
    "USES_ALL",
    "USES_CLOTH",
    "USES_PROPS",
    "USES_ROLLING",
    "USES_SENSORS",
    "Vec2",
    "World",
    "WorldStats",
    "closest_point_on_segment",
    "detect_static",
    "library_path",
    "library_version",
    "respond",
    "respond_segment",
    "rolling_advance",
    "separate",
    "sweep",
    "sweep_many",
    "sweep_rolling",
    "sweep_segment",
    "sweep_segment_rolling",
]

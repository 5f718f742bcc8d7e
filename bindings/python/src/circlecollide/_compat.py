"""Reads that became properties in 1.2 and are still called as methods by 1.1 code.

``World.kinetic_energy``, ``World.momentum`` and ``World.hash`` were methods in 1.1; in 1.2 every
read of the world's state without arguments is a property (``time``, ``stats``, ``positions``,
...). So that ``w.kinetic_energy()`` keeps working, the property's value is a float, int or
Vec2 that may also be called: the call returns the same value as a plain float, int or Vec2 and
warns (``DeprecationWarning``) once per place. The values compare, hash, add and format as the
plain ones do; ``type(v)`` is the subclass.
"""

from __future__ import annotations

import warnings
from typing import Any

from ._types import Vec2, _new_tuple


def _warn(name: str) -> None:
    warnings.warn(
        f"World.{name} is a property since circlecollide 1.2: write w.{name}, not w.{name}()",
        DeprecationWarning,
        stacklevel=3,
    )


class CallableFloat(float):
    """A float that 1.1's ``w.kinetic_energy()`` may still call (deprecated)."""

    __slots__ = ()
    _name = "kinetic_energy"

    def __call__(self) -> float:
        _warn(self._name)
        return float(self)

    def __reduce__(self) -> Any:
        return (float, (float(self),))


class CallableInt(int):
    """An int that 1.1's ``w.hash()`` may still call (deprecated)."""

    __slots__ = ()
    _name = "hash"

    def __call__(self) -> int:
        _warn(self._name)
        return int(self)

    def __reduce__(self) -> Any:
        return (int, (int(self),))


class CallableVec2(Vec2):
    """A Vec2 that 1.1's ``w.momentum()`` may still call (deprecated)."""

    __slots__ = ()
    _name = "momentum"

    def __new__(cls, x: float, y: float) -> "CallableVec2":
        return _new_tuple(cls, (x, y))

    def __call__(self) -> Vec2:
        _warn(self._name)
        return Vec2(self[0], self[1])

    def __repr__(self) -> str:
        return f"Vec2(x={self[0]!r}, y={self[1]!r})"

    def __reduce__(self) -> Any:
        return (Vec2, (self[0], self[1]))

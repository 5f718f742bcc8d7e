"""The Python value types (Circle, Contact) and their conversion to and from the C structs."""

from __future__ import annotations

import ctypes
import math
import struct
from dataclasses import dataclass
from typing import Iterable, Literal, Tuple, Union

from . import _lib

Vec2 = Tuple[float, float]
Precision = Literal["double", "float"]


def vec2(v: Iterable[float], name: str = "vector") -> Vec2:
    """(x, y) as a tuple of two floats; anything else is a ValueError."""
    try:
        x, y = v
        return (float(x), float(y))
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a pair of numbers (x, y), got {v!r}") from None


class Circle:
    """A moving circle: centre ``pos`` at t = 0, constant velocity ``vel``, ``radius``, ``mass``.

    A mutable value: the pair functions that respond or separate update it in place. Give
    ``mass=math.inf`` for an immovable obstacle. Values are checked by the C library when the
    circle is used (a NaN or a radius <= 0 raises ``ValueError`` there), not here.
    """

    __slots__ = ("_pos", "_vel", "radius", "mass")

    def __init__(
        self,
        pos: Iterable[float] = (0.0, 0.0),
        vel: Iterable[float] = (0.0, 0.0),
        radius: float = 1.0,
        mass: float = 1.0,
    ) -> None:
        self._pos = vec2(pos, "pos")
        self._vel = vec2(vel, "vel")
        self.radius = float(radius)
        self.mass = float(mass)

    @property
    def pos(self) -> Vec2:
        """Centre at t = 0, (x, y)."""
        return self._pos

    @pos.setter
    def pos(self, value: Iterable[float]) -> None:
        self._pos = vec2(value, "pos")

    @property
    def vel(self) -> Vec2:
        """Velocity, (vx, vy): displacement per unit time."""
        return self._vel

    @vel.setter
    def vel(self, value: Iterable[float]) -> None:
        self._vel = vec2(value, "vel")

    @property
    def immovable(self) -> bool:
        """True when mass is +inf."""
        return math.isinf(self.mass) and self.mass > 0

    def at(self, t: float) -> "Circle":
        """A copy moved along its velocity to time t."""
        return Circle(
            (self._pos[0] + self._vel[0] * t, self._pos[1] + self._vel[1] * t),
            self._vel,
            self.radius,
            self.mass,
        )

    def copy(self) -> "Circle":
        return Circle(self._pos, self._vel, self.radius, self.mass)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Circle):
            return NotImplemented
        return (self._pos, self._vel, self.radius, self.mass) == (
            other._pos,
            other._vel,
            other.radius,
            other.mass,
        )

    __hash__ = None  # type: ignore[assignment]  # mutable

    def __repr__(self) -> str:
        return f"Circle(pos={self._pos!r}, vel={self._vel!r}, radius={self.radius!r}, mass={self.mass!r})"


@dataclass(frozen=True)
class Contact:
    """A contact found by a sweep or a static test.

    ``kind`` is ``"hit"`` (first touch at time ``t``, depth 0) or ``"overlap"`` (already
    overlapping at t = 0, ``depth`` > 0). ``normal`` is a unit vector from a towards b (or the
    wall); ``point`` is the contact point at time ``t``.
    """

    kind: Literal["hit", "overlap"]
    t: float
    point: Vec2
    normal: Vec2
    depth: float


_pack6d = struct.Struct("=6d").pack  # cc_circle: pos.x, pos.y, vel.x, vel.y, radius, mass
assert struct.calcsize("=6d") == ctypes.sizeof(_lib.cc_circle)
AnyCircleStruct = Union[_lib.cc_circle, _lib.cc_circlef]


def circle_to_c(c: Circle, precision: Precision = "double") -> AnyCircleStruct:
    if not isinstance(c, Circle):
        raise TypeError(f"expected a Circle, got {type(c).__name__}")
    if precision == "double":
        # packing the six doubles is several times faster than building the nested structs
        return _lib.cc_circle.from_buffer_copy(_pack6d(*c._pos, *c._vel, c.radius, c.mass))
    if precision == "float":
        return _lib.cc_circlef(_lib.cc_vec2f(*c.pos), _lib.cc_vec2f(*c.vel), c.radius, c.mass)
    raise ValueError(f"precision must be 'double' or 'float', got {precision!r}")


def circle_from_c(s: AnyCircleStruct) -> Circle:
    return Circle((s.pos.x, s.pos.y), (s.vel.x, s.vel.y), s.radius, s.mass)


def store_circle(dst: Circle, s: AnyCircleStruct) -> None:
    """Writes the C struct's state back into an existing Circle (in-place update)."""
    dst.pos = (s.pos.x, s.pos.y)
    dst.vel = (s.vel.x, s.vel.y)
    dst.radius = s.radius
    dst.mass = s.mass


def contact_from_c(code: int, s: Union[_lib.cc_contact, _lib.cc_contactf]) -> Contact:
    return Contact(
        "hit" if code == _lib.HIT else "overlap",
        s.t,
        (s.point.x, s.point.y),
        (s.normal.x, s.normal.y),
        s.depth,
    )


def contact_to_c(c: Contact, precision: Precision = "double") -> Union[_lib.cc_contact, _lib.cc_contactf]:
    if not isinstance(c, Contact):
        raise TypeError(f"expected a Contact, got {type(c).__name__}")
    v, s = (_lib.cc_vec2, _lib.cc_contact) if precision == "double" else (_lib.cc_vec2f, _lib.cc_contactf)
    return s(c.t, v(*vec2(c.point, "point")), v(*vec2(c.normal, "normal")), c.depth)

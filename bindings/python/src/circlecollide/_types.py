"""The Python value types (Circle, Contact) and their conversion to and from the C structs."""

from __future__ import annotations

import ctypes
import math
import struct
from dataclasses import dataclass
from typing import Iterable, Literal, Optional, Tuple, Union

import numpy as np

from . import _errors, _lib

Precision = Literal["double", "float"]


class Vec2(Tuple[float, float]):
    """A 2D vector of two floats: ``v.x``, ``v.y``, with the arithmetic of a vector.

    ``a + b``, ``a - b``, ``-a``, ``2 * a``, ``a * 2``, ``a / 2``, ``a.dot(b)``, ``a.cross(b)``,
    ``a.length``, ``a.normalized()``; ``b`` may be any pair of numbers (``a + (1, 0)``). Still a
    tuple of two floats, as in 1.1: ``x, y = v``, ``v[0]``, ``v == (1.0, 2.0)``,
    ``hash(v) == hash((1.0, 2.0))`` (a dict key), ``np.asarray(v)``. A tuple's own ``+`` (which
    would concatenate) and ``*`` (which would repeat) are replaced by the vector's.
    """

    __slots__ = ()
    _fields = ("x", "y")

    def __new__(cls, x: float = 0.0, y: float = 0.0) -> "Vec2":
        return _new_tuple(cls, (_errors.number(x, "x", "Vec2"), _errors.number(y, "y", "Vec2")))

    @property
    def x(self) -> float:
        """The x component."""
        return self[0]

    @property
    def y(self) -> float:
        """The y component."""
        return self[1]

    def __repr__(self) -> str:
        return f"Vec2(x={self[0]!r}, y={self[1]!r})"

    def __getnewargs__(self) -> "tuple[float, float]":  # pickle and copy: Vec2(x, y)
        return (self[0], self[1])

    def _replace(self, **changes: float) -> "Vec2":
        """A copy with some components changed (as a NamedTuple's ``_replace``)."""
        unknown = set(changes) - {"x", "y"}
        if unknown:
            raise TypeError(f"Vec2._replace: no component {sorted(unknown)[0]!r}")
        return Vec2(changes.get("x", self[0]), changes.get("y", self[1]))

    def _asdict(self) -> "dict[str, float]":
        """``{"x": x, "y": y}`` (as a NamedTuple's ``_asdict``)."""
        return {"x": self[0], "y": self[1]}

    # ---- arithmetic ----------------------------------------------------------------------

    def __add__(self, other: object) -> "Vec2":
        o = _pair_or_none(other)
        if o is None:
            return NotImplemented
        return _v2(self[0] + o[0], self[1] + o[1])

    def __radd__(self, other: object) -> "Vec2":
        return self.__add__(other)

    def __sub__(self, other: object) -> "Vec2":
        o = _pair_or_none(other)
        if o is None:
            return NotImplemented
        return _v2(self[0] - o[0], self[1] - o[1])

    def __rsub__(self, other: object) -> "Vec2":
        o = _pair_or_none(other)
        if o is None:
            return NotImplemented
        return _v2(o[0] - self[0], o[1] - self[1])

    def __mul__(self, k: object) -> "Vec2":
        f = _scalar_or_none(k)
        if f is None:
            return NotImplemented
        return _v2(self[0] * f, self[1] * f)

    def __rmul__(self, k: object) -> "Vec2":
        return self.__mul__(k)

    def __truediv__(self, k: object) -> "Vec2":
        f = _scalar_or_none(k)
        if f is None:
            return NotImplemented
        return _v2(self[0] / f, self[1] / f)

    def __neg__(self) -> "Vec2":
        return _v2(-self[0], -self[1])

    def __pos__(self) -> "Vec2":
        return self

    def __abs__(self) -> float:
        return self.length

    def dot(self, other: Iterable[float]) -> float:
        """The dot product with another vector (any pair of numbers)."""
        o = vec2(other, "other")
        return self[0] * o[0] + self[1] * o[1]

    def cross(self, other: Iterable[float]) -> float:
        """The z component of the cross product, ``x * other.y - y * other.x``."""
        o = vec2(other, "other")
        return self[0] * o[1] - self[1] * o[0]

    @property
    def length(self) -> float:
        """The Euclidean length (``abs(v)`` too), without overflow for large components."""
        return math.hypot(self[0], self[1])

    @property
    def length_squared(self) -> float:
        """``x * x + y * y``."""
        return self[0] * self[0] + self[1] * self[1]

    def normalized(self) -> "Vec2":
        """The unit vector along this one; ``ZeroDivisionError`` for the zero vector."""
        n = self.length
        if n == 0.0:
            raise ZeroDivisionError("Vec2.normalized: the zero vector has no direction")
        return _v2(self[0] / n, self[1] / n)


_new_tuple = tuple.__new__


def _v2(x: float, y: float) -> Vec2:
    """Vec2(x, y) of two floats without the checks (twice as fast): for the library's outputs."""
    return _new_tuple(Vec2, (x, y))


def _scalar_or_none(k: object) -> Optional[float]:
    """k as a float when it is a real number (not a bool, str or vector), else None."""
    if type(k) is float:
        return k
    if isinstance(k, (bool, str, bytes, tuple, list)) or not isinstance(k, (int, float, np.floating, np.integer)):
        return None
    return float(k)


def _pair_or_none(v: object) -> Optional["tuple[float, float]"]:
    """v as two floats when it is a Vec2 or a pair of real numbers, else None."""
    if type(v) is Vec2:
        return v
    if isinstance(v, (tuple, list)) and len(v) == 2:
        x, y = _scalar_or_none(v[0]), _scalar_or_none(v[1])
        if x is not None and y is not None:
            return (x, y)
    return None


def vec2(v: Iterable[float], name: str = "vector", context: str = "") -> Vec2:
    """(x, y) as a Vec2 of two floats. Anything but a pair of real numbers is a TypeError naming
    the argument (a string, numbers as strings, bools, None); a sequence of another length is a
    ValueError."""
    if type(v) is Vec2:
        return v
    where = f"{context}: " if context else ""
    if isinstance(v, (str, bytes)) or not isinstance(v, Iterable):
        raise TypeError(f"{where}{name} must be a pair of real numbers (x, y), got {v!r}")
    items = list(v)
    if len(items) != 2:
        raise ValueError(f"{where}{name} must be a pair of real numbers (x, y), got {len(items)} values: {v!r}")
    x, y = _scalar_or_none(items[0]), _scalar_or_none(items[1])
    if x is None or y is None:
        raise TypeError(f"{where}{name} must be a pair of real numbers (x, y), got {v!r}")
    return _v2(x, y)


def finite_vec2(v: Iterable[float], name: str, context: str = "") -> Vec2:
    """A Vec2 whose components are finite, else CC_ERR_INVALID naming the argument."""
    r = vec2(v, name, context)
    if not (math.isfinite(r[0]) and math.isfinite(r[1])):
        raise _errors.invalid(context, f"{name} must be finite, got ({_errors.show(r[0])}, {_errors.show(r[1])})")
    return r


class Circle:
    """A moving circle: centre ``pos`` at t = 0, constant velocity ``vel``, ``radius``, ``mass``.

    A mutable value: the pair functions that respond or separate update it in place. Give
    ``mass=math.inf`` for an immovable obstacle. Every field is checked when it is set, at
    construction and at assignment: ``pos`` and ``vel`` finite, ``radius`` finite and > 0,
    ``mass`` > 0 (finite, or inf); a bad value raises ``CircleCollideError`` (a ``ValueError``
    with ``code`` CC_ERR_INVALID) naming the field and the value, and a value that is not a
    number raises ``TypeError``. So a ``Circle`` always holds a circle the library accepts.
    """

    __slots__ = ("_pos", "_vel", "_radius", "_mass")

    def __init__(
        self,
        pos: Iterable[float] = (0.0, 0.0),
        vel: Iterable[float] = (0.0, 0.0),
        radius: float = 1.0,
        mass: float = 1.0,
    ) -> None:
        self._pos = finite_vec2(pos, "pos", "Circle")
        self._vel = finite_vec2(vel, "vel", "Circle")
        self._radius = _errors.radius(radius, context="Circle")
        self._mass = _errors.mass(mass, context="Circle")

    @property
    def pos(self) -> Vec2:
        """Centre at t = 0, (x, y)."""
        return self._pos

    @pos.setter
    def pos(self, value: Iterable[float]) -> None:
        self._pos = finite_vec2(value, "pos", "Circle")

    @property
    def vel(self) -> Vec2:
        """Velocity, (vx, vy): displacement per unit time."""
        return self._vel

    @vel.setter
    def vel(self, value: Iterable[float]) -> None:
        self._vel = finite_vec2(value, "vel", "Circle")

    @property
    def radius(self) -> float:
        """Radius: finite and > 0."""
        return self._radius

    @radius.setter
    def radius(self, value: float) -> None:
        self._radius = _errors.radius(value, context="Circle")

    @property
    def mass(self) -> float:
        """Mass: > 0, finite or ``math.inf`` (immovable)."""
        return self._mass

    @mass.setter
    def mass(self, value: float) -> None:
        self._mass = _errors.mass(value, context="Circle")

    @property
    def immovable(self) -> bool:
        """True when mass is +inf."""
        return math.isinf(self._mass)

    def at(self, t: float) -> "Circle":
        """A copy moved along its velocity to time t."""
        return Circle(
            (self._pos[0] + self._vel[0] * t, self._pos[1] + self._vel[1] * t),
            self._vel,
            self.radius,
            self.mass,
        )

    def copy(self) -> "Circle":
        """An independent copy (the fields as they are, not checked again)."""
        c = Circle.__new__(Circle)
        c._pos, c._vel, c._radius, c._mass = self._pos, self._vel, self._radius, self._mass
        return c

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Circle):
            return NotImplemented
        return (self._pos, self._vel, self._radius, self._mass) == (
            other._pos,
            other._vel,
            other._radius,
            other._mass,
        )

    __hash__ = None  # type: ignore[assignment]  # mutable

    def __repr__(self) -> str:
        return f"Circle(pos={tuple(self._pos)!r}, vel={tuple(self._vel)!r}, radius={self._radius!r}, mass={self._mass!r})"


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

    def __post_init__(self) -> None:
        # a Contact made by hand with plain tuples still has .point.x
        if type(self.point) is not Vec2:
            object.__setattr__(self, "point", vec2(self.point, "point"))
        if type(self.normal) is not Vec2:
            object.__setattr__(self, "normal", vec2(self.normal, "normal"))


_pack6d = struct.Struct("=6d").pack  # cc_circle: pos.x, pos.y, vel.x, vel.y, radius, mass
assert struct.calcsize("=6d") == ctypes.sizeof(_lib.cc_circle)
AnyCircleStruct = Union[_lib.cc_circle, _lib.cc_circlef]


def circle_to_c(c: Circle, precision: Precision = "double") -> AnyCircleStruct:
    """The C struct of a Circle (in the given precision)."""
    if not isinstance(c, Circle):
        raise TypeError(f"expected a Circle, got {type(c).__name__}")
    if precision == "double":
        # packing the six doubles is several times faster than building the nested structs
        return _lib.cc_circle.from_buffer_copy(_pack6d(*c._pos, *c._vel, c._radius, c._mass))
    if precision == "float":
        return _lib.cc_circlef(_lib.cc_vec2f(*c.pos), _lib.cc_vec2f(*c.vel), c.radius, c.mass)
    raise ValueError(f"precision must be 'double' or 'float', got {precision!r}")


def circle_from_c(s: AnyCircleStruct) -> Circle:
    """A Circle from the C struct."""
    return Circle((s.pos.x, s.pos.y), (s.vel.x, s.vel.y), s.radius, s.mass)


def store_circle(dst: Circle, s: AnyCircleStruct) -> None:
    """Writes the C struct's state back into an existing Circle (in-place update)."""
    # the library's outputs are valid circles: written as they are, all four or none raising
    dst._pos = _v2(s.pos.x, s.pos.y)
    dst._vel = _v2(s.vel.x, s.vel.y)
    dst._radius = s.radius
    dst._mass = s.mass


_unpack6d = struct.Struct("=6d").unpack_from  # cc_contact: t, point.x, point.y, normal.x, normal.y, depth
assert struct.calcsize("=6d") == ctypes.sizeof(_lib.cc_contact)
_new_object = object.__new__


def contact_from_c(code: int, s: Union[_lib.cc_contact, _lib.cc_contactf]) -> Contact:
    """A Contact from the C struct and the result code (HIT or OVERLAP).

    The fields are read in one unpack (each ``s.point`` would make a ctypes object) and the
    frozen dataclass is filled through its __dict__ (its __init__ sets each field through
    object.__setattr__ and checks the vectors again): together about twice as fast (2.3 to
    1.3 us here, of about 6 us that ``sweep`` costs from Python)."""
    if type(s) is _lib.cc_contact:
        t, px, py, nx, ny, depth = _unpack6d(s)
    else:
        t, px, py, nx, ny, depth = s.t, s.point.x, s.point.y, s.normal.x, s.normal.y, s.depth
    c = _new_object(Contact)
    c.__dict__.update(
        kind="hit" if code == _lib.HIT else "overlap", t=t, point=_v2(px, py), normal=_v2(nx, ny), depth=depth
    )
    return c


def contact_to_c(c: Contact, precision: Precision = "double") -> Union[_lib.cc_contact, _lib.cc_contactf]:
    """The C struct of a Contact (in the given precision)."""
    if not isinstance(c, Contact):
        raise TypeError(f"expected a Contact, got {type(c).__name__}")
    v, s = (_lib.cc_vec2, _lib.cc_contact) if precision == "double" else (_lib.cc_vec2f, _lib.cc_contactf)
    return s(c.t, v(*vec2(c.point, "point")), v(*vec2(c.normal, "normal")), c.depth)

"""The pair functions: sweeps, static tests, push-apart and impulses on Circle values.

Every function takes ``precision="double"`` (the C functions) or ``precision="float"`` (their
single-precision twins with the suffix f: inputs are rounded to float, the answer computed in
float, and returned as Python floats).
"""

from __future__ import annotations

import ctypes
import math
import struct
from typing import Any, Iterable, Optional

from . import _lib
from . import _errors
from ._errors import check
from ._types import (
    Circle,
    Contact,
    Precision,
    Vec2,
    circle_to_c,
    contact_from_c,
    contact_to_c,
    store_circle,
    vec2,
)

L = _lib.lib
byref = ctypes.byref


def _f(precision: Precision, name: str) -> Any:  # the double function or its float twin
    if precision not in ("double", "float"):
        raise ValueError(f"precision must be 'double' or 'float', got {precision!r}")
    return getattr(L, name if precision == "double" else name + "f")


def _segment(a: Iterable[float], b: Iterable[float], precision: Precision) -> Any:
    v, s = (_lib.cc_vec2, _lib.cc_segment) if precision == "double" else (_lib.cc_vec2f, _lib.cc_segmentf)
    return s(v(*vec2(a, "segment end a")), v(*vec2(b, "segment end b")))


def _contact_struct(precision: Precision) -> Any:
    return _lib.cc_contact() if precision == "double" else _lib.cc_contactf()


# What the library refuses that a Circle's own checks cannot see, named by the binding (the pair
# functions take no def, so the library says CC_ERR_INVALID for all of it).
def _not_both_immovable(a: Circle, b: Circle, context: str) -> None:
    if isinstance(a, Circle) and isinstance(b, Circle) and a.immovable and b.immovable:
        raise _errors.invalid(
            context, "a and b are both immovable (mass inf): two immovable circles cannot respond to each other"
        )


def _unit_normal(contact: Contact, precision: Precision, context: str) -> None:
    """The library's check of contact.normal (|n| within 1e-6 of 1; 1e-4 in float), named."""
    if not isinstance(contact, Contact):
        raise TypeError(f"{context}: contact must be a Contact, got {type(contact).__name__}")
    n = vec2(contact.normal, "contact.normal", context)
    tol = 1e-6 if precision == "double" else 1e-4
    length = math.hypot(n[0], n[1])
    if not abs(length - 1.0) <= tol:
        raise _errors.invalid(
            context, f"contact.normal must be a unit vector (length within {tol:g} of 1), got length {_errors.show(length)}"
        )


# ---- the per-call fast path ---------------------------------------------------------------------
# A Circle is valid by construction (checked when made and when set), so the double functions
# of two Circles need no checks: the six fields are packed into bytes and passed as they are
# (the same C function, declared with byte-string arguments: ctypes passes a bytes object's own
# buffer, no copy), instead of building a ctypes struct from them. About half of what a call from
# Python costs (bench/python_path.py, docs/BENCHMARKS.md section 7).
_pack6d = struct.Struct("=6d").pack
_new_contact = _lib.cc_contact


def _packed(name: str, *middle: Any) -> Any:
    fn = getattr(L, name)
    if isinstance(fn, _lib._Missing):
        return fn
    proto = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p, *middle, ctypes.c_void_p)
    addr = ctypes.cast(fn, ctypes.c_void_p).value
    return proto(addr) if addr else _lib._Missing(name)


_sweep_packed = _packed("cc_sweep", ctypes.c_double)
_detect_packed = _packed("cc_detect_static")


def sweep(a: Circle, b: Circle, t_max: float = math.inf, *, precision: Precision = "double") -> Optional[Contact]:
    """First contact of two circles moving at constant velocity, within t in [0, t_max].

    Returns a ``Contact`` of kind ``"hit"`` (first touch, approaching), of kind ``"overlap"``
    (already overlapping at t = 0), or ``None`` when they do not touch by t_max.
    """
    if precision == "double" and type(a) is Circle and type(b) is Circle and type(t_max) is float and t_max >= 0:
        out = _new_contact()
        code = _sweep_packed(
            _pack6d(*a._pos, *a._vel, a._radius, a._mass), _pack6d(*b._pos, *b._vel, b._radius, b._mass), t_max, byref(out)
        )
        return None if code == _lib.MISS else contact_from_c(check(code, "sweep"), out)
    ca, cb, out = circle_to_c(a, precision), circle_to_c(b, precision), _contact_struct(precision)
    code = check(_f(precision, "cc_sweep")(byref(ca), byref(cb), _errors.t_max(t_max, context="sweep"), byref(out)), "sweep")
    return None if code == _lib.MISS else contact_from_c(code, out)


def sweep_segment(
    c: Circle, a: Iterable[float], b: Iterable[float], t_max: float = math.inf, *, precision: Precision = "double"
) -> Optional[Contact]:
    """First contact of a moving circle with the static segment from a to b (a == b: a point)."""
    cc, seg, out = circle_to_c(c, precision), _segment(a, b, precision), _contact_struct(precision)
    code = check(_f(precision, "cc_sweep_segment")(byref(cc), byref(seg), _errors.t_max(t_max, context="sweep_segment"), byref(out)), "sweep_segment")
    return None if code == _lib.MISS else contact_from_c(code, out)


def sweep_rolling(
    a: Circle, decel_a: float, b: Circle, decel_b: float, t_max: float = math.inf, *, precision: Precision = "double"
) -> Optional[Contact]:
    """First contact of two circles that slow down along their motion at constant decelerations.

    A circle moving at v (speed s) with deceleration decel is at pos + v (t - decel t^2 / (2 s))
    until it stops at t = s / decel, then at rest. decel = 0 is ``sweep`` (the same bits). Two
    circles that come to rest exactly touching do not hit.
    """
    ca, cb, out = circle_to_c(a, precision), circle_to_c(b, precision), _contact_struct(precision)
    fn = _f(precision, "cc_sweep_rolling")
    ctx = "sweep_rolling"
    da, db = _errors.nonneg_finite(decel_a, "decel_a", ctx), _errors.nonneg_finite(decel_b, "decel_b", ctx)
    code = check(fn(byref(ca), da, byref(cb), db, _errors.t_max(t_max, context=ctx), byref(out)), ctx)
    return None if code == _lib.MISS else contact_from_c(code, out)


def sweep_segment_rolling(
    c: Circle,
    decel: float,
    a: Iterable[float],
    b: Iterable[float],
    t_max: float = math.inf,
    *,
    precision: Precision = "double",
) -> Optional[Contact]:
    """First contact of a decelerating circle with the static segment from a to b."""
    cc, seg, out = circle_to_c(c, precision), _segment(a, b, precision), _contact_struct(precision)
    fn = _f(precision, "cc_sweep_segment_rolling")
    ctx = "sweep_segment_rolling"
    d, tm = _errors.nonneg_finite(decel, "decel", ctx), _errors.t_max(t_max, context=ctx)
    code = check(fn(byref(cc), d, byref(seg), tm, byref(out)), ctx)
    return None if code == _lib.MISS else contact_from_c(code, out)


def rolling_advance(c: Circle, decel: float, t: float, *, precision: Precision = "double") -> None:
    """Moves c (in place) to time t >= 0 along its decelerating motion (at rest after its stop)."""
    cc = circle_to_c(c, precision)
    ctx = "rolling_advance"
    d, tt = _errors.nonneg_finite(decel, "decel", ctx), _errors.nonneg_finite(t, "t", ctx)
    check(_f(precision, "cc_rolling_advance")(byref(cc), d, tt), ctx)
    store_circle(c, cc)


def detect_static(a: Circle, b: Circle, *, precision: Precision = "double") -> Optional[Contact]:
    """The overlap of a and b at t = 0 (touching is not overlapping), or None."""
    if precision == "double" and type(a) is Circle and type(b) is Circle:
        out = _new_contact()
        code = _detect_packed(
            _pack6d(*a._pos, *a._vel, a._radius, a._mass), _pack6d(*b._pos, *b._vel, b._radius, b._mass), byref(out)
        )
        return None if code == _lib.MISS else contact_from_c(check(code, "detect_static"), out)
    ca, cb, out = circle_to_c(a, precision), circle_to_c(b, precision), _contact_struct(precision)
    code = check(_f(precision, "cc_detect_static")(byref(ca), byref(cb), byref(out)), "detect_static")
    return None if code == _lib.MISS else contact_from_c(code, out)


def separate(a: Circle, b: Circle, *, precision: Precision = "double") -> bool:
    """Pushes overlapping circles apart along the centre line until they touch (in place).

    Each moves by a share inversely proportional to its mass. Returns True when they overlapped
    and were moved, False (nothing changed) otherwise.
    """
    ca, cb = circle_to_c(a, precision), circle_to_c(b, precision)
    _not_both_immovable(a, b, "separate")
    code = check(_f(precision, "cc_separate")(byref(ca), byref(cb)), "separate")
    if code == _lib.OVERLAP:
        store_circle(a, ca)
        store_circle(b, cb)
    return code == _lib.OVERLAP


def respond(a: Circle, b: Circle, contact: Contact, restitution: float = 1.0, *, precision: Precision = "double") -> bool:
    """Applies the collision impulse along contact.normal to the velocities of a and b (in place).

    Positions are not moved: advance the circles to ``contact.t`` first (``Circle.at``).
    Returns True when an impulse was applied, False when they were not approaching.
    """
    ca, cb, cc = circle_to_c(a, precision), circle_to_c(b, precision), contact_to_c(contact, precision)
    _not_both_immovable(a, b, "respond")
    _unit_normal(contact, precision, "respond")
    code = check(_f(precision, "cc_respond")(byref(ca), byref(cb), byref(cc), _errors.restitution(restitution, context="respond")), "respond")
    if code == _lib.HIT:
        store_circle(a, ca)
        store_circle(b, cb)
    return code == _lib.HIT


def respond_segment(c: Circle, contact: Contact, restitution: float = 1.0, *, precision: Precision = "double") -> bool:
    """Bounces c off an immovable wall whose normal (circle towards wall) is contact.normal."""
    cc, ct = circle_to_c(c, precision), contact_to_c(contact, precision)
    if c.immovable:
        raise _errors.invalid(
            "respond_segment", "c is immovable (mass inf): an immovable circle cannot respond to an immovable wall"
        )
    _unit_normal(contact, precision, "respond_segment")
    code = check(_f(precision, "cc_respond_segment")(byref(cc), byref(ct), _errors.restitution(restitution, context="respond_segment")), "respond_segment")
    if code == _lib.HIT:
        store_circle(c, cc)
    return code == _lib.HIT


def closest_point_on_segment(
    p: Iterable[float], a: Iterable[float], b: Iterable[float], *, precision: Precision = "double"
) -> Vec2:
    """The point of the segment from a to b closest to p."""
    fn = _f(precision, "cc_closest_point_on_segment")
    v = _lib.cc_vec2 if precision == "double" else _lib.cc_vec2f
    seg = _segment(a, b, precision)
    r = fn(v(*vec2(p, "p")), byref(seg))
    return Vec2(r.x, r.y)

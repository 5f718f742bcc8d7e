"""World: many circles and walls simulated by the C library in memory this object owns."""

from __future__ import annotations

import ctypes
from dataclasses import dataclass
from typing import Any, Callable, Iterable, List, Optional

import numpy as np

from . import _lib
from ._errors import CircleCollideError, check
from ._types import Circle, Vec2, circle_from_c, circle_to_c, vec2

L = _lib.lib
byref = ctypes.byref

MODES = {"exact": 0, "swept": 1, "discrete": 2}


@dataclass(frozen=True)
class ContactEvent:
    """One impulse the world applied: circle ``a`` against circle ``b`` or wall ``segment``.

    ``b`` is -1 for a wall and ``segment`` -1 for a circle; ``t`` is the world time, ``normal``
    the unit normal from a towards b (or the wall), ``impulse`` the normal impulse's magnitude.
    """

    a: int
    b: int
    segment: int
    t: float
    point: Vec2
    normal: Vec2
    impulse: float


@dataclass(frozen=True)
class WorldStats:
    """Counters since the world was made (cc_world_stats)."""

    collisions: int
    events: int
    stale_events: int
    pairs_tested: int
    cell_crossings: int
    max_overlap: float


ContactCallback = Callable[[ContactEvent], None]


class World:
    """A simulation of up to ``max_circles`` circles and ``max_segments`` static walls.

    ``mode`` is ``"exact"`` (every collision in time order), ``"swept"`` or ``"discrete"``;
    ``restitution`` in [0, 1] applies to every contact. ``on_contact``, if given, is called with a
    ``ContactEvent`` for every impulse during ``step``; an exception it raises is kept and raised
    again when ``step`` returns (the C step itself cannot be interrupted; later contacts of that
    step are not reported). The world's memory is a buffer owned by this object.
    """

    def __init__(
        self,
        max_circles: int,
        max_segments: int = 0,
        mode: str = "exact",
        restitution: float = 1.0,
        *,
        rest_speed: float = 0.0,
        cell_size: float = 0.0,
        max_events: Optional[int] = None,
        on_contact: Optional[ContactCallback] = None,
    ) -> None:
        if mode not in MODES:
            raise ValueError(f"mode must be one of {sorted(MODES)}, got {mode!r}")
        d, self._lib_def_size = _lib.world_def_defaults()
        d.max_circles = _c_int(max_circles, "max_circles")
        d.max_segments = _c_int(max_segments, "max_segments")
        d.mode = MODES[mode]
        d.restitution = float(restitution)
        d.rest_speed = float(rest_speed)
        d.cell_size = float(cell_size)
        if max_events is not None:
            if not 0 < int(max_events) < 2**64:
                raise ValueError("max_events must be a positive integer")
            d.max_events = int(max_events)
        self._on_contact = on_contact
        self._error: Optional[BaseException] = None
        # Kept on self so that ctypes never frees the trampoline while C holds its address.
        self._trampoline = _lib.cc_contact_fn(self._dispatch) if on_contact is not None else _lib.cc_contact_fn()
        d.on_contact = self._trampoline
        d.user = None
        size = L.cc_world_size(byref(d))
        if size == 0:
            raise CircleCollideError(_lib.ERR_INVALID, "World")
        # 16-byte alignment: over-allocate and start at the first aligned address.
        self._buffer = (ctypes.c_char * (size + 16))()
        base = ctypes.addressof(self._buffer)
        self._addr = base + (-base % 16)
        status = ctypes.c_int(0)
        w = L.cc_world_init(self._addr, size, byref(d), byref(status))
        if not w:
            raise CircleCollideError(status.value or _lib.ERR_INVALID, "World")
        self._w = ctypes.c_void_p(w)
        self.max_circles = d.max_circles
        self.max_segments = d.max_segments
        self.mode = mode
        self._scratch = (_lib.cc_circle * max(1, self.max_circles))()
        self._ids = (ctypes.c_int * max(1, self.max_circles))()

    def __repr__(self) -> str:
        return f"World(max_circles={self.max_circles}, mode={self.mode!r}, circles={len(self)}, time={self.time!r})"

    # ---- contact callback ---------------------------------------------------------------

    def _dispatch(self, event: Any, user: Any) -> None:  # called from C: must never raise
        if self._error is not None or self._on_contact is None:
            return
        try:
            e = event.contents
            self._on_contact(
                ContactEvent(
                    e.a, e.b, e.segment, e.t, (e.point.x, e.point.y), (e.normal.x, e.normal.y), e.impulse
                )
            )
        except BaseException as exc:  # noqa: BLE001  (re-raised by step)
            self._error = exc

    # ---- building the scene -------------------------------------------------------------

    def add_circle(self, circle: Circle) -> int:
        """Adds a circle (its state at the current world time); returns its id."""
        c = circle_to_c(circle)
        return check(L.cc_world_add_circle(self._w, byref(c)), "add_circle")

    def add_segment(self, p: Iterable[float], q: Iterable[float]) -> int:
        """Adds a static wall from p to q; returns its id."""
        s = _lib.cc_segment(_lib.cc_vec2(*vec2(p, "p")), _lib.cc_vec2(*vec2(q, "q")))
        return check(L.cc_world_add_segment(self._w, byref(s)), "add_segment")

    def remove_circle(self, id: int) -> None:
        """Removes a circle; the other ids stay valid."""
        check(L.cc_world_remove_circle(self._w, _c_int(id, "id")), "remove_circle")

    def circle(self, id: int) -> Circle:
        """A copy of the circle's state at the current world time."""
        out = _lib.cc_circle()
        check(L.cc_world_get_circle(self._w, _c_int(id, "id"), byref(out)), "circle")
        return circle_from_c(out)

    def set_circle(self, id: int, circle: Circle) -> None:
        """Replaces a circle's state at the current world time."""
        c = circle_to_c(circle)
        check(L.cc_world_set_circle(self._w, _c_int(id, "id"), byref(c)), "set_circle")

    def segment(self, id: int) -> tuple[Vec2, Vec2]:
        """The wall's end points."""
        s = _lib.cc_segment()
        check(L.cc_world_get_segment(self._w, _c_int(id, "id"), byref(s)), "segment")
        return (s.a.x, s.a.y), (s.b.x, s.b.y)

    # ---- running ------------------------------------------------------------------------

    def step(self, dt: float) -> bool:
        """Advances world time by dt. Returns False when the step stopped at max_events (the
        world is consistent at the last event; call again to continue), True otherwise."""
        self._error = None
        code = check(L.cc_world_step(self._w, float(dt)), "step")
        if self._error is not None:
            err, self._error = self._error, None
            raise err
        return code != _lib.EVENT_LIMIT

    @property
    def time(self) -> float:
        """Current world time."""
        return float(L.cc_world_time(self._w))

    @property
    def on_contact(self) -> Optional[ContactCallback]:
        return self._on_contact

    @on_contact.setter
    def on_contact(self, fn: Optional[ContactCallback]) -> None:
        if fn is not None and not self._trampoline:
            raise ValueError("give on_contact when making the World to receive contacts")
        self._on_contact = fn

    @property
    def stats(self) -> WorldStats:
        s = _lib.cc_world_stats()
        s.struct_size = ctypes.sizeof(s)
        check(L.cc_world_get_stats(self._w, byref(s)), "stats")
        return WorldStats(
            s.collisions, s.events, s.stale_events, s.pairs_tested, s.cell_crossings, s.max_overlap
        )

    # ---- bulk state as numpy ------------------------------------------------------------

    def _table(self) -> np.ndarray:
        n = check(L.cc_world_get_circles(self._w, self._ids, self._scratch, len(self._scratch)), "get_circles")
        n = min(n, len(self._scratch))
        # cc_circle is 6 doubles: pos.x, pos.y, vel.x, vel.y, radius, mass
        return np.ctypeslib.as_array(self._scratch).view(np.float64).reshape(-1, 6)[:n].copy()

    @property
    def ids(self) -> List[int]:
        """Ids of the live circles, in increasing order (the row order of positions)."""
        n = min(check(L.cc_world_get_circles(self._w, self._ids, None, len(self._ids)), "ids"), len(self._ids))
        return list(self._ids[:n])

    def __len__(self) -> int:
        return check(L.cc_world_get_circles(self._w, None, None, 0), "len")

    @property
    def positions(self) -> np.ndarray:
        """(n, 2) float64 array of the live circles' centres now, rows in id order (a copy)."""
        return self._table()[:, 0:2].copy()

    @property
    def velocities(self) -> np.ndarray:
        """(n, 2) float64 array of the live circles' velocities, rows in id order (a copy)."""
        return self._table()[:, 2:4].copy()

    @property
    def radii(self) -> np.ndarray:
        return self._table()[:, 4].copy()

    @property
    def masses(self) -> np.ndarray:
        return self._table()[:, 5].copy()

    def kinetic_energy(self) -> float:
        """Sum of m |v|^2 / 2 over the movable circles."""
        t = self._table()
        m = t[:, 5]
        movable = np.isfinite(m)
        return float(0.5 * np.sum(m[movable] * (t[movable, 2] ** 2 + t[movable, 3] ** 2)))

    def momentum(self) -> Vec2:
        """Sum of m v over the movable circles."""
        t = self._table()
        m = t[:, 5]
        movable = np.isfinite(m)
        return (float(np.sum(m[movable] * t[movable, 2])), float(np.sum(m[movable] * t[movable, 3])))


def _c_int(v: int, name: str) -> int:
    if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or not -(2**31) <= int(v) < 2**31:
        raise ValueError(f"{name} must be an int in the C int range, got {v!r}")
    return int(v)



"""World: many circles and walls simulated by the C library in memory this object owns."""

from __future__ import annotations

import copy as _copy
import ctypes
import dataclasses
import math
import struct
import sys
import threading
from dataclasses import dataclass
from typing import Any, Callable, Dict, Iterable, List, Literal, Optional

import numpy as np

from . import _errors, _lib
from ._compat import CallableFloat, CallableInt, CallableVec2
from ._errors import CircleCollideError, check
from ._types import Circle, Vec2, circle_from_c, circle_to_c, finite_vec2

L = _lib.lib
byref = ctypes.byref

MODES = {"exact": 0, "swept": 1, "discrete": 2}
#: restitution_mix: how a contact's restitution is made from its two sides' (CC_MIX_*)
MIXES = {"min": _lib.MIX_MIN, "max": _lib.MIX_MAX, "product": _lib.MIX_PRODUCT, "mean": _lib.MIX_MEAN}
ALL_BITS = 0xFFFFFFFF
#: the most circles (and walls) a world holds (the header's cc_world_def: 2^26)
MAX_CAPACITY = 1 << 26


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
class SensorEvent:
    """A circle ``visitor`` began (``begin`` True) or stopped (False) overlapping the sensor
    circle ``sensor`` at world time ``t``."""

    sensor: int
    visitor: int
    begin: bool
    t: float


@dataclass(frozen=True)
class WorldStats:
    """Counters since the world was made (cc_world_stats).

    ``virial``: the sum over circle-circle impulses of impulse times the distance between the
    centres at contact (in a periodic box, P A = N kT + virial / (2 t)); ``wall_impulse``: the
    sum of the impulses on walls.
    """

    collisions: int
    events: int
    stale_events: int
    pairs_tested: int
    cell_crossings: int
    max_overlap: float
    virial: float = 0.0
    wall_impulse: float = 0.0


@dataclass(frozen=True)
class CircleProps:
    """A circle's properties (cc_circle_props): its ``restitution`` in [0, 1], its own
    ``rolling_decel`` (>= 0), the filter bits ``category`` (what it is) and ``mask`` (what it
    interacts with), and whether it is a ``sensor``."""

    restitution: float = 1.0
    rolling_decel: float = 0.0
    category: int = 1
    mask: int = ALL_BITS
    sensor: bool = False


@dataclass(frozen=True)
class SegmentProps:
    """A wall's properties (cc_segment_props): ``restitution``, ``category``, ``mask``."""

    restitution: float = 1.0
    category: int = 1
    mask: int = ALL_BITS


@dataclass(frozen=True)
class CastHit:
    """What a cast circle touched first (cc_cast_hit).

    ``kind`` is ``"hit"`` (touched at fraction ``t`` of the path: the centre is at p + d t) or
    ``"overlap"`` (it already overlaps at p, t = 0). ``circle`` is the circle's id or -1,
    ``segment`` the wall's id or -1; ``normal`` points from the cast circle towards it.
    """

    kind: Literal["hit", "overlap"]
    circle: int
    segment: int
    t: float
    point: Vec2
    normal: Vec2


ContactCallback = Callable[[ContactEvent], None]
SensorCallback = Callable[[SensorEvent], None]

# ---- the callback trampolines ------------------------------------------------------------------
# The C world keeps the def's function pointers (and user pointer) in its own memory, and a copy
# of that memory keeps them too. So every World shares the same two trampolines, made once per
# process, with user NULL: a copy's memory then points at trampolines that are as valid for it
# as for the original. The trampolines find the World to call back through the thread's active
# world, which each call that may fire the callbacks sets around its C call (a stack: a callback
# of one world may step another).
_active = threading.local()


def _contact_trampoline(event: Any, user: Any) -> None:  # called from C: must never raise
    w = getattr(_active, "world", None)
    if w is not None:
        w._dispatch(event)


def _sensor_trampoline(event: Any, user: Any) -> None:  # called from C: must never raise
    w = getattr(_active, "world", None)
    if w is not None:
        w._dispatch_sensor(event)


_CONTACT_TRAMPOLINE = _lib.cc_contact_fn(_contact_trampoline)
_SENSOR_TRAMPOLINE = _lib.cc_sensor_fn(_sensor_trampoline)

#: the pickle format of a World (bumped when its state tuple changes)
_PICKLE_FORMAT = 1


class World:
    """A simulation of up to ``max_circles`` circles and ``max_segments`` static walls.

    ``mode`` is ``"exact"`` (every collision in time order), ``"swept"`` or ``"discrete"``;
    ``restitution`` in [0, 1] is what new circles and walls get (``set_circle_props`` and
    ``set_segment_props`` change it per body), and ``restitution_mix`` (``"min"``, ``"max"``,
    ``"product"`` or ``"mean"``) makes a contact's from its two sides' (between two sides that
    keep ``restitution``: that value, or its square under ``"product"``). ``rolling_decel`` (>= 0)
    is the deceleration new movable circles get (rolling to rest). ``period=(px, py)``: a
    component > 0 makes the world wrap along that axis (positions kept in [0, period)).
    ``uses`` (``USES_*`` bits, default ``USES_ALL``): what the world may use; its memory holds
    no more (``uses=0``, 1.0's world, is the smallest and fastest), and a call that needs what
    it left out (``set_circle_props`` with a restitution, filter, deceleration or sensor,
    ``set_segment_props``, ``rolling_decel`` without ``USES_ROLLING``) raises
    CircleCollideError (CC_ERR_INVALID), the world unchanged.

    ``max_events`` (an int >= 1) caps the events of one exact ``step``; ``None`` (the default)
    follows the C default, the automatic cap of 32 events per circle of ``max_circles`` and at
    least 10,000 (the C header's "Collapse"), sized so that a step that jams returns within
    about 0.2 s for 1,000 circles; ``step`` returns False at the cap. A long offline step (a
    whole run in one call) passes a larger cap or steps again to the same end time
    (``circlecollide.hard_disks.advance``).

    ``on_contact``, if given, is called with a ``ContactEvent`` for every impulse, and
    ``on_sensor`` with a ``SensorEvent`` for every sensor begin and end; both are also plain
    attributes, settable at any time on a world that has them: ``callbacks`` (default: whether
    a callback was given) installs the trampolines that call back into Python, about 1 us per
    collision even while both are None, so a world given no callback pays nothing for them
    (setting one later then raises ValueError: pass ``callbacks=True`` to set them later).
    A callback may read the world but not change it (``step``, ``add_circle``, ... raise
    "called from a callback"). An exception a callback raises is kept and raised again when
    the call that fired it (``step``, ``add_circle``, ``set_circle``, ``set_circle_props``,
    ``set_positions``, ``set_velocities``) returns (the C call itself cannot be interrupted;
    later events of that call are not reported). The world's memory is a buffer owned by this
    object.

    ``copy.copy(world)`` (or ``world.copy()``) and ``copy.deepcopy(world)`` make an independent
    world in the same state (a copy of the C memory, which is position-independent), with the
    same callbacks (deep-copied by ``deepcopy``); ``pickle`` carries a world made without
    callbacks to another process (one made with callbacks refuses: ``TypeError``). A copy or an
    unpickled world steps bit for bit as the original would. A copy made inside a callback is
    the world as the callback sees it, a world of its own at once (the C header's "Snapshots":
    it goes on from that contact, not bit for bit as the original).
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
        rolling_decel: float = 0.0,
        restitution_mix: str = "min",
        on_sensor: Optional[SensorCallback] = None,
        period: Iterable[float] = (0.0, 0.0),
        callbacks: Optional[bool] = None,
        uses: int = _lib.USES_ALL,
    ) -> None:
        for name, v, names in (("mode", mode, MODES), ("restitution_mix", restitution_mix, MIXES)):
            if not isinstance(v, str):
                raise TypeError(f"World: {name} must be a str, one of {sorted(names)}, got {v!r}")
            if v not in names:
                raise ValueError(f"World: {name} must be one of {sorted(names)}, got {v!r}")
        _errors.callback(on_contact, "on_contact", "World")
        _errors.callback(on_sensor, "on_sensor", "World")
        if callbacks is not None:
            _errors.boolean(callbacks, "callbacks", "World")
        d, self._lib_def_size = _lib.world_def_defaults()
        d.max_circles = _capacity(max_circles, "max_circles")
        d.max_segments = _capacity(max_segments, "max_segments")
        d.mode = MODES[mode]
        d.restitution = _errors.restitution(restitution, context="World")
        d.rest_speed = _errors.nonneg_finite(rest_speed, "rest_speed", "World")
        d.cell_size = _errors.nonneg_finite(cell_size, "cell_size", "World")
        if max_events is not None:
            if not 0 < _errors.integer(max_events, "max_events", "World") < 2**64:
                raise _errors.invalid("World", f"max_events must be an int in [1, 2^64), got {max_events!r}")
            d.max_events = int(max_events)
        d.rolling_decel = _errors.nonneg_finite(rolling_decel, "rolling_decel", "World")
        d.restitution_mix = MIXES[restitution_mix]
        px, py = finite_vec2(period, "period", "World")
        if px < 0 or py < 0:
            raise _errors.invalid("World", f"period must be >= 0 (0: open), got ({_errors.show(px)}, {_errors.show(py)})")
        d.period = _lib.cc_vec2(px, py)
        if not 0 <= _errors.integer(uses, "uses", "World") <= _lib.USES_ALL:
            raise _errors.invalid("World", f"uses must be USES_* bits in [0, USES_ALL], got {uses!r}")
        d.uses = int(uses)
        if d.rolling_decel != 0.0 and not d.uses & _lib.USES_ROLLING:
            raise _errors.invalid("World", "rolling_decel needs uses to include USES_ROLLING")
        # a library older than these declarations ignores the fields beyond its def: refuse to
        # drop a setting silently
        asked = {
            "rolling_decel": d.rolling_decel != 0.0,
            "restitution_mix": d.restitution_mix != _lib.MIX_MIN,
            "on_sensor": on_sensor is not None,
            "period": (px, py) != (0.0, 0.0),
            "uses": d.uses != _lib.USES_ALL,
        }
        for name, wanted in asked.items():
            if wanted and self._lib_def_size < _lib.field_end(_lib.cc_world_def, name):
                raise NotImplementedError(f"circlecollide: the C library loaded has no cc_world_def.{name}")
        self._on_contact = on_contact
        self._on_sensor = on_sensor
        self._error: Optional[BaseException] = None
        self._in_callback = 0  # > 0 while on_contact or on_sensor runs
        # The def holds the callbacks for the world's lifetime, so a world with callbacks always
        # gets the (shared) trampolines; they call self._on_contact / self._on_sensor at each
        # event, which makes the attributes plain settable properties.
        self._callbacks = bool(callbacks) if callbacks is not None else (on_contact is not None or on_sensor is not None)
        if not self._callbacks and (on_contact is not None or on_sensor is not None):
            raise ValueError("World: on_contact/on_sensor given with callbacks=False")
        self._has_sensor_fn = self._callbacks and self._lib_def_size >= _lib.field_end(_lib.cc_world_def, "on_sensor")
        self._trampoline = _CONTACT_TRAMPOLINE if self._callbacks else _lib.cc_contact_fn()
        self._sensor_trampoline = _SENSOR_TRAMPOLINE if self._has_sensor_fn else _lib.cc_sensor_fn()
        d.on_contact = self._trampoline
        d.on_sensor = self._sensor_trampoline
        d.user = None
        size = L.cc_world_size(byref(d))
        if size == 0:
            status = ctypes.c_int(0)  # the library's code for the def, which its size cannot say
            L.cc_world_init(None, 0, byref(d), byref(status))
            raise _world_refusal(status.value, px, py, d.cell_size)
        # 16-byte alignment: over-allocate and start at the first aligned address. numpy's zeros
        # come from calloc, whose large blocks are fresh pages zeroed by the system when first
        # touched: a world of a million circles (217 MB) costs nothing until it is used, where
        # a ctypes array is cleared byte by byte at once (0.36 s)
        self._size = int(size)
        self._buffer = np.zeros(size + 16, dtype=np.uint8)
        base = int(self._buffer.ctypes.data)
        self._addr = base + (-base % 16)
        status = ctypes.c_int(0)
        w = L.cc_world_init(self._addr, size, byref(d), byref(status))
        if not w:
            raise CircleCollideError(status.value or _lib.ERR_INVALID, "World")
        self._w = ctypes.c_void_p(w)
        # the validated def: what a copy or an unpickled world is rebuilt from (before its memory
        # is copied in)
        self._def_args: Dict[str, Any] = dict(
            max_circles=d.max_circles,
            max_segments=d.max_segments,
            mode=mode,
            restitution=d.restitution,
            rest_speed=d.rest_speed,
            cell_size=d.cell_size,
            max_events=None if max_events is None else int(d.max_events),
            rolling_decel=d.rolling_decel,
            restitution_mix=restitution_mix,
            period=(px, py),
            uses=d.uses,
        )
        self.max_circles = d.max_circles
        self.max_segments = d.max_segments
        self.mode = mode
        self.period: Vec2 = Vec2(px, py)
        self._cell_size = d.cell_size
        # cc_circle is 6 doubles (pos.x, pos.y, vel.x, vel.y, radius, mass): the scratch rows
        # are a float64 table (zeroed lazily, as the world) seen by ctypes as cc_circle[],
        # made once (np.ctypeslib.as_array per call parses the struct's format each time:
        # about half the cost of reading positions)
        self._table_view = np.zeros((max(1, self.max_circles), 6), dtype=np.float64)
        self._scratch = (_lib.cc_circle * max(1, self.max_circles)).from_buffer(self._table_view)
        self._ids_view = np.zeros(max(1, self.max_circles), dtype=np.intc)
        self._ids = (ctypes.c_int * max(1, self.max_circles)).from_buffer(self._ids_view)

    def __repr__(self) -> str:
        return f"World(max_circles={self.max_circles}, mode={self.mode!r}, circles={len(self)}, time={self.time!r})"

    # ---- copies and pickles -------------------------------------------------------------
    # The C world is position-independent (the header's "Memory": a memcpy of its bytes to other
    # aligned memory of the same size is a valid world), so a copy is a new World of the same
    # def with the bytes copied in, and a pickle carries the bytes. Stepping a copy gives, bit
    # for bit, what stepping the original gives.

    def _refuse_mid_call(self, what: str) -> None:
        if self._in_callback:
            raise _errors.invalid(
                what,
                f"{what} called from a callback (on_contact/on_sensor): the world is in the middle of a call; "
                f"{what} it after the call that fired the callback returns",
            )

    def _memory(self) -> bytes:
        return ctypes.string_at(self._addr, self._size)

    def _clone(self, on_contact: Optional[ContactCallback], on_sensor: Optional[SensorCallback]) -> "World":
        # also from inside a callback: the C world is busy only at its own address, so the copy
        # (other memory) is a world of its own, the world as the callback sees it (header:
        # "Snapshots")
        new = World(**self._def_args, callbacks=self._callbacks)
        if new._size != self._size:  # the same library, the same def: cannot happen
            raise RuntimeError(f"circlecollide: a copy's world has {new._size} bytes, the original {self._size}")
        ctypes.memmove(new._addr, self._addr, self._size)
        new._on_contact, new._on_sensor = on_contact, on_sensor
        return new

    def __copy__(self) -> "World":
        """``copy.copy``: an independent world in the same state (its own memory: stepping one
        does not move the other), calling the same ``on_contact`` / ``on_sensor`` objects."""
        return self._clone(self._on_contact, self._on_sensor)

    def __deepcopy__(self, memo: Dict[int, Any]) -> "World":
        """``copy.deepcopy``: as ``copy.copy``, with the callbacks deep-copied too (functions
        stay themselves, bound methods get a deep copy of their object)."""
        new = self._clone(None, None)
        memo[id(self)] = new  # a callback that refers back to this world gets the copy
        new._on_contact = _copy.deepcopy(self._on_contact, memo)
        new._on_sensor = _copy.deepcopy(self._on_sensor, memo)
        return new

    def copy(self) -> "World":
        """Same as ``copy.copy(world)``: an independent world in the same state."""
        return self.__copy__()

    def __reduce__(self) -> Any:
        """Pickling: the def and the world's memory, with what checks that the memory fits the
        library that unpickles it (its version, pointer size, byte order, the world's size and
        state hash).

        A World made with callbacks (``on_contact``/``on_sensor`` given, or ``callbacks=True``)
        does not pickle: its C memory holds the address of this process's callback trampoline,
        which means nothing in another process (pickling raises ``TypeError``; ``copy.deepcopy``
        copies such a world within the process). Make the world with ``callbacks=False`` (the
        default when no callback is given) to pickle it.
        """
        if self._callbacks:
            raise TypeError(
                "cannot pickle a World made with callbacks: its C memory holds the address of this process's "
                "callback trampoline, meaningless in another process. copy.deepcopy copies it within the "
                "process; a World made without callbacks (callbacks=False, the default when none is given) pickles"
            )
        self._refuse_mid_call("pickle")
        state = {
            "format": _PICKLE_FORMAT,
            "library": _lib.lib.cc_version_string().decode(),
            "platform": _platform(),
            "def": dict(self._def_args),
            "memory": self._memory(),
            "hash": int(self.hash),
        }
        return (_unpickle_world, (state,))

    # ---- contact callback ---------------------------------------------------------------

    def _call(self, fn: Callable[..., int], *args: Any) -> int:
        """Calls a C function that may fire the callbacks, with this world the thread's active
        one (what the shared trampolines call back)."""
        if not self._callbacks:
            return fn(*args)
        prev = getattr(_active, "world", None)
        _active.world = self
        try:
            return fn(*args)
        finally:
            _active.world = prev

    def _dispatch(self, event: Any) -> None:  # called from C: must never raise
        if self._error is not None or self._on_contact is None:
            return
        self._in_callback += 1
        try:
            e = event.contents
            self._on_contact(
                ContactEvent(
                    e.a, e.b, e.segment, e.t, Vec2(e.point.x, e.point.y), Vec2(e.normal.x, e.normal.y), e.impulse
                )
            )
        except BaseException as exc:  # noqa: BLE001  (re-raised by step)
            self._error = exc
        finally:
            self._in_callback -= 1

    def _dispatch_sensor(self, event: Any) -> None:  # called from C: must never raise
        if self._error is not None or self._on_sensor is None:
            return
        self._in_callback += 1
        try:
            e = event.contents
            self._on_sensor(SensorEvent(e.sensor, e.visitor, bool(e.begin), e.t))
        except BaseException as exc:  # noqa: BLE001  (re-raised by the call that fired it)
            self._error = exc
        finally:
            self._in_callback -= 1

    def _mutating(self, context: str) -> None:
        """Refuses a change of the world from inside on_contact / on_sensor (the library would
        return CC_ERR_BUSY, or CC_ERR_INVALID for a 1.1 def, and do nothing): says so."""
        if self._in_callback:
            raise _errors.busy(
                context,
                f"{context} called from a callback (on_contact/on_sensor): the world cannot be changed "
                "there; record what you need and act after the call that fired the callback returns",
            )

    def _firing(self, code: int, context: str) -> int:
        """check() for a call that may fire the callbacks: an exception one of them raised
        during the call is raised now (after a C error, which comes first)."""
        err, self._error = self._error, None
        code = check(code, context)
        if err is not None:
            raise err
        return code

    # ---- building the scene -------------------------------------------------------------

    def _placing(self, code: int, circle: Circle, context: str) -> int:
        """The result of add_circle or set_circle, a refusal named: a Circle is valid by
        construction and calls from a callback are refused before the library is asked, so
        the library's CC_ERR_RANGE (CC_ERR_INVALID from a 1.1 library) here is the period."""
        if code in (_lib.ERR_RANGE, _lib.ERR_INVALID) and (self.period[0] > 0 or self.period[1] > 0):
            self._error = None
            d = 2.0 * circle.radius
            raise _errors.out_of_range(
                context,
                f"a circle of radius {_errors.show(circle.radius)} is too wide for the period "
                f"({_errors.show(self.period[0])}, {_errors.show(self.period[1])}): along a periodic axis the "
                f"period must be at least 2 d + max(1.0625 d, cell_size) = {_errors.show(2 * d + max(1.0625 * d, self._cell_size))}",
            )
        return self._firing(code, context)

    def add_circle(self, circle: Circle) -> int:
        """Adds a circle (its state at the current world time); returns its id."""
        self._mutating("add_circle")
        c = circle_to_c(circle)
        self._error = None
        return self._placing(self._call(L.cc_world_add_circle, self._w, byref(c)), circle, "add_circle")

    #: rows per C call of add_circles: a chunk's table of cc_circle (48 bytes a row) stays at
    #: 12 MiB however many rows come
    ADD_CHUNK = 1 << 18

    def add_circles(self, pos: Any, vel: Any = 0.0, radius: Any = 1.0, mass: Any = 1.0) -> np.ndarray:
        """Adds n circles from arrays: ``pos`` of shape (n, 2), ``vel`` (n, 2) or one velocity,
        ``radius`` and ``mass`` (n,) or one value each (``mass`` inf: immovable). Returns their
        ids (an int array of n, in row order), which are what n ``add_circle`` calls in row
        order would return, and the world ends in the state those calls leave
        (cc_world_add_circles: one C call per ``ADD_CHUNK`` rows, not one per circle).

        Every row is checked before any is added: a row the library would refuse (a value not
        finite, a radius <= 0, a mass <= 0 or NaN, a circle too wide for the period, or more
        rows than the world has room for) raises ``CircleCollideError`` naming the row and the
        value, and nothing is added. In ``"exact"`` mode a circle put on top of another after
        the first step is pushed apart at once and may fire on_contact, as ``add_circle`` does.
        """
        self._mutating("add_circles")
        table = _circle_table(pos, vel, radius, mass, "add_circles")
        n = table.shape[0]
        # the first row the library would refuse decides, as for add_circle called row by row
        room = self.max_circles - len(self)
        self._check_rows(table[: room + 1])
        if n > room:
            raise CircleCollideError(
                _lib.ERR_FULL, "add_circles", f"row {room} does not fit: the world holds {self.max_circles} circles"
            )
        ids = np.empty(n, dtype=np.intc)
        failed = ctypes.c_int(-1)
        self._error = None
        for start in range(0, n, self.ADD_CHUNK):
            chunk = table[start : start + self.ADD_CHUNK]
            code = self._call(
                L.cc_world_add_circles,
                self._w,
                chunk.ctypes.data_as(ctypes.POINTER(_lib.cc_circle)),
                chunk.shape[0],
                ids[start:].ctypes.data_as(ctypes.POINTER(ctypes.c_int)),
                byref(failed),
            )
            if code < 0:  # what the checks above let through: rows before this chunk were added
                self._error = None
                row = start + failed.value if failed.value >= 0 else start
                raise CircleCollideError(code, f"add_circles: row {row} (rows before {start} were added)")
        self._firing(0, "add_circles")
        return ids

    def _check_rows(self, table: np.ndarray) -> None:
        """The rows' values as the library checks them (cc_circle's rules, and the room a
        circle needs in a periodic world: 2 diameters plus a cell along each periodic axis, the
        header's "Periodic boxes"), so that a bad row is named with its value before any row
        is added."""
        p, v, r, m = table[:, 0:2], table[:, 2:4], table[:, 4], table[:, 5]
        d = 2.0 * r
        need = 2.0 * d + np.maximum(1.0625 * d, self._def_args["cell_size"])
        ok = np.isfinite(table[:, 0:5]).all(axis=1) & (r > 0) & (m > 0)
        for period in self.period:
            if period > 0:
                ok &= need <= period
        if ok.all():  # the common case, in one pass
            return
        i = int(np.flatnonzero(~ok)[0])
        show = _errors.show
        if not np.isfinite(p[i]).all():
            say = f"pos must be finite, got ({show(p[i, 0])}, {show(p[i, 1])})"
        elif not np.isfinite(v[i]).all():
            say = f"vel must be finite, got ({show(v[i, 0])}, {show(v[i, 1])})"
        elif not (np.isfinite(r[i]) and r[i] > 0):
            say = f"radius must be finite and > 0, got {show(r[i])}"
        elif not m[i] > 0:
            say = f"mass must be > 0 (inf: immovable), got {show(m[i])}"
        else:
            axis = next(k for k, period in enumerate(self.period) if period > 0 and not need[i] <= period)
            say = (
                f"radius {show(r[i])} is too wide for the period {show(self.period[axis])} along {'xy'[axis]} "
                "(it needs 2 diameters plus a cell)"
            )
        raise _errors.invalid("add_circles", f"row {i}: {say}")

    def add_segment(self, p: Iterable[float], q: Iterable[float]) -> int:
        """Adds a static wall from p to q; returns its id."""
        self._mutating("add_segment")
        pv, qv = finite_vec2(p, "p", "add_segment"), finite_vec2(q, "q", "add_segment")
        s = _lib.cc_segment(_lib.cc_vec2(*pv), _lib.cc_vec2(*qv))
        return check(L.cc_world_add_segment(self._w, byref(s)), "add_segment")

    def remove_circle(self, id: int) -> None:
        """Removes a circle; the other ids stay valid."""
        self._mutating("remove_circle")
        check(L.cc_world_remove_circle(self._w, _c_int(id, "id")), "remove_circle")

    def circle(self, id: int) -> Circle:
        """A copy of the circle's state at the current world time."""
        out = _lib.cc_circle()
        check(L.cc_world_get_circle(self._w, _c_int(id, "id"), byref(out)), "circle")
        return circle_from_c(out)

    def set_circle(self, id: int, circle: Circle) -> None:
        """Replaces a circle's state at the current world time."""
        self._mutating("set_circle")
        c = circle_to_c(circle)
        self._error = None
        self._placing(self._call(L.cc_world_set_circle, self._w, _c_int(id, "id"), byref(c)), circle, "set_circle")

    def segment(self, id: int) -> tuple[Vec2, Vec2]:
        """The wall's end points."""
        s = _lib.cc_segment()
        check(L.cc_world_get_segment(self._w, _c_int(id, "id"), byref(s)), "segment")
        return Vec2(s.a.x, s.a.y), Vec2(s.b.x, s.b.y)

    # ---- running ------------------------------------------------------------------------

    def step(self, dt: float) -> bool:
        """Advances world time by dt. Returns False when the step stopped at max_events (the
        world is consistent at the last event; call again with what is left of dt to continue,
        as ``circlecollide.hard_disks.advance`` does), True otherwise."""
        self._mutating("step")
        dt = _errors.nonneg_finite(dt, "dt", "step")
        self._error = None
        code = self._call(L.cc_world_step, self._w, dt)
        if code in (_lib.ERR_RANGE, _lib.ERR_INVALID):  # dt is valid and this is no callback: a limit
            self._error = None
            raise _errors.out_of_range("step", self._step_limit(dt))
        return self._firing(code, "step") != _lib.EVENT_LIMIT

    def _step_limit(self, dt: float) -> str:
        """Which of the header's limits on a step (cc_world_step) a refused valid dt met."""
        now = self.time
        if not math.isfinite(now + dt):
            return f"dt = {_errors.show(dt)} at world time {_errors.show(now)}: the world time would overflow"
        if self.mode == "swept" and (self.period[0] > 0 or self.period[1] > 0):
            return (
                f"dt = {_errors.show(dt)} would carry a circle half a period or more "
                f"(period ({_errors.show(self.period[0])}, {_errors.show(self.period[1])})), which a periodic "
                "SWEPT world cannot sweep: take shorter steps"
            )
        return f"dt = {_errors.show(dt)} would carry a circle past 2^1017 (about 1.4e306) in a coordinate"

    @property
    def time(self) -> float:
        """Current world time."""
        return float(L.cc_world_time(self._w))

    @property
    def on_contact(self) -> Optional[ContactCallback]:
        """Called with a ``ContactEvent`` for every impulse, or None. Settable at any time
        (also from inside a callback: it takes effect at the next event)."""
        return self._on_contact

    @on_contact.setter
    def on_contact(self, fn: Optional[ContactCallback]) -> None:
        if fn is not None and not callable(fn):
            raise TypeError(f"on_contact must be callable or None, got {fn!r}")
        if fn is not None and not self._callbacks:
            raise ValueError("on_contact cannot be set on a World made without callbacks (pass callbacks=True)")
        self._on_contact = fn

    @property
    def on_sensor(self) -> Optional[SensorCallback]:
        """Called with a ``SensorEvent`` for every sensor begin and end, or None. Settable at
        any time."""
        return self._on_sensor

    @on_sensor.setter
    def on_sensor(self, fn: Optional[SensorCallback]) -> None:
        if fn is not None and not callable(fn):
            raise TypeError(f"on_sensor must be callable or None, got {fn!r}")
        if fn is not None and not self._callbacks:
            raise ValueError("on_sensor cannot be set on a World made without callbacks (pass callbacks=True)")
        if fn is not None and not self._has_sensor_fn:
            raise NotImplementedError("circlecollide: the C library loaded has no cc_world_def.on_sensor")
        self._on_sensor = fn

    @property
    def stats(self) -> WorldStats:
        """The world's counters since it was made (``WorldStats``, cc_world_get_stats)."""
        s = _lib.cc_world_stats()
        s.struct_size = ctypes.sizeof(s)
        check(L.cc_world_get_stats(self._w, byref(s)), "stats")
        return WorldStats(
            s.collisions,
            s.events,
            s.stale_events,
            s.pairs_tested,
            s.cell_crossings,
            s.max_overlap,
            s.virial,
            s.wall_impulse,
        )

    # ---- per-body properties ------------------------------------------------------------

    def circle_props(self, id: int) -> CircleProps:
        """The circle's properties (restitution, rolling_decel, category, mask, sensor)."""
        p = _lib.cc_circle_props()
        p.struct_size = ctypes.sizeof(p)
        check(L.cc_world_get_circle_props(self._w, _c_int(id, "id"), byref(p)), "circle_props")
        return CircleProps(p.restitution, p.rolling_decel, p.category, p.mask, bool(p.sensor))

    def set_circle_props(self, id: int, props: Optional[CircleProps] = None, **changes: Any) -> CircleProps:
        """Sets the circle's properties: ``props`` whole, or its current ones with the keyword
        ``changes`` (``restitution``, ``rolling_decel``, ``category``, ``mask``, ``sensor``).
        May fire on_contact and on_sensor (an overlap that starts to count). Returns the
        properties now in force."""
        base = props if props is not None else self.circle_props(id)
        if not isinstance(base, CircleProps):
            raise TypeError(f"expected CircleProps, got {type(base).__name__}")
        self._mutating("set_circle_props")
        new = dataclasses.replace(base, **changes)
        p = _lib.cc_circle_props(
            ctypes.sizeof(_lib.cc_circle_props),
            _errors.restitution(new.restitution, context="set_circle_props"),
            _errors.nonneg_finite(new.rolling_decel, "rolling_decel", "set_circle_props"),
            _u32(new.category, "category"),
            _u32(new.mask, "mask"),
            1 if _errors.boolean(new.sensor, "sensor", "set_circle_props") else 0,
        )
        self._error = None
        self._firing(
            self._call(L.cc_world_set_circle_props, self._w, _c_int(id, "id"), byref(p)), "set_circle_props"
        )
        return self.circle_props(id)

    def segment_props(self, id: int) -> SegmentProps:
        """The wall's properties (restitution, category, mask)."""
        p = _lib.cc_segment_props()
        p.struct_size = ctypes.sizeof(p)
        check(L.cc_world_get_segment_props(self._w, _c_int(id, "id"), byref(p)), "segment_props")
        return SegmentProps(p.restitution, p.category, p.mask)

    def set_segment_props(self, id: int, props: Optional[SegmentProps] = None, **changes: Any) -> SegmentProps:
        """Sets the wall's properties, as ``set_circle_props``. Returns those now in force."""
        base = props if props is not None else self.segment_props(id)
        if not isinstance(base, SegmentProps):
            raise TypeError(f"expected SegmentProps, got {type(base).__name__}")
        self._mutating("set_segment_props")
        new = dataclasses.replace(base, **changes)
        p = _lib.cc_segment_props(
            ctypes.sizeof(_lib.cc_segment_props),
            _errors.restitution(new.restitution, context="set_segment_props"),
            _u32(new.category, "category"),
            _u32(new.mask, "mask"),
        )
        check(L.cc_world_set_segment_props(self._w, _c_int(id, "id"), byref(p)), "set_segment_props")
        return self.segment_props(id)

    # ---- queries and state --------------------------------------------------------------

    def cast_circle(
        self,
        p: Iterable[float],
        d: Iterable[float],
        radius: float = 0.0,
        mask: int = ALL_BITS,
        *,
        ignore: Optional[int] = None,
    ) -> Optional[CastHit]:
        """The first circle or wall that a circle of ``radius`` (0: a ray) moving from p to
        p + d touches, the world held still at its current time; only bodies whose category
        meets ``mask``, sensors skipped, and never circle ``ignore`` (an id: a cast from the cue
        ball's centre leaves the cue ball out). ``None`` when it touches nothing."""
        out = _lib.cc_cast_hit()
        f = _filter(mask, ignore)
        code = check(
            L.cc_world_cast_circle_filtered(
                self._w,
                _lib.cc_vec2(*finite_vec2(p, "p", "cast_circle")),
                _errors.nonneg_finite(radius, "radius", "cast_circle"),
                _lib.cc_vec2(*finite_vec2(d, "d", "cast_circle")),
                byref(f),
                byref(out),
            ),
            "cast_circle",
        )
        if code == _lib.MISS:
            return None
        return CastHit(
            "hit" if code == _lib.HIT else "overlap",
            out.circle,
            out.segment,
            out.t,
            Vec2(out.point.x, out.point.y),
            Vec2(out.normal.x, out.normal.y),
        )

    def _ids_query(self, call: Callable[[Any, int], int], context: str) -> List[int]:
        cap = max(1, len(self))
        while True:
            ids = (ctypes.c_int * cap)()
            n = check(call(ids, cap), context)
            if n <= cap:
                return list(ids[:n])
            cap = n

    def query_circle(
        self, c: Iterable[float], radius: float = 0.0, mask: int = ALL_BITS, *, ignore: Optional[int] = None
    ) -> List[int]:
        """Ids (increasing) of the circles overlapping the disc of centre c and ``radius``
        (0: the circles whose interior holds c), whose category meets ``mask``, sensors included,
        circle ``ignore`` (an id) left out."""
        cv = _lib.cc_vec2(*finite_vec2(c, "c", "query_circle"))
        r, f = _errors.nonneg_finite(radius, "radius", "query_circle"), _filter(mask, ignore)
        return self._ids_query(
            lambda ids, cap: L.cc_world_query_circle_filtered(self._w, cv, r, byref(f), ids, cap), "query_circle"
        )

    def query_box(
        self, lo: Iterable[float], hi: Iterable[float], mask: int = ALL_BITS, *, ignore: Optional[int] = None
    ) -> List[int]:
        """Ids (increasing) of the circles that meet the closed box [lo, hi] (exactly: a circle
        touching it counts), whose category meets ``mask``, sensors included, circle ``ignore``
        left out. lo <= hi in both coordinates."""
        lo2, hi2 = finite_vec2(lo, "lo", "query_box"), finite_vec2(hi, "hi", "query_box")
        for k, axis in ((0, "x"), (1, "y")):
            if not lo2[k] <= hi2[k]:
                raise _errors.invalid(
                    "query_box", f"lo.{axis} must be <= hi.{axis}, got lo = {tuple(lo2)}, hi = {tuple(hi2)}"
                )
        lv, hv, f = _lib.cc_vec2(*lo2), _lib.cc_vec2(*hi2), _filter(mask, ignore)
        return self._ids_query(
            lambda ids, cap: L.cc_world_query_box_filtered(self._w, lv, hv, byref(f), ids, cap), "query_box"
        )

    @property
    def hash(self) -> int:
        """64-bit hash of the simulation state (cc_world_hash): equal for equal states, for
        replays and lock-step runs (compare hashes to find where two runs part). A property since
        1.2 (``w.hash()``, 1.1's spelling, still works and warns)."""
        return CallableInt(L.cc_world_hash(self._w))

    def unwrapped(self, id: int) -> Vec2:
        """Circle id's position without the periods taken off (its position along open axes)."""
        out = _lib.cc_vec2()
        check(L.cc_world_get_unwrapped(self._w, _c_int(id, "id"), byref(out)), "unwrapped")
        return Vec2(out.x, out.y)

    # ---- bulk state as numpy ------------------------------------------------------------

    @property
    def unwrapped_positions(self) -> np.ndarray:
        """(n, 2) float64 array of the live circles' positions without the periods taken off
        (``unwrapped`` for each), rows in id order as ``positions``: a read-only snapshot, one C
        call (cc_world_get_unwrapped_all). ``(unwrapped_positions - positions) / period`` is
        each circle's image along a periodic axis."""
        n = check(L.cc_world_get_unwrapped_all(self._w, None, None, 0), "unwrapped_positions")
        out = np.empty((n, 2), dtype=np.float64)
        if n:
            got = check(
                L.cc_world_get_unwrapped_all(self._w, None, out.ctypes.data_as(ctypes.POINTER(_lib.cc_vec2)), n),
                "unwrapped_positions",
            )
            assert got == n
        out.flags.writeable = False
        return out

    def _table(self) -> np.ndarray:
        n = check(L.cc_world_get_circles(self._w, self._ids, self._scratch, len(self._scratch)), "get_circles")
        # a view of the scratch rows (the callers copy what they return)
        return self._table_view[: min(n, len(self._scratch))]

    @property
    def ids(self) -> List[int]:
        """Ids of the live circles, in increasing order (the row order of positions)."""
        n = min(check(L.cc_world_get_circles(self._w, self._ids, None, len(self._ids)), "ids"), len(self._ids))
        ids: List[int] = self._ids_view[:n].tolist()
        return ids

    def __len__(self) -> int:
        return check(L.cc_world_get_circles(self._w, None, None, 0), "len")

    @property
    def positions(self) -> np.ndarray:
        """(n, 2) float64 array of the live circles' centres now, rows in id order: a read-only
        snapshot (writing raises ``ValueError``); change positions with ``set_positions``."""
        return _frozen(self._table()[:, 0:2])

    @property
    def velocities(self) -> np.ndarray:
        """(n, 2) float64 array of the live circles' velocities, rows in id order: a read-only
        snapshot; change velocities with ``set_velocities``."""
        return _frozen(self._table()[:, 2:4])

    @property
    def radii(self) -> np.ndarray:
        """(n,) float64 array of the live circles' radii, rows in id order (read-only)."""
        return _frozen(self._table()[:, 4])

    @property
    def masses(self) -> np.ndarray:
        """(n,) float64 array of the live circles' masses (inf: immovable), rows in id order
        (read-only)."""
        return _frozen(self._table()[:, 5])

    def set_positions(self, positions: Any) -> None:
        """Sets every live circle's centre from an (n, 2) array, rows in id order (as
        ``positions`` returns them), velocities kept.

        Each row goes through the world's validation as ``set_circle`` (cc_world_set_circle,
        circle by circle in id order): a non-finite row is refused before anything changes,
        with the row and the circle's id in the message; a refusal by the library names the row
        too (the rows before it are set). In ``"exact"`` mode a circle put on top of another
        is pushed apart at once, as ``set_circle`` does, and may fire on_contact.
        """
        self._set_columns(positions, 0, "set_positions")

    def set_velocities(self, velocities: Any) -> None:
        """Sets every live circle's velocity from an (n, 2) array, rows in id order, positions
        kept; validated as ``set_positions``. An immovable circle keeps a velocity too."""
        self._set_columns(velocities, 2, "set_velocities")

    def _set_columns(self, values: Any, col: int, context: str) -> None:
        self._mutating(context)
        try:
            a = np.asarray(values, dtype=np.float64)
        except (TypeError, ValueError):
            raise ValueError(f"{context}: expected an (n, 2) array of numbers, got {values!r}") from None
        n = check(L.cc_world_get_circles(self._w, self._ids, self._scratch, len(self._scratch)), context)
        if a.shape != (n, 2):
            raise ValueError(f"{context}: expected shape ({n}, 2) (one row per live circle), got {a.shape}")
        bad = np.flatnonzero(~np.isfinite(a).all(axis=1))
        if bad.size:
            i = int(bad[0])
            raise _errors.invalid(
                context,
                f"row {i} (circle {self._ids[i]}) must be finite, got ({_errors.show(a[i, 0])}, {_errors.show(a[i, 1])})",
            )
        ids = list(self._ids[:n])
        rows = [self._scratch[i] for i in range(n)]  # copies are not needed: each row is used once
        self._error = None
        for i, (cid, c) in enumerate(zip(ids, rows)):
            if col == 0:
                c.pos.x, c.pos.y = a[i, 0], a[i, 1]
            else:
                c.vel.x, c.vel.y = a[i, 0], a[i, 1]
            code = self._call(L.cc_world_set_circle, self._w, cid, byref(c))
            if code < 0:
                self._error = None
                raise CircleCollideError(code, f"{context}: row {i} (circle {cid})")
        self._firing(0, context)

    def write_gsd(self, path: Any, mode: str = "w", step: Optional[int] = None, **options: Any) -> int:
        """Writes the world's state now as a frame of a GSD trajectory (HOOMD-blue's format:
        positions within the box, images, velocities, diameters, masses, the box and which axes
        wrap, the world's time; ``circlecollide.trajectory`` says field by field). ``mode``
        ``"w"`` makes a new file, ``"a"`` appends a frame; ``step`` is its step (default: its
        index); ``options`` are ``Trajectory``'s (``precision``, ``open_box``). For many frames
        keep one ``circlecollide.trajectory.Trajectory`` open instead. Needs the ``gsd`` package
        (``pip install circlecollide[science]``). Returns the frame's index in the file."""
        from .trajectory import write_gsd

        return write_gsd(self, path, mode, step, **options)

    @property
    def kinetic_energy(self) -> float:
        """Sum of m |v|^2 / 2 over the movable circles. A property since 1.2 (``w.kinetic_energy()``,
        1.1's spelling, still works and warns)."""
        t = self._table()
        m = t[:, 5]
        movable = np.isfinite(m)
        return CallableFloat(0.5 * np.sum(m[movable] * (t[movable, 2] ** 2 + t[movable, 3] ** 2)))

    @property
    def momentum(self) -> Vec2:
        """Sum of m v over the movable circles. A property since 1.2 (``w.momentum()``, 1.1's
        spelling, still works and warns)."""
        t = self._table()
        m = t[:, 5]
        movable = np.isfinite(m)
        return CallableVec2(float(np.sum(m[movable] * t[movable, 2])), float(np.sum(m[movable] * t[movable, 3])))


def _platform() -> str:
    """What the layout of a world's memory depends on besides the library's version."""
    return f"{struct.calcsize('P') * 8}-bit {sys.byteorder}-endian"


def _unpickle_world(state: Dict[str, Any]) -> World:
    """Rebuilds a pickled World: a new world of the same def, the pickled memory copied in,
    after checking that this library can read it."""
    if state.get("format") != _PICKLE_FORMAT:
        raise ValueError(f"circlecollide: World pickle format {state.get('format')!r}, this version reads {_PICKLE_FORMAT}")
    here = _lib.lib.cc_version_string().decode()
    if state["library"] != here or state["platform"] != _platform():
        raise ValueError(
            f"circlecollide: this World was pickled with C library {state['library']} ({state['platform']}); "
            f"the one loaded is {here} ({_platform()}): a world's memory moves only between equal libraries"
        )
    w = World(**state["def"])
    memory = state["memory"]
    if len(memory) != w._size:
        raise ValueError(f"circlecollide: the pickled world has {len(memory)} bytes, its def needs {w._size}")
    ctypes.memmove(w._addr, memory, w._size)
    if w.hash != state["hash"]:
        raise ValueError("circlecollide: the unpickled world's state hash differs from the pickled one's (corrupt pickle?)")
    return w


def _circle_table(pos: Any, vel: Any, radius: Any, mass: Any, context: str) -> np.ndarray:
    """The rows as a C-contiguous (n, 6) float64 array: cc_circle's layout (pos.x, pos.y, vel.x,
    vel.y, radius, mass), so that a chunk of it is an array of cc_circle."""
    try:
        p = np.asarray(pos, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{context}: pos must be an (n, 2) array of numbers, got {pos!r}") from None
    if p.ndim != 2 or p.shape[1] != 2:
        raise ValueError(f"{context}: pos must have shape (n, 2), got {p.shape}")
    n = p.shape[0]
    table = np.empty((n, 6), dtype=np.float64)
    table[:, 0:2] = p
    for cols, value, name, shape in ((slice(2, 4), vel, "vel", (n, 2)), (4, radius, "radius", (n,)), (5, mass, "mass", (n,))):
        try:
            a = np.asarray(value, dtype=np.float64)
            table[:, cols] = np.broadcast_to(a, shape)
        except (TypeError, ValueError):
            raise ValueError(f"{context}: {name} must be one value or an array of shape {shape}, got {np.shape(value)}") from None
    return table


def _frozen(a: np.ndarray) -> np.ndarray:
    out = a.copy()
    out.flags.writeable = False
    return out


def _u32(v: int, name: str) -> int:
    x = _errors.integer(v, name)
    if not 0 <= x <= ALL_BITS:
        raise ValueError(f"{name} must be an int in [0, 0xFFFFFFFF], got {v!r}")
    return x


def _c_int(v: int, name: str) -> int:
    x = _errors.integer(v, name)
    if not -(2**31) <= x < 2**31:
        raise ValueError(f"{name} must be an int in the C int range, got {v!r}")
    return x


def _capacity(v: int, name: str) -> int:
    """A world's capacity: an int in [0, 2^26] (the header's limit: CC_ERR_RANGE beyond)."""
    x = _errors.integer(v, name, "World")
    if x < 0:
        raise _errors.invalid("World", f"{name} must be >= 0, got {x}")
    if x > MAX_CAPACITY:
        raise _errors.out_of_range("World", f"{name} must be at most 2^26 = {MAX_CAPACITY}, got {x}")
    return x


def _filter(mask: int, ignore: Optional[int]) -> Any:
    """The cc_query_filter of a cast or query: the mask, and the id left out (None: none)."""
    f = _lib.cc_query_filter()
    f.struct_size = ctypes.sizeof(f)
    f.mask = _u32(mask, "mask")
    f.ignore = -1 if ignore is None else _c_int(ignore, "ignore")
    return f


def _world_refusal(code: int, px: float, py: float, cell_size: float) -> CircleCollideError:
    """A def the library refused, whatever the binding checked: named where the cause is known
    (a period not wider than cell_size, the one limit of the def it leaves to the library)."""
    for p, axis in ((px, "x"), (py, "y")):
        if p > 0 and not p > cell_size:
            return _errors.out_of_range(
                "World", f"period.{axis} = {_errors.show(p)} must be wider than cell_size = {_errors.show(cell_size)}"
            )
    return CircleCollideError(code or _lib.ERR_INVALID, "World")



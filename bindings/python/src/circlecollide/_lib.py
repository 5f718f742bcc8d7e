"""Loads the C library with ctypes and declares its ABI: structs, prototypes, result codes.

This is the only module that knows the C layout; it mirrors include/circlecollide.h field for
field (tests/test_abi.py compares the two when the header is reachable).
"""

from __future__ import annotations

import ctypes
import glob
import os
import sys
from typing import Any, Optional

#: The library major version these declarations were written for (CC_VERSION_MAJOR).
EXPECTED_MAJOR = 1

# ---- result codes ----------------------------------------------------------------------------

MISS = 0
OK = 0
HIT = 1
OVERLAP = 2
EVENT_LIMIT = 3
ERR_INVALID = -1
ERR_NOT_FOUND = -2
ERR_FULL = -3
ERR_MEMORY = -4
ERR_VERSION = -5
# 1.2: a world made from a def past 1.1's gives these where 1.0 and 1.1 said ERR_INVALID
ERR_RANGE = -6
ERR_BUSY = -7

# ---- value types -----------------------------------------------------------------------------

c_double = ctypes.c_double
c_float = ctypes.c_float
c_int = ctypes.c_int


class cc_vec2(ctypes.Structure):
    _fields_ = [("x", c_double), ("y", c_double)]


class cc_circle(ctypes.Structure):
    _fields_ = [("pos", cc_vec2), ("vel", cc_vec2), ("radius", c_double), ("mass", c_double)]


class cc_segment(ctypes.Structure):
    _fields_ = [("a", cc_vec2), ("b", cc_vec2)]


class cc_contact(ctypes.Structure):
    _fields_ = [("t", c_double), ("point", cc_vec2), ("normal", cc_vec2), ("depth", c_double)]


class cc_vec2f(ctypes.Structure):
    _fields_ = [("x", c_float), ("y", c_float)]


class cc_circlef(ctypes.Structure):
    _fields_ = [("pos", cc_vec2f), ("vel", cc_vec2f), ("radius", c_float), ("mass", c_float)]


class cc_segmentf(ctypes.Structure):
    _fields_ = [("a", cc_vec2f), ("b", cc_vec2f)]


class cc_contactf(ctypes.Structure):
    _fields_ = [("t", c_float), ("point", cc_vec2f), ("normal", cc_vec2f), ("depth", c_float)]


_pd = ctypes.POINTER(c_double)


class cc_circle_soa(ctypes.Structure):
    _fields_ = [("px", _pd), ("py", _pd), ("vx", _pd), ("vy", _pd), ("radius", _pd)]


class cc_contact_event(ctypes.Structure):
    _fields_ = [
        ("a", c_int),
        ("b", c_int),
        ("segment", c_int),
        ("t", c_double),
        ("point", cc_vec2),
        ("normal", cc_vec2),
        ("impulse", c_double),
    ]


cc_contact_fn = ctypes.CFUNCTYPE(None, ctypes.POINTER(cc_contact_event), ctypes.c_void_p)


class cc_sensor_event(ctypes.Structure):
    _fields_ = [("sensor", c_int), ("visitor", c_int), ("begin", c_int), ("t", c_double)]


cc_sensor_fn = ctypes.CFUNCTYPE(None, ctypes.POINTER(cc_sensor_event), ctypes.c_void_p)

# restitution_mix values (CC_MIX_*)
MIX_MIN = 0
MIX_MAX = 1
MIX_PRODUCT = 2
MIX_MEAN = 3

# cc_world_def.uses bits (CC_USES_*, 1.2): what a world may use; it reserves memory for no more
USES_PROPS = 1
USES_SENSORS = 2
USES_ROLLING = 4
USES_CLOTH = 8
USES_ALL = 0xFFFF

#: CC_MAX_SENSORS: sensors a world holds at once
MAX_SENSORS = 64


class cc_world_def(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_size_t),
        ("max_circles", c_int),
        ("max_segments", c_int),
        ("mode", c_int),
        ("restitution", c_double),
        ("rest_speed", c_double),
        ("cell_size", c_double),
        ("max_events", ctypes.c_uint64),
        ("on_contact", cc_contact_fn),
        ("user", ctypes.c_void_p),
        # 1.1
        ("rolling_decel", c_double),
        ("restitution_mix", c_int),
        ("on_sensor", cc_sensor_fn),
        ("period", cc_vec2),
        # 1.2
        ("uses", ctypes.c_uint),
    ]


class cc_world_stats(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_size_t),
        ("collisions", ctypes.c_uint64),
        ("events", ctypes.c_uint64),
        ("stale_events", ctypes.c_uint64),
        ("pairs_tested", ctypes.c_uint64),
        ("cell_crossings", ctypes.c_uint64),
        ("max_overlap", c_double),
        # 1.1
        ("virial", c_double),
        ("wall_impulse", c_double),
    ]


class cc_circle_props(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_size_t),
        ("restitution", c_double),
        ("rolling_decel", c_double),
        ("category", ctypes.c_uint32),
        ("mask", ctypes.c_uint32),
        ("sensor", c_int),
    ]


class cc_segment_props(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_size_t),
        ("restitution", c_double),
        ("category", ctypes.c_uint32),
        ("mask", ctypes.c_uint32),
    ]


class cc_cast_hit(ctypes.Structure):
    _fields_ = [
        ("circle", c_int),
        ("segment", c_int),
        ("t", c_double),
        ("point", cc_vec2),
        ("normal", cc_vec2),
    ]


class cc_query_filter(ctypes.Structure):  # 1.2
    _fields_ = [
        ("struct_size", ctypes.c_size_t),
        ("mask", ctypes.c_uint32),
        ("ignore", c_int),
    ]


P = ctypes.POINTER
_vp = ctypes.c_void_p

# name: (restype, argtypes). The world functions take the opaque cc_world* as a void pointer.
PROTOTYPES: dict[str, tuple[Any, list[Any]]] = {
    "cc_version": (ctypes.c_uint, []),
    "cc_version_string": (ctypes.c_char_p, []),
    "cc_result_string": (ctypes.c_char_p, [c_int]),
    "cc_detect_static": (c_int, [P(cc_circle), P(cc_circle), P(cc_contact)]),
    "cc_separate": (c_int, [P(cc_circle), P(cc_circle)]),
    "cc_sweep": (c_int, [P(cc_circle), P(cc_circle), c_double, P(cc_contact)]),
    "cc_sweep_segment": (c_int, [P(cc_circle), P(cc_segment), c_double, P(cc_contact)]),
    "cc_sweep_rolling": (c_int, [P(cc_circle), c_double, P(cc_circle), c_double, c_double, P(cc_contact)]),
    "cc_sweep_segment_rolling": (c_int, [P(cc_circle), c_double, P(cc_segment), c_double, P(cc_contact)]),
    "cc_rolling_advance": (c_int, [P(cc_circle), c_double, c_double]),
    "cc_respond": (c_int, [P(cc_circle), P(cc_circle), P(cc_contact), c_double]),
    "cc_respond_segment": (c_int, [P(cc_circle), P(cc_contact), c_double]),
    "cc_closest_point_on_segment": (cc_vec2, [cc_vec2, P(cc_segment)]),
    "cc_sweep_many": (
        ctypes.c_long,
        [ctypes.c_size_t, P(cc_circle_soa), P(cc_circle_soa), c_double, _pd, P(c_int)],
    ),
    "cc_detect_staticf": (c_int, [P(cc_circlef), P(cc_circlef), P(cc_contactf)]),
    "cc_separatef": (c_int, [P(cc_circlef), P(cc_circlef)]),
    "cc_sweepf": (c_int, [P(cc_circlef), P(cc_circlef), c_float, P(cc_contactf)]),
    "cc_sweep_segmentf": (c_int, [P(cc_circlef), P(cc_segmentf), c_float, P(cc_contactf)]),
    "cc_sweep_rollingf": (c_int, [P(cc_circlef), c_float, P(cc_circlef), c_float, c_float, P(cc_contactf)]),
    "cc_sweep_segment_rollingf": (c_int, [P(cc_circlef), c_float, P(cc_segmentf), c_float, P(cc_contactf)]),
    "cc_rolling_advancef": (c_int, [P(cc_circlef), c_float, c_float]),
    "cc_respondf": (c_int, [P(cc_circlef), P(cc_circlef), P(cc_contactf), c_float]),
    "cc_respond_segmentf": (c_int, [P(cc_circlef), P(cc_contactf), c_float]),
    "cc_closest_point_on_segmentf": (cc_vec2f, [cc_vec2f, P(cc_segmentf)]),
    "cc_world_def_init": (None, [P(cc_world_def)]),
    "cc_world_def_init_sized": (None, [P(cc_world_def), ctypes.c_size_t]),
    "cc_world_size": (ctypes.c_size_t, [P(cc_world_def)]),
    "cc_world_init": (_vp, [_vp, ctypes.c_size_t, P(cc_world_def), P(c_int)]),
    "cc_world_add_circle": (c_int, [_vp, P(cc_circle)]),
    "cc_world_add_segment": (c_int, [_vp, P(cc_segment)]),
    "cc_world_remove_circle": (c_int, [_vp, c_int]),
    "cc_world_step": (c_int, [_vp, c_double]),
    "cc_world_get_circle": (c_int, [_vp, c_int, P(cc_circle)]),
    "cc_world_set_circle": (c_int, [_vp, c_int, P(cc_circle)]),
    "cc_world_get_circles": (c_int, [_vp, P(c_int), P(cc_circle), c_int]),
    "cc_world_get_segment": (c_int, [_vp, c_int, P(cc_segment)]),
    "cc_world_time": (c_double, [_vp]),
    "cc_world_get_stats": (c_int, [_vp, P(cc_world_stats)]),
    # 1.1
    "cc_world_get_unwrapped": (c_int, [_vp, c_int, P(cc_vec2)]),
    "cc_world_get_circle_props": (c_int, [_vp, c_int, P(cc_circle_props)]),
    "cc_world_set_circle_props": (c_int, [_vp, c_int, P(cc_circle_props)]),
    "cc_world_get_segment_props": (c_int, [_vp, c_int, P(cc_segment_props)]),
    "cc_world_set_segment_props": (c_int, [_vp, c_int, P(cc_segment_props)]),
    "cc_world_cast_circle": (c_int, [_vp, cc_vec2, c_double, cc_vec2, ctypes.c_uint32, P(cc_cast_hit)]),
    "cc_world_query_circle": (c_int, [_vp, cc_vec2, c_double, ctypes.c_uint32, P(c_int), c_int]),
    "cc_world_query_box": (c_int, [_vp, cc_vec2, cc_vec2, ctypes.c_uint32, P(c_int), c_int]),
    "cc_world_hash": (ctypes.c_uint64, [_vp]),
    # 1.2
    "cc_world_add_circles": (c_int, [_vp, P(cc_circle), c_int, P(c_int), P(c_int)]),
    "cc_world_get_unwrapped_all": (c_int, [_vp, P(c_int), P(cc_vec2), c_int]),
    "cc_world_cast_circle_filtered": (c_int, [_vp, cc_vec2, c_double, cc_vec2, P(cc_query_filter), P(cc_cast_hit)]),
    "cc_world_query_circle_filtered": (c_int, [_vp, cc_vec2, c_double, P(cc_query_filter), P(c_int), c_int]),
    "cc_world_query_box_filtered": (c_int, [_vp, cc_vec2, cc_vec2, P(cc_query_filter), P(c_int), c_int]),
}

#: Functions a library of our major version may lack while the world is being built; calling a
#: missing one raises NotImplementedError instead of failing the import.
OPTIONAL_PREFIX = "cc_world_"


class LibraryVersionError(ImportError):
    """The library found has another major version than these bindings were written for."""


def _library_names() -> list[str]:
    if sys.platform == "win32":
        return ["circlecollide*.dll", "libcirclecollide*.dll"]
    if sys.platform == "darwin":
        return ["libcirclecollide*.dylib"]
    return ["libcirclecollide.so*"]


def find_library() -> str:
    """Path of the library: $CIRCLECOLLIDE_LIBRARY, else the one installed in this package."""
    env = os.environ.get("CIRCLECOLLIDE_LIBRARY")
    if env:
        return env
    here = os.path.dirname(os.path.abspath(__file__))
    for pattern in _library_names():
        found = sorted(glob.glob(os.path.join(here, pattern)))
        if found:
            return found[0]
    raise ImportError(
        f"circlecollide: no C library in {here}; install the package with pip "
        "(it builds the library) or set CIRCLECOLLIDE_LIBRARY to a libcirclecollide"
    )


def check_version(found: int, expected_major: int = EXPECTED_MAJOR, path: str = "") -> None:
    """Refuses a library whose cc_version() major differs from expected_major."""
    major = found >> 16
    if major != expected_major:
        where = f" at {path}" if path else ""
        raise LibraryVersionError(
            f"circlecollide: the C library{where} is version "
            f"{major}.{(found >> 8) & 0xFF}.{found & 0xFF}, but these bindings need major "
            f"version {expected_major}; install matching versions of the two"
        )


class _Missing:
    """Stands for a symbol the loaded library does not export."""

    def __init__(self, name: str) -> None:
        self.name = name

    def __call__(self, *args: Any) -> Any:
        raise NotImplementedError(f"circlecollide: the C library has no {self.name}")


def load(path: Optional[str] = None, expected_major: int = EXPECTED_MAJOR) -> Any:
    """Opens the library, checks its major version, and declares every prototype."""
    path = path or find_library()
    lib = ctypes.CDLL(path)
    lib.cc_version.restype = ctypes.c_uint
    lib.cc_version.argtypes = []
    check_version(lib.cc_version(), expected_major, path)

    class Lib:
        pass

    out = Lib()
    for name, (restype, argtypes) in PROTOTYPES.items():
        try:
            fn = getattr(lib, name)
        except AttributeError:
            if name.startswith(OPTIONAL_PREFIX):
                setattr(out, name, _Missing(name))
                continue
            raise ImportError(f"circlecollide: the C library at {path} lacks {name}") from None
        fn.restype = restype
        fn.argtypes = argtypes
        setattr(out, name, fn)
    out._dll = lib  # type: ignore[attr-defined]
    out.path = path  # type: ignore[attr-defined]
    return out


lib = load()


def world_def_defaults() -> "tuple[cc_world_def, int]":
    """The library's defaults in our cc_world_def, and the size of the def that library knows.

    A 1.1 library has cc_world_def_init_sized, which fills the fields of a def of the size we
    give (what the C header's cc_world_def_init macro calls): it knows every field we declare.
    The exported cc_world_def_init fills 1.0's def only (it cannot know its caller's size); a
    1.0 library's writes its own sizeof, so it writes into a buffer with room to spare and only
    our fields are kept; the size it reports tells which fields it knows (the rest stay zero,
    their defaults).
    """
    if not isinstance(lib.cc_world_def_init_sized, _Missing):
        d = cc_world_def()
        lib.cc_world_def_init_sized(ctypes.byref(d), ctypes.sizeof(cc_world_def))
        return d, ctypes.sizeof(cc_world_def)
    room = (ctypes.c_uint64 * ((ctypes.sizeof(cc_world_def) + 4096) // 8))()
    lib.cc_world_def_init(ctypes.cast(room, ctypes.POINTER(cc_world_def)))
    d = cc_world_def.from_buffer_copy(room)
    lib_size = int(d.struct_size)
    d.struct_size = ctypes.sizeof(cc_world_def)
    return d, lib_size


def field_end(struct: Any, name: str) -> int:
    """Offset of the byte after field name: the struct_size a library needs to read it."""
    f = getattr(struct, name)
    return int(f.offset + f.size)


def result_string(code: int) -> str:
    """The library's own name and explanation of a result code."""
    s = lib.cc_result_string(code)
    return s.decode("utf-8", "replace") if s else f"result code {code}"

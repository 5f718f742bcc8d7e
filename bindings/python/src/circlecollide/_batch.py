"""sweep_many: the batch sweep over numpy columns, one C call for all pairs."""

from __future__ import annotations

import ctypes
import math
from typing import Any, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import _lib
from . import _errors
from ._errors import CircleCollideError

ArrayLike = npt.ArrayLike


def _column(x: ArrayLike, n: int) -> np.ndarray:
    return np.ascontiguousarray(np.broadcast_to(np.asarray(x, dtype=np.float64), (n,)))


def _points(x: ArrayLike, name: str) -> np.ndarray:
    a = np.asarray(x, dtype=np.float64)
    if a.ndim != 2 or a.shape[1] != 2:
        raise ValueError(f"{name} must have shape (n, 2), got {a.shape}")
    return a


def _ptr(a: np.ndarray) -> Any:
    return a.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


def sweep_many(
    a_pos: ArrayLike,
    a_vel: ArrayLike,
    a_radius: ArrayLike,
    b_pos: ArrayLike,
    b_vel: ArrayLike,
    b_radius: ArrayLike,
    t_max: float = math.inf,
    *,
    return_codes: bool = False,
) -> Union[np.ndarray, Tuple[np.ndarray, np.ndarray]]:
    """Sweeps n pairs (a[i], b[i]) in one call to cc_sweep_many.

    Positions and velocities have shape (n, 2); a radius is an array of n values or a scalar.
    Returns t, an array of n float64: the time of first contact for a hit, 0 for an overlap at
    t = 0, +inf for a miss. With ``return_codes=True`` returns ``(t, codes)`` where codes (int32)
    holds 0 (miss), 1 (hit) or 2 (overlap) per pair. Bit-identical to ``sweep`` pair by pair.
    Any invalid value (NaN, radius <= 0, ...) raises ``CircleCollideError`` (a ValueError) naming
    the first row that holds one (``sweep_many: row 3: a_radius[3] must be finite and > 0, got
    nan``), and nothing is returned.
    """
    ap, av, bp, bv = (
        _points(a_pos, "a_pos"),
        _points(a_vel, "a_vel"),
        _points(b_pos, "b_pos"),
        _points(b_vel, "b_vel"),
    )
    n = ap.shape[0]
    for name, arr in (("a_vel", av), ("b_pos", bp), ("b_vel", bv)):
        if arr.shape[0] != n:
            raise ValueError(f"{name} has {arr.shape[0]} rows, a_pos has {n}")
    try:
        ar, br = _column(a_radius, n), _column(b_radius, n)
    except ValueError:
        raise ValueError(f"radii must be scalars or arrays of {n} values") from None
    cols = [np.ascontiguousarray(m[:, k]) for m in (ap, av, bp, bv) for k in (0, 1)]
    soa_a = _lib.cc_circle_soa(*(_ptr(c) for c in cols[0:4]), _ptr(ar))
    soa_b = _lib.cc_circle_soa(*(_ptr(c) for c in cols[4:8]), _ptr(br))
    t = np.empty(n, dtype=np.float64)
    codes = np.empty(n, dtype=np.intc) if return_codes else None
    codes_ptr = codes.ctypes.data_as(ctypes.POINTER(ctypes.c_int)) if codes is not None else None
    tm = _errors.t_max(t_max, context="sweep_many")
    # also for n == 0, so that t_max is validated the same way
    r = _lib.lib.cc_sweep_many(n, ctypes.byref(soa_a), ctypes.byref(soa_b), tm, _ptr(t), codes_ptr)
    if r < 0:
        raise _first_bad_row(r, (("a_pos", ap), ("a_vel", av), ("b_pos", bp), ("b_vel", bv)), (("a_radius", ar), ("b_radius", br)))
    return (t, codes) if codes is not None else t


def _first_bad_row(code: int, points: Any, radii: Any) -> CircleCollideError:
    """The library refused the batch (it says CC_ERR_INVALID, not where): the first row whose
    position or velocity is not finite, or whose radius is not finite and > 0, named with its
    value. Only on that error path: the valid call pays nothing for it."""
    bad = []
    for name, a in points:
        rows = np.flatnonzero(~np.isfinite(a).all(axis=1))
        if rows.size:
            i = int(rows[0])
            bad.append((i, f"{name}[{i}] must be finite, got ({_errors.show(a[i, 0])}, {_errors.show(a[i, 1])})"))
    for name, r in radii:
        rows = np.flatnonzero(~(np.isfinite(r) & (r > 0)))
        if rows.size:
            i = int(rows[0])
            bad.append((i, f"{name}[{i}] must be finite and > 0, got {_errors.show(r[i])}"))
    if not bad:
        return CircleCollideError(code, "sweep_many")
    i, detail = min(bad)
    return CircleCollideError(code, "sweep_many", f"row {i}: {detail}")

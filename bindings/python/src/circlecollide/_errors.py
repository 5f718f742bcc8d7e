"""The exception raised for every error code the C library returns, and the binding's own
checks that name the argument and the value before the library is called."""

from __future__ import annotations

import math
from typing import Any, Optional

import numpy as np

from . import _lib

#: the C names of the error codes, for messages the binding writes itself
CODE_NAMES = {
    _lib.ERR_INVALID: "CC_ERR_INVALID",
    _lib.ERR_NOT_FOUND: "CC_ERR_NOT_FOUND",
    _lib.ERR_FULL: "CC_ERR_FULL",
    _lib.ERR_MEMORY: "CC_ERR_MEMORY",
    _lib.ERR_VERSION: "CC_ERR_VERSION",
    _lib.ERR_RANGE: "CC_ERR_RANGE",
    _lib.ERR_BUSY: "CC_ERR_BUSY",
}


class CircleCollideError(ValueError):
    """Bad input (or a full world, an unknown id, ...), a ``ValueError``.

    ``code`` holds the C result code (``CC_ERR_*``, negative). When the binding found the
    problem itself the message names the argument and its value (``radius must be finite and
    > 0, got nan (CC_ERR_INVALID)``); otherwise it is the library's own explanation of the code.
    """

    code: int

    def __init__(self, code: int, context: str = "", detail: Optional[str] = None) -> None:
        self.code = code
        if detail is not None:
            message = f"{detail} ({CODE_NAMES.get(code, f'result code {code}')})"
        else:
            message = _lib.result_string(code)
        super().__init__(f"{context}: {message}" if context else message)


def check(code: int, context: str = "") -> int:
    """Returns code when it is not an error, raises CircleCollideError otherwise."""
    if code < 0:
        raise CircleCollideError(code, context)
    return code


def invalid(context: str, detail: str) -> CircleCollideError:
    """A CircleCollideError with code CC_ERR_INVALID and the binding's own explanation."""
    return CircleCollideError(_lib.ERR_INVALID, context, detail)


def out_of_range(context: str, detail: str) -> CircleCollideError:
    """A CircleCollideError with code CC_ERR_RANGE (a value beyond a documented limit) and the
    binding's own explanation."""
    return CircleCollideError(_lib.ERR_RANGE, context, detail)


def busy(context: str, detail: str) -> CircleCollideError:
    """A CircleCollideError with code CC_ERR_BUSY (a change of the world from inside its own
    callback) and the binding's own explanation."""
    return CircleCollideError(_lib.ERR_BUSY, context, detail)


def show(v: Any) -> str:
    """A value as a message shows it: ints as ints, other numbers as Python floats
    (``nan``, ``-1.0``; numpy scalars lose their type name), anything else as its repr."""
    if isinstance(v, bool):
        return repr(v)
    if isinstance(v, int):
        return str(v)
    try:
        if hasattr(v, "dtype") and getattr(v.dtype, "kind", "") in "iu":
            return str(int(v))
        return repr(float(v))
    except (TypeError, ValueError, OverflowError):
        return repr(v)


def number(v: Any, name: str, context: str = "") -> float:
    """v as a float; a value that is not a real number (a string, even of digits, a bool, None,
    a complex) is a TypeError naming the argument."""
    if type(v) is float:  # the common case, first
        return v
    if isinstance(v, (str, bytes, complex, bool, np.bool_)):
        raise TypeError(f"{context + ': ' if context else ''}{name} must be a real number, got {v!r}")
    try:
        return float(v)
    except (TypeError, ValueError):
        raise TypeError(f"{context + ': ' if context else ''}{name} must be a real number, got {v!r}") from None


def integer(v: Any, name: str, context: str = "") -> int:
    """v as an int; anything but an integer (a float, even 5.0, a string, a bool) is a TypeError
    naming the argument."""
    if type(v) is int:
        return v
    if isinstance(v, bool) or not hasattr(v, "__index__"):
        raise TypeError(f"{context + ': ' if context else ''}{name} must be an int, got {v!r}")
    return int(v.__index__())


def boolean(v: Any, name: str, context: str = "") -> bool:
    """v as a bool: True, False (or numpy's); anything else is a TypeError naming the argument
    ('yes' and 1 are not a bool)."""
    if v is True or v is False:
        return v
    if isinstance(v, np.bool_):
        return bool(v)
    raise TypeError(f"{context + ': ' if context else ''}{name} must be True or False, got {v!r}")


def callback(v: Any, name: str, context: str = "") -> Any:
    """v when it is callable or None; anything else is a TypeError naming the argument (at once,
    not at the first event)."""
    if v is not None and not callable(v):
        raise TypeError(f"{context + ': ' if context else ''}{name} must be callable or None, got {v!r}")
    return v


def finite(v: Any, name: str, context: str = "") -> float:
    """A finite float, else CC_ERR_INVALID naming the argument and value."""
    x = number(v, name, context)
    if not math.isfinite(x):
        raise invalid(context, f"{name} must be finite, got {show(v)}")
    return x


def radius(v: Any, name: str = "radius", context: str = "") -> float:
    """A circle's radius: finite and > 0."""
    x = number(v, name, context)
    if not (math.isfinite(x) and x > 0):
        raise invalid(context, f"{name} must be finite and > 0, got {show(v)}")
    return x


def mass(v: Any, name: str = "mass", context: str = "") -> float:
    """A circle's mass: > 0, finite or +inf (immovable)."""
    x = number(v, name, context)
    if not x > 0:  # NaN fails too
        raise invalid(context, f"{name} must be > 0 (inf: immovable), got {show(v)}")
    return x


def t_max(v: Any, name: str = "t_max", context: str = "") -> float:
    """A sweep's horizon: >= 0, +inf allowed, not NaN."""
    x = number(v, name, context)
    if not x >= 0:
        raise invalid(context, f"{name} must be >= 0, got {show(v)}")
    return x


def nonneg_finite(v: Any, name: str, context: str = "") -> float:
    """A time step, a time or a deceleration: finite and >= 0."""
    x = number(v, name, context)
    if not (math.isfinite(x) and x >= 0):
        raise invalid(context, f"{name} must be finite and >= 0, got {show(v)}")
    return x


def restitution(v: Any, name: str = "restitution", context: str = "") -> float:
    """A restitution: in [0, 1]."""
    x = number(v, name, context)
    if not 0 <= x <= 1:
        raise invalid(context, f"{name} must be in [0, 1], got {show(v)}")
    return x

"""The exception raised for every error code the C library returns."""

from __future__ import annotations

from . import _lib


class CircleCollideError(ValueError):
    """Bad input (or a full world, an unknown id, ...): the message is the library's own.

    ``code`` holds the C result code (``CC_ERR_*``, negative).
    """

    def __init__(self, code: int, context: str = "") -> None:
        self.code = code
        message = _lib.result_string(code)
        super().__init__(f"{context}: {message}" if context else message)


def check(code: int, context: str = "") -> int:
    """Returns code when it is not an error, raises CircleCollideError otherwise."""
    if code < 0:
        raise CircleCollideError(code, context)
    return code

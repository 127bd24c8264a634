# SPDX-License-Identifier: MIT
"""The exceptions of sinew: one class per C status (rb/base.h's rb_status),
all under :class:`Error`, each carrying the C library's own message.

The C libraries report a failure by a status and a message on the calling
thread (``rb_last_error()``, which names the function, the argument and
what was expected). Every call the package makes that can fail is checked
here, right after it returns: a status other than RB_OK becomes the
exception of that status, its text the C message. Misuse the C side cannot
see (a closed world, a destroyed object's handle) raises before any call.
"""
import numbers

from ._lib import rb


class Error(Exception):
    """A sinew C call failed. ``status`` is the C status name
    ("RB_ERR_INVALID_ARGUMENT"), ``str()`` the C message."""

    status = "RB_ERR"

    def __init__(self, message, status=None):
        super().__init__(message)
        if status is not None:
            self.status = status


class InvalidArgument(Error, ValueError):
    """RB_ERR_INVALID_ARGUMENT: NaN, infinity, out of range, a bad index or name."""

    status = "RB_ERR_INVALID_ARGUMENT"


class StaleId(Error):
    """RB_ERR_STALE_ID: the object was destroyed."""

    status = "RB_ERR_STALE_ID"


class ForeignId(Error):
    """RB_ERR_FOREIGN_ID: the object belongs to another world (or is none)."""

    status = "RB_ERR_FOREIGN_ID"


class DegenerateShape(Error, ValueError):
    """RB_ERR_DEGENERATE_SHAPE: zero size, collinear or coincident points."""

    status = "RB_ERR_DEGENERATE_SHAPE"


class NotConvex(Error, ValueError):
    """RB_ERR_NOT_CONVEX: polygon points that are not their own convex hull."""

    status = "RB_ERR_NOT_CONVEX"


class NoMass(Error, ValueError):
    """RB_ERR_NO_MASS: a dynamic body would get zero or negative mass."""

    status = "RB_ERR_NO_MASS"


class Locked(Error):
    """RB_ERR_LOCKED: the world is inside a step (a callback tried to change it)."""

    status = "RB_ERR_LOCKED"


class OutOfMemory(Error, MemoryError):
    """RB_ERR_OUT_OF_MEMORY."""

    status = "RB_ERR_OUT_OF_MEMORY"


class NotFinite(Error, ArithmeticError):
    """RB_ERR_NOT_FINITE: a step made a body's state non-finite; the world
    was put back as it was before the step."""

    status = "RB_ERR_NOT_FINITE"


class Closed(Error):
    """The world or model was closed: its C object is freed, and every
    object of it (bodies, shapes, joints, muscles) is unusable."""

    status = "closed"


# In rb_status order (rb/base.h): RB_OK is 0.
_BY_STATUS = {
    1: InvalidArgument,
    2: StaleId,
    3: ForeignId,
    4: DegenerateShape,
    5: NotConvex,
    6: NoMass,
    7: Locked,
    8: OutOfMemory,
    9: NotFinite,
}


def clear():
    """Resets the thread's last status to RB_OK, for the C getters that
    record an error but do not clear it on success."""
    rb.rb_report_error(0, b"")


def raise_status(status):
    """Raises the exception of a C status with the C message."""
    message = (rb.rb_last_error() or b"").decode("utf-8", "replace")
    name = (rb.rb_status_name(status) or b"RB_ERR").decode()
    cls = _BY_STATUS.get(status, Error)
    raise cls(message or name, name)


def check(status):
    """For a function returning rb_status."""
    if status != 0:
        raise_status(status)


def checked(function, *args):
    """Calls a C getter that reports a failure through rb_last_status()
    rather than its result, and raises that failure."""
    clear()
    result = function(*args)
    status = rb.rb_last_status()
    if status != 0:
        raise_status(status)
    return result


# ------------------------------------------------------ argument conversions


def real(name, value):
    """A float from a Python number (NaN and infinity pass: the C side
    refuses them with its own message). Anything else is a TypeError."""
    if isinstance(value, numbers.Real):
        return float(value)
    raise TypeError(f"{name} must be a real number, got {type(value).__name__} {value!r}")


def integer(name, value):
    """An int that fits the C int it is passed as (ctypes would wrap a larger one)."""
    if not isinstance(value, numbers.Integral) or isinstance(value, bool):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__} {value!r}")
    if not -(2**31) <= value < 2**31:
        raise InvalidArgument(f"{name} is {value}, expected a 32-bit integer")
    return int(value)


def bits(name, value):
    """A 32-bit unsigned mask (collision categories and masks)."""
    if not isinstance(value, numbers.Integral) or isinstance(value, bool):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__} {value!r}")
    if not 0 <= value < 2**32:
        raise InvalidArgument(f"{name} is {value}, expected 32 bits (0 .. 0xFFFFFFFF)")
    return int(value)


def boolean(name, value):
    if isinstance(value, (bool, numbers.Integral)):
        return bool(value)
    raise TypeError(f"{name} must be a bool, got {type(value).__name__} {value!r}")


def text(name, value):
    if isinstance(value, str):
        return value.encode("utf-8")
    raise TypeError(f"{name} must be a str, got {type(value).__name__} {value!r}")


def pair(name, value):
    """An (x, y) pair of real numbers: a tuple, a list, a numpy array of 2, or a Vec2."""
    if hasattr(value, "x") and hasattr(value, "y"):
        return real(name + ".x", value.x), real(name + ".y", value.y)
    try:
        items = list(value)
    except TypeError:
        raise TypeError(f"{name} must be a pair (x, y), got {type(value).__name__} {value!r}") from None
    if len(items) != 2:
        raise TypeError(f"{name} must be a pair (x, y), got {len(items)} items")
    return real(name + "[0]", items[0]), real(name + "[1]", items[1])

"""Argument checks shared by the package: every bad argument is a one-line ValueError or
TypeError naming the argument, the value (shortened) and what is allowed; none escapes as a
bare OverflowError (a Python int too large for a float or for 64 bits)."""

from __future__ import annotations

import functools
import math
import os

import numpy as np

U64_MAX = 2**64 - 1

#: The largest float's magnitude, as messages show it.
_FLOAT_MAX = "1.8e308"


def shown(x) -> str:
    """`x` as a message shows it: short. An integer of more than 20 digits in exponent form
    (its digits are never formed: Python refuses str() of one beyond 4300 digits), anything
    else as its repr cut to 60 characters."""
    if isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_)):
        x = int(x)
        if abs(x) < 10**20:
            return str(x)
        e = math.log10(abs(x))
        exponent = math.floor(e)
        mantissa = 10 ** (e - exponent)
        return f"{'-' if x < 0 else ''}{mantissa:.3g}e+{exponent}"
    try:
        r = repr(x)
    except Exception:  # a repr that fails is no reason to hide the argument's name
        r = f"<{type(x).__name__}>"
    r = " ".join(r.split())
    return r if len(r) <= 60 else r[:59] + "…"


def _names_memory(convert):
    """`convert(name, x, …)`, whose MemoryError (NumPy's, converting a large array to
    contiguous float64 or uint64) names the argument."""

    @functools.wraps(convert)
    def checked(name, x, *args):
        try:
            return convert(name, x, *args)
        except MemoryError as e:
            if str(e).startswith(f"invalid `{name}`"):
                raise
            shape = getattr(x, "shape", None)
            value = f"an array of shape {shape}" if shape is not None else "its values"
            raise MemoryError(
                f"invalid `{name}` = {value}: allowed a size that fits in memory: its conversion "
                f"to a contiguous array could not be allocated ({' '.join(str(e).split())})"
            ) from None

    return checked


@_names_memory
def float_array(name: str, x) -> np.ndarray:
    """`x` as a float64 array: a float64 array is returned as it is (no copy); other real
    floats and integers are converted; anything else is a TypeError."""
    if isinstance(x, np.ndarray):
        a = x
    else:
        try:
            a = np.asarray(x)
        except (ValueError, TypeError) as e:
            raise TypeError(f"`{name}`: not an array of numbers ({e})") from None
    if a.dtype == np.float64:
        return a
    if a.dtype.kind in "fiu":
        return a.astype(np.float64)
    raise TypeError(
        f"`{name}` has dtype {a.dtype}: allowed float64 (or another real float or integer type)"
    )


@_names_memory
def vec3(name: str, x) -> tuple[np.ndarray, int | None]:
    """`x` as a C-contiguous float64 `(rows, 3)` array and its row count (`None` for a single
    3-vector, broadcast to every hit). No copy when `x` is already C-contiguous float64."""
    a = float_array(name, x)
    if a.ndim == 1 and a.shape[0] == 3:
        return np.ascontiguousarray(a).reshape(1, 3), None
    if a.ndim == 2 and a.shape[1] == 3:
        return np.ascontiguousarray(a), a.shape[0]
    raise ValueError(f"`{name}` has shape {a.shape}: allowed (3,) or (n, 3)")


@_names_memory
def per_hit_float(name: str, x) -> tuple[np.ndarray, int | None]:
    """A per-hit number: a scalar (broadcast) or an `(n,)` array, as contiguous float64."""
    a = float_array(name, x)
    if a.ndim == 0:
        return a.reshape(1), None
    if a.ndim == 1:
        return np.ascontiguousarray(a), a.shape[0]
    raise ValueError(f"`{name}` has shape {a.shape}: allowed a number or (n,)")


@_names_memory
def per_hit_u64(name: str, x) -> tuple[np.ndarray, int | None]:
    """A per-hit key: a non-negative integer (broadcast) or an `(n,)` array of them, as
    contiguous uint64."""
    if isinstance(x, (bool, np.bool_)):
        raise TypeError(f"`{name}` is a bool: allowed integers 0 to 2**64 - 1")
    if isinstance(x, np.ndarray):
        a = x
    else:
        try:
            a = np.asarray(x)
        except (ValueError, TypeError, OverflowError) as e:
            raise TypeError(f"`{name}`: not an array of integers ({e})") from None
    if a.dtype.kind not in "iu":
        if a.dtype == object and a.ndim == 0 and isinstance(x, int):
            raise ValueError(f"invalid `{name}` = {shown(x)}: allowed integers 0 to 2**64 - 1")
        raise TypeError(f"`{name}` has dtype {a.dtype}: allowed integers 0 to 2**64 - 1")
    if a.dtype.kind == "i" and a.size and a.min() < 0:
        bad = a.min()
        raise ValueError(f"invalid `{name}` = {bad}: allowed integers 0 to 2**64 - 1")
    a = a.astype(np.uint64, copy=False)
    if a.ndim == 0:
        return a.reshape(1), None
    if a.ndim == 1:
        return np.ascontiguousarray(a), a.shape[0]
    raise ValueError(f"`{name}` has shape {a.shape}: allowed an integer or (n,)")


def count(name: str, x, lo: int, hi: int) -> int:
    """An integer in [lo, hi]."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
        raise TypeError(f"`{name}` = {shown(x)}: allowed an integer from {lo} to {hi}")
    if not lo <= int(x) <= hi:
        raise ValueError(f"invalid `{name}` = {shown(x)}: allowed an integer from {lo} to {hi}")
    return int(x)


def threads(x) -> int:
    """Threads to run on: `None` is every core (0 for the core)."""
    if x is None:
        return 0
    return count("threads", x, 1, 1024)


def seed(x) -> int:
    """A seed, 0 to 2**64 - 1."""
    return count("seed", x, 0, U64_MAX)


def number(name: str, x, optional: bool = False):
    """A real number as float (`None` passes when `optional`); NaN and infinities pass, for
    the library to refuse with its own message; an integer too large for a float is a
    ValueError naming `name`."""
    if x is None and optional:
        return None
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, float, np.integer, np.floating)):
        allowed = "a real number or None" if optional else "a real number"
        raise TypeError(f"`{name}` = {shown(x)}: allowed {allowed}")
    try:
        return float(x)
    except OverflowError:
        raise ValueError(
            f"invalid `{name}` = {shown(x)}: allowed a real number (a float: at most {_FLOAT_MAX} in magnitude)"
        ) from None


def _length(x):
    """len(x) of a sequence that is no string, else None (a scalar, a 0-d array, a string)."""
    if isinstance(x, (str, bytes)):
        return None
    try:
        return len(x)
    except TypeError:
        return None


def pair(name: str, x, what: str) -> tuple[float, float]:
    """Two real numbers `what` (e.g. "(dx, dy) in m"), as floats."""
    allowed = f"a pair of real numbers {what}"
    n = _length(x)
    if n is None:
        raise TypeError(f"`{name}` = {shown(x)}: allowed {allowed}")
    if n != 2:
        raise ValueError(f"invalid `{name}` = {shown(x)}: allowed {allowed}")
    a, b = x
    return number(name, a), number(name, b)


def numbers(name: str, x, most: int) -> list[float]:
    """A sequence of at most `most` real numbers, as floats; its length is checked before
    anything is converted."""
    n = _length(x)
    if n is None:
        raise TypeError(f"`{name}` = {shown(x)}: allowed a sequence of at most {most} real numbers")
    if n > most:
        raise ValueError(f"invalid `{name}` = {n} values: allowed at most {most}")
    return [number(name, v) for v in x]


def pairs(name: str, x, names: tuple[str, str], most: int) -> list[tuple[float, float]]:
    """A sequence of 1 to `most` pairs of real numbers (`names`: what each holds), as
    floats; its length is checked before anything is converted."""
    allowed = f"1 to {most} ({names[0]}, {names[1]}) pairs"
    n = _length(x)
    if n is None:
        raise TypeError(f"`{name}` = {shown(x)}: allowed {allowed}")
    if not 1 <= n <= most:
        raise ValueError(f"invalid `{name}` = {n} pairs: allowed {allowed}")
    out = []
    for p in x:
        if _length(p) != 2:
            raise TypeError(f"`{name}` holds {shown(p)}: allowed {allowed}")
        a, b = p
        try:
            out.append((number(names[0], a), number(names[1], b)))
        except (TypeError, ValueError) as e:
            raise type(e)(f"{e} (in `{name}`)") from None
    return out


def text(key: str, x) -> str:
    """A name (str)."""
    if not isinstance(x, str):
        raise TypeError(f"`{key}` = {shown(x)}: allowed a name (str)")
    return x


def path(key: str, x) -> str:
    """A file path (str or os.PathLike)."""
    try:
        p = os.fspath(x)
    except TypeError:
        raise TypeError(f"`{key}` = {shown(x)}: allowed a path (str or os.PathLike)") from None
    if isinstance(p, bytes):
        p = os.fsdecode(p)
    return p


def name(key: str, x):
    """A name (str) or None."""
    if x is not None and not isinstance(x, str):
        raise TypeError(f"`{key}` = {shown(x)}: allowed a name (str) or None")
    return x

"""Argument checks shared by the package: every bad argument is a one-line ValueError or
TypeError naming the argument, the value and what is allowed."""

from __future__ import annotations

import numpy as np

U64_MAX = 2**64 - 1


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


def vec3(name: str, x) -> tuple[np.ndarray, int | None]:
    """`x` as a C-contiguous float64 `(rows, 3)` array and its row count (`None` for a single
    3-vector, broadcast to every hit). No copy when `x` is already C-contiguous float64."""
    a = float_array(name, x)
    if a.ndim == 1 and a.shape[0] == 3:
        return np.ascontiguousarray(a).reshape(1, 3), None
    if a.ndim == 2 and a.shape[1] == 3:
        return np.ascontiguousarray(a), a.shape[0]
    raise ValueError(f"`{name}` has shape {a.shape}: allowed (3,) or (n, 3)")


def per_hit_float(name: str, x) -> tuple[np.ndarray, int | None]:
    """A per-hit number: a scalar (broadcast) or an `(n,)` array, as contiguous float64."""
    a = float_array(name, x)
    if a.ndim == 0:
        return a.reshape(1), None
    if a.ndim == 1:
        return np.ascontiguousarray(a), a.shape[0]
    raise ValueError(f"`{name}` has shape {a.shape}: allowed a number or (n,)")


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
            raise ValueError(f"invalid `{name}` = {x}: allowed integers 0 to 2**64 - 1")
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
        raise TypeError(f"`{name}` = {x!r}: allowed an integer from {lo} to {hi}")
    if not lo <= int(x) <= hi:
        raise ValueError(f"invalid `{name}` = {x}: allowed an integer from {lo} to {hi}")
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
    the library to refuse with its own message."""
    if x is None and optional:
        return None
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, float, np.integer, np.floating)):
        allowed = "a real number or None" if optional else "a real number"
        raise TypeError(f"`{name}` = {x!r}: allowed {allowed}")
    return float(x)


def name(key: str, x):
    """A name (str) or None."""
    if x is not None and not isinstance(x, str):
        raise TypeError(f"`{key}` = {x!r}: allowed a name (str) or None")
    return x

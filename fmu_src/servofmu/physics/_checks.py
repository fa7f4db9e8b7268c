"""Argument checks shared by the physics functions.

Every public physics function rejects bad input with a :class:`ValueError` that names the
argument, its offending value and the valid range, instead of returning NaN.
"""

from __future__ import annotations

import math

import numpy as np


def _first_bad(values: np.ndarray, bad: np.ndarray) -> float:
    return float(values[bad].flat[0])


def _describe(lo: float | None, hi: float | None, lo_open: bool, hi_open: bool) -> str:
    left = "(" if lo_open or lo is None else "["
    right = ")" if hi_open or hi is None else "]"
    lo_s = "-inf" if lo is None else f"{lo:g}"
    hi_s = "inf" if hi is None else f"{hi:g}"
    return f"{left}{lo_s}, {hi_s}{right}"


def check_range(
    name: str,
    value,
    lo: float | None = None,
    hi: float | None = None,
    *,
    lo_open: bool = False,
    hi_open: bool = False,
    unit: str = "",
):
    """Return ``value`` as float or float array after checking it is finite and within range.

    ``lo_open``/``hi_open`` exclude the bound itself. Raises ``ValueError`` naming ``name``,
    the first offending value and the valid range.
    """
    unit_s = f" {unit}" if unit else ""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        v = float(value)
        ok = math.isfinite(v)
        if ok and lo is not None:
            ok = v > lo if lo_open else v >= lo
        if ok and hi is not None:
            ok = v < hi if hi_open else v <= hi
        if not ok:
            rng = _describe(lo, hi, lo_open, hi_open)
            raise ValueError(f"{name} = {v!r}{unit_s} is outside the valid range {rng}{unit_s}")
        return v
    arr = np.asarray(value, dtype=float)
    bad = ~np.isfinite(arr)
    if lo is not None:
        bad |= (arr <= lo) if lo_open else (arr < lo)
    if hi is not None:
        bad |= (arr >= hi) if hi_open else (arr > hi)
    if bad.any():
        rng = _describe(lo, hi, lo_open, hi_open)
        raise ValueError(
            f"{name} = {_first_bad(arr, bad)!r}{unit_s} is outside the valid range {rng}{unit_s}"
        )
    return arr if arr.ndim else float(arr)


def check_positive(name: str, value, unit: str = ""):
    """Finite and strictly positive."""
    return check_range(name, value, 0.0, None, lo_open=True, unit=unit)


def check_nonnegative(name: str, value, unit: str = ""):
    """Finite and >= 0."""
    return check_range(name, value, 0.0, None, unit=unit)


def check_finite(name: str, value, unit: str = ""):
    """Finite (any sign)."""
    return check_range(name, value, unit=unit)


def check_temperature(name: str, value):
    """Absolute temperature in kelvin: finite and > 0 K."""
    return check_range(name, value, 0.0, None, lo_open=True, unit="K")


def check_choice(name: str, value: str, choices) -> str:
    """One of a fixed set of strings."""
    if value not in choices:
        raise ValueError(f"{name} = {value!r} is not one of {sorted(choices)}")
    return value

"""Argument checks shared by the physics functions.

Every public physics function rejects bad input with a :class:`ValueError` that names the
argument, its offending value and the valid range, instead of returning NaN.
"""

from __future__ import annotations

import difflib
import math

import numpy as np

#: The temperatures the models accept [K]: the FMUs' declared range of every temperature
#: input and parameter (−100…+200 °C).
TEMPERATURE_RANGE = (173.15, 473.15)


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

    Parameters
    ----------
    name : str
        The variable's name, for the message.
    value : float or array_like
        The value(s).
    lo, hi : float or None
        Bounds (None: unbounded).
    lo_open, hi_open : bool
        Exclude the bound itself.
    unit : str
        The unit, for the message.

    Returns
    -------
    float or ndarray
        ``value`` as float (array); ValueError otherwise.

    Examples
    --------
    >>> check_range("speed", 2.0, 0.0, 10.0, unit="rad/s")
    2.0
    >>> try:
    ...     check_range("speed", 12.0, 0.0, 10.0, unit="rad/s")
    ... except ValueError as e:
    ...     print(e)
    speed = 12.0 rad/s is outside the valid range [0, 10] rad/s
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
    """Finite and strictly positive.

    Parameters
    ----------
    name : str
        The variable's name.
    value : float or array_like
        The value(s).
    unit : str
        Its unit, for the message.

    Returns
    -------
    float or ndarray
        ``value`` as float (array); ValueError unless finite and > 0.

    Examples
    --------
    >>> check_positive("pitch_diameter", 0.0215, "m")
    0.0215
    """
    return check_range(name, value, 0.0, None, lo_open=True, unit=unit)


def check_nonnegative(name: str, value, unit: str = ""):
    """Finite and >= 0.

    Parameters
    ----------
    name : str
        The variable's name.
    value : float or array_like
        The value(s).
    unit : str
        Its unit, for the message.

    Returns
    -------
    float or ndarray
        ``value`` as float (array); ValueError unless finite and ≥ 0.

    Examples
    --------
    >>> check_nonnegative("viscous_damping", 0.0, "N·m·s/rad")
    0.0
    """
    return check_range(name, value, 0.0, None, unit=unit)


def check_finite(name: str, value, unit: str = ""):
    """Finite (any sign).

    Parameters
    ----------
    name : str
        The variable's name.
    value : float or array_like
        The value(s).
    unit : str
        Its unit, for the message.

    Returns
    -------
    float or ndarray
        ``value`` as float (array); ValueError for nan or ±inf.

    Examples
    --------
    >>> check_finite("axial_load", -5.0, "N")
    -5.0
    """
    return check_range(name, value, unit=unit)


def check_temperature(name: str, value):
    """Absolute temperature in kelvin: finite and > 0 K.

    Parameters
    ----------
    name : str
        The variable's name.
    value : float or array_like
        Temperature(s) [K].

    Returns
    -------
    float or ndarray
        ``value`` [K] as float (array); ValueError unless finite and > 0 K.

    Examples
    --------
    >>> check_temperature("temperature", 233.15)
    233.15
    """
    return check_range(name, value, 0.0, None, lo_open=True, unit="K")


def check_operating_temperature(name: str, value):
    """A temperature [K] within :data:`TEMPERATURE_RANGE`, the range the FMUs declare; a value
    outside it that would lie inside it read as °C gets a hint ("−40 looks like °C: 233.15 K").

    Parameters
    ----------
    name : str
        The variable's name.
    value : float or array_like
        Temperature(s) [K].

    Returns
    -------
    float or ndarray
        ``value`` [K] as float (array); ValueError naming the first bad value, the range and,
        where it fits, the kelvin value it would be in °C.

    Examples
    --------
    >>> check_operating_temperature("temperature", 233.15)
    233.15
    >>> try:
    ...     check_operating_temperature("temperature", -40.0)
    ... except ValueError as e:
    ...     print(e)
    temperature = -40.0 K is outside the valid range [173.15, 473.15] K; -40 looks like °C: 233.15 K
    """
    lo, hi = TEMPERATURE_RANGE
    try:
        return check_range(name, value, lo, hi, unit="K")
    except ValueError as err:
        arr = np.asarray(value, dtype=float)
        bad = arr[~(np.isfinite(arr) & (arr >= lo) & (arr <= hi))]
        first = float(bad.flat[0]) if bad.size else math.nan
        kelvin = first + 273.15
        if math.isfinite(first) and lo <= kelvin <= hi:
            raise ValueError(f"{err}; {first:g} looks like °C: {kelvin:.10g} K") from None
        raise


def suggest(word, choices) -> str:
    """ " (did you mean 'x'?)" for the closest of ``choices`` to a mistyped ``word`` (difflib's
    ratio ≥ 0.6), or "" when none is close.

    Parameters
    ----------
    word : str
        What was typed.
    choices : iterable of str
        The valid words.

    Returns
    -------
    str
        The hint, with a leading space, or "".

    Examples
    --------
    >>> suggest("friction_vs_temprature", ["friction_vs_temperature", "thermal_cycle"])
    " (did you mean 'friction_vs_temperature'?)"
    >>> suggest("xyz", ["bore", "width"])
    ''
    """
    close = difflib.get_close_matches(str(word), [str(c) for c in choices], n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def check_choice(name: str, value: str, choices) -> str:
    """One of a fixed set of strings.

    Parameters
    ----------
    name : str
        The variable's name.
    value : str
        The choice.
    choices : iterable of str
        The valid ones.

    Returns
    -------
    str
        ``value``; ValueError naming the valid choices otherwise.

    Examples
    --------
    >>> check_choice("lubrication", "grease", ("grease", "solid"))
    'grease'
    """
    if value not in choices:
        raise ValueError(
            f"{name} = {value!r} is not one of {sorted(choices)}{suggest(value, choices)}"
        )
    return value

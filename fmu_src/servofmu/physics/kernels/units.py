"""Unit conversions used at the edges (papers' tables, display, data files).

Everything inside servofmu is SI: K, m, N, N·m, rad, rad/s, Pa, Pa·s, m²/s.
"""

from __future__ import annotations

import math

ZERO_CELSIUS = 273.15  # K
RPM = 2.0 * math.pi / 60.0  # rad/s per rev/min
CST = 1.0e-6  # m²/s per centistokes
MM = 1.0e-3  # m per mm
UM = 1.0e-6  # m per µm
NMM = 1.0e-3  # N·m per N·mm
GPA = 1.0e9  # Pa per GPa
DEG = math.pi / 180.0  # rad per degree
GRAM_FORCE = 9.80665e-3  # N per gram-force (standard gravity)
GRAM_FORCE_CM = GRAM_FORCE * 1.0e-2  # N·m per gram-force centimetre (g·cm, grease torque tests)


def celsius_to_kelvin(t_c):
    """°C → K.

    Parameters
    ----------
    t_c : float or array_like
        Temperature [°C].

    Returns
    -------
    float or ndarray
        Temperature [K] (t_c + 273.15).

    Examples
    --------
    >>> celsius_to_kelvin(-40.0)  # K
    233.14999999999998
    """
    return t_c + ZERO_CELSIUS


def kelvin_to_celsius(t_k):
    """K → °C.

    Parameters
    ----------
    t_k : float or array_like
        Temperature [K].

    Returns
    -------
    float or ndarray
        Temperature [°C] (t_k − 273.15).

    Examples
    --------
    >>> kelvin_to_celsius(373.15)  # °C
    100.0
    """
    return t_k - ZERO_CELSIUS


def rpm_to_rad_per_s(n):
    """rev/min → rad/s.

    Parameters
    ----------
    n : float or array_like
        Speed [rev/min].

    Returns
    -------
    float or ndarray
        Speed [rad/s] (n·2π/60).

    Examples
    --------
    >>> round(rpm_to_rad_per_s(60.0), 6)  # rad/s: one turn a second is 2π
    6.283185
    """
    return n * RPM


def rad_per_s_to_rpm(omega):
    """rad/s → rev/min.

    Parameters
    ----------
    omega : float or array_like
        Speed [rad/s].

    Returns
    -------
    float or ndarray
        Speed [rev/min] (ω·60/2π).

    Examples
    --------
    >>> round(rad_per_s_to_rpm(math.pi), 6)  # rev/min
    30.0
    """
    return omega / RPM


# Factors to SI for the unit strings allowed in the data files (parameters/data/*.toml).
TO_SI = {
    "m": 1.0,
    "mm": MM,
    "in": 0.0254,
    "um": UM,
    "Pa": 1.0,
    "MPa": 1.0e6,
    "GPa": GPA,
    "1/K": 1.0,
    "rad": 1.0,
    "deg": DEG,
    "-": 1.0,
    "N": 1.0,
    "N/m": 1.0,
    "N/mm": 1.0e3,
    "m2": 1.0,
    "mm2": MM * MM,
    "K": 1.0,
    "cSt": CST,
    "m2/s": 1.0,
    "kg/m3": 1.0,
    "g/cm3": 1.0e3,
    "g/mL": 1.0e3,
    "m4": 1.0,
    "mm4": MM**4,
    "N.m/rad": 1.0,
    "N.m/deg": 1.0 / DEG,
    "J/kg/K": 1.0,
    "W/m/K": 1.0,
    "W/m2/K": 1.0,
    "m2.K/W": 1.0,
    "m/s": 1.0,
    "W/K": 1.0,
    "N.m": 1.0,
    "mN.m": 1.0e-3,
    "N.mm": NMM,
    "g.cm": GRAM_FORCE_CM,  # gram-force centimetre, ASTM D1478 torques
    "rpm": RPM,
    "kg": 1.0,
    "g": 1.0e-3,
    "mm2/s": CST,
    "Pa.s": 1.0,
}


def to_si(value: float, unit: str) -> float:
    """Convert ``value`` given in ``unit`` (a key of :data:`TO_SI`, or ``degC``) to SI.

    Parameters
    ----------
    value : float
        The number in ``unit``.
    unit : str
        A key of :data:`TO_SI` (e.g. "mm", "cSt", "N/mm") or "degC".

    Returns
    -------
    float
        The value in SI (m, m²/s, N/m, K, ...); ValueError for an unknown unit.

    Examples
    --------
    >>> to_si(26.0, "mm")  # m
    0.026000000000000002
    >>> round(to_si(20.0, "degC"), 2)  # K
    293.15
    """
    if unit == "degC":
        return celsius_to_kelvin(value)
    try:
        return value * TO_SI[unit]
    except KeyError:
        raise ValueError(f"unit = {unit!r} is not one of {sorted([*TO_SI, 'degC'])}") from None

r"""Lubricant viscosity versus temperature: the Walther equation (ASTM D341).

Yu 2017 eq 18:

.. math::

   \lg\,\lg(\nu + c) = a - b\,\lg T

with ν in cSt, T in K and lg = log10. For Krytox 143AA Yu fits a = 9.597, b = 3.773,
c = 0.932 (catalogue key ``krytox_143aa``). ASTM D341 uses the same form with c = 0.7 and
builds (a, b) from two measured viscosities: :func:`walther_from_two_points`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._checks import check_positive, check_range, check_temperature
from .units import CST


@dataclass(frozen=True)
class WaltherViscosity:
    """Kinematic viscosity model lg lg(ν[cSt] + c) = a − b·lg(T[K]) (Yu 2017 eq 18).

    Attributes
    ----------
    key, name : catalogue key and name
    a, b : Walther coefficients [-]
    c : additive constant [cSt] (0.7 in ASTM D341; 0.932 in Yu's Krytox fit)
    provenance : ((field, source), ...)
    """

    key: str
    name: str
    a: float
    b: float
    c: float = 0.7
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_range("a", self.a)
        check_positive("b", self.b)
        check_range("c", self.c, 0.0, 10.0, lo_open=True, unit="cSt")

    def kinematic_viscosity(self, temperature):
        """ν(T) [m²/s] for ``temperature`` [K] (scalar or array). Yu 2017 eq 18."""
        return walther_kinematic_viscosity(temperature, self.a, self.b, self.c)

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")


def walther_kinematic_viscosity(temperature, a: float, b: float, c: float = 0.7):
    """Kinematic viscosity [m²/s] from the Walther equation (Yu 2017 eq 18; ASTM D341).

    Parameters
    ----------
    temperature : absolute temperature T [K], > 0
    a, b : Walther coefficients [-] of lg lg(ν + c) = a − b·lg T (lg = log10, ν in cSt)
    c : additive constant [cSt]

    The equation is written in cSt and kelvin; the result is converted to m²/s.

    Returns
    -------
    float or ndarray
        ν [m²/s].

    Examples
    --------
    >>> nu = walther_kinematic_viscosity(313.15, 8.0, 3.1)
    >>> round(float(nu) * 1e6, 2)  # cSt at 40 °C for lg lg(ν + 0.7) = 8 − 3.1·lg T
    67.38
    """
    t = check_temperature("temperature", temperature)
    nu_cst = 10.0 ** (10.0 ** (a - b * np.log10(t))) - c
    return nu_cst * CST


def walther_from_two_points(
    t1: float, nu1: float, t2: float, nu2: float, c: float = 0.7, key: str = "", name: str = ""
) -> WaltherViscosity:
    """Walther/ASTM D341 fit through two measured viscosities.

    Parameters
    ----------
    t1, t2 : temperatures [K], different
    nu1, nu2 : kinematic viscosities [m²/s] at t1, t2; ν + c must exceed 1 cSt so that
        lg lg(ν + c) is defined
    c : additive constant [cSt] (ASTM D341: 0.7)

    Returns the :class:`WaltherViscosity` with b = (Y1 − Y2)/(lg T2 − lg T1), a = Y1 + b·lg T1,
    Y = lg lg(ν[cSt] + c).

    Examples
    --------
    >>> v = walther_from_two_points(313.15, 32e-6, 373.15, 5.4e-6)  # an ISO VG 32 oil
    >>> round(float(v.kinematic_viscosity(313.15)) * 1e6, 9)  # cSt: back through the point
    32.0
    """
    t1 = check_temperature("t1", t1)
    t2 = check_temperature("t2", t2)
    if t1 == t2:
        raise ValueError(f"t2 = {t2!r} K must differ from t1 = {t1!r} K")
    y = []
    for label, nu in (("nu1", nu1), ("nu2", nu2)):
        nu_cst = check_positive(label, nu, "m²/s") / CST
        if nu_cst + c <= 1.0:
            raise ValueError(
                f"{label} = {nu!r} m²/s gives ν + c = {nu_cst + c:g} cSt; Walther needs > 1 cSt"
            )
        y.append(np.log10(np.log10(nu_cst + c)))
    b = (y[0] - y[1]) / (np.log10(t2) - np.log10(t1))
    a = y[0] + b * np.log10(t1)
    if b <= 0:
        raise ValueError(
            f"viscosity must fall with temperature: nu1 = {nu1!r} at t1 = {t1!r} K and "
            f"nu2 = {nu2!r} at t2 = {t2!r} K give b = {b:g} <= 0"
        )
    prov = (("a", "derived: ASTM D341 two-point fit"), ("b", "derived: ASTM D341 two-point fit"))
    return WaltherViscosity(key=key, name=name, a=float(a), b=float(b), c=c, provenance=prov)


#: The reference temperatures of ν40 and ν100 (ISO 3448, ASTM D341) [K].
T40, T100 = 313.15, 373.15


def walther_from_reference(
    viscosity_40: float, viscosity_100: float, c: float = 0.7, key: str = "", name: str = ""
) -> WaltherViscosity:
    """Walther/ASTM D341 model through the kinematic viscosities at 40 and 100 °C, the two
    numbers of every lubricant datasheet (:func:`walther_from_two_points` at 313.15 and
    373.15 K). Every fluid lubricant of servofmu is this model: catalogue entries that give
    a, b (and c) are turned into ν40 and ν100 first, so that the FMU parameters
    ``lubricant_viscosity_40``/``_100`` reproduce them exactly.

    Parameters
    ----------
    viscosity_40, viscosity_100 : ν at 40 and 100 °C [m²/s], ν100 < ν40
    c : Walther's additive constant [cSt] (ASTM D341: 0.7)

    Returns
    -------
    WaltherViscosity

    Examples
    --------
    >>> vg32 = walther_from_reference(32e-6, 5.4e-6)
    >>> round(float(vg32.kinematic_viscosity(T40)) * 1e6, 9)  # cSt at 40 °C
    32.0
    """
    nu40 = check_positive("viscosity_40", viscosity_40, "m²/s")
    nu100 = check_positive("viscosity_100", viscosity_100, "m²/s")
    if not nu100 < nu40:
        raise ValueError(
            f"viscosity_100 = {nu100!r} m²/s must be below viscosity_40 = {nu40!r} m²/s "
            "(a lubricant thins on heating)"
        )
    return walther_from_two_points(T40, nu40, T100, nu100, c=c, key=key, name=name)

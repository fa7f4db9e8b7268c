# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The viscosity laws of a lubricant, floats or arrays: Walther's (ASTM D341; Yu 2017 eq 18)
and Vogel's, and the temperature a bearing model evaluates them at. The models with their
ranges and fits are :mod:`servofmu.physics.lubrication.viscosity`.

Examples
--------
>>> import math
>>> round(walther_viscosity(math.log10(313.15), 8.0, 3.1, 0.7), 2)  # cSt at 40 °C
67.38
"""

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from . import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.servofmu.physics.kernels._elementary import maximum
else:
    from .elementary import maximum


@cython.ccall
def walther_viscosity(
    log10_temperature: cython.double, a: cython.double, b: cython.double, c: cython.double
) -> cython.double:
    """Kinematic viscosity ν [cSt] of Walther's equation (ASTM D341-20 §5; Yu 2017 eq 18)

        lg lg(ν + c) = a − b·lg T

    at lg T = ``log10_temperature`` (T in K), with the coefficients a, b [-] and the additive
    constant c [cSt] (ASTM D341: 0.7). Floats or arrays.

    Returns
    -------
    float or ndarray
        ν [cSt].

    Examples
    --------
    Back through its own line: lg lg(ν + c) at 40 °C is a − b·lg 313.15 (by hand):

    >>> from math import log10
    >>> nu = walther_viscosity(log10(313.15), 8.0, 3.1, 0.7)
    >>> round(log10(log10(nu + 0.7)), 12) == round(8.0 - 3.1 * log10(313.15), 12)
    True
    """
    return 10.0 ** (10.0 ** (a - b * log10_temperature)) - c


@cython.ccall
def vogel_log_viscosity(
    temperature: cython.double, a: cython.double, b: cython.double, t_inf: cython.double
) -> cython.double:
    """ln ν [ln(m²/s)] of Vogel's law (Vogel 1921; Seeton 2006 §2)

        ln ν = a + b/(T − T∞)

    at ``temperature`` T [K] above T∞ [K], with a [ln(m²/s)] and b [K]. Floats or arrays.

    Returns
    -------
    float or ndarray
        ln ν [ln(m²/s)].

    Examples
    --------
    >>> vogel_log_viscosity(300.0, -10.0, 500.0, 200.0)  # −10 + 500/100
    -5.0
    """
    return a + b / (temperature - t_inf)


@cython.ccall
def operating_temperature(temperature: cython.double, hold: cython.double) -> cython.double:
    """The temperature [K] at which a lubricant's law gives the viscosity a bearing model uses
    at ``temperature`` [K]: the temperature itself, or ``hold`` [K] below which the viscosity
    is held at its value there (0: never held;
    :meth:`~servofmu.physics.lubrication.viscosity.ViscosityRange.operating_viscosity`).
    Floats or arrays.

    Returns
    -------
    float or ndarray
        [K].

    Examples
    --------
    >>> operating_temperature(200.0, 213.15), operating_temperature(250.0, 213.15)  # K
    (213.15, 250.0)
    """
    return maximum(temperature, hold)

# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The ball–race contact, floats or arrays: the race geometry (clearance, curvature
distance, first contact, free contact angle; Harris & Kotzalas 2007, ch. 2), the curvature
of a ball–groove contact and its Hertz coefficients (ch. 6), and one ball's load and
stiffness at a displacement of its groove centres (Jones 1960). The records, the ellipticity
and the checked functions are :mod:`servofmu.physics.contact`.

Conventions: Dw the ball diameter, r the groove radius, f = r/Dw, γ = Dw·cos α/dm; the axial
offset a of the groove curvature centres is measured from the centred position.

Examples
--------
A = 100 µm, Pd = 40 µm: h = √(100² − 80²) = 60 µm (by hand):

>>> round(first_contact_offset(40e-6, 100e-6) * 1e6, 6)  # µm
60.0
"""

import math

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from . import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.servofmu.physics.kernels._elementary import (
        arccos,
        cbrt,
        maximum,
        minimum,
        sqrt,
    )
else:
    from .elementary import arccos, cbrt, maximum, minimum, sqrt

_PI: cython.double = math.pi


# ---------------------------------------------------------------- race geometry
@cython.ccall
def diametral_clearance(
    inner_groove: cython.double, outer_groove: cython.double, ball_diameter: cython.double
) -> cython.double:
    """Diametral (radial internal) clearance Pd = d_o − d_i − 2·Dw [m] from the groove-bottom
    diameters d_i, d_o and the ball diameter Dw [m] (Yu 2017 §2.1, P_r2; negative: the balls
    are squeezed between the grooves). Floats or arrays.

    Returns
    -------
    float or ndarray
        Pd [m].

    Examples
    --------
    >>> round(diametral_clearance(19.1109e-3, 23.8891e-3, 2.381e-3) * 1e6, 4)  # µm, by hand
    16.2
    """
    return outer_groove - inner_groove - 2.0 * ball_diameter


@cython.ccall
def curvature_distance(
    inner_radius: cython.double, outer_radius: cython.double, ball_diameter: cython.double
) -> cython.double:
    """Distance A = r_i + r_o − Dw [m] between the groove curvature centres of a ball in
    contact with both grooves (groove radii r_i, r_o and ball diameter Dw [m]; Harris &
    Kotzalas 2007, ch. 2: A = (f_i + f_o − 1)·Dw). Floats or arrays.

    Returns
    -------
    float or ndarray
        A [m].

    Examples
    --------
    >>> round(curvature_distance(1.4e-3, 1.35e-3, 2.5e-3) * 1e6, 6)  # µm: 0.1·Dw
    250.0
    """
    return inner_radius + outer_radius - ball_diameter


@cython.ccall
def pitch_diameter(inner_groove: cython.double, outer_groove: cython.double) -> cython.double:
    """Pitch diameter dm = (d_i + d_o)/2 [m], the mean of the groove-bottom diameters [m]
    (Harris & Kotzalas 2007, ch. 2). Floats or arrays.

    Returns
    -------
    float or ndarray
        dm [m].

    Examples
    --------
    >>> round(pitch_diameter(19.1109e-3, 23.8891e-3) * 1e3, 4)  # mm: the 71803's 21.5 mm
    21.5
    """
    return 0.5 * (inner_groove + outer_groove)


@cython.ccall
def first_contact_offset(
    clearance: cython.double, curvature_distance: cython.double
) -> cython.double:
    """Axial offset h [m] of the groove curvature centres, from the centred position, at which
    the ball first touches both grooves: h = √(A² − (A − Pd/2)²) = A·sin α0, the clearance Pd
    [m] taken within [0, 2A] (0 at Pd ≤ 0: the balls touch at once), A [m] the curvature
    distance (Harris & Kotzalas 2007, ch. 2; axial play 2h). Floats or arrays.

    Returns
    -------
    float or ndarray
        h [m].

    Examples
    --------
    >>> first_contact_offset(-1e-6, 100e-6)  # negative clearance: in contact at once
    0.0
    """
    a: cython.double = curvature_distance
    half: cython.double = 0.5 * minimum(maximum(clearance, 0.0), 2.0 * a)
    return sqrt(maximum(a * a - (a - half) * (a - half), 0.0))


@cython.ccall
def free_contact_angle(
    clearance: cython.double, curvature_distance: cython.double
) -> cython.double:
    """Free (unloaded) contact angle α0 [rad] at the diametral clearance Pd [m] and the
    curvature distance A [m]: cos α0 = 1 − Pd/(2A) (Harris & Kotzalas 2007, ch. 2); 0 at
    Pd ≤ 0 (the balls touch or are squeezed at α = 0), π at Pd ≥ 4A. Floats or arrays.

    Returns
    -------
    float or ndarray
        α0 [rad].

    Examples
    --------
    Pd = A gives cos α0 = 1/2 (by hand 60°):

    >>> import math
    >>> round(math.degrees(free_contact_angle(0.1e-3, 0.1e-3)), 6)  # degrees
    60.0
    """
    return arccos(1.0 - maximum(clearance, 0.0) / (2.0 * curvature_distance))


# ---------------------------------------------------------------- one contact
@cython.ccall
def elliptic_slopes(
    m: cython.double, k_integral: cython.double, e_integral: cython.double
) -> tuple[cython.double, cython.double, cython.double, cython.double]:
    """First and second derivatives in m of the complete elliptic integrals K(m), E(m) [-] at
    the parameter 0 < m < 1 [-], from dK/dm = (E − (1 − m)·K)/(2m(1 − m)) and
    dE/dm = (E − K)/(2m) (Byrd & Friedman 1971, 710.00, 710.02) and their derivatives. Floats
    or arrays.

    Returns
    -------
    tuple
        (dK/dm, d²K/dm², dE/dm, d²E/dm²) [-].

    Examples
    --------
    At m = 1/2 (K = 1.854075, E = 1.350644; Abramowitz & Stegun 1964, table 17.1):

    >>> k1, k2, e1, e2 = elliptic_slopes(0.5, 1.8540746773013719, 1.3506438810476755)
    >>> round(k1, 6), round(e1, 6)  # (E − K/2)/(1/2), (E − K)/1
    (0.847213, -0.503431)
    """
    q: cython.double = 1.0 - m
    k1: cython.double = (e_integral - q * k_integral) / (2.0 * m * q)
    e1: cython.double = (e_integral - k_integral) / (2.0 * m)
    # (E − qK)' = E' + K − qK';  (2mq)' = 2(1 − 2m)
    k2: cython.double = (
        (e1 + k_integral - q * k1) * 2.0 * m * q
        - (e_integral - q * k_integral) * 2.0 * (1.0 - 2.0 * m)
    ) / ((2.0 * m * q) ** 2)
    e2: cython.double = (e1 - k1) / (2.0 * m) - (e_integral - k_integral) / (2.0 * m * m)
    return k1, k2, e1, e2


@cython.ccall
def hertz_relation(
    k: cython.double, k_integral: cython.double, e_integral: cython.double
) -> tuple[cython.double, cython.double, cython.double]:
    """The Hertz relation F(k) = ((k² + 1)·E − 2·K)/((k² − 1)·E) between the curvature
    difference F [-] and the ellipticity k > 1 [-] of a point contact (Harris & Kotzalas
    2007, ch. 6), and its first and second derivatives in k, given K = K(m) and E = E(m) at
    m = 1 − 1/k² [-] (dm/dk = 2/k³; :func:`elliptic_slopes`). Floats or arrays.

    Returns
    -------
    tuple
        (F [-], dF/dk [-], d²F/dk² [-]).

    Examples
    --------
    >>> from scipy.special import ellipe, ellipk
    >>> k = 8.0
    >>> f, df, _ = hertz_relation(k, ellipk(1 - 1 / k**2), ellipe(1 - 1 / k**2))
    >>> round(float(f), 6), float(df) > 0  # F rises with k
    (0.923924, True)
    """
    m: cython.double = 1.0 - 1.0 / (k * k)
    k1: cython.double
    k2: cython.double
    e1: cython.double
    e2: cython.double
    k1, k2, e1, e2 = elliptic_slopes(m, k_integral, e_integral)
    # F = N/D, N = (k² + 1)E − 2K, D = (k² − 1)E, as functions of k through m = 1 − 1/k²
    mk: cython.double = 2.0 / (k * k * k)
    mkk: cython.double = -6.0 / (k * k * k * k)
    ek: cython.double = e1 * mk
    ekk: cython.double = e2 * mk * mk + e1 * mkk
    kk_: cython.double = k1 * mk
    kkk: cython.double = k2 * mk * mk + k1 * mkk
    kq: cython.double = k * k
    n: cython.double = (kq + 1.0) * e_integral - 2.0 * k_integral
    d: cython.double = (kq - 1.0) * e_integral
    nk: cython.double = 2.0 * k * e_integral + (kq + 1.0) * ek - 2.0 * kk_
    dk: cython.double = 2.0 * k * e_integral + (kq - 1.0) * ek
    nkk: cython.double = 2.0 * e_integral + 4.0 * k * ek + (kq + 1.0) * ekk - 2.0 * kkk
    dkk: cython.double = 2.0 * e_integral + 4.0 * k * ek + (kq - 1.0) * ekk
    f1: cython.double = (nk * d - n * dk) / (d * d)
    return n / d, f1, (nkk * d - n * dkk) / (d * d) - 2.0 * dk * f1 / d


@cython.ccall
def race_curvature(
    gamma: cython.double, inverse_conformity: cython.double, inner: cython.bint
) -> tuple[cython.double, cython.double]:
    """Curvature sum times the ball diameter, Σρ·Dw [-], and curvature difference F(ρ) [-] of
    a ball–groove contact (Harris & Kotzalas 2007, ch. 2), with γ = Dw·cos α/dm [-] and
    1/f = Dw/r [-] of the groove:

        inner: Σρ·Dw = 4 − 1/f + 2γ/(1 − γ),  F = (1/f + 2γ/(1 − γ))/(Σρ·Dw);
        outer: Σρ·Dw = 4 − 1/f − 2γ/(1 + γ),  F = (1/f − 2γ/(1 + γ))/(Σρ·Dw).

    Floats or arrays (``inner`` a bool).

    Returns
    -------
    tuple
        (Σρ·Dw [-], F(ρ) [-]).

    Examples
    --------
    A flat race (γ = 0) on a groove of f = 0.5 (1/f = 2): Σρ·Dw = 2, F = 1 (by hand):

    >>> race_curvature(0.0, 2.0, True)
    (2.0, 1.0)
    """
    race: cython.double
    if inner:
        race = 2.0 * gamma / (1.0 - gamma)
    else:
        race = -2.0 * gamma / (1.0 + gamma)
    total: cython.double = 4.0 - inverse_conformity + race
    return total, (inverse_conformity + race) / total


@cython.ccall
def hertz_coefficients(
    curvature_sum: cython.double,
    ellipticity: cython.double,
    k_integral: cython.double,
    e_integral: cython.double,
    compliance: cython.double,
) -> tuple[cython.double, cython.double, cython.double]:
    """Load-independent coefficients of a Hertz point contact (Harris & Kotzalas 2007, ch. 6;
    Johnson 1985, ch. 4) from the curvature sum Σρ [1/m], the ellipticity k = a/b [-], the
    complete elliptic integrals K(m), E(m) at m = 1 − 1/k² [-] and the compliance
    η = (1 − ν1²)/E1 + (1 − ν2²)/E2 [1/Pa]:

        a = a*·Q^(1/3),  a* = (3k²·E·η/(π·Σρ))^(1/3),
        b = b*·Q^(1/3),  b* = a*/k,
        δ = c_δ·Q^(2/3), c_δ = (K/π)·(π/(2k²·E))^(1/3)·(3η/2)^(2/3)·Σρ^(1/3),

    so that Q = c_δ^(−3/2)·δ^(3/2) (the load–deflection constant K_c = c_δ^(−3/2)). For k = 1
    (E = K = π/2) these are Hertz's sphere: a = (3QR/(4E*))^(1/3), δ = a²/R. Floats or
    arrays.

    Returns
    -------
    tuple
        (a* [m/N^(1/3)], b* [m/N^(1/3)], c_δ [m/N^(2/3)]).

    Examples
    --------
    A sphere of R = 5 mm on a flat (Σρ = 2/R: two principal curvatures 1/R, k = 1,
    E = K = π/2), η = 1e-11 /Pa (E* = 1/η = 100 GPa): a³ = 3·Q·R·η/4 per newton and
    δ = a²/R (by hand):

    >>> import math
    >>> a, b, c = hertz_coefficients(400.0, 1.0, math.pi / 2, math.pi / 2, 1e-11)
    >>> round(a**3 / (0.75 * 5e-3 * 1e-11), 12), round(c / (a * a / 5e-3), 12)
    (1.0, 1.0)
    """
    x: cython.double = cbrt(curvature_sum / (ellipticity * ellipticity * e_integral))
    a: cython.double = cbrt(3.0 * compliance / _PI) / x
    c_delta: cython.double = (
        (k_integral / _PI) * cbrt(0.5 * _PI) * (1.5 * compliance) ** (2.0 / 3.0) * x
    )
    return a, a / ellipticity, c_delta


@cython.ccall
def hertz_pressure(load: cython.double, semi_axes: cython.double) -> cython.double:
    """Largest pressure of a Hertz point contact, p0 = 3Q/(2π·a·b) [Pa], from its load Q [N]
    and the product a·b of its semi-axes [m²] (Harris & Kotzalas 2007, ch. 6). Floats or
    arrays (Q > 0).

    Returns
    -------
    float or ndarray
        p0 [Pa].

    Examples
    --------
    >>> import math
    >>> round(hertz_pressure(math.pi, 1e-8) / 1e6, 9)  # MPa: 3π/(2π·1e-8 m²)
    150.0
    """
    return 1.5 * load / (_PI * semi_axes)


@cython.ccall
def series_stiffness(c_inner: cython.double, c_outer: cython.double) -> cython.double:
    """Load–deflection constant K_n [N/m^1.5] of a ball's two contacts in series,
    Q = K_n·δ^1.5, from their approach coefficients c_δ = K_c^(−2/3) [m/N^(2/3)]
    (:func:`hertz_coefficients`): the deflections add, K_n = (c_i + c_o)^(−3/2) (Harris &
    Kotzalas 2007, ch. 7). Floats or arrays.

    Returns
    -------
    float or ndarray
        K_n [N/m^1.5].

    Examples
    --------
    >>> round(series_stiffness(1e-7, 1e-7) / 1e9, 6)  # GN/m^1.5: two equal contacts
    11.18034
    """
    total: cython.double = c_inner + c_outer
    return 1.0 / (total * sqrt(total))


# ---------------------------------------------------------------- one ball (Jones 1960)
@cython.ccall
def ball_contact(
    axial: cython.double, radial: cython.double, curvature_distance: cython.double
) -> tuple[cython.double, cython.double, cython.double, cython.double]:
    """Geometry of one ball whose inner-groove curvature centre is displaced by ``axial`` A1
    and ``radial`` A2 [m] from the outer one (Jones 1960; Harris & Kotzalas 2007, Advanced
    Concepts ch. 1):

        s = √(A1² + A2²),  sin α = A1/s,  cos α = A2/s,  δ = s − A,

    A [m] the curvature distance; δ ≤ 0: the ball is free. Floats or arrays.

    Returns
    -------
    tuple
        (s [m], sin α [-], cos α [-], δ [m]).

    Examples
    --------
    A 3-4-5 triangle, A = 4 µm: δ = 1 µm (by hand):

    >>> s, sin_a, cos_a, d = ball_contact(3e-6, 4e-6, 4e-6)
    >>> round(s * 1e6, 12), round(sin_a, 12), round(cos_a, 12), round(d * 1e6, 12)  # µm, -, -, µm
    (5.0, 0.6, 0.8, 1.0)
    """
    s: cython.double = sqrt(axial * axial + radial * radial)
    return s, axial / s, radial / s, s - curvature_distance


@cython.ccall
def hertz_load(stiffness: cython.double, deflection: cython.double) -> cython.double:
    """Normal load Q = K·max(δ, 0)^1.5 [N] of a Hertz point contact (or a ball's two in
    series) of load–deflection constant K [N/m^1.5] at the approach δ [m] (Harris &
    Kotzalas 2007, ch. 7). Floats or arrays.

    Returns
    -------
    float or ndarray
        Q [N] (0 where δ ≤ 0).

    Examples
    --------
    >>> round(hertz_load(1e10, 1e-6), 9), hertz_load(1e10, -1e-6)  # N: K·δ^1.5
    (10.0, 0.0)
    """
    d: cython.double = maximum(deflection, 0.0)
    return stiffness * d * sqrt(d)


@cython.ccall
def ball_stiffness(
    load: cython.double,
    distance: cython.double,
    deflection: cython.double,
    stiffness: cython.double,
    stiffness_slope: cython.double,
    sin_a: cython.double,
    cos_a: cython.double,
) -> tuple[cython.double, cython.double, cython.double, cython.double, cython.double]:
    """Stiffness of one ball's force Q·(sin α, cos α) against the displacements (A1, A2) of
    its groove centres (:func:`ball_contact`; Jones 1960): with Q = K_n(α)·δ^1.5,
    dδ = sin α·dA1 + cos α·dA2 and dα = (cos α·dA1 − sin α·dA2)/s,

        dQ/dA1 = 1.5·K_n·√δ·sin α + g·cos α,  dQ/dA2 = 1.5·K_n·√δ·cos α − g·sin α,
        g = δ^1.5·(dK_n/dα)/s,

    and the force turns with α: d(Q·n)/dA = n·dQ/dA + (Q/s)·(I − n·nᵀ) (n the contact
    normal). ``load`` Q [N], ``distance`` s [m], ``deflection`` δ [m], ``stiffness`` K_n
    [N/m^1.5], ``stiffness_slope`` dK_n/dα [N/m^1.5/rad] (0: K_n held at the ball's angle).
    Floats or arrays.

    Returns
    -------
    tuple
        (d(Q·sin α)/dA1, d(Q·sin α)/dA2, d(Q·cos α)/dA1, d(Q·cos α)/dA2, and
        d(Q·sin α)/dA1 with K_n held) [N/m].

    Examples
    --------
    A ball in line with the axis (α = 90°), K_n = 1e10 N/m^1.5, δ = 1 µm, Q = 10 N,
    s = 0.1 mm: its axial stiffness is dQ/dδ = 1.5·K_n·√δ and its radial one Q/s (by hand
    1.5e7 N/m and 1e5 N/m):

    >>> k11, k12, k21, k22, held = ball_stiffness(10.0, 1e-4, 1e-6, 1e10, 0.0, 1.0, 0.0)
    >>> round(k11), round(k22), k12, held == k11  # N/m
    (15000000, 100000, 0.0, True)
    """
    d: cython.double = maximum(deflection, 0.0)
    root: cython.double = sqrt(d)
    axial: cython.double = 1.5 * stiffness * root  # dQ/dδ
    turn: cython.double = load / distance  # Q/s
    g: cython.double = d * root * stiffness_slope / distance
    dq1: cython.double = axial * sin_a + g * cos_a
    dq2: cython.double = axial * cos_a - g * sin_a
    sc: cython.double = turn * sin_a * cos_a
    return (
        dq1 * sin_a + turn * cos_a * cos_a,
        dq2 * sin_a - sc,
        dq1 * cos_a - sc,
        dq2 * cos_a + turn * sin_a * sin_a,
        axial * sin_a * sin_a + turn * cos_a * cos_a,
    )

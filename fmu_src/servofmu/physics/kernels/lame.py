# cython: language_level=3, auto_pickle=False, embedsignature=False
"""Lamé's thick cylinders and the radial thermal coupling of a bearing's fits (Yu 2017 eq
10–13; Ning §2.1), floats or arrays: the compliance of a shaft and of a hub, the pressure of a
shrink fit between them, the change of a ring's raceway under that pressure, and the chain
from the parts' temperatures to the mounted raceways (:func:`mounted_races`). The records
and the checked functions are :mod:`servofmu.physics.thermal.fits`.

Examples
--------
A solid steel shaft in a steel ring with D = 2d: p = 3·δ·E/(8·d) (by hand 77.25 MPa):

>>> e, nu = 206e9, 0.3
>>> p = fit_pressure(10e-6, 0.010, shaft_compliance(0.0, 0.010, e, nu),
...                  hub_compliance(0.010, 0.020, e, nu))
>>> round(p / 1e6, 6)  # MPa
77.25
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
def lame_ratio(d_small: cython.double, d_large: cython.double) -> cython.double:
    """(D² + d²)/(D² − d²) [-] of an annulus from diameter d to D (Lamé's thick cylinder; Yu
    2017 eq 12–13: the compliances of ring, seat and shaft per diameter are this ratio ∓ ν
    over E). Floats or arrays.

    Parameters
    ----------
    d_small, d_large : float or ndarray
        d < D [m].

    Returns
    -------
    float or ndarray
        [-].

    Examples
    --------
    >>> lame_ratio(1.0, 2.0)  # (4 + 1)/(4 − 1)
    1.6666666666666667
    """
    return (d_large * d_large + d_small * d_small) / (d_large * d_large - d_small * d_small)


@cython.ccall
def shaft_compliance(
    bore: cython.double,
    diameter: cython.double,
    youngs_modulus: cython.double,
    poisson_ratio: cython.double,
) -> cython.double:
    """Radial compliance per diameter [1/Pa] of the inner member of a shrink fit (a shaft of
    ``bore`` d_b [m], 0 when solid, pressed at its outside ``diameter`` d [m]; or a bearing
    ring pressed into its housing): (lame_ratio(d_b, d) − ν)/E, E [Pa] and ν [-] its
    material's (Lamé; Yu 2017 eq 12–13, k1). Floats or arrays.

    Returns
    -------
    float or ndarray
        [1/Pa]: Δd/d per unit pressure.

    Examples
    --------
    >>> shaft_compliance(0.0, 0.01, 200e9, 0.3) * 200e9  # a solid shaft: 1 − ν
    0.7
    """
    return (lame_ratio(bore, diameter) - poisson_ratio) / youngs_modulus


@cython.ccall
def hub_compliance(
    diameter: cython.double,
    outer_diameter: cython.double,
    youngs_modulus: cython.double,
    poisson_ratio: cython.double,
) -> cython.double:
    """Radial compliance per diameter [1/Pa] of the outer member of a shrink fit (a hub or
    housing of bore ``diameter`` d [m] and ``outer_diameter`` D [m]; or a bearing ring on its
    shaft): (lame_ratio(d, D) + ν)/E, E [Pa] and ν [-] its material's (Lamé; Yu 2017 eq
    12–13, k2). Floats or arrays.

    Returns
    -------
    float or ndarray
        [1/Pa]: Δd/d per unit pressure.

    Examples
    --------
    >>> round(hub_compliance(0.01, 0.02, 200e9, 0.3) * 200e9, 12)  # 5/3 + ν
    1.966666666667
    """
    return (lame_ratio(diameter, outer_diameter) + poisson_ratio) / youngs_modulus


@cython.ccall
def fit_pressure(
    interference: cython.double,
    diameter: cython.double,
    shaft: cython.double,
    hub: cython.double,
) -> cython.double:
    """Contact pressure p [Pa] of a shrink fit (Lamé; Yu 2017 eq 12–13):

        p = max(δ, 0)/(d·(c_shaft + c_hub)),

    from the diametral ``interference`` δ [m] at the common ``diameter`` d [m] and the two
    members' compliances per diameter [1/Pa] (:func:`shaft_compliance`,
    :func:`hub_compliance`). A seat that has grown away from the ring loses contact instead
    of pulling on it: p ≥ 0 (the printed eq 13 would go negative). Floats or arrays.

    Returns
    -------
    float or ndarray
        p [Pa].

    Examples
    --------
    >>> fit_pressure(-1e-6, 0.01, 3.5e-12, 9.8e-12)  # a clearance fit: no pressure
    0.0
    """
    return maximum(interference, 0.0) / (diameter * (shaft + hub))


@cython.ccall
def bore_change(
    pressure: cython.double,
    outer_diameter: cython.double,
    bore: cython.double,
    youngs_modulus: cython.double,
) -> cython.double:
    """Change of the bore diameter [m] of an annulus (bore d_b [m], outside D [m], E [Pa])
    under an external pressure p [Pa] (Lamé; Yu 2017 eq 13, third line: the outer raceway of
    a ring pressed into a housing):

        Δd_b = −2·p·D²·d_b/(E·(D² − d_b²)).

    Floats or arrays.

    Returns
    -------
    float or ndarray
        Δd_b [m] (negative: the bore shrinks).

    Examples
    --------
    With D = 2·d_b, Δd_b = −8·p·d_b/(3·E) (by hand −10 µm):

    >>> round(bore_change(77.25e6, 0.020, 0.010, 206e9) * 1e6, 6)  # µm
    -10.0
    """
    d2: cython.double = outer_diameter * outer_diameter
    return -2.0 * pressure * d2 * bore / (youngs_modulus * (d2 - bore * bore))


@cython.ccall
def outside_change(
    pressure: cython.double,
    bore: cython.double,
    outer_diameter: cython.double,
    youngs_modulus: cython.double,
) -> cython.double:
    """Change of the outside diameter [m] of an annulus (bore d [m], outside D [m], E [Pa])
    under an internal pressure p [Pa] (Lamé; the inner raceway of a ring pressed onto a
    shaft, Ning §2.1):

        ΔD = 2·p·d²·D/(E·(D² − d²)).

    Floats or arrays.

    Returns
    -------
    float or ndarray
        ΔD [m] (positive: the outside grows).

    Examples
    --------
    With D = 2·d, ΔD = 4·p·d/(3·E) (by hand 5 µm):

    >>> round(outside_change(77.25e6, 0.010, 0.020, 206e9) * 1e6, 6)  # µm
    5.0
    """
    b2: cython.double = bore * bore
    return 2.0 * pressure * b2 * outer_diameter / (youngs_modulus * (outer_diameter**2 - b2))


@cython.ccall
def mounted_races(
    t_housing: cython.double,
    t_shaft: cython.double,
    t_outer: cython.double,
    t_inner: cython.double,
    t0: cython.double,
    ring: tuple[cython.double, cython.double, cython.double],
    ball_expansion: cython.double,
    housing: tuple[cython.double, cython.double, cython.double],
    shaft: tuple[cython.double, cython.double, cython.double],
    bearing: tuple[
        cython.double, cython.double, cython.double, cython.double, cython.double,
        cython.double, cython.double,
    ],
    seats: tuple[cython.double, cython.double, cython.double, cython.double],
    coupled: cython.bint,
) -> tuple[
    cython.double, cython.double, cython.double, cython.double, cython.double,
    cython.double, cython.double, cython.double, cython.double,
]:  # fmt: skip
    """The mounted raceways of a bearing at its parts' temperatures (Yu 2017 eq 10–13; Ning
    §2.1): each part grows freely by α·(T_part − T0) (eq 10); the interferences become
    δ_o = D·g_o − (D − δ_o0)·g_h and δ_i = (d + δ_i0)·g_s − d·g_i (g = 1 + α·ΔT of ring,
    housing, shaft); the Lamé pressures of the two fits (:func:`fit_pressure`, eq 12) then
    shrink the outer raceway (:func:`bore_change`, eq 13) and expand the inner one
    (:func:`outside_change`). The balls take the rings' mean temperature, the groove radii
    their ring's. Floats or arrays (broadcasting).

    Parameters
    ----------
    t_housing, t_shaft, t_outer, t_inner : float or ndarray
        The parts' temperatures [K] (housing, shaft, outer ring, inner ring).
    t0 : float
        The assembly temperature T0 [K], at which the dimensions hold.
    ring : tuple
        The rings' material: (expansion α [1/K], Young's modulus E [Pa], Poisson's ratio ν).
    ball_expansion : float
        The balls' α [1/K].
    housing, shaft : tuple
        (α [1/K], E [Pa], ν [-]) of the housing and of the shaft.
    bearing : tuple
        (outer diameter D, bore d, outer groove d_o, inner groove d_i, ball Dw [m], inner and
        outer groove curvature f_i, f_o [-]).
    seats : tuple
        (housing bore D − δ_o0, shaft seat d + δ_i0, housing outside diameter, shaft bore [m]),
        at T0.
    coupled : bool
        The fit pressures act on the raceways (False: free growth only, Yu Fig 3 "without
        coupling").

    Returns
    -------
    tuple
        (inner and outer groove diameters d_i, d_o, ball diameter Dw, inner and outer groove
        radii r_i, r_o [m], outer and inner fit pressures [Pa], outer and inner
        interferences [m]).

    Examples
    --------
    A 71803 (grooves 19.1109 and 23.8891 mm, a 3/32" ball) with a 12 µm outer fit in
    aluminium: at T0 without coupling nothing moves, the clearance is
    23.8891 − 19.1109 − 2·2.381 = 0.0162 mm (by hand); with it the fit pressure closes part of
    it (:func:`servofmu.physics.thermal.fits.mounted_geometry` of the catalogue's pair):

    >>> steel, alu = (11.7e-6, 206e9, 0.3), (21.7e-6, 70e9, 0.33)
    >>> bearing = (0.026, 0.017, 0.0238891, 0.0191109, 0.002381, 0.56, 0.54)
    >>> seats = (0.026 - 12e-6, 0.017, 0.036, 0.0)
    >>> free = mounted_races(293.15, 293.15, 293.15, 293.15, 293.15, steel, 11.7e-6, alu,
    ...                      steel, bearing, seats, False)
    >>> round((free[1] - free[0] - 2 * free[2]) * 1e6, 4), free[5]  # µm, Pa
    (16.2, 0.0)
    >>> fit = mounted_races(293.15, 293.15, 293.15, 293.15, 293.15, steel, 11.7e-6, alu,
    ...                     steel, bearing, seats, True)
    >>> fit[1] - fit[0] - 2 * fit[2] < 16.2e-6 and fit[5] > 0.0  # m, Pa
    True
    """
    alpha_r, e_r, nu_r = ring
    alpha_h, e_h, nu_h = housing
    alpha_s, e_s, nu_s = shaft
    outer_diameter, bore, outer_groove, inner_groove, dw, f_i, f_o = bearing
    housing_bore, shaft_seat, housing_outside, shaft_bore = seats
    grow_o = 1.0 + alpha_r * (t_outer - t0)
    grow_i = 1.0 + alpha_r * (t_inner - t0)
    grow_h = 1.0 + alpha_h * (t_housing - t0)
    grow_s = 1.0 + alpha_s * (t_shaft - t0)
    d_ring_o = outer_diameter * grow_o
    d_ring_i = bore * grow_i
    d_groove_o = outer_groove * grow_o
    d_groove_i = inner_groove * grow_i
    delta_o = d_ring_o - housing_bore * grow_h
    delta_i = shaft_seat * grow_s - d_ring_i
    p_o = 0.0 * delta_o
    p_i = 0.0 * delta_i
    if coupled:
        p_o = fit_pressure(
            delta_o,
            d_ring_o,
            shaft_compliance(d_groove_o, d_ring_o, e_r, nu_r),
            hub_compliance(d_ring_o, housing_outside * grow_h, e_h, nu_h),
        )
        p_i = fit_pressure(
            delta_i,
            d_ring_i,
            shaft_compliance(shaft_bore * grow_s, d_ring_i, e_s, nu_s),
            hub_compliance(d_ring_i, d_groove_i, e_r, nu_r),
        )
        d_groove_o = d_groove_o + bore_change(p_o, d_ring_o, d_groove_o, e_r)
        d_groove_i = d_groove_i + outside_change(p_i, d_ring_i, d_groove_i, e_r)
    t_balls = 0.5 * (t_outer + t_inner)
    return (
        d_groove_i,
        d_groove_o,
        dw * (1.0 + ball_expansion * (t_balls - t0)),
        f_i * dw * grow_i,
        f_o * dw * grow_o,
        p_o,
        p_i,
        delta_o,
        delta_i,
    )

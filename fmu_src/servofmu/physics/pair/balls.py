# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The balls of one bearing in the per-step path: each contact's Hertz constants from an
*anchor* (:class:`Anchor`: the exact constants at an ellipticity near the contact's) and a
ball's *base* (:func:`ball_base`: the constants with their derivatives at one γ and 1/f, see
:mod:`.continuation`), one bearing's loads and Jacobian (:func:`ring_point`, the Jones ball
of :func:`~servofmu.physics.kernels.contact.ball_contact` and
:func:`~servofmu.physics.kernels.contact.ball_stiffness`) and its torques (:func:`ring_sums`).

Examples
--------
>>> Anchor(5.0).k
5.0
"""

from scipy.special import ellipe, ellipk

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import atan2, cbrt
    from cython.cimports.servofmu.physics.kernels._contact import (
        ball_contact,
        ball_stiffness,
        elliptic_slopes,
        hertz_coefficients,
        hertz_load,
        hertz_pressure,
        hertz_relation,
        race_curvature,
        series_stiffness,
    )
    from cython.cimports.servofmu.physics.pair._constants import (
        PairConstants,
        Thermal,
        set_coefficients,
    )
else:
    from math import atan2, cbrt

    from ..kernels.contact import (
        ball_contact,
        ball_stiffness,
        elliptic_slopes,
        hertz_coefficients,
        hertz_load,
        hertz_pressure,
        hertz_relation,
        race_curvature,
        series_stiffness,
    )
    from .constants import PairConstants, Thermal, set_coefficients

#: Relative change of a contact's ellipticity from its anchor beyond which the anchor is
#: renewed for the next step (the second-order expansion's error is below 2e-12 there:
#: measured 1.8e-12 for k, K and E at F = 0.85…0.97, tests/physics/test_continuation.py).
ANCHOR_DRIFT = 1e-4
#: Relative change beyond which the step is solved again with the renewed anchors (error of
#: the expansion below 2e-11 up to there, tests/physics/test_continuation.py).
ANCHOR_REDO = 2e-4
#: Largest |Δγ| (γ = Dw·cos α/dm) and |Δ(1/f)| from a ball's base within which its Hertz
#: constants are taken to second order in γ and first order in 1/f (relative error below 2e-12
#: on the catalogue bearings, tests/physics/test_continuation.py).
GAMMA_SPAN = 5e-5
INV_F_SPAN = 3e-9
# the same numbers as C doubles for the compiled path (module globals are Python objects)
_DRIFT: cython.double = ANCHOR_DRIFT
_REDO: cython.double = ANCHOR_REDO
_G_SPAN: cython.double = GAMMA_SPAN
_F_SPAN: cython.double = INV_F_SPAN
_THIRD: cython.double = 1.0 / 3.0

# A contact's Hertz terms (contact_terms), a bearing's ring result (ring_point) and the sums over
# a ring (ring_sums): C structs compiled (declared in balls.pxd), tuples uncompiled.
if not cython.compiled:
    Terms = cython.typedef(tuple[
    cython.double, cython.double, cython.double, cython.double, cython.double, cython.double,
    cython.double, cython.double, cython.double, cython.double, cython.double, cython.double,
    cython.double, cython.double, cython.double, cython.double,
])  # fmt: skip
    Ring = cython.typedef(tuple[
    cython.double, cython.double, cython.double, cython.double, cython.double, cython.double,
    cython.double, cython.double,
])  # fmt: skip
    Sums = cython.typedef(tuple[
    cython.double, cython.double, cython.double, cython.double, cython.double, cython.double,
    cython.double, cython.double, cython.double, cython.bint,
])  # fmt: skip


@cython.final
@cython.cclass
class Anchor:
    """Exact Hertz data of one contact at its anchor ellipticity k0 (see module docstring):
    K, E and their first and second derivatives in m, F(k0) and its first and second
    derivatives in k (``inv_f1`` = 1/F', ``f2_f1`` = F''/F').

    Parameters
    ----------
    k : float
        The anchor ellipticity k0 > 1 [-].
    """

    k: cython.double
    m: cython.double
    k_int: cython.double
    e_int: cython.double
    f: cython.double
    f1: cython.double
    f2: cython.double
    f2_f1: cython.double
    inv_f1: cython.double
    k1: cython.double
    k2: cython.double
    e1: cython.double
    e2: cython.double
    __slots__ = ("e1", "e2", "e_int", "f", "f1", "f2", "f2_f1", "inv_f1", "k", "k1", "k2",
                 "k_int", "m")  # fmt: skip

    def __init__(self, k: cython.double):
        self.set(k)

    @cython.ccall
    def copy(self):
        """An independent anchor with the same data (no new evaluation).

        Returns
        -------
        Anchor
        """
        out: Anchor = Anchor.__new__(Anchor)
        out.k, out.m, out.k_int, out.e_int = self.k, self.m, self.k_int, self.e_int
        out.f, out.f1, out.f2, out.f2_f1, out.inv_f1 = (
            self.f,
            self.f1,
            self.f2,
            self.f2_f1,
            self.inv_f1,
        )
        out.k1, out.k2, out.e1, out.e2 = self.k1, self.k2, self.e1, self.e2
        return out

    @cython.ccall
    def set(self, k: cython.double):
        """Anchor at ellipticity ``k`` > 1: K(m), E(m) by scipy.special, derivatives from
        dK/dm = (E − (1 − m)·K)/(2m(1 − m)), dE/dm = (E − K)/(2m) (Byrd & Friedman 1971,
        710.00, 710.02) and their derivatives (:func:`~.kernels.contact.elliptic_slopes`), F(k)
        and its derivatives (:func:`~.kernels.contact.hertz_relation`)."""
        m: cython.double = 1.0 - 1.0 / (k * k)
        ki: cython.double = float(ellipk(m))
        ei: cython.double = float(ellipe(m))
        k1: cython.double
        k2: cython.double
        e1: cython.double
        e2: cython.double
        f: cython.double
        f1: cython.double
        f2: cython.double
        k1, k2, e1, e2 = elliptic_slopes(m, ki, ei)
        f, f1, f2 = hertz_relation(k, ki, ei)
        self.k, self.m, self.k_int, self.e_int = k, m, ki, ei
        self.f, self.f1, self.f2 = f, f1, f2
        self.inv_f1, self.f2_f1 = 1.0 / f1, f2 / f1
        self.k1, self.k2, self.e1, self.e2 = k1, k2, e1, e2


@cython.ccall
def contact_terms(
    c: PairConstants,
    gamma: cython.double,
    inv_f: cython.double,
    inner: cython.bint,
    anc: Anchor,
) -> Terms:
    """Hertz constants of the inner or outer contact at γ = Dw·cos α/dm and 1/f = Dw/r:
    :func:`hertz.curvature_sum_difference` and :func:`hertz.contact_constants` rearranged, with
    the ellipticity to second order from the anchor ``anc``; each with its first and second
    derivatives in γ and its first derivative in 1/f (chain rule through the race term,
    F(ρ), k, m = 1 − 1/k² and the anchor's expansions of K and E).

    The constants depend on the ball diameter only through Dw^(∓1/3): c_δ·Dw^(1/3) and
    a_coef/Dw^(1/3) are returned.

    Parameters
    ----------
    c : PairConstants
        The pair's data (its compliance [1/Pa]).
    gamma : float
        γ = Dw·cos α/dm [-].
    inv_f : float
        1/f = Dw/r [-] of the groove.
    inner : bool
        True for the inner contact, False for the outer.
    anc : Anchor
        The contact's anchor (exact Hertz data at an ellipticity k0 near the contact's).

    Returns
    -------
    tuple
        16 floats, four per quantity (value, d/dγ, ½·d²/dγ², ∂/∂(1/f)) of: c_δ·Dw^(1/3)
        [m^(4/3)/N^(2/3)] (c_δ = K_c^(−2/3), K_c the contact's load–deflection constant),
        a_coef/Dw^(1/3) [m^(2/3)/N^(1/3)], the ellipticity k [-] and E(m) [-]
        (b_coef = a_coef/k).

    Examples
    --------
    Anchored at the exact ellipticity, the values are those of
    :func:`equilibrium.contact_constants_at` (71803, inner contact at 15°):

    >>> import math
    >>> from servofmu.physics.contact import equilibrium
    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> c, g = PairConstants(pair), pair.bearing.race_geometry()
    >>> inner = equilibrium.contact_constants_at(g, math.radians(15))[0]
    >>> gamma = g.ball_diameter * math.cos(math.radians(15)) / g.pitch_diameter
    >>> t = contact_terms(c, gamma, 1 / 0.56, True, Anchor(inner.ellipticity))
    >>> len(t), round(t[8], 6), round(float(inner.ellipticity), 6)  # k
    (16, 4.626368, 4.626368)
    >>> stiffness = (t[0] / math.cbrt(g.ball_diameter)) ** -1.5  # K_c = c_δ^(−3/2) [N/m^1.5]
    >>> round(stiffness / float(inner.stiffness), 9)
    1.0
    """
    u: cython.double
    rt: cython.double
    r1: cython.double
    r2: cython.double
    if inner:
        u = 1.0 / (1.0 - gamma)
        rt, r1, r2 = 2.0 * gamma * u, 2.0 * u * u, 4.0 * u * u * u  # race term, d/dγ, d²/dγ²
    else:
        u = 1.0 / (1.0 + gamma)
        rt, r1, r2 = -2.0 * gamma * u, -2.0 * u * u, 4.0 * u * u * u
    den: cython.double
    f_rho: cython.double
    den, f_rho = race_curvature(gamma, inv_f, inner)  # Σρ·Dw, F(ρ)
    g4: cython.double = (4.0 - 2.0 * inv_f) / (den * den)
    f_g: cython.double = g4 * r1  # dF/dγ
    f_gg: cython.double = g4 * (r2 - 2.0 * r1 * r1 / den)
    f_f: cython.double = (4.0 + 2.0 * rt) / (den * den)  # ∂F/∂(1/f)
    inv_f1: cython.double = anc.inv_f1
    f2_f1: cython.double = anc.f2_f1
    k1: cython.double = anc.k1
    k2: cython.double = anc.k2
    e1: cython.double = anc.e1
    e2: cython.double = anc.e2
    q: cython.double = (f_rho - anc.f) * inv_f1  # Δk to first order
    k: cython.double = anc.k + q * (1.0 - 0.5 * f2_f1 * q)  # Δk = ΔF/F' − F''·ΔF²/(2F'³)
    k_f: cython.double = (1.0 - f2_f1 * q) * inv_f1  # dk/dF
    k_ff: cython.double = -f2_f1 * inv_f1 * inv_f1
    kg: cython.double = k_f * f_g
    kgg: cython.double = k_ff * f_g * f_g + k_f * f_gg
    kf: cython.double = k_f * f_f
    ik: cython.double = 1.0 / k
    m_k: cython.double = 2.0 * ik * ik * ik  # m = 1 − 1/k²
    mg: cython.double = m_k * kg
    mgg: cython.double = m_k * (kgg - 3.0 * ik * kg * kg)
    mf: cython.double = m_k * kf
    dm: cython.double = (1.0 - ik * ik) - anc.m
    ki: cython.double = anc.k_int + (k1 + 0.5 * k2 * dm) * dm
    ei: cython.double = anc.e_int + (e1 + 0.5 * e2 * dm) * dm
    km: cython.double = k1 + k2 * dm  # dK/dm
    em: cython.double = e1 + e2 * dm  # dE/dm
    lk_g: cython.double = km * mg / ki
    lk_gg: cython.double = (k2 * mg * mg + km * mgg) / ki
    lk_f: cython.double = km * mf / ki
    le_g: cython.double = em * mg / ei
    le_gg: cython.double = (e2 * mg * mg + em * mgg) / ei
    le_f: cython.double = em * mf / ei
    # ln X = (ln Σρ·Dw − 2 ln k − ln E)/3, X·Dw^(−1/3) = (Σρ/(k²·E))^(1/3)
    lx_g: cython.double = (r1 / den - 2.0 * kg * ik - le_g) * _THIRD
    lx_gg: cython.double = (
        r2 / den - (r1 / den) ** 2 - 2.0 * (kgg * ik - (kg * ik) ** 2) - (le_gg - le_g * le_g)
    ) * _THIRD
    lx_f: cython.double = (-1.0 / den - 2.0 * kf * ik - le_f) * _THIRD
    # the coefficients at Σρ·Dw: c_δ·Dw^(1/3) and a*/Dw^(1/3)
    ac: cython.double
    cd: cython.double
    ac, _, cd = hertz_coefficients(den, k, ki, ei, c.compliance)
    lc_g: cython.double = lk_g + lx_g
    return (
        cd,
        cd * lc_g,
        0.5 * cd * (lc_g * lc_g + lk_gg - lk_g * lk_g + lx_gg),
        cd * (lk_f + lx_f),
        ac,
        -ac * lx_g,
        0.5 * ac * (lx_g * lx_g - lx_gg),
        -ac * lx_f,
        k,
        kg,
        0.5 * kgg,
        kf,
        ei,
        ei * le_g,
        0.5 * ei * le_gg,
        ei * le_f,
    )


def exact_contact_k(th: Thermal, cos_a: float, inner: bool) -> float:
    """The exact ellipticity [-] of the inner or outer contact at the angle with cosine
    ``cos_a`` (:func:`hertz.ellipticity` on the curvature difference): an anchor's start.

    Parameters
    ----------
    th : Thermal
        Thermal state of the step (:func:`thermal_at`).
    cos_a : float
        cos α [-] of the contact angle α.
    inner : bool
        True for the inner contact, False for the outer.

    Returns
    -------
    float
        k = a/b [-].

    Examples
    --------
    The same as :func:`equilibrium.contact_constants_at` on the mounted geometry:

    >>> import math
    >>> from servofmu.physics.pair.constants import thermal_at
    >>> from servofmu.physics.contact import equilibrium
    >>> from servofmu.physics.thermal import fits
    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> c = PairConstants(pair)
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> race = fits.mounted_geometry(pair.bearing, pair.mounting.fit, c.t0, c.t0).race
    >>> outer = equilibrium.contact_constants_at(race, math.radians(15))[1]
    >>> round(exact_contact_k(th, math.cos(math.radians(15)), False), 9)
    5.097093463
    >>> round(float(outer.ellipticity), 9)
    5.097093463
    """
    from ..contact.hertz import ellipticity

    inv_f = th.inv_f_inner if inner else th.inv_f_outer
    return float(ellipticity(race_curvature(th.gamma_scale * cos_a, inv_f, inner)[1]))


@cython.final
@cython.cclass
class Ball:
    """One ball position of a bearing: azimuth cosine cos ψ and weight (Z for the one ball of
    pure axial load; 1 or 2 over half the ring under a radial load), the anchors of its inner
    and outer contacts, its base (:func:`ball_base`) or None, and the state at the last
    evaluation: load Q [N], cos α, sin α.

    Parameters
    ----------
    cos_psi : float
        cos ψ [-].
    weight : float
        How many balls it stands for [-].
    anc_i, anc_o : Anchor
        The anchors of its inner and outer contacts.
    """

    cos_psi: cython.double
    weight: cython.double
    anc_i: Anchor
    anc_o: Anchor
    base: object
    load: cython.double
    cos_a: cython.double
    sin_a: cython.double
    __slots__ = ("anc_i", "anc_o", "base", "cos_a", "cos_psi", "load", "sin_a", "weight")

    def __init__(self, cos_psi: cython.double, weight: cython.double, anc_i: Anchor, anc_o: Anchor):
        self.cos_psi, self.weight, self.anc_i, self.anc_o = cos_psi, weight, anc_i, anc_o
        self.base = None
        self.load = self.cos_a = self.sin_a = 0.0


@cython.ccall
def ball_base(
    c: PairConstants, gamma: cython.double, inv_f_i: cython.double, inv_f_o: cython.double, b: Ball
) -> tuple:
    """The base of ball ``b`` at γ = Dw·cos α/dm and the grooves' 1/f: (γ0, 1/f_i0, 1/f_o0,
    the c_δ terms of the inner and outer contact (8 floats), their a_coef, k and E terms (24
    floats)) from :func:`contact_terms`. Within :data:`GAMMA_SPAN` in γ and :data:`INV_F_SPAN`
    in 1/f the Hertz constants are taken to second order in γ and first order in 1/f, at any
    thermal state.

    Parameters
    ----------
    c : PairConstants
        The pair's data.
    gamma : float
        γ = Dw·cos α/dm [-].
    inv_f_i, inv_f_o : float
        1/f = Dw/r [-] of the inner and outer groove.
    b : Ball
        The ball (its anchors).

    Returns
    -------
    tuple
        (γ0 [-], 1/f_i0 [-], 1/f_o0 [-], 8 floats, 24 floats): the terms of
        :func:`contact_terms` (units there).

    Examples
    --------
    >>> import math
    >>> from servofmu.physics.pair.constants import thermal_at
    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> cos_a = math.cos(math.radians(15))
    >>> k_i, k_o = exact_contact_k(th, cos_a, True), exact_contact_k(th, cos_a, False)
    >>> ball = Ball(0.0, 15.0, Anchor(k_i), Anchor(k_o))  # cos ψ, weight Z
    >>> base = ball_base(c, th.gamma_scale * cos_a, th.inv_f_inner, th.inv_f_outer, ball)
    >>> len(base[3]), len(base[4]), round(base[1], 6)  # 1/f_i0 = 1/0.56
    (8, 24, 1.785714)
    """
    ti = contact_terms(c, gamma, inv_f_i, True, b.anc_i)
    to = contact_terms(c, gamma, inv_f_o, False, b.anc_o)
    return (
        gamma,
        inv_f_i,
        inv_f_o,
        (ti[0], ti[1], ti[2], ti[3], to[0], to[1], to[2], to[3]),
        (
            ti[4], ti[5], ti[6], ti[7], ti[8], ti[9], ti[10], ti[11], ti[12], ti[13], ti[14],
            ti[15], to[4], to[5], to[6], to[7], to[8], to[9], to[10], to[11], to[12], to[13],
            to[14], to[15],
        ),
    )  # fmt: skip


# ------------------------------------------------------------------ one bearing's balls
@cython.ccall
def ring_point(th: Thermal, c: PairConstants, a: cython.double, dr: cython.double,
               balls: list) -> Ring:  # fmt: skip
    """One bearing at axial offset ``a`` [m] and radial displacement ``dr`` [m] (Jones 1960;
    :func:`equilibrium.ball_loads` without tilt): each ball's load Q_j = K_n(α_j)·δ_j^1.5,
    stored on the :class:`Ball`, and the ring's loads and Jacobian.

    Parameters
    ----------
    th : Thermal
        Thermal state of the step (:func:`thermal_at`).
    c : PairConstants
        The pair's data.
    a : float
        Axial offset [m] of the groove curvature centres from the centred position.
    dr : float
        Radial displacement δr [m] of the inner ring along ψ = 0.
    balls : list of Ball
        The bearing's ball positions (cos ψ, weight, anchors, base); their load, cos α and
        sin α are set.

    Returns
    -------
    tuple
        (Fa = Σ w·Q·sin α [N], Fr = Σ w·Q·cos α·cos ψ [N], dFa/da, dFa/dδr, dFr/da, dFr/dδr
        [N/m] with K_n(α) varied, dFa/da with K_n held [N/m] (the output stiffness), the
        smallest deflection of a loaded ball [m] (A when no ball is loaded)).

    Examples
    --------
    Pure axial load, one ball of weight Z = 15: the same as :func:`equilibrium.axial_state`
    on the mounted geometry:

    >>> import math
    >>> from servofmu.physics.pair.constants import thermal_at
    >>> from servofmu.physics.contact import equilibrium
    >>> from servofmu.physics.thermal import fits
    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> c = PairConstants(pair)
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> cos_a = th.radial_centre_distance / math.hypot(70e-6, th.radial_centre_distance)
    >>> k_i, k_o = exact_contact_k(th, cos_a, True), exact_contact_k(th, cos_a, False)
    >>> r = ring_point(th, c, 70e-6, 0.0, [Ball(0.0, 15.0, Anchor(k_i), Anchor(k_o))])
    >>> round(r[0], 4), round(r[1], 4), round(r[6] / 1e6, 4)  # N, N, N/µm
    (210.6691, 0.0, 19.4344)
    >>> race = fits.mounted_geometry(pair.bearing, pair.mounting.fit, c.t0, c.t0).race
    >>> s = equilibrium.axial_state(race, 70e-6)
    >>> round(float(s.axial_force), 4), round(float(s.axial_stiffness) / 1e6, 4)  # N, N/µm
    (210.6691, 19.4344)
    """
    a2_0: cython.double = th.radial_centre_distance
    dist: cython.double = th.curvature_distance
    gs: cython.double = th.gamma_scale
    f_i: cython.double = th.inv_f_inner
    f_o: cython.double = th.inv_f_outer
    dw_m13: cython.double = 1.0 / th.dw_third
    gs_dw: cython.double = gs * dw_m13  # d c_δ/d cos α = (d c_δ·Dw^(1/3)/dγ)·(Dw/dm)·Dw^(−1/3)
    fa: cython.double = 0.0
    fr: cython.double = 0.0
    j11: cython.double = 0.0
    j12: cython.double = 0.0
    j21: cython.double = 0.0
    j22: cython.double = 0.0
    kax: cython.double = 0.0
    d_min: cython.double = dist
    b: Ball
    cp: cython.double
    s: cython.double
    cos_a: cython.double
    sin_a: cython.double
    delta: cython.double
    gamma: cython.double
    g0: cython.double
    fi0: cython.double
    fo0: cython.double
    ci0: cython.double
    ci1: cython.double
    ci2: cython.double
    cif: cython.double
    co0: cython.double
    co1: cython.double
    co2: cython.double
    cof: cython.double
    d: cython.double
    k_n: cython.double
    q: cython.double
    slope: cython.double
    k11: cython.double
    k12: cython.double
    k21: cython.double
    k22: cython.double
    held: cython.double
    ci: cython.double
    co: cython.double
    w: cython.double
    wc: cython.double
    for b in balls:
        cp = b.cos_psi
        s, sin_a, cos_a, delta = ball_contact(a, a2_0 + dr * cp, dist)
        b.cos_a, b.sin_a = cos_a, sin_a
        if delta <= 0.0:
            b.load = 0.0
            continue
        if delta < d_min:
            d_min = delta
        base = b.base
        gamma = gs * cos_a
        if base is None:
            base = b.base = ball_base(c, gamma, f_i, f_o, b)
        g0, fi0, fo0, terms, _ = base
        if abs(gamma - g0) > _G_SPAN or abs(f_i - fi0) > _F_SPAN or abs(f_o - fo0) > _F_SPAN:
            base = b.base = ball_base(c, gamma, f_i, f_o, b)
            g0, fi0, fo0, terms, _ = base
        d = gamma - g0
        ci0, ci1, ci2, cif, co0, co1, co2, cof = terms
        ci = (ci0 + d * (ci1 + ci2 * d) + cif * (f_i - fi0)) * dw_m13
        co = (co0 + d * (co1 + co2 * d) + cof * (f_o - fo0)) * dw_m13
        k_n = series_stiffness(ci, co)
        q = hertz_load(k_n, delta)
        b.load = q
        # dK_n/dα = −1.5·K_n·(dc_i + dc_o)/dα/(c_i + c_o), dc/dα = −sin α·dc/d cos α
        slope = 1.5 * k_n * (ci1 + co1) * gs_dw / (ci + co) * sin_a
        k11, k12, k21, k22, held = ball_stiffness(q, s, delta, k_n, slope, sin_a, cos_a)
        w = b.weight
        wc = w * cp
        fa += w * q * sin_a
        fr += wc * q * cos_a
        j11 += w * k11
        j12 += wc * k12
        j21 += wc * k21
        j22 += wc * cp * k22
        kax += w * held
    return fa, fr, j11, j12, j21, j22, kax, d_min


@cython.ccall
def ring_sums(th: Thermal, c: PairConstants, balls: list, ehl: object = None) -> Sums:
    """Weighted sums over one bearing's balls at their last evaluation: (hysteresis, spin,
    sliding, inner ring, outer ring torques [N·m], largest pressure [Pa], Σ w·Q [N],
    Σ w·Q·α [N·rad], Fa [N], redo), with the Hertz constants from the balls' bases. With
    ``ehl`` five lists (a friction model of the contacts' terms, :mod:`.friction.registry`),
    the terms of the model's ``contact_rolling_terms`` of every loaded contact (inner, then
    outer, ball by ball; the scale times the ball's weight) are appended to them.

    The torques are those of :func:`friction.ball_torque_terms` (Yu 2017 eq 1–3, 5–7; Ning)
    at the race radii (dm ∓ Dw·cos α)/2: each term is a product of powers of the load, the
    semi-axes and E(e), so its coefficient is the friction kernel at unit arguments
    (:func:`set_coefficients`) and a ball costs a few products (tests/physics/test_continuation.py
    checks the two agree).

    Every anchor whose contact's ellipticity moved more than :data:`ANCHOR_DRIFT` from it is
    renewed at the current k (for the next step; the ball's base is dropped); ``redo`` is True
    when one moved more than :data:`ANCHOR_REDO` (the step is then solved again).

    Parameters
    ----------
    th : Thermal
        Thermal state of the step (:func:`thermal_at`).
    c : PairConstants
        The pair's data.
    balls : list of Ball
        The bearing's balls, after :func:`ring_point` (their loads and bases).
    ehl : list of 5 lists, or None
        Where the EHL terms go (the dynamic viscosity from ``th`` and ``c``), or None.

    Returns
    -------
    tuple
        The 10 entries listed above: five torques [N·m], pressure [Pa], Σ w·Q [N],
        Σ w·Q·α [N·rad], Fa [N], redo (bool).

    Examples
    --------
    After the :func:`ring_point` example: Fa is the same, and the inner and outer ring
    torques add up to hysteresis + spin + sliding (by construction):

    >>> import math
    >>> from servofmu.physics.pair.constants import thermal_at
    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> cos_a = th.radial_centre_distance / math.hypot(70e-6, th.radial_centre_distance)
    >>> k_i, k_o = exact_contact_k(th, cos_a, True), exact_contact_k(th, cos_a, False)
    >>> balls = [Ball(0.0, 15.0, Anchor(k_i), Anchor(k_o))]
    >>> fa = ring_point(th, c, 70e-6, 0.0, balls)[0]
    >>> s = ring_sums(th, c, balls)
    >>> s[8] == fa, round(s[0] * 1e3, 4), round(s[1] * 1e3, 4), s[2]  # N·mm
    (True, 0.795, 1.609, 0.0)
    >>> round((s[3] + s[4]) * 1e3, 4), round((s[0] + s[1] + s[2]) * 1e3, 4)  # N·mm
    (2.404, 2.404)
    """
    dw: cython.double = th.ball_diameter
    dm: cython.double = th.pitch_diameter
    gs: cython.double = th.gamma_scale
    f_i: cython.double = th.inv_f_inner
    f_o: cython.double = th.inv_f_outer
    dw_third: cython.double = th.dw_third
    if not th.has_coefficients:
        set_coefficients(th, c)
    c_h: cython.double = th.c_hysteresis
    c_sl_i: cython.double = th.c_sliding_inner
    c_sl_o: cython.double = th.c_sliding_outer
    c_sp: cython.double = th.c_spin
    solid: cython.bint = c.solid
    hyst: cython.double = 0.0
    spin: cython.double = 0.0
    slide: cython.double = 0.0
    inner: cython.double = 0.0
    outer: cython.double = 0.0
    p_max: cython.double = 0.0
    qsum: cython.double = 0.0
    qalpha: cython.double = 0.0
    fa: cython.double = 0.0
    redo: cython.bint = False
    eta: cython.double = th.kinematic_viscosity * c.density if ehl is not None else 0.0
    b: Ball
    q: cython.double
    w: cython.double
    cos_a: cython.double
    sin_a: cython.double
    g0: cython.double
    fi0: cython.double
    fo0: cython.double
    d: cython.double
    d_i: cython.double
    d_o: cython.double
    ai0: cython.double
    ai1: cython.double
    ai2: cython.double
    aif: cython.double
    ki0: cython.double
    ki1: cython.double
    ki2: cython.double
    kif: cython.double
    ei0: cython.double
    ei1: cython.double
    ei2: cython.double
    eif: cython.double
    ao0: cython.double
    ao1: cython.double
    ao2: cython.double
    aof: cython.double
    ko0: cython.double
    ko1: cython.double
    ko2: cython.double
    kof: cython.double
    eo0: cython.double
    eo1: cython.double
    eo2: cython.double
    eof: cython.double
    sp_i: cython.double
    sp_o: cython.double
    anc_i: Anchor
    anc_o: Anchor
    a_i: cython.double
    a_o: cython.double
    k_i: cython.double
    k_o: cython.double
    e_i: cython.double
    e_o: cython.double
    b_i: cython.double
    b_o: cython.double
    q3: cython.double
    qa_i: cython.double
    qa_o: cython.double
    r_in: cython.double
    r_out: cython.double
    h_i: cython.double
    h_o: cython.double
    sl_i: cython.double
    sl_o: cython.double
    sin_abs: cython.double
    p: cython.double
    drift_i: cython.double
    drift_o: cython.double
    for b in balls:
        q = b.load
        if q <= 0.0:
            continue
        w, cos_a, sin_a = b.weight, b.cos_a, b.sin_a
        g0, fi0, fo0, _, terms = b.base
        d, d_i, d_o = gs * cos_a - g0, f_i - fi0, f_o - fo0
        (ai0, ai1, ai2, aif, ki0, ki1, ki2, kif, ei0, ei1, ei2, eif,
         ao0, ao1, ao2, aof, ko0, ko1, ko2, kof, eo0, eo1, eo2, eof) = terms  # fmt: skip
        a_i = (ai0 + d * (ai1 + ai2 * d) + aif * d_i) * dw_third  # a_coef
        a_o = (ao0 + d * (ao1 + ao2 * d) + aof * d_o) * dw_third
        k_i = ki0 + d * (ki1 + ki2 * d) + kif * d_i
        k_o = ko0 + d * (ko1 + ko2 * d) + kof * d_o
        e_i = ei0 + d * (ei1 + ei2 * d) + eif * d_i
        e_o = eo0 + d * (eo1 + eo2 * d) + eof * d_o
        b_i, b_o = a_i / k_i, a_o / k_o  # b_coef
        q3 = cbrt(q)
        qa_i, qa_o = q * q3 * a_i, q * q3 * a_o  # Q·a
        r_in, r_out = 0.5 * (dm - dw * cos_a), 0.5 * (dm + dw * cos_a)
        h_i, h_o = c_h * q * q3 * b_i * r_in, c_h * q * q3 * b_o * r_out
        sl_i, sl_o = c_sl_i * qa_i * a_i * q3 * r_in, c_sl_o * qa_o * a_o * q3 * r_out
        sin_abs = abs(sin_a)
        sp_i = c_sp * qa_i * e_i * sin_abs
        sp_o = c_sp * qa_o * e_o * sin_abs
        if solid or sp_i >= sp_o:  # Ning: the inner race spins; Yu eq 7: the larger moment
            sp_o = 0.0
        else:
            sp_i = 0.0
        hyst += w * (h_i + h_o)
        spin += w * (sp_i + sp_o)
        slide += w * (sl_i + sl_o)
        inner += w * (h_i + sl_i + sp_i)
        outer += w * (h_o + sl_o + sp_o)
        p = hertz_pressure(q, min(a_i * b_i, a_o * b_o) * q3 * q3)
        if p > p_max:
            p_max = p
        qsum += w * q
        qalpha += w * q * atan2(sin_a, cos_a)
        fa += w * q * sin_a
        if ehl is not None:
            _ehl_terms(th, c, ehl, q, q3, w, gs * cos_a, a_i, k_i, e_i, a_o, k_o, e_o, eta)
        anc_i, anc_o = b.anc_i, b.anc_o
        drift_i = abs(k_i - anc_i.k)
        drift_o = abs(k_o - anc_o.k)
        if drift_i > _DRIFT * anc_i.k or drift_o > _DRIFT * anc_o.k:
            if drift_i > _DRIFT * anc_i.k:
                redo |= drift_i > _REDO * anc_i.k
                anc_i.set(k_i)
            if drift_o > _DRIFT * anc_o.k:
                redo |= drift_o > _REDO * anc_o.k
                anc_o.set(k_o)
            b.base = None
    return hyst, spin, slide, inner, outer, p_max, qsum, qalpha, fa, redo


def _ehl_terms(th: Thermal, c: PairConstants, ehl, q, q3, w, g, a_i, k_i, e_i, a_o, k_o, e_o,
               eta):  # fmt: skip
    """Append the inner and outer contact's terms of the friction model's
    ``contact_rolling_terms`` (:mod:`.friction.registry`) of one ball (load ``q`` [N], weight
    ``w``) to the five lists of ``ehl``."""
    terms = c.model.contact_rolling_terms
    dw, dm = th.ball_diameter, th.pitch_diameter
    for a, k, e, inv_f, on_inner in (
        (a_i, k_i, e_i, th.inv_f_inner, True),
        (a_o, k_o, e_o, th.inv_f_outer, False),
    ):
        t = terms(q, a * q3, k, e, g, dw, dm, inv_f, c.compliance, eta, on_inner)
        ehl[0].append(w * t[0])
        for j in range(1, 5):
            ehl[j].append(t[j])

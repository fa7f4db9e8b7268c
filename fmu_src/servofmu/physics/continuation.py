"""Per-step continuation solve of a bearing pair's thermal and load state, on Python floats.

The exact path (:func:`bearing.thermal_state`, :func:`bearing.load_state`) solves every
operating point from scratch with bracketing root finders over numpy arrays: robust, and the
reference, but about a millisecond per point. Inside an FMU the temperature and the loads
change a little from one communication step to the next, so this module solves the same
equations from the previous step's solution:

- the thermal state (ring growth, Lamé fits, clearance, loop closure, viscosity) is closed
  form: the equations of :func:`fits.mounted_geometry` and :func:`preload.loop_interference`
  written out on floats, and the lubricant's own law on floats
  (:meth:`viscosity.ViscosityRange.operating_viscosity_at`) (:func:`thermal_floats`);
- the pair's offsets and radial displacements x = (p, z, δr_A, δr_B) [m] solve the conditions
  of :func:`preload.pair_equilibrium` (F_A − F_B = F_ext, Fr_A = Fr_B = F_r/2,
  (F_A + F_B)/2 = k·(C − 2p)) by Newton's method with the analytic Jacobian, the contact
  angle's effect on the Hertz constants included, started from a predictor: the previous
  solution moved by the tangent of the load change (the last Jacobian) and by the secant of
  the last temperature change when the temperatures move on in the same direction. The
  radial rows are eliminated by hand (they involve one bearing each), which leaves a 2×2
  system in the bearings' axial offsets (:func:`newton_step`). A bearing with no ball in
  contact under a radial load (its radial row is empty) is first moved radially until its
  ball nearest the load's direction touches (:meth:`PairSolver._touch`);
- under pure axial load every ball of a bearing is alike (Yu 2017 eq 4): a bearing is one ball
  of weight Z (one unknown less when the load is zero, none for a rigid loop at zero load);
  under a radial load every ball differs (Jones 1960): the balls of half the ring (the load is
  symmetric about the radial load's direction) with weights 1 or 2, one ball at a time on
  floats (faster than numpy over a dozen balls);
- the Hertz constants of each contact need the ellipticity k, the root of the Hertz relation
  F(k) = F(ρ) (:func:`hertz.ellipticity`). Each contact keeps an *anchor*: k0 with the exact
  K(m0), E(m0), F(k0) and its derivatives (scipy.special). k, K and E are taken to second order
  from the anchor, whose error is below C·(Δk/k)³ with C ≈ 2 (measured on the catalogue
  bearings); the anchor is renewed for the next step at the current k when |Δk| exceeds
  :data:`ANCHOR_DRIFT`·k, and the step is solved again when it exceeds :data:`ANCHOR_REDO`·k,
  which keeps every Hertz constant within about 2e-11 of the exact one;
- the Hertz constants depend on the contact angle only through γ = Dw·cos α/dm, on the
  thermal state through γ, the grooves' 1/f = Dw/r and Dw^(∓1/3), and weakly on γ (relative
  first derivatives of 0.1–0.8, second of 0.1–0.2 on the catalogue bearings). Each ball
  keeps a *base*: the Hertz constants with their first and second derivatives in γ and first
  in 1/f at one (γ0, 1/f0) (:func:`contact_terms`); within :data:`GAMMA_SPAN` and
  :data:`INV_F_SPAN` of it they follow to second order in γ and first order in 1/f (relative
  error below 2e-12, tests/test_continuation.py), at any temperature: on a ramp a ball
  evaluates the Hertz relation again every ten to twenty steps, not every step (1/f is
  constant while balls and rings share their temperature and expansion).

Newton stops at the first point whose next correction is below 1e-12 of the curvature distance
A (about 1e-16 m, the absolute tolerance of the exact path's root finders) and below 2e-10 of
the smallest deflection of a loaded ball (a ball load Q ∝ δ^1.5 and its stiffness ∝ δ^0.5 then
move by less than 3e-10 of their value; a ball that barely touches needs the finer step), or
at rounding (1e-15·A): with the analytic Jacobian and the predictor that is about two
evaluations per step on a temperature ramp (measured 2.1 with 20 N axial load, 2.6 with the
axial and radial loads changing every step: benchmarks/bench_fmus.py's loops). A step that
does not converge in :data:`MAX_ITERATIONS`, a singular Jacobian (no ball in contact while the
external load is not zero), or a non-finite value returns None, and the caller falls back to
the exact path. The outputs equal the exact path's to a relative 1e-9 (tests check this on
random trajectories of temperature and load).

The continuation state (:meth:`PairSolver.state`) is a JSON-serialisable dict of floats (the
solution and its inputs, the anchors' k, the bases' γ0 and 1/f0, the last Jacobian and
temperature secant of the predictor): a restored solver continues bit for bit.

The thermal state takes the four parts' temperatures (housing, shaft, outer ring, inner ring);
a uniform temperature is four equal ones.
"""

from __future__ import annotations

import math

from scipy.special import ellipe, ellipk

from .ehl_rolling import contact_rolling_terms
from .friction import _heathcote, _hysteresis, _spin
from .friction_models import skf_loads
from .hertz import ellipticity
from .materials import reduced_compliance
from .pair import assembly_geometry, effective_shim, is_tandem, loop_stiffness, tandem_preload
from .pair_state import PointState, axial_play, preload_force, rest_torque, state_flags
from .preload import ROLES

#: Relative change of a contact's ellipticity from its anchor beyond which the anchor is
#: renewed for the next step (the second-order expansion's error is below 2e-12 there:
#: measured 1.8e-12 for k, K and E at F = 0.85…0.97, tests/test_continuation.py).
ANCHOR_DRIFT = 1e-4
#: Relative change beyond which the step is solved again with the renewed anchors (error of
#: the expansion below 2e-11 up to there, tests/test_continuation.py).
ANCHOR_REDO = 2e-4
#: Largest |Δγ| (γ = Dw·cos α/dm) and |Δ(1/f)| from a ball's base within which its Hertz
#: constants are taken to second order in γ and first order in 1/f (relative error below 2e-12
#: on the catalogue bearings, tests/test_continuation.py).
GAMMA_SPAN = 5e-5
INV_F_SPAN = 3e-9
#: Newton iterations of one step before the exact path takes over.
MAX_ITERATIONS = 12
#: Newton iterations of each stage of a cold start (:meth:`PairSolver.start`): from the loop
#: closure's half to a barely loaded contact the convergence is linear (ratio 1/3, Hertz's
#: Q ∝ δ^1.5) until the quadratic phase.
START_ITERATIONS = 60
#: The smallest share of the external load a cold start adds in one stage (it halves a stage
#: whose Newton's method fails, down to this).
START_SMALLEST_STAGE = 1.0 / 256.0
#: Newton stops at the first point whose next correction is below this fraction of the
#: curvature distance A (≈ 1e-16 m for the catalogue bearings, the exact path's tolerance).
_TOLERANCE = 1e-12
#: ... and below this fraction of the smallest deflection of a loaded ball (a ball load
#: Q ∝ δ^1.5 and its stiffness ∝ δ^0.5 then move by less than 3e-10 of their value), unless it
#: is below rounding (this fraction of A).
_DEFLECTION_TOLERANCE = 2e-10
_ROUNDING = 1e-15
#: Rounds of anchor renewal within one step before the exact path takes over.
MAX_ANCHOR_ROUNDS = 6

_sqrt, _cbrt, _atan2, _hypot = math.sqrt, math.cbrt, math.atan2, math.hypot
_THIRD = 1.0 / 3.0
_PI = math.pi
_2_PI = 2.0 / math.pi
_PI_2 = 0.5 * math.pi
_INF = math.inf


def _ratio(d_small, d_large):
    return (d_large * d_large + d_small * d_small) / (d_large * d_large - d_small * d_small)


class PairConstants:
    """The pair's data as floats, for the per-step equations (built once per configuration).

    Parameters
    ----------
    pair : :class:`~.bearing.BearingPair`
    """

    def __init__(self, pair):
        b, m = pair.bearing, pair.mounting
        fit, loop = m.fit, m.loop
        ring, ball = b.ring_material, b.ball_material
        hm, sm = fit.housing_material, fit.shaft_material
        self.t0 = float(m.assembly_temperature)
        self.outer_diameter, self.bore = float(b.outer_diameter), float(b.bore)
        self.outer_groove, self.inner_groove = (
            float(b.outer_groove_diameter),
            float(b.inner_groove_diameter),
        )
        self.ball_diameter = float(b.ball_diameter)
        self.inner_curvature, self.outer_curvature = (
            float(b.inner_curvature),
            float(b.outer_curvature),
        )
        self.n_balls = int(b.n_balls)
        eta = float(reduced_compliance(ring, ball))
        self.compliance = eta
        # c_δ = C_c·K·X and a_coef = C_a/X with X = (Σρ/(k²·E))^(1/3): hertz._constants
        # rearranged (b_coef = a_coef/k), one cube root per contact
        self.c_delta_coef = 0.5 * _2_PI * _PI_2**_THIRD * (1.5 * eta) ** (2.0 / 3.0)
        self.a_coef = (3.0 * eta / _PI) ** _THIRD
        self.alpha_ring, self.e_ring, self.nu_ring = (
            ring.expansion,
            ring.youngs_modulus,
            ring.poisson_ratio,
        )
        self.alpha_ball = ball.expansion
        self.alpha_housing, self.e_housing, self.nu_housing = (
            hm.expansion,
            hm.youngs_modulus,
            hm.poisson_ratio,
        )
        self.alpha_shaft, self.e_shaft, self.nu_shaft = (
            sm.expansion,
            sm.youngs_modulus,
            sm.poisson_ratio,
        )
        self.outer_interference = float(fit.outer_interference)
        self.inner_interference = float(fit.inner_interference)
        self.housing_outer_diameter = float(fit.housing_outer_diameter)
        self.shaft_bore = float(fit.shaft_bore)
        self.coupled = bool(pair.thermal_coupling)
        # the Lamé terms of fits.mounted_geometry whose diameters grow together (ring with its
        # groove): ring compliances per diameter, and the groove's change per unit pressure
        od, og, bo, ig = self.outer_diameter, self.outer_groove, self.bore, self.inner_groove
        e_r, nu_r = self.e_ring, self.nu_ring
        self.seat_outer = od - self.outer_interference  # housing bore at T0
        self.seat_inner = bo + self.inner_interference  # shaft seat at T0
        self.outer_ring_compliance = (_ratio(og, od) - nu_r) / e_r
        self.inner_ring_compliance = (_ratio(bo, ig) + nu_r) / e_r
        self.outer_groove_per_pressure = 2.0 * od * od * og / (e_r * (od * od - og * og))
        self.inner_groove_per_pressure = 2.0 * bo * bo * ig / (e_r * (ig * ig - bo * bo))
        # loop closure C = 2·h(T0) + s − Σ σ·L·α·(T_part − T0), summed by part
        terms = [
            (ROLES[mm.role] * mm.length * mm.material.expansion, mm.part) for mm in loop.members
        ]
        self.loop_terms = tuple(terms)
        self.closure_housing = sum(k for k, part in terms if part == "housing")
        self.closure_shaft = sum(k for k, part in terms if part == "shaft")
        self.closure_rings = sum(k for k, part in terms if part not in ("housing", "shaft"))
        # a tandem pair: B's mismatch d(T) along the thrust instead of the loop closure (0 at
        # T0, :func:`pair.loop_closure`), and its preload spring's k_s and thrust T
        self.tandem = is_tandem(pair)
        self.closure0 = (
            0.0
            if self.tandem
            else 2.0 * float(assembly_geometry(pair).first_contact_offset)
            + float(effective_shim(pair))
        )
        self.spring_stiffness, self.thrust = tandem_preload(pair) if self.tandem else (0.0, 0.0)
        self.loop_stiffness = self.spring_stiffness if self.tandem else float(loop_stiffness(pair))
        visc = pair.lubricant
        # the lubricant's law on floats, held below its range, and the range (:mod:`.viscosity`)
        self.viscosity = None if visc is None else visc.operating_viscosity_at
        self.lubricant_range = (0.0, _INF) if visc is None else (visc.lower_limit, visc.upper_limit)
        self.coefficients = pair.coefficients
        self.lubrication = pair.lubrication
        self.solid = pair.lubrication == "solid"
        self.sliding = bool(pair.sliding)
        self.pressure_limit = float(pair.pressure_limit)
        self.friction_model = pair.friction.model
        self.density = float(pair.friction.lubricant_density)


class Thermal:
    """Thermal state of one step, as floats: the fields of :class:`~.bearing.ThermalState`
    that the outputs read, and the race geometry of :class:`~.geometry.RaceGeometry` that the
    contacts need (γ scale Dw/dm, 1/f = Dw/r of each groove)."""

    __slots__ = (
        "ball_diameter",
        "clearance",
        "closure",
        "curvature_distance",
        "dw_third",
        "first_contact_offset",
        "gamma_scale",
        "inner_fit_pressure",
        "inner_groove_radius",
        "inner_interference",
        "inv_f_inner",
        "inv_f_outer",
        "kinematic_viscosity",
        "outer_fit_pressure",
        "outer_groove_radius",
        "outer_interference",
        "outside_lubricant_range",
        "pitch_diameter",
        "radial_centre_distance",
        "rest_offset",
        "rest_torque",
        "temperatures",
        "torque_coefficients",
    )

    @property
    def free_contact_angle(self) -> float:
        """Free contact angle at the operating clearance [rad] (:class:`RaceGeometry`)."""
        a, pd = self.curvature_distance, self.clearance
        return math.acos(min(max(1.0 - max(pd, 0.0) / (2.0 * a), -1.0), 1.0))


def thermal_floats(c: PairConstants, temps: tuple[float, float, float, float]) -> Thermal:
    """Thermal state at the parts' temperatures ``temps`` = (housing, shaft, outer ring, inner
    ring) [K]: the equations of :func:`fits.mounted_geometry` (Yu 2017 eq 10–13),
    :func:`preload.loop_interference` (eq 14–15) and the lubricant's viscosity (eq 18, or
    Vogel's law; :mod:`.viscosity`) on floats, with the lubricant's range flag.

    Parameters
    ----------
    c : PairConstants
        The pair's data.
    temps : tuple of 4 floats
        (housing, shaft, outer ring, inner ring) temperatures [K].

    Returns
    -------
    Thermal
        Lengths [m], pressures [Pa], viscosity [m²/s].

    Examples
    --------
    At the assembly temperature the grooves keep their curvature, 1/f_i = 1/0.56 (by hand),
    and the clearance is that of :func:`fits.mounted_geometry` (9.6583 µm, 4.4114 MPa):

    >>> from servofmu.physics.pair import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_floats(c, (c.t0, c.t0, c.t0, c.t0))
    >>> round(th.inv_f_inner, 12) == round(1 / 0.56, 12)
    True
    >>> round(th.clearance * 1e6, 4), round(th.outer_fit_pressure / 1e6, 4)  # µm, MPa
    (9.6583, 4.4114)
    """
    t_h, t_s, t_o, t_i = temps
    t0 = c.t0
    t_b = 0.5 * (t_o + t_i)
    grow_o = 1.0 + c.alpha_ring * (t_o - t0)
    grow_i = 1.0 + c.alpha_ring * (t_i - t0)
    grow_h = 1.0 + c.alpha_housing * (t_h - t0)
    grow_s = 1.0 + c.alpha_shaft * (t_s - t0)
    d_ring_o = c.outer_diameter * grow_o
    d_ring_i = c.bore * grow_i
    d_groove_o = c.outer_groove * grow_o
    d_groove_i = c.inner_groove * grow_i
    delta_o = d_ring_o - c.seat_outer * grow_h
    delta_i = c.seat_inner * grow_s - d_ring_i
    th = Thermal()
    if c.coupled:
        d_h = c.housing_outer_diameter * grow_h
        d_sb = c.shaft_bore * grow_s
        k_out = (_ratio(d_ring_o, d_h) + c.nu_housing) / c.e_housing
        p_o = max(delta_o, 0.0) / (d_ring_o * (c.outer_ring_compliance + k_out))
        k_in = (_ratio(d_sb, d_ring_i) - c.nu_shaft) / c.e_shaft
        p_i = max(delta_i, 0.0) / (d_ring_i * (k_in + c.inner_ring_compliance))
        d_groove_o = d_groove_o - p_o * grow_o * c.outer_groove_per_pressure
        d_groove_i = d_groove_i + p_i * grow_i * c.inner_groove_per_pressure
    else:
        p_o = p_i = 0.0
    dw = c.ball_diameter * (1.0 + c.alpha_ball * (t_b - t0))
    r_i = c.inner_curvature * c.ball_diameter * grow_i
    r_o = c.outer_curvature * c.ball_diameter * grow_o
    pd = d_groove_o - d_groove_i - 2.0 * dw
    a = r_i + r_o - dw
    dm = 0.5 * (d_groove_i + d_groove_o)
    th.temperatures = temps
    th.ball_diameter, th.dw_third = dw, _cbrt(dw)
    th.rest_torque = th.torque_coefficients = th.rest_offset = None  # when first needed
    th.pitch_diameter = dm
    th.inner_groove_radius, th.outer_groove_radius = r_i, r_o
    th.inv_f_inner, th.inv_f_outer = dw / r_i, dw / r_o
    th.gamma_scale = dw / dm
    th.clearance = pd
    th.curvature_distance = a
    th.radial_centre_distance = a - 0.5 * pd
    th.closure = c.closure0 - (
        c.closure_housing * (t_h - t0) + c.closure_shaft * (t_s - t0) + c.closure_rings * (t_b - t0)
    )
    th.kinematic_viscosity = 0.0 if c.viscosity is None else c.viscosity(t_b)
    lo, hi = c.lubricant_range
    th.outside_lubricant_range = not lo <= t_b <= hi
    hp = 0.5 * min(max(pd, 0.0), 2.0 * a)  # geometry.first_contact_offset on floats
    th.first_contact_offset = _sqrt(max(a * a - (a - hp) * (a - hp), 0.0))
    th.outer_fit_pressure, th.inner_fit_pressure = p_o, p_i
    th.outer_interference, th.inner_interference = delta_o, delta_i
    return th


class Anchor:
    """Exact Hertz data of one contact at its anchor ellipticity k0 (see module docstring):
    K, E and their first and second derivatives in m, F(k0) and its first and second
    derivatives in k (``inv_f1`` = 1/F', ``f2_f1`` = F''/F'); ``data`` holds them as one tuple
    (k, m, K, E, F, 1/F', F''/F', K', K'', E', E'') for the per-step arithmetic."""

    __slots__ = (
        "data",
        "e1",
        "e2",
        "e_int",
        "f",
        "f1",
        "f2",
        "f2_f1",
        "inv_f1",
        "k",
        "k1",
        "k2",
        "k_int",
        "m",
    )

    def __init__(self, k: float):
        self.set(k)

    def copy(self) -> Anchor:
        """An independent anchor with the same data (no new evaluation)."""
        out = Anchor.__new__(Anchor)
        for name in Anchor.__slots__:
            setattr(out, name, getattr(self, name))
        return out

    def set(self, k: float) -> None:
        """Anchor at ellipticity ``k`` > 1: K(m), E(m) by scipy.special, derivatives from
        dK/dm = (E − (1 − m)·K)/(2m(1 − m)), dE/dm = (E − K)/(2m) (Byrd & Friedman 1971,
        710.00, 710.02) and their derivatives, F(k) of :func:`hertz.hertz_relation`."""
        k = float(k)
        m = 1.0 - 1.0 / (k * k)
        ki, ei = float(ellipk(m)), float(ellipe(m))
        q = 1.0 - m
        k1 = (ei - q * ki) / (2.0 * m * q)
        e1 = (ei - ki) / (2.0 * m)
        # (E − qK)' = E' + K − qK';  (2mq)' = 2(1 − 2m)
        k2 = ((e1 + ki - q * k1) * 2.0 * m * q - (ei - q * ki) * 2.0 * (1.0 - 2.0 * m)) / (
            (2.0 * m * q) ** 2
        )
        e2 = (e1 - k1) / (2.0 * m) - (ei - ki) / (2.0 * m * m)
        # F = N/D, N = (k² + 1)E − 2K, D = (k² − 1)E, as functions of k through m = 1 − 1/k²
        mk, mkk = 2.0 / (k * k * k), -6.0 / (k * k * k * k)
        ek, ekk = e1 * mk, e2 * mk * mk + e1 * mkk
        kk_, kkk = k1 * mk, k2 * mk * mk + k1 * mkk
        kq = k * k
        n = (kq + 1.0) * ei - 2.0 * ki
        d = (kq - 1.0) * ei
        nk = 2.0 * k * ei + (kq + 1.0) * ek - 2.0 * kk_
        dk = 2.0 * k * ei + (kq - 1.0) * ek
        nkk = 2.0 * ei + 4.0 * k * ek + (kq + 1.0) * ekk - 2.0 * kkk
        dkk = 2.0 * ei + 4.0 * k * ek + (kq - 1.0) * ekk
        f1 = (nk * d - n * dk) / (d * d)
        self.k, self.m, self.k_int, self.e_int = k, m, ki, ei
        self.f = n / d
        self.f1 = f1
        self.f2 = (nkk * d - n * dkk) / (d * d) - 2.0 * dk * f1 / d
        self.inv_f1, self.f2_f1 = 1.0 / f1, self.f2 / f1
        self.k1, self.k2, self.e1, self.e2 = k1, k2, e1, e2
        self.data = (k, m, ki, ei, self.f, self.inv_f1, self.f2_f1, k1, k2, e1, e2)


def contact_terms(c: PairConstants, gamma: float, inv_f: float, inner: bool, anc: Anchor):
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

    >>> from servofmu.physics import equilibrium
    >>> from servofmu.physics.pair import BearingPair
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
    if inner:
        u = 1.0 / (1.0 - gamma)
        rt, r1, r2 = 2.0 * gamma * u, 2.0 * u * u, 4.0 * u * u * u  # race term, d/dγ, d²/dγ²
    else:
        u = 1.0 / (1.0 + gamma)
        rt, r1, r2 = -2.0 * gamma * u, -2.0 * u * u, 4.0 * u * u * u
    den = 4.0 - inv_f + rt  # Σρ·Dw
    g4 = (4.0 - 2.0 * inv_f) / (den * den)
    f_g = g4 * r1  # dF/dγ
    f_gg = g4 * (r2 - 2.0 * r1 * r1 / den)
    f_f = (4.0 + 2.0 * rt) / (den * den)  # ∂F/∂(1/f)
    k0, m0, ki0, ei0, f0, inv_f1, f2_f1, k1, k2, e1, e2 = anc.data
    q = ((inv_f + rt) / den - f0) * inv_f1  # Δk to first order
    k = k0 + q * (1.0 - 0.5 * f2_f1 * q)  # Δk = ΔF/F' − F''·ΔF²/(2F'³)
    k_f = (1.0 - f2_f1 * q) * inv_f1  # dk/dF
    k_ff = -f2_f1 * inv_f1 * inv_f1
    kg, kgg, kf = k_f * f_g, k_ff * f_g * f_g + k_f * f_gg, k_f * f_f
    ik = 1.0 / k
    m_k = 2.0 * ik * ik * ik  # m = 1 − 1/k²
    mg, mgg, mf = m_k * kg, m_k * (kgg - 3.0 * ik * kg * kg), m_k * kf
    dm = (1.0 - ik * ik) - m0
    ki = ki0 + (k1 + 0.5 * k2 * dm) * dm
    ei = ei0 + (e1 + 0.5 * e2 * dm) * dm
    km, em = k1 + k2 * dm, e1 + e2 * dm  # dK/dm, dE/dm
    lk_g, lk_gg, lk_f = km * mg / ki, (k2 * mg * mg + km * mgg) / ki, km * mf / ki
    le_g, le_gg, le_f = em * mg / ei, (e2 * mg * mg + em * mgg) / ei, em * mf / ei
    # ln X = (ln Σρ·Dw − 2 ln k − ln E)/3, X·Dw^(−1/3) = (Σρ/(k²·E))^(1/3)
    lx_g = (r1 / den - 2.0 * kg * ik - le_g) * _THIRD
    lx_gg = (
        r2 / den - (r1 / den) ** 2 - 2.0 * (kgg * ik - (kg * ik) ** 2) - (le_gg - le_g * le_g)
    ) * _THIRD
    lx_f = (-1.0 / den - 2.0 * kf * ik - le_f) * _THIRD
    x = _cbrt(den / (k * k * ei))
    cd = c.c_delta_coef * ki * x  # c_δ = C·K·X
    lc_g = lk_g + lx_g
    ac = c.a_coef / x  # a_coef = C_a/X
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
        Thermal state of the step (:func:`thermal_floats`).
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

    >>> from servofmu.physics import equilibrium, fits
    >>> from servofmu.physics.pair import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> c = PairConstants(pair)
    >>> th = thermal_floats(c, (c.t0,) * 4)
    >>> race = fits.mounted_geometry(pair.bearing, pair.mounting.fit, c.t0, c.t0).race
    >>> outer = equilibrium.contact_constants_at(race, math.radians(15))[1]
    >>> round(exact_contact_k(th, math.cos(math.radians(15)), False), 9)
    5.097093463
    >>> round(float(outer.ellipticity), 9)
    5.097093463
    """
    g = th.gamma_scale * cos_a
    inv_f = th.inv_f_inner if inner else th.inv_f_outer
    rt = 2.0 * g / (1.0 - g) if inner else -2.0 * g / (1.0 + g)
    return float(ellipticity((inv_f + rt) / (4.0 - inv_f + rt)))


class Ball:
    """One ball position of a bearing: azimuth cosine cos ψ and weight (Z for the one ball of
    pure axial load; 1 or 2 over half the ring under a radial load), the anchors of its inner
    and outer contacts, its base (:func:`ball_base`) or None, and the state at the last
    evaluation: load Q [N], cos α, sin α."""

    __slots__ = ("anc_i", "anc_o", "base", "cos_a", "cos_psi", "load", "sin_a", "weight")

    def __init__(self, cos_psi: float, weight: float, anc_i: Anchor, anc_o: Anchor):
        self.cos_psi, self.weight, self.anc_i, self.anc_o = cos_psi, weight, anc_i, anc_o
        self.base = None
        self.load = self.cos_a = self.sin_a = 0.0


def ball_base(c: PairConstants, gamma: float, inv_f_i: float, inv_f_o: float, b: Ball) -> tuple:
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
    >>> from servofmu.physics.pair import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_floats(c, (c.t0,) * 4)
    >>> cos_a = math.cos(math.radians(15))
    >>> k_i, k_o = exact_contact_k(th, cos_a, True), exact_contact_k(th, cos_a, False)
    >>> anchors = Anchor(k_i), Anchor(k_o)
    >>> ball = Ball(0.0, 15.0, *anchors)  # cos ψ, weight Z
    >>> base = ball_base(c, th.gamma_scale * cos_a, th.inv_f_inner, th.inv_f_outer, ball)
    >>> len(base[3]), len(base[4]), round(base[1], 6)  # 1/f_i0 = 1/0.56
    (8, 24, 1.785714)
    """
    ti = contact_terms(c, gamma, inv_f_i, True, b.anc_i)
    to = contact_terms(c, gamma, inv_f_o, False, b.anc_o)
    return gamma, inv_f_i, inv_f_o, (*ti[:4], *to[:4]), (*ti[4:], *to[4:])


def ring_point(th: Thermal, c: PairConstants, a: float, dr: float, balls) -> tuple:
    """One bearing at axial offset ``a`` [m] and radial displacement ``dr`` [m] (Jones 1960;
    :func:`equilibrium.ball_loads` without tilt): each ball's load Q_j = K_n(α_j)·δ_j^1.5,
    stored on the :class:`Ball`, and the ring's loads and Jacobian.

    Parameters
    ----------
    th : Thermal
        Thermal state of the step (:func:`thermal_floats`).
    c : PairConstants
        The pair's data.
    a : float
        Axial offset [m] of the groove curvature centres from the centred position.
    dr : float
        Radial displacement δr [m] of the inner ring along ψ = 0.
    balls : sequence of Ball
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

    >>> from servofmu.physics import equilibrium, fits
    >>> from servofmu.physics.pair import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> c = PairConstants(pair)
    >>> th = thermal_floats(c, (c.t0,) * 4)
    >>> cos_a = th.radial_centre_distance / math.hypot(70e-6, th.radial_centre_distance)
    >>> k_i, k_o = exact_contact_k(th, cos_a, True), exact_contact_k(th, cos_a, False)
    >>> anchors = Anchor(k_i), Anchor(k_o)
    >>> r = ring_point(th, c, 70e-6, 0.0, [Ball(0.0, 15.0, *anchors)])
    >>> round(r[0], 4), round(r[1], 4), round(r[6] / 1e6, 4)  # N, N, N/µm
    (210.6691, 0.0, 19.4344)
    >>> race = fits.mounted_geometry(pair.bearing, pair.mounting.fit, c.t0, c.t0).race
    >>> s = equilibrium.axial_state(race, 70e-6)
    >>> round(float(s.axial_force), 4), round(float(s.axial_stiffness) / 1e6, 4)  # N, N/µm
    (210.6691, 19.4344)
    """
    a2_0, dist = th.radial_centre_distance, th.curvature_distance
    gs, f_i, f_o, dw_m13 = th.gamma_scale, th.inv_f_inner, th.inv_f_outer, 1.0 / th.dw_third
    gs_dw = gs * dw_m13  # d c_δ/d cos α = (d c_δ·Dw^(1/3)/dγ)·(Dw/dm)·Dw^(−1/3)
    fa = fr = j11 = j12 = j21 = j22 = kax = 0.0
    d_min = dist
    for b in balls:
        cp = b.cos_psi
        a2 = a2_0 + dr * cp
        s = _hypot(a, a2)
        cos_a, sin_a = a2 / s, a / s
        b.cos_a, b.sin_a = cos_a, sin_a
        delta = s - dist
        if delta <= 0.0:
            b.load = 0.0
            continue
        if delta < d_min:
            d_min = delta
        base = b.base
        gamma = gs * cos_a
        if (
            base is None
            or abs(gamma - base[0]) > GAMMA_SPAN
            or abs(f_i - base[1]) > INV_F_SPAN
            or abs(f_o - base[2]) > INV_F_SPAN
        ):
            base = b.base = ball_base(c, gamma, f_i, f_o, b)
        g0, fi0, fo0, terms, _ = base
        d, d_i, d_o = gamma - g0, f_i - fi0, f_o - fo0
        ci0, ci1, ci2, cif, co0, co1, co2, cof = terms
        ci = (ci0 + d * (ci1 + ci2 * d) + cif * d_i) * dw_m13
        co = (co0 + d * (co1 + co2 * d) + cof * d_o) * dw_m13
        csum = ci + co
        k_n = 1.0 / (csum * _sqrt(csum))
        root = _sqrt(delta)
        knr = 1.5 * k_n * root
        q = k_n * delta * root
        b.load = q
        # the share of K_n(α) in dQ/dA1 (·cos α) and dQ/dA2 (·−sin α): dα = (cos α·dA1 −
        # sin α·dA2)/s, d ln c/dα = −sin α·d ln c/d cos α
        g = knr * (ci1 + co1) * gs_dw / csum * sin_a * delta / s
        dq1 = knr * sin_a + g * cos_a
        dq2 = knr * cos_a - g * sin_a
        qs = q / s
        sc = qs * sin_a * cos_a
        w = b.weight
        wc = w * cp
        fa += w * q * sin_a
        fr += wc * q * cos_a
        j11 += w * (dq1 * sin_a + qs * cos_a * cos_a)
        j12 += wc * (dq2 * sin_a - sc)
        j21 += wc * (dq1 * cos_a - sc)
        j22 += wc * cp * (dq2 * cos_a + qs * sin_a * sin_a)
        kax += w * (knr * sin_a * sin_a + qs * cos_a * cos_a)
    return fa, fr, j11, j12, j21, j22, kax, d_min


def newton_step(ra: tuple, rb: tuple, r1, r2, r3, r4, k_loop: float, radial: bool):
    """Newton correction (dp, dz, dδr_A, dδr_B) [m] of the pair equilibrium from the bearings'
    :func:`ring_point` results ``ra``, ``rb`` (their Jacobians dFa/da, dFa/dδr, dFr/da,
    dFr/dδr [N/m]) and the residuals r1 = F_A − F_B − F_ext, r2 = Fr_A − F_r/2,
    r3 = Fr_B − F_r/2 [N], r4 = 2p + (F_A + F_B)/(2k) − C [m]. The radial rows hold one bearing
    each: dδr_A = (−r2 − dFr_A/da·u)/(dFr_A/dδr) with u = dp + dz, v = dp − dz the changes of
    the offsets of A and B, which leaves

        e_A·u − e_B·v = g1,   (1 + e_A/2k)·u + (1 + e_B/2k)·v = g2,

    e = dFa/da − (dFa/dδr)(dFr/da)/(dFr/dδr) each bearing's axial stiffness at balanced radial
    load. A rigid loop (k = inf) fixes p. None when singular.

    Parameters
    ----------
    ra, rb : tuple
        :func:`ring_point` results of bearings A and B (only the Jacobian entries are read).
    r1, r2, r3 : float
        Force residuals [N].
    r4 : float
        Loop residual [m].
    k_loop : float
        Loop stiffness k [N/m] (inf: rigid).
    radial : bool
        Whether the radial rows are solved (a radial load); else dδr_A = dδr_B = 0.

    Returns
    -------
    tuple or None
        (dp, dz, dδr_A, dδr_B) [m], or None when the system is singular.

    Examples
    --------
    A rigid loop under axial load only: dz = −r1/(e_A + e_B), by hand 3 N / (3 N/µm) = 1 µm:

    >>> ra = (0.0, 0.0, 2e6, 0.0, 0.0, 0.0, 2e6, 1e-6)  # dFa/da = 2 N/µm
    >>> rb = (0.0, 0.0, 1e6, 0.0, 0.0, 0.0, 1e6, 1e-6)  # 1 N/µm
    >>> dp, dz, da, db = newton_step(ra, rb, -3.0, 0.0, 0.0, 0.0, math.inf, False)
    >>> dp, round(dz * 1e6, 9), da, db  # µm for dz
    (0.0, 1.0, 0.0, 0.0)
    >>> zero = (0.0,) * 8  # no ball in contact: no stiffness
    >>> newton_step(zero, zero, -3.0, 0.0, 0.0, 0.0, math.inf, False) is None
    True
    """
    _, _, a11, a12, a21, a22, _, _ = ra
    _, _, b11, b12, b21, b22, _, _ = rb
    if radial:
        if a22 == 0.0 or b22 == 0.0:
            return None
        ta, tb = a12 / a22, b12 / b22
        ea, eb = a11 - ta * a21, b11 - tb * b21
        g1 = -r1 + ta * r2 - tb * r3
    else:
        ea, eb = a11, b11
        g1 = -r1
    if k_loop == _INF:
        det = ea + eb
        if not det > 0.0:
            return None
        dz = g1 / det
        dp, u, v = 0.0, dz, -dz
    else:
        g2 = -r4 + 0.5 * (ta * r2 + tb * r3) / k_loop if radial else -r4
        ha, hb = 1.0 + 0.5 * ea / k_loop, 1.0 + 0.5 * eb / k_loop
        det = ea * hb + eb * ha
        if det == 0.0:
            return None
        u = (g1 * hb + eb * g2) / det
        v = (ea * g2 - ha * g1) / det
        dp, dz = 0.5 * (u + v), 0.5 * (u - v)
    if radial:
        return dp, dz, (-r2 - a21 * u) / a22, (-r3 - b21 * v) / b22
    return dp, dz, 0.0, 0.0


def tandem_step(ra: tuple, rb: tuple, r1, r2, r3, k_spring: float, radial: bool):
    """Newton correction (dp, 0, dδr_A, dδr_B) [m] of a tandem pair's equilibrium
    (:func:`preload.tandem_equilibrium`: both offsets move together, a_B = a_A + d) from the
    bearings' :func:`ring_point` results and the residuals r1 = F_A + F_B + k_s·a_A − T −
    F_ext, r2 = Fr_A − F_r/2, r3 = Fr_B − F_r/2 [N]: the radial rows eliminated as in
    :func:`newton_step`, u = (−r1 + t_A·r2 + t_B·r3)/(e_A + e_B + k_s). None when singular.

    Parameters
    ----------
    ra, rb : tuple
        :func:`ring_point` results of bearings A and B.
    r1, r2, r3 : float
        Residuals [N].
    k_spring : float
        The preload spring's stiffness k_s [N/m] (0: a constant force).
    radial : bool
        Whether the radial rows are solved.

    Returns
    -------
    tuple or None
        (dp, 0, dδr_A, dδr_B) [m], or None when singular.

    Examples
    --------
    Axial only: u = −r1/(e_A + e_B + k_s), by hand 3 N / (3 N/µm) = 1 µm:

    >>> ra = (0.0, 0.0, 2e6, 0.0, 0.0, 0.0, 2e6, 1e-6)  # dFa/da = 2 N/µm
    >>> rb = (0.0, 0.0, 1e6, 0.0, 0.0, 0.0, 1e6, 1e-6)
    >>> round(tandem_step(ra, rb, -3.0, 0.0, 0.0, 0.0, False)[0] * 1e6, 9)  # µm
    1.0
    """
    _, _, a11, a12, a21, a22, _, _ = ra
    _, _, b11, b12, b21, b22, _, _ = rb
    g = -r1
    if radial:
        if a22 == 0.0 or b22 == 0.0:
            return None
        ta, tb = a12 / a22, b12 / b22
        a11, b11 = a11 - ta * a21, b11 - tb * b21
        g += ta * r2 + tb * r3
    det = a11 + b11 + k_spring
    if not det > 0.0:
        return None
    u = g / det
    if radial:
        return u, 0.0, (-r2 - a21 * u) / a22, (-r3 - b21 * u) / b22
    return u, 0.0, 0.0, 0.0


def _parallel(d1, d0) -> float:
    """θ with d1 ≈ θ·d0 for the 4-vectors d1 and d0 when they are parallel (cosine above
    1 − 1e-6) and point the same way; else 0."""
    a0, a1, a2, a3 = d1
    b0, b1, b2, b3 = d0
    dot = a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3
    n0 = b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3
    if dot <= 0.0 or dot * dot < (1.0 - 1e-6) * n0 * (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3):
        return 0.0
    return dot / n0


class PairSolver:
    """Continuation solve of one :class:`~.pair.BearingPair` (see module docstring).

    :meth:`solve` takes the thermal state of a step (:func:`thermal_floats`) and the external
    loads, and returns the step's :class:`~.pair_state.PointState`, or None when the warm
    start fails; the caller then solves exactly and :meth:`seed` s the solver with that
    solution.
    """

    def __init__(self, pair):
        self.pair = pair
        self.c = PairConstants(pair)
        z = self.c.n_balls
        self.half_ring = tuple(
            (math.cos(2.0 * math.pi * j / z), 1.0 if j == 0 or 2 * j == z else 2.0)
            for j in range(z // 2 + 1)
        )
        self.reset()

    def reset(self) -> None:
        """Forget the last solution: the next step solves exactly."""
        self.mode = None  # "axial" (all balls alike) or "radial" (per ball)
        self.x = None  # (p, z, δr_A, δr_B) [m] of the last step
        self.rings = None  # the balls of bearings A and B
        self.inputs = None  # inputs of the last step: (4 temperatures [K], F_ext, F_r [N])
        self.jacobian = None  # the bearings' ring_point results at x (newton_step), or None
        self.secant = None  # (Δx, ΔT) of the last step's temperature change, or None

    def _layout(self, mode: str):
        """(cos ψ, weight) of the balls of one bearing in ``mode``."""
        return ((0.0, float(self.c.n_balls)),) if mode == "axial" else self.half_ring

    # ---------------------------------------------------------------- state
    def state(self) -> dict | None:
        """JSON-serialisable continuation state (floats), or None before the first solve."""
        if self.x is None:
            return None
        return {
            "mode": self.mode,
            "x": list(self.x),
            "k": [[[b.anc_i.k, b.anc_o.k] for b in ring] for ring in self.rings],
            "base": [
                [None if b.base is None else list(b.base[:3]) for b in ring] for ring in self.rings
            ],
            "inputs": list(self.inputs),
            "jacobian": None if self.jacobian is None else [list(r) for r in self.jacobian],
            "secant": None if self.secant is None else [list(v) for v in self.secant],
        }

    def restore(self, state: dict | None) -> None:
        """Inverse of :meth:`state` (the balls' bases are evaluated again from their γ and
        1/f): a restored solver continues bit for bit."""
        self.reset()
        if state is None:
            return
        self.mode = state["mode"]
        self.x = tuple(float(v) for v in state["x"])
        layout = self._layout(self.mode)
        self.rings = [
            [
                Ball(cp, w, Anchor(float(ki)), Anchor(float(ko)))
                for (cp, w), (ki, ko) in zip(layout, ks, strict=True)
            ]
            for ks in state["k"]
        ]
        for ring, bases in zip(self.rings, state["base"], strict=True):
            for b, at in zip(ring, bases, strict=True):
                if at is not None:
                    b.base = ball_base(self.c, *(float(v) for v in at), b)
        self.inputs = tuple(float(v) for v in state["inputs"])
        jac, sec = state.get("jacobian"), state.get("secant")
        self.jacobian = None if jac is None else tuple(tuple(float(v) for v in r) for r in jac)
        self.secant = None if sec is None else tuple(tuple(float(v) for v in p) for p in sec)

    def seed(self, th: Thermal, inputs, x, ball_cosines=None) -> None:
        """Start from an exactly solved state: ``x`` = (p, z) (axial) or (p, z, δr_A, δr_B)
        (radial) [m] at the thermal state ``th`` and ``inputs`` (temperatures, loads), the
        anchors at the exact ellipticities of the contacts (``ball_cosines``: the per-ball
        (cos α_A, cos α_B) arrays over half the ring under a radial load)."""
        self.reset()
        a2 = th.radial_centre_distance
        if len(x) == 2:
            self.mode = "axial"
            p, z = x
            cosines = [[a2 / _hypot(p + z, a2)], [a2 / _hypot(p - z, a2)]]
            x = (p, z, 0.0, 0.0)
        else:
            self.mode = "radial"
            cosines = [[float(v) for v in cs] for cs in ball_cosines]
        layout = self._layout(self.mode)
        self.rings = [
            [
                Ball(
                    cp,
                    w,
                    Anchor(exact_contact_k(th, cos_a, True)),
                    Anchor(exact_contact_k(th, cos_a, False)),
                )
                for (cp, w), cos_a in zip(layout, cs, strict=True)
            ]
            for cs in cosines
        ]
        self.x, self.inputs = tuple(float(v) for v in x), tuple(inputs)

    def _switch(self, mode: str) -> None:
        """Carry the anchors over between the axial and the radial form (the radial balls
        start from the axial ball's anchors; the axial ball from the ball at ψ = 0)."""
        layout = self._layout(mode)
        self.rings = [
            [Ball(cp, w, ring[0].anc_i.copy(), ring[0].anc_o.copy()) for cp, w in layout]
            for ring in self.rings
        ]
        if mode == "axial":
            self.x = (*self.x[:2], 0.0, 0.0)
        self.mode, self.jacobian, self.secant = mode, None, None

    # ---------------------------------------------------------------- solve
    def start(self, th: Thermal, axial_load: float, radial_load: float) -> PointState | None:
        """A first solution without the exact path: the pair at zero external load (Newton's
        method on the symmetric offset p of 2p + F(p)/k = C from p = C/2, F one bearing's
        axial force: it converges monotonically, F being odd and convex beyond first
        contact), then the external loads added in stages, each solved by :meth:`solve` (its
        predictor and Newton's method) and halved when that fails. The step's
        :class:`~.pair_state.PointState`, or None (the solver reset: the caller solves
        exactly)."""
        half = 0.5 * th.closure  # a tandem pair: a_A = 0, a_B = d
        self.seed(th, (*th.temperatures, 0.0, 0.0), (half, -half if self.c.tandem else 0.0))
        point = self.solve(th, 0.0, 0.0, START_ITERATIONS)
        done, stage = 0.0, 1.0
        while point is not None and done < 1.0:
            share = min(1.0, done + stage)
            nxt = self.solve(th, share * axial_load, share * radial_load, START_ITERATIONS)
            if nxt is None:
                stage *= 0.5
                if stage < START_SMALLEST_STAGE:
                    point = None
                continue
            point, done, stage = nxt, share, 2.0 * stage
        if point is None:
            self.reset()
        return point

    def solve(
        self,
        th: Thermal,
        axial_load: float,
        radial_load: float,
        iterations: int = MAX_ITERATIONS,
    ) -> PointState | None:
        """The pair at the thermal state ``th`` under ``axial_load`` (pressing A) and
        ``radial_load`` [N] from the last solution, in at most ``iterations`` Newton
        iterations per anchor round: the step's :class:`~.pair_state.PointState`, or None."""
        if self.x is None:
            return None
        mode = "axial" if radial_load == 0.0 else "radial"
        if mode != self.mode:
            self._switch(mode)
        inputs = (*th.temperatures, axial_load, radial_load)
        x = self._predict(inputs)
        for _ in range(MAX_ANCHOR_ROUNDS):
            sol = self._newton(th, axial_load, radial_load, x, iterations)
            if sol is None and x is not self.x:  # the predictor overshot: from the last step
                x = self.x
                sol = self._newton(th, axial_load, radial_load, x, iterations)
            if sol is None:
                return None
            x, ka, kb, jac = sol
            symmetric = axial_load == 0.0 and mode == "axial" and not self.c.tandem
            point, redo = self._point(th, x, ka, kb, symmetric, radial_load)
            if not redo:
                self._advance(x, inputs, jac)
                return point
        return None

    def _load_step(self, jac, inputs_new, inputs_old):
        """First-order change of x [m] from the loads of ``inputs_old`` to those of
        ``inputs_new`` (the Newton step of the load change alone), or None."""
        d_ext, d_r = inputs_new[4] - inputs_old[4], inputs_new[5] - inputs_old[5]
        if d_ext == 0.0 and d_r == 0.0:
            return (0.0, 0.0, 0.0, 0.0)
        half = -0.5 * d_r
        if self.c.tandem:
            return tandem_step(*jac, -d_ext, half, half, self.c.spring_stiffness,
                               self.mode == "radial")  # fmt: skip
        return newton_step(
            *jac, -d_ext, half, half, 0.0, self.c.loop_stiffness, self.mode == "radial"
        )

    def _predict(self, inputs):
        """Start of a step at ``inputs``: the last solution moved by the tangent of the load
        change (the last Jacobian) and by the secant of the temperature change (the last step's
        change of x less its load part, when the temperatures move on in the same direction)."""
        x, u = self.x, self.inputs
        p, z, da, db = x
        moved = False
        if self.jacobian is not None and (inputs[4] != u[4] or inputs[5] != u[5]):
            dx = self._load_step(self.jacobian, inputs, u)
            if dx is not None:
                p, z, da, db = p + dx[0], z + dx[1], da + dx[2], db + dx[3]
                moved = True
        if self.secant is not None and inputs[:4] != u[:4]:
            d_t = (inputs[0] - u[0], inputs[1] - u[1], inputs[2] - u[2], inputs[3] - u[3])
            theta = _parallel(d_t, self.secant[1])
            if theta:
                s0, s1, s2, s3 = self.secant[0]
                p, z, da, db = p + theta * s0, z + theta * s1, da + theta * s2, db + theta * s3
                moved = True
        return (p, z, da, db) if moved else x

    def _advance(self, x, inputs, jac) -> None:
        """Make ``x`` at ``inputs`` (Jacobian ``jac``) the last solution, and keep the secant of
        the temperature change from the solution before."""
        u = self.inputs
        self.secant = None
        if inputs[:4] != u[:4]:
            dx = self._load_step(jac, inputs, u)
            if dx is not None:
                x0 = self.x
                self.secant = (
                    (
                        x[0] - x0[0] - dx[0],
                        x[1] - x0[1] - dx[1],
                        x[2] - x0[2] - dx[2],
                        x[3] - x0[3] - dx[3],
                    ),
                    (inputs[0] - u[0], inputs[1] - u[1], inputs[2] - u[2], inputs[3] - u[3]),
                )
        self.x, self.inputs, self.jacobian = x, inputs, jac

    def _newton(self, th: Thermal, f_ext: float, f_r: float, x0, iterations=MAX_ITERATIONS):
        """Newton's method from ``x0`` = (p, z, δr_A, δr_B) [m] in at most ``iterations``
        iterations: the solution, the bearings' output stiffnesses [N/m] and their Jacobians
        there (the balls hold its loads), or None (see :func:`newton_step`).
        Without external load z = 0 and B mirrors A (the exact path's symmetric solution)."""
        c = self.c
        if c.tandem:
            return self._newton_tandem(th, f_ext, f_r, x0, iterations)
        k_loop, closure = c.loop_stiffness, th.closure
        rigid = k_loop == _INF
        tol = _TOLERANCE * th.curvature_distance
        floor = _ROUNDING * th.curvature_distance
        p, z, da, db = x0
        radial = f_r != 0.0
        if rigid:
            p = 0.5 * closure
        symmetric = f_ext == 0.0 and not radial
        if symmetric:
            z = 0.0
        ring_a, ring_b = self.rings
        half = 0.5 * f_r
        for _ in range(iterations):
            ra = ring_point(th, c, p + z, da, ring_a)
            rb = ra if symmetric else ring_point(th, c, p - z, db, ring_b)
            r4 = 0.0 if rigid else 2.0 * p + 0.5 * (ra[0] + rb[0]) / k_loop - closure
            if symmetric:
                dp = 0.0 if rigid else -r4 / (2.0 + ra[2] / k_loop)
                dz = dda = ddb = 0.0
            elif not radial and ra[2] == 0.0 and rb[2] == 0.0:
                # no ball of either bearing touches (axial play): move the shaft along the
                # load until its first contact carries about the load, and go on
                z = self._engage(th, p, f_ext)
                if z is None:
                    return None
                continue
            elif radial and (ra[5] == 0.0 or rb[5] == 0.0):
                # a bearing with no ball in contact has no radial stiffness: move it radially
                # until its ball nearest the load's direction carries about F_r/2, and go on
                da = self._touch(th, p + z, half, ring_a) if ra[5] == 0.0 else da
                db = self._touch(th, p - z, half, ring_b) if rb[5] == 0.0 else db
                if da is None or db is None:
                    return None
                continue
            else:
                r1 = ra[0] - rb[0] - f_ext
                dx = newton_step(ra, rb, r1, ra[1] - half, rb[1] - half, r4, k_loop, radial)
                if dx is None:
                    return None
                dp, dz, dda, ddb = dx
            step = max(abs(dp), abs(dz), abs(dda), abs(ddb))
            if step <= tol and (step <= _DEFLECTION_TOLERANCE * min(ra[7], rb[7]) or step <= floor):
                return (p, z, da, db), ra[6], rb[6], (ra, rb)
            if not step < _INF:
                return None
            p, z, da, db = p + dp, z + dz, da + dda, db + ddb
        return None

    def _newton_tandem(self, th: Thermal, f_ext: float, f_r: float, x0, iterations):
        """:meth:`_newton` of a tandem pair: a_A = p + z, a_B = p − z with z = −d/2 held
        (the mismatch d of the thermal state), Newton's method on p (and the radial
        displacements) by :func:`tandem_step`."""
        c = self.c
        tol = _TOLERANCE * th.curvature_distance
        floor = _ROUNDING * th.curvature_distance
        p, _, da, db = x0
        z = -0.5 * th.closure
        radial = f_r != 0.0
        ring_a, ring_b = self.rings
        half = 0.5 * f_r
        ks, target = c.spring_stiffness, c.thrust + f_ext
        for _ in range(iterations):
            ra = ring_point(th, c, p + z, da, ring_a)
            rb = ring_point(th, c, p - z, db, ring_b)
            if radial and (ra[5] == 0.0 or rb[5] == 0.0):
                da = self._touch(th, p + z, half, ring_a) if ra[5] == 0.0 else da
                db = self._touch(th, p - z, half, ring_b) if rb[5] == 0.0 else db
                if da is None or db is None:
                    return None
                continue
            r1 = ra[0] + rb[0] + ks * (p + z) - target
            if not radial and ra[2] == 0.0 and rb[2] == 0.0 and ks == 0.0:
                p = self._engage_tandem(th, z, r1)
                if p is None:
                    return None
                continue
            dx = tandem_step(ra, rb, r1, ra[1] - half, rb[1] - half, ks, radial)
            if dx is None:
                return None
            dp, _, dda, ddb = dx
            step = max(abs(dp), abs(dda), abs(ddb))
            if step <= tol and (step <= _DEFLECTION_TOLERANCE * min(ra[7], rb[7]) or step <= floor):
                return (p, z, da, db), ra[6], rb[6], (ra, rb)
            if not step < _INF:
                return None
            p, da, db = p + dp, da + dda, db + ddb
        return None

    def _engage_tandem(self, th: Thermal, z: float, r1: float) -> float | None:
        """Mean offset p [m] at which a tandem pair (a_A = p + z, a_B = p − z) with no ball in
        contact and a constant force carries its residual thrust −``r1`` [N] on its first
        contact along that thrust (:meth:`_engage` for a tandem pair)."""
        h = th.first_contact_offset
        s = 1.0 if r1 < 0.0 else -1.0  # the set moves along the thrust it lacks
        # the offsets at which A and B first touch going that way: a_A = ±h, a_B = ±h
        p_touch = min(s * h - z, s * h + z) if s > 0.0 else max(s * h - z, s * h + z)
        trial = s * 1e-3 * th.curvature_distance
        ring_a, ring_b = self.rings
        got = abs(
            ring_point(th, self.c, p_touch + trial + z, 0.0, ring_a)[0]
            + ring_point(th, self.c, p_touch + trial - z, 0.0, ring_b)[0]
        )
        if not got > 0.0:
            return None
        return p_touch + trial * (abs(r1) / got) ** (2.0 / 3.0)

    def _engage(self, th: Thermal, p: float, f: float) -> float | None:
        """Shaft displacement z [m] at which the pair with mean offset ``p`` [m] and axial play
        carries about the axial load ``f`` [N] on its first contact: the balls of A meet
        their grooves at a_A = p + z = ±h, those of B at a_B = p − z = ±h (h the first-contact
        offset; the sign of the load picks the side), the nearer of them at
        |z| = h − |p|; beyond it the load rises as δ^1.5 (Hertz), so one trial deflection
        scales to the load's. None without play or load."""
        if f == 0.0:
            return None
        gap = th.first_contact_offset - abs(p)
        if not gap >= 0.0:
            return None
        s = 1.0 if f > 0.0 else -1.0
        trial = 1e-3 * th.curvature_distance
        z = s * (gap + trial)
        ring_a, ring_b = self.rings
        got = abs(
            ring_point(th, self.c, p + z, 0.0, ring_a)[0]
            - ring_point(th, self.c, p - z, 0.0, ring_b)[0]
        )
        if not got > 0.0:
            return None
        return s * (gap + trial * (abs(f) / got) ** (2.0 / 3.0))

    def _touch(self, th: Thermal, a: float, f: float, balls) -> float | None:
        """Radial displacement [m] of a bearing at axial offset ``a`` [m] at which its ball
        nearest the direction of the radial force ``f`` [N] carries |f| with the other balls
        free (Hertz: δ = (|f|/(K_n·cos α))^(2/3)): a start for Newton's method where no ball
        touches. None when no radial displacement brings that ball into contact."""
        dist, a2_0 = th.curvature_distance, th.radial_centre_distance
        b = max(balls, key=lambda ball: ball.cos_psi * f)
        cp = b.cos_psi
        if abs(a) >= dist or cp * f <= 0.0:
            return None
        a2 = _sqrt(dist * dist - a * a)
        cos_a = a2 / dist
        gamma = th.gamma_scale * cos_a
        ci = contact_terms(self.c, gamma, th.inv_f_inner, True, b.anc_i)[0] / th.dw_third
        co = contact_terms(self.c, gamma, th.inv_f_outer, False, b.anc_o)[0] / th.dw_third
        delta = (abs(f) * (ci + co) ** 1.5 / cos_a) ** (2.0 / 3.0)
        s = dist + delta
        return (_sqrt(s * s - a * a) - a2_0) / cp

    def _rest_displacement(self, th: Thermal, a_a: float) -> float:
        """A tandem pair's axial displacement [m]: a_A less its offset at zero external load
        at the thermal state ``th`` (:func:`pair_state._displacement`), that offset solved once
        per thermal state by :meth:`_newton_tandem` on one axial ball per bearing (their
        anchors A's and B's first ball's), from a_A."""
        if th.rest_offset is None:
            rings = self.rings
            self.rings = [
                [Ball(0.0, float(self.c.n_balls), r[0].anc_i.copy(), r[0].anc_o.copy())]
                for r in rings
            ]
            z = -0.5 * th.closure
            sol = self._newton_tandem(th, 0.0, 0.0, (a_a - z, z, 0.0, 0.0), START_ITERATIONS)
            self.rings = rings
            th.rest_offset = math.nan if sol is None else sol[0][0] + z
        return a_a - th.rest_offset

    def _point(self, th: Thermal, x, ka: float, kb: float, symmetric: bool, radial_load: float):
        """The step's :class:`~.pair_state.PointState` from the balls' last evaluation
        (:func:`ring_sums`): torques [N·m], forces [N], the pair's stiffness [N/m], the
        load-weighted contact angle of A [rad], the largest pressure [Pa], flags; and whether
        an anchor moved so far that the step must be solved again. B mirrors A when
        ``symmetric`` (its anchors follow A's). The friction model's data
        (:func:`~.pair_state.rolling_data`): the bearings' loads under ``skf2004``
        (``radial_load`` [N] the external one), the contacts' EHL terms under
        ``ehl_per_contact``."""
        c = self.c
        ring_a, ring_b = self.rings
        ehl = c.friction_model == "ehl_per_contact"
        eta = th.kinematic_viscosity * c.density if ehl else None
        sa = ring_sums(th, c, ring_a, eta)
        if symmetric:
            sb = sa
            for a, b in zip(ring_a, ring_b, strict=True):
                if b.anc_i.k != a.anc_i.k or b.anc_o.k != a.anc_o.k:
                    b.anc_i, b.anc_o, b.base = a.anc_i.copy(), a.anc_o.copy(), None
        else:
            sb = ring_sums(th, c, ring_b, eta)
        fa, fb = sa[8], sb[8]
        rolling = None
        if ehl:
            rolling = tuple(ta + tb for ta, tb in zip(sa[10], sb[10], strict=True))
        elif c.friction_model == "skf2004":
            rolling = skf_loads(fa, fb, radial_load)
        p_max = max(sa[5], sb[5])
        flags = state_flags(self.pair, th.clearance, p_max, fa, fb)
        a_a, a_b = x[0] + x[1], x[0] - x[1]
        if th.rest_torque is None:
            th.rest_torque = rest_torque(self.pair, th.kinematic_viscosity, th.pitch_diameter)
        point = PointState.of(
            self.pair,
            th,
            (sa[0] + sb[0], sa[1] + sb[1], sa[2] + sb[2], sa[3] + sb[3], sa[4] + sb[4]),
            (
                preload_force(fa, fb),
                sa[7] / sa[6] if sa[6] > 0.0 else th.free_contact_angle,
                ka + kb + c.spring_stiffness
                if c.tandem
                else _pair_stiffness(ka, kb, c.loop_stiffness),
                p_max,
                fa,
                fb,
                self._rest_displacement(th, a_a) if c.tandem else x[1],
                axial_play(th.first_contact_offset, a_a, a_b, fa, fb),
            ),
            (flags["overloaded"], flags["locked"], flags["unloaded"], flags["reverse_loaded"]),
            th.rest_torque,
            rolling,
        )
        return point, sa[9] or sb[9]


def ring_sums(th: Thermal, c: PairConstants, balls, eta: float | None = None) -> tuple:
    """Weighted sums over one bearing's balls at their last evaluation: (hysteresis, spin,
    sliding, inner ring, outer ring torques [N·m], largest pressure [Pa], Σ w·Q [N],
    Σ w·Q·α [N·rad], Fa [N], redo, EHL terms), with the Hertz constants from the balls' bases.
    With a dynamic viscosity ``eta`` [Pa·s] (``ehl_per_contact``), the EHL terms are those of
    :func:`.ehl_rolling.contact_rolling_terms` of every loaded contact (inner, then outer, ball
    by ball; the scale times the ball's weight) as five lists; else None.

    The torques are those of :func:`friction.ball_torque_terms` (Yu 2017 eq 1–3, 5–7; Ning)
    at the race radii (dm ∓ Dw·cos α)/2: each term is a product of powers of the load, the
    semi-axes and E(e), so its coefficient is the friction function at unit arguments
    (:func:`torque_coefficients`) and a ball costs a few products (a call of
    ball_torque_terms per ball cost 0.9 µs; tests/test_continuation.py checks the two agree).

    Every anchor whose contact's ellipticity moved more than :data:`ANCHOR_DRIFT` from it is
    renewed at the current k (for the next step; the ball's base is dropped); ``redo`` is True
    when one moved more than :data:`ANCHOR_REDO` (the step is then solved again).

    Parameters
    ----------
    th : Thermal
        Thermal state of the step (:func:`thermal_floats`).
    c : PairConstants
        The pair's data.
    balls : sequence of Ball
        The bearing's balls, after :func:`ring_point` (their loads and bases).
    eta : float or None
        Dynamic viscosity [Pa·s] for the EHL terms, or None.

    Returns
    -------
    tuple
        The 11 entries listed above: five torques [N·m], pressure [Pa], Σ w·Q [N],
        Σ w·Q·α [N·rad], Fa [N], redo (bool), EHL terms (five lists) or None.

    Examples
    --------
    After the :func:`ring_point` example: Fa is the same, and the inner and outer ring
    torques add up to hysteresis + spin + sliding (by construction):

    >>> from servofmu.physics.pair import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_floats(c, (c.t0,) * 4)
    >>> cos_a = th.radial_centre_distance / math.hypot(70e-6, th.radial_centre_distance)
    >>> k_i, k_o = exact_contact_k(th, cos_a, True), exact_contact_k(th, cos_a, False)
    >>> anchors = Anchor(k_i), Anchor(k_o)
    >>> balls = [Ball(0.0, 15.0, *anchors)]
    >>> fa = ring_point(th, c, 70e-6, 0.0, balls)[0]
    >>> s = ring_sums(th, c, balls)
    >>> s[8] == fa, round(s[0] * 1e3, 4), round(s[1] * 1e3, 4), s[2]  # N·mm
    (True, 0.795, 1.609, 0.0)
    >>> round((s[3] + s[4]) * 1e3, 4), round((s[0] + s[1] + s[2]) * 1e3, 4)  # N·mm
    (2.404, 2.404)
    """
    dw, dm = th.ball_diameter, th.pitch_diameter
    gs, f_i, f_o, dw_third = th.gamma_scale, th.inv_f_inner, th.inv_f_outer, th.dw_third
    if th.torque_coefficients is None:
        th.torque_coefficients = torque_coefficients(th, c)
    c_h, c_sl_i, c_sl_o, c_sp = th.torque_coefficients
    solid = c.solid
    hyst = spin = slide = inner = outer = p_max = qsum = qalpha = fa = 0.0
    redo = False
    ehl = None if eta is None else ([], [], [], [], [])
    for b in balls:
        q = b.load
        if q <= 0.0:
            continue
        w, cos_a, sin_a = b.weight, b.cos_a, b.sin_a
        g0, fi0, fo0, _, terms = b.base
        d, d_i, d_o = gs * cos_a - g0, f_i - fi0, f_o - fo0
        (ai0, ai1, ai2, aif, ki0, ki1, ki2, kif, ei0, ei1, ei2, eif) = terms[:12]
        (ao0, ao1, ao2, aof, ko0, ko1, ko2, kof, eo0, eo1, eo2, eof) = terms[12:]
        a_i = (ai0 + d * (ai1 + ai2 * d) + aif * d_i) * dw_third  # a_coef
        a_o = (ao0 + d * (ao1 + ao2 * d) + aof * d_o) * dw_third
        k_i = ki0 + d * (ki1 + ki2 * d) + kif * d_i
        k_o = ko0 + d * (ko1 + ko2 * d) + kof * d_o
        e_i = ei0 + d * (ei1 + ei2 * d) + eif * d_i
        e_o = eo0 + d * (eo1 + eo2 * d) + eof * d_o
        b_i, b_o = a_i / k_i, a_o / k_o  # b_coef
        q3 = q**_THIRD
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
        p = 1.5 * q3 / (_PI * min(a_i * b_i, a_o * b_o))
        if p > p_max:
            p_max = p
        qsum += w * q
        qalpha += w * q * _atan2(sin_a, cos_a)
        fa += w * q * sin_a
        if ehl is not None:
            g = gs * cos_a
            for a, k, e, inv_f, on_inner in (
                (a_i, k_i, e_i, f_i, True),
                (a_o, k_o, e_o, f_o, False),
            ):
                t = contact_rolling_terms(
                    q, a * q3, k, e, g, dw, dm, inv_f, c.compliance, eta, on_inner
                )
                ehl[0].append(w * t[0])
                for j in range(1, 5):
                    ehl[j].append(t[j])
        anc_i, anc_o = b.anc_i, b.anc_o
        drift_i, drift_o = abs(k_i - anc_i.k), abs(k_o - anc_o.k)
        if drift_i > ANCHOR_DRIFT * anc_i.k or drift_o > ANCHOR_DRIFT * anc_o.k:
            for anc, k, drift in ((anc_i, k_i, drift_i), (anc_o, k_o, drift_o)):
                if drift > ANCHOR_DRIFT * anc.k:
                    redo |= drift > ANCHOR_REDO * anc.k
                    anc.set(k)
            b.base = None
    return hyst, spin, slide, inner, outer, p_max, qsum, qalpha, fa, redo, ehl


def torque_coefficients(th: Thermal, c: PairConstants) -> tuple:
    """Coefficients of one ball's torque terms at the thermal state ``th``: (hysteresis
    3·α_r/(8·Dw) [1/m] per Q·b·r, Heathcote sliding of the inner and outer race [1/m²] per
    Q·a²·r (0 without differential sliding), spin 3μ/8 [-] per Q·a·E(e)): the functions of
    :mod:`.friction` at unit load, semi-axes and E(e).

    Parameters
    ----------
    th : Thermal
        Thermal state of the step (Dw [m], groove radii [m]).
    c : PairConstants
        The pair's data (friction coefficients, sliding switch).

    Returns
    -------
    tuple
        (hysteresis [1/m], inner sliding [1/m²], outer sliding [1/m²], spin [-]).

    Examples
    --------
    Yu's pair (α_r = 0.007, μ = 0.0817, no differential sliding): by hand
    3 · 0.007 / (8 · 2.381 mm) = 1.1025 /m and 3 · 0.0817 / 8 = 0.0307:

    >>> from servofmu.physics.pair import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> h, sl_i, sl_o, sp = torque_coefficients(thermal_floats(c, (c.t0,) * 4), c)
    >>> round(h, 4), sl_i, sl_o, round(sp, 4)  # 1/m, 1/m², 1/m², -
    (1.1025, 0.0, 0.0, 0.0307)
    """
    dw, mu = th.ball_diameter, c.coefficients.sliding_friction
    c_h = _hysteresis(1.0, 1.0, dw, c.coefficients.hysteresis_loss)
    if c.sliding:
        c_sl_i = _heathcote(1.0, 1.0, dw, th.inner_groove_radius, mu)
        c_sl_o = _heathcote(1.0, 1.0, dw, th.outer_groove_radius, mu)
    else:
        c_sl_i = c_sl_o = 0.0
    return c_h, c_sl_i, c_sl_o, _spin(1.0, 1.0, 1.0, mu)


def _pair_stiffness(ka: float, kb: float, k: float) -> float:
    """:func:`preload.pair_axial_stiffness` on floats [N/m]."""
    return ka + kb if k == _INF else ka + kb - (ka - kb) ** 2 / (4.0 * k + ka + kb)

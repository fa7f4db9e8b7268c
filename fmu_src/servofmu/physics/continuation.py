"""Per-step continuation solve of a bearing pair's thermal and load state, on Python floats.

The exact path (:func:`bearing.thermal_state`, :func:`bearing.load_state`) solves every
operating point from scratch with bracketing root finders over numpy arrays: robust, and the
reference, but about a millisecond per point. Inside an FMU the temperature and the loads
change a little from one communication step to the next, so this module solves the same
equations from the previous step's solution:

- the thermal state (ring growth, Lamé fits, clearance, loop closure, viscosity) is closed
  form: the equations of :func:`fits.mounted_geometry`, :func:`preload.loop_interference` and
  :func:`viscosity.walther_kinematic_viscosity`, written out on floats (:func:`thermal_floats`);
- under pure axial load every ball of a bearing is alike (Yu 2017 eq 4): the pair's offsets
  (p, z) solve the two conditions of :func:`preload.pair_offsets` by Newton's method with the
  analytic Jacobian, the contact angle's effect on the Hertz constants included, started from
  the previous solution (one unknown when the load is zero, none for a rigid loop at zero load);
- under a radial load every ball differs (Jones 1960): the pair's (p, z, δr_A, δr_B) solve the
  conditions of :func:`preload.pair_equilibrium` by Newton's method over the balls of half the
  ring (the load is symmetric about the radial load's direction), one ball at a time on
  floats (faster than numpy over a dozen balls);
- the Hertz constants of each contact need the ellipticity k, the root of the Hertz relation
  F(k) = F(ρ) (:func:`hertz.ellipticity`). Each contact keeps an *anchor*: k0 with the exact
  K(m0), E(m0), F(k0) and dF/dk at k0 (scipy.special). Within a step k, K and E are taken to
  first order from the anchor (one Newton step of the inverse), whose error is below
  C·(Δk/k)² with C ≈ 2 (measured on the catalogue bearings); the anchor is renewed at the
  current k when |Δk| exceeds :data:`ANCHOR_DRIFT`·k, which keeps every Hertz constant within
  about 1e-12 of the exact one.

Newton stops at the first point whose next correction is below 1e-12 of the curvature distance
A (about 1e-16 m, the absolute tolerance of the exact path's root finders): with the analytic
Jacobian and a secant predictor that is two evaluations per step on a temperature ramp. A step that
does not converge in :data:`MAX_ITERATIONS`, a singular Jacobian (no ball in contact while the
external load is not zero), or a non-finite value returns None, and the caller falls back to
the exact path. The outputs equal the exact path's to a relative 1e-9 (tests check this on
random trajectories of temperature and load).

The continuation state (:meth:`PairSolver.state`) is a JSON-serialisable dict of floats: a
restored solver continues bit for bit.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import ellipe, ellipk

from .friction import BallSetTorques, ball_torque_terms
from .hertz import ellipticity
from .materials import reduced_compliance
from .pair import assembly_geometry, effective_shim, loop_stiffness
from .pair_state import LoadState, state_flags
from .preload import ROLES

#: Largest relative change of a contact's ellipticity from its anchor before the anchor is
#: renewed (the second-order expansion's error is below 2e-12 there: measured 1.8e-12 for
#: k, K and E at F = 0.85…0.97, tests/test_continuation.py).
ANCHOR_DRIFT = 1e-4
#: Newton iterations of one step before the exact path takes over.
MAX_ITERATIONS = 12
#: Newton stops at the first point whose next correction is below this fraction of the
#: curvature distance A (≈ 1e-16 m for the catalogue bearings, the exact path's tolerance).
_TOLERANCE = 1e-12
#: Rounds of anchor renewal within one step before the exact path takes over.
MAX_ANCHOR_ROUNDS = 6

_sqrt, _cbrt, _atan2, _hypot = math.sqrt, math.cbrt, math.atan2, math.hypot
_THIRD = 1.0 / 3.0
_PI = math.pi
_2_PI = 2.0 / math.pi
_PI_2 = 0.5 * math.pi


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
        # loop closure C = 2·h(T0) + s − Σ σ·L·α·(T_part − T0)
        self.loop_terms = tuple(
            (ROLES[mm.role] * mm.length * mm.material.expansion, mm.part) for mm in loop.members
        )
        self.closure0 = 2.0 * float(assembly_geometry(pair).first_contact_offset) + float(
            effective_shim(pair)
        )
        self.loop_stiffness = float(loop_stiffness(pair))
        visc = pair.lubricant
        self.walther = None if visc is None else (visc.a, visc.b, visc.c)
        self.coefficients = pair.coefficients
        self.lubrication = pair.lubrication
        self.solid = pair.lubrication == "solid"
        self.sliding = bool(pair.sliding)
        self.pressure_limit = float(pair.pressure_limit)


class Thermal:
    """Thermal state of one step, as floats (the fields of :class:`~.bearing.ThermalState`
    that the outputs read, plus the race geometry of :class:`~.geometry.RaceGeometry`)."""

    __slots__ = (
        "ball_diameter",
        "clearance",
        "closure",
        "curvature_distance",
        "first_contact_offset",
        "free_contact_angle",
        "gamma_scale",
        "inner_curvature",
        "inner_fit_pressure",
        "inner_groove_radius",
        "inner_interference",
        "inner_race_diameter",
        "inv_f_inner",
        "inv_f_outer",
        "kinematic_viscosity",
        "loop_stiffness",
        "outer_curvature",
        "outer_fit_pressure",
        "outer_groove_radius",
        "outer_interference",
        "outer_race_diameter",
        "pitch_diameter",
        "radial_centre_distance",
        "temperatures",
    )


def thermal_floats(c: PairConstants, temps: tuple[float, float, float, float]) -> Thermal:
    """Thermal state at the parts' temperatures ``temps`` = (housing, shaft, outer ring, inner
    ring) [K]: the equations of :func:`fits.mounted_geometry` (Yu 2017 eq 10–13),
    :func:`preload.loop_interference` (eq 14–15) and Walther's viscosity (eq 18) on floats.

    Returns
    -------
    Thermal
        Lengths [m], pressures [Pa], viscosity [m²/s].
    """
    t_h, t_s, t_o, t_i = temps
    t0 = c.t0
    t_b = 0.5 * (t_o + t_i)
    grow_o = 1.0 + c.alpha_ring * (t_o - t0)
    grow_i = 1.0 + c.alpha_ring * (t_i - t0)
    grow_b = 1.0 + c.alpha_ball * (t_b - t0)
    grow_h = 1.0 + c.alpha_housing * (t_h - t0)
    grow_s = 1.0 + c.alpha_shaft * (t_s - t0)
    d_ring_o = c.outer_diameter * grow_o
    d_groove_o = c.outer_groove * grow_o
    d_ring_i = c.bore * grow_i
    d_groove_i = c.inner_groove * grow_i
    delta_o = d_ring_o - (c.outer_diameter - c.outer_interference) * grow_h
    delta_i = (c.bore + c.inner_interference) * grow_s - d_ring_i
    th = Thermal()
    if c.coupled:
        e_r, nu_r = c.e_ring, c.nu_ring
        d_h = c.housing_outer_diameter * grow_h
        d_sb = c.shaft_bore * grow_s
        k_in = d_ring_o / e_r * (_ratio(d_groove_o, d_ring_o) - nu_r)
        k_out = d_ring_o / c.e_housing * (_ratio(d_ring_o, d_h) + c.nu_housing)
        p_o = max(delta_o, 0.0) / (k_in + k_out)
        k_in = d_ring_i / c.e_shaft * (_ratio(d_sb, d_ring_i) - c.nu_shaft)
        k_out = d_ring_i / e_r * (_ratio(d_ring_i, d_groove_i) + nu_r)
        p_i = max(delta_i, 0.0) / (k_in + k_out)
        d_groove_o = d_groove_o + (
            -2.0 * p_o * d_ring_o**2 * d_groove_o / (e_r * (d_ring_o**2 - d_groove_o**2))
        )
        d_groove_i = d_groove_i + (
            2.0 * p_i * d_ring_i**2 * d_groove_i / (e_r * (d_groove_i**2 - d_ring_i**2))
        )
    else:
        p_o = p_i = 0.0
    dw = c.ball_diameter * grow_b
    r_i = c.inner_curvature * c.ball_diameter * grow_i
    r_o = c.outer_curvature * c.ball_diameter * grow_o
    pd = d_groove_o - d_groove_i - 2.0 * dw
    a = r_i + r_o - dw
    th.temperatures = temps
    th.ball_diameter = dw
    th.pitch_diameter = 0.5 * (d_groove_i + d_groove_o)
    th.inner_race_diameter, th.outer_race_diameter = d_groove_i, d_groove_o
    th.inner_groove_radius, th.outer_groove_radius = r_i, r_o
    th.inner_curvature, th.outer_curvature = r_i / dw, r_o / dw
    th.inv_f_inner, th.inv_f_outer = dw / r_i, dw / r_o
    th.gamma_scale = dw / th.pitch_diameter
    th.clearance = pd
    th.curvature_distance = a
    th.radial_centre_distance = a - 0.5 * pd
    pd_c = min(max(pd, 0.0), 2.0 * a)
    th.first_contact_offset = _sqrt(max(a * a - (a - 0.5 * pd_c) ** 2, 0.0))
    th.free_contact_angle = math.acos(min(max(1.0 - max(pd, 0.0) / (2.0 * a), -1.0), 1.0))
    growth = 0.0
    for coef, part in c.loop_terms:
        t_part = t_h if part == "housing" else t_s if part == "shaft" else t_b
        growth = growth + coef * (t_part - t0)
    th.closure = c.closure0 - growth
    th.loop_stiffness = c.loop_stiffness
    if c.walther is None:
        th.kinematic_viscosity = 0.0
    else:
        wa, wb, wc = c.walther
        th.kinematic_viscosity = (10.0 ** (10.0 ** (wa - wb * math.log10(t_b))) - wc) * 1e-6
    th.outer_fit_pressure, th.inner_fit_pressure = p_o, p_i
    th.outer_interference, th.inner_interference = delta_o, delta_i
    return th


class Anchor:
    """Exact Hertz data of one contact at its anchor ellipticity k0 (see module docstring):
    K, E and their first and second derivatives in m, F(k0) and its first and second
    derivatives in k."""

    __slots__ = ("e1", "e2", "e_int", "f", "f1", "f2", "k", "k1", "k2", "k_int", "m")

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
        m = 1.0 - 1.0 / (k * k)
        ki, ei = ellipk(m), ellipe(m)
        if type(k) is float:
            ki, ei = float(ki), float(ei)
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
        self.k1, self.k2, self.e1, self.e2 = k1, k2, e1, e2


class Contact:
    """Hertz constants of one ball–groove contact (floats or per-ball arrays): the interface
    of :class:`hertz.ContactConstants` that the friction equations use (``semi_axes``,
    ``e_integral``, ``max_pressure``), from a :func:`contact` tuple."""

    __slots__ = ("a_coef", "b_coef", "e_integral")

    def __init__(self, terms):
        _, _, a, k, e = terms
        self.a_coef, self.b_coef, self.e_integral = a, a / k, e

    def semi_axes(self, load):
        """(a, b) [m] under the normal load ``load`` [N] ≥ 0."""
        q3 = load**_THIRD
        return self.a_coef * q3, self.b_coef * q3

    def max_pressure(self, load):
        """Largest Hertz pressure 3Q/(2πab) [Pa] (0 without load)."""
        if isinstance(load, float) and load <= 0.0:
            return 0.0
        return 1.5 * load**_THIRD / (_PI * self.a_coef * self.b_coef)


def contact(th: Thermal, c: PairConstants, cos_a, sin_a, inner: bool, anc: Anchor):
    """Hertz constants of the inner or outer contact at the contact angle of cosine ``cos_a``
    and sine ``sin_a`` (floats, or per-ball arrays with array anchors):
    :func:`hertz.curvature_sum_difference` and :func:`hertz.contact_constants` rearranged,
    with the ellipticity to second order from the anchor ``anc``.

    Returns
    -------
    tuple
        (c_δ = K_c^(−2/3) [m/N^(2/3)] with K_c the contact's load–deflection constant,
        d ln c_δ/dα [1/rad], a_coef [m/N^(1/3)], ellipticity k [-], E(m) [-]);
        b_coef = a_coef/k.
    """
    g = th.gamma_scale * cos_a
    if inner:
        inv_f = th.inv_f_inner
        rt = 2.0 * g / (1.0 - g)
        drt_dg = 2.0 / ((1.0 - g) * (1.0 - g))
    else:
        inv_f = th.inv_f_outer
        rt = -2.0 * g / (1.0 + g)
        drt_dg = -2.0 / ((1.0 + g) * (1.0 + g))
    denom = 4.0 - inv_f + rt
    f1 = anc.f1
    q = ((inv_f + rt) / denom - anc.f) / f1  # Δk to first order
    f2q = anc.f2 * q / f1
    k = anc.k + q * (1.0 - 0.5 * f2q)  # Δk = ΔF/F' − F''·ΔF²/(2F'³)
    k2 = k * k
    dm_ = (1.0 - 1.0 / k2) - anc.m
    ki = anc.k_int + (anc.k1 + 0.5 * anc.k2 * dm_) * dm_
    ei = anc.e_int + (anc.e1 + 0.5 * anc.e2 * dm_) * dm_
    x = (denom / (th.ball_diameter * k2 * ei)) ** _THIRD
    # d ln c_δ/dα = d ln K + (d ln Σρ − 2·d ln k − d ln E)/3, dγ/dα = −(Dw/dm)·sin α
    drt_da = -drt_dg * th.gamma_scale * sin_a
    dk_da = (4.0 - 2.0 * inv_f) / (denom * denom) * drt_da * (1.0 - f2q) / f1
    dm_da = 2.0 * dk_da / (k2 * k)
    dln_c = (anc.k1 + anc.k2 * dm_) * dm_da / ki + (
        drt_da / denom - 2.0 * dk_da / k - (anc.e1 + anc.e2 * dm_) * dm_da / ei
    ) * _THIRD
    return c.c_delta_coef * ki * x, dln_c, c.a_coef / x, k, ei


def exact_contact_k(th: Thermal, cos_a: float, inner: bool) -> float:
    """The exact ellipticity [-] of the inner or outer contact at the angle with cosine
    ``cos_a`` (:func:`hertz.ellipticity` on the curvature difference): an anchor's start."""
    g = th.gamma_scale * cos_a
    inv_f = th.inv_f_inner if inner else th.inv_f_outer
    rt = 2.0 * g / (1.0 - g) if inner else -2.0 * g / (1.0 + g)
    return float(ellipticity((inv_f + rt) / (4.0 - inv_f + rt)))


class BearingPoint:
    """One bearing (all balls alike) at one axial offset: force, stiffness, contacts."""

    __slots__ = ("cos_a", "dforce", "force", "inner", "load", "outer", "sin_a", "stiffness")


def bearing_point(th: Thermal, c: PairConstants, a: float, anc_i: Anchor, anc_o: Anchor):
    """One bearing at axial offset ``a`` [m] under pure axial load (:func:`equilibrium.
    axial_state` on floats): ball load Q [N], Fa = Z·Q·sin α [N], dFa/da [N/m] with K_n held
    (the output ``axial_stiffness``) and with K_n(α) varied (the Newton Jacobian)."""
    a2 = th.radial_centre_distance
    s = _hypot(a, a2)
    cos_a, sin_a = a2 / s, a / s
    delta = s - th.curvature_distance
    ci = contact(th, c, cos_a, sin_a, True, anc_i)
    co = contact(th, c, cos_a, sin_a, False, anc_o)
    p = BearingPoint()
    p.cos_a, p.sin_a, p.inner, p.outer = cos_a, sin_a, ci, co
    if delta > 0.0:
        csum = ci[0] + co[0]
        k_n = csum**-1.5
        z = c.n_balls
        root = _sqrt(delta)
        q = k_n * delta * root
        p.load = q
        p.force = z * q * sin_a
        p.stiffness = z * (1.5 * k_n * root * sin_a * sin_a + q / s * cos_a * cos_a)
        dkn_da = -1.5 * k_n * (ci[0] * ci[1] + co[0] * co[1]) / csum
        p.dforce = p.stiffness + z * dkn_da * delta * root * sin_a * cos_a / s
    else:
        p.load = p.force = p.stiffness = p.dforce = 0.0
    return p


def _ball_torques(c: PairConstants, th: Thermal, q, cos_a, sin_a, ci: Contact, co: Contact):
    """(hysteresis, spin, sliding, inner ring, outer ring) torques of single balls [N·m]:
    :func:`friction.ball_torque_terms` at the race radii (dm ∓ Dw·cos α)/2 (floats)."""
    dw, dm = th.ball_diameter, th.pitch_diameter
    a_i, b_i = ci.semi_axes(q)
    a_o, b_o = co.semi_axes(q)
    h_i, h_o, sl_i, sl_o, sp_i, sp_o = ball_torque_terms(
        q,
        (a_i, b_i, ci.e_integral),
        (a_o, b_o, co.e_integral),
        0.5 * (dm - dw * cos_a),
        0.5 * (dm + dw * cos_a),
        abs(sin_a),
        dw,
        (th.inner_groove_radius, th.outer_groove_radius),
        c.coefficients,
        c.solid,
        c.sliding,
    )
    return h_i + h_o, sp_i + sp_o, sl_i + sl_o, h_i + sl_i + sp_i, h_o + sl_o + sp_o


class AxialSolution:
    """The pair under pure axial load at one step: both bearings' points and the offsets."""

    __slots__ = ("a", "b", "p", "z")


def solve_axial(th: Thermal, c: PairConstants, f_ext: float, x0, anchors) -> AxialSolution | None:
    """Offsets of the pair under the axial load ``f_ext`` [N] (pressing bearing A): the two
    conditions of :func:`preload.pair_offsets`, F_A − F_B = F_ext and
    a_A + a_B + (F_A + F_B)/(2k) = C, by Newton's method from ``x0`` = (p, z) [m] with the
    contact ``anchors`` (A inner, A outer, B inner, B outer). Without external load z = 0 (the
    exact path's symmetric solution) and one unknown is left; a rigid loop fixes p = C/2.
    None when Newton does not converge (the caller falls back to the exact path)."""
    k_loop, closure = c.loop_stiffness, th.closure
    rigid = k_loop == math.inf
    tol = _TOLERANCE * th.curvature_distance
    p, z = x0
    if rigid:
        p = 0.5 * closure
    symmetric = f_ext == 0.0
    if symmetric:
        z = 0.0
    aa, ao, ba, bo = anchors
    for _ in range(MAX_ITERATIONS):
        pa = bearing_point(th, c, p + z, aa, ao)
        if symmetric:
            pb = pa
            if rigid:
                dp = dz = 0.0
            else:
                dp, dz = -(2.0 * p + pa.force / k_loop - closure) / (2.0 + pa.dforce / k_loop), 0.0
        else:
            pb = bearing_point(th, c, p - z, ba, bo)
            r1 = pa.force - pb.force - f_ext
            j11, j12 = pa.dforce - pb.dforce, pa.dforce + pb.dforce
            if rigid:
                if j12 <= 0.0:
                    return None
                dp, dz = 0.0, -r1 / j12
            else:
                r2 = 2.0 * p + 0.5 * (pa.force + pb.force) / k_loop - closure
                j21, j22 = 2.0 + 0.5 * j12 / k_loop, 0.5 * j11 / k_loop
                det = j11 * j22 - j12 * j21
                if det == 0.0:
                    return None
                dp = -(r1 * j22 - r2 * j12) / det
                dz = -(j11 * r2 - j21 * r1) / det
        step = max(abs(dp), abs(dz))
        if step <= tol:
            sol = AxialSolution()
            sol.p, sol.z, sol.a, sol.b = p, z, pa, pb
            return sol
        if not step < math.inf:
            return None
        p, z = p + dp, z + dz
    return None


class RingPoint:
    """One bearing's balls over half the ring (ψ_j = 2πj/Z, j = 0…⌊Z/2⌋, weights w_j: the
    load is symmetric about the radial load's direction) at axial offset a and radial
    displacement δr: per-ball (Q, cos α, sin α, inner contact, outer contact), the ring loads
    and their Jacobian (the contact angle's effect on the Hertz constants included)."""

    __slots__ = ("axial_force", "axial_stiffness", "balls", "jacobian", "radial_force")


def ring_point(th: Thermal, c: PairConstants, a, dr, anc_i, anc_o, cos_psi, w) -> RingPoint:
    """One bearing at axial offset ``a`` [m] and radial displacement ``dr`` [m] (Jones 1960;
    :func:`equilibrium.ball_loads` without tilt): ball loads Q_j [N], Fa = Σ w·Q·sin α,
    Fr = Σ w·Q·cos α·cos ψ [N], d(Fa, Fr)/d(a, δr), and dFa/da with K_n held (the output).
    ``anc_i``, ``anc_o``: the balls' anchors; ``cos_psi``, ``w``: the balls' cos ψ_j and
    weights (lists of floats)."""
    a2_0, dist = th.radial_centre_distance, th.curvature_distance
    fa = fr = j11 = j12 = j21 = j22 = kax = 0.0
    balls = []
    for cp, wj, ai, ao in zip(cos_psi, w, anc_i, anc_o, strict=True):
        a2 = a2_0 + dr * cp
        s = _hypot(a, a2)
        cos_a, sin_a = a2 / s, a / s
        ci = contact(th, c, cos_a, sin_a, True, ai)
        co = contact(th, c, cos_a, sin_a, False, ao)
        delta = s - dist
        if delta > 0.0:
            csum = ci[0] + co[0]
            k_n = csum**-1.5
            root = _sqrt(delta)
            q = k_n * delta * root
            # the share of K_n(α) in dQ/dA1 (·cos α) and dQ/dA2 (·−sin α), dα = (cos α·dA1 −
            # sin α·dA2)/s
            dkn = -1.5 * k_n * (ci[0] * ci[1] + co[0] * co[1]) / csum * delta * root / s
            dq1 = 1.5 * k_n * root * sin_a + dkn * cos_a
            dq2 = 1.5 * k_n * root * cos_a - dkn * sin_a
            qs = q / s
            sc = qs * sin_a * cos_a
            wc = wj * cp
            fa += wj * q * sin_a
            fr += wc * q * cos_a
            j11 += wj * (dq1 * sin_a + qs * cos_a * cos_a)
            j12 += wc * (dq2 * sin_a - sc)
            j21 += wc * (dq1 * cos_a - sc)
            j22 += wc * cp * (dq2 * cos_a + qs * sin_a * sin_a)
            kax += wj * (1.5 * k_n * root * sin_a * sin_a + qs * cos_a * cos_a)
        else:
            q = 0.0
        balls.append((q, cos_a, sin_a, ci, co))
    r = RingPoint()
    r.balls, r.axial_force, r.radial_force = balls, fa, fr
    r.jacobian, r.axial_stiffness = (j11, j12, j21, j22), kax
    return r


class RadialSolution:
    """The pair under axial and radial load at one step."""

    __slots__ = ("a", "b", "x")


def solve_radial(th: Thermal, c: PairConstants, f_ext, f_r, x0, anchors, cos_psi, w):
    """Pair under axial load ``f_ext`` [N] (pressing A) and radial load ``f_r`` [N] shared
    equally: the conditions of :func:`preload.pair_equilibrium` (F_A − F_B = F_ext,
    Fr_A = Fr_B = F_r/2, (F_A + F_B)/2 = k·(C − 2p)) by Newton's method from ``x0`` =
    (p, z, δr_A, δr_B) [m]. None when Newton does not converge."""
    k_loop, closure = c.loop_stiffness, th.closure
    rigid = k_loop == math.inf
    tol = _TOLERANCE * th.curvature_distance
    x = np.array(x0, dtype=float)
    if rigid:
        x[0] = 0.5 * closure
    half = 0.5 * f_r
    for _ in range(MAX_ITERATIONS):
        p, z, da, db = x
        ra = ring_point(th, c, p + z, da, anchors[0], anchors[1], cos_psi, w)
        rb = ring_point(th, c, p - z, db, anchors[2], anchors[3], cos_psi, w)
        (a11, a12, a21, a22), (b11, b12, b21, b22) = ra.jacobian, rb.jacobian
        res = [
            ra.axial_force - rb.axial_force - f_ext,
            ra.radial_force - half,
            rb.radial_force - half,
        ]
        jac = [[a11 - b11, a11 + b11, a12, -b12], [a21, a21, a22, 0.0], [b21, -b21, 0.0, b22]]
        if rigid:
            jac = [row[1:] for row in jac]
        else:
            res.append(0.5 * (ra.axial_force + rb.axial_force) - k_loop * (closure - 2.0 * p))
            jac.append([0.5 * (a11 + b11) + 2.0 * k_loop, 0.5 * (a11 - b11), 0.5 * a12, 0.5 * b12])
        try:
            dx = -np.linalg.solve(np.array(jac), np.array(res))
        except np.linalg.LinAlgError:
            return None
        if rigid:
            dx = np.concatenate([[0.0], dx])
        step = float(np.max(np.abs(dx)))
        if step <= tol:
            sol = RadialSolution()
            sol.x, sol.a, sol.b = tuple(float(v) for v in x), ra, rb
            return sol
        if not step < math.inf:
            return None
        x = x + dx
    return None


def _secant(x1, x0, u2, u1, u0):
    """Secant predictor: x1 + θ·(x1 − x0), θ the projection of the input change u2 − u1 on the
    previous change u1 − u0 when the two are parallel (cosine above 1 − 1e-6); else x1."""
    d1 = [a - b for a, b in zip(u2, u1, strict=True)]
    d0 = [a - b for a, b in zip(u1, u0, strict=True)]
    dot = sum(a * b for a, b in zip(d1, d0, strict=True))
    n0 = sum(b * b for b in d0)
    if dot <= 0.0 or dot * dot < (1.0 - 1e-6) * n0 * sum(a * a for a in d1):
        return x1
    theta = dot / n0
    return tuple(a + theta * (a - b) for a, b in zip(x1, x0, strict=True))


class PairSolver:
    """Continuation solve of one :class:`~.pair.BearingPair` (see module docstring).

    :meth:`solve` takes the thermal state of a step (:func:`thermal_floats`) and the external
    loads, and returns the solution, or None when the warm start fails; the caller then solves
    exactly and :meth:`seed` s the solver with that solution.
    """

    def __init__(self, pair):
        self.pair = pair
        self.c = PairConstants(pair)
        z = self.c.n_balls
        self.cos_psi = [math.cos(2.0 * math.pi * j / z) for j in range(z // 2 + 1)]
        self.weights = [1.0 if j == 0 or 2 * j == z else 2.0 for j in range(z // 2 + 1)]
        self.reset()

    def reset(self) -> None:
        """Forget the last solution: the next step solves exactly."""
        self.mode = None  # "axial" (all balls alike) or "radial" (per ball)
        self.x = None  # (p, z) or (p, z, δr_A, δr_B) [m] of the last step
        self.anchors = None  # A inner, A outer, B inner, B outer
        self.previous = None  # (x, inputs) of the step before: the secant predictor
        self.inputs = None  # inputs of the last step

    # ---------------------------------------------------------------- state
    def state(self) -> dict | None:
        """JSON-serialisable continuation state (floats), or None before the first solve."""
        if self.x is None:
            return None

        def ks(a):
            return [b.k for b in a] if isinstance(a, list) else a.k

        prev = None if self.previous is None else [list(v) for v in self.previous]
        return {
            "mode": self.mode,
            "x": list(self.x),
            "k": [ks(a) for a in self.anchors],
            "inputs": list(self.inputs),
            "previous": prev,
        }

    def restore(self, state: dict | None) -> None:
        """Inverse of :meth:`state`: a restored solver continues bit for bit."""
        self.reset()
        if state is None:
            return
        self.mode = state["mode"]
        self.x = tuple(float(v) for v in state["x"])
        self.anchors = [
            [Anchor(float(v)) for v in k] if isinstance(k, list) else Anchor(float(k))
            for k in state["k"]
        ]
        self.inputs = tuple(float(v) for v in state["inputs"])
        prev = state["previous"]
        self.previous = None if prev is None else tuple(tuple(float(v) for v in p) for p in prev)

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
            cosines = [a2 / _hypot(p + z, a2), a2 / _hypot(p - z, a2)]
        else:
            self.mode = "radial"
            cosines = list(ball_cosines)
        anchors = []
        for cos_a in cosines:
            for inner in (True, False):
                if np.ndim(cos_a):
                    anchors.append([Anchor(exact_contact_k(th, float(v), inner)) for v in cos_a])
                else:
                    anchors.append(Anchor(exact_contact_k(th, float(cos_a), inner)))
        self.x, self.anchors, self.inputs = tuple(float(v) for v in x), anchors, tuple(inputs)

    def _switch(self, mode: str) -> None:
        """Carry the anchors and offsets over between the axial and the radial form."""
        n = len(self.cos_psi)
        if mode == "radial":
            self.anchors = [[a.copy() for _ in range(n)] for a in self.anchors]
            self.x = (*self.x, 0.0, 0.0)
        else:
            self.anchors = [a[0].copy() for a in self.anchors]
            self.x = self.x[:2]
        self.mode, self.previous = mode, None

    # ---------------------------------------------------------------- solve
    def evaluate(self, th: Thermal, axial_load: float, radial_load: float):
        """The solution object at the current offsets and anchors, without a Newton step: the
        last step's solution again, bit for bit (after :meth:`restore`)."""
        if self.mode == "axial":
            p, z = self.x
            sol = AxialSolution()
            sol.p, sol.z = p, z
            sol.a = bearing_point(th, self.c, p + z, self.anchors[0], self.anchors[1])
            sol.b = (
                sol.a
                if axial_load == 0.0
                else bearing_point(th, self.c, p - z, self.anchors[2], self.anchors[3])
            )
            return sol
        p, z, da, db = self.x
        sol = RadialSolution()
        sol.x = self.x
        args = (self.cos_psi, self.weights)
        sol.a = ring_point(th, self.c, p + z, da, *self.anchors[:2], *args)
        sol.b = ring_point(th, self.c, p - z, db, *self.anchors[2:], *args)
        return sol

    def solve(self, th: Thermal, axial_load: float, radial_load: float):
        """The pair at the thermal state ``th`` under ``axial_load`` and ``radial_load`` [N]:
        an :class:`AxialSolution` (no radial load) or a :class:`RadialSolution`, or None."""
        if self.x is None:
            return None
        mode = "axial" if radial_load == 0.0 else "radial"
        if mode != self.mode:
            self._switch(mode)
        inputs = (*th.temperatures, axial_load, radial_load)
        x = self.x
        if self.previous is not None:
            x = _secant(self.x, self.previous[0], inputs, self.inputs, self.previous[1])
        anchors = self.anchors
        for _ in range(MAX_ANCHOR_ROUNDS):
            if mode == "axial":
                sol = solve_axial(th, self.c, axial_load, x, anchors)
                if sol is None:
                    return None
                x = (sol.p, sol.z)
                drift = _drifted(anchors, (sol.a.inner, sol.a.outer, sol.b.inner, sol.b.outer))
                if drift and axial_load == 0.0:  # B mirrors A
                    anchors[2], anchors[3] = anchors[0].copy(), anchors[1].copy()
            else:
                sol = solve_radial(
                    th, self.c, axial_load, radial_load, x, anchors, self.cos_psi, self.weights
                )
                if sol is None:
                    return None
                x = sol.x
                drift = False
                for ring, (anc_i, anc_o) in ((sol.a, anchors[:2]), (sol.b, anchors[2:])):
                    cons = [b[3] for b in ring.balls] + [b[4] for b in ring.balls]
                    drift |= _drifted(anc_i + anc_o, cons)
            if not drift:
                self.previous = (self.x, self.inputs)
                self.x, self.inputs = x, inputs
                return sol
        return None


def _drifted(anchors, contacts) -> bool:
    """Renew every anchor whose contact's ellipticity moved more than :data:`ANCHOR_DRIFT`
    from it (at the contact's current k); True when one was renewed."""
    drift = False
    for anc, con in zip(anchors, contacts, strict=True):
        k = con[3]
        if abs(k - anc.k) > ANCHOR_DRIFT * anc.k:
            anc.set(k)
            drift = True
    return drift


def _pair_stiffness(ka: float, kb: float, k: float) -> float:
    """:func:`preload.pair_axial_stiffness` on floats [N/m]."""
    return ka + kb if k == math.inf else ka + kb - (ka - kb) ** 2 / (4.0 * k + ka + kb)


def axial_state_of(pair, c: PairConstants, th: Thermal, sol: AxialSolution) -> LoadState:
    """The :class:`~.pair_state.LoadState` (floats) of an axial solution: forces [N], torques
    [N·m] of Z balls per bearing, stiffness [N/m], contact angle [rad], pressure [Pa], flags."""
    z = c.n_balls
    sums = [0.0] * 5
    p_max = 0.0
    for pt in (sol.a, sol.b):
        if pt.load > 0.0:
            ci, co = Contact(pt.inner), Contact(pt.outer)
            t = _ball_torques(c, th, pt.load, pt.cos_a, pt.sin_a, ci, co)
            sums = [s + z * v for s, v in zip(sums, t, strict=True)]
            p_max = max(p_max, ci.max_pressure(pt.load), co.max_pressure(pt.load))
    fa, fb = sol.a.force, sol.b.force
    angle = _atan2(sol.a.sin_a, sol.a.cos_a) if sol.a.load > 0.0 else th.free_contact_angle
    return LoadState(
        force_a=fa,
        force_b=fb,
        preload=0.5 * (fa + fb),
        contact_angle=angle,
        axial_stiffness=_pair_stiffness(sol.a.stiffness, sol.b.stiffness, c.loop_stiffness),
        max_contact_pressure=p_max,
        **state_flags(pair, th.clearance, p_max, fa, fb),
        torques=BallSetTorques(*sums),
        axial_displacement=sol.z,
        offset_a=sol.p + sol.z,
        offset_b=sol.p - sol.z,
    )


def radial_state_of(pair, solver: PairSolver, th: Thermal, sol: RadialSolution) -> LoadState:
    """The :class:`~.pair_state.LoadState` (floats) of a radial solution: ball sums weighted
    over half the ring."""
    c, w = solver.c, solver.weights
    sums = [0.0] * 5
    p_max = 0.0
    for ring in (sol.a, sol.b):
        for wj, (q, cos_a, sin_a, ti, to) in zip(w, ring.balls, strict=True):
            if q > 0.0:
                ci, co = Contact(ti), Contact(to)
                t = _ball_torques(c, th, q, cos_a, sin_a, ci, co)
                sums = [s + wj * v for s, v in zip(sums, t, strict=True)]
                p_max = max(p_max, ci.max_pressure(q), co.max_pressure(q))
    fa, fb = sol.a.axial_force, sol.b.axial_force
    qsum = qalpha = 0.0
    for wj, (q, cos_a, sin_a, _, _) in zip(w, sol.a.balls, strict=True):
        qsum += wj * q
        qalpha += wj * q * _atan2(sin_a, cos_a)
    angle = qalpha / qsum if qsum > 0.0 else th.free_contact_angle
    p, z, da, db = sol.x
    return LoadState(
        force_a=fa,
        force_b=fb,
        preload=0.5 * (fa + fb),
        contact_angle=angle,
        axial_stiffness=_pair_stiffness(
            sol.a.axial_stiffness, sol.b.axial_stiffness, c.loop_stiffness
        ),
        max_contact_pressure=p_max,
        **state_flags(pair, th.clearance, p_max, fa, fb),
        torques=BallSetTorques(*sums),
        axial_displacement=z,
        offset_a=p + z,
        offset_b=p - z,
        radial_a=da,
        radial_b=db,
    )

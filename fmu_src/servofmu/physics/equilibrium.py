"""Quasi-static equilibrium of a ball bearing under axial load, radial load and moment.

Jones (1960) / Harris & Kotzalas (2007), *Advanced Concepts of Bearing Technology*, ch. 1
("distribution of internal loading"), without centrifugal and gyroscopic terms (servo
mechanisms run slowly). Ball j at azimuth ψ_j = 2πj/Z sees its inner-groove curvature centre
displaced from the outer one by

    A1_j = a + θ·R_i·cos ψ_j                       (axial; a = axial offset from the centred
                                                     position, see :mod:`geometry`)
    A2_j = (A − Pd/2) + δr·cos ψ_j                 (radial)

so that s_j = √(A1² + A2²), the contact deformation is δ_j = s_j − A (no load when ≤ 0), the
contact angle is α_j = atan2(A1_j, A2_j), and Q_j = K_n(α_j)·δ_j^1.5 with K_n the series
load–deflection constant of the inner and outer Hertz contacts at α_j. The ring loads are
Fa = Σ Q sin α, Fr = Σ Q cos α cos ψ, M = Σ Q sin α·R_i·cos ψ.

This general geometry holds at zero and negative clearance (Pd ≤ 0: the balls are compressed
already at a = 0), where Yu 2017 eq 16–17 are singular. The groove is treated as continuous
across its bottom, so small negative contact angles (ball rolling over the groove bottom
towards the low shoulder) are allowed.

For pure axial loading (δr = θ = 0) all balls carry the same load and Yu 2017 eq 4,
Q = Fa/(Z sin α), holds; :func:`axial_state` evaluates that case in closed form.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import root
from scipy.optimize.elementwise import bracket_root, find_root

from ._checks import check_finite
from .geometry import RaceGeometry
from .hertz import ContactConstants, _constants, _curvature, ellipticity


def _groove_constants(geom: RaceGeometry, alpha, race: str, expand: bool) -> ContactConstants:
    """Hertz constants of the inner or outer contacts at contact angle(s) ``alpha``."""

    def g(x):
        return np.asarray(x)[..., None] if expand else x

    f = geom.inner_curvature if race == "inner" else geom.outer_curvature
    rho, f_rho = _curvature(g(geom.ball_diameter), g(geom.pitch_diameter), g(f), alpha, race)
    return _constants(rho, ellipticity(f_rho), geom.compliance)


def contact_constants_at(geom: RaceGeometry, alpha, expand: bool = False):
    """(inner, outer) :class:`~hertz.ContactConstants` and the series constant K_n [N/m^1.5]
    at contact angle(s) ``alpha`` [rad]. With ``expand`` the geometry fields get a trailing
    axis so that ``alpha`` may carry a ball axis."""
    alpha = check_finite("alpha", alpha, "rad")
    inner = _groove_constants(geom, alpha, "inner", expand)
    outer = _groove_constants(geom, alpha, "outer", expand)
    k_n = (inner.stiffness ** (-2.0 / 3.0) + outer.stiffness ** (-2.0 / 3.0)) ** -1.5
    return inner, outer, k_n


@dataclass(frozen=True)
class BallLoads:
    """Per-ball state of one bearing (arrays with a trailing ball axis of length Z).

    Attributes
    ----------
    azimuth : ψ_j [rad]
    contact_angle : α_j [rad]
    deflection : δ_j [m] (≤ 0: no contact)
    load : Q_j [N]
    inner, outer : Hertz constants of the inner / outer contacts
    axial_force, radial_force, moment : ring loads Fa [N], Fr [N], M [N·m]
    """

    azimuth: np.ndarray
    contact_angle: np.ndarray
    deflection: np.ndarray
    load: np.ndarray
    inner: ContactConstants
    outer: ContactConstants
    axial_force: np.ndarray
    radial_force: np.ndarray
    moment: np.ndarray


def ball_loads(geom: RaceGeometry, axial_offset, radial_displacement=0.0, tilt=0.0) -> BallLoads:
    """Per-ball loads and contact angles for given ring displacements (Jones 1960; Harris &
    Kotzalas 2007, Advanced Concepts ch. 1).

    Parameters
    ----------
    geom : operating geometry (fields scalar or arrays of one shape S)
    axial_offset : a [m], axial offset of the groove curvature centres from the centred
        position (broadcast with S)
    radial_displacement : δr [m], along ψ = 0
    tilt : θ [rad], inner ring relative to outer, about the axis at ψ = 90°

    Returns :class:`BallLoads` with per-ball arrays of shape S + (Z,).
    """
    a = np.asarray(check_finite("axial_offset", axial_offset, "m"))[..., None]
    dr = np.asarray(check_finite("radial_displacement", radial_displacement, "m"))[..., None]
    th = np.asarray(check_finite("tilt", tilt, "rad"))[..., None]
    return _ball_loads(geom, a, dr, th)


def _ball_loads(geom: RaceGeometry, a, dr, th) -> BallLoads:
    psi = 2.0 * np.pi * np.arange(geom.n_balls) / geom.n_balls
    cos_psi = np.cos(psi)
    r_i = np.asarray(geom.inner_centre_radius)[..., None]
    a1 = a + th * r_i * cos_psi
    a2 = np.asarray(geom.radial_centre_distance)[..., None] + dr * cos_psi
    s = np.hypot(a1, a2)
    alpha = np.arctan2(a1, a2)
    delta = s - np.asarray(geom.curvature_distance)[..., None]
    inner, outer, k_n = contact_constants_at(geom, alpha, expand=True)
    q = k_n * np.maximum(delta, 0.0) ** 1.5
    sin_a, cos_a = a1 / s, a2 / s
    return BallLoads(
        azimuth=psi,
        contact_angle=alpha,
        deflection=delta,
        load=q,
        inner=inner,
        outer=outer,
        axial_force=np.sum(q * sin_a, axis=-1),
        radial_force=np.sum(q * cos_a * cos_psi, axis=-1),
        moment=np.sum(q * sin_a * r_i * cos_psi, axis=-1),
    )


def _ring_stiffness(geom: RaceGeometry, loads: BallLoads):
    """3×3 stiffness d(Fa, Fr, M)/d(a, δr, θ) of one bearing [N/m, N, N·m/rad …], with K_n
    held at each ball's operating angle (its angle dependence is a < 0.1 % correction)."""
    cos_psi = np.cos(loads.azimuth)
    r_i = np.asarray(geom.inner_centre_radius)[..., None]
    a_dist = np.asarray(geom.curvature_distance)[..., None]
    s = a_dist + loads.deflection
    n1, n2 = np.sin(loads.contact_angle), np.cos(loads.contact_angle)
    contact = loads.deflection > 0
    k_n = np.where(contact, loads.load / np.where(contact, loads.deflection, 1.0) ** 1.5, 0.0)
    dq_ds = 1.5 * k_n * np.sqrt(np.maximum(loads.deflection, 0.0))
    q_s = np.where(contact, loads.load / s, 0.0)
    # d(force vector)/d(A1, A2) = dQ/ds·n·nᵀ + Q/s·(I − n·nᵀ)
    k11 = dq_ds * n1 * n1 + q_s * (1 - n1 * n1)
    k12 = dq_ds * n1 * n2 - q_s * n1 * n2
    k22 = dq_ds * n2 * n2 + q_s * (1 - n2 * n2)
    # (A1, A2) = (a + θ·R_i·cosψ, … + δr·cosψ);  (Fa, Fr, M) = (f1, f2·cosψ, f1·R_i·cosψ)
    rc = r_i * cos_psi
    jac = np.empty((*np.shape(loads.axial_force), 3, 3))
    jac[..., 0, 0] = np.sum(k11, -1)
    jac[..., 0, 1] = np.sum(k12 * cos_psi, -1)
    jac[..., 0, 2] = np.sum(k11 * rc, -1)
    jac[..., 1, 0] = jac[..., 0, 1]
    jac[..., 1, 1] = np.sum(k22 * cos_psi**2, -1)
    jac[..., 1, 2] = np.sum(k12 * cos_psi * rc, -1)
    jac[..., 2, 0] = jac[..., 0, 2]
    jac[..., 2, 1] = jac[..., 1, 2]
    jac[..., 2, 2] = np.sum(k11 * rc * rc, -1)
    return jac


@dataclass(frozen=True)
class AxialState:
    """One bearing under pure axial offset: every ball alike (Yu 2017 eq 4 holds).

    Attributes
    ----------
    offset : a [m]
    contact_angle : α [rad]
    deflection : δ [m] (≤ 0: no contact)
    ball_load : Q [N]
    axial_force : Fa = Z·Q·sin α [N]
    axial_stiffness : dFa/da [N/m]
    inner, outer : Hertz constants of the contacts
    """

    offset: np.ndarray
    contact_angle: np.ndarray
    deflection: np.ndarray
    ball_load: np.ndarray
    axial_force: np.ndarray
    axial_stiffness: np.ndarray
    inner: ContactConstants
    outer: ContactConstants


def axial_state(geom: RaceGeometry, offset) -> AxialState:
    """Closed-form state of one bearing under a pure axial offset ``offset`` [m] (broadcast
    with the geometry fields). Harris & Kotzalas 2007, Advanced Concepts ch. 1 (thrust load);
    Yu 2017 eq 4 (Q = Fa/(Z sin α)) follows from it."""
    a = np.asarray(check_finite("offset", offset, "m"), dtype=float)
    return _axial_state(geom, a)


def _axial_state(geom: RaceGeometry, a) -> AxialState:
    a2 = geom.radial_centre_distance
    s = np.hypot(a, a2)
    alpha = np.arctan2(a, a2)
    delta = s - geom.curvature_distance
    inner, outer, k_n = contact_constants_at(geom, alpha)
    dpos = np.maximum(delta, 0.0)
    q = k_n * dpos**1.5
    sin_a = a / s
    z = geom.n_balls
    force = z * q * sin_a
    stiffness = z * (1.5 * k_n * np.sqrt(dpos) * sin_a**2 + q / s * (1.0 - sin_a**2))
    return AxialState(a, alpha, delta, q, force, stiffness, inner, outer)


def axial_force(offset, geom: RaceGeometry):
    """Axial force Fa(a) [N] of one bearing at axial offset a [m]: odd, non-decreasing in a,
    zero inside the axial play (|a| < h) when the clearance is positive."""
    a = np.asarray(check_finite("offset", offset, "m"), dtype=float)
    return _axial_state(geom, a).axial_force


def _geometry_args(geom: RaceGeometry, shape):
    """Geometry fields broadcast to ``shape`` (for the elementwise root finders)."""
    fields = (
        geom.ball_diameter,
        geom.inner_race_diameter,
        geom.outer_race_diameter,
        geom.inner_groove_radius,
        geom.outer_groove_radius,
    )
    return tuple(np.broadcast_to(np.asarray(f, dtype=float), shape) for f in fields)


def _geometry_from_args(args, n_balls, compliance) -> RaceGeometry:
    return RaceGeometry(*args, n_balls=n_balls, compliance=compliance)


def offset_for_axial_force(geom: RaceGeometry, force):
    """Axial offset a [m] at which one bearing carries axial force ``force`` [N] (inverse of
    :func:`axial_force`, by bracketing root finding; elementwise over arrays). For Fa = 0 the
    first-contact offset (the edge of the axial play) is returned."""
    f = np.asarray(check_finite("force", force, "N"), dtype=float)
    shape = np.broadcast_shapes(f.shape, np.shape(geom.clearance))
    f = np.broadcast_to(f, shape)
    args = _geometry_args(geom, shape)
    h = np.broadcast_to(geom.first_contact_offset, shape)

    def residual(a, fa, *g):
        return axial_force(a, _geometry_from_args(g, geom.n_balls, geom.compliance)) - fa

    sign = np.where(f >= 0, 1.0, -1.0)
    scale = np.broadcast_to(geom.curvature_distance, shape)
    lo = np.where(f >= 0, h, -h - 0.05 * scale)
    hi = np.where(f >= 0, h + 0.05 * scale, -h)
    bracket = bracket_root(residual, lo, hi, args=(f, *args))
    res = find_root(residual, bracket.bracket, args=(f, *args), tolerances={"xatol": 1e-16})
    out = np.where(f == 0, sign * h, res.x)
    return out if out.ndim else float(out)


@dataclass(frozen=True)
class Displacements:
    """Solution of :func:`bearing_displacements`.

    Attributes
    ----------
    axial_offset : a [m] from the centred position
    axial_displacement : a − h [m], from first axial contact (h = first-contact offset)
    radial_displacement : δr [m]
    tilt : θ [rad]
    balls : per-ball :class:`BallLoads` at the solution
    converged : whether the force balance was met (relative residual < 1e-9)
    """

    axial_offset: float
    axial_displacement: float
    radial_displacement: float
    tilt: float
    balls: BallLoads
    converged: bool


def bearing_displacements(
    geom: RaceGeometry, axial_load: float, radial_load: float = 0.0, moment: float = 0.0
) -> Displacements:
    """Ring displacements (axial, radial, tilt) and per-ball loads and contact angles of one
    bearing under (Fa [N], Fr [N], M [N·m]) (Jones 1960; Harris & Kotzalas 2007, Advanced
    Concepts ch. 1). Scalar geometry only. Newton–Powell (scipy.optimize.root, hybr) on the
    three force balances, started from the closed-form pure-axial solution; a load the
    bearing cannot carry (e.g. a radial load with no axial load and positive clearance needs
    balls on both groove flanks) is returned with ``converged = False``.
    """
    fa = check_finite("axial_load", axial_load, "N")
    fr = check_finite("radial_load", radial_load, "N")
    mo = check_finite("moment", moment, "N·m")
    if np.ndim(geom.clearance):
        raise ValueError("bearing_displacements takes a scalar geometry (one temperature)")
    a_len = float(geom.curvature_distance)
    r_i = float(geom.inner_centre_radius)
    target = np.array([fa, fr, mo / r_i])
    scale = max(np.abs(target).max(), 1e-3)
    h = float(geom.first_contact_offset)
    a0 = float(offset_for_axial_force(geom, fa)) if fa else 0.0
    if fr:
        # start with the radially loaded balls already in contact
        dr0 = np.sign(fr) * (max(float(geom.clearance), 0.0) * 0.5 + 1e-3 * a_len)
        a0 = a0 if fa else 0.0
    else:
        dr0 = 0.0
    x0 = np.array([a0, dr0, 0.0]) / a_len

    def fun(x):
        loads = _ball_loads(geom, x[0] * a_len, x[1] * a_len, x[2] * a_len / r_i)
        res = np.array([loads.axial_force, loads.radial_force, loads.moment / r_i]) - target
        jac = _ring_stiffness(geom, loads) * a_len
        jac[:, 2] /= r_i
        jac[2, :] /= r_i
        return res / scale, jac / scale

    best = None
    for method in ("hybr", "lm"):
        sol = root(fun, x0, jac=True, method=method, options={"xtol": 1e-14})
        resid = np.abs(fun(sol.x)[0]).max()
        if best is None or resid < best[1]:
            best = (sol.x, resid)
        if resid < 1e-9:
            break
    x, resid = best
    a, dr, th = x[0] * a_len, x[1] * a_len, x[2] * a_len / r_i
    loads = _ball_loads(geom, np.asarray(a)[..., None], np.asarray(dr)[..., None], th)
    return Displacements(
        axial_offset=float(a),
        axial_displacement=float(a - h),
        radial_displacement=float(dr),
        tilt=float(th),
        balls=loads,
        converged=bool(resid < 1e-9),
    )

r"""Quasi-static equilibrium of a ball bearing under axial load, radial load and moment.

Jones (1960) / Harris & Kotzalas (2007), *Advanced Concepts of Bearing Technology*, ch. 1
("distribution of internal loading"), without centrifugal and gyroscopic terms (servo
mechanisms run slowly). Ball j at azimuth :math:`\psi_j = 2\pi j/Z` sees its inner-groove
curvature centre displaced from the outer one by

.. math::

   A_{1j} = a + \theta\,R\cos\psi_j \quad \text{(axial)}, \qquad
   A_{2j} = (A - P_d/2) + \delta_r\cos\psi_j \quad \text{(radial)},

a being the axial offset from the centred position (see :mod:`.contact.geometry`), so that

.. math::

   s_j = \sqrt{A_{1j}^2 + A_{2j}^2}, \qquad \delta_j = s_j - A, \qquad
   \alpha_j = \operatorname{atan2}(A_{1j}, A_{2j}), \qquad Q_j = K_n(\alpha_j)\,\delta_j^{1.5}

(no load when :math:`\delta_j \le 0`), with :math:`K_n` the series load–deflection constant
of the inner and outer Hertz contacts at :math:`\alpha_j`. The ring loads are

.. math::

   F_a = \sum Q\sin\alpha, \qquad F_r = \sum Q\cos\alpha\cos\psi, \qquad
   M = \sum Q\sin\alpha\,R\cos\psi.

The tilt arm R is a choice (:func:`tilt_arm_radius`, keyword ``tilt_arm``):

- ``"groove"`` (default): R_i = d_i/2 + r_i, the radius of the locus of inner-groove
  curvature centres (Jones 1960; Harris & Kotzalas 2007, Advanced Concepts ch. 1, where
  ℜ_i = d_m/2 + (r_i − D/2)·cos α°). The contact normal passes through that centre, so R_i is
  both the exact first-order axial travel of the centre under a rigid tilt of the inner ring
  and the exact arm of the contact force about the ring centre (both taken in the plane of the
  inner groove centres, as Harris does): the consistent choice for this groove-centre model.
- ``"pitch"``: R = d_m/2 (D_pw/2), the pitch radius, the arm that tools built on the
  ISO/TS 16281:2008 load distribution (e.g. MASTA) are reported to use; offered to compare
  with their tilts (not checked here against the standard's own text). It moves the
  kinematics and the moment arm together, so the stiffness stays the exact derivative.

For the same ball loads the two tilts differ exactly by R_i/(d_m/2) (0.5–3.3 % for the
catalogue bearings, 1.29 % for the 71803). Under the same moment they differ by that ratio
squared where the bearing is linear (preloaded, small moment: the tilting stiffness grows as
R²; 2.6 % for the 71803 at 50 N and 0.1 N·mm), and by about the ratio itself where the tilt
mostly takes up axial play (no preload, positive clearance: 1.3 % at a pure 10 N·mm).

A single bearing under a moment with no radial constraint (Fr prescribed) tilts mainly about
its pressure centre, the point on the axis where the contact lines meet: the balls' normal
approach is then unchanged to first order and only the tangential term Q/s of the preloaded
contacts resists, so its tilting stiffness is far below the radially held K_ax·R²/2
(a factor ≈ 14 for the 71803 at 50 N). That is physics of the single row, not a solver
artefact; a pair or a shaft supplies the radial constraint.

This general geometry holds at zero and negative clearance (Pd ≤ 0: the balls are compressed
already at a = 0), where Yu 2017 eq 16–17 are singular. The groove is treated as continuous
across its bottom, so small negative contact angles (ball rolling over the groove bottom
towards the low shoulder) are allowed.

For pure axial loading (δr = θ = 0) all balls carry the same load and Yu 2017 eq 4,
Q = Fa/(Z sin α), holds; :func:`axial_state` evaluates that case in closed form.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
from scipy.optimize import root
from scipy.optimize.elementwise import bracket_root, find_root

from .._checks import check_choice, check_finite
from ..kernels import contact as kernels
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
    axis so that ``alpha`` may carry a ball axis.

    Parameters
    ----------
    geom : RaceGeometry
        Operating geometry (lengths [m], compliance [1/Pa]).
    alpha : float or array_like
        Contact angle(s) α [rad].
    expand : bool
        Add a trailing axis to the geometry fields (``alpha`` of shape S + (Z,)).

    Returns
    -------
    tuple
        (inner, outer, K_n): the :class:`~hertz.ContactConstants` of the two contacts and the
        series constant K_n = (K_i^(−2/3) + K_o^(−2/3))^(−3/2) [N/m^1.5] of Q = K_n·δ^1.5.

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> inner, outer, k_n = contact_constants_at(g, np.radians(15.0))
    >>> f"{float(k_n):.4g}"  # N/m^1.5
    '3.843e+09'
    >>> series = (inner.stiffness ** (-2 / 3) + outer.stiffness ** (-2 / 3)) ** -1.5
    >>> round(float(k_n / series), 12)  # the two contacts' deflections add
    1.0
    """
    alpha = check_finite("alpha", alpha, "rad")
    inner = _groove_constants(geom, alpha, "inner", expand)
    outer = _groove_constants(geom, alpha, "outer", expand)
    k_n = kernels.series_stiffness(inner.stiffness ** (-2.0 / 3.0), outer.stiffness ** (-2.0 / 3.0))
    return inner, outer, k_n


TILT_ARMS = ("groove", "pitch")


def tilt_arm_radius(geom: RaceGeometry, tilt_arm: str = "groove"):
    """Arm R [m] of a ring tilt: the radius at which a tilt θ moves the inner groove axially by
    θ·R·cos ψ and at which the balls' axial forces act on the ring (module docstring).

    Parameters
    ----------
    geom : RaceGeometry
        Operating geometry (fields scalar or arrays).
    tilt_arm : {"groove", "pitch"}
        ``"groove"``: R_i = d_i/2 + r_i [m], the locus of inner-groove curvature centres
        (Jones 1960; Harris & Kotzalas 2007, Advanced Concepts ch. 1), the default.
        ``"pitch"``: d_m/2 [m], the pitch radius, as in ISO/TS 16281-based tools.

    Returns
    -------
    float or numpy.ndarray
        R [m], the shape of the geometry fields.

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> round(float(tilt_arm_radius(g, "groove")) * 1e3, 4), tilt_arm_radius(g, "pitch") * 1e3
    (10.8888, 10.75)
    """
    check_choice("tilt_arm", tilt_arm, TILT_ARMS)
    if tilt_arm == "pitch":
        return 0.5 * geom.pitch_diameter
    return geom.inner_centre_radius


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
    arm : tilt arm R [m] of the kinematics and of ``moment`` (:func:`tilt_arm_radius`),
        with a trailing axis of length 1
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
    arm: np.ndarray


def ball_loads(
    geom: RaceGeometry,
    axial_offset,
    radial_displacement=0.0,
    tilt=0.0,
    *,
    tilt_arm: str = "groove",
) -> BallLoads:
    """Per-ball loads and contact angles for given ring displacements (Jones 1960; Harris &
    Kotzalas 2007, Advanced Concepts ch. 1).

    Parameters
    ----------
    geom : RaceGeometry
        Operating geometry (fields scalar or arrays of one shape S).
    axial_offset : float or array_like
        a [m], axial offset of the groove curvature centres from the centred position
        (broadcast with S).
    radial_displacement : float or array_like
        δr [m], inner ring relative to outer, along ψ = 0.
    tilt : float or array_like
        θ [rad], inner ring relative to outer, about the axis at ψ = 90° (positive: the ball at
        ψ = 0 is pushed towards positive a).
    tilt_arm : {"groove", "pitch"}
        Arm of the tilt, see :func:`tilt_arm_radius`.

    Returns
    -------
    BallLoads
        Per-ball arrays of shape S + (Z,): Q_j [N], α_j [rad], δ_j [m]; ring loads Fa [N],
        Fr [N], M [N·m] of shape S.

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> b = ball_loads(g, 70e-6, tilt=1e-4, tilt_arm="pitch")
    >>> b.load.shape, round(float(b.axial_force), 1), round(float(b.moment) * 1e3, 2)  # N, N·mm
    ((15,), 59.0, 68.75)
    """
    a = np.asarray(check_finite("axial_offset", axial_offset, "m"))[..., None]
    dr = np.asarray(check_finite("radial_displacement", radial_displacement, "m"))[..., None]
    th = np.asarray(check_finite("tilt", tilt, "rad"))[..., None]
    return _ball_loads(geom, a, dr, th, tilt_arm=tilt_arm)


def _ball_loads(geom: RaceGeometry, a, dr, th, tilt_arm: str = "groove") -> BallLoads:
    psi = 2.0 * np.pi * np.arange(geom.n_balls) / geom.n_balls
    cos_psi = np.cos(psi)
    arm = np.asarray(tilt_arm_radius(geom, tilt_arm))[..., None]
    a1 = a + th * arm * cos_psi
    a2 = np.asarray(geom.radial_centre_distance)[..., None] + dr * cos_psi
    _, sin_a, cos_a, delta = kernels.ball_contact(
        a1, a2, np.asarray(geom.curvature_distance)[..., None]
    )
    alpha = np.arctan2(a1, a2)
    inner, outer, k_n = contact_constants_at(geom, alpha, expand=True)
    q = kernels.hertz_load(k_n, delta)
    return BallLoads(
        azimuth=psi,
        contact_angle=alpha,
        deflection=delta,
        load=q,
        inner=inner,
        outer=outer,
        axial_force=np.sum(q * sin_a, axis=-1),
        radial_force=np.sum(q * cos_a * cos_psi, axis=-1),
        moment=np.sum(q * sin_a * arm * cos_psi, axis=-1),
        arm=arm,
    )


def _ring_stiffness(geom: RaceGeometry, loads: BallLoads):
    """3×3 stiffness d(Fa, Fr, M)/d(a, δr, θ) of one bearing [N/m, N, N·m/rad …], with K_n
    held at each ball's operating angle (its angle dependence is a < 0.1 % correction), about
    the tilt arm the loads were computed with (``loads.arm``)."""
    cos_psi = np.cos(loads.azimuth)
    a_dist = np.asarray(geom.curvature_distance)[..., None]
    s = a_dist + loads.deflection
    n1, n2 = np.sin(loads.contact_angle), np.cos(loads.contact_angle)
    contact = loads.deflection > 0
    k_n = np.where(contact, loads.load / np.where(contact, loads.deflection, 1.0) ** 1.5, 0.0)
    # d(force vector)/d(A1, A2) = dQ/ds·n·nᵀ + Q/s·(I − n·nᵀ), K_n held (slope 0)
    k11, k12, _, k22, _ = kernels.ball_stiffness(loads.load, s, loads.deflection, k_n, 0.0, n1, n2)
    # (A1, A2) = (a + θ·R·cosψ, … + δr·cosψ);  (Fa, Fr, M) = (f1, f2·cosψ, f1·R·cosψ)
    rc = loads.arm * cos_psi
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
    Yu 2017 eq 4 (Q = Fa/(Z sin α)) follows from it.

    Parameters
    ----------
    geom : RaceGeometry
        Operating geometry (fields scalar or arrays).
    offset : float or array_like
        a [m], axial offset of the groove curvature centres from the centred position.

    Returns
    -------
    AxialState
        a [m], α [rad], δ [m], Q [N], Fa [N], dFa/da [N/m] and the Hertz constants.

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> s = axial_state(g, 70e-6)
    >>> round(float(s.axial_force), 4), round(float(np.degrees(s.contact_angle)), 4)  # N, °
    (58.7038, 16.9285)
    >>> round(float(s.axial_force / (g.n_balls * s.ball_load * np.sin(s.contact_angle))), 12)
    1.0

    (the last line is Yu 2017 eq 4, Fa = Z·Q·sin α).
    """
    a = np.asarray(check_finite("offset", offset, "m"), dtype=float)
    return _axial_state(geom, a)


def _axial_state(geom: RaceGeometry, a) -> AxialState:
    a2 = geom.radial_centre_distance
    s, sin_a, cos_a, delta = kernels.ball_contact(a, a2, geom.curvature_distance)
    alpha = np.arctan2(a, a2)
    inner, outer, k_n = contact_constants_at(geom, alpha)
    q = kernels.hertz_load(k_n, delta)
    z = geom.n_balls
    force = z * q * sin_a
    held = kernels.ball_stiffness(q, s, delta, k_n, 0.0, sin_a, cos_a)[4]  # K_n held
    stiffness = z * held
    return AxialState(a, alpha, delta, q, force, stiffness, inner, outer)


def axial_force(offset, geom: RaceGeometry):
    """Axial force Fa(a) [N] of one bearing at axial offset a [m]: odd, non-decreasing in a,
    zero inside the axial play (|a| < h) when the clearance is positive.

    Parameters
    ----------
    offset : float or array_like
        a [m], axial offset of the groove curvature centres from the centred position.
    geom : RaceGeometry
        Operating geometry (fields scalar or arrays).

    Returns
    -------
    numpy.ndarray
        Fa [N], the broadcast shape of ``offset`` and the geometry fields.

    Examples
    --------
    The 71803 first touches at h = A·sin 15° = 61.6 µm:

    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> [round(float(f), 4) for f in axial_force(np.array([50e-6, 70e-6, -70e-6]), g)]  # N
    [0.0, 58.7038, -58.7038]
    """
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
    first-contact offset (the edge of the axial play) is returned.

    Parameters
    ----------
    geom : RaceGeometry
        Operating geometry (fields scalar or arrays).
    force : float or array_like
        Fa [N] (negative: towards negative offsets).

    Returns
    -------
    float or numpy.ndarray
        a [m].

    Examples
    --------
    At Fa = 0 the edge of the play, h = A·sin α0 (:func:`geometry.first_contact_offset`):

    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> a0 = offset_for_axial_force(g, 0.0)
    >>> h = float(g.curvature_distance * np.sin(np.radians(15.0)))
    >>> round(a0 * 1e6, 4), round(h * 1e6, 4)  # µm
    (61.6245, 61.6245)
    >>> a = offset_for_axial_force(g, 50.0)
    >>> round(a * 1e6, 4), round(float(axial_force(a, g)), 6)  # µm, N: the inverse
    (69.2409, 50.0)
    """
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


def _tilt_start(geom: RaceGeometry, axial_load: float, moment: float, a0: float, arm: float):
    """Starting tilt θ0 [rad] for the Newton solve, from the moment and the bearing's own
    axial load–deflection curve (a secant stiffness estimate, not a fixed number).

    Rigid rings, balls alike: ball j carries the axial share Fa/Z + 2·M·cos ψ_j/(Z·R)
    (Σ cos² ψ_j = Z/2 for Z ≥ 3; Harris & Kotzalas 2007, Advanced Concepts ch. 1). The most
    loaded ball then sits at the offset a* of the whole bearing under the axial load
    Fa + 2·|M|/R (:func:`offset_for_axial_force`, which includes the axial play), and the tilt
    that puts it there from the start offset a0 is θ0 = ±(a* − a0)/R. Exact for linear
    springs; for Hertz contacts an order-one estimate that Newton corrects. At θ = 0 with no
    axial load the balls are out of contact (or touch with zero stiffness at zero clearance),
    which is why the solve cannot start there.
    """
    if moment == 0.0:
        return 0.0
    side = 1.0 if axial_load >= 0.0 else -1.0
    peak = side * (abs(axial_load) + 2.0 * abs(moment) / arm)
    return float(np.sign(moment)) * side * (float(offset_for_axial_force(geom, peak)) - a0) / arm


def _start(geom: RaceGeometry, fa: float, fr: float, mo: float, arm: float):
    """Start (a [m], δr [m], θ [rad]) of :func:`bearing_displacements`: the closed-form pure-axial
    offset (centred when Fa = 0), the radially loaded balls just in contact, the tilt of
    :func:`_tilt_start`."""
    a0 = float(offset_for_axial_force(geom, fa)) if fa else 0.0
    dr0 = 0.0
    if fr:
        dr0 = np.sign(fr) * (max(float(geom.clearance), 0.0) * 0.5 + 1e-3 * geom.curvature_distance)
    return a0, dr0, _tilt_start(geom, fa, mo, a0, arm)


def bearing_displacements(
    geom: RaceGeometry,
    axial_load: float,
    radial_load: float = 0.0,
    moment: float = 0.0,
    *,
    tilt_arm: str = "groove",
) -> Displacements:
    """Ring displacements (axial, radial, tilt) and per-ball loads and contact angles of one
    bearing under (Fa, Fr, M) (Jones 1960; Harris & Kotzalas 2007, Advanced Concepts ch. 1).

    Newton–Powell (scipy.optimize.root, hybr, then lm if hybr stalls) on the three force
    balances, started from the closed-form pure-axial solution, the radially loaded balls in
    contact and a finite tilt estimated from the moment (:func:`_tilt_start`), so that a pure
    moment converges; if that fails, again from zero tilt. A load the bearing cannot carry
    (e.g. a radial load with no axial load and positive clearance needs balls on both groove
    flanks) is returned with ``converged = False``. With no axial load a moment is carried on
    both groove flanks (the groove is continuous across its bottom; shoulder heights are not
    modelled).

    Parameters
    ----------
    geom : RaceGeometry
        Operating geometry, scalar fields only (one temperature).
    axial_load : float
        Fa [N] on the inner ring, positive towards positive axial offset.
    radial_load : float
        Fr [N] along ψ = 0.
    moment : float
        M [N·m] about the axis at ψ = 90° (positive loads the ball at ψ = 0 further).
    tilt_arm : {"groove", "pitch"}
        Arm of the tilt and of the moment, see :func:`tilt_arm_radius`.

    Returns
    -------
    Displacements
        a [m], a − h [m], δr [m], θ [rad], the per-ball loads and ``converged`` (relative
        residual of the balances < 1e-9).

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> d = bearing_displacements(g, 0.0, 0.0, 0.01, tilt_arm="pitch")  # a pure 10 N·mm
    >>> d.converged, round(d.tilt * 1e3, 2)  # mrad
    (True, 5.97)
    """
    fa = check_finite("axial_load", axial_load, "N")
    fr = check_finite("radial_load", radial_load, "N")
    mo = check_finite("moment", moment, "N·m")
    check_choice("tilt_arm", tilt_arm, TILT_ARMS)
    if np.ndim(geom.clearance):
        raise ValueError("bearing_displacements takes a scalar geometry (one temperature)")
    a_len = float(geom.curvature_distance)
    arm = float(tilt_arm_radius(geom, tilt_arm))
    target = np.array([fa, fr, mo / arm])
    scale = max(np.abs(target).max(), 1e-3)
    a0, dr0, th0 = _start(geom, fa, fr, mo, arm)
    # the untilted start (today's) is kept as a fallback: on near-singular mixes (small Fa,
    # large Fr and M, positive clearance) hybr and lm can stall in a local minimum of |res|
    starts = [np.array([a0, dr0, th * arm]) / a_len for th in dict.fromkeys((th0, 0.0))]

    def fun(x):
        loads = _ball_loads(geom, x[0] * a_len, x[1] * a_len, x[2] * a_len / arm, tilt_arm)
        res = np.array([loads.axial_force, loads.radial_force, loads.moment / arm]) - target
        jac = _ring_stiffness(geom, loads) * a_len
        jac[:, 2] /= arm
        jac[2, :] /= arm
        return res / scale, jac / scale

    x, resid = _solve(fun, starts)
    a, dr, th = x[0] * a_len, x[1] * a_len, x[2] * a_len / arm
    loads = _ball_loads(geom, np.asarray(a)[..., None], np.asarray(dr)[..., None], th, tilt_arm)
    return Displacements(
        axial_offset=float(a),
        axial_displacement=float(a - float(geom.first_contact_offset)),
        radial_displacement=float(dr),
        tilt=float(th),
        balls=loads,
        converged=bool(resid < 1e-9),
    )


def _solve(fun, starts):
    """Root of ``fun`` (scaled residual, Jacobian) by hybr, then lm if hybr stalls, from each
    start in turn until one converges: the best point and its largest scaled residual."""
    best = None
    for x0, method in itertools.product(starts, ("hybr", "lm")):
        sol = root(fun, x0, jac=True, method=method, options={"xtol": 1e-14})
        resid = np.abs(fun(sol.x)[0]).max()
        if best is None or resid < best[1]:
            best = (sol.x, resid)
        if resid < 1e-9:
            break
    return best

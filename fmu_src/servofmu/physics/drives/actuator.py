r"""Stiffness of an electromechanical actuator: gear train → ball screw → crank-slider linkage
→ output shaft, in a housing (Liu Yuan, Wang Yongle, Cao Donghai, Liu Tao 2014, "A stiffness
calculation method of servo mechanism", Navigation Positioning and Timing 2014(2):46–49),
plus the screw's support bearings as a Hertzian element (this project's extension).

**Geometry of the crank-slider** (Liu Fig 5; the figure is lost, this layout satisfies
eq 9–16): the output shaft C is the origin; the crank CB of length :math:`L_1` stands at
angle θ from the slide direction x, :math:`B = L_1(\cos\theta, \sin\theta)`; the connecting
rod BA of length :math:`L_2` joins the ball-screw nut A, which slides on :math:`y = Y_1`:
:math:`A = (L_1\cos\theta + L_2\cos\gamma,\; Y_1)` with (eq 9, corrected: printed inverted)

.. math::

   \sin\gamma = \frac{L_1\sin\theta - Y_1}{L_2}.

The output (rudder) angle is :math:`\delta = \theta - \theta_0`, counter-clockwise positive.
The nut position :math:`x_A(\theta)` is solved exactly (eq 2–3 without the small-angle
expansion), and its derivative

.. math::

   \frac{dx}{d\theta} = -L_1\,(\sin\theta + \cos\theta\tan\gamma)

is the kinematic lever that reflects every axial stiffness of the screw line to the output
shaft: :math:`K_\mathrm{out} = (dx/d\theta)^2\,k_\mathrm{axial}`.

**Reduction ratios** (eq 1, 4, 5):

.. math::

   i_s = \frac{2\pi L_1}{p}, \qquad
   i = i_g\,\frac{2\pi}{p}\left|\frac{dx}{d\theta}\right|, \qquad
   i_r = \frac{i}{i_g\,i_s} = \frac{|dx/d\theta|}{L_1}

(eq 1 reads the nut travel as the arc of the crank of length :math:`L_1`: Liu names that
lever "L", the connecting rod's name in eq 9, but only the crank radius makes the ratio
dimensionless); :math:`i_r = 1` where the rod is square to the crank.

**Series stiffness at the output** (eq 6–8):

.. math::

   \frac{1}{K} = \frac{1}{(i_s i_r)^2 K_\mathrm{gear}} + \frac{1}{i_r^2 K_\mathrm{screw}}
   + \frac{1}{K_\mathrm{rod}} + \frac{1}{K_\mathrm{body}}
   \;\left(+ \frac{1}{K_\mathrm{support}}\right)

with :math:`K_\mathrm{gear}` torsional at the screw shaft,
:math:`K_\mathrm{screw} = k_\mathrm{screw} L_1^2` the screw's axial stiffness at the crank
radius (so :math:`i_r^2 K_\mathrm{screw} = (dx/d\theta)^2 k_\mathrm{screw}`) and
:math:`K_\mathrm{body} = (dx/d\theta)^2 k_\mathrm{body}`.

**Linkage stiffness** (eq 9–20): rod force :math:`F_2 = M/(L_1\sin\beta)` (eq 10), screw
force :math:`F_3 = F_2\cos\gamma` (eq 11), the crank and rod stretch by N·L/(E·A)
(eq 12–13), the deformed mechanism is closed again with the nut held (eq 14–16, solved
exactly as the intersection of two circles), the output shaft twists by
:math:`M l/(G I_1)` (eq 17) and the output arm bends as a cantilever by
:math:`M l^3/(3 E I L_1)` (eq 18, corrected: the printed form lacks the second moment of
area I), adding :math:`\arctan(M l^2/(3 E I L_1))` to the rotation (eq 19), and
:math:`K_\mathrm{rod} = M/\Delta\theta` (eq 20). Every term is linear in M for small
deflections: eq 9–20 give a load-independent :math:`K_\mathrm{rod}`.

**Motor side** (this project): the motor angle from the neutral position is the nut travel in
motor radians,

.. math::

   \varphi = \pm\,i_g\,\frac{2\pi}{p}\,\bigl(x_A(\theta_0 + \delta) - x_A(\theta_0)\bigr),
   \qquad \frac{d\varphi}{d\delta} = i \quad \text{(eq 4)}.

Its inverse is closed form: the crank pin lies on the circle of radius :math:`L_1` about the
output shaft and on the circle of radius :math:`L_2` about the nut, so

.. math::

   \theta = \psi \pm \arccos\frac{L_1^2 + R^2 - L_2^2}{2 L_1 R}, \qquad
   R = |CA|, \qquad \psi = \operatorname{atan2}(Y_1, x_A);

the reach ends at the dead centres (:math:`R = L_1 + L_2` and :math:`R = |L_2 - L_1|`).
"""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass

import numpy as np

from .. import compiled
from .._checks import (
    check_finite,
    check_operating_temperature,
    check_positive,
    check_range,
)
from ..kernels.units import DEG
from ..thermal.temperatures import PartTemperatures
from . import stepping
from .stepping import (
    SMALLEST_MOMENT,
    SMALLEST_SCREW_FORCE,
    dead_centre_error,
    motor_reach_error,
    reach_error,
)


@dataclass(frozen=True)
class Actuator:
    """Parameters of the actuator (SI). Build from the catalogue with
    :meth:`Actuator.from_catalog`.

    Attributes
    ----------
    key, name : catalogue key and description
    gear_ratio : i_g [-]
    screw_lead : p [m/rev]
    crank_length : L1 [m]
    rod_length : L2 [m]
    neutral_crank_angle : θ0 [rad], crank angle at zero output angle
    neutral_rod_angle : γ0 [rad], rod angle at zero output angle (sets Y1)
    crank_area, rod_area : A1, A2 [m²] (eq 12–13)
    arm_length : l [m] (eq 17–19)
    shaft_polar_moment : I1 [m⁴] (torsion, eq 17)
    arm_second_moment : I [m⁴] (bending, eq 18–19)
    youngs_modulus, shear_modulus : E, G [Pa] of the linkage
    gear_stiffness : K_gear, torsional at the screw shaft [N·m/rad]
    screw_stiffness : k_screw, axial [N/m]
    housing_stiffness : k_body, axial along the screw [N/m]
    support_mounting : catalogue key of the screw's support-bearing pair (or "")
    seat_stiffness : axial stiffness in series with the support bearings [N/m] (inf: rigid)
    provenance : ((field, source), ...)
    """

    key: str
    name: str
    gear_ratio: float
    screw_lead: float
    crank_length: float
    rod_length: float
    neutral_crank_angle: float
    neutral_rod_angle: float
    crank_area: float
    rod_area: float
    arm_length: float
    shaft_polar_moment: float
    arm_second_moment: float
    youngs_modulus: float
    shear_modulus: float
    gear_stiffness: float
    screw_stiffness: float
    housing_stiffness: float
    support_mounting: str = ""
    seat_stiffness: float = np.inf
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        for name in (
            "gear_ratio",
            "screw_lead",
            "crank_length",
            "rod_length",
            "crank_area",
            "rod_area",
            "arm_length",
            "shaft_polar_moment",
            "arm_second_moment",
            "youngs_modulus",
            "shear_modulus",
            "gear_stiffness",
            "screw_stiffness",
            "housing_stiffness",
        ):
            check_positive(name, getattr(self, name))
        check_range(
            "neutral_crank_angle", self.neutral_crank_angle, 0.0, np.pi, lo_open=True, hi_open=True
        )
        check_range(
            "neutral_rod_angle",
            self.neutral_rod_angle,
            -np.pi / 2,
            np.pi / 2,
            lo_open=True,
            hi_open=True,
        )
        if not self.seat_stiffness > 0:
            raise ValueError(
                f"seat_stiffness = {self.seat_stiffness!r} N/m must be > 0 (inf: rigid)"
            )
        if (
            abs(self.slide_offset - self.crank_length * np.sin(self.neutral_crank_angle))
            > self.rod_length
        ):
            raise ValueError("the linkage cannot close at the neutral position")

    @property
    def slide_offset(self) -> float:
        """Y1 [m]: height of the slide above the output shaft (from θ0 and γ0, eq 9)."""
        return self.crank_length * np.sin(self.neutral_crank_angle) - self.rod_length * np.sin(
            self.neutral_rod_angle
        )

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")

    @classmethod
    def from_catalog(cls, key: str, **overrides) -> Actuator:
        """The actuator ``key`` of ``data/actuators.toml``, with the stiffnesses the data give
        reflected to the output (Liu 2014 Table 1, at the reference angle) turned into
        intrinsic ones through the kinematics (eq 1–5). ``overrides`` (SI) replace data values
        before that conversion (the calibration of ``servofmu paper liu2014``).

        >>> ema = Actuator.from_catalog("liu2014_ema")
        >>> ema.gear_ratio, ema.source("crank_length").split(":")[0]
        (3.0, 'calibrated')
        """
        from ...parameters import catalog

        text, v, prov = catalog.actuator_entry(key)
        reflected = {
            f: v.pop(f"{f}_reflected")
            for f in ("gear_stiffness", "screw_stiffness", "housing_stiffness")
        }
        ref_angle = v.pop("reference_angle")
        for field, value in overrides.items():
            if field not in v:
                raise ValueError(f"actuator override {field!r} is not one of {sorted(v)}")
            v[field] = value
            prov[field] = "override"
        act = cls(
            key=key,
            name=text["name"],
            support_mounting=text.get("support_mounting", ""),
            gear_stiffness=1.0,
            screw_stiffness=1.0,
            housing_stiffness=1.0,
            **v,
        )
        lever2 = float(kinematics(act, ref_angle).lever) ** 2
        screw_rev = (2.0 * math.pi / act.screw_lead) ** 2
        intrinsic = {
            "gear_stiffness": reflected["gear_stiffness"] / (screw_rev * lever2),
            "screw_stiffness": reflected["screw_stiffness"] / lever2,
            "housing_stiffness": reflected["housing_stiffness"] / lever2,
        }
        for f in intrinsic:
            prov[f] = "derived: " + prov.pop(f"{f}_reflected") + ", through the kinematics"
        prov.pop("reference_angle", None)
        return dataclasses.replace(act, **intrinsic, provenance=tuple(sorted(prov.items())))


@dataclass(frozen=True)
class Kinematics:
    """Crank-slider state at output angles δ (arrays).

    Attributes
    ----------
    crank_angle : θ = θ0 + δ [rad]
    rod_angle : γ [rad] (eq 9)
    transmission_angle : β, between crank BC and rod BA at B [rad]
    nut_position : x_A [m] (eq 2–3)
    lever : dx_A/dθ [m/rad] (signed)
    """

    crank_angle: np.ndarray
    rod_angle: np.ndarray
    transmission_angle: np.ndarray
    nut_position: np.ndarray
    lever: np.ndarray


def kinematics(act: Actuator, output_angle) -> Kinematics:
    """Exact crank-slider kinematics at output angle δ [rad] (Liu 2014 eq 2–3, 9): rod angle,
    transmission angle, nut position and its derivative. Raises ValueError where the linkage
    cannot close (|sin γ| ≥ 1).

    Parameters
    ----------
    act : Actuator
        The actuator.
    output_angle : float or array_like
        δ [rad].

    Returns
    -------
    Kinematics
        Crank, rod and transmission angles [rad], nut position [m], lever dx/dθ [m/rad].

    Examples
    --------
    >>> act = Actuator.from_catalog("liu2014_ema")
    >>> k = kinematics(act, 0.0)
    >>> round(float(k.nut_position) * 1e3, 3), round(float(k.lever) * 1e3, 3)  # mm, mm/rad
    (125.0, -51.806)
    """
    delta = np.asarray(check_finite("output_angle", output_angle, "rad"), dtype=float)
    theta = act.neutral_crank_angle + delta
    crank = crank_slider(act)
    s = crank.sin_rod_angle(theta)
    if np.any(np.abs(s) >= 1.0):
        bad = float(np.asarray(delta)[np.abs(s) >= 1.0].flat[0])
        raise reach_error(bad, act.crank_length, act.rod_length)
    gamma = np.arcsin(s)
    beta = crank.transmission_angle(theta, gamma)
    x = crank.nut_position(theta, gamma)
    lever = crank.lever(theta, gamma)
    dead = np.abs(lever) < 1e-6 * act.crank_length
    if np.any(dead):
        raise dead_centre_error(float(np.asarray(delta)[dead].flat[0]))
    return Kinematics(theta, gamma, beta, x, lever)


def crank_slider(act: Actuator, kernels=stepping) -> stepping.Linkage:
    """The crank-slider of ``act`` with its equations (Liu 2014 eq 2–3, 9–19) from the module
    ``kernels`` (:mod:`.stepping`, floats or arrays; or its compiled twin, floats).

    Returns
    -------
    Linkage

    Examples
    --------
    >>> round(crank_slider(Actuator.from_catalog("liu2014_ema")).l1 * 1e3, 3)  # mm: L1
    51.806
    """
    return kernels.Linkage(
        float(act.crank_length),
        float(act.rod_length),
        float(act.slide_offset),
        float(act.youngs_modulus),
        float(act.crank_area),
        float(act.rod_area),
        float(act.arm_length),
        float(act.shear_modulus),
        float(act.shaft_polar_moment),
        float(act.arm_second_moment),
    )


@dataclass(frozen=True)
class ReductionRatios:
    """Liu 2014 eq 1, 4, 5 at output angles δ: ``screw`` i_s = 2π·L1/p, ``linkage``
    i_r = |dx/dθ|/L1, ``total`` i = i_g·i_s·i_r (motor radians per output radian)."""

    screw: float
    linkage: np.ndarray
    total: np.ndarray


def reduction_ratio(act: Actuator, output_angle) -> ReductionRatios:
    """Reduction ratios at output angle δ [rad] (Liu 2014 eq 1, 4–5).

    Parameters
    ----------
    act : Actuator
        The actuator.
    output_angle : float or array_like
        δ [rad].

    Returns
    -------
    ReductionRatios
        screw, linkage and total ratios [-] (motor angle per output angle).

    Examples
    --------
    >>> act = Actuator.from_catalog("liu2014_ema")
    >>> r = reduction_ratio(act, 0.0)
    >>> round(float(r.total), 6) == round(act.gear_ratio * r.screw * float(r.linkage), 6)
    True

    (eq 1: i = i_g·i_s·i_r)
    """
    lever = np.abs(kinematics(act, output_angle).lever)
    i_s = 2.0 * np.pi * act.crank_length / act.screw_lead
    i_r = lever / act.crank_length
    return ReductionRatios(screw=i_s, linkage=i_r, total=act.gear_ratio * i_s * i_r)


def _motor_radians_per_metre(act: Actuator) -> float:
    """Signed motor angle per nut travel [rad/m]: i_g·2π/p (Liu 2014 eq 1, 4), with the sign
    that makes the motor angle rise with the output angle (the sign of dx/dθ at neutral)."""
    lever0 = kinematics(act, 0.0).lever
    return float(np.sign(lever0) * act.gear_ratio * 2.0 * np.pi / act.screw_lead)


def motor_angle(act: Actuator, output_angle):
    """Motor-shaft angle φ [rad] from the neutral position that puts the rigid mechanism at
    output angle δ [rad]: φ = ±(i_g·2π/p)·(x_A(θ0 + δ) − x_A(θ0)), the nut travel of the exact
    crank-slider (Liu 2014 eq 2–3, 9) turned into motor radians by the screw lead and the gear
    ratio (eq 1, 4). dφ/dδ is the reduction ratio i of eq 4 (positive: φ rises with δ).

    Parameters
    ----------
    act : the actuator
    output_angle : δ [rad], array-like

    Returns
    -------
    ndarray
        φ [rad]; ValueError where the linkage cannot reach δ (see :func:`kinematics`).

    Examples
    --------
    >>> ema = Actuator.from_catalog("liu2014_ema")
    >>> round(float(motor_angle(ema, np.radians(10.0))), 6)
    33.92322
    """
    x = kinematics(act, output_angle).nut_position
    return _motor_radians_per_metre(act) * (x - kinematics(act, 0.0).nut_position)


def output_angle(act: Actuator, motor_angle):
    """Output angle δ [rad] of the rigid mechanism at motor-shaft angle φ [rad] from the
    neutral position: the exact inverse of :func:`motor_angle`, in closed form.

    The motor angle gives the nut position x_A = x_A(θ0) + φ/(±i_g·2π/p) (Liu 2014 eq 1, 4).
    The crank pin B lies on the circle |CB| = L1 about the output shaft and on the circle
    |AB| = L2 about the nut A = (x_A, Y1), so x_A·cos θ + Y1·sin θ = (L1² + R² − L2²)/2L1 with
    R = |CA|: θ = ψ ± arccos((L1² + R² − L2²)/(2·L1·R)), ψ = atan2(Y1, x_A), on the branch of
    the neutral position. The two branches meet at the dead centres (crank and rod in line,
    R = L1 + L2 or |L2 − L1|), which bound the reach.

    Parameters
    ----------
    act : the actuator
    motor_angle : φ [rad] from the neutral position, array-like

    Returns
    -------
    ndarray
        δ [rad]. ValueError naming the motor angle where the mechanism would have to pass a
        dead centre, or where the rod would leave the slide's side of the crank.

    Examples
    --------
    >>> ema = Actuator.from_catalog("liu2014_ema")
    >>> round(float(np.degrees(output_angle(ema, motor_angle(ema, np.radians(10.0))))), 9)
    10.0
    """
    phi = np.asarray(check_finite("motor_angle", motor_angle, "rad"), dtype=float)
    crank = crank_slider(act)
    x = kinematics(act, 0.0).nut_position + phi / _motor_radians_per_metre(act)
    theta = crank.crank_angle(x, _branch(act))
    # cos γ > 0: the rod runs from B towards +x
    bad = ~(np.abs(crank.reach_cosine(x)) < 1.0) | ~(crank.rod_cosine(x, theta) > 0.0)
    if np.any(bad):
        raise motor_reach_error(float(phi[bad].flat[0]), _motor_reach_text(act))
    return np.angle(np.exp(1j * (theta - act.neutral_crank_angle)))


def _branch(act: Actuator) -> float:
    """±1: the side of the line from the output shaft C to the nut A that the crank pin B lies
    on at the neutral position (the branch of :func:`output_angle`)."""
    x0 = kinematics(act, 0.0).nut_position
    psi0 = np.arctan2(act.slide_offset, x0)
    return float(np.sign(np.angle(np.exp(1j * (act.neutral_crank_angle - psi0)))))


def _motor_reach_text(act: Actuator) -> str:
    """The open interval of motor angles between the dead centres around the neutral
    position, as text (nut at distance L1 + L2 and |L2 − L1| from the output shaft)."""
    l1, l2, y1 = act.crank_length, act.rod_length, act.slide_offset
    x0 = kinematics(act, 0.0).nut_position
    ends = [np.sign(x0) * np.sqrt(d**2 - y1**2) for d in (l1 + l2, abs(l2 - l1)) if d**2 > y1**2]
    phis = sorted(_motor_radians_per_metre(act) * (x - x0) for x in ends)
    if len(phis) == 2:
        return f"({phis[0]:.9g}, {phis[1]:.9g}) rad"
    return "motor angles keep the nut between the dead centres"


def screw_force(act: Actuator, output_angle, load_torque):
    """Axial force in the screw F3 = M·cos γ/(L1·sin β) = M/|dx/dθ| [N] (Liu 2014 eq 10–11;
    the second form is virtual work) for hinge moment M [N·m] at output angle δ [rad].

    Parameters
    ----------
    act : Actuator
        The actuator.
    output_angle : float or array_like
        δ [rad].
    load_torque : float or array_like
        M [N·m].

    Returns
    -------
    float or ndarray
        F3 [N].

    Examples
    --------
    >>> act = Actuator.from_catalog("liu2014_ema")
    >>> f = screw_force(act, 0.0, 100.0)
    >>> round(float(f), 3), round(float(f * abs(kinematics(act, 0.0).lever)), 9)  # N; F·|dx/dθ| = M
    (1930.296, 100.0)
    """
    m = np.asarray(check_finite("load_torque", load_torque, "N·m"), dtype=float)
    return m / np.abs(kinematics(act, output_angle).lever)


def linkage_rotation(act: Actuator, output_angle, load_torque) -> np.ndarray:
    """Elastic rotation Δθ [rad] of the output shaft under hinge moment M [N·m] with the nut
    held (Liu 2014 eq 10–19, eq 18–19 with the second moment of area I).

    Parameters
    ----------
    act : Actuator
        The actuator.
    output_angle : float or array_like
        δ [rad].
    load_torque : float or array_like
        M [N·m].

    Returns
    -------
    ndarray
        Δθ [rad].

    Examples
    --------
    >>> act = Actuator.from_catalog("liu2014_ema")
    >>> round(float(linkage_rotation(act, 0.0, 100.0)) * 1e6, 4)  # µrad at 100 N·m
    1701.4761
    """
    m = np.asarray(check_finite("load_torque", load_torque, "N·m"), dtype=float)
    kin = kinematics(act, output_angle)
    return crank_slider(act).rotation(kin.crank_angle, kin.transmission_angle, kin.nut_position, m)


def linkage_stiffness(act: Actuator, output_angle, load_torque):
    """K_rod = M/Δθ [N·m/rad] (Liu 2014 eq 20); for |M| below :data:`SMALLEST_MOMENT`
    (M = 0 included) the secant at that moment, with the sign of M.

    Parameters
    ----------
    act : Actuator
        The actuator.
    output_angle : float or array_like
        δ [rad].
    load_torque : float or array_like
        M [N·m].

    Returns
    -------
    float or ndarray
        K_rod [N·m/rad].

    Examples
    --------
    >>> act = Actuator.from_catalog("liu2014_ema")
    >>> k = linkage_stiffness(act, 0.0, 100.0)
    >>> round(float(k * linkage_rotation(act, 0.0, 100.0)), 9)  # N·m: K·Δθ = M
    100.0
    """
    m = np.asarray(check_finite("load_torque", load_torque, "N·m"), dtype=float)
    probe = np.where(np.abs(m) < SMALLEST_MOMENT, np.copysign(SMALLEST_MOMENT, m), m)
    return probe / linkage_rotation(act, output_angle, probe)


@dataclass(frozen=True)
class StiffnessBreakdown:
    """Stiffness of the actuator at the output shaft and its parts (arrays), N·m/rad.

    gear, screw, linkage, housing, support_bearing : each element reflected to the output
    (Liu eq 8; support_bearing is this project's extension, inf when none); total : the
    series sum (eq 6); deflection : M/total [rad]; reduction_ratio : i [-]; screw_force : F3
    [N]; shares : each element's compliance over the total compliance (Liu Fig 3–4).
    """

    gear: np.ndarray
    screw: np.ndarray
    linkage: np.ndarray
    housing: np.ndarray
    support_bearing: np.ndarray
    total: np.ndarray
    deflection: np.ndarray
    reduction_ratio: np.ndarray
    screw_force: np.ndarray

    ELEMENTS = ("gear", "screw", "linkage", "housing", "support_bearing")

    def share(self, element: str):
        """Compliance share of ``element`` [-]."""
        return self.total / getattr(self, element)


def series_stiffness(*stiffnesses):
    """1/K = Σ 1/K_i (Liu 2014 eq 6), elementwise [unit of the inputs]; an infinite (rigid)
    element drops out.

    Parameters
    ----------
    *stiffnesses : float or array_like
        K_i (any one unit; inf: rigid).

    Returns
    -------
    float or ndarray
        K.

    Examples
    --------
    >>> float(series_stiffness(2.0, 2.0)), float(series_stiffness(3.0, float("inf")))
    (1.0, 3.0)
    """
    ks = np.broadcast_arrays(*(np.asarray(k, dtype=float) for k in stiffnesses))
    for i, k in enumerate(ks):
        if np.any(~(k > 0)):
            raise ValueError(f"stiffness[{i}] = {float(k[~(k > 0)].flat[0])!r} must be > 0")
    return 1.0 / sum(1.0 / k for k in ks)


def stiffness_breakdown(
    act: Actuator, output_angle, load_torque, temperature=293.15, support=None
) -> StiffnessBreakdown:
    """Stiffness of the actuator at the output shaft (Liu 2014 eq 6–20 and the support-bearing
    extension) for output angle δ [rad], hinge moment M [N·m] and temperature T [K], all
    broadcast together. Elastic moduli are temperature-independent; the support-bearing
    preload follows the thermal coupling of :mod:`bearing`. ``support(F3, T)`` may replace
    :func:`support_axial_stiffness` (:class:`ActuatorModel` has its own per-step path).

    Returns
    -------
    StiffnessBreakdown
        gear, screw, linkage, housing, support bearing and total stiffness [N·m/rad], the
        deflection [rad], the reduction ratio [-] and the screw force [N].

    Examples
    --------
    >>> act = Actuator.from_catalog("liu2014_ema")
    >>> b = stiffness_breakdown(act, 0.0, 100.0)
    >>> round(float(per_degree(b.total)), 1)  # N·m/°, Liu's unit, at 100 N·m
    441.8
    """
    delta, m, t = np.broadcast_arrays(
        np.asarray(check_finite("output_angle", output_angle, "rad"), dtype=float),
        np.asarray(check_finite("load_torque", load_torque, "N·m"), dtype=float),
        np.asarray(check_operating_temperature("temperature", temperature), dtype=float),
    )
    kin = kinematics(act, delta)
    lever2 = kin.lever**2
    ratios = reduction_ratio(act, delta)
    gear = (2.0 * np.pi / act.screw_lead) ** 2 * lever2 * act.gear_stiffness  # (i_s·i_r)²·K_gear
    screw = lever2 * act.screw_stiffness  # i_r²·K_screw with K_screw = k_screw·L1²
    housing = lever2 * act.housing_stiffness
    linkage = linkage_stiffness(act, delta, m)
    f3 = np.abs(m) / np.abs(kin.lever)
    axial = support_axial_stiffness(act, f3, t) if support is None else support(f3, t)
    support = lever2 * axial
    total = series_stiffness(gear, screw, linkage, housing, support)
    return StiffnessBreakdown(
        gear=gear,
        screw=screw,
        linkage=linkage,
        housing=housing,
        support_bearing=support,
        total=total,
        deflection=m / total,
        reduction_ratio=ratios.total,
        screw_force=f3,
    )


def check_support_pair(pair) -> None:
    """ValueError unless :class:`~.pair.configuration.BearingPair` ``pair`` can support the screw:
    the screw pushes both ways, so its pair must be opposed (a tandem pair carries thrust one way).

    Returns
    -------
    None
        (ValueError for a tandem pair).

    >>> from servofmu.physics.bearing import BearingPair
    >>> check_support_pair(BearingPair.from_catalog("liu2014_screw_support", "mos2_film"))
    """
    if pair.mounting.arrangement == "tandem":
        raise ValueError(
            "arrangement = 'tandem' is not valid for the screw's support pair: the screw pushes "
            "both ways and a tandem pair carries thrust one way (valid: face_to_face, "
            "back_to_back)"
        )


@functools.lru_cache(maxsize=8)
def _support_pair(mounting: str):
    from ..pair.configuration import BearingPair

    return BearingPair.from_catalog(mounting, "mos2_film")


def support_axial_stiffness(act: Actuator, screw_force, temperature):
    """Secant axial stiffness F3/Δz [N/m] of the support-bearing pair under the screw force
    F3 [N] at temperature T [K], in series with the seat stiffness (this project's extension
    of Liu 2014: the Hertzian element that makes the stiffness rise with load). Δz is the
    shaft displacement of the preloaded pair from its unloaded state (general geometry,
    :func:`preload.pair_offsets`); below :data:`SMALLEST_SCREW_FORCE` the tangent stiffness
    (its limit). inf when the actuator has no support mounting.

    Parameters
    ----------
    act : Actuator
        The actuator (its support mounting).
    screw_force : float or array_like
        F3 [N].
    temperature : float or array_like
        T [K].

    Returns
    -------
    ndarray
        [N/m] (inf without a support mounting).

    Examples
    --------
    >>> act = Actuator.from_catalog("liu2014_ema")
    >>> k = support_axial_stiffness(act, [500.0, 2000.0], 293.15)
    >>> bool(k[1] > k[0])  # Hertzian: stiffer under more load
    True
    """
    f3, t = np.broadcast_arrays(
        np.asarray(check_finite("screw_force", screw_force, "N"), dtype=float),
        np.asarray(check_operating_temperature("temperature", temperature), dtype=float),
    )
    if not act.support_mounting:
        return np.full(f3.shape, np.inf)
    from ..pair.preload import pair_offsets
    from ..pair.state import axial_load_state, thermal_state

    pair = _support_pair(act.support_mounting)  # its lubricant plays no part in stiffness
    th = thermal_state(pair, t)
    off = pair_offsets(th.geometry, th.closure, th.loop_stiffness, f3)
    dz = 0.5 * (off.offset_a - off.offset_b)
    tangent = axial_load_state(pair, th, th.preload_offset, th.preload_offset).axial_stiffness
    secant = (f3 >= SMALLEST_SCREW_FORCE) & (dz > 0)
    bearing = np.where(secant, f3 / np.where(secant, dz, 1.0), tangent)
    return series_stiffness(bearing, act.seat_stiffness)


def per_degree(stiffness):
    """N·m/rad → N·m/° (Liu's unit), for display.

    Parameters
    ----------
    stiffness : float or array_like
        [N·m/rad].

    Returns
    -------
    float or ndarray
        [N·m/°].

    Examples
    --------
    >>> round(float(per_degree(180.0 / math.pi)), 12)  # N·m/°: 1 N·m/° back
    1.0
    """
    return np.asarray(stiffness) * DEG


class ActuatorModel:
    """Scalar evaluation of an :class:`Actuator` for the per-step path of the FMU: the
    equations of :func:`stiffness_breakdown` on floats in one call
    (:class:`~.stepping.ActuatorStepper`, compiled when the build could compile it:
    :mod:`servofmu.physics.compiled`), and the support-bearing pair solved by
    :class:`~.pair.model.BearingModel` (continuation from the previous step, exact to 1e-9)
    instead of the exact nested solve.

    Attributes
    ----------
    stepper : ActuatorStepper
        The per-step update: ``stepper.evaluate(δ, M, T)`` on checked floats gives the
        fields of :class:`StiffnessBreakdown` as a tuple; ``stepper.output_angle(φ)`` is
        :func:`output_angle` on a float (C's ``libm`` where numpy has its own arccos and
        arctan2: the same δ to a few units in the last place).
    """

    def __init__(self, act: Actuator, support_pair=None, implementation: str | None = None):
        """``support_pair``: a :class:`bearing.BearingPair` replacing the catalogue pair of
        ``act.support_mounting`` (e.g. with another bearing or preload); ``implementation``:
        "compiled", "python" or None (the one :mod:`.compiled` chose)."""
        self.act = act
        self._bearings = None
        if act.support_mounting:
            from ..pair.model import BearingModel

            pair = support_pair or _support_pair(act.support_mounting)
            check_support_pair(pair)
            self._bearings = BearingModel(pair, implementation)
        self.kernels = compiled.module("drives.stepping", implementation)
        self.stepper = self.kernels.ActuatorStepper(
            crank_slider(act, self.kernels),
            float(act.neutral_crank_angle),
            float(act.gear_ratio),
            float(act.screw_lead),
            float(act.gear_stiffness),
            float(act.screw_stiffness),
            float(act.housing_stiffness),
            float(act.seat_stiffness),
            None if self._bearings is None else self._bearings.update,
            float(kinematics(act, 0.0).nut_position),
            _motor_radians_per_metre(act),
            _branch(act),
            _motor_reach_text(act),
        )

    @property
    def implementation(self) -> str:
        """ "compiled" or "python"."""
        return "compiled" if compiled.is_compiled(self.kernels) else "python"

    def state(self) -> dict | None:
        """The support pair's continuation state (JSON-serialisable; None without one)."""
        return None if self._bearings is None else self._bearings.state()

    def restore(self, state: dict | None) -> None:
        """Continue from a :meth:`state` (bit for bit)."""
        if self._bearings is not None:
            self._bearings.restore(state)

    def evaluate(self, output_angle: float, load_torque: float, temperature):
        """:class:`StiffnessBreakdown` with float fields at one operating point (the equations
        of :func:`stiffness_breakdown`; ValueError naming a bad argument): output angle δ
        [rad], hinge moment M [N·m], and the temperature [K] of the support pair, uniform or
        its parts' (a :class:`~.thermal.temperatures.PartTemperatures` or a (housing, shaft, outer
        ring, inner ring) tuple: only the support pair's thermal preload depends on it).

        Returns
        -------
        StiffnessBreakdown
            Stiffnesses [N·m/rad], deflection [rad], ratio [-], screw force [N].

        >>> model = ActuatorModel(Actuator.from_catalog("liu2014_ema"))
        >>> even = model.evaluate(0.17, 100.0, 253.15).total
        >>> even == model.evaluate(0.17, 100.0, (253.15,) * 4).total
        True
        """
        from ..pair.model import _temperatures

        delta = _finite_float("output_angle", output_angle, "rad")
        m = _finite_float("load_torque", load_torque, "N·m")
        if isinstance(temperature, tuple | PartTemperatures):
            t = _temperatures(temperature)  # checked floats, named on error
        else:
            t = _finite_float("temperature", temperature, "K")
            if not t > 0.0:
                raise ValueError(f"temperature = {t!r} K is outside the valid range (0, inf) K")
        return StiffnessBreakdown(*self.stepper.evaluate(delta, m, t))


def _finite_float(name: str, value, unit: str) -> float:
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{name} = {v!r} {unit} is outside the valid range (-inf, inf)")
    return v


def shared_step(*args, implementation: str | None = None):
    """The ActuatorStiffness FMU's step on the values it shares with servofmu's export
    (:class:`.stepping.ActuatorSharedStep`; ``args``: those of
    :class:`~servofmu.physics.shared_step.SharedStep`), of ``implementation`` ("compiled",
    "python"; None: the one :mod:`servofmu.physics.compiled` chose, as
    :class:`ActuatorModel`'s).

    Returns
    -------
    ActuatorSharedStep

    Examples
    --------
    >>> step = shared_step(bytearray(32), 0, 0, 2, False, None, None)  # a block of no values
    >>> type(step).__name__, step.armed
    ('ActuatorSharedStep', False)
    """
    return compiled.module("drives.stepping", implementation).ActuatorSharedStep(*args)

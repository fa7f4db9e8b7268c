r"""Friction torque of a ball bearing: elastic hysteresis, ball spin, differential (Heathcote)
sliding and Palmgren's viscous torque, plus the breakaway/running distinction and a smooth
regularisation through zero speed.

**Grease-lubricated bearing** (Yu 2017 eq 9): the running torque is the sum of the rolling
(hysteresis), spin and viscous parts,

.. math::

   M = M_R + M_K + M_L .

- *Hysteresis* (Yu eq 1–3): each contact resists rolling with the force

  .. math::

     F = \frac{3\,\alpha_r\,b\,Q}{16\,R}, \qquad R = D_w/2,

  the ball radius (Johnson 1985, *Contact Mechanics*, ch. 9: the hysteresis rolling moment
  :math:`3\alpha_r b Q/16` divided by the rolling radius; Yu calls R the "Hertz contact
  radius"), acting at the race contact radius :math:`d/2 = (d_m \mp D_w\cos\alpha)/2`
  (eq 2), summed over the contacts (eq 3).
- *Spin* (Yu eq 5–7): per contact

  .. math::

     M'_K = \tfrac{3}{8}\,\mu\,Q\,a\,\mathcal{E}(e)

  (Harris & Kotzalas 2007), the larger of inner and outer, projected on the bearing axis by
  :math:`\sin\alpha` (eq 7).
- *Viscous* (Yu eq 8): Palmgren's load-independent torque, see
  :func:`palmgren_viscous_torque`.

**Solid-lubricated bearing** (Ning; the equations are missing from the published text and are
reconstructed here): hysteresis as above at both races (Ning cites Snare and Jones; the same
rolling-resistance form); differential sliding at both races (Heathcote slip,
:func:`heathcote_sliding_force`, with the variables f, Q, a, α, μ, dm, Dw that Ning lists for
his :math:`M_{di}`, :math:`M_{do}`); spin at the inner race only ("outer-race control",
Jones 1960), projected by :math:`\sin\alpha_i`; no viscous term.
"""

from __future__ import annotations

import math  # noqa: F401  (the examples use it)
from dataclasses import dataclass

import numpy as np

from .._checks import (
    check_choice,
    check_finite,
    check_nonnegative,
    check_positive,
    check_range,
)
from ..kernels.friction import (  # the equations, shared with the per-step path
    HEATHCOTE as HEATHCOTE,
)
from ..kernels.friction import (
    PALMGREN_THRESHOLD as PALMGREN_THRESHOLD,
)
from ..kernels.friction import (
    contact_spin_moment,
    heathcote_force,
    hysteresis_force,
    palmgren_torque,
    regularised_torque,
)


def race_contact_radius(pitch_diameter, ball_diameter, contact_angle, race: str):
    """Radius of the race contact about the bearing axis, (dm ∓ Dw·cos α)/2 [m] (Yu 2017
    eq 2: − for the inner, + for the outer race). pitch_diameter dm [m], ball_diameter Dw [m],
    contact_angle α [rad].

    Returns
    -------
    float or ndarray
        r [m].

    Examples
    --------
    >>> round(race_contact_radius(21.5e-3, 2.381e-3, 0.0, "inner") * 1e3, 4)  # mm: (dm − Dw)/2
    np.float64(9.5595)
    >>> round(race_contact_radius(21.5e-3, 2.381e-3, 0.0, "outer") * 1e3, 4)  # mm: (dm + Dw)/2
    np.float64(11.9405)
    """
    check_choice("race", race, ("inner", "outer"))
    check_positive("pitch_diameter", pitch_diameter, "m")
    check_positive("ball_diameter", ball_diameter, "m")
    check_finite("contact_angle", contact_angle, "rad")
    return _race_radius(pitch_diameter, ball_diameter, contact_angle, race)


def _race_radius(pitch_diameter, ball_diameter, contact_angle, race):
    sign = -1.0 if race == "inner" else 1.0
    return 0.5 * (pitch_diameter + sign * ball_diameter * np.cos(contact_angle))


def hysteresis_rolling_force(load, semi_minor_axis, ball_diameter, loss_factor):
    """Rolling resistance of one contact from elastic hysteresis, F_SE = 3·b·α_r·Q/(16·R) [N]
    (Yu 2017 eq 1) with R = Dw/2 the ball radius (Johnson 1985, ch. 9).

    load Q [N], semi_minor_axis b [m] (rolling direction), ball_diameter Dw [m],
    loss_factor α_r [-] (energy lost per cycle, < 1 % for metals per Yu).

    Parameters
    ----------
    load : float or array_like
        Q [N].
    semi_minor_axis : float or array_like
        b [m].
    ball_diameter : float or array_like
        Dw [m].
    loss_factor : float
        α_r [-].

    Returns
    -------
    float or ndarray
        F_SE [N].

    Examples
    --------
    >>> round(hysteresis_rolling_force(10.0, 50e-6, 2.5e-3, 0.01) * 1e6, 3)  # µN: 3·b·α·Q/(16·Dw/2)
    750.0
    """
    check_nonnegative("load", load, "N")
    check_nonnegative("semi_minor_axis", semi_minor_axis, "m")
    check_positive("ball_diameter", ball_diameter, "m")
    check_range("loss_factor", loss_factor, 0.0, 1.0)
    return hysteresis_force(load, semi_minor_axis, ball_diameter, loss_factor)


def spin_moment(load, semi_major_axis, e_integral, friction_coefficient):
    """Spin friction moment of one contact about its normal, M'_K = (3/8)·μ·Q·a·E(e) [N·m]
    (Yu 2017 eq 6; Harris & Kotzalas 2007). load Q [N], semi_major_axis a [m], e_integral E(e)
    [-] the complete elliptic integral of the second kind, friction_coefficient μ [-].

    Returns
    -------
    float or ndarray
        M' [N·m].

    Examples
    --------
    >>> round(spin_moment(10.0, 2e-4, 1.0, 0.1) * 1e6, 6)  # µN·m: (3/8)·0.1·10 N·0.2 mm
    75.0
    """
    check_nonnegative("load", load, "N")
    check_nonnegative("semi_major_axis", semi_major_axis, "m")
    check_range("e_integral", e_integral, 1.0, np.pi / 2)
    check_nonnegative("friction_coefficient", friction_coefficient)
    return contact_spin_moment(load, semi_major_axis, e_integral, friction_coefficient)


def heathcote_sliding_force(load, semi_major_axis, ball_diameter, groove_radius, friction):
    """Rolling resistance of one contact from differential (Heathcote) sliding [N]:
    F_d = C_H·μ·Q·a²/(R_c·Dw),  C_H = (3/4)∫(1−u²)|u0² − u²|du ≈ 0.161,
    R_c = 2·r·Dw/(2·r + Dw) the radius of the deformed contact surface (harmonic mean of ball
    and groove radii). For a close groove (R_c → Dw/2) this is Johnson's (1985, ch. 8)
    F ≈ 0.08·μ·Q·(a/R)², R = Dw/2. Reconstructs Ning's M_di, M_do (equations missing from
    the received text).

    load Q [N], semi_major_axis a [m], ball_diameter Dw [m], groove_radius r [m],
    friction μ [-].

    Parameters
    ----------
    load : float or array_like
        Q [N].
    semi_major_axis : float or array_like
        a [m].
    ball_diameter : float or array_like
        Dw [m].
    groove_radius : float or array_like
        r [m].
    friction : float
        μ [-].

    Returns
    -------
    float or ndarray
        F_d [N].

    Examples
    --------
    >>> f = heathcote_sliding_force(10.0, 2e-4, 2.5e-3, 1.3e-3, 0.1)
    >>> round(f * 1e3, 4)  # mN
    2.023
    """
    check_nonnegative("load", load, "N")
    check_nonnegative("semi_major_axis", semi_major_axis, "m")
    check_positive("ball_diameter", ball_diameter, "m")
    check_positive("groove_radius", groove_radius, "m")
    check_nonnegative("friction", friction)
    return heathcote_force(load, semi_major_axis, ball_diameter, groove_radius, friction)


def palmgren_viscous_torque(kinematic_viscosity, speed, pitch_diameter, s0):
    """Viscous friction torque of one grease-lubricated bearing [N·m] (Palmgren; Yu 2017 eq 8):

        M_L = 1e-7·s0·(ν0·n)^(2/3)·dm³  [N·mm]   for ν0·n ≥ 2000,
        M_L = 160e-7·s0·dm³             [N·mm]   for ν0·n < 2000,

    ν0 in cSt, n in rpm, dm in mm (the equation's own units; converted here). The printed 160
    is 2000^(2/3) = 158.7 rounded up, which makes eq 8 jump by 0.8 % at ν0·n = 2000; the
    continuous form (max(ν0·n, 2000))^(2/3) is used so that the torque has no step in speed
    or temperature.

    kinematic_viscosity ν0 [m²/s], speed ω [rad/s] (sign ignored), pitch_diameter dm [m],
    s0 [-] the bearing/lubrication factor (f0 in Palmgren's notation).

    Returns
    -------
    float or ndarray
        M_L [N·m].

    Examples
    --------
    >>> m = palmgren_viscous_torque(100e-6, 2 * math.pi, 21.5e-3, 1.0)  # 100 cSt, 60 rpm
    >>> round(m * 1e3, 6)  # N·mm: 1e-7·s0·(ν·n)^(2/3)·dm³ with ν·n = 100 cSt × 60 rpm
    0.328158
    """
    check_nonnegative("kinematic_viscosity", kinematic_viscosity, "m²/s")
    check_finite("speed", speed, "rad/s")
    check_positive("pitch_diameter", pitch_diameter, "m")
    check_nonnegative("s0", s0)
    return palmgren_torque(kinematic_viscosity, speed, pitch_diameter, s0)


def regularised_friction_torque(
    speed, running_torque, breakaway_excess, regularisation_speed, stribeck_speed
):
    """Friction torque opposing rotation, smooth through zero speed [N·m]:

        M(ω) = tanh(ω/ω_r) · (M_run(|ω|) + ΔM_break·exp(−|ω|/ω_s))

    speed ω [rad/s] (signed), running_torque M_run [N·m] at |ω|, breakaway_excess
    ΔM_break = breakaway − running-at-rest [N·m] ≥ 0, regularisation_speed ω_r [rad/s] (width
    of the smooth sign), stribeck_speed ω_s [rad/s] (decay of the static excess). The sign
    regularisation and Stribeck decay follow Andersson, Söderberg & Björklund (2007),
    Tribology International 40:580. Signed like ``speed``.

    Returns
    -------
    float or ndarray
        M [N·m], signed like ``speed``.

    Examples
    --------
    >>> regularised_friction_torque(0.0, 1e-3, 5e-4, 1e-3, 1e-2)  # N·m: nothing at rest
    0.0
    >>> round(regularised_friction_torque(-1.0, 1e-3, 5e-4, 1e-3, 1e-2) * 1e3, 6)  # N·mm
    -1.0
    """
    check_finite("speed", speed, "rad/s")
    check_nonnegative("running_torque", running_torque, "N·m")
    check_nonnegative("breakaway_excess", breakaway_excess, "N·m")
    check_positive("regularisation_speed", regularisation_speed, "rad/s")
    check_positive("stribeck_speed", stribeck_speed, "rad/s")
    return regularised_torque(
        speed, running_torque, breakaway_excess, regularisation_speed, stribeck_speed
    )


@dataclass(frozen=True)
class FrictionCoefficients:
    """Coefficients of the friction model.

    Attributes
    ----------
    hysteresis_loss : α_r, elastic hysteresis loss factor [-] (Yu eq 1; < 1 % for metals)
    sliding_friction : μ, coefficient of sliding friction in spin and differential sliding [-]
    static_friction_ratio : μ_static/μ ≥ 1 for the breakaway torque [-]
    palmgren_s0 : s0 of Yu eq 8 [-] (grease only)
    provenance : ((field, source), ...)
    """

    hysteresis_loss: float = 0.007
    sliding_friction: float = 0.05
    static_friction_ratio: float = 1.2
    palmgren_s0: float = 1.0
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_range("hysteresis_loss", self.hysteresis_loss, 0.0, 1.0)
        check_range("sliding_friction", self.sliding_friction, 0.0, 2.0)
        check_range("static_friction_ratio", self.static_friction_ratio, 1.0, 10.0)
        check_nonnegative("palmgren_s0", self.palmgren_s0)

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")


@dataclass(slots=True)
class BallSetTorques:
    """Speed-independent friction torques of one bearing's ball set [N·m] (arrays).

    hysteresis (Yu eq 3), spin (Yu eq 7 / Ning inner-race spin), sliding (Heathcote, Ning),
    inner_ring, outer_ring: the same total split by race (Ning Fig 10a).
    """

    hysteresis: np.ndarray
    spin: np.ndarray
    sliding: np.ndarray
    inner_ring: np.ndarray
    outer_ring: np.ndarray

    @property
    def total(self):
        return self.hysteresis + self.spin + self.sliding


def ball_torque_terms(
    load,
    inner,
    outer,
    r_in,
    r_out,
    sin_abs,
    ball_diameter,
    groove_radii,
    coefficients,
    solid,
    differential_sliding,
):
    """Friction torques of single balls about the bearing axis [N·m], elementwise on floats
    or arrays (Yu 2017 eq 1–3, 5–7; Ning, reconstructed): the one place these equations are
    written, for :func:`ball_set_torques` and the per-step continuation.

    Parameters
    ----------
    load : Q [N]
    inner, outer : (a, b, E(e)) of the inner / outer contact: semi-axes [m] at Q and the
        complete elliptic integral of the second kind [-]
    r_in, r_out : race contact radii (dm ∓ Dw·cos α)/2 [m] (Yu eq 2)
    sin_abs : |sin α| [-]
    ball_diameter : Dw [m]
    groove_radii : (r_i, r_o) [m]
    coefficients : :class:`FrictionCoefficients` (α_r, μ)
    solid : outer-race control (spin at the inner race only) instead of Yu eq 7's larger race
    differential_sliding : include Heathcote sliding

    Returns
    -------
    tuple
        (hysteresis inner, hysteresis outer, sliding inner, sliding outer, spin inner,
        spin outer) [N·m].

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> from servofmu.physics.contact.equilibrium import axial_state
    >>> g = catalog.bearing("71803").race_geometry()
    >>> s = axial_state(g, 70e-6)  # one ball of the 71803 under 59 N
    >>> q, alpha = float(s.ball_load), float(s.contact_angle)
    >>> c3 = q ** (1 / 3)  # the semi-axes grow as Q^(1/3)
    >>> inner = (float(s.inner.a_coef) * c3, float(s.inner.b_coef) * c3, float(s.inner.e_integral))
    >>> outer = (float(s.outer.a_coef) * c3, float(s.outer.b_coef) * c3, float(s.outer.e_integral))
    >>> r_in = race_contact_radius(g.pitch_diameter, g.ball_diameter, alpha, "inner")
    >>> r_out = race_contact_radius(g.pitch_diameter, g.ball_diameter, alpha, "outer")
    >>> terms = ball_torque_terms(q, inner, outer, r_in, r_out, math.sin(alpha), g.ball_diameter,
    ...                          (g.inner_groove_radius, g.outer_groove_radius),
    ...                          FrictionCoefficients(), False, False)
    >>> [round(float(t) * 1e6, 4) for t in terms]  # µN·m: one ball; Yu eq 7 spins one race
    [4.1457, 5.3362, 0.0, 0.0, 0.0, 11.8902]
    """
    (a_i, b_i, e_i), (a_o, b_o, e_o) = inner, outer
    dw = ball_diameter
    alpha_r, mu = coefficients.hysteresis_loss, coefficients.sliding_friction
    hyst_i = hysteresis_force(load, b_i, dw, alpha_r) * r_in
    hyst_o = hysteresis_force(load, b_o, dw, alpha_r) * r_out
    if differential_sliding:
        slide_i = heathcote_force(load, a_i, dw, groove_radii[0], mu) * r_in
        slide_o = heathcote_force(load, a_o, dw, groove_radii[1], mu) * r_out
    else:
        slide_i = slide_o = 0.0 * load
    spin_i = contact_spin_moment(load, a_i, e_i, mu) * sin_abs
    spin_o = contact_spin_moment(load, a_o, e_o, mu) * sin_abs
    if solid:
        spin_o = 0.0 * spin_o
    else:  # Yu eq 7: the race with the larger spin moment spins
        inner_spins = spin_i >= spin_o
        spin_i, spin_o = spin_i * inner_spins, spin_o * (1 - inner_spins)
    return hyst_i, hyst_o, slide_i, slide_o, spin_i, spin_o


def ball_set_torques(
    load,
    contact_angle,
    inner,
    outer,
    pitch_diameter,
    ball_diameter,
    inner_groove_radius,
    outer_groove_radius,
    coefficients: FrictionCoefficients,
    lubrication: str,
    differential_sliding: bool,
) -> BallSetTorques:
    """Friction torques about the bearing axis of one bearing's balls (sum over the trailing
    ball axis).

    Parameters
    ----------
    load : Q_j [N], shape S + (Z,)
    contact_angle : α_j [rad], same shape
    inner, outer : :class:`hertz.ContactConstants` of the inner / outer contacts (same shape)
    pitch_diameter, ball_diameter, inner_groove_radius, outer_groove_radius : dm, Dw, r_i, r_o
        [m], shape S (broadcast against S + (Z,) by a trailing axis)
    coefficients : α_r, μ (see :class:`FrictionCoefficients`)
    lubrication : "grease" (Yu eq 7: spin at the race with the larger spin moment) or "solid"
        (Ning: outer-race control, spin at the inner race)
    differential_sliding : include Heathcote sliding (Ning); Yu eq 9 has no such term

    Yu 2017 eq 1–3, 5–7; Ning (reconstructed, see module docstring).

    Returns
    -------
    BallSetTorques
        hysteresis, spin, sliding, inner_ring, outer_ring [N·m] (summed over the balls).

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> from servofmu.physics.contact.equilibrium import axial_state
    >>> g = catalog.bearing("71803").race_geometry()
    >>> s = axial_state(g, 70e-6)  # one ball of the 71803 under 59 N
    >>> z = g.n_balls
    >>> t = ball_set_torques(np.full(z, float(s.ball_load)), np.full(z, float(s.contact_angle)),
    ...                      s.inner, s.outer, g.pitch_diameter, g.ball_diameter,
    ...                      g.inner_groove_radius, g.outer_groove_radius,
    ...                      FrictionCoefficients(), "grease", False)
    >>> round(float(t.hysteresis) * 1e3, 5), round(float(t.spin) * 1e3, 5)  # N·mm
    (0.14223, 0.17835)
    """

    def g(x):
        return np.asarray(x)[..., None]

    dm, dw = g(pitch_diameter), g(ball_diameter)
    a_i, b_i = inner.semi_axes(load)
    a_o, b_o = outer.semi_axes(load)
    hyst_i, hyst_o, slide_i, slide_o, spin_i, spin_o = ball_torque_terms(
        load,
        (a_i, b_i, inner.e_integral),
        (a_o, b_o, outer.e_integral),
        _race_radius(dm, dw, contact_angle, "inner"),
        _race_radius(dm, dw, contact_angle, "outer"),
        np.abs(np.sin(contact_angle)),
        dw,
        (g(inner_groove_radius), g(outer_groove_radius)),
        coefficients,
        lubrication == "solid",
        differential_sliding,
    )
    inner_ring = np.sum(hyst_i + slide_i + spin_i, axis=-1)
    outer_ring = np.sum(hyst_o + slide_o + spin_o, axis=-1)
    return BallSetTorques(
        hysteresis=np.sum(hyst_i + hyst_o, axis=-1),
        spin=np.sum(spin_i + spin_o, axis=-1),
        sliding=np.sum(slide_i + slide_o, axis=-1),
        inner_ring=inner_ring,
        outer_ring=outer_ring,
    )

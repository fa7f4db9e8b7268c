r"""Hydrodynamic (EHL) rolling resistance of lubricated ball–race contacts, per contact, and
the torque it costs a ball bearing.

Per contact (Biboulet & Houpert 2010, "Hydrodynamic force and moment in pure rolling
lubricated contacts. Part 2: point contacts", Proc. IMechE Part J 224:777–787, eq 2, 14, 31,
32), the rolling force

.. math::

   F_R = E'\,R_x^2\,\tilde{T}^*, \qquad
   \tilde{T}^* = \frac{2a}{R_x}\left[\frac{0.77\,\beta^{-1/3}\kappa^{0.12}U^{-1/12}
   - 1.8\,\beta^{-1/4}}{1 + M/6.6} + 1.8\,\beta^{-1/4}\right] U^{3/4}

with the dimensionless speed, load and their combination

.. math::

   U = \frac{2\,\eta_0\,u_m}{E' R_x}, \qquad W = \frac{w}{E' R_x^2}, \qquad
   M = \frac{\beta^{1/4}\,\kappa\,W}{U^{3/4}},

and the geometry

.. math::

   \beta = \frac{4}{\pi}\,\frac{\mathcal{E}}{1 + R_x/R_z}, \qquad \kappa = \frac{b}{a},
   \qquad \frac{2}{E'} = \frac{1 - \nu_1^2}{E_1} + \frac{1 - \nu_2^2}{E_2}:

a smooth, fully flooded, isothermal fit from the isoviscous-rigid (IVR, M → 0) to the EHL
(M → ∞) asymptote; a, b the Hertz semi-axes across and along the rolling direction,
:math:`\mathcal{E}` the complete elliptic integral of the second kind of the contact ellipse,
:math:`u_m` the mean of the two surface speeds relative to the contact. The force acts on both
surfaces against their motion, so a contact dissipates :math:`2 F_R u_m`.

Bearing torque (power balance): with the outer ring fixed and no spin, both contacts of a
ball roll at :math:`u_m = (d_m/4)(1 - \gamma^2)\,|\omega|`, :math:`\gamma = D_w\cos\alpha/d_m`,
so the torque about the axis is

.. math::

   M = \sum_\mathrm{balls}\;\sum_\mathrm{inner,\,outer} \frac{2 F_R u_m}{|\omega|}
     = \sum F_R\,\frac{d_m (1 - \gamma^2)}{2}.

For a thrust rig (α = 90°, race radius r = dm/2) this is :math:`6 r F_R` for three balls,
the expression Bălan et al. (2015, Lubricants 3:222, eq 14) use.

Bălan et al. (2015, eq 1–7) print a simplified version of the same fit, with
:math:`U = \eta_0 v/(E^* R_x)`, v the mean speed, and coefficients 2.9766 and 7.5826 that
absorb Biboulet's factor 2 in U: with the same :math:`u_m`, the two agree within about 10 %,
two parameterisations of one fit. This module follows the original.

No thermal (inlet shear) or starvation reduction is applied to the EHL model: Biboulet &
Houpert's fit is for a fully flooded, isothermal contact, and SKF's factors
:math:`\phi_\mathrm{ish}` and :math:`\phi_\mathrm{rs}` are empirical for a bearing's total
rolling moment, not for one contact. For scale, on the gimbal's 71803 at 10 °/s and −40 °C
(Krytox 143AA, ν = 4.1e4 mm²/s) :math:`\phi_\mathrm{ish}` is 1 − 1.6e-4 (inlet heating is
negligible at servo speeds), while SKF's replenishment factor for grease is 0.92 there and
0.0019 at −60 °C (ν extrapolated to 2.9e6 mm²/s): a starved, slowly turning grease-packed
contact would have less rolling torque than this model gives, by an amount no cited
per-contact law gives.
"""

from __future__ import annotations

import math

import numpy as np

from .._checks import check_finite, check_nonnegative, check_positive, check_range
from ..contact.hertz import contact_constants


def _scalar(x):
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def entrainment_speed(pitch_diameter, ball_diameter, contact_angle, speed):
    """Mean rolling (entrainment) speed of both ball–race contacts, outer ring fixed, no spin:
    u_m = (dm/4)·(1 − γ²)·|ω|, γ = Dw·cos α/dm [m/s] (epicyclic ball kinematics; Harris &
    Kotzalas 2007, *Essential Concepts of Bearing Technology*, cage and ball speeds). For a
    thrust bearing (α = 90°) the ball centre moves at half the race speed, as in Bălan et al.
    2015 eq 8, and u_m = |ω|·r/2.

    Parameters
    ----------
    pitch_diameter : dm [m]
    ball_diameter : Dw [m]
    contact_angle : α [rad]
    speed : ω [rad/s] of the rotating ring relative to the fixed one (sign ignored)

    Returns
    -------
    u_m [m/s]

    >>> round(entrainment_speed(0.036, 0.003, 3.141592653589793 / 2, 6.283185307179586), 6)
    0.056549
    """
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    dw = check_positive("ball_diameter", ball_diameter, "m")
    alpha = check_finite("contact_angle", contact_angle, "rad")
    w = check_finite("speed", speed, "rad/s")
    gamma = dw * np.cos(alpha) / dm
    return _scalar(0.25 * dm * (1.0 - gamma**2) * np.abs(w))


def rolling_radii(pitch_diameter, ball_diameter, contact_angle, groove_radius, race):
    """Reduced radii of a ball–groove contact [m]: Rx along the rolling direction and Rz
    across it (Harris & Kotzalas 2007, ch. 2; Biboulet & Houpert 2010 eq 1):

        Rx = Dw·(1 ∓ γ)/2  (− inner, + outer),  γ = Dw·cos α/dm,
        Rz = r·Dw/(2·r − Dw)  (r the groove radius, > Dw/2).

    Parameters
    ----------
    pitch_diameter : dm [m]
    ball_diameter : Dw [m]
    contact_angle : α [rad]
    groove_radius : r [m], > Dw/2
    race : "inner" or "outer"

    Returns
    -------
    (Rx, Rz) [m]

    >>> rx, rz = rolling_radii(0.036, 0.007938, 3.141592653589793 / 2, 0.00416, "inner")
    >>> round(rz / rx, 2)  # the k ratio Bălan et al. 2015 §4.5 quote: 21.78
    21.78
    """
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    dw = check_positive("ball_diameter", ball_diameter, "m")
    alpha = check_finite("contact_angle", contact_angle, "rad")
    r = check_positive("groove_radius", groove_radius, "m")
    if np.any(np.asarray(r) <= 0.5 * np.asarray(dw)):
        raise ValueError(
            f"groove_radius = {groove_radius!r} m must exceed half the ball diameter "
            f"({0.5 * np.asarray(dw)!r} m)"
        )
    if race not in ("inner", "outer"):
        raise ValueError(f"race = {race!r} is not one of ['inner', 'outer']")
    gamma = dw * np.cos(alpha) / dm
    sign = -1.0 if race == "inner" else 1.0
    return _scalar(0.5 * dw * (1.0 + sign * gamma)), _scalar(r * dw / (2.0 * r - dw))


def hydrodynamic_rolling_force(
    load, mean_speed, dynamic_viscosity, rolling_radius, transverse_radius, reduced_modulus
):
    """Hydrodynamic rolling force of one lubricated point contact F_R [N], fully flooded and
    isothermal, IVR to EHL (Biboulet & Houpert 2010 eq 32 with eq 14 and 31; see the module
    docstring).

    Parameters
    ----------
    load : normal load w [N], ≥ 0 (0 gives 0)
    mean_speed : u_m [m/s], mean of the two surface speeds relative to the contact
    dynamic_viscosity : η0 [Pa·s] at the inlet temperature and ambient pressure
    rolling_radius : Rx [m], reduced radius along the rolling direction
    transverse_radius : Rz [m], reduced radius across it (≥ Rx: a contact ellipse wide across
        the rolling direction, as in ball bearings)
    reduced_modulus : E' [Pa], 2/E' = (1 − ν1²)/E1 + (1 − ν2²)/E2 (steel–steel ≈ 2.3e11)

    Returns
    -------
    F_R [N]

    >>> round(hydrodynamic_rolling_force(0.633, 0.0565, 0.05, 1.5e-3, 2.346e-3, 2.3e11) * 1e6, 1)
    255.9
    """
    w = np.asarray(check_nonnegative("load", load, "N"), dtype=float)
    u = np.asarray(check_nonnegative("mean_speed", mean_speed, "m/s"), dtype=float)
    eta = check_positive("dynamic_viscosity", dynamic_viscosity, "Pa·s")
    rx = np.asarray(check_positive("rolling_radius", rolling_radius, "m"), dtype=float)
    rz = np.asarray(check_positive("transverse_radius", transverse_radius, "m"), dtype=float)
    e_red = check_positive("reduced_modulus", reduced_modulus, "Pa")
    if np.any(rz < rx):
        raise ValueError(
            f"transverse_radius = {transverse_radius!r} m must be ≥ rolling_radius = "
            f"{rolling_radius!r} m (contact ellipse wide across the rolling direction)"
        )
    rho = 1.0 / rx + 1.0 / rz
    c = contact_constants(rho, (1.0 / rx - 1.0 / rz) / rho, 2.0 / e_red)
    a = c.semi_axes(w)[0]
    terms = _force_terms(w, a, c.ellipticity, c.e_integral, rx, rz, e_red)
    with np.errstate(divide="ignore", invalid="ignore"):
        force = 2.0 * a * e_red * rx * _force_factor(*terms, 2.0 * eta * u / (e_red * rx))
    force = np.where((w > 0.0) & (u > 0.0), force, 0.0)
    return float(force) if force.ndim == 0 else force


# Biboulet & Houpert's fit split into what depends on the contact (load, ellipse, radii) and
# what depends on the speed, elementwise on floats (the per-step path) or arrays.
def _force_terms(load, semi_major_axis, ellipticity, e_integral, rx, rz, e_red):
    """(0.77·β^(−1/3)·κ^0.12, 1.8·β^(−1/4), β^(1/4)·κ·W) of one contact: M = (last)/U^(3/4)
    (eq 14, 31, 32; κ = b/a = 1/ellipticity, W = w/(E'·Rx²))."""
    beta = (4.0 / math.pi) * e_integral / (1.0 + rx / rz)
    kappa = 1.0 / ellipticity
    b4 = beta**0.25
    return (
        0.77 * beta ** (-1.0 / 3.0) * kappa**0.12,
        1.8 / b4,
        b4 * kappa * load / (e_red * rx * rx),
    )


def _force_factor(ivr, ehl, m0, u):
    """T̃*·Rx/(2a) of eq 32 at the dimensionless speed U, from :func:`_force_terms`:
    [(ivr·U^(−1/12) − ehl)/(1 + M/6.6) + ehl]·U^(3/4), M = m0/U^(3/4), written as
    (ivr·U^(2/3) − ehl·V)·V/(V + m0/6.6) + ehl·V with V = U^(3/4) (finite at U = 0)."""
    v = u**0.75
    return (ivr * u ** (2.0 / 3.0) - ehl * v) * v / (v + m0 / 6.6) + ehl * v


def contact_rolling_terms(
    load,
    semi_major_axis,
    ellipticity,
    e_integral,
    gamma,
    ball_diameter,
    pitch_diameter,
    inverse_conformity,
    compliance,
    dynamic_viscosity,
    inner,
):
    """Speed-independent terms of one ball–race contact's hydrodynamic rolling torque about
    the bearing axis (Biboulet & Houpert 2010 eq 32; power balance of the module docstring),
    from the contact's Hertz data: with them :func:`contact_rolling_torque` gives the torque
    at any speed. Elementwise on floats or arrays; a contact must carry load (Q > 0).

    Parameters
    ----------
    load : Q [N], > 0
    semi_major_axis : a [m] (across the rolling direction)
    ellipticity : k = a/b [-]
    e_integral : E(m) [-] of the contact ellipse
    gamma : γ = Dw·cos α/dm [-]
    ball_diameter, pitch_diameter : Dw, dm [m]
    inverse_conformity : 1/f = Dw/r [-] of the groove (r the groove radius)
    compliance : η = (1 − ν1²)/E1 + (1 − ν2²)/E2 [1/Pa] (E' = 2/η)
    dynamic_viscosity : η0 [Pa·s] (0: a dry film, no rolling torque)
    inner : True for the inner race (Rx = Dw·(1 − γ)/2), False for the outer (1 + γ)

    Returns
    -------
    tuple
        (2a·E'·Rx·dm·(1 − γ²)/2 [N·m], ivr [-], ehl [-], m0 [-], U per rad/s [s]):
        torque = first × :func:`_force_factor` (ivr, ehl, m0, U), U = last·|ω|.

    >>> t = contact_rolling_terms(1.0, 1e-4, 8.0, 1.05, 0.1, 0.003, 0.03, 1 / 0.53, 1e-11,
    ...                           0.05, True)
    >>> round(contact_rolling_torque(*t, 1.0) * 1e9, 3)  # nN·m at 1 rad/s
    3119.009
    """
    e_red = 2.0 / compliance
    rx = 0.5 * ball_diameter * ((1.0 - gamma) if inner else (1.0 + gamma))
    rz = ball_diameter / (2.0 - inverse_conformity)
    arm = 0.5 * pitch_diameter * (1.0 - gamma * gamma)
    ivr, ehl, m0 = _force_terms(load, semi_major_axis, ellipticity, e_integral, rx, rz, e_red)
    return (
        2.0 * semi_major_axis * e_red * rx * arm,
        ivr,
        ehl,
        m0,
        dynamic_viscosity * arm / (e_red * rx),
    )


def contact_rolling_torque(scale, ivr, ehl, m0, u_per_speed, speed):
    """Hydrodynamic rolling torque of one contact about the bearing axis [N·m] at speed ω
    [rad/s] (sign ignored) from :func:`contact_rolling_terms`: F_R·dm·(1 − γ²)/2, with
    U = 2·η0·u_m/(E'·Rx) and u_m = (dm/4)·(1 − γ²)·|ω|. Elementwise on floats or arrays.

    Parameters
    ----------
    scale, ivr, ehl, m0, u_per_speed : the contact's terms from :func:`contact_rolling_terms`
        (``scale`` [N·m], ``u_per_speed`` [s/rad], the others dimensionless)
    speed : ω [rad/s] (sign ignored)

    Returns
    -------
    float or ndarray
        The contact's rolling torque [N·m].

    Examples
    --------
    >>> contact_rolling_torque(1.0, 1.0, 1.0, 1.0, 0.0, 5.0)  # dry: U = 0
    0.0
    """
    return scale * _force_factor(ivr, ehl, m0, u_per_speed * abs(speed))


def ehl_rolling_torque(
    ball_load_inner,
    ball_load_outer,
    contact_angle,
    pitch_diameter,
    ball_diameter,
    inner_groove_radius,
    outer_groove_radius,
    dynamic_viscosity,
    speed,
    reduced_modulus,
):
    """Torque about the bearing axis from the hydrodynamic rolling forces of every ball–race
    contact [N·m]: M = Σ_j [F_R,i + F_R,o]·dm·(1 − γj²)/2 (power balance, module docstring),
    outer ring fixed, fully flooded and isothermal (multiply by SKF's φish·φrs, or a
    starvation factor, outside if wanted). The inner and outer contacts of ball j share αj.

    Parameters
    ----------
    ball_load_inner, ball_load_outer : Qij, Qoj [N], shape S + (Z,) (ball index last)
    contact_angle : αj [rad], same shape
    pitch_diameter, ball_diameter : dm, Dw [m] (scalars or shape S)
    inner_groove_radius, outer_groove_radius : ri, ro [m]
    dynamic_viscosity : η0 [Pa·s] of the oil or the grease's base oil (ν·ρ)
    speed : ω [rad/s] (sign ignored)
    reduced_modulus : E' [Pa] (= 2/compliance of :class:`geometry.RaceGeometry`)

    Returns
    -------
    M [N·m], shape S

    >>> import numpy as np
    >>> q = np.full(3, 0.633)
    >>> m = ehl_rolling_torque(q, q, np.full(3, np.pi / 2), 0.036, 0.003, 0.00416, 0.00416,
    ...                        0.05, 2 * np.pi, 2.3e11)
    >>> round(float(m) * 1e6, 2)  # 6·r·F_R of Bălan et al. 2015 eq 14, µN·m
    27.66
    """
    qi = np.asarray(check_nonnegative("ball_load_inner", ball_load_inner, "N"), dtype=float)
    qo = np.asarray(check_nonnegative("ball_load_outer", ball_load_outer, "N"), dtype=float)
    alpha = np.asarray(check_finite("contact_angle", contact_angle, "rad"), dtype=float)

    def g(x):
        return np.asarray(x, dtype=float)[..., None]

    dm, dw = g(pitch_diameter), g(ball_diameter)
    u = entrainment_speed(dm, dw, alpha, speed)
    total = 0.0
    for q, r, race in ((qi, inner_groove_radius, "inner"), (qo, outer_groove_radius, "outer")):
        rx, rz = rolling_radii(dm, dw, alpha, g(r), race)
        total = total + hydrodynamic_rolling_force(q, u, dynamic_viscosity, rx, rz, reduced_modulus)
    gamma = dw * np.cos(alpha) / dm
    out = np.sum(total * 0.5 * dm * (1.0 - gamma**2), axis=-1)
    return float(out) if np.ndim(out) == 0 else out


def dynamic_viscosity(kinematic_viscosity, density):
    """Dynamic viscosity η = ν·ρ [Pa·s].

    Parameters
    ----------
    kinematic_viscosity : ν [m²/s]
    density : ρ [kg/m³]

    Returns
    -------
    η [Pa·s]

    >>> round(dynamic_viscosity(57.5e-6, 870.0), 4)
    0.05
    """
    nu = check_nonnegative("kinematic_viscosity", kinematic_viscosity, "m²/s")
    rho = check_range("density", density, 100.0, 5000.0, unit="kg/m³")
    return nu * rho


def ehl_torque(terms, speed):
    """Σ over the contacts of :func:`.friction.ehl_per_contact.contact_rolling_torque` [N·m] at ω
    [rad/s]. ``terms`` = (scale, ivr, ehl, m0, U per rad/s): tuples of floats (one per loaded
    contact, the per-step path) or arrays with a trailing contact axis (the exact path).

    Parameters
    ----------
    terms : tuple
        The contacts' terms.
    speed : float or ndarray
        ω [rad/s].

    Returns
    -------
    float or ndarray
        [N·m].

    Examples
    --------
    >>> ehl_torque(((1.0,), (1.0,), (1.0,), (1.0,), (0.0,)), 5.0)  # dry contact: U = 0
    0.0
    """
    scale, ivr, ehl, m0, u = terms
    if isinstance(scale, np.ndarray):
        return np.sum(contact_rolling_torque(scale, ivr, ehl, m0, u, speed), axis=-1)
    total = 0.0
    for k in range(len(scale)):
        total += contact_rolling_torque(scale[k], ivr[k], ehl[k], m0[k], u[k], speed)
    return total


def running_terms(pair, kinematic_viscosity, pitch_diameter, rolling, speed):
    """The friction model's speed terms (:mod:`.friction.registry`): (:func:`ehl_torque` of
    the contacts' terms ``rolling`` at ω [rad/s], None) [N·m]; ν and dm are in the terms.

    Returns
    -------
    tuple
        (rolling torque [N·m], None: no sliding torque of its own).

    Examples
    --------
    >>> running_terms(None, 1e-4, 0.02, ((1.0,), (1.0,), (1.0,), (1.0,), (0.0,)), 5.0)
    (0.0, None)
    """
    return ehl_torque(rolling, speed), None


#: Names :mod:`.models` offered before this model had a module of its own: importable from it
#: still (its ``__getattr__``).
FORMER_NAMES = ("ehl_torque",)

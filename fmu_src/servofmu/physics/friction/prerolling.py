r"""Pre-rolling friction of a ball-bearing pair: Dahl's model of the torque of small motions
and reversals, with its rest stiffness from Mindlin's no-slip stiffness of the contacts.

**Dahl's model** (Dahl 1976, AIAA J. 14(12):1675, eq. 1 with the exponent of his 1968
report): over the relative angle θ of the rings the friction torque T follows

.. math::

   \frac{dT}{d\theta} = \sigma_0\,\Bigl|1 - \frac{T}{T_c}\,\mathrm{sgn}\,\omega\Bigr|^{i}
   \,\mathrm{sgn}\Bigl(1 - \frac{T}{T_c}\,\mathrm{sgn}\,\omega\Bigr),

σ₀ the rest slope [N·m/rad], T_c the sliding (Coulomb) torque [N·m], i ≥ 0 the exponent.
With s = sgn ω and T_c held, y = 1 − s·T/T_c and x = |Δθ| give dy/dx = −k·|y|^i·sgn y,
k = σ₀/T_c, which integrates in closed form (separation of variables, y keeps its sign):

.. math::

   i = 1:&\quad y = y_0\,e^{-kx},\\
   i > 1:&\quad |y| = \bigl(|y_0|^{1-i} + (i-1)\,k\,x\bigr)^{-1/(i-1)},\\
   i < 1:&\quad |y| = \max\bigl(0,\ |y_0|^{1-i} - (1-i)\,k\,x\bigr)^{1/(1-i)}.

:func:`~servofmu.physics.kernels.friction.dahl_torque_step` uses these: a step over which the
sign of the speed and T_c are held is exact for every i (to rounding), not integrated to a
tolerance. From rest (T = 0) in one direction, i = 1 gives Dahl's loop
T = T_c·(1 − e^(−σ₀θ/T_c)) (:func:`dahl_loop_torque`). The stress the contacts hold never
exceeds what they transmit sliding: |T| ≤ T_c always (a T_c that falls below |T|, e.g. as the
temperature changes, takes T to ±T_c at once: the contacts slip), so y stays in [0, 2].

**The rest stiffness from the contacts** (:func:`contact_rest_stiffness`): before a ball
rolls, the rings' relative rotation is taken up by the elastic tangential deflection of its
two contacts. Mindlin's no-slip tangential stiffness of a Hertz contact (Mindlin 1949,
J. Appl. Mech. 16:259; Johnson 1985, *Contact Mechanics*, §7.2, the compliance
δ = Q·((2 − ν₁)/G₁ + (2 − ν₂)/G₂)/(8a) of a circular contact of radius a) is

.. math::

   k_t = 8\,G^*\,a, \qquad \frac{1}{G^*} = \frac{2-\nu_1}{G_1} + \frac{2-\nu_2}{G_2},

with a the radius of the circle of the same area as the contact ellipse, a = √(a·b)
(Johnson 1985, §4.2: the equivalent radius c = (ab)^½ of an elliptical contact). With the
ball rigid and not rolling, the shaft's rotation θ moves the inner contact by r_i·θ, taken up
by the inner and outer contacts in series (the same tangential force Q through both), and
the torque on the shaft is Q·r_i:

.. math::

   \sigma_0 = \sum_{\text{bearings}} \sum_{\text{balls}}
   \frac{k_{t,i}\,k_{t,o}}{k_{t,i} + k_{t,o}}\; r_i^2,
   \qquad r_i = \tfrac12\,(d_m - D_w\cos\alpha),

at the operating point (thermal state, ball loads and contact angles). A ball without load
adds nothing. The ball's rolling is what pre-rolling ends, so this σ₀ is the stiffness of the
very first micro-radians: an upper bound on a measured rest slope, which also holds the
compliance of cage, lubricant film and seats.
"""

from __future__ import annotations

import numpy as np

from .._checks import check_finite, check_nonnegative, check_positive
from ..kernels.friction import (  # the equations, shared with the per-step path
    dahl_torque_step as dahl_torque_step,
)
from ..kernels.friction import (
    stribeck_torque as stribeck_torque,
)

#: prerolling_model: the pre-rolling models by number (0: none, the regularised sign).
MODELS = ("none", "dahl")
NONE, DAHL = 0, 1
#: Valid range of Dahl's exponent i [-].
EXPONENT_RANGE = (0.0, 10.0)
#: Valid range of a given rest stiffness σ₀ [N·m/rad] (0: derived from the contacts).
STIFFNESS_RANGE = (0.0, 1.0e9)


# ------------------------------------------------------------------ Dahl's model
def dahl_loop_torque(theta, coulomb, sigma0, theta_reversal=None, torque_reversal=0.0):
    """Dahl's loop for i = 1 (Dahl 1976, AIAA J. 14:1675, eq. 1 integrated): from rest,
    T = T_c·(1 − e^(−σ₀θ/T_c)) for θ ≥ 0; after a reversal at (θ_r, T_r) to decreasing θ,
    T = −T_c + (T_r + T_c)·e^(−σ₀(θ_r − θ)/T_c).

    Parameters
    ----------
    theta : θ [rad] (float or array), ≥ 0 from rest, ≤ θ_r after the reversal
    coulomb : T_c [N·m] > 0
    sigma0 : σ₀ [N·m/rad] ≥ 0
    theta_reversal : θ_r [rad] (None: the loop from rest)
    torque_reversal : T_r [N·m] at the reversal

    Returns
    -------
    float or ndarray
        T [N·m].

    Examples
    --------
    >>> round(float(dahl_loop_torque(1e-3, 1e-3, 1.0)) / 1e-3, 6)  # one T_c/σ₀: 1 − 1/e
    0.632121
    """
    check_positive("coulomb", coulomb, "N·m")
    check_nonnegative("sigma0", sigma0, "N·m/rad")
    if theta_reversal is None:
        return coulomb * -np.expm1(-sigma0 * np.asarray(theta) / coulomb)
    x = theta_reversal - np.asarray(theta)
    return -coulomb + (torque_reversal + coulomb) * np.exp(-sigma0 * x / coulomb)


def dahl_resonance_frequency(sigma0, inertia):
    """Frequency [Hz] of the small oscillation of an inertia on the rest slope:
    f = √(σ₀/J)/(2π) (Dahl 1976, AIAA J. 14:1675: the linear spring of |T| ≪ T_c).

    Parameters
    ----------
    sigma0 : σ₀ [N·m/rad] ≥ 0
    inertia : J [kg·m²] > 0

    Returns
    -------
    float or ndarray
        f [Hz].

    Examples
    --------
    >>> round(float(dahl_resonance_frequency(4.0, 1e-4)), 4)  # Hz
    31.831
    """
    check_nonnegative("sigma0", sigma0, "N·m/rad")
    check_positive("inertia", inertia, "kg·m²")
    return np.sqrt(sigma0 / inertia) / (2.0 * np.pi)


# ------------------------------------------------------------------ the rest stiffness
def tangential_modulus(youngs_1, poisson_1, youngs_2, poisson_2):
    """G* [Pa] of Mindlin's no-slip tangential stiffness, 1/G* = (2 − ν₁)/G₁ + (2 − ν₂)/G₂ with
    G = E/(2(1 + ν)) (Johnson 1985, *Contact Mechanics*, §7.2; Mindlin 1949).

    Parameters
    ----------
    youngs_1, youngs_2 : E of the two bodies [Pa] > 0
    poisson_1, poisson_2 : ν of the two bodies [-]

    Returns
    -------
    float or ndarray
        G* [Pa].

    Examples
    --------
    >>> round(tangential_modulus(208e9, 0.3, 208e9, 0.3) / 1e9, 4)  # GPa, steel on steel
    23.5294
    """
    check_positive("youngs_1", youngs_1, "Pa")
    check_positive("youngs_2", youngs_2, "Pa")
    g1 = youngs_1 / (2.0 * (1.0 + poisson_1))
    g2 = youngs_2 / (2.0 * (1.0 + poisson_2))
    return 1.0 / ((2.0 - poisson_1) / g1 + (2.0 - poisson_2) / g2)


def mindlin_tangential_stiffness(modulus, semi_major, semi_minor):
    """Mindlin's no-slip tangential stiffness k_t = 8·G*·√(a·b) [N/m] of a Hertz contact
    (Mindlin 1949; Johnson 1985, §7.2 for the circle, §4.2 for the equivalent radius √(ab) of
    an ellipse).

    Parameters
    ----------
    modulus : G* [Pa] (:func:`tangential_modulus`)
    semi_major, semi_minor : a, b of the contact ellipse [m] ≥ 0

    Returns
    -------
    float or ndarray
        k_t [N/m].

    Examples
    --------
    >>> round(float(mindlin_tangential_stiffness(23.53e9, 100e-6, 25e-6)) / 1e6, 3)  # N/µm
    9.412
    """
    return 8.0 * modulus * np.sqrt(np.asarray(semi_major) * np.asarray(semi_minor))


def ball_rest_stiffness(k_inner, k_outer, arm):
    """Rest stiffness [N·m/rad] of one ball about the bearing's axis: its inner and outer
    tangential stiffnesses [N/m] in series times the square of the lever arm [m] (the radius
    of the inner contact), 0 for an unloaded ball (see the module docstring).

    Returns
    -------
    float or ndarray
        [N·m/rad].

    Examples
    --------
    >>> round(float(ball_rest_stiffness(2e7, 2e7, 0.01)), 6)  # N·m/rad
    1000.0
    """
    ki, ko = np.asarray(k_inner, dtype=float), np.asarray(k_outer, dtype=float)
    total = ki + ko
    series = np.divide(ki * ko, total, out=np.zeros(np.broadcast(ki, ko).shape), where=total > 0)
    return series * np.asarray(arm) ** 2


def contact_rest_stiffness(pair, temperatures, axial_load: float = 0.0, radial_load: float = 0.0):
    """σ₀ [N·m/rad] of the pair from its contacts (module docstring): every ball's inner and
    outer Mindlin stiffness in series times the square of its inner contact radius, summed over
    the balls of both bearings, at the exact thermal state and load equilibrium
    (:func:`.pair_state.thermal_state`, :func:`.preload.pair_equilibrium`, Jones per ball).

    Parameters
    ----------
    pair : :class:`~.pair.BearingPair`
    temperatures : (housing, shaft, outer ring, inner ring) [K]
    axial_load : external axial load [N], positive towards bearing A
    radial_load : external radial load [N], shared by the two bearings

    Returns
    -------
    float
        σ₀ [N·m/rad].

    Examples
    --------
    >>> from servofmu.physics.pair import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> round(contact_rest_stiffness(pair, (293.15,) * 4))  # N·m/rad, Yu's 71803 pair at 20 °C
    9653
    """
    from ..pair.configuration import pair_rows
    from ..pair.preload import pair_equilibrium
    from ..pair.state import thermal_state
    from ..thermal.temperatures import PartTemperatures

    check_finite("axial_load", axial_load, "N")
    check_finite("radial_load", radial_load, "N")
    th = thermal_state(pair, PartTemperatures(*(float(t) for t in temperatures)))
    geom = th.geometry
    rings, balls = pair.bearing.ring_material, pair.bearing.ball_material
    g_star = tangential_modulus(
        rings.youngs_modulus, rings.poisson_ratio, balls.youngs_modulus, balls.poisson_ratio
    )
    state = pair_equilibrium(
        geom, float(th.closure), pair_rows(pair), float(axial_load), float(radial_load)
    )
    dm, dw = float(geom.pitch_diameter), float(geom.ball_diameter)
    total = 0.0
    for b in (state.balls_a, state.balls_b):
        q = np.maximum(b.load, 0.0)
        k_in = mindlin_tangential_stiffness(g_star, *b.inner.semi_axes(q))
        k_out = mindlin_tangential_stiffness(g_star, *b.outer.semi_axes(q))
        arm = 0.5 * (dm - dw * np.cos(b.contact_angle))
        total += float(np.sum(ball_rest_stiffness(k_in, k_out, arm)))
    return total

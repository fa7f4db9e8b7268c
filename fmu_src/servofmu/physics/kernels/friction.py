# cython: language_level=3, auto_pickle=False, embedsignature=False
r"""The friction terms of a ball bearing, floats or arrays: elastic hysteresis, spin and
differential (Heathcote) sliding of one contact, Palmgren's viscous torque, the breakaway of
the Coulomb terms and the regularised sign through zero speed (Yu 2017 eq 1–9; Ning,
reconstructed). The coefficients, the ball-set sums and the checked functions are
:mod:`servofmu.physics.friction.terms`; the friction models composing them are
:mod:`servofmu.physics.friction`.

Examples
--------
>>> import math
>>> round(palmgren_torque(100e-6, 2 * math.pi, 21.5e-3, 1.0) * 1e3, 6)  # N·mm, 100 cSt, 60 rpm
0.328158
"""

from scipy.optimize import brentq

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from . import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.servofmu.physics.kernels._elementary import (
        exp,
        maximum,
        minimum,
        power,
        tanh,
    )
else:
    from .elementary import exp, maximum, minimum, power, tanh

from .units import CST, MM, NMM, RPM

#: ν·n [cSt·rpm] below which Palmgren's eq 8 is speed-independent.
PALMGREN_THRESHOLD = 2000.0


def _heathcote_constant() -> float:
    # Rolling lines at |y| = u0·a where the Hertz line load (1 − u²) splits the contact into
    # equal halves: u0 − u0³/3 = 1/3 (Heathcote 1921; Johnson 1985 ch. 8: u0 ≈ 0.347).
    u0 = brentq(lambda u: u - u**3 / 3.0 - 1.0 / 3.0, 0.0, 1.0, xtol=1e-15)
    c = u0 * u0
    inner = c * u0 - (c + 1.0) * u0**3 / 3.0 + u0**5 / 5.0  # ∫0^u0 (1−u²)(c−u²) du
    full = c - (c + 1.0) / 3.0 + 0.2  # ∫0^1 (1−u²)(c−u²) du
    return 0.75 * 2.0 * (2.0 * inner - full)  # (3/4)·∫_{-1}^{1} (1−u²)|c−u²| du


#: C_H = (3/4)·∫(1 − u²)·|u0² − u²|du ≈ 0.161 of :func:`heathcote_force` [-].
HEATHCOTE = _heathcote_constant()
# the same numbers as C doubles for the compiled path (module globals are Python objects)
_HEATHCOTE: cython.double = HEATHCOTE
_THRESHOLD: cython.double = PALMGREN_THRESHOLD
_TWO_THIRDS: cython.double = 2.0 / 3.0
_CST: cython.double = CST
_MM: cython.double = MM
_NMM: cython.double = NMM
_RPM: cython.double = RPM


@cython.ccall
def hysteresis_force(
    load: cython.double,
    semi_minor_axis: cython.double,
    ball_diameter: cython.double,
    loss_factor: cython.double,
) -> cython.double:
    """Rolling resistance of one contact from elastic hysteresis (Yu 2017 eq 1)

        F_SE = 3·α_r·b·Q/(16·R),  R = Dw/2 the ball radius

    (Johnson 1985, *Contact Mechanics*, ch. 9: the hysteresis rolling moment 3·α_r·b·Q/16
    divided by the rolling radius; Yu calls R the "Hertz contact radius"), from the load Q
    [N], the semi-axis b [m] in the rolling direction, the ball diameter Dw [m] and the loss
    factor α_r [-] (energy lost per cycle, < 1 % for metals per Yu). Floats or arrays.

    Returns
    -------
    float or ndarray
        F_SE [N].

    Examples
    --------
    >>> round(hysteresis_force(10.0, 50e-6, 2.5e-3, 0.01) * 1e6, 3)  # µN, by hand
    750.0
    """
    return 3.0 * loss_factor * semi_minor_axis * load / (8.0 * ball_diameter)


@cython.ccall
def contact_spin_moment(
    load: cython.double,
    semi_major_axis: cython.double,
    e_integral: cython.double,
    friction_coefficient: cython.double,
) -> cython.double:
    """Spin friction moment of one contact about its normal (Yu 2017 eq 6; Harris & Kotzalas
    2007)

        M'_K = (3/8)·μ·Q·a·E(e),

    from the load Q [N], the semi-major axis a [m], the complete elliptic integral of the
    second kind E(e) [-] of the contact ellipse and the sliding friction coefficient μ [-].
    Floats or arrays.

    Returns
    -------
    float or ndarray
        M'_K [N·m].

    Examples
    --------
    >>> round(contact_spin_moment(10.0, 2e-4, 1.0, 0.1) * 1e6, 6)  # µN·m, by hand
    75.0
    """
    return 0.375 * friction_coefficient * load * semi_major_axis * e_integral


@cython.ccall
def heathcote_force(
    load: cython.double,
    semi_major_axis: cython.double,
    ball_diameter: cython.double,
    groove_radius: cython.double,
    friction: cython.double,
) -> cython.double:
    """Rolling resistance of one contact from differential (Heathcote) sliding

        F_d = C_H·μ·Q·a²/(R_c·Dw),  C_H = (3/4)∫(1 − u²)·|u0² − u²|du ≈ 0.161,

    R_c = 2·r·Dw/(2·r + Dw) the radius of the deformed contact surface (the harmonic mean of
    ball and groove radii), from the load Q [N], the semi-major axis a [m], the ball
    diameter Dw [m], the groove radius r [m] and the friction coefficient μ [-]. For a close
    groove (R_c → Dw/2) this is Johnson's (1985, ch. 8) F ≈ 0.08·μ·Q·(a/R)², R = Dw/2. It
    reconstructs Ning's M_di, M_do (equations missing from the received text). Floats or
    arrays.

    Returns
    -------
    float or ndarray
        F_d [N].

    Examples
    --------
    >>> round(heathcote_force(10.0, 2e-4, 2.5e-3, 1.3e-3, 0.1) * 1e3, 4)  # mN
    2.023
    """
    r_c = 2.0 * groove_radius * ball_diameter / (2.0 * groove_radius + ball_diameter)
    return _HEATHCOTE * friction * load * semi_major_axis**2 / (r_c * ball_diameter)


@cython.ccall
def palmgren_torque(
    kinematic_viscosity: cython.double,
    speed: cython.double,
    pitch_diameter: cython.double,
    s0: cython.double,
) -> cython.double:
    """Viscous friction torque of one bearing (Palmgren; Yu 2017 eq 8)

        M_L = 1e-7·s0·(ν0·n)^(2/3)·dm³  [N·mm]   for ν0·n ≥ 2000,
        M_L = 160e-7·s0·dm³             [N·mm]   for ν0·n < 2000,

    ν0 in cSt, n in rpm, dm in mm (the equation's own units; converted here from the
    kinematic viscosity ν0 [m²/s], the speed ω [rad/s] (sign ignored) and the pitch
    diameter dm [m]), s0 [-] the bearing/lubrication factor (f0 in Palmgren's notation). The
    printed 160 is 2000^(2/3) = 158.7 rounded up, which makes eq 8 jump by 0.8 % at
    ν0·n = 2000; the continuous form (max(ν0·n, 2000))^(2/3) is used, so that the torque has
    no step in speed or temperature. Floats or arrays.

    Returns
    -------
    float or ndarray
        M_L [N·m].

    Examples
    --------
    At rest, below the threshold: 1e-7·2000^(2/3)·dm³ (by hand 1e-7 · 158.74 · 10³ =
    0.0159 N·mm for dm = 10 mm):

    >>> round(palmgren_torque(1e-4, 0.0, 10e-3, 1.0) * 1e3, 4)  # N·mm
    0.0159
    """
    nu_n = kinematic_viscosity / _CST * abs(speed) / _RPM
    dm_mm = pitch_diameter / _MM
    return 1e-7 * s0 * power(maximum(nu_n, _THRESHOLD), _TWO_THIRDS) * dm_mm**3 * _NMM


@cython.ccall
def stribeck_torque(
    running_torque: cython.double,
    breakaway_excess: cython.double,
    speed: cython.double,
    stribeck_speed: cython.double,
) -> cython.double:
    """Magnitude of the sliding friction torque at speed ω, the Stribeck decay of the breakaway
    onto the running torque:

        T_c(ω) = M_run(|ω|) + ΔM_break·exp(−|ω|/ω_s)

    (Andersson, Söderberg & Björklund 2007, Tribology International 40:580), from the running
    torque M_run [N·m] at |ω|, the breakaway excess ΔM_break [N·m] ≥ 0, the speed ω [rad/s]
    (signed) and the Stribeck speed ω_s [rad/s] > 0. Floats or arrays.

    Returns
    -------
    float or ndarray
        T_c [N·m] ≥ 0.

    Examples
    --------
    >>> stribeck_torque(1e-3, 5e-4, 0.0, 1e-2)  # N·m: the breakaway at rest
    0.0015
    """
    return running_torque + breakaway_excess * exp(-abs(speed) / stribeck_speed)


@cython.ccall
def regularised_torque(
    speed: cython.double,
    running_torque: cython.double,
    breakaway_excess: cython.double,
    regularisation_speed: cython.double,
    stribeck_speed: cython.double,
) -> cython.double:
    """Friction torque opposing rotation, smooth through zero speed:

        M(ω) = tanh(ω/ω_r)·(M_run(|ω|) + ΔM_break·exp(−|ω|/ω_s))

    from the speed ω [rad/s] (signed), the running torque M_run [N·m] at |ω|, the breakaway
    excess ΔM_break = breakaway − running-at-rest [N·m] ≥ 0, the regularisation speed ω_r
    [rad/s] (width of the smooth sign) and the Stribeck speed ω_s [rad/s] (decay of the
    static excess, :func:`stribeck_torque`). The sign regularisation and Stribeck decay follow
    Andersson, Söderberg & Björklund (2007), Tribology International 40:580. Floats or arrays.

    Returns
    -------
    float or ndarray
        M [N·m], signed like the speed.

    Examples
    --------
    >>> regularised_torque(0.0, 1e-3, 5e-4, 1e-3, 1e-2)  # N·m: nothing at rest
    0.0
    """
    return tanh(speed / regularisation_speed) * stribeck_torque(
        running_torque, breakaway_excess, speed, stribeck_speed
    )


@cython.ccall
def coulomb_and_excess(
    static_ratio: cython.double,
    hysteresis: cython.double,
    spin: cython.double,
    sliding: cython.double,
) -> tuple[cython.double, cython.double]:
    """The Coulomb torque of the contacts and the excess of their breakaway over it (Yu 2017
    eq 9; the static friction of spin and sliding):

        M_C = M_hysteresis + M_spin + M_sliding,  ΔM = (μ_s/μ − 1)·(M_spin + M_sliding),

    from the static-to-sliding friction ratio μ_s/μ [-] and the three torques [N·m]. Floats
    or arrays.

    Returns
    -------
    tuple
        (M_C [N·m], ΔM [N·m]).

    Examples
    --------
    >>> coulomb_and_excess(1.5, 1.0, 2.0, 0.0)  # N·m: spin alone has static friction
    (3.0, 1.0)
    """
    return hysteresis + spin + sliding, (static_ratio - 1.0) * (spin + sliding)


@cython.ccall
def dahl_torque_step(
    torque: cython.double,
    coulomb: cython.double,
    sigma0: cython.double,
    exponent: cython.double,
    dtheta: cython.double,
) -> cython.double:
    """Dahl's pre-rolling torque after the rings turn by Δθ with the sign of the speed and T_c
    held (Dahl 1976, AIAA J. 14(12):1675, eq. 1, dT/dθ = σ₀·|1 − s·T/T_c|^i·sgn(1 − s·T/T_c),
    s = sgn Δθ), in closed form: with y = 1 − s·T/T_c and k = σ₀/T_c,
    y = y₀·e^(−k|Δθ|) for i = 1, |y| = (|y₀|^(1−i) + (i − 1)·k·|Δθ|)^(−1/(i−1)) for i > 1,
    |y| = max(0, |y₀|^(1−i) − (1 − i)·k·|Δθ|)^(1/(1−i)) for i < 1 (separation of variables:
    exact for every i, to rounding). A T_c below |T| takes T to ±T_c at once (the contacts
    slip), so y₀ is in [0, 2]. Floats.

    Parameters
    ----------
    torque : T [N·m] at the start of the step, signed like the speed that built it
    coulomb : T_c [N·m] ≥ 0 (0: no torque; :func:`stribeck_torque`)
    sigma0 : rest slope σ₀ [N·m/rad] ≥ 0
    exponent : i [-] ≥ 0
    dtheta : Δθ [rad], the relative rotation of the rings over the step (0: T held)

    Returns
    -------
    float
        T [N·m] at the end of the step, |T| ≤ T_c.

    Examples
    --------
    >>> t = dahl_torque_step(0.0, 1e-3, 2.0, 1.0, 5e-4)  # one T_c/σ₀ from rest
    >>> round(t / 1e-3, 12) == round(1 - exp(-1.0), 12)
    True
    >>> dahl_torque_step(2e-3, 1e-3, 2.0, 1.0, 0.0)  # T_c fell below |T|: the contacts slip
    0.001
    """
    if not coulomb > 0.0:
        return 0.0
    t: cython.double = maximum(minimum(torque, coulomb), -coulomb)
    if dtheta == 0.0 or sigma0 == 0.0:
        return t
    s: cython.double = 1.0 if dtheta > 0.0 else -1.0
    y0: cython.double = 1.0 - s * t / coulomb  # in [0, 2]: |T| <= T_c
    if y0 == 0.0:
        return t
    kx: cython.double = sigma0 / coulomb * abs(dtheta)
    y: cython.double
    if exponent == 1.0:
        y = y0 * exp(-kx)
    elif exponent > 1.0:
        y = power(power(y0, 1.0 - exponent) + (exponent - 1.0) * kx, -1.0 / (exponent - 1.0))
    else:
        y = power(
            maximum(0.0, power(y0, 1.0 - exponent) - (1.0 - exponent) * kx),
            1.0 / (1.0 - exponent),
        )
    return s * coulomb * (1.0 - y)

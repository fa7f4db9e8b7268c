# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The bearing pair's kernels: the float-or-array equations the exact vectorised path and
the per-step path share, and the per-step update of a pair (its continuation), written once
in Cython's pure-Python mode.

This file runs as it is (plain Python: the kernels take floats or numpy arrays), and the
build compiles the same file into ``servofmu.physics.pair._continuation`` when a C compiler is
there (``setup.py``; the annotations are C types then, and a call of
:meth:`PairSolver.update` is one compiled call: thermal state, predictor, Newton iterations,
ring sums, torques and the output record). :mod:`.compiled` chooses the implementation
at import. The exact path always imports this file (its kernels take arrays).

**Shared kernels** (floats or arrays): the Lamé ratio of an annulus (:func:`lame_ratio`, Yu
2017 eq 12), the friction terms of one contact (Yu eq 1–3, 5–7; Heathcote; Palmgren's eq 8 and
the regularised sign), the preload, axial play and flags of a state, and the pair's
equilibrium rows per arrangement (:class:`PairRows`: the conditions of
:func:`preload.pair_equilibrium` for a face-to-face or back-to-back pair in its loop and a
tandem pair under its thrust, their Jacobian and the Newton correction with the radial rows
eliminated) — one residual per arrangement for the exact root finders and the continuation.

**The continuation.** The exact path (:func:`pair_state.thermal_state`,
:func:`pair_state.load_state`) solves every operating point from scratch with bracketing root
finders over numpy arrays: robust, and the reference, but about a millisecond per point. Inside
an FMU the temperature and the loads change a little from one communication step to the next,
so :class:`PairSolver` solves the same equations from the previous step's solution:

- the thermal state (ring growth, Lamé fits, clearance, loop closure, viscosity) is closed
  form: the equations of :func:`fits.mounted_geometry` and :func:`preload.loop_interference`
  on floats, and the lubricant's own law on floats
  (:meth:`viscosity.ViscosityRange.operating_viscosity_at`) (:func:`thermal_floats`);
- the pair's offsets and radial displacements x = (p, z, δr_A, δr_B) [m] (a_A = p + z,
  a_B = p − z) solve the arrangement's rows (:class:`PairRows`) by Newton's method with the
  analytic Jacobian, the contact angle's effect on the Hertz constants included, started from
  a predictor: the previous solution moved by the tangent of the load change (the last
  Jacobian) and by the secant of the last temperature change when the temperatures move on in
  the same direction. The radial rows are eliminated by hand (they involve one bearing each),
  which leaves a 2×2 system in the bearings' axial offsets (:meth:`PairRows.newton_step`). A
  bearing with no ball in contact under a radial load (its radial row is empty) is first moved
  radially until its ball nearest the load's direction touches (:meth:`PairSolver._touch`);
- under pure axial load every ball of a bearing is alike (Yu 2017 eq 4): a bearing is one ball
  of weight Z (one unknown less when the load is zero, none for a rigid loop at zero load);
  under a radial load every ball differs (Jones 1960): the balls of half the ring (the load is
  symmetric about the radial load's direction) with weights 1 or 2, one ball at a time;
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
evaluations per step on a temperature ramp. A step that does not converge in
:data:`MAX_ITERATIONS`, a singular Jacobian (no ball in contact while the external load is not
zero), or a non-finite value returns None, and the caller starts again from the unloaded pair
(:meth:`PairSolver.start`) and then falls back to the exact path. The outputs equal the exact
path's to a relative 1e-9 (tests check this on random trajectories of temperature and load,
compiled and not).

The continuation state (:meth:`PairSolver.state`) is a JSON-serialisable dict of floats (the
solution and its inputs, the anchors' k, the bases' γ0 and 1/f0, the last Jacobian and
temperature secant of the predictor, the operating point and its output record): a restored
solver continues bit for bit (the same build: the compiled and the Python path round
differently, by about 1e-16 relative).

The thermal state takes the four parts' temperatures (housing, shaft, outer ring, inner ring);
a uniform temperature is four equal ones.
"""

import math

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from ..units import CST, MM, NMM, RPM

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from .. import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import acos, atan2, cbrt, exp, hypot, log10, sqrt, tanh
else:
    from math import acos, atan2, cbrt, exp, hypot, log10, sqrt, tanh


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
#: Newton iterations of one step before the step starts again from the unloaded pair.
MAX_ITERATIONS = 12
#: Newton iterations of each stage of a cold start (:meth:`PairSolver.start`): from the loop
#: closure's half to a barely loaded contact the convergence is linear (ratio 1/3, Hertz's
#: Q ∝ δ^1.5) until the quadratic phase.
START_ITERATIONS = 60
#: The smallest share of the external load a cold start adds in one stage (it halves a stage
#: whose Newton's method fails, down to this).
START_SMALLEST_STAGE = 1.0 / 256.0
#: Rounds of anchor renewal within one step before the step starts again.
MAX_ANCHOR_ROUNDS = 6
#: ν·n [cSt·rpm] below which Palmgren's eq 8 is speed-independent.
PALMGREN_THRESHOLD = 2000.0

# the same numbers as C doubles for the compiled path (module globals are Python objects)
_DRIFT: cython.double = ANCHOR_DRIFT
_REDO: cython.double = ANCHOR_REDO
_G_SPAN: cython.double = GAMMA_SPAN
_F_SPAN: cython.double = INV_F_SPAN
_THRESHOLD: cython.double = PALMGREN_THRESHOLD
_ROUNDS: cython.int = MAX_ANCHOR_ROUNDS
_ITERATIONS: cython.int = MAX_ITERATIONS
_START_ITERATIONS: cython.int = START_ITERATIONS
#: Newton stops at the first point whose next correction is below this fraction of the
#: curvature distance A (≈ 1e-16 m for the catalogue bearings, the exact path's tolerance) ...
_TOLERANCE: cython.double = 1e-12
#: ... and below this fraction of the smallest deflection of a loaded ball (a ball load
#: Q ∝ δ^1.5 and its stiffness ∝ δ^0.5 then move by less than 3e-10 of their value), unless it
#: is below rounding (this fraction of A).
_DEFLECTION_TOLERANCE: cython.double = 2e-10
_ROUNDING: cython.double = 1e-15
_INF: cython.double = math.inf
_NAN: cython.double = math.nan
_THIRD: cython.double = 1.0 / 3.0
_TWO_THIRDS: cython.double = 2.0 / 3.0
_PI: cython.double = math.pi
_2_PI: cython.double = 2.0 / math.pi
_PI_2: cython.double = 0.5 * math.pi
_CST: cython.double = CST
_MM: cython.double = MM
_NMM: cython.double = NMM
_RPM: cython.double = RPM
#: Arrangement of a pair (:class:`PairRows`): a face-to-face or back-to-back pair in a
#: compliant loop, the same in a rigid loop (its mean offset held at C/2), a tandem pair (its
#: offsets' half difference held at −d/2).
_LOOP: cython.int = 0
_RIGID: cython.int = 1
_TANDEM: cython.int = 2
#: Friction models (:mod:`.friction.models`) by number.
_YU: cython.int = 0
_SKF: cython.int = 1
_EHL: cython.int = 2
_MODELS = {"yu2017": 0, "skf2004": 1, "ehl_per_contact": 2}
#: Viscosity laws (:mod:`.lubrication.viscosity`) by number.
_NO_LAW: cython.int = 0
_WALTHER: cython.int = 1
_VOGEL: cython.int = 2
_OTHER_LAW: cython.int = 3

# A bearing's ring result (ring_point), a contact's Hertz terms (contact_terms) and the sums
# over a ring (ring_sums): C structs compiled, tuples uncompiled.
Ring = cython.typedef(
    tuple[
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
    ]
)
Terms = cython.typedef(
    tuple[
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
    ]
)
Sums = cython.typedef(
    tuple[
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.bint,
    ]
)
Step = cython.typedef(
    tuple[cython.bint, cython.double, cython.double, cython.double, cython.double]
)
Flags = cython.typedef(tuple[cython.bint, cython.bint, cython.bint, cython.bint])
Quad = cython.typedef(tuple[cython.double, cython.double, cython.double, cython.double])
Pair2 = cython.typedef(tuple[cython.double, cython.double])
Speed = cython.typedef(
    tuple[cython.double, cython.double, cython.double, cython.double, cython.double]
)


# ------------------------------------------------------------------ elementary operations
# Python floats through the math module (a per-step call costs a fraction of a microsecond),
# arrays through numpy, C doubles compiled.
@cython.cfunc
@cython.inline
def _maximum(a: cython.double, b: cython.double) -> cython.double:
    if cython.compiled:
        return a if a >= b else b
    return max(a, b) if type(a) is float else np.maximum(a, b)


@cython.cfunc
@cython.inline
def _tanh(x: cython.double) -> cython.double:
    if cython.compiled:
        return tanh(x)
    return math.tanh(x) if type(x) is float else np.tanh(x)


@cython.cfunc
@cython.inline
def _exp(x: cython.double) -> cython.double:
    if cython.compiled:
        return exp(x)
    return math.exp(x) if type(x) is float else np.exp(x)


# ------------------------------------------------------------------ shared kernels
@cython.ccall
def lame_ratio(d_small: cython.double, d_large: cython.double) -> cython.double:
    """(D² + d²)/(D² − d²) [-] of an annulus from diameter d to D (Lamé's thick cylinder; Yu
    2017 eq 12–13: the ring, seat and shaft compliances per diameter are this ratio ∓ ν over
    E). Floats or arrays.

    Parameters
    ----------
    d_small, d_large : float or ndarray
        d < D [m].

    Returns
    -------
    float or ndarray
        [-].

    Examples
    --------
    >>> lame_ratio(1.0, 2.0)  # (4 + 1)/(4 − 1)
    1.6666666666666667
    """
    return (d_large * d_large + d_small * d_small) / (d_large * d_large - d_small * d_small)


@cython.cfunc
def _walther_cst(
    lg_t: cython.double, a: cython.double, b: cython.double, c: cython.double
) -> cython.double:
    """ν [cSt] of lg lg(ν + c) = a − b·lg T at lg T = ``lg_t`` (float or array): the one place
    of Walther's equation (Yu 2017 eq 18, ASTM D341; :mod:`.lubrication.viscosity`)."""
    return 10.0 ** (10.0 ** (a - b * lg_t)) - c


@cython.cfunc
def _vogel_exponent(
    t: cython.double, a: cython.double, b: cython.double, t_inf: cython.double
) -> cython.double:
    """ln ν [ln(m²/s)] of Vogel's law at ``t`` [K] (float or array): the one place of it
    (:mod:`.lubrication.viscosity`)."""
    return a + b / (t - t_inf)


@cython.cfunc
def _operating_temperature(t: cython.double, hold: cython.double) -> cython.double:
    """The temperature [K] at which a lubricant's law gives the viscosity a bearing model
    uses at ``t`` [K]: ``t``, or the temperature ``hold`` [K] below which the viscosity is
    held (0: never; :meth:`.lubrication.viscosity.ViscosityRange.operating_viscosity_at`)."""
    return t if t > hold else hold


@cython.cfunc
def _hysteresis(
    load: cython.double,
    semi_minor_axis: cython.double,
    ball_diameter: cython.double,
    loss_factor: cython.double,
) -> cython.double:
    # Yu 2017 eq 1: F = 3·α_r·b·Q/(16·R), R = Dw/2 (friction.hysteresis_rolling_force)
    return 3.0 * loss_factor * semi_minor_axis * load / (8.0 * ball_diameter)


@cython.cfunc
def _spin(
    load: cython.double,
    semi_major_axis: cython.double,
    e_integral: cython.double,
    friction_coefficient: cython.double,
) -> cython.double:
    # Yu 2017 eq 6: M' = (3/8)·μ·Q·a·E(e) (friction.spin_moment)
    return 0.375 * friction_coefficient * load * semi_major_axis * e_integral


def _heathcote_constant() -> float:
    # Rolling lines at |y| = u0·a where the Hertz line load (1 − u²) splits the contact into
    # equal halves: u0 − u0³/3 = 1/3 (Heathcote 1921; Johnson 1985 ch. 8: u0 ≈ 0.347).
    u0 = brentq(lambda u: u - u**3 / 3.0 - 1.0 / 3.0, 0.0, 1.0, xtol=1e-15)
    c = u0 * u0
    inner = c * u0 - (c + 1.0) * u0**3 / 3.0 + u0**5 / 5.0  # ∫0^u0 (1−u²)(c−u²) du
    full = c - (c + 1.0) / 3.0 + 0.2  # ∫0^1 (1−u²)(c−u²) du
    return 0.75 * 2.0 * (2.0 * inner - full)  # (3/4)·∫_{-1}^{1} (1−u²)|c−u²| du


HEATHCOTE = _heathcote_constant()  # ≈ 0.1611
_HEATHCOTE: cython.double = HEATHCOTE


@cython.cfunc
def _heathcote(
    load: cython.double,
    semi_major_axis: cython.double,
    ball_diameter: cython.double,
    groove_radius: cython.double,
    friction: cython.double,
) -> cython.double:
    # F_d = C_H·μ·Q·a²/(R_c·Dw), R_c = 2·r·Dw/(2·r + Dw) (friction.heathcote_sliding_force)
    r_c = 2.0 * groove_radius * ball_diameter / (2.0 * groove_radius + ball_diameter)
    return _HEATHCOTE * friction * load * semi_major_axis**2 / (r_c * ball_diameter)


@cython.cfunc
def _palmgren(
    kinematic_viscosity: cython.double,
    speed: cython.double,
    pitch_diameter: cython.double,
    s0: cython.double,
) -> cython.double:
    # Yu 2017 eq 8 with (max(ν·n, 2000))^(2/3) (friction.palmgren_viscous_torque)
    nu_n = kinematic_viscosity / _CST * abs(speed) / _RPM
    dm_mm = pitch_diameter / _MM
    return 1e-7 * s0 * _maximum(nu_n, _THRESHOLD) ** _TWO_THIRDS * dm_mm**3 * _NMM


@cython.cfunc
def _regularised(
    speed: cython.double,
    running: cython.double,
    excess: cython.double,
    w_reg: cython.double,
    w_stribeck: cython.double,
) -> cython.double:
    # tanh(ω/ω_r)·(M_run + ΔM·exp(−|ω|/ω_s)) (friction.regularised_friction_torque)
    return _tanh(speed / w_reg) * (running + excess * _exp(-abs(speed) / w_stribeck))


@cython.cfunc
def _coulomb_excess(
    static_ratio: cython.double,
    hysteresis: cython.double,
    spin: cython.double,
    sliding: cython.double,
) -> Pair2:
    # (hysteresis + spin + sliding, (μ_s/μ − 1)·(spin + sliding)) [N·m] (Yu 2017 eq 9; the
    # static friction of spin and sliding)
    return hysteresis + spin + sliding, (static_ratio - 1.0) * (spin + sliding)


@cython.ccall
def preload_force(force_a: cython.double, force_b: cython.double) -> cython.double:
    """The preload [N]: the mean axial force of the two bearings, (F_A + F_B)/2, the loop's
    compression (a tandem pair: half the thrust the set carries, the spring's or force's plus
    the external load), and 0 where that mean is not a compression (both bearings pushed onto
    the other flanks of their grooves, ``reverse_loaded``). Under an external load one bearing
    carries more than the preload, the other less; once one carries nothing (``unloaded``) the
    mean is half the load the other carries, and :func:`axial_play` says how far the shaft can
    move.

    Parameters
    ----------
    force_a, force_b : float or ndarray
        Axial forces of bearings A and B [N] (negative: on the other flanks).

    Returns
    -------
    float or ndarray
        [N], ≥ 0.

    Examples
    --------
    >>> preload_force(60.0, 20.0), preload_force(-10.0, -30.0)  # N
    (40.0, 0.0)
    """
    n = 0.5 * (force_a + force_b)
    if cython.compiled or type(n) is float:  # the per-step path
        return n if n > 0.0 else 0.0
    return np.maximum(n, 0.0)


@cython.ccall
def axial_play(
    first_contact_offset: cython.double,
    offset_a: cython.double,
    offset_b: cython.double,
    force_a: cython.double,
    force_b: cython.double,
) -> cython.double:
    """Axial play of the pair [m]: for each bearing that carries no axial load (F ≤ 0), the
    axial offset its groove centres lack to first contact, h − a (the balls' gap to the flanks
    that carry a preload); summed over the two bearings, 0 when both carry load. At zero
    external load it is how far the loop is short of closing on the two bearings, 2h − C (loop
    closure C); under a load, how far the shaft can move back before the unloaded bearing
    touches (its elastic deflections aside). Harris & Kotzalas 2007 ch. 2 (axial play 2h).

    Parameters
    ----------
    first_contact_offset : float or ndarray
        h [m] (:func:`.contact.geometry.first_contact_offset`).
    offset_a, offset_b : float or ndarray
        Axial offsets of bearings A and B [m].
    force_a, force_b : float or ndarray
        Their axial forces [N].

    Returns
    -------
    float or ndarray
        [m], ≥ 0.

    Examples
    --------
    >>> round(axial_play(60e-6, 40e-6, 40e-6, 0.0, 0.0) * 1e6, 9)  # µm: two 20 µm gaps
    40.0
    >>> axial_play(60e-6, 65e-6, 50e-6, 30.0, 10.0)  # both in contact
    0.0
    """
    h = first_contact_offset
    if cython.compiled or type(offset_a) is float:  # the per-step path
        play_a = h - offset_a if force_a <= 0.0 and offset_a < h else 0.0
        play_b = h - offset_b if force_b <= 0.0 and offset_b < h else 0.0
        return play_a + play_b
    play_a = np.where(np.asarray(force_a) <= 0.0, np.maximum(h - np.asarray(offset_a), 0.0), 0.0)
    play_b = np.where(np.asarray(force_b) <= 0.0, np.maximum(h - np.asarray(offset_b), 0.0), 0.0)
    return play_a + play_b


@cython.cfunc
def _flags(
    pressure_limit: cython.double,
    clearance: cython.double,
    max_contact_pressure: cython.double,
    force_a: cython.double,
    force_b: cython.double,
) -> Flags:
    # (overloaded, locked, unloaded, reverse_loaded) of pair_state.state_flags, elementwise
    return (
        max_contact_pressure >= pressure_limit,
        clearance <= 0.0,
        (force_a <= 0.0) | (force_b <= 0.0),
        (force_a < 0.0) | (force_b < 0.0),
    )


@cython.ccall
def loop_closure_at(
    assembly: cython.double,
    housing: cython.double,
    shaft: cython.double,
    rings: cython.double,
    t0: cython.double,
    t_housing: cython.double,
    t_shaft: cython.double,
    t_rings: cython.double,
) -> cython.double:
    """The loop closure C = C0 − Σ_parts c_part·(T_part − T0) [m] (Yu 2017 eq 14–15; see
    :mod:`.pair.preload`) from the closure at assembly C0 [m] and the loop members' Σ σ·L·α of the
    housing, the shaft and the rings [m/K] (:func:`.pair.configuration.closure_coefficients`), at
    the temperatures of housing, shaft and rings (the rings' mean) [K] from T0 [K]. A tandem pair:
    B's mismatch d(T) along the thrust (C0 = 0). Floats or arrays.

    Returns
    -------
    float or ndarray
        C [m].

    Examples
    --------
    A frame 10 mm of aluminium (23e-6 /K, opening) 40 K colder closes the loop by 9.2 µm:

    >>> c = loop_closure_at(0.0, 10e-3 * 23e-6, 0.0, 0.0, 293.15, 253.15, 293.15, 293.15)
    >>> round(c * 1e6, 9)  # µm
    9.2
    """
    return assembly - (housing * (t_housing - t0) + shaft * (t_shaft - t0) + rings * (t_rings - t0))


# ------------------------------------------------------------------ the pair's equilibrium rows
@cython.final
@cython.cclass
class PairRows:
    """The equilibrium conditions of a pair in its arrangement, as residual rows over the
    unknowns x = (p, z, δr_A, δr_B) [m] (a_A = p + z, a_B = p − z the axial offsets of the
    bearings' groove curvature centres, δr the radial displacements), from the bearings'
    axial and radial forces F, Fr [N] and their Jacobians; floats or arrays.

    - r1, the axial balance [N]: F_A − F_B − F_ext for a face-to-face or back-to-back pair
      (Yu 2017 eq 14–17 with the external load), F_A + F_B + k_s·a_A − T − F_ext for a tandem
      pair under its preload spring k_s and thrust T (:func:`preload.tandem_offsets`);
    - r2, r3, the radial balances [N]: Fr_A − F_r/2, Fr_B − F_r/2 (the load midway);
    - r4 [m]: a pair in a compliant loop closes it, 2p + (F_A + F_B)/(2k) − C (loop closure C,
      stiffness k); a rigid loop holds 2p − C; a tandem pair holds 2z + d (B displaced by the
      mismatch d along the thrust).

    Parameters
    ----------
    tandem : bool
        A tandem pair.
    stiffness : float
        Loop stiffness k [N/m] (inf: rigid), or a tandem pair's spring k_s [N/m] (0: a
        constant force).
    thrust : float
        A tandem pair's thrust T [N] (0 otherwise).

    Examples
    --------
    A rigid loop under 3 N with bearings of 2 and 1 N/µm: dz = 1 µm (by hand 3 N / 3 N/µm):

    >>> rows = PairRows(False, float("inf"), 0.0)
    >>> ok, dp, dz, da, db = rows.newton_step(2e6, 0, 0, 1, 1e6, 0, 0, 1, -3.0, 0, 0, 0, False)
    >>> ok, dp, round(dz * 1e6, 9)
    (True, 0.0, 1.0)
    """

    kind: cython.int
    sign_b: cython.double
    spring: cython.double
    thrust: cython.double
    k_loop: cython.double
    __slots__ = ("k_loop", "kind", "sign_b", "spring", "thrust")

    def __init__(self, tandem: cython.bint, stiffness: cython.double, thrust: cython.double):
        if tandem:
            self.kind, self.sign_b, self.spring, self.thrust = _TANDEM, 1.0, stiffness, thrust
            self.k_loop = _INF
        else:
            self.kind = _RIGID if stiffness == _INF else _LOOP
            self.sign_b, self.spring, self.thrust, self.k_loop = -1.0, 0.0, 0.0, stiffness

    @property
    def is_tandem(self) -> bool:
        """A tandem pair."""
        return self.kind == _TANDEM

    @property
    def stiffness(self) -> float:
        """The loop's stiffness k [N/m] (inf: rigid), or a tandem pair's spring k_s [N/m]."""
        return self.spring if self.kind == _TANDEM else self.k_loop

    @property
    def held(self) -> str:
        """The unknown the rows hold fixed: "p" (rigid loop), "z" (tandem) or "" (none)."""
        return {_RIGID: "p", _TANDEM: "z"}.get(self.kind, "")

    @cython.ccall
    def residuals(
        self,
        fa_a: cython.double,
        fa_b: cython.double,
        fr_a: cython.double,
        fr_b: cython.double,
        p: cython.double,
        z: cython.double,
        closure: cython.double,
        f_ext: cython.double,
        f_r: cython.double,
    ) -> Quad:
        """(r1, r2, r3 [N], r4 [m]) at the bearings' axial forces ``fa_a``, ``fa_b`` and
        radial forces ``fr_a``, ``fr_b`` [N], the unknowns p, z [m], the loop closure (a
        tandem pair: the mismatch d) [m] and the external loads [N]. Floats or arrays.

        Returns
        -------
        tuple
            (r1 [N], r2 [N], r3 [N], r4 [m]).

        Examples
        --------
        >>> rows = PairRows(True, 0.0, 40.0)  # a tandem pair under a constant 40 N
        >>> rows.residuals(20.0, 20.0, 0.0, 0.0, 1e-6, 0.0, 0.0, 0.0, 0.0)  # balanced
        (0.0, 0.0, 0.0, 0.0)
        """
        r1 = fa_a + self.sign_b * fa_b + self.spring * (p + z) - self.thrust - f_ext
        half = 0.5 * f_r
        if self.kind == _TANDEM:
            r4 = 2.0 * z + closure
        elif self.kind == _RIGID:
            r4 = 2.0 * p - closure
        else:
            r4 = 2.0 * p + 0.5 * (fa_a + fa_b) / self.k_loop - closure
        return r1, fr_a - half, fr_b - half, r4

    def jacobian(self, ja, jb):
        """d(r1, r2, r3, r4)/d(p, z, δr_A, δr_B) from the bearings' 2×2 Jacobians ``ja``,
        ``jb`` = ((dFa/da, dFa/dδr), (dFr/da, dFr/dδr)) [N/m].

        Returns
        -------
        list
            Four rows of four entries ([N/m] for r1–r3, [-] for r4).

        Examples
        --------
        >>> rows = PairRows(False, 2e7, 0.0)
        >>> rows.jacobian(((1e7, 0.0), (0.0, 1e7)), ((1e7, 0.0), (0.0, 1e7)))[0]
        [0.0, 20000000.0, 0.0, -0.0]
        """
        s, ks = self.sign_b, self.spring
        rows = [
            [ja[0][0] + ks + s * jb[0][0], ja[0][0] + ks - s * jb[0][0], ja[0][1], s * jb[0][1]],
            [ja[1][0], ja[1][0], ja[1][1], 0.0],
            [jb[1][0], -jb[1][0], 0.0, jb[1][1]],
        ]
        if self.kind == _TANDEM:
            rows.append([0.0, 2.0, 0.0, 0.0])
        elif self.kind == _RIGID:
            rows.append([2.0, 0.0, 0.0, 0.0])
        else:
            k2 = 0.5 / self.k_loop
            rows.append(
                [
                    2.0 + (ja[0][0] + jb[0][0]) * k2,
                    (ja[0][0] - jb[0][0]) * k2,
                    ja[0][1] * k2,
                    jb[0][1] * k2,
                ]
            )
        return rows

    @cython.ccall
    def newton_step(
        self,
        a11: cython.double,
        a12: cython.double,
        a21: cython.double,
        a22: cython.double,
        b11: cython.double,
        b12: cython.double,
        b21: cython.double,
        b22: cython.double,
        r1: cython.double,
        r2: cython.double,
        r3: cython.double,
        r4: cython.double,
        radial: cython.bint,
    ) -> Step:
        """Newton correction (ok, dp, dz, dδr_A, dδr_B) [m] from the bearings' Jacobians
        (``a11`` = dFa_A/da, ``a12`` = dFa_A/dδr, ``a21`` = dFr_A/da, ``a22`` = dFr_A/dδr
        [N/m], ``b..`` bearing B's) and the residuals of :meth:`residuals`. The radial rows
        hold one bearing each: dδr_A = (−r2 − dFr_A/da·u)/(dFr_A/dδr) with u, v the changes
        of a_A, a_B, which leaves a 2×2 system in (u, v) with e = dFa/da −
        (dFa/dδr)(dFr/da)/(dFr/dδr) each bearing's axial stiffness at balanced radial load:

            (e_A + k_s)·u + σ·e_B·v = −r1 + t_A·r2 + σ·t_B·r3   (σ = −1 in a loop, +1 tandem)

        and the loop row (1 + e_A/2k)·u + (1 + e_B/2k)·v = −r4 + (t_A·r2 + t_B·r3)/(2k), or
        u + v = −r4 (rigid loop), or v − u = r4 (tandem). ``ok`` is False when the system is
        singular (its determinant not positive: no stiffness).

        Returns
        -------
        tuple
            (ok, dp [m], dz [m], dδr_A [m], dδr_B [m]).

        Examples
        --------
        A tandem pair under axial load only: u = −r1/(e_A + e_B + k_s), by hand
        3 N / (3 N/µm) = 1 µm:

        >>> rows = PairRows(True, 0.0, 40.0)
        >>> ok, dp, dz, _, _ = rows.newton_step(2e6, 0, 0, 0, 1e6, 0, 0, 0, -3.0, 0, 0, 0, False)
        >>> ok, round(dp * 1e6, 9), dz
        (True, 1.0, 0.0)
        """
        s: cython.double = self.sign_b
        ta: cython.double = 0.0
        tb: cython.double = 0.0
        if radial:
            if a22 == 0.0 or b22 == 0.0:
                return False, 0.0, 0.0, 0.0, 0.0
            ta, tb = a12 / a22, b12 / b22
            a11, b11 = a11 - ta * a21, b11 - tb * b21
        m11: cython.double = a11 + self.spring
        m12: cython.double = s * b11
        g1: cython.double = -r1 + ta * r2 + s * tb * r3
        m21: cython.double
        m22: cython.double
        g2: cython.double
        if self.kind == _LOOP:
            k2 = 0.5 / self.k_loop
            m21, m22 = 1.0 + a11 * k2, 1.0 + b11 * k2
            g2 = -r4 + (ta * r2 + tb * r3) * k2
        elif self.kind == _RIGID:
            m21, m22, g2 = 1.0, 1.0, -r4
        else:
            m21, m22, g2 = -1.0, 1.0, r4
        det = m11 * m22 - m12 * m21
        if not det > 0.0:
            return False, 0.0, 0.0, 0.0, 0.0
        u = (g1 * m22 - m12 * g2) / det
        v = (m11 * g2 - m21 * g1) / det
        if radial:
            return True, 0.5 * (u + v), 0.5 * (u - v), (-r2 - a21 * u) / a22, (-r3 - b21 * v) / b22
        return True, 0.5 * (u + v), 0.5 * (u - v), 0.0, 0.0

    @cython.ccall
    def axial_stiffness(self, ka: cython.double, kb: cython.double) -> cython.double:
        """Axial stiffness of the shaft in the pair [N/m] from the bearings' dFa/da [N/m]:
        K = k_A + k_B − (k_A − k_B)²/(4k + k_A + k_B) in a loop of stiffness k (differentiating
        its two conditions; k_A + k_B when rigid), K = k_A + k_B + k_s for a tandem pair (its
        spring relaxing as the shaft moves along the thrust). Floats or arrays.

        Returns
        -------
        float or ndarray
            K [N/m].

        Examples
        --------
        >>> PairRows(False, 2e7, 0.0).axial_stiffness(1e7, 1e7)  # N/m: 2·k_b when symmetric
        20000000.0
        >>> PairRows(True, 1e5, 40.0).axial_stiffness(1.0e7, 1.2e7)  # N/m
        22100000.0
        """
        if self.kind == _TANDEM:
            return ka + kb + self.spring
        if self.kind == _RIGID:
            return ka + kb
        return ka + kb - (ka - kb) ** 2 / (4.0 * self.k_loop + ka + kb)


# ------------------------------------------------------------------ the pair's data as floats
@cython.final
@cython.cclass
class PairConstants:
    """The pair's data as floats, for the per-step equations (built once per configuration).

    Parameters
    ----------
    pair : :class:`~.bearing.BearingPair`
    """

    pair: object
    t0: cython.double
    outer_diameter: cython.double
    bore: cython.double
    outer_groove: cython.double
    inner_groove: cython.double
    ball_diameter: cython.double
    inner_curvature: cython.double
    outer_curvature: cython.double
    n_balls: cython.int
    compliance: cython.double
    c_delta_coef: cython.double
    a_coef: cython.double
    alpha_ring: cython.double
    alpha_ball: cython.double
    alpha_housing: cython.double
    e_housing: cython.double
    nu_housing: cython.double
    alpha_shaft: cython.double
    e_shaft: cython.double
    nu_shaft: cython.double
    outer_interference: cython.double
    inner_interference: cython.double
    housing_outer_diameter: cython.double
    shaft_bore: cython.double
    coupled: cython.bint
    seat_outer: cython.double
    seat_inner: cython.double
    outer_ring_compliance: cython.double
    inner_ring_compliance: cython.double
    outer_groove_per_pressure: cython.double
    inner_groove_per_pressure: cython.double
    closure_housing: cython.double
    closure_shaft: cython.double
    closure_rings: cython.double
    closure0: cython.double
    tandem: cython.bint
    rows: PairRows
    spring_stiffness: cython.double
    viscosity: object
    law: cython.int
    law_a: cython.double
    law_b: cython.double
    law_c: cython.double
    hold_temperature: cython.double
    lubricated: cython.bint
    lower_limit: cython.double
    upper_limit: cython.double
    solid: cython.bint
    sliding: cython.bint
    pressure_limit: cython.double
    model: cython.int
    grease: cython.bint
    density: cython.double
    hysteresis_loss: cython.double
    mu: cython.double
    static_ratio: cython.double
    s0: cython.double
    rest_s0: cython.double
    w_reg: cython.double
    w_stribeck: cython.double
    python: object
    __slots__ = (
        "a_coef",
        "alpha_ball",
        "alpha_housing",
        "alpha_ring",
        "alpha_shaft",
        "ball_diameter",
        "bore",
        "c_delta_coef",
        "closure0",
        "closure_housing",
        "closure_rings",
        "closure_shaft",
        "compliance",
        "coupled",
        "density",
        "e_housing",
        "e_shaft",
        "grease",
        "hold_temperature",
        "housing_outer_diameter",
        "hysteresis_loss",
        "inner_curvature",
        "inner_groove",
        "inner_groove_per_pressure",
        "inner_interference",
        "inner_ring_compliance",
        "law",
        "law_a",
        "law_b",
        "law_c",
        "lower_limit",
        "lubricated",
        "model",
        "mu",
        "n_balls",
        "nu_housing",
        "nu_shaft",
        "outer_curvature",
        "outer_diameter",
        "outer_groove",
        "outer_groove_per_pressure",
        "outer_interference",
        "outer_ring_compliance",
        "pair",
        "pressure_limit",
        "python",
        "rest_s0",
        "rows",
        "s0",
        "seat_inner",
        "seat_outer",
        "shaft_bore",
        "sliding",
        "solid",
        "spring_stiffness",
        "static_ratio",
        "t0",
        "tandem",
        "upper_limit",
        "viscosity",
        "w_reg",
        "w_stribeck",
    )

    def __init__(self, pair):
        from ..materials import reduced_compliance
        from . import state as pair_state  # the pair-level functions (imported when first used)
        from .configuration import closure_coefficients, pair_rows

        b, m = pair.bearing, pair.mounting
        fit = m.fit
        ring, ball = b.ring_material, b.ball_material
        hm, sm = fit.housing_material, fit.shaft_material
        self.pair = pair
        self.python = pair_state
        self.t0 = float(m.assembly_temperature)
        self.outer_diameter, self.bore = float(b.outer_diameter), float(b.bore)
        self.outer_groove = float(b.outer_groove_diameter)
        self.inner_groove = float(b.inner_groove_diameter)
        self.ball_diameter = float(b.ball_diameter)
        self.inner_curvature = float(b.inner_curvature)
        self.outer_curvature = float(b.outer_curvature)
        self.n_balls = int(b.n_balls)
        eta = float(reduced_compliance(ring, ball))
        self.compliance = eta
        # c_δ = C_c·K·X and a_coef = C_a/X with X = (Σρ/(k²·E))^(1/3): hertz._constants
        # rearranged (b_coef = a_coef/k), one cube root per contact
        self.c_delta_coef = 0.5 * _2_PI * _PI_2**_THIRD * (1.5 * eta) ** (2.0 / 3.0)
        self.a_coef = (3.0 * eta / _PI) ** _THIRD
        self.alpha_ring = ring.expansion
        self.alpha_ball = ball.expansion
        self.alpha_housing, self.e_housing = hm.expansion, hm.youngs_modulus
        self.nu_housing = hm.poisson_ratio
        self.alpha_shaft, self.e_shaft = sm.expansion, sm.youngs_modulus
        self.nu_shaft = sm.poisson_ratio
        self.outer_interference = float(fit.outer_interference)
        self.inner_interference = float(fit.inner_interference)
        self.housing_outer_diameter = float(fit.housing_outer_diameter)
        self.shaft_bore = float(fit.shaft_bore)
        self.coupled = bool(pair.thermal_coupling)
        # the Lamé terms of fits.mounted_geometry whose diameters grow together (ring with its
        # groove): ring compliances per diameter, and the groove's change per unit pressure
        od, og, bo, ig = self.outer_diameter, self.outer_groove, self.bore, self.inner_groove
        e_r, nu_r = ring.youngs_modulus, ring.poisson_ratio
        self.seat_outer = od - self.outer_interference  # housing bore at T0
        self.seat_inner = bo + self.inner_interference  # shaft seat at T0
        self.outer_ring_compliance = (lame_ratio(og, od) - nu_r) / e_r
        self.inner_ring_compliance = (lame_ratio(bo, ig) + nu_r) / e_r
        self.outer_groove_per_pressure = 2.0 * od * od * og / (e_r * (od * od - og * og))
        self.inner_groove_per_pressure = 2.0 * bo * bo * ig / (e_r * (ig * ig - bo * bo))
        # loop closure C = C0 − Σ σ·L·α·(T_part − T0), summed by part (a tandem pair: B's
        # mismatch d(T), 0 at T0; pair.loop_closure)
        closure = closure_coefficients(pair)
        self.closure0, self.closure_housing, self.closure_shaft, self.closure_rings = closure
        rows = pair_rows(pair)
        self.tandem = rows.is_tandem
        self.rows = PairRows(rows.is_tandem, rows.stiffness, rows.thrust)
        self.spring_stiffness = self.rows.spring
        visc = pair.lubricant
        # the lubricant's law on floats, held below its flow limit when the user chose so, and
        # the range of its data (:mod:`.lubrication.viscosity`)
        self.viscosity = None if visc is None else visc.operating_viscosity_at
        self.law, self.law_a, self.law_b, self.law_c = _law(visc)
        self.hold_temperature = 0.0 if visc is None else visc.hold_temperature
        self.lubricated = visc is not None
        self.lower_limit = 0.0 if visc is None else visc.lower_limit
        self.upper_limit = _INF if visc is None else visc.upper_limit
        self.solid = pair.lubrication == "solid"
        self.sliding = bool(pair.sliding)
        self.pressure_limit = float(pair.pressure_limit)
        fm = pair.friction
        self.model = _MODELS[fm.model]
        self.grease = fm.grease is not None
        self.density = float(fm.lubricant_density)
        co = pair.coefficients
        self.hysteresis_loss, self.mu = co.hysteresis_loss, co.sliding_friction
        self.static_ratio = co.static_friction_ratio
        # Palmgren's s0 running (a lubricant) and at rest (the yu2017 model only)
        self.s0 = co.palmgren_s0 if visc is not None else 0.0
        self.rest_s0 = self.s0 if self.model == _YU else 0.0
        self.w_reg = float(pair.regularisation_speed)
        self.w_stribeck = float(pair.stribeck_speed)

    @property
    def loop_stiffness(self) -> float:
        """The loop's stiffness [N/m] (a tandem pair: its spring's)."""
        return self.rows.stiffness


def _law(visc) -> tuple:
    """(law, a, b, c) of a viscosity model: Walther's (1, a, b, c), Vogel's (2, a, b, T∞),
    none (0: a dry film), or another model (3: its own method)."""
    from ..lubrication.viscosity import VogelViscosity, WaltherViscosity

    if visc is None:
        return _NO_LAW, 0.0, 0.0, 0.0
    if isinstance(visc, WaltherViscosity):
        return _WALTHER, visc.a, visc.b, visc.c
    if isinstance(visc, VogelViscosity):
        return _VOGEL, visc.a, visc.b, visc.t_inf
    return _OTHER_LAW, 0.0, 0.0, 0.0


@cython.cfunc
def _viscosity(c: PairConstants, t: cython.double) -> cython.double:
    """The viscosity [m²/s] the bearing uses at the lubricant's temperature ``t`` [K] (Yu 2017
    eq 18 or Vogel's law, held below the flow limit when chosen; :mod:`.lubrication.viscosity`)."""
    if c.law == _NO_LAW:
        return 0.0
    nu: cython.double = _INF
    at: cython.double = _operating_temperature(t, c.hold_temperature)
    if c.law == _WALTHER:
        nu = _walther_cst(log10(at), c.law_a, c.law_b, c.law_c) * _CST
    elif c.law == _VOGEL:
        nu = exp(_vogel_exponent(at, c.law_a, c.law_b, c.law_c))
    if nu < _INF:
        return nu
    return c.viscosity(t)  # another law, or none at this temperature: the model's own error


# ------------------------------------------------------------------ the thermal state
@cython.final
@cython.cclass
class Thermal:
    """Thermal state of one step, as floats: the fields of :class:`~.pair.state.ThermalState`
    that the outputs read, and the race geometry of :class:`~.contact.geometry.RaceGeometry` that
    the contacts need (γ scale Dw/dm, 1/f = Dw/r of each groove); some evaluated when first
    needed (the viscous torque at rest, the torque coefficients, a tandem pair's offset at
    zero external load)."""

    t_housing: cython.double
    t_shaft: cython.double
    t_outer: cython.double
    t_inner: cython.double
    ball_diameter: cython.double
    clearance: cython.double
    closure: cython.double
    curvature_distance: cython.double
    dw_third: cython.double
    first_contact_offset: cython.double
    gamma_scale: cython.double
    inner_fit_pressure: cython.double
    inner_groove_radius: cython.double
    inner_interference: cython.double
    inv_f_inner: cython.double
    inv_f_outer: cython.double
    kinematic_viscosity: cython.double
    outer_fit_pressure: cython.double
    outer_groove_radius: cython.double
    outer_interference: cython.double
    outside_lubricant_range: cython.bint
    pitch_diameter: cython.double
    radial_centre_distance: cython.double
    has_rest: cython.bint
    rest_torque: cython.double
    has_rest_offset: cython.bint
    rest_offset: cython.double
    has_coefficients: cython.bint
    c_hysteresis: cython.double
    c_sliding_inner: cython.double
    c_sliding_outer: cython.double
    c_spin: cython.double
    __slots__ = (
        "ball_diameter",
        "c_hysteresis",
        "c_sliding_inner",
        "c_sliding_outer",
        "c_spin",
        "clearance",
        "closure",
        "curvature_distance",
        "dw_third",
        "first_contact_offset",
        "gamma_scale",
        "has_coefficients",
        "has_rest",
        "has_rest_offset",
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
        "t_housing",
        "t_inner",
        "t_outer",
        "t_shaft",
    )

    @property
    def temperatures(self) -> tuple:
        """(housing, shaft, outer ring, inner ring) [K]."""
        return (self.t_housing, self.t_shaft, self.t_outer, self.t_inner)

    @property
    def free_contact_angle(self) -> float:
        """Free contact angle at the operating clearance [rad] (:class:`RaceGeometry`)."""
        return _free_angle(self)

    @property
    def torque_coefficients(self) -> tuple:
        """:func:`torque_coefficients` at this state (evaluated when first needed)."""
        return torque_coefficients(self)


@cython.cfunc
def _free_angle(th: Thermal) -> cython.double:
    a: cython.double = th.curvature_distance
    pd: cython.double = th.clearance
    return acos(min(max(1.0 - max(pd, 0.0) / (2.0 * a), -1.0), 1.0))


@cython.ccall
def thermal_at(
    c: PairConstants,
    t_h: cython.double,
    t_s: cython.double,
    t_o: cython.double,
    t_i: cython.double,
) -> Thermal:
    """Thermal state at the parts' temperatures (housing ``t_h``, shaft ``t_s``, outer ring
    ``t_o``, inner ring ``t_i``) [K]: the equations of :func:`fits.mounted_geometry` (Yu 2017
    eq 10–13; the Lamé ratio :func:`lame_ratio`), the loop closure (:func:`loop_closure_at`,
    eq 14–15) and the lubricant's viscosity (eq 18, or Vogel's law; :mod:`.lubrication.viscosity`)
    on floats, with the lubricant's range flag.

    Parameters
    ----------
    c : PairConstants
        The pair's data.
    t_h, t_s, t_o, t_i : float
        Temperatures [K].

    Returns
    -------
    Thermal
        Lengths [m], pressures [Pa], viscosity [m²/s].

    Examples
    --------
    At the assembly temperature the grooves keep their curvature, 1/f_i = 1/0.56 (by hand),
    and the clearance is that of :func:`fits.mounted_geometry` (9.6583 µm, 4.4114 MPa):

    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> round(th.inv_f_inner, 12) == round(1 / 0.56, 12)
    True
    >>> round(th.clearance * 1e6, 4), round(th.outer_fit_pressure / 1e6, 4)  # µm, MPa
    (9.6583, 4.4114)
    """
    t0: cython.double = c.t0
    t_b: cython.double = 0.5 * (t_o + t_i)
    grow_o: cython.double = 1.0 + c.alpha_ring * (t_o - t0)
    grow_i: cython.double = 1.0 + c.alpha_ring * (t_i - t0)
    grow_h: cython.double = 1.0 + c.alpha_housing * (t_h - t0)
    grow_s: cython.double = 1.0 + c.alpha_shaft * (t_s - t0)
    d_ring_o: cython.double = c.outer_diameter * grow_o
    d_ring_i: cython.double = c.bore * grow_i
    d_groove_o: cython.double = c.outer_groove * grow_o
    d_groove_i: cython.double = c.inner_groove * grow_i
    delta_o: cython.double = d_ring_o - c.seat_outer * grow_h
    delta_i: cython.double = c.seat_inner * grow_s - d_ring_i
    p_o: cython.double = 0.0
    p_i: cython.double = 0.0
    th: Thermal = Thermal.__new__(Thermal)
    if c.coupled:
        d_h = c.housing_outer_diameter * grow_h
        d_sb = c.shaft_bore * grow_s
        k_out = (lame_ratio(d_ring_o, d_h) + c.nu_housing) / c.e_housing
        p_o = max(delta_o, 0.0) / (d_ring_o * (c.outer_ring_compliance + k_out))
        k_in = (lame_ratio(d_sb, d_ring_i) - c.nu_shaft) / c.e_shaft
        p_i = max(delta_i, 0.0) / (d_ring_i * (k_in + c.inner_ring_compliance))
        d_groove_o = d_groove_o - p_o * grow_o * c.outer_groove_per_pressure
        d_groove_i = d_groove_i + p_i * grow_i * c.inner_groove_per_pressure
    dw: cython.double = c.ball_diameter * (1.0 + c.alpha_ball * (t_b - t0))
    r_i: cython.double = c.inner_curvature * c.ball_diameter * grow_i
    r_o: cython.double = c.outer_curvature * c.ball_diameter * grow_o
    pd: cython.double = d_groove_o - d_groove_i - 2.0 * dw
    a: cython.double = r_i + r_o - dw
    dm: cython.double = 0.5 * (d_groove_i + d_groove_o)
    th.t_housing, th.t_shaft, th.t_outer, th.t_inner = t_h, t_s, t_o, t_i
    th.ball_diameter, th.dw_third = dw, cbrt(dw)
    th.has_rest = th.has_coefficients = th.has_rest_offset = False  # when first needed
    th.rest_torque = th.rest_offset = 0.0
    th.c_hysteresis = th.c_sliding_inner = th.c_sliding_outer = th.c_spin = 0.0
    th.pitch_diameter = dm
    th.inner_groove_radius, th.outer_groove_radius = r_i, r_o
    th.inv_f_inner, th.inv_f_outer = dw / r_i, dw / r_o
    th.gamma_scale = dw / dm
    th.clearance = pd
    th.curvature_distance = a
    th.radial_centre_distance = a - 0.5 * pd
    th.closure = loop_closure_at(
        c.closure0, c.closure_housing, c.closure_shaft, c.closure_rings, t0, t_h, t_s, t_b
    )
    th.kinematic_viscosity = _viscosity(c, t_b)
    th.outside_lubricant_range = not c.lower_limit <= t_b <= c.upper_limit
    hp: cython.double = 0.5 * min(max(pd, 0.0), 2.0 * a)  # geometry.first_contact_offset
    th.first_contact_offset = sqrt(max(a * a - (a - hp) * (a - hp), 0.0))
    th.outer_fit_pressure, th.inner_fit_pressure = p_o, p_i
    th.outer_interference, th.inner_interference = delta_o, delta_i
    return th


def thermal_floats(c: PairConstants, temps) -> Thermal:
    """:func:`thermal_at` at ``temps`` = (housing, shaft, outer ring, inner ring) [K].

    Parameters
    ----------
    c : PairConstants
        The pair's data.
    temps : tuple of 4 floats
        Temperatures [K].

    Returns
    -------
    Thermal
        Lengths [m], pressures [Pa], viscosity [m²/s].

    Examples
    --------
    The lubricant's law at −20 °C (within its data):

    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> nu = thermal_floats(PairConstants(pair), (253.15,) * 4).kinematic_viscosity
    >>> nu == float(pair.lubricant.kinematic_viscosity(253.15))
    True
    """
    t_h, t_s, t_o, t_i = temps
    return thermal_at(c, t_h, t_s, t_o, t_i)


# ------------------------------------------------------------------ Hertz constants per contact
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
        710.00, 710.02) and their derivatives, F(k) of :func:`hertz.hertz_relation`."""
        m: cython.double = 1.0 - 1.0 / (k * k)
        ki: cython.double = float(ellipk(m))
        ei: cython.double = float(ellipe(m))
        q: cython.double = 1.0 - m
        k1: cython.double = (ei - q * ki) / (2.0 * m * q)
        e1: cython.double = (ei - ki) / (2.0 * m)
        # (E − qK)' = E' + K − qK';  (2mq)' = 2(1 − 2m)
        k2: cython.double = (
            (e1 + ki - q * k1) * 2.0 * m * q - (ei - q * ki) * 2.0 * (1.0 - 2.0 * m)
        ) / ((2.0 * m * q) ** 2)
        e2: cython.double = (e1 - k1) / (2.0 * m) - (ei - ki) / (2.0 * m * m)
        # F = N/D, N = (k² + 1)E − 2K, D = (k² − 1)E, as functions of k through m = 1 − 1/k²
        mk: cython.double = 2.0 / (k * k * k)
        mkk: cython.double = -6.0 / (k * k * k * k)
        ek: cython.double = e1 * mk
        ekk: cython.double = e2 * mk * mk + e1 * mkk
        kk_: cython.double = k1 * mk
        kkk: cython.double = k2 * mk * mk + k1 * mkk
        kq: cython.double = k * k
        n: cython.double = (kq + 1.0) * ei - 2.0 * ki
        d: cython.double = (kq - 1.0) * ei
        nk: cython.double = 2.0 * k * ei + (kq + 1.0) * ek - 2.0 * kk_
        dk: cython.double = 2.0 * k * ei + (kq - 1.0) * ek
        nkk: cython.double = 2.0 * ei + 4.0 * k * ek + (kq + 1.0) * ekk - 2.0 * kkk
        dkk: cython.double = 2.0 * ei + 4.0 * k * ek + (kq - 1.0) * ekk
        f1: cython.double = (nk * d - n * dk) / (d * d)
        self.k, self.m, self.k_int, self.e_int = k, m, ki, ei
        self.f = n / d
        self.f1 = f1
        self.f2 = (nkk * d - n * dkk) / (d * d) - 2.0 * dk * f1 / d
        self.inv_f1, self.f2_f1 = 1.0 / f1, self.f2 / f1
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
    den: cython.double = 4.0 - inv_f + rt  # Σρ·Dw
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
    q: cython.double = ((inv_f + rt) / den - anc.f) * inv_f1  # Δk to first order
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
    x: cython.double = cbrt(den / (k * k * ei))
    cd: cython.double = c.c_delta_coef * ki * x  # c_δ = C·K·X
    lc_g: cython.double = lk_g + lx_g
    ac: cython.double = c.a_coef / x  # a_coef = C_a/X
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

    g = th.gamma_scale * cos_a
    inv_f = th.inv_f_inner if inner else th.inv_f_outer
    rt = 2.0 * g / (1.0 - g) if inner else -2.0 * g / (1.0 + g)
    return float(ellipticity((inv_f + rt) / (4.0 - inv_f + rt)))


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
    a2: cython.double
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
    for b in balls:
        cp = b.cos_psi
        a2 = a2_0 + dr * cp
        s = hypot(a, a2)
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
        csum = ci + co
        k_n = 1.0 / (csum * sqrt(csum))
        root = sqrt(delta)
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


@cython.ccall
def torque_coefficients(th: Thermal) -> tuple:
    """Coefficients of one ball's torque terms at the thermal state ``th`` (evaluated once per
    state): (hysteresis 3·α_r/(8·Dw) [1/m] per Q·b·r, Heathcote sliding of the inner and outer
    race [1/m²] per Q·a²·r (0 without differential sliding), spin 3μ/8 [-] per Q·a·E(e)): the
    kernels of :mod:`.friction.terms` at unit load, semi-axes and E(e).

    Parameters
    ----------
    th : Thermal
        Thermal state of the step (Dw [m], groove radii [m]); its pair's coefficients are
        those of the :class:`PairConstants` it was made with (:func:`set_coefficients`).

    Returns
    -------
    tuple
        (hysteresis [1/m], inner sliding [1/m²], outer sliding [1/m²], spin [-]).

    Examples
    --------
    Yu's pair (α_r = 0.007, μ = 0.0817, no differential sliding): by hand
    3 · 0.007 / (8 · 2.381 mm) = 1.1025 /m and 3 · 0.0817 / 8 = 0.0307:

    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> h, sl_i, sl_o, sp = set_coefficients(th, c)
    >>> round(h, 4), sl_i, sl_o, round(sp, 4)  # 1/m, 1/m², 1/m², -
    (1.1025, 0.0, 0.0, 0.0307)
    """
    return th.c_hysteresis, th.c_sliding_inner, th.c_sliding_outer, th.c_spin


@cython.ccall
def set_coefficients(th: Thermal, c: PairConstants) -> tuple:
    """Evaluate :func:`torque_coefficients` of ``th`` for the pair ``c`` (once per state).

    Returns
    -------
    tuple
        (hysteresis [1/m], inner sliding [1/m²], outer sliding [1/m²], spin [-]).

    Examples
    --------
    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("ning_space_shaft", "mos2_film"))
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> set_coefficients(th, c)[1] > 0.0  # solid film: differential sliding on
    True
    """
    if not th.has_coefficients:
        dw: cython.double = th.ball_diameter
        th.c_hysteresis = _hysteresis(1.0, 1.0, dw, c.hysteresis_loss)
        if c.sliding:
            th.c_sliding_inner = _heathcote(1.0, 1.0, dw, th.inner_groove_radius, c.mu)
            th.c_sliding_outer = _heathcote(1.0, 1.0, dw, th.outer_groove_radius, c.mu)
        else:
            th.c_sliding_inner = th.c_sliding_outer = 0.0
        th.c_spin = _spin(1.0, 1.0, 1.0, c.mu)
        th.has_coefficients = True
    return th.c_hysteresis, th.c_sliding_inner, th.c_sliding_outer, th.c_spin


@cython.ccall
def ring_sums(th: Thermal, c: PairConstants, balls: list, ehl: object = None) -> Sums:
    """Weighted sums over one bearing's balls at their last evaluation: (hysteresis, spin,
    sliding, inner ring, outer ring torques [N·m], largest pressure [Pa], Σ w·Q [N],
    Σ w·Q·α [N·rad], Fa [N], redo), with the Hertz constants from the balls' bases. With
    ``ehl`` five lists (``ehl_per_contact``), the terms of
    :func:`.friction.ehl_per_contact.contact_rolling_terms` of every loaded contact (inner, then
    outer, ball by ball; the scale times the ball's weight) are appended to them.

    The torques are those of :func:`friction.ball_torque_terms` (Yu 2017 eq 1–3, 5–7; Ning)
    at the race radii (dm ∓ Dw·cos α)/2: each term is a product of powers of the load, the
    semi-axes and E(e), so its coefficient is the friction kernel at unit arguments
    (:func:`set_coefficients`) and a ball costs a few products (tests/test_continuation.py
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
        p = 1.5 * q3 / (_PI * min(a_i * b_i, a_o * b_o))
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
    """Append the inner and outer contact's :func:`.friction.ehl_per_contact.contact_rolling_terms`
    of one ball (load ``q`` [N], weight ``w``) to the five lists of ``ehl``."""
    terms = c.python.contact_rolling_terms
    dw, dm = th.ball_diameter, th.pitch_diameter
    for a, k, e, inv_f, on_inner in (
        (a_i, k_i, e_i, th.inv_f_inner, True),
        (a_o, k_o, e_o, th.inv_f_outer, False),
    ):
        t = terms(q, a * q3, k, e, g, dw, dm, inv_f, c.compliance, eta, on_inner)
        ehl[0].append(w * t[0])
        for j in range(1, 5):
            ehl[j].append(t[j])


# ------------------------------------------------------------------ the output record
@cython.dataclasses.dataclass
@cython.cclass
class PointState:
    """Everything BearingFriction reports at one operating point except what moves with speed,
    as floats: the per-step state of :class:`~.bearing.BearingModel` (from the continuation or
    the exact path), with the Coulomb torque, breakaway excess, pitch diameter [m], kinematic
    viscosity [m²/s] and friction model data (``rolling``, :func:`~.pair.state.rolling_data`
    as floats: JSON-serialisable) that the speed terms need. Fields as
    :class:`~.pair.state.BearingOutputs` (torques [N·m], forces [N], angle [rad], lengths
    [m], stiffness [N/m], pressures [Pa]); ``sliding_torque`` is that of the contacts (the SKF
    model's moves with speed)."""

    hysteresis_torque: cython.double
    spin_torque: cython.double
    sliding_torque: cython.double
    inner_ring_torque: cython.double
    outer_ring_torque: cython.double
    coulomb_torque: cython.double
    breakaway_excess: cython.double
    breakaway_torque: cython.double
    preload: cython.double
    contact_angle: cython.double
    radial_clearance: cython.double
    kinematic_viscosity: cython.double
    pitch_diameter: cython.double
    axial_stiffness: cython.double
    max_contact_pressure: cython.double
    outer_fit_pressure: cython.double
    inner_fit_pressure: cython.double
    outer_interference: cython.double
    inner_interference: cython.double
    force_a: cython.double
    force_b: cython.double
    axial_displacement: cython.double
    overloaded: cython.bint
    locked: cython.bint
    unloaded: cython.bint
    reverse_loaded: cython.bint
    outside_lubricant_range: cython.bint
    axial_play: cython.double
    rolling: object = None

    def as_dict(self) -> dict:
        """The fields as a JSON-serialisable dict.

        Returns
        -------
        dict
        """
        return {name: getattr(self, name) for name in POINT_FIELDS}


#: The fields of :class:`PointState`, in order.
POINT_FIELDS = (
    "hysteresis_torque",
    "spin_torque",
    "sliding_torque",
    "inner_ring_torque",
    "outer_ring_torque",
    "coulomb_torque",
    "breakaway_excess",
    "breakaway_torque",
    "preload",
    "contact_angle",
    "radial_clearance",
    "kinematic_viscosity",
    "pitch_diameter",
    "axial_stiffness",
    "max_contact_pressure",
    "outer_fit_pressure",
    "inner_fit_pressure",
    "outer_interference",
    "inner_interference",
    "force_a",
    "force_b",
    "axial_displacement",
    "overloaded",
    "locked",
    "unloaded",
    "reverse_loaded",
    "outside_lubricant_range",
    "axial_play",
    "rolling",
)


@cython.cfunc
def _speed(c: PairConstants, pt: PointState, w: cython.double) -> Speed:
    """(signed friction, running, sliding, viscous, grease torque) [N·m] of the state ``pt``
    at speed ``w`` [rad/s] (Yu 2017 eq 8–9 and the regularised sign; another friction model or
    a grease term through ``pair_state._speed_terms``)."""
    if c.model != _YU or c.grease:
        return c.python._speed_terms(
            c.pair, pt.kinematic_viscosity, pt.pitch_diameter, pt.coulomb_torque,
            pt.breakaway_excess, pt.sliding_torque, pt.rolling, w,
        )  # fmt: skip
    viscous: cython.double = 2.0 * _palmgren(pt.kinematic_viscosity, w, pt.pitch_diameter, c.s0)
    running: cython.double = pt.coulomb_torque + viscous
    signed: cython.double = _regularised(w, running, pt.breakaway_excess, c.w_reg, c.w_stribeck)
    return signed, running, pt.sliding_torque, viscous, 0.0


def speed_terms(c: PairConstants, point: PointState, w: float) -> tuple:
    """(signed friction, running, sliding, viscous, grease torque) [N·m] of the state
    ``point`` at speed ``w`` [rad/s] (Yu 2017 eq 8–9, or the pair's friction model;
    regularised sign).

    Returns
    -------
    tuple
        Five torques [N·m].

    Examples
    --------
    At rest the regularised sign gives no torque, and the running torque is the Coulomb
    torque plus Palmgren's at rest:

    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> solver = PairSolver(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> point = solver.update(253.15, 253.15, 253.15, 253.15, 5.0, 0.0)
    >>> signed, running, sliding, viscous, grease = speed_terms(solver.constants, point, 0.0)
    >>> signed, running == point.coulomb_torque + viscous, sliding, grease
    (0.0, True, 0.0, 0.0)
    """
    return _speed(c, point, w)


# ------------------------------------------------------------------ the continuation
@cython.cfunc
def _parallel(
    a0: cython.double,
    a1: cython.double,
    a2: cython.double,
    a3: cython.double,
    b0: cython.double,
    b1: cython.double,
    b2: cython.double,
    b3: cython.double,
) -> cython.double:
    """θ with a ≈ θ·b for the 4-vectors a and b when they are parallel (cosine above
    1 − 1e-6) and point the same way; else 0."""
    dot = a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3
    n0 = b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3
    if dot <= 0.0 or dot * dot < (1.0 - 1e-6) * n0 * (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3):
        return 0.0
    return dot / n0


_AXIAL: cython.int = 1
_RADIAL: cython.int = 2
_MODE_NAMES = {0: None, 1: "axial", 2: "radial"}


@cython.final
@cython.cclass
class PairSolver:
    """Continuation solve of one :class:`~.pair.configuration.BearingPair` (see module docstring),
    and the per-step update of its state (:meth:`update`).

    :meth:`solve` takes the thermal state of a step (:func:`thermal_at`) and the external
    loads, and returns the step's :class:`PointState`, or None when the warm start fails;
    :meth:`start` solves from the unloaded pair; the caller solves exactly when that fails
    too and :meth:`seed` s the solver with that solution (:meth:`accept` makes it the state).

    Parameters
    ----------
    pair : BearingPair
    """

    c: PairConstants
    half_ring: list
    mode: cython.int
    has_x: cython.bint
    x0: cython.double
    x1: cython.double
    x2: cython.double
    x3: cython.double
    rings: list
    u0: cython.double
    u1: cython.double
    u2: cython.double
    u3: cython.double
    u4: cython.double
    u5: cython.double
    has_jac: cython.bint
    jac_a: Ring
    jac_b: Ring
    new_a: Ring
    new_b: Ring
    has_secant: cython.bint
    sx0: cython.double
    sx1: cython.double
    sx2: cython.double
    sx3: cython.double
    st0: cython.double
    st1: cython.double
    st2: cython.double
    st3: cython.double
    th: Thermal
    point: PointState
    p0: cython.double
    p1: cython.double
    p2: cython.double
    p3: cython.double
    p4: cython.double
    p5: cython.double
    n_steps: cython.int
    n_cold: cython.int
    __slots__ = (
        "c",
        "half_ring",
        "has_jac",
        "has_secant",
        "has_x",
        "jac_a",
        "jac_b",
        "mode",
        "n_cold",
        "n_steps",
        "new_a",
        "new_b",
        "p0",
        "p1",
        "p2",
        "p3",
        "p4",
        "p5",
        "point",
        "rings",
        "st0",
        "st1",
        "st2",
        "st3",
        "sx0",
        "sx1",
        "sx2",
        "sx3",
        "th",
        "u0",
        "u1",
        "u2",
        "u3",
        "u4",
        "u5",
        "x0",
        "x1",
        "x2",
        "x3",
    )  # fmt: skip

    def __init__(self, pair):
        self.c = PairConstants(pair)
        z = self.c.n_balls
        self.half_ring = [
            (math.cos(2.0 * math.pi * j / z), 1.0 if j == 0 or 2 * j == z else 2.0)
            for j in range(z // 2 + 1)
        ]
        self.th = None
        self.point = None
        self.n_steps = self.n_cold = 0
        self.reset()

    @property
    def pair(self):
        """The :class:`~.pair.configuration.BearingPair`."""
        return self.c.pair

    @property
    def constants(self):
        """The pair's :class:`PairConstants`."""
        return self.c

    @property
    def steps(self) -> int:
        """Calls of :meth:`update` that solved a new state (the exact path's included)."""
        return self.n_steps

    @property
    def cold_starts(self) -> int:
        """Of those, the ones solved from the unloaded pair (:meth:`start`)."""
        return self.n_cold

    @property
    def x(self):
        """(p, z, δr_A, δr_B) [m] of the last step, or None."""
        return (self.x0, self.x1, self.x2, self.x3) if self.has_x else None

    @property
    def thermal(self):
        """The thermal state of the current operating point (:func:`thermal_at`), or None."""
        return self.th

    @property
    def current(self):
        """The :class:`PointState` of the current operating point, or None."""
        return self.point

    @cython.ccall
    def reset(self):
        """Forget the last solution: the next step starts from the unloaded pair."""
        self.mode = 0  # _AXIAL (all balls alike) or _RADIAL (per ball)
        self.has_x = self.has_jac = self.has_secant = False
        self.x0 = self.x1 = self.x2 = self.x3 = 0.0
        self.rings = None  # the balls of bearings A and B

    def _layout(self, mode):
        """(cos ψ, weight) of the balls of one bearing in ``mode``."""
        return [(0.0, float(self.c.n_balls))] if mode == _AXIAL else self.half_ring

    # ---------------------------------------------------------------- state
    def state(self) -> dict:
        """JSON-serialisable state (floats): the continuation, the operating point and the
        state there. With :meth:`restore`, a solver continues bit for bit.

        Returns
        -------
        dict
        """
        solver = None
        if self.has_x:
            solver = {
                "mode": _MODE_NAMES[self.mode],
                "x": [self.x0, self.x1, self.x2, self.x3],
                "k": [_anchors_of(ring) for ring in self.rings],
                "base": [_bases_of(ring) for ring in self.rings],
                "inputs": [self.u0, self.u1, self.u2, self.u3, self.u4, self.u5],
                "jacobian": [list(self.jac_a), list(self.jac_b)] if self.has_jac else None,
                "secant": [[self.sx0, self.sx1, self.sx2, self.sx3],
                           [self.st0, self.st1, self.st2, self.st3]]
                if self.has_secant else None,
            }  # fmt: skip
        if self.point is None:
            return {"solver": solver, "point": None, "values": None}
        return {
            "solver": solver,
            "point": [self.p0, self.p1, self.p2, self.p3, self.p4, self.p5],
            "values": self.point.as_dict(),
        }

    def restore(self, state) -> None:
        """Inverse of :meth:`state` (the balls' bases are evaluated again from their γ and
        1/f): a restored solver continues bit for bit."""
        state = state or {"solver": None, "point": None, "values": None}
        self.reset()
        self.th = None
        self.point = None
        solver = state["solver"]
        if solver is not None:
            self.mode = _AXIAL if solver["mode"] == "axial" else _RADIAL
            self.x0, self.x1, self.x2, self.x3 = (float(v) for v in solver["x"])
            self.has_x = True
            layout = self._layout(self.mode)
            self.rings = [
                [
                    Ball(cp, w, Anchor(float(ki)), Anchor(float(ko)))
                    for (cp, w), (ki, ko) in zip(layout, ks, strict=True)
                ]
                for ks in solver["k"]
            ]
            for ring, bases in zip(self.rings, solver["base"], strict=True):
                _set_bases(self.c, ring, bases)
            self.u0, self.u1, self.u2, self.u3, self.u4, self.u5 = (
                float(v) for v in solver["inputs"]
            )
            jac, sec = solver.get("jacobian"), solver.get("secant")
            self.has_jac = jac is not None
            if self.has_jac:
                self.jac_a = tuple(float(v) for v in jac[0])
                self.jac_b = tuple(float(v) for v in jac[1])
            self.has_secant = sec is not None
            if self.has_secant:
                self.sx0, self.sx1, self.sx2, self.sx3 = (float(v) for v in sec[0])
                self.st0, self.st1, self.st2, self.st3 = (float(v) for v in sec[1])
        point = state["point"]
        if point is not None:
            self.p0, self.p1, self.p2, self.p3, self.p4, self.p5 = (float(v) for v in point)
            self.th = thermal_at(self.c, self.p0, self.p1, self.p2, self.p3)
            self.point = PointState(**state["values"])

    def seed(self, th: Thermal, inputs: tuple, x: tuple, ball_cosines=None):
        """Start from an exactly solved state: ``x`` = (p, z) (axial) or (p, z, δr_A, δr_B)
        (radial) [m] at the thermal state ``th`` and ``inputs`` (4 temperatures [K], axial and
        radial load [N]), the anchors at the exact ellipticities of the contacts
        (``ball_cosines``: the per-ball (cos α_A, cos α_B) arrays over half the ring under a
        radial load)."""
        self.reset()
        a2 = th.radial_centre_distance
        if len(x) == 2:
            self.mode = _AXIAL
            p, z = x
            cosines = [[a2 / hypot(p + z, a2)], [a2 / hypot(p - z, a2)]]
            x = (p, z, 0.0, 0.0)
        else:
            self.mode = _RADIAL
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
        self.x0, self.x1, self.x2, self.x3 = (float(v) for v in x)
        self.has_x = True
        self.u0, self.u1, self.u2, self.u3, self.u4, self.u5 = (float(v) for v in inputs)

    @cython.cfunc
    def _switch(self, mode: cython.int):
        """Carry the anchors over between the axial and the radial form (the radial balls
        start from the axial ball's anchors; the axial ball from the ball at ψ = 0)."""
        layout = self._layout(mode)
        first: Ball
        rings = []
        for ring in self.rings:
            first = ring[0]
            rings.append([Ball(cp, w, first.anc_i.copy(), first.anc_o.copy()) for cp, w in layout])
        self.rings = rings
        if mode == _AXIAL:
            self.x2 = self.x3 = 0.0
        self.mode, self.has_jac, self.has_secant = mode, False, False

    # ---------------------------------------------------------------- per step
    @cython.ccall
    def update(
        self,
        t_h: cython.double,
        t_s: cython.double,
        t_o: cython.double,
        t_i: cython.double,
        axial_load: cython.double,
        radial_load: cython.double,
    ) -> PointState:
        """The state at the parts' temperatures [K] and loads [N]: the last one when nothing
        changed, else solved by continuation (the thermal state kept when the temperatures
        did not change), from the unloaded pair when that fails (a cold start: the first call,
        or a failed warm start); None when that fails too (the caller solves exactly and
        calls :meth:`seed` and :meth:`accept`). ValueError names a temperature outside
        (0, inf) K or a load outside (−inf, inf) N.

        Returns
        -------
        PointState or None

        Examples
        --------
        The first call starts cold, and gives the exact path's preload:

        >>> from servofmu.physics.pair import state as pair_state
        >>> from servofmu.physics.pair.configuration import BearingPair
        >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
        >>> solver = PairSolver(pair)
        >>> point = solver.update(233.15, 233.15, 233.15, 233.15, 5.0, 0.0)
        >>> th = pair_state.thermal_state(pair, 233.15)
        >>> exact = float(pair_state.load_state(pair, th, 5.0).preload)
        >>> abs(point.preload - exact) < 1e-9 * exact, solver.cold_starts  # N
        (True, 1)
        """
        if (
            self.point is not None
            and t_h == self.p0
            and t_s == self.p1
            and t_o == self.p2
            and t_i == self.p3
            and axial_load == self.p4
            and radial_load == self.p5
        ):
            return self.point
        if not (0.0 < t_h < _INF and 0.0 < t_s < _INF and 0.0 < t_o < _INF and 0.0 < t_i < _INF):
            _bad_temperature(t_h, t_s, t_o, t_i)
        if not -_INF < axial_load < _INF:
            raise ValueError(
                f"axial_load = {axial_load!r} N is outside the valid range (-inf, inf)"
            )
        if not -_INF < radial_load < _INF:
            raise ValueError(
                f"radial_load = {radial_load!r} N is outside the valid range (-inf, inf)"
            )
        th: Thermal = self.th
        if th is None or not (
            t_h == th.t_housing and t_s == th.t_shaft and t_o == th.t_outer and t_i == th.t_inner
        ):
            th = thermal_at(self.c, t_h, t_s, t_o, t_i)
        point: PointState = self.solve(th, axial_load, radial_load, _ITERATIONS)
        if point is None:  # no last solution, or the warm start failed: a cold start
            self.n_cold += 1
            point = self.start(th, axial_load, radial_load)
        if point is None:
            self.th = th  # the exact path seeds the solver at it
            return None
        self.accept(th, point, axial_load, radial_load)
        return point

    @cython.ccall
    def accept(self, th: Thermal, point: PointState, axial_load: cython.double,
               radial_load: cython.double):  # fmt: skip
        """Make ``point`` at the thermal state ``th`` and the loads [N] the current state."""
        self.th, self.point = th, point
        self.p0, self.p1, self.p2, self.p3 = th.t_housing, th.t_shaft, th.t_outer, th.t_inner
        self.p4, self.p5 = axial_load, radial_load
        self.n_steps += 1

    @cython.ccall
    def speed_outputs(self, w: cython.double) -> tuple:
        """(friction_torque, running_torque, sliding_torque, viscous_torque, grease_torque
        [N·m], power_loss [W]) at speed ``w`` [rad/s] for the current state (ValueError for a
        speed outside (−inf, inf)).

        Returns
        -------
        tuple
            Five torques [N·m] and the power [W].
        """
        if not -_INF < w < _INF:
            raise ValueError(f"speed = {w!r} rad/s is outside the valid range (-inf, inf)")
        signed: cython.double
        running: cython.double
        sliding: cython.double
        viscous: cython.double
        grease: cython.double
        signed, running, sliding, viscous, grease = _speed(self.c, self.point, w)
        return signed, running, sliding, viscous, grease, signed * w

    # ---------------------------------------------------------------- solve
    @cython.ccall
    def start(self, th: Thermal, axial_load: cython.double, radial_load: cython.double
              ) -> PointState:  # fmt: skip
        """A first solution without the exact path: the pair at zero external load (Newton's
        method on the symmetric offset p of 2p + F(p)/k = C from p = C/2, F one bearing's
        axial force: it converges monotonically, F being odd and convex beyond first
        contact), then the external loads added in stages, each solved by :meth:`solve` (its
        predictor and Newton's method) and halved when that fails. The step's
        :class:`PointState`, or None (the solver reset: the caller solves exactly)."""
        half = 0.5 * th.closure  # a tandem pair: a_A = 0, a_B = d
        self.seed(th, (th.t_housing, th.t_shaft, th.t_outer, th.t_inner, 0.0, 0.0),
                  (half, -half if self.c.tandem else 0.0))  # fmt: skip
        point: PointState = self.solve(th, 0.0, 0.0, _START_ITERATIONS)
        done: cython.double = 0.0
        stage: cython.double = 1.0
        while point is not None and done < 1.0:
            share = min(1.0, done + stage)
            nxt = self.solve(th, share * axial_load, share * radial_load, _START_ITERATIONS)
            if nxt is None:
                stage *= 0.5
                if stage < START_SMALLEST_STAGE:
                    point = None
                continue
            point, done, stage = nxt, share, 2.0 * stage
        if point is None:
            self.reset()
        return point

    @cython.ccall
    def solve(
        self,
        th: Thermal,
        axial_load: cython.double,
        radial_load: cython.double,
        iterations: cython.int = MAX_ITERATIONS,
    ) -> PointState:
        """The pair at the thermal state ``th`` under ``axial_load`` (pressing A) and
        ``radial_load`` [N] from the last solution, in at most ``iterations`` Newton
        iterations per anchor round: the step's :class:`PointState`, or None."""
        if not self.has_x:
            return None
        mode: cython.int = _AXIAL if radial_load == 0.0 else _RADIAL
        if mode != self.mode:
            self._switch(mode)
        p: cython.double
        z: cython.double
        da: cython.double
        db: cython.double
        moved: cython.bint
        p, z, da, db, moved = self._predict(th, axial_load, radial_load)
        ok: cython.bint
        ka: cython.double
        kb: cython.double
        symmetric: cython.bint = axial_load == 0.0 and mode == _AXIAL and not self.c.tandem
        at_last: cython.bint = not moved  # the start is the last solution
        point: PointState
        redo: cython.bint
        for _ in range(_ROUNDS):
            ok, p, z, da, db, ka, kb = self._newton(th, axial_load, radial_load, p, z, da, db,
                                                    iterations)  # fmt: skip
            if not ok and not at_last:  # the predictor overshot: from the last step
                ok, p, z, da, db, ka, kb = self._newton(
                    th, axial_load, radial_load, self.x0, self.x1, self.x2, self.x3, iterations
                )
            if not ok:
                return None
            point, redo = self._point(th, p, z, ka, kb, symmetric, radial_load)
            if not redo:
                self._advance(th, axial_load, radial_load, p, z, da, db)
                return point
            at_last = False  # the next round starts from this round's solution
        return None

    @cython.cfunc
    def _load_step(self, d_ext: cython.double, d_r: cython.double) -> Step:
        """First-order change of x [m] for a change of the loads by ``d_ext``, ``d_r`` [N]
        (the Newton step of the load change alone, from the last Jacobian)."""
        if d_ext == 0.0 and d_r == 0.0:
            return True, 0.0, 0.0, 0.0, 0.0
        half = -0.5 * d_r
        a11, a12, a21, a22 = self.jac_a[2], self.jac_a[3], self.jac_a[4], self.jac_a[5]
        b11, b12, b21, b22 = self.jac_b[2], self.jac_b[3], self.jac_b[4], self.jac_b[5]
        return self.c.rows.newton_step(a11, a12, a21, a22, b11, b12, b21, b22, -d_ext, half,
                                       half, 0.0, self.mode == _RADIAL)  # fmt: skip

    @cython.cfunc
    def _predict(
        self, th: Thermal, axial_load: cython.double, radial_load: cython.double
    ) -> tuple[cython.double, cython.double, cython.double, cython.double, cython.bint]:
        """Start of a step: the last solution moved by the tangent of the load change (the
        last Jacobian) and by the secant of the temperature change (the last step's change of
        x less its load part, when the temperatures move on in the same direction)."""
        p: cython.double = self.x0
        z: cython.double = self.x1
        da: cython.double = self.x2
        db: cython.double = self.x3
        moved: cython.bint = False
        ok: cython.bint
        d0: cython.double
        d1: cython.double
        d2: cython.double
        d3: cython.double
        if self.has_jac and (axial_load != self.u4 or radial_load != self.u5):
            ok, d0, d1, d2, d3 = self._load_step(axial_load - self.u4, radial_load - self.u5)
            if ok:
                p, z, da, db = p + d0, z + d1, da + d2, db + d3
                moved = True
        dt0: cython.double = th.t_housing - self.u0
        dt1: cython.double = th.t_shaft - self.u1
        dt2: cython.double = th.t_outer - self.u2
        dt3: cython.double = th.t_inner - self.u3
        if self.has_secant and (dt0 != 0.0 or dt1 != 0.0 or dt2 != 0.0 or dt3 != 0.0):
            theta = _parallel(dt0, dt1, dt2, dt3, self.st0, self.st1, self.st2, self.st3)
            if theta != 0.0:
                p, z = p + theta * self.sx0, z + theta * self.sx1
                da, db = da + theta * self.sx2, db + theta * self.sx3
                moved = True
        return p, z, da, db, moved

    @cython.cfunc
    def _advance(
        self,
        th: Thermal,
        axial_load: cython.double,
        radial_load: cython.double,
        p: cython.double,
        z: cython.double,
        da: cython.double,
        db: cython.double,
    ):
        """Make x at the inputs (Jacobian in ``new_a``, ``new_b``) the last solution, and keep
        the secant of the temperature change from the solution before."""
        dt0: cython.double = th.t_housing - self.u0
        dt1: cython.double = th.t_shaft - self.u1
        dt2: cython.double = th.t_outer - self.u2
        dt3: cython.double = th.t_inner - self.u3
        self.has_secant = False
        ok: cython.bint
        d0: cython.double
        d1: cython.double
        d2: cython.double
        d3: cython.double
        if dt0 != 0.0 or dt1 != 0.0 or dt2 != 0.0 or dt3 != 0.0:
            self.jac_a, self.jac_b = self.new_a, self.new_b
            ok, d0, d1, d2, d3 = self._load_step(axial_load - self.u4, radial_load - self.u5)
            if ok:
                self.sx0, self.sx1 = p - self.x0 - d0, z - self.x1 - d1
                self.sx2, self.sx3 = da - self.x2 - d2, db - self.x3 - d3
                self.st0, self.st1, self.st2, self.st3 = dt0, dt1, dt2, dt3
                self.has_secant = True
        self.x0, self.x1, self.x2, self.x3 = p, z, da, db
        self.u0, self.u1, self.u2, self.u3 = th.t_housing, th.t_shaft, th.t_outer, th.t_inner
        self.u4, self.u5 = axial_load, radial_load
        self.jac_a, self.jac_b, self.has_jac = self.new_a, self.new_b, True

    @cython.cfunc
    def _newton(
        self,
        th: Thermal,
        f_ext: cython.double,
        f_r: cython.double,
        p: cython.double,
        z: cython.double,
        da: cython.double,
        db: cython.double,
        iterations: cython.int,
    ) -> tuple[
        cython.bint,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
    ]:
        """Newton's method from (p, z, δr_A, δr_B) [m] in at most ``iterations`` iterations:
        (ok, the solution, the bearings' output stiffnesses [N/m]); their Jacobians there go
        to ``new_a``, ``new_b`` and the balls hold the loads. A pair in a loop without
        external load keeps z = 0 and B mirrors A (the exact path's symmetric solution); a
        rigid loop holds p = C/2, a tandem pair z = −d/2 (:class:`PairRows`)."""
        c: PairConstants = self.c
        rows: PairRows = c.rows
        closure: cython.double = th.closure
        tol: cython.double = _TOLERANCE * th.curvature_distance
        floor: cython.double = _ROUNDING * th.curvature_distance
        radial: cython.bint = f_r != 0.0
        kind: cython.int = rows.kind
        if kind == _RIGID:
            p = 0.5 * closure
        elif kind == _TANDEM:
            z = -0.5 * closure
        symmetric: cython.bint = kind != _TANDEM and f_ext == 0.0 and not radial
        if symmetric:
            z = 0.0
        ring_a: list = self.rings[0]
        ring_b: list = self.rings[1]
        half: cython.double = 0.5 * f_r
        ra: Ring
        rb: Ring
        r1: cython.double
        r2: cython.double
        r3: cython.double
        r4: cython.double
        ok: cython.bint
        dp: cython.double
        dz: cython.double
        dda: cython.double
        ddb: cython.double
        step: cython.double
        engage: object
        for _ in range(iterations):
            ra = ring_point(th, c, p + z, da, ring_a)
            rb = ra if symmetric else ring_point(th, c, p - z, db, ring_b)
            if radial and (ra[5] == 0.0 or rb[5] == 0.0):
                # a bearing with no ball in contact has no radial stiffness: move it radially
                # until its ball nearest the load's direction carries about F_r/2, and go on
                if ra[5] == 0.0:
                    engage = self._touch(th, p + z, half, ring_a)
                    if engage is None:
                        return False, p, z, da, db, 0.0, 0.0
                    da = engage
                if rb[5] == 0.0:
                    engage = self._touch(th, p - z, half, ring_b)
                    if engage is None:
                        return False, p, z, da, db, 0.0, 0.0
                    db = engage
                continue
            r1, r2, r3, r4 = rows.residuals(ra[0], rb[0], ra[1], rb[1], p, z, closure, f_ext,
                                            f_r)  # fmt: skip
            if symmetric:
                dp = 0.0 if kind == _RIGID else -r4 / (2.0 + ra[2] / rows.k_loop)
                dz = dda = ddb = 0.0
            elif not radial and ra[2] == 0.0 and rb[2] == 0.0 and rows.spring == 0.0:
                # no ball of either bearing touches (axial play): move the shaft along the
                # load until its first contact carries about the load, and go on
                if kind == _TANDEM:
                    engage = self._engage_tandem(th, z, r1)
                    if engage is None:
                        return False, p, z, da, db, 0.0, 0.0
                    p = engage
                else:
                    engage = self._engage(th, p, f_ext)
                    if engage is None:
                        return False, p, z, da, db, 0.0, 0.0
                    z = engage
                continue
            else:
                ok, dp, dz, dda, ddb = rows.newton_step(
                    ra[2], ra[3], ra[4], ra[5], rb[2], rb[3], rb[4], rb[5], r1, r2, r3, r4, radial
                )
                if not ok:
                    return False, p, z, da, db, 0.0, 0.0
            step = max(abs(dp), abs(dz), abs(dda), abs(ddb))
            if step <= tol and (step <= _DEFLECTION_TOLERANCE * min(ra[7], rb[7]) or step <= floor):
                self.new_a, self.new_b = ra, rb
                return True, p, z, da, db, ra[6], rb[6]
            if not step < _INF:
                return False, p, z, da, db, 0.0, 0.0
            p, z, da, db = p + dp, z + dz, da + dda, db + ddb
        return False, p, z, da, db, 0.0, 0.0

    def _engage_tandem(self, th: Thermal, z: float, r1: float):
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

    def _engage(self, th: Thermal, p: float, f: float):
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

    def _touch(self, th: Thermal, a: float, f: float, balls: list):
        """Radial displacement [m] of a bearing at axial offset ``a`` [m] at which its ball
        nearest the direction of the radial force ``f`` [N] carries |f| with the other balls
        free (Hertz: δ = (|f|/(K_n·cos α))^(2/3)): a start for Newton's method where no ball
        touches. None when no radial displacement brings that ball into contact."""
        dist, a2_0 = th.curvature_distance, th.radial_centre_distance
        b: Ball = balls[0]
        ball: Ball
        for ball in balls:  # the ball nearest the force's direction (the first of equals)
            if ball.cos_psi * f > b.cos_psi * f:
                b = ball
        cp = b.cos_psi
        if abs(a) >= dist or cp * f <= 0.0:
            return None
        a2 = math.sqrt(dist * dist - a * a)
        cos_a = a2 / dist
        gamma = th.gamma_scale * cos_a
        ci = contact_terms(self.c, gamma, th.inv_f_inner, True, b.anc_i)[0] / th.dw_third
        co = contact_terms(self.c, gamma, th.inv_f_outer, False, b.anc_o)[0] / th.dw_third
        delta = (abs(f) * (ci + co) ** 1.5 / cos_a) ** (2.0 / 3.0)
        s = dist + delta
        return (math.sqrt(s * s - a * a) - a2_0) / cp

    def _rest_displacement(self, th: Thermal, a_a: float):
        """A tandem pair's axial displacement [m]: a_A less its offset at zero external load
        at the thermal state ``th`` (:func:`pair_state._displacement`), that offset solved once
        per thermal state by :meth:`_newton` on one axial ball per bearing (their anchors A's
        and B's first ball's), from a_A."""
        if not th.has_rest_offset:
            rings = self.rings
            new_a, new_b = self.new_a, self.new_b
            first_a: Ball = rings[0][0]
            first_b: Ball = rings[1][0]
            self.rings = [
                [Ball(0.0, float(self.c.n_balls), first_a.anc_i.copy(), first_a.anc_o.copy())],
                [Ball(0.0, float(self.c.n_balls), first_b.anc_i.copy(), first_b.anc_o.copy())],
            ]
            z = -0.5 * th.closure
            sol = self._newton(th, 0.0, 0.0, a_a - z, z, 0.0, 0.0, START_ITERATIONS)
            self.rings = rings
            self.new_a, self.new_b = new_a, new_b
            th.rest_offset = sol[1] + z if sol[0] else math.nan
            th.has_rest_offset = True
        return a_a - th.rest_offset

    @cython.cfunc
    def _point(
        self,
        th: Thermal,
        p: cython.double,
        z: cython.double,
        ka: cython.double,
        kb: cython.double,
        symmetric: cython.bint,
        radial_load: cython.double,
    ) -> tuple[PointState, cython.bint]:
        """The step's :class:`PointState` from the balls' last evaluation (:func:`ring_sums`):
        torques [N·m], forces [N], the pair's stiffness [N/m], the load-weighted contact angle
        of A [rad], the largest pressure [Pa], flags; and whether an anchor moved so far that
        the step must be solved again. B mirrors A when ``symmetric`` (its anchors follow A's).
        The friction model's data (:func:`~.pair.state.rolling_data`): the bearings' loads
        under ``skf2004`` (``radial_load`` [N] the external one), the contacts' EHL terms under
        ``ehl_per_contact``."""
        c: PairConstants = self.c
        ring_a: list = self.rings[0]
        ring_b: list = self.rings[1]
        ehl = [[], [], [], [], []] if c.model == _EHL else None
        sa: Sums = ring_sums(th, c, ring_a, ehl)
        sb: Sums
        a: Ball
        b: Ball
        if symmetric:
            sb = sa
            for a, b in zip(ring_a, ring_b, strict=True):
                if b.anc_i.k != a.anc_i.k or b.anc_o.k != a.anc_o.k:
                    b.anc_i, b.anc_o, b.base = a.anc_i.copy(), a.anc_o.copy(), None
            if ehl is not None:  # B's contacts are A's
                ehl = [v + v for v in ehl]
        else:
            sb = ring_sums(th, c, ring_b, ehl)
        fa: cython.double = sa[8]
        fb: cython.double = sb[8]
        rolling = None
        if c.model == _EHL:
            rolling = tuple(tuple(v) for v in ehl)
        elif c.model == _SKF:
            rolling = c.python.skf_loads(fa, fb, radial_load)
        p_max: cython.double = max(sa[5], sb[5])
        overloaded: cython.bint
        locked: cython.bint
        unloaded: cython.bint
        reverse: cython.bint
        overloaded, locked, unloaded, reverse = _flags(c.pressure_limit, th.clearance, p_max, fa,
                                                       fb)  # fmt: skip
        a_a: cython.double = p + z
        a_b: cython.double = p - z
        if not th.has_rest:
            th.rest_torque = 2.0 * _palmgren(th.kinematic_viscosity, 0.0, th.pitch_diameter,
                                             c.rest_s0)  # fmt: skip
            th.has_rest = True
        hyst: cython.double = sa[0] + sb[0]
        spin: cython.double = sa[1] + sb[1]
        slide: cython.double = sa[2] + sb[2]
        inner: cython.double = sa[3] + sb[3]
        outer: cython.double = sa[4] + sb[4]
        coulomb: cython.double
        excess: cython.double
        breakaway: cython.double
        if c.model == _YU and not c.grease:  # the default: the per-step hot path
            coulomb, excess = _coulomb_excess(c.static_ratio, hyst, spin, slide)
            breakaway = coulomb + excess + th.rest_torque
        else:
            hyst, spin, slide, inner, outer = c.python.contact_terms(c.pair, hyst, spin, slide,
                                                                     inner, outer)  # fmt: skip
            coulomb, excess, breakaway = c.python.state_torques(
                c.pair, hyst, spin, slide, th.kinematic_viscosity, th.pitch_diameter, rolling,
                th.rest_torque,
            )  # fmt: skip
        displacement: cython.double = self._rest_displacement(th, a_a) if c.tandem else z
        pt: PointState = PointState.__new__(PointState)
        pt.hysteresis_torque, pt.spin_torque, pt.sliding_torque = hyst, spin, slide
        pt.inner_ring_torque, pt.outer_ring_torque = inner, outer
        pt.coulomb_torque, pt.breakaway_excess, pt.breakaway_torque = coulomb, excess, breakaway
        pt.preload = preload_force(fa, fb)
        pt.contact_angle = sa[7] / sa[6] if sa[6] > 0.0 else _free_angle(th)
        pt.radial_clearance = th.clearance
        pt.kinematic_viscosity, pt.pitch_diameter = th.kinematic_viscosity, th.pitch_diameter
        pt.axial_stiffness = c.rows.axial_stiffness(ka, kb)
        pt.max_contact_pressure = p_max
        pt.outer_fit_pressure, pt.inner_fit_pressure = th.outer_fit_pressure, th.inner_fit_pressure
        pt.outer_interference, pt.inner_interference = th.outer_interference, th.inner_interference
        pt.force_a, pt.force_b, pt.axial_displacement = fa, fb, displacement
        pt.overloaded, pt.locked, pt.unloaded, pt.reverse_loaded = (
            overloaded,
            locked,
            unloaded,
            reverse,
        )
        pt.outside_lubricant_range = th.outside_lubricant_range
        pt.axial_play = axial_play(th.first_contact_offset, a_a, a_b, fa, fb)
        pt.rolling = rolling
        return pt, sa[9] or sb[9]


def _anchors_of(ring: list) -> list:
    """[[k_inner, k_outer] of each ball's anchors]."""
    out = []
    b: Ball
    for b in ring:
        out.append([b.anc_i.k, b.anc_o.k])
    return out


def _bases_of(ring: list) -> list:
    """[(γ0, 1/f_i0, 1/f_o0) of each ball's base, or None]."""
    out = []
    b: Ball
    for b in ring:
        out.append(None if b.base is None else list(b.base[:3]))
    return out


def _set_bases(c: PairConstants, ring: list, bases: list):
    """The balls' bases evaluated again at their (γ0, 1/f_i0, 1/f_o0) (None: no base)."""
    b: Ball
    for b, at in zip(ring, bases, strict=True):
        if at is not None:
            b.base = ball_base(c, float(at[0]), float(at[1]), float(at[2]), b)


def _bad_temperature(t_h, t_s, t_o, t_i):
    """Raise the ValueError naming the first temperature outside (0, inf) K (``temperature``
    when all four are equal)."""
    temps = (t_h, t_s, t_o, t_i)
    for name, t in zip(("housing", "shaft", "outer_ring", "inner_ring"), temps, strict=True):
        if not (0.0 < t < math.inf):
            label = "temperature" if temps.count(t) == 4 else f"{name}_temperature"
            raise ValueError(f"{label} = {t!r} K is outside the valid range (0, inf) K")

r"""Permanent-magnet DC motor with its load inertia (the DCMotor FMU's equations):

.. math::

   L\,\frac{di}{dt} = V - R\,i - k_e\,\omega, \qquad
   J\,\frac{d\omega}{dt} = k_t\,i - b\,\omega - T_\mathrm{load}, \qquad
   \frac{d\varphi}{dt} = \omega

with armature resistance R [Ω], inductance L [H], torque constant :math:`k_t` [N·m/A],
back-EMF constant :math:`k_e` [V·s/rad], inertia J [kg·m²] and viscous damping b [N·m·s/rad]
(a textbook model, e.g. Franklin, Powell & Emami-Naeini, *Feedback Control of Dynamic
Systems*, ch. 2).

The equations are linear with constant coefficients, so with the inputs
(V, :math:`T_\mathrm{load}`) held over a communication step h the exact solution is

.. math::

   x(t + h) = \Phi(h)\,x(t) + \Gamma(h)\,u, \qquad \Phi = e^{A h}, \qquad
   \Gamma = \int_0^h e^{A\tau}\,d\tau\;B

(zero-order hold; both from one matrix exponential of the augmented matrix,
``scipy.linalg.expm``). It is exact for any step and unconditionally stable, so one sub-step
per communication step is as accurate as any number of them; the electrical time constant L/R
(often well below the step) needs no special treatment.

Coulomb friction of the bearings (:func:`step_with_friction`) is applied inside the motor,
implicitly, on sub-steps of at most ``substep`` seconds: each sub-step first takes the
friction-free exact step, then the friction torque that opposes the speed at the *end* of the
sub-step, limited to the running torque (breakaway torque while stuck). When that friction can
bring the speed to zero it does so exactly and the rotor sticks (the set-valued friction law
solved backwards, Karnopp-style). This is stable for any step, so the stiff friction law does
not make a co-simulation chatter around zero speed, as a signed friction torque fed back from
another FMU at the communication step would.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import expm

from .. import compiled
from .._checks import check_finite, check_nonnegative, check_positive

#: The sub-steps with friction (:mod:`.motor_stepping`): compiled when the build could.
_stepping = compiled.module("drives.motor_stepping")


@dataclass(frozen=True)
class DCMotorParameters:
    """Parameters of the motor and its load (SI). See module docstring for the equations."""

    resistance: float = 2.0  # Ω
    inductance: float = 1.0e-3  # H
    torque_constant: float = 0.05  # N·m/A
    back_emf_constant: float = 0.05  # V·s/rad
    inertia: float = 2.0e-4  # kg·m²
    viscous_damping: float = 1.0e-5  # N·m·s/rad

    def __post_init__(self):
        for name in ("resistance", "inductance", "torque_constant", "back_emf_constant", "inertia"):
            check_positive(name, getattr(self, name))
        check_nonnegative("viscous_damping", self.viscous_damping)


def state_matrices(p: DCMotorParameters):
    """(A, B) of x' = A·x + B·u with x = (i [A], ω [rad/s], φ [rad]), u = (V [V], T_load [N·m]).

    Parameters
    ----------
    p : DCMotorParameters
        Resistance [Ω], inductance [H], k_t [N·m/A], k_e [V·s/rad], inertia [kg·m²],
        damping [N·m·s/rad].

    Returns
    -------
    tuple of ndarray
        (A [3×3], B [3×2]) in SI.

    Examples
    --------
    >>> a, b = state_matrices(DCMotorParameters())
    >>> float(a[0, 0]), float(b[1, 1])  # −R/L [1/s], −1/J [1/(kg·m²)]
    (-2000.0, -5000.0)
    """
    a = np.array(
        [
            [-p.resistance / p.inductance, -p.back_emf_constant / p.inductance, 0.0],
            [p.torque_constant / p.inertia, -p.viscous_damping / p.inertia, 0.0],
            [0.0, 1.0, 0.0],
        ]
    )
    b = np.array([[1.0 / p.inductance, 0.0], [0.0, -1.0 / p.inertia], [0.0, 0.0]])
    return a, b


@functools.lru_cache(maxsize=32)
def discretise(p: DCMotorParameters, step: float):
    """(Φ, Γ) of the exact zero-order-hold step of length ``step`` [s]: the top blocks of
    expm([[A, B], [0, 0]]·h) (Van Loan). Returned as nested tuples of floats.

    Parameters
    ----------
    p : DCMotorParameters
        The motor.
    step : float
        h [s], > 0.

    Returns
    -------
    tuple
        (Φ [3×3], Γ [3×2]) as nested tuples of floats.

    Examples
    --------
    >>> phi, gamma = discretise(DCMotorParameters(), 1e-3)
    >>> round(phi[2][2], 12), len(gamma), len(gamma[0])  # φ keeps itself
    (1.0, 3, 2)
    """
    h = check_positive("step", step, "s")
    a, b = state_matrices(p)
    m = np.zeros((5, 5))
    m[:3, :3], m[:3, 3:] = a * h, b * h
    e = expm(m)
    phi, gamma = e[:3, :3], e[:3, 3:]
    as_floats = lambda m: tuple(tuple(float(v) for v in row) for row in m)  # noqa: E731
    return as_floats(phi), as_floats(gamma)


def step(p: DCMotorParameters, state, voltage: float, load_torque: float, h: float):
    """Advance x = (i, ω, φ) by ``h`` [s] with voltage [V] and load torque [N·m] held; returns
    the new (i, ω, φ) as floats (exact, see module docstring).

    Parameters
    ----------
    p : DCMotorParameters
        The motor.
    state : tuple of float
        (i [A], ω [rad/s], φ [rad]).
    voltage : float
        V [V].
    load_torque : float
        T_load [N·m].
    h : float
        Step [s].

    Returns
    -------
    tuple of float
        The new (i [A], ω [rad/s], φ [rad]).

    Examples
    --------
    >>> p = DCMotorParameters()
    >>> i, w, phi = step(p, (0.0, 0.0, 0.0), 12.0, 0.0, 10.0)  # long enough to settle
    >>> round(w, 3)  # rad/s: V·k_t/(R·b + k_t·k_e) in steady state
    238.095
    """
    check_finite("voltage", voltage, "V")
    check_finite("load_torque", load_torque, "N·m")
    return step_unchecked(p, state, voltage, load_torque, h)


def step_unchecked(p: DCMotorParameters, state, voltage: float, load_torque: float, h: float):
    """:func:`step` without its argument checks, for a caller that checked them (the DCMotor
    FMU checks its inputs once per step).

    Parameters
    ----------
    p, state, voltage, load_torque, h : as :func:`step` (finite; h > 0 [s])

    Returns
    -------
    tuple of float
        The new (i [A], ω [rad/s], φ [rad]).

    Examples
    --------
    >>> p = DCMotorParameters()
    >>> step_unchecked(p, (0.0, 0.0, 0.0), 12.0, 0.0, 1e-3) == step(p, (0.0, 0.0, 0.0), 12.0, 0.0, 1e-3)
    True
    """  # noqa: E501
    phi, gamma = discretise(p, float(h))
    u = (voltage, load_torque)
    return tuple(
        phi[r][0] * state[0]
        + phi[r][1] * state[1]
        + phi[r][2] * state[2]
        + gamma[r][0] * u[0]
        + gamma[r][1] * u[1]
        for r in range(3)
    )


def motor_torque(p: DCMotorParameters, current):
    """Electromagnetic torque k_t·i [N·m] for current i [A].

    Parameters
    ----------
    p : DCMotorParameters
        The motor (k_t [N·m/A]).
    current : float or array_like
        i [A].

    Returns
    -------
    float or ndarray
        Torque [N·m].

    Examples
    --------
    >>> motor_torque(DCMotorParameters(), 2.0)  # N·m: 0.05 N·m/A × 2 A
    0.1
    """
    return p.torque_constant * current


def step_with_friction(
    p: DCMotorParameters,
    state,
    voltage: float,
    load_torque: float,
    h: float,
    running_friction: float,
    breakaway_friction: float,
    substep: float = 1.0e-4,
):
    """Advance x = (i, ω, φ) by ``h`` [s] with Coulomb friction of magnitude
    ``running_friction`` [N·m] while sliding and ``breakaway_friction`` [N·m] while stuck,
    applied implicitly on sub-steps of at most ``substep`` [s] (see module docstring).
    Returns (new state, mean friction torque over the step [N·m, signed like the speed]).

    Examples
    --------
    >>> p = DCMotorParameters()
    >>> state, friction = step_with_friction(p, (0.0, 0.0, 0.0), 0.1, 0.0, 1e-3, 0.01, 0.02)
    >>> state[1], round(friction * 1e3, 4)  # rad/s, mN·m: stuck, friction holds the motor
    (0.0, 1.4192)

    (the motor torque rises towards k_t·V/R = 2.5 mN·m, below the 20 mN·m breakaway)
    """
    check_finite("voltage", voltage, "V")
    check_finite("load_torque", load_torque, "N·m")
    check_nonnegative("running_friction", running_friction, "N·m")
    check_nonnegative("breakaway_friction", breakaway_friction, "N·m")
    return step_with_friction_unchecked(
        p, state, voltage, load_torque, h, running_friction, breakaway_friction, substep
    )


def step_with_friction_unchecked(
    p, state, voltage, load_torque, h, running_friction, breakaway_friction, substep
):
    """:func:`step_with_friction` without its argument checks, for a caller that checked
    them (the DCMotor FMU checks its inputs once per step).

    Parameters
    ----------
    p, state, voltage, load_torque, h, running_friction, breakaway_friction, substep : as
        :func:`step_with_friction` (finite; friction magnitudes ≥ 0 [N·m]; h, substep > 0 [s])

    Returns
    -------
    tuple
        (new (i [A], ω [rad/s], φ [rad]), mean friction torque over the step [N·m]).

    Examples
    --------
    >>> p = DCMotorParameters()
    >>> args = (p, (0.0, 0.0, 0.0), 0.1, 0.0, 1e-3, 0.01, 0.02, 1e-4)
    >>> step_with_friction_unchecked(*args) == step_with_friction(*args)
    True
    """
    n = max(1, math.ceil(h / substep - 1e-9))
    phi, gamma = discretise(p, h / n)
    i, w, a = state
    return _stepping.friction_substeps(
        phi, gamma, i, w, a, voltage, load_torque, n, running_friction, breakaway_friction
    )


def shared_step(*args, implementation: str | None = None):
    """The DCMotor FMU's step on the values it shares with servofmu's export
    (:class:`.motor_stepping.MotorSharedStep`; ``args``: those of
    :class:`~servofmu.physics.shared_step.SharedStep`), of ``implementation`` ("compiled",
    "python"; None: the one :mod:`servofmu.physics.compiled` chose).

    Returns
    -------
    MotorSharedStep

    Examples
    --------
    >>> step = shared_step(bytearray(32), 0, 0, 2, True, None, None)  # a block of no values
    >>> type(step).__name__, step.armed
    ('MotorSharedStep', False)
    """
    return compiled.module("drives.motor_stepping", implementation).MotorSharedStep(*args)

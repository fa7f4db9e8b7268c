# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The DC motor's exact sub-steps with bearing friction (:mod:`.motor`), written in Cython's
pure-Python mode: the zero-order-hold step x⁺ = Φ·x + Γ·u of the armature circuit and rotor
(i [A], ω [rad/s], φ [rad]; u = (V [V], load torque [N·m])) with the friction torque that
holds the rotor, or opposes its motion with the running torque, solved exactly per sub-step
(:func:`.motor.step_with_friction`). The library and the DCMotor FMU run this function; the
build compiles it (:mod:`servofmu.physics.compiled`).

The sums are taken in the order of the Python expressions, and ``copysign`` is C's (as
:mod:`math` calls it): both implementations give the same bits.

Examples
--------
>>> phi = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
>>> gamma = ((0.0, 0.0), (0.0, -0.5), (0.0, 0.0))  # 1 N·m held takes 0.5 rad/s
>>> friction_substeps(phi, gamma, 0.0, 1.0, 0.0, 0.0, 0.0, 1, 0.1, 0.2)  # running: 0.1 N·m
((0.0, 0.95, 0.0), 0.1)
"""

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import ceil, copysign, fabs, isfinite
    from cython.cimports.servofmu.physics._shared_step import SharedStep
else:
    from math import ceil, copysign, isfinite
    from math import fabs as fabs

    from ..shared_step import SharedStep


@cython.ccall
def friction_substeps(
    phi: tuple,
    gamma: tuple,
    current: cython.double,
    speed: cython.double,
    angle: cython.double,
    voltage: cython.double,
    load_torque: cython.double,
    substeps: cython.int,
    running_friction: cython.double,
    breakaway_friction: cython.double,
) -> tuple:
    """``substeps`` exact sub-steps of the motor with friction, inputs held (Φ [3×3] and
    Γ [3×2] of one sub-step: :func:`.motor.discretise`): in each, the free step
    x_free = Φ·x + Γ·u; when |ω_free| ≤ −Γ[1][1]·T_limit (T_limit the breakaway torque
    [N·m] at rest, the running one moving) the friction holds the rotor (ω = 0) with the
    torque that does so, else it is ±running_friction [N·m] against ω_free; x = x_free +
    Γ[:, 1]·friction.

    Parameters
    ----------
    phi, gamma : Φ and Γ of one sub-step, nested tuples of floats
    current, speed, angle : i [A], ω [rad/s], φ [rad] at the start
    voltage : V [V]; load_torque : [N·m], held
    substeps : n ≥ 1
    running_friction, breakaway_friction : [N·m] ≥ 0

    Returns
    -------
    tuple
        ((i [A], ω [rad/s], φ [rad]) at the end, mean friction torque over the step [N·m]).

    Examples
    --------
    >>> phi = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    >>> gamma = ((0.0, 0.0), (0.0, -0.5), (0.0, 0.0))  # 1 N·m held takes 0.5 rad/s
    >>> friction_substeps(phi, gamma, 0.0, 0.04, 0.0, 0.0, 0.0, 1, 0.1, 0.2)  # held at rest
    ((0.0, 0.0, 0.0), 0.08)
    """
    p00: cython.double = phi[0][0]
    p01: cython.double = phi[0][1]
    p02: cython.double = phi[0][2]
    p10: cython.double = phi[1][0]
    p11: cython.double = phi[1][1]
    p12: cython.double = phi[1][2]
    p20: cython.double = phi[2][0]
    p21: cython.double = phi[2][1]
    p22: cython.double = phi[2][2]
    g00: cython.double = gamma[0][0]
    g01: cython.double = gamma[0][1]
    g10: cython.double = gamma[1][0]
    g11: cython.double = gamma[1][1]
    g20: cython.double = gamma[2][0]
    g21: cython.double = gamma[2][1]
    drop: cython.double = -g11  # speed lost per N·m of friction (> 0)
    i: cython.double = current
    w: cython.double = speed
    a: cython.double = angle
    total: cython.double = 0.0
    f0: cython.double
    f1: cython.double
    f2: cython.double
    limit: cython.double
    friction: cython.double
    held: cython.bint
    for _ in range(substeps):
        f0 = p00 * i + p01 * w + p02 * a + g00 * voltage + g01 * load_torque
        f1 = p10 * i + p11 * w + p12 * a + g10 * voltage + g11 * load_torque
        f2 = p20 * i + p21 * w + p22 * a + g20 * voltage + g21 * load_torque
        limit = breakaway_friction if w == 0.0 else running_friction
        held = fabs(f1) <= drop * limit
        if held:
            friction = f1 / drop  # holds (or stops) the rotor exactly
        else:
            friction = copysign(running_friction, f1)
        i = f0 + g01 * friction
        w = 0.0 if held else f1 + g11 * friction
        a = f2 + g21 * friction
        total += friction
    return (i, w, a), total / substeps


@cython.final
@cython.cclass
class MotorSharedStep(SharedStep):
    """The DCMotor FMU's step on the values it shares with servofmu's export
    (:class:`~servofmu.physics.shared_step.SharedStep`): the motor's state (its outputs
    current, speed and angle) over the step by the same functions as the slave (``plain``
    without friction, ``with_friction`` with it: :mod:`.motor`'s ``step_unchecked`` and
    ``step_with_friction_unchecked``), and motor_torque = k_t·i. A step of more sub-steps than
    the slave allows, or one that leaves the state not finite or outside the ranges a state
    can be given, is declined (the slave's message)."""

    def bind(
        self,
        params,
        plain,
        with_friction,
        substep: cython.double,
        most: cython.double,
        ranges: tuple,
        inputs: tuple,
        outputs: tuple,
    ):
        """The slave's motor ``params`` (DCMotorParameters); the step functions ``plain`` and
        ``with_friction``; the longest sub-step [s] and the most sub-steps of a step; the
        (lo, hi) of current [A], speed [rad/s] and angle [rad]; the slots of the inputs
        (voltage, load torque, running and breakaway friction) and of the outputs (current,
        speed, angle, motor torque, friction torque)."""
        self.params = params
        self.torque_constant = params.torque_constant
        self.plain, self.with_friction = plain, with_friction
        self.substep, self.most = substep, most
        self.ranges, self.inputs, self.outputs = ranges, inputs, outputs

    @cython.cfunc
    def advance(self, t: cython.double, h: cython.double) -> cython.bint:
        values = self.values
        k: cython.Py_ssize_t
        slot: cython.Py_ssize_t
        x: cython.double
        if ceil(h / self.substep - 1e-9) > self.most:
            return False
        state: list = [0.0, 0.0, 0.0]
        for k in range(3):
            slot = self.outputs[k]
            state[k] = values[slot]
        u: list = [0.0, 0.0, 0.0, 0.0]
        for k in range(4):
            slot = self.inputs[k]
            u[k] = values[slot]
        friction: cython.double = 0.0
        if u[2] == 0.0 and u[3] == 0.0:
            new = self.plain(self.params, tuple(state), u[0], u[1], h)
        else:
            new, friction = self.with_friction(
                self.params, tuple(state), u[0], u[1], h, u[2], u[3], self.substep
            )
        for k in range(3):
            x = new[k]
            lo, hi = self.ranges[k]
            if not (isfinite(x) and lo <= x <= hi):
                return False
        for k in range(3):
            slot = self.outputs[k]
            values[slot] = new[k]
        slot = self.outputs[0]
        x = values[slot]
        slot = self.outputs[3]
        values[slot] = self.torque_constant * x
        slot = self.outputs[4]
        values[slot] = friction
        return True

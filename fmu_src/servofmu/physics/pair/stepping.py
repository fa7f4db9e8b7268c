# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The BearingFriction FMU's step on the values it shares with servofmu's export
(:class:`~servofmu.physics.shared_step.SharedStep`), written in Cython's pure-Python mode; the
build compiles it (:mod:`servofmu.physics.compiled`).

A step is the slave's algebraic step, in the same order and with the same calls: when the
inputs changed since the outputs were computed, the state at the operating point
(:meth:`.model.BearingModel.update`, only when the temperatures or loads changed; the speed
terms otherwise) and the speed terms (:meth:`.continuation.PairSolver.speed_outputs`), then,
with pre-rolling, Dahl's state held within T_c and carried over the step
(:func:`~servofmu.physics.kernels.friction.stribeck_torque`,
:func:`~servofmu.physics.kernels.friction.dahl_torque_step`).

It declines what the slave says in Python: a Boolean output that changes (its warnings), the
lubricant below its flow limit unsaid, an output that is not finite. It may have solved the
state at a new operating point by then; the model keeps the state of its last point, so the
slave's Python path, asking for the same point, gets that same state (nothing else has
changed).
"""

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import isfinite
    from cython.cimports.servofmu.physics._shared_step import SharedStep
    from cython.cimports.servofmu.physics.kernels._friction import (
        dahl_torque_step,
        stribeck_torque,
    )
    from cython.cimports.servofmu.physics.pair._point import PointState
else:
    from math import isfinite

    from ..kernels.friction import dahl_torque_step, stribeck_torque
    from ..shared_step import SharedStep
    from .point import PointState

from .._checks import TEMPERATURE_RANGE

#: The PointState fields a step copies to the block, read in C (:meth:`PairSharedStep.bind`):
#: the Real ones, then the flags (Boolean outputs).
STATE_FIELDS = (
    "breakaway_torque",
    "hysteresis_torque",
    "spin_torque",
    "sliding_torque",
    "preload",
    "contact_angle",
    "radial_clearance",
    "kinematic_viscosity",
    "axial_stiffness",
    "max_contact_pressure",
    "outer_interference",
    "inner_interference",
    "axial_play",
)
FLAG_FIELDS = ("overloaded", "locked", "unloaded", "reverse_loaded", "outside_lubricant_range")


@cython.final
@cython.cclass
class PairSharedStep(SharedStep):
    """BearingFriction's step on its block (module docstring). :meth:`bind` and
    :meth:`bind_prerolling` give it the slave's model, slots and state before it is armed;
    the slave reads the state back from :meth:`point` and the ``prerolling_*`` attributes."""

    def __init__(self, *args):
        SharedStep.__init__(self, *args)
        self.point = None
        self.prerolling = False

    def bind(
        self,
        model,
        temperatures: tuple,
        loads: tuple,
        state_outputs: tuple,
        speed_outputs: tuple,
        flags: cython.int,
        point,
        checked_flow: cython.bint,
        below_flow,
    ):
        """The slave's ``model`` (:class:`.model.BearingModel`); the slots of the
        ``temperatures`` inputs (1: uniform, 2: housing and shaft, 4: the parts) and of the
        ``loads`` (axial, radial, speed); ``state_outputs``: the slot of each field of
        :data:`STATE_FIELDS` (-1: not an output); the slots of the speed terms (friction,
        running, sliding, viscous and grease torque, power loss); ``flags``: the values of the
        Boolean outputs of :data:`FLAG_FIELDS`, bit k the k-th (:func:`flag_bits`); the last
        operating ``point`` ((temperatures, axial [N],
        radial [N]) or None: none yet); whether the flow limit was checked (its warning
        given) and ``below_flow(t)``, whether the lubricant at t [K] is below it."""
        self.model = model
        self.solver = model.solver
        self.lowest, self.highest = TEMPERATURE_RANGE
        self.temperature_slots = temperatures
        self.axial, self.radial, self.speed = loads[0], loads[1], loads[2]
        self.state_outputs = state_outputs
        self.speed_slots = speed_outputs
        self.flags = flags
        self.point = point
        self.checked_flow = checked_flow
        self.below_flow = below_flow
        self.prerolling = False

    def bind_prerolling(
        self,
        slots: tuple,
        rest_stiffness,
        stiffness: cython.double,
        sigma0: cython.double,
        excess: cython.double,
        stribeck: cython.double,
        exponent: cython.double,
        angle: cython.double,
        torque: cython.double,
        coulomb: cython.double,
    ):
        """Dahl's pre-rolling: the slots of prerolling_angle and prerolling_torque;
        ``rest_stiffness(temperatures, axial, radial)`` [N·m/rad], the parameter
        ``stiffness`` (0: the rest stiffness at each operating point) and the current
        ``sigma0`` [N·m/rad]; the breakaway ``excess`` [N·m]; ω_s ``stribeck`` [rad/s]; Dahl's
        ``exponent``; the state (``angle`` [rad], ``torque`` [N·m]) and the last T_c
        ``coulomb`` [N·m]."""
        self.prerolling = True
        self.prerolling_slots = slots
        self.rest_stiffness = rest_stiffness
        self.stiffness, self.sigma0, self.excess = stiffness, sigma0, excess
        self.stribeck, self.exponent = stribeck, exponent
        self.prerolling_angle, self.prerolling_torque, self.coulomb = angle, torque, coulomb

    @cython.cfunc
    def advance(self, t: cython.double, h: cython.double) -> cython.bint:
        values = self.values
        k: cython.Py_ssize_t
        slot: cython.Py_ssize_t
        speed: cython.double = values[self.speed]
        point = self.point
        state = None
        if self.inputs_changed():  # the outputs from the inputs
            temps = self.temperatures(self.temperature_slots)
            point = (temps, values[self.axial], values[self.radial])
            if point != self.point:
                state = self._update(point)
                if not self._keeps_flags(state, point[0]):
                    return False
                self._write_state(state)
            terms: tuple = self.solver.speed_outputs(speed)
            for k in range(6):
                slot = self.speed_slots[k]
                values[slot] = terms[k]
        if self.prerolling and not self._roll(state, point, speed, h):
            return False
        for k in range(len(self.state_outputs)):
            slot = self.state_outputs[k]
            if slot >= 0 and not isfinite(values[slot]):
                return False
        for k in range(6):
            slot = self.speed_slots[k]
            if not isfinite(values[slot]):
                return False
        self.point = point
        return True

    @cython.cfunc
    def _update(self, point: tuple):
        """The model's state at ``point`` (:meth:`.model.BearingModel.update`: the solver's,
        or the exact path's where it fails; temperatures outside the model's range go to the
        model itself, which names them)."""
        temps = point[0]
        t_h: cython.double
        t_s: cython.double
        t_o: cython.double
        t_i: cython.double
        if type(temps) is float:
            t_h = t_s = t_o = t_i = temps
        else:
            t_h, t_s, t_o, t_i = temps
        lo: cython.double = self.lowest
        hi: cython.double = self.highest
        if not (lo <= t_h <= hi and lo <= t_s <= hi and lo <= t_o <= hi and lo <= t_i <= hi):
            return self.model.update(temps, point[1], point[2])
        state = self.solver.update(t_h, t_s, t_o, t_i, point[1], point[2])
        if state is None:
            state = self.model.solve_exactly(t_h, t_s, t_o, t_i, point[1], point[2])
        return state

    @cython.cfunc
    def _write_state(self, s: PointState):
        """The Real outputs of the state ``s`` (:data:`STATE_FIELDS`, in order) to the block."""
        slots: tuple = self.state_outputs
        self._put(slots[0], s.breakaway_torque)
        self._put(slots[1], s.hysteresis_torque)
        self._put(slots[2], s.spin_torque)
        self._put(slots[3], s.sliding_torque)
        self._put(slots[4], s.preload)
        self._put(slots[5], s.contact_angle)
        self._put(slots[6], s.radial_clearance)
        self._put(slots[7], s.kinematic_viscosity)
        self._put(slots[8], s.axial_stiffness)
        self._put(slots[9], s.max_contact_pressure)
        self._put(slots[10], s.outer_interference)
        self._put(slots[11], s.inner_interference)
        self._put(slots[12], s.axial_play)

    @cython.cfunc
    def _put(self, slot: cython.Py_ssize_t, x: cython.double):
        """values[slot] = x, unless slot < 0 (not an output)."""
        if slot >= 0:
            self.values[slot] = x

    @cython.cfunc
    def _keeps_flags(self, s: PointState, temps) -> cython.bint:
        """Whether the state ``s`` leaves every Boolean output as it is and the lubricant at
        ``temps`` [K] is not below its flow limit unsaid (else the slave's warnings are due)."""
        bits: cython.int = (  # as flag_bits, in C
            s.overloaded
            | s.locked << 1
            | s.unloaded << 2
            | s.reverse_loaded << 3
            | s.outside_lubricant_range << 4
        )
        if bits != self.flags:
            return False
        if s.outside_lubricant_range and not self.checked_flow:
            t = temps if type(temps) is float else 0.5 * (temps[2] + temps[3])
            return not self.below_flow(t)
        return True

    @cython.cfunc
    def _roll(self, state, point, speed: cython.double, h: cython.double) -> cython.bint:
        """Dahl's state held within T_c of the current inputs and carried over the step
        (BearingFriction's _hold_prerolling and _advance_prerolling); its outputs written, its
        state kept only when every output is finite."""
        values = self.values
        excess: cython.double = self.excess
        sigma0: cython.double = self.sigma0
        if state is not None:
            excess = state.breakaway_excess
            if self.stiffness == 0.0:
                temps = point[0]
                t4 = (temps,) * 4 if type(temps) is float else temps
                sigma0 = self.rest_stiffness(t4, point[1], point[2])
        running_slot: cython.Py_ssize_t = self.speed_slots[1]
        tc: cython.double = self.coulomb
        if self.inputs_changed():  # the outputs were computed: T_c of this step's inputs
            tc = stribeck_torque(values[running_slot], excess, speed, self.stribeck)
        dtheta: cython.double = speed * h
        angle: cython.double = self.prerolling_angle + dtheta
        torque: cython.double = 0.0
        friction_slot: cython.Py_ssize_t = self.speed_slots[0]
        power_slot: cython.Py_ssize_t = self.speed_slots[5]
        if sigma0 > 0.0:
            torque = dahl_torque_step(self.prerolling_torque, tc, sigma0, self.exponent, dtheta)
            values[friction_slot] = torque
            values[power_slot] = torque * speed
        angle_slot: cython.Py_ssize_t = self.prerolling_slots[0]
        torque_slot: cython.Py_ssize_t = self.prerolling_slots[1]
        values[angle_slot] = angle
        values[torque_slot] = torque
        if not (isfinite(angle) and isfinite(torque) and isfinite(values[power_slot])):
            return False
        self.excess, self.sigma0, self.coulomb = excess, sigma0, tc
        self.prerolling_angle, self.prerolling_torque = angle, torque
        return True


@cython.ccall
def flag_bits(flags: tuple) -> cython.int:
    """The Boolean values ``flags`` (those of :data:`FLAG_FIELDS`, in order) as bits: bit k
    set when the k-th is true.

    Returns
    -------
    int

    Examples
    --------
    >>> flag_bits((True, False, False, True, False))
    9
    """
    bits: cython.int = 0
    k: cython.int
    for k in range(len(flags)):
        if flags[k]:
            bits |= 1 << k
    return bits

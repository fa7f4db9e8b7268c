"""DCMotor FMU: armature circuit and rotor/load inertia, integrated exactly inside the FMU
(zero-order hold of the linear equations), with the bearings' Coulomb friction applied
implicitly on sub-steps (:mod:`servofmu.physics.drives.motor`): connect a BearingFriction's
running_torque and breakaway_torque to friction_running_torque and friction_breakaway_torque
for chatter-free low-speed co-simulation at any communication step."""

from __future__ import annotations

import math
from pathlib import Path

import servofmu

servofmu.share_copy(Path(__file__).parent)  # first of all: see its docstring

from servofmu.fmus.declarations import output, real_input, real_parameter  # noqa: E402
from servofmu.fmus.runtime import ServoSlave  # noqa: E402
from servofmu.physics.drives import motor  # noqa: E402
from servofmu.physics.drives.motor import DCMotorParameters  # noqa: E402

_P = DCMotorParameters()
#: The most sub-steps of max_substep one fmi2DoStep takes, with or without friction (the work
#: per call is bounded: a longer step is discarded, naming this limit). At the default
#: max_substep of 0.1 ms that is 10 s, where the friction-free exact step is still accurate to
#: 3e-14 (relative, measured against the steady state; the matrix exponential of a much longer
#: step loses digits: 2e-8 at 1e5 s, NaN at 1e18 s).
MAX_SUBSTEPS = 100_000
_SRC = "assumed: a small brushed torque motor driving a gimbal axis"
_STATE = ("current", "speed", "angle")  # the motor's state: outputs, set by initial_<name>
#: the inputs a step takes, in the order of the compiled step's (motor_stepping.MotorSharedStep)
_FORCING = ("voltage", "load_torque", "friction_running_torque", "friction_breakaway_torque")


def _param(name, description, **kw):
    """A Real parameter (keywords as :func:`real_parameter`), by default of provenance _SRC."""
    return real_parameter(name, description, **{"source": _SRC, **kw})


class DCMotor(ServoSlave):
    """Permanent-magnet DC motor with its load inertia."""

    description = "Permanent-magnet DC motor with rotor and load inertia (exact ZOH stepping)"
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-3)
    PHYSICS = ("servofmu.physics.drives.motor",)
    # the state is integrated inside the FMU: no output depends directly on an input, and
    # right after initialization each is its initial state (friction_torque: none applied yet)
    VARIABLES = (
        real_input("voltage", "Armature voltage", start=0.0, unit="V", min=-1.0e3, max=1.0e3),
        real_input(
            "load_torque",
            "Load torque, subtracted from the motor torque",
            start=0.0,
            unit="N.m",
            display_unit="N.mm",
            min=-1.0e3,
            max=1.0e3,
        ),
        real_input(
            "friction_running_torque",
            "Coulomb friction magnitude while turning (opposes the motion)",
            start=0.0,
            unit="N.m",
            display_unit="N.mm",
            min=0.0,
            max=1.0e3,
        ),
        real_input(
            "friction_breakaway_torque",
            "Coulomb friction magnitude that holds the rotor at rest",
            start=0.0,
            unit="N.m",
            display_unit="N.mm",
            min=0.0,
            max=1.0e3,
        ),
        output(
            "speed",
            "Rotor speed",
            unit="rad/s",
            display_unit="rpm",
            initial_depends=("initial_speed",),
        ),
        output(
            "angle",
            "Rotor angle",
            unit="rad",
            display_unit="deg",
            initial_depends=("initial_angle",),
        ),
        output("current", "Armature current", unit="A", initial_depends=("initial_current",)),
        output(
            "motor_torque",
            "Electromagnetic torque k_t·i",
            unit="N.m",
            display_unit="N.mm",
            initial_depends=("torque_constant", "initial_current"),
        ),
        output(
            "friction_torque",
            "Coulomb friction applied over the last step (mean, signed like the speed)",
            unit="N.m",
            display_unit="N.mm",
            initial_depends=(),
        ),
        _param(
            "resistance",
            "Armature resistance R",
            start=_P.resistance,
            unit="Ohm",
            min=1e-6,
            max=1e6,
        ),
        _param(
            "inductance",
            "Armature inductance L",
            start=_P.inductance,
            unit="H",
            display_unit="mH",
            min=1e-9,
            max=1e3,
        ),
        _param(
            "torque_constant",
            "Torque constant k_t",
            start=_P.torque_constant,
            unit="N.m/A",
            min=1e-6,
            max=1e3,
        ),
        _param(
            "back_emf_constant",
            "Back-EMF constant k_e",
            start=_P.back_emf_constant,
            unit="V.s/rad",
            min=1e-6,
            max=1e3,
        ),
        _param(
            "inertia",
            "Rotor plus load inertia J",
            start=_P.inertia,
            unit="kg.m2",
            min=1e-12,
            max=1e6,
        ),
        _param(
            "viscous_damping",
            "Viscous damping b",
            start=_P.viscous_damping,
            unit="N.m.s/rad",
            min=0.0,
            max=1e6,
        ),
        _param(
            "initial_current",
            "Current at the start time",
            start=0.0,
            unit="A",
            min=-1e4,
            max=1e4,
            source="assumed: at rest",
        ),
        _param(
            "initial_speed",
            "Speed at the start time",
            start=0.0,
            unit="rad/s",
            display_unit="rpm",
            min=-1e5,
            max=1e5,
            source="assumed: at rest",
        ),
        _param(
            "initial_angle",
            "Angle at the start time",
            start=0.0,
            unit="rad",
            display_unit="deg",
            min=-1e9,
            max=1e9,
            source="assumed: at rest",
        ),
        _param(
            "max_substep",
            "Longest sub-step for the implicit Coulomb friction",
            start=1.0e-4,
            unit="s",
            display_unit="ms",
            min=1e-7,
            max=1.0,
            source="assumed: 0.1 ms",
        ),
    )

    def configure(self):
        self.params = DCMotorParameters(
            resistance=self.resistance,
            inductance=self.inductance,
            torque_constant=self.torque_constant,
            back_emf_constant=self.back_emf_constant,
            inertia=self.inertia,
            viscous_damping=self.viscous_damping,
        )

    def initialise(self):
        self._set_state((self.initial_current, self.initial_speed, self.initial_angle))

    def advance(self, current_time, step_size):
        substeps = math.ceil(step_size / self.max_substep - 1e-9)
        if substeps > MAX_SUBSTEPS:
            self._error = (
                f"communicationStepSize = {step_size!r} s is {substeps} sub-steps of max_substep "
                f"= {self.max_substep!r} s; one step takes at most {MAX_SUBSTEPS} (≤ "
                f"{MAX_SUBSTEPS * self.max_substep:g} s here): take shorter steps"
            )
            return False
        state = (self.current, self.speed, self.angle)
        if self.friction_running_torque == 0.0 and self.friction_breakaway_torque == 0.0:
            new = motor.step_unchecked(
                self.params, state, self.voltage, self.load_torque, step_size
            )
            self.friction_torque = 0.0
        else:
            new, self.friction_torque = (
                motor.step_with_friction_unchecked(  # inputs checked by the slave
                    self.params,
                    state,
                    self.voltage,
                    self.load_torque,
                    step_size,
                    self.friction_running_torque,
                    self.friction_breakaway_torque,
                    self.max_substep,
                )
            )
        if not all(math.isfinite(v) for v in new):
            self._error = f"the state (current, speed, angle) = {new!r} is not finite"
            return False
        self._error = _outside(zip(_STATE, new, strict=True))
        if self._error:
            return False
        self._set_state(new)
        return True

    shared_step = staticmethod(motor.shared_step)

    def _bind_shared_step(self, step):
        slots = self._shared.slots
        step.bind(
            self.params,
            motor.step_unchecked,
            motor.step_with_friction_unchecked,
            self.max_substep,
            MAX_SUBSTEPS,
            tuple(_RANGES[name][:2] for name in _STATE),
            tuple(slots[name] for name in _FORCING),
            tuple(slots[name] for name in (*_STATE, "motor_torque", "friction_torque")),
        )
        return True

    def _set_state(self, x):
        self.current, self.speed, self.angle = (float(v) for v in x)
        self.motor_torque = float(motor.motor_torque(self.params, self.current))

    def state_problem(self):
        # a state handed back: within what a step allows, and motor_torque = k_t·current
        problem = _outside((name, getattr(self, name)) for name in _STATE)
        if problem or not self._configured:
            return problem
        if self.motor_torque != motor.motor_torque(self.params, self.current):
            return f"motor_torque = {self.motor_torque!r} N.m is not k_t·current"
        return ""


#: The range each state variable can be given through FMI (its initial_<name> parameter's)
_RANGES = {
    name: next((v.min, v.max, v.unit) for v in DCMotor.VARIABLES if v.name == f"initial_{name}")
    for name in _STATE
}


def _outside(state) -> str:
    """The first (name, value) of the motor's state outside :data:`_RANGES`, named, else "":
    a step that would leave it is discarded, so every state the FMU saves can be restored."""
    for name, x in state:
        lo, hi, unit = _RANGES[name]
        if not lo <= x <= hi:
            return (
                f"{name} = {x!r} {unit} is outside the range a motor state can be given "
                f"(initial_{name}: [{lo:g}, {hi:g}] {unit})"
            )
    return ""

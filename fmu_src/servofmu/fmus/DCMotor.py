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

from servofmu.fmus.slave import ServoSlave, output, real_input, real_parameter  # noqa: E402
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


def _param(name, description, start, unit, display, lo, hi, source=_SRC):
    return real_parameter(name, description, start, unit, display, lo, hi, source=source)


class DCMotor(ServoSlave):
    """Permanent-magnet DC motor with its load inertia."""

    description = "Permanent-magnet DC motor with rotor and load inertia (exact ZOH stepping)"
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-3)
    PHYSICS = ("servofmu.physics.drives.motor",)
    # the state is integrated inside the FMU: no output depends directly on an input, and
    # right after initialization each is its initial state (friction_torque: none applied yet)
    VARIABLES = (
        real_input("voltage", "Armature voltage", 0.0, "V", None, -1.0e3, 1.0e3),
        real_input(
            "load_torque",
            "Load torque, subtracted from the motor torque",
            0.0,
            "N.m",
            "N.mm",
            -1.0e3,
            1.0e3,
        ),
        real_input(
            "friction_running_torque",
            "Coulomb friction magnitude while turning (opposes the motion)",
            0.0,
            "N.m",
            "N.mm",
            0.0,
            1.0e3,
        ),
        real_input(
            "friction_breakaway_torque",
            "Coulomb friction magnitude that holds the rotor at rest",
            0.0,
            "N.m",
            "N.mm",
            0.0,
            1.0e3,
        ),
        output("speed", "Rotor speed", "rad/s", "rpm", initial_depends=("initial_speed",)),
        output("angle", "Rotor angle", "rad", "deg", initial_depends=("initial_angle",)),
        output("current", "Armature current", "A", initial_depends=("initial_current",)),
        output(
            "motor_torque",
            "Electromagnetic torque k_t·i",
            "N.m",
            "N.mm",
            initial_depends=("torque_constant", "initial_current"),
        ),
        output(
            "friction_torque",
            "Coulomb friction applied over the last step (mean, signed like the speed)",
            "N.m",
            "N.mm",
            initial_depends=(),
        ),
        _param("resistance", "Armature resistance R", _P.resistance, "Ohm", None, 1e-6, 1e6),
        _param("inductance", "Armature inductance L", _P.inductance, "H", "mH", 1e-9, 1e3),
        _param(
            "torque_constant", "Torque constant k_t", _P.torque_constant, "N.m/A", None, 1e-6, 1e3
        ),
        _param(
            "back_emf_constant",
            "Back-EMF constant k_e",
            _P.back_emf_constant,
            "V.s/rad",
            None,
            1e-6,
            1e3,
        ),
        _param("inertia", "Rotor plus load inertia J", _P.inertia, "kg.m2", None, 1e-12, 1e6),
        _param(
            "viscous_damping",
            "Viscous damping b",
            _P.viscous_damping,
            "N.m.s/rad",
            None,
            0.0,
            1e6,
        ),
        _param(
            "initial_current",
            "Current at the start time",
            0.0,
            "A",
            None,
            -1e4,
            1e4,
            "assumed: at rest",
        ),
        _param(
            "initial_speed",
            "Speed at the start time",
            0.0,
            "rad/s",
            "rpm",
            -1e5,
            1e5,
            "assumed: at rest",
        ),
        _param(
            "initial_angle",
            "Angle at the start time",
            0.0,
            "rad",
            "deg",
            -1e9,
            1e9,
            "assumed: at rest",
        ),
        _param(
            "max_substep",
            "Longest sub-step for the implicit Coulomb friction",
            1.0e-4,
            "s",
            "ms",
            1e-7,
            1.0,
            "assumed: 0.1 ms",
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
            new = motor._step(self.params, state, self.voltage, self.load_torque, step_size)
            self.friction_torque = 0.0
        else:
            new, self.friction_torque = motor._step_with_friction(  # inputs checked by the slave
                self.params,
                state,
                self.voltage,
                self.load_torque,
                step_size,
                self.friction_running_torque,
                self.friction_breakaway_torque,
                self.max_substep,
            )
        if not all(math.isfinite(v) for v in new):
            self._error = f"the state (current, speed, angle) = {new!r} is not finite"
            return False
        self._set_state(new)
        return True

    def _set_state(self, x):
        self.current, self.speed, self.angle = (float(v) for v in x)
        self.motor_torque = float(motor.motor_torque(self.params, self.current))

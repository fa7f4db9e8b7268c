"""ServoController FMU: discrete PID with anti-windup and output limit, position or speed loop
(:mod:`servofmu.physics.control`)."""

from __future__ import annotations

from servofmu.fmus.slave import ServoSlave, Var
from servofmu.physics.control import MODES, PIDParameters, PIDState, pid_sample

_P = PIDParameters()
_SRC = "assumed: a speed loop for the gimbal motor of the DCMotor defaults"


class ServoController(ServoSlave):
    """Discrete PID controller sampled every sample_period."""

    description = "Discrete PID (derivative on measurement, clamping anti-windup, output limit)"
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-3)
    PHYSICS = ("servofmu.physics.control",)
    VARIABLES = (
        Var(
            "reference",
            "Real",
            "input",
            "Set point: angle [rad] in position mode, speed [rad/s] in speed mode",
            0.0,
            None,
            None,
            -1.0e9,
            1.0e9,
        ),
        Var(
            "measurement",
            "Real",
            "input",
            "Measured angle [rad] or speed [rad/s]",
            0.0,
            None,
            None,
            -1.0e9,
            1.0e9,
        ),
        Var("command", "Real", "output", "Controller output: motor voltage", unit="V"),
        Var(
            "mode",
            "String",
            "parameter",
            "position or speed loop",
            _P.mode,
            choices=MODES,
            source=_SRC,
        ),
        Var(
            "kp",
            "Real",
            "parameter",
            "Proportional gain [V per rad or rad/s]",
            _P.kp,
            None,
            None,
            0.0,
            1e9,
            "tunable",
            source=_SRC,
        ),
        Var(
            "ki",
            "Real",
            "parameter",
            "Integral gain [V/s per rad or rad/s]",
            _P.ki,
            None,
            None,
            0.0,
            1e12,
            "tunable",
            source=_SRC,
        ),
        Var(
            "kd",
            "Real",
            "parameter",
            "Derivative gain [V·s per rad or rad/s]",
            _P.kd,
            None,
            None,
            0.0,
            1e9,
            "tunable",
            source=_SRC,
        ),
        Var(
            "derivative_filter",
            "Real",
            "parameter",
            "Time constant of the derivative filter",
            _P.derivative_filter,
            "s",
            "ms",
            1e-9,
            1e3,
            "tunable",
            source=_SRC,
        ),
        Var(
            "output_min",
            "Real",
            "parameter",
            "Lower output limit",
            _P.output_min,
            "V",
            None,
            -1e4,
            1e4,
            "tunable",
            source=_SRC,
        ),
        Var(
            "output_max",
            "Real",
            "parameter",
            "Upper output limit",
            _P.output_max,
            "V",
            None,
            -1e4,
            1e4,
            "tunable",
            source=_SRC,
        ),
        Var(
            "sample_period",
            "Real",
            "parameter",
            "Sample period",
            _P.sample_period,
            "s",
            "ms",
            1e-7,
            1e3,
            source=_SRC,
        ),
    )

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.pid = PIDState()
        self.next_sample = 0  # index k of the next sample instant t0 + k·Ts
        self.start_time = 0.0

    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        self.start_time = float(start_time)

    def configure(self):
        self.params = PIDParameters(
            mode=self.mode,
            kp=self.kp,
            ki=self.ki,
            kd=self.kd,
            derivative_filter=self.derivative_filter,
            output_min=self.output_min,
            output_max=self.output_max,
            sample_period=self.sample_period,
        )

    def initialise(self):
        # the command the first sample will give, without committing it (no integration yet)
        self.command, _ = pid_sample(self.params, self.pid, self.reference, self.measurement)

    def advance(self, current_time, step_size):
        end = current_time + step_size
        ts = self.params.sample_period
        # samples at t0 + k·Ts within [t, t + h), with the inputs held over the step
        while self.start_time + self.next_sample * ts < end - 1e-9 * ts:
            self.command, self.pid = pid_sample(
                self.params, self.pid, self.reference, self.measurement
            )
            self.next_sample += 1
        return True

    def hidden_state(self):
        return {
            "integral": self.pid.integral,
            "derivative": self.pid.derivative,
            "last_measurement": self.pid.last_measurement,
            "next_sample": self.next_sample,
            "start_time": self.start_time,
        }

    def restore_hidden_state(self, state):
        self.pid = PIDState(state["integral"], state["derivative"], state["last_measurement"])
        self.next_sample = state["next_sample"]
        self.start_time = state["start_time"]

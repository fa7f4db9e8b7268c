"""ServoController FMU: discrete PID with anti-windup and output limit, position or speed loop
(:mod:`servofmu.physics.drives.control`)."""

from __future__ import annotations

import math
from pathlib import Path

import servofmu

servofmu.share_copy(Path(__file__).parent)  # first of all: see its docstring

from servofmu.fmus.declarations import Item, Var, output, real_input, real_parameter  # noqa: E402
from servofmu.fmus.runtime import ServoSlave  # noqa: E402
from servofmu.physics.drives import control  # noqa: E402
from servofmu.physics.drives.control import MODES, PIDParameters, PIDState, pid_sample  # noqa: E402

#: The most samples one fmi2DoStep computes (the work per call is bounded: a longer step is
#: discarded, naming this limit)
MAX_SAMPLES = 100_000
_PID_FIELDS = ("integral", "derivative", "last_measurement")

_P = PIDParameters()
_SRC = "assumed: a speed loop for the gimbal motor of the DCMotor defaults"
_MODES = {
    "position": "position loop: reference and measurement in rad",
    "speed": "speed loop: reference and measurement in rad/s",
}


def _param(name, description, **kw):
    """A Real parameter (keywords as :func:`real_parameter`), tunable unless said."""
    return real_parameter(name, description, **{"variability": "tunable", "source": _SRC, **kw})


class ServoController(ServoSlave):
    """Discrete PID controller sampled every sample_period."""

    description = "Discrete PID (derivative on measurement, clamping anti-windup, output limit)"
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-3)
    PHYSICS = ("servofmu.physics.drives.control",)
    VARIABLES = (
        real_input(
            "reference",
            "Set point: angle [rad] in position mode, speed [rad/s] in speed mode",
            start=0.0,
            min=-1.0e9,
            max=1.0e9,
        ),
        real_input(
            "measurement", "Measured angle [rad] or speed [rad/s]", start=0.0, min=-1.0e9, max=1.0e9
        ),
        # sampled: no direct feedthrough while stepping; right after initialization the first
        # sample's command (no integral or derivative yet: clip(kp·(r − y)))
        output(
            "command",
            "Controller output: motor voltage",
            unit="V",
            initial_depends=("reference", "measurement", "kp", "output_min", "output_max"),
        ),
        Var(
            name="mode",
            type="Enumeration",
            causality="parameter",
            description="Position or speed loop (the units of reference and measurement)",
            start=MODES.index(_P.mode) + 1,
            items=tuple(Item(m, _MODES[m]) for m in MODES),
            declared_type="ControllerMode",
            source=_SRC,
        ),
        _param("kp", "Proportional gain [V per rad or rad/s]", start=_P.kp, min=0.0, max=1e9),
        _param("ki", "Integral gain [V/s per rad or rad/s]", start=_P.ki, min=0.0, max=1e12),
        _param("kd", "Derivative gain [V·s per rad or rad/s]", start=_P.kd, min=0.0, max=1e9),
        _param(
            "derivative_filter",
            "Time constant of the derivative filter",
            start=_P.derivative_filter,
            unit="s",
            display_unit="ms",
            min=1e-9,
            max=1e3,
        ),
        _param(
            "output_min", "Lower output limit", start=_P.output_min, unit="V", min=-1e4, max=1e4
        ),
        _param(
            "output_max", "Upper output limit", start=_P.output_max, unit="V", min=-1e4, max=1e4
        ),
        _param(
            "sample_period",
            "Sample period",
            start=_P.sample_period,
            unit="s",
            display_unit="ms",
            min=1e-7,
            max=1e3,
            variability="fixed",
        ),
    )

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.pid = PIDState()
        self.next_sample = 0  # index k of the next sample instant t0 + k·Ts (t0: start time)

    def configure(self):
        self.params = PIDParameters(
            mode=self.item("mode"),
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
        last = math.ceil((end - 1e-9 * ts - self._start_time) / ts)  # first sample not due
        due = last - self.next_sample
        if due > MAX_SAMPLES:
            self._error = (
                f"communicationStepSize = {step_size!r} s holds {due} samples of sample_period "
                f"= {ts!r} s; one step takes at most {MAX_SAMPLES} (≤ {MAX_SAMPLES * ts:g} s "
                "here): take shorter steps"
            )
            return False
        for _ in range(max(0, due)):
            self.command, self.pid = pid_sample(
                self.params, self.pid, self.reference, self.measurement
            )
        self.next_sample = max(self.next_sample, last)
        return True

    shared_step = staticmethod(control.shared_step)

    def _bind_shared_step(self, step):
        slots = self._shared.slots
        step.bind(
            self.params,
            pid_sample,
            self.pid,
            self.next_sample,
            self._start_time,
            MAX_SAMPLES,
            (slots["reference"], slots["measurement"]),
            slots["command"],
        )
        return True

    def _read_shared_step(self, step):
        self.pid, self.next_sample = step.pid, step.next_sample

    def state_problem(self):
        # every step leaves next_sample at the first sample instant not yet due
        if self._time is None or not self._configured:
            return ""
        ts = self.params.sample_period
        due = max(0, math.ceil((self._time - 1e-9 * ts - self._start_time) / ts))
        if self.next_sample != due:
            return (
                f"next_sample = {self.next_sample!r} is not the next sample at time = "
                f"{self._time!r} s ({due}, sample_period = {ts!r} s)"
            )
        return ""

    def hidden_state(self):
        return {
            "integral": self.pid.integral,
            "derivative": self.pid.derivative,
            "last_measurement": self.pid.last_measurement,
            "next_sample": self.next_sample,
        }

    def restore_hidden_state(self, state):
        integral, derivative, last = (state[k] for k in _PID_FIELDS)
        numbers = (integral, derivative, 0.0 if last is None else last)
        if not all(type(x) in (int, float) for x in numbers):
            raise TypeError(f"{_PID_FIELDS}: numbers, not {(integral, derivative, last)!r}")
        for name, x in zip(_PID_FIELDS, numbers, strict=True):
            if not math.isfinite(x):  # a sample of finite inputs gives finite values
                raise ValueError(f"{name} = {x!r} is not finite")
        if type(state["next_sample"]) is not int:
            raise TypeError(f"next_sample = {state['next_sample']!r} is not an integer")
        self.pid = PIDState(float(integral), float(derivative), last)
        self.next_sample = state["next_sample"]

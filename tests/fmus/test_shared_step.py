"""The compiled step on the shared values (``servofmu.physics.shared_step``): a model that has
one takes its steps there, and a host sees what the slave's Python path gives, bit for bit:
the same statuses, values, Boolean outputs, states and log messages. The reference is the same
FMU with every call in Python (``SERVOFMU_SHARED_VALUES=0``), run in this process over the
same calls; the script of calls visits what the compiled step declines (a warning to give, a
step that does not continue the last, an input out of range, a restored state) and what it
must hand back (reads through Python between its steps)."""

from __future__ import annotations

import importlib
import math
from collections import Counter

import pytest
from fmpy.fmi1 import FMICallException
from fmu_helpers import Fmu

from servofmu.build.exportlib import compiled_export
from servofmu.build.fmu import FMUS
from servofmu.fmus import shared_values
from servofmu.fmus.part_temperatures import PARTS
from servofmu.fmus.runtime import ServoSlave

pytestmark = pytest.mark.skipif(
    compiled_export() is None, reason="servofmu's export was not compiled (no C++17 compiler)"
)


def _steps(inputs, n, h):
    return [("step", inputs(k), h) for k in range(n)]


def _bearing_script(temperature):
    """BearingFriction's script; ``temperature(T)``: the temperature inputs at T [K]."""

    def inputs(t, speed, axial=5.0, radial=0.0):
        return {**temperature(t), "speed": speed, "axial_load": axial, "radial_load": radial}

    return [
        *_steps(lambda k: inputs(253.15, 0.2 * math.sin(0.3 * k)), 30, 1e-3),  # reversals
        *_steps(lambda k: {}, 5, 1e-3),  # the inputs kept: nothing to compute
        ("booleans",),
        ("save",),
        # below the lubricant's data (a warning) and back, with the loads changing
        *_steps(lambda k: inputs(293.15 - 5.0 * k, 0.1, 5.0 + k, k), 20, 1e-3),
        ("booleans",),
        ("restore",),
        *_steps(lambda k: inputs(200.0 + 5.0 * k, -0.1, 10.0, 2.0), 20, 1e-3),
        *_steps(lambda k: inputs(293.15, 0.05, -30.0), 3, 1e-3),  # the other bearing
        *_steps(lambda k: inputs(293.15, 0.05 * (k % 2)), 4, 1e-3),
        ("booleans",),
        ("save",),
        *_steps(lambda k: inputs(293.15, 1e5), 1, 1e-3),  # out of range: error
        ("restore",),
        *_steps(lambda k: inputs(293.15, 0.05), 3, 1e-3),
        *_steps(lambda k: inputs(293.15, 0.05), 1, -1e-3),  # not a step size: error
    ]


def _uniform(t):
    return {"temperature": t}


def _parts(t):
    return {f"{p}_temperature": t + d for p, d in zip(PARTS, (0.0, 2.0, 0.5, 1.5), strict=True)}


def _actuator_script(position, temperature, beyond=None):
    """ActuatorStiffness's script; ``position(k)``: the position inputs at step k (angle and
    speed, or the motor's), ``temperature(T)``: the temperature inputs at T [K]; ``beyond``:
    a position the linkage cannot reach (its step is discarded), if any."""

    def inputs(k, torque, t=293.15):
        return {**position(k), **temperature(t), "load_torque": torque}

    return [
        *_steps(lambda k: inputs(k, 150.0 * math.sin(0.4 * k)), 30, 1e-2),  # moment through 0
        *_steps(lambda k: {}, 3, 1e-2),  # the inputs kept: nothing to compute
        ("save",),
        *_steps(lambda k: inputs(30 + k, 100.0, 293.15 - 6.0 * k), 20, 1e-2),
        ("restore",),
        *_steps(lambda k: inputs(k, -80.0, 350.0), 5, 1e-2),
        ("save",),
        *([] if beyond is None else [("step", {**beyond, "load_torque": 10.0}, 1e-2)]),
        *([] if beyond is None else [("restore",)]),
        *_steps(lambda k: inputs(k, 1e9), 1, 1e-2),  # out of range: error
        ("restore",),
        *_steps(lambda k: inputs(k, 50.0), 3, 1e-2),
        *_steps(lambda k: inputs(k, 50.0), 1, -1e-2),  # not a step size: error
    ]


def _output_side(k):
    return {"angle": 0.6 * math.sin(0.2 * k), "speed": 0.12 * math.cos(0.2 * k)}


def _motor_side(k):
    return {"motor_angle": 30.0 * math.sin(0.2 * k), "motor_speed": 6.0 * math.cos(0.2 * k)}


def _stepped_script(name, inputs, huge, too_long):
    """The script of a stepped FMU: ``inputs(k)`` at step k, a value out of range ``huge``
    ({input: value}), and a step size holding too many sub-steps or samples (discarded)."""
    return [
        *_steps(inputs, 30, 1e-3),
        *_steps(lambda k: {}, 3, 1e-3),  # the inputs kept
        ("save",),
        *_steps(lambda k: inputs(30 + k), 10, 0.5e-3),
        ("restore",),
        *_steps(lambda k: inputs(40 + k), 5, 2.5e-3),
        *_steps(lambda k: inputs(50 + k), 1, too_long),  # discarded
        ("restore",),
        ("save",),
        *_steps(lambda k: huge, 1, 1e-3),  # out of range: error
        ("restore",),
        *_steps(lambda k: inputs(60 + k), 3, 1e-3),
        ("at", 1e6),  # does not continue the last step
        *_steps(lambda k: inputs(60 + k), 1, 1e-3),
    ]


def _motor_inputs(k):
    friction = 0.0 if k % 10 < 5 else 2e-3  # without friction, then with it
    return {
        "voltage": 6.0 * math.sin(0.3 * k),
        "load_torque": 1e-3 * math.cos(0.2 * k),
        "friction_running_torque": friction,
        "friction_breakaway_torque": 1.5 * friction,
    }


def _controller_inputs(k):
    return {"reference": 1.0 if k % 20 < 10 else 50.0, "measurement": 0.02 * k}


#: Per case: (FMU, parameters and inputs at the start, the script of calls).
#: ("step", {input: value}, h): set the inputs, fmi2DoStep, read every output;
#: ("save",) / ("restore",): fmi2GetFMUstate / fmi2SetFMUstate; ("at", t): the next step's
#: point; ("booleans",): read the Boolean outputs.
SCRIPTS = {
    "ThermalNetwork": (
        "ThermalNetwork",
        dict(ambient_temperature=293.15, power_loss=0.05, minimum_part_temperature=260.0),
        [
            *_steps(lambda k: {"ambient_temperature": 293.15 - 0.01 * k}, 30, 1e-3),
            ("booleans",),
            ("save",),
            *_steps(lambda k: {"power_loss": 0.05 + 0.01 * k}, 10, 0.5),
            ("restore",),
            *_steps(lambda k: {"power_loss": 0.05 + 0.01 * k}, 10, 0.5),
            # the parts cool below minimum_part_temperature (a warning), and warm up again
            *_steps(lambda k: {"ambient_temperature": 200.0}, 20, 200.0),
            ("booleans",),
            *_steps(lambda k: {"ambient_temperature": 300.0}, 40, 200.0),
            ("booleans",),
            ("save",),
            *_steps(lambda k: {"ambient_temperature": 1e5}, 1, 1.0),  # out of range: error
            ("restore",),
            *_steps(lambda k: {"ambient_temperature": 290.0}, 3, 1.0),
            ("at", 1e6),  # does not continue the last step
            *_steps(lambda k: {"ambient_temperature": 290.0}, 1, 1.0),
        ],
    ),
    "BearingFriction": ("BearingFriction", {}, _bearing_script(_uniform)),
    "DCMotor": (
        "DCMotor",
        {},
        _stepped_script("DCMotor", _motor_inputs, {"voltage": 1e5}, 20.0),
    ),
    "ServoController": (
        "ServoController",
        {},
        _stepped_script("ServoController", _controller_inputs, {"reference": 1e12}, 200.0),
    ),
    "ActuatorStiffness": ("ActuatorStiffness", {}, _actuator_script(_output_side, _uniform)),
    "ActuatorStiffness, motor side, parts": (
        "ActuatorStiffness",
        dict(motor_side_inputs=True, temperature_mode="parts"),
        _actuator_script(_motor_side, _parts, beyond={"motor_angle": 9e3}),
    ),
    "ActuatorStiffness, no support bearings, housing and shaft": (
        "ActuatorStiffness",
        dict(support_bearings=False, temperature_mode="housing_shaft"),
        _actuator_script(
            _output_side, lambda t: {"housing_temperature": t, "shaft_temperature": t - 4.0}
        ),
    ),
    "BearingFriction, pre-rolling": (
        "BearingFriction",
        dict(prerolling_model=1),
        _bearing_script(_uniform),
    ),
    "BearingFriction, pre-rolling of a given stiffness, parts": (
        "BearingFriction",
        dict(prerolling_model=1, prerolling_stiffness=5.0, temperature_mode="parts"),
        _bearing_script(_parts),
    ),
    "BearingFriction, skf2004, housing and shaft": (
        "BearingFriction",
        dict(friction_model="skf2004", temperature_mode="housing_shaft"),
        _bearing_script(lambda t: {"housing_temperature": t, "shaft_temperature": t + 3.0}),
    ),
}


#: What each case's script reaches besides its refusals (warnings, Boolean outputs set,
#: discarded steps), with every call in Python.
REACHES = {
    "ThermalNetwork": {"warning", "a Boolean set"},
    **{
        name: {"warning", "a Boolean set"} for name in SCRIPTS if name.startswith("BearingFriction")
    },
    "ActuatorStiffness, motor side, parts": {"discard"},
    "DCMotor": {"discard"},
    "ServoController": {"discard"},
}


def _call(record, what, f, *args):
    """Call ``f``; record (what, status, result)."""
    try:
        result, status = f(*args), 0
    except FMICallException as exc:
        result, status = None, exc.status
    record.append((what, status, result))
    return result


def _run(fmus, name, shared: bool, monkeypatch) -> tuple[list, list]:
    """Every answer of the script of ``name`` and the log, with or without shared values."""
    monkeypatch.setenv(shared_values.ENVIRONMENT, "1" if shared else "0")
    model, start, script = SCRIPTS[name]
    fmu = Fmu(fmus[model], "inst").init(**start)
    slave, vr = fmu.slave, fmu.vr
    outputs = [vr[n] for n in fmu.outputs() if fmu.type[n] == "Real"]
    booleans = [vr[n] for n in fmu.outputs() if fmu.type[n] == "Boolean"]
    record, t, saved, at = [], 0.0, None, None
    for op in script:
        if op[0] == "step":
            _, inputs, h = op
            for key, value in inputs.items():
                _call(record, f"set {key}", slave.setReal, [vr[key]], [value])
            point = t if at is None else at
            _call(record, "step", slave.doStep, point, h)
            t, at = (point + h if record[-1][1] == 0 else t), None
            _call(record, "outputs", slave.getReal, outputs)
        elif op[0] == "booleans":
            _call(record, "booleans", slave.getBoolean, booleans)
        elif op[0] == "save":
            saved, saved_t = slave.getFMUstate(), t
        elif op[0] == "restore":
            _call(record, "restore", slave.setFMUstate, saved)
            t = saved_t
        elif op[0] == "at":
            at = op[1]
    log = list(fmu.log)
    fmu.close()
    return record, log


@pytest.mark.parametrize("name", SCRIPTS)
def test_the_compiled_step_answers_as_the_python_path_bit_for_bit(fmus, monkeypatch, name):
    python, python_log = _run(fmus, name, False, monkeypatch)
    compiled, compiled_log = _run(fmus, name, True, monkeypatch)
    assert len(compiled) == len(python)
    for k, (a, b) in enumerate(zip(compiled, python, strict=True)):
        assert repr(a) == repr(b), f"answer {k}: {a} != {b}"  # repr: every bit of a float
    assert compiled_log == python_log
    # the script reaches what the compiled step must decline or hand back
    assert sum(what == "step" and status == 3 for what, status, _ in python) == 2  # refused
    reached = {
        "warning": any(status == 1 for status, _ in python_log),
        "a Boolean set": any(what == "booleans" and any(values) for what, _, values in python),
        "discard": any(what == "step" and status == 2 for what, status, _ in python),
    }
    assert {k for k, v in reached.items() if v} == REACHES.get(name, set()), reached
    assert [what for what, status, _ in python if what == "restore" and status == 0] == [
        "restore"
    ] * sum(op == ("restore",) for op in SCRIPTS[name][2])


@pytest.fixture
def python_steps(monkeypatch):
    """Counts of the slave's own do_step (the Python path) entered."""
    calls = Counter()
    original = ServoSlave.do_step

    def counting(self, *args):
        calls["do_step"] += 1
        return original(self, *args)

    monkeypatch.setattr(ServoSlave, "do_step", counting)
    return calls


@pytest.mark.parametrize("name", SCRIPTS)
def test_the_compiled_step_takes_the_steady_steps(fmus, python_steps, name):
    """After the start, a run of ordinary steps never enters the slave's own do_step; a step
    of a size that is not > 0 does (and is refused there)."""
    model, start, script = SCRIPTS[name]
    fmu = Fmu(fmus[model], "inst").init(**start)
    steps = [op for op in script if op[0] == "step"][:20]
    t = 0.0
    for _, inputs, h in steps:
        fmu.set(**inputs)
        fmu.slave.doStep(t, h)
        t += h
    assert python_steps == Counter()
    with pytest.raises(FMICallException):
        fmu.slave.doStep(t, -1e-3)
    assert python_steps == Counter(do_step=1)
    fmu.close()


def test_every_fmu_has_a_compiled_step():
    for name in FMUS:
        assert importlib.import_module(f"servofmu.fmus.{name}").__dict__[name].shared_step
    assert {model for model, _, _ in SCRIPTS.values()} == set(FMUS)

"""The Real values an instance shares with servofmu's export library: fmi2SetReal and
fmi2GetReal are served without entering Python where the slave's tables allow it, every other
call goes to the slave as before, and either way a host sees the same statuses, values and
messages (the Python path: ``SERVOFMU_SHARED_VALUES=0``).

The FMUs run in this process, so the slave class they instantiate is the one imported here:
counting the calls of its methods shows which FMI calls entered Python."""

from __future__ import annotations

import importlib
import math
from collections import Counter

import pytest
from fmpy.fmi1 import FMICallException
from fmu_helpers import Fmu

from servofmu.build.exportlib import compiled_export
from servofmu.fmus import shared_values
from servofmu.fmus.runtime import ServoSlave

NAMES = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController", "ThermalNetwork")
#: inputs at which each FMU runs, and the input a sequence varies
INPUTS = {
    "BearingFriction": (dict(temperature=253.15, speed=0.2, axial_load=5.0), "speed"),
    "ActuatorStiffness": (dict(angle=0.17, load_torque=150.0, temperature=263.15), "load_torque"),
    "DCMotor": (dict(voltage=6.0, load_torque=2e-3), "voltage"),
    "ServoController": (dict(reference=1.0, measurement=0.25), "measurement"),
    "ThermalNetwork": (dict(ambient_temperature=253.15, power_loss=0.05), "ambient_temperature"),
}
ENTRIES = ("set_real", "get_real", "do_step", "get_boolean")

pytestmark = pytest.mark.skipif(
    compiled_export() is None, reason="servofmu's export was not compiled (no C++17 compiler)"
)


@pytest.fixture
def python_calls(monkeypatch):
    """Counts of the slave's FMI entry points entered (from any FMU of this process)."""
    calls = Counter()
    for name in ENTRIES:
        original = getattr(ServoSlave, name)

        def counting(self, *args, _name=name, _original=original):
            calls[_name] += 1
            return _original(self, *args)

        monkeypatch.setattr(ServoSlave, name, counting)
    return calls


def _start(fmus, name, instance="inst") -> tuple[Fmu, list[int], list[int]]:
    inputs, _ = INPUTS[name]
    fmu = Fmu(fmus[name], instance).init(**inputs)
    ins = [fmu.vr[n] for n in inputs]
    outs = [fmu.vr[n] for n in fmu.outputs() if fmu.type[n] == "Real"]
    return fmu, ins, outs


@pytest.mark.parametrize("name", NAMES)
def test_a_step_crosses_into_python_once(fmus, python_calls, name):
    """One crossing per step: into the FMU's compiled step on the shared values, which enters
    no Python method of the slave."""
    fmu, ins, outs = _start(fmus, name)
    values = list(INPUTS[name][0].values())
    python_calls.clear()
    for k in range(20):
        fmu.slave.setReal(ins, [v * (1 + 1e-3 * k) for v in values])
        fmu.slave.doStep(k * 1e-3, 1e-3)
        assert all(math.isfinite(x) for x in fmu.slave.getReal(outs))
    compiled_step = getattr(fmus_module(name), name).shared_step is not None
    assert compiled_step
    assert python_calls == Counter(), python_calls
    fmu.close()


def fmus_module(name: str):
    """The module of FMU ``name``'s slave class."""
    return importlib.import_module(f"servofmu.fmus.{name}")


def test_without_shared_values_every_call_enters_python(fmus, python_calls, monkeypatch):
    monkeypatch.setenv(shared_values.ENVIRONMENT, "0")
    fmu, ins, outs = _start(fmus, "BearingFriction")
    python_calls.clear()
    for k in range(5):
        fmu.slave.setReal(ins, [253.15, 0.2 + 1e-3 * k, 5.0])
        fmu.slave.doStep(k * 1e-3, 1e-3)
        fmu.slave.getReal(outs)
    assert python_calls == Counter(set_real=5, do_step=5, get_real=5), python_calls
    fmu.close()


def _python_answers(fmu, calls, call, *args) -> tuple[int, int]:
    """(status, number of Python entries) of one FMI call."""
    before = sum(calls.values())
    try:
        getattr(fmu.slave, call)(*args)
        status = 0
    except FMICallException as exc:
        status = exc.status
    return status, sum(calls.values()) - before


def test_what_the_export_library_leaves_to_python(fmus, python_calls):
    """Each reason to decline: a value out of range or not finite, a parameter, an output,
    an unknown reference, a read while an algebraic FMU's inputs changed, a state that does
    not allow the call, a non-finite value to read."""
    fmu = _start(fmus, "BearingFriction")[0]
    vr = fmu.vr
    temperature, torque = vr["temperature"], vr["friction_torque"]
    fmu.slave.doStep(0.0, 1e-3)
    assert _python_answers(fmu, python_calls, "getReal", [torque]) == (0, 0)
    assert _python_answers(fmu, python_calls, "setReal", [temperature], [300.0]) == (0, 0)
    # the inputs changed: an algebraic FMU computes before the read (in Python), then not
    assert _python_answers(fmu, python_calls, "getReal", [torque]) == (0, 1)
    assert _python_answers(fmu, python_calls, "getReal", [torque]) == (0, 0)
    assert _python_answers(fmu, python_calls, "getReal", [vr["ball_diameter"]]) == (0, 0)
    for value in (1e6, math.nan, math.inf, 20.0):  # outside [173.15, 473.15] K or not finite
        assert _python_answers(fmu, python_calls, "setReal", [temperature], [value]) == (0, 1)
    assert _python_answers(fmu, python_calls, "setReal", [temperature], [293.15]) == (0, 0)
    fixed = vr["ball_diameter"]  # a fixed parameter, after initialization: refused
    assert _python_answers(fmu, python_calls, "setReal", [fixed], [2e-3]) == (3, 1)
    fmu.close()
    fmu = _start(fmus, "BearingFriction", "second")[0]
    for refs, values in (([torque], [1.0]), ([10_000], [1.0]), ([temperature, torque], [300, 1])):
        assert _python_answers(fmu, python_calls, "setReal", refs, values)[1] == 1
    fmu.close()
    fmu = _start(fmus, "BearingFriction", "third")[0]
    assert _python_answers(fmu, python_calls, "getReal", [10_000]) == (3, 1)
    # in the error state a read is served again; a step is not
    assert _python_answers(fmu, python_calls, "getReal", [vr["preload"]]) == (0, 0)
    assert _python_answers(fmu, python_calls, "doStep", 0.0, 1e-3)[0] == 3
    fmu.close()
    # before initialization: a set is served, a read goes to Python (and is refused)
    fmu = Fmu(fmus["DCMotor"], "fourth")
    assert _python_answers(fmu, python_calls, "setReal", [fmu.vr["voltage"]], [1.0]) == (0, 0)
    assert _python_answers(fmu, python_calls, "getReal", [fmu.vr["voltage"]]) == (3, 1)
    fmu.close()


def test_a_non_finite_value_is_read_through_python(fmus, python_calls):
    """ActuatorStiffness without support bearings: support_bearing_stiffness is +inf (its
    description says when), which the export library leaves to the slave."""
    fmu = Fmu(fmus["ActuatorStiffness"], "rigid")
    fmu.init(angle=0.17, load_torque=150.0, support_bearings=False)
    ref = fmu.vr["support_bearing_stiffness"]
    assert _python_answers(fmu, python_calls, "getReal", [ref]) == (0, 1)
    assert fmu.slave.getReal([ref]) == [math.inf]
    assert _python_answers(fmu, python_calls, "getReal", [fmu.vr["stiffness"]]) == (0, 0)
    fmu.close()


def _session(fmus, name: str, instance: str) -> list:
    """A host's session with good and bad calls; every status, value read and message."""
    inputs, varied = INPUTS[name]
    fmu = Fmu(fmus[name], instance)
    vr, log, record = fmu.vr, fmu.log, []
    reals = [vr[n] for n, t in fmu.type.items() if t == "Real"]
    bools = [vr[n] for n, t in fmu.type.items() if t == "Boolean"]

    def call(method, *args):
        n = len(log)
        try:
            result = getattr(fmu.slave, method)(*args)
            status = 0
        except FMICallException as exc:
            result, status = None, exc.status
        said = [m.replace(f"{instance}: ", "INST: ") for _, m in log[n:]]
        values = list(result) if method.startswith("get") and result is not None else None
        record.append((method, status, values, said))

    call("setupExperiment", None, 0.0)
    call("enterInitializationMode")
    call("setReal", [vr[n] for n in inputs], list(inputs.values()))
    call("getReal", reals)
    call("exitInitializationMode")
    t, h, saved = 0.0, 1e-3, None
    for k in range(12):
        value = inputs[varied] * (1.0 + 0.01 * k)
        if k == 4:
            value = math.nan  # refused at the step: the error state
        if k == 6:
            value = 1e12  # out of range
        call("setReal", [vr[varied]], [value])
        call("getReal", reals)
        call("getBoolean", bools)
        if k == 3:
            saved = fmu.slave.getFMUstate()
        call("doStep", t, h)
        if record[-1][1] == 0:
            t += h
        elif saved is not None:
            call("setFMUstate", saved)
            t = 3 * h  # the time of the state saved before the step at k = 3
        call("getReal", reals)
        call("getBoolean", bools)
    call("terminate")
    call("getReal", reals)
    call("getReal", [10_000])  # an unknown reference: the error state
    call("getReal", reals)
    fmu.slave.freeFMUstate(saved)
    fmu.slave.freeInstance()
    return record


@pytest.mark.parametrize("name", NAMES)
def test_both_paths_answer_a_host_alike(fmus, monkeypatch, name):
    shared = _session(fmus, name, "hostA")
    monkeypatch.setenv(shared_values.ENVIRONMENT, "0")
    python = _session(fmus, name, "hostB")
    assert len(shared) == len(python)
    for a, b in zip(shared, python, strict=True):
        assert a == b or (a[:3] == b[:3] and _same_but_the_export_line(a[3], b[3])), (a, b)
    statuses = Counter((r[0], r[1]) for r in shared)
    assert statuses["doStep", 0] >= 8 and statuses["doStep", 3] >= 2, statuses  # ran and erred


def _same_but_the_export_line(a: list, b: list) -> bool:
    return [m for m in a if "runs under" not in m] == [m for m in b if "runs under" not in m]

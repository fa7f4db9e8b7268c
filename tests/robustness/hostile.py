"""A careless or hostile FMI host: one case against one FMU, in this process.

    python hostile.py FMU CASE [--stock]

Each case makes the calls a careless host would make through fmpy's low-level ``FMU2Slave``
(and, for the C-level ones, through the FMU's functions with NULL pointers), with logging
*off* as in a plain fmpy run, and checks every answer:

- servofmu's export (default): a host's mistake gets fmi2Error (3) with an error message in
  the log, a step beyond what the FMU takes in bounded time fmi2Discard (2), never fmi2Fatal;
  an output is never non-finite with fmi2OK;
- pythonfmu's own binary (``--stock``; the FMUs of an install without a C++ compiler): never
  fmi2Fatal either, and the refusal shows as a discarded step (2) naming it, with logging on.

The process must then leave by a normal interpreter exit (exit status 0 and the line
"done"): a crash, an abort or a hang fails the case. After a first instantiation (the
imports of the FMU's code), the case's calls get ``--limit`` seconds of CPU time (default 5;
``RLIMIT_CPU``, so that a busy machine's waiting does not count: SIGXCPU ends a process that
computes longer) and ``--wall`` seconds in all (default 60; SIGALRM ends a process that
waits longer). Only fmpy (and numpy, scipy, which the FMUs use) is imported here.
"""

from __future__ import annotations

import argparse
import ctypes
import json
import math
import resource
import signal
import sys
import time
import zipfile
from pathlib import Path

from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException, calloc, free
from fmpy.fmi2 import (
    FMU2Slave,
    fmi2CallbackAllocateMemoryTYPE,
    fmi2CallbackFreeMemoryTYPE,
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
)

OK, DISCARD, ERROR, FATAL = 0, 2, 3, 4
GOOD_INPUTS = {  # FMU: inputs at which it runs
    "BearingFriction": {"temperature": 253.15, "speed": 0.2, "axial_load": 5.0},
    "ActuatorStiffness": {"angle": 0.17, "load_torque": 150.0, "temperature": 263.15},
    "DCMotor": {"voltage": 6.0, "load_torque": 2e-3},
    "ServoController": {"reference": 1.0, "measurement": 0.25},
    "ThermalNetwork": {"ambient_temperature": 253.15, "power_loss": 0.05},
}
ALGEBRAIC = ("BearingFriction", "ActuatorStiffness")
_KEEP = []  # ctypes callbacks must outlive the instances


class Host:
    """One FMU instance; :meth:`call` returns the status of an FMI call and the messages it
    logged."""

    #: logging on or off when not said: off for servofmu's export (a plain fmpy run's default,
    #: under which its errors must still be logged), on for pythonfmu's binary (which logs
    #: nothing otherwise)
    logging = False

    def __init__(self, path: Path, name: str = "host", logging: bool | None = None):
        self.path = Path(path)
        self.md = read_model_description(str(path))
        self.model = self.md.coSimulation.modelIdentifier
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.log: list[tuple[int, str]] = []
        self.dir = extract(str(path))

        def logger(env, instance, status, category, message):
            text = message.decode(errors="replace") if isinstance(message, bytes) else message
            self.log.append((status, str(text)))

        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        _KEEP.append((cb, logger))
        self.callbacks = cb
        self.slave = FMU2Slave(
            guid=self.md.guid,
            unzipDirectory=self.dir,
            modelIdentifier=self.model,
            instanceName=name,
        )
        self.slave.instantiate(callbacks=cb, loggingOn=self.logging if logging is None else logging)

    def call(self, method: str, *args):
        """(status, result, messages logged by the call)."""
        n = len(self.log)
        try:
            result = getattr(self.slave, method)(*args)
            status = OK
        except FMICallException as exc:
            status, result = exc.status, None
        return status, result, self.log[n:]

    def raw(self, function: str, *args) -> tuple[int, list]:
        """A C call with the arguments as given (NULL pointers included)."""
        n = len(self.log)
        status = self.slave._functions[function](self.slave.component, *args)
        return status, self.log[n:]

    def vr(self, name: str) -> int:
        return self.vars[name].valueReference

    def init(self, **values):
        self.slave.setupExperiment(startTime=0.0)
        self.slave.enterInitializationMode()
        for name, value in {**GOOD_INPUTS[self.model], **values}.items():
            self.slave.setReal([self.vr(name)], [value])
        self.slave.exitInitializationMode()
        return self

    def outputs(self) -> list:
        return [v for v in self.md.modelVariables if v.causality == "output" and v.type == "Real"]

    def read_outputs(self) -> tuple[int, list]:
        status, values, _ = self.call("getReal", [v.valueReference for v in self.outputs()])
        return status, values

    def free(self):
        self.slave.freeInstance()


class Checker:
    """The expectations of one case; :meth:`report` prints them and the verdict."""

    def __init__(self, stock: bool):
        self.stock = stock
        self.failures: list[str] = []
        self.calls: list[dict] = []

    def refused(self, what: str, answer, host: Host | None = None):
        """A host's mistake: fmi2Error and an error message (servofmu's export), or (stock)
        no fatal status; either way never fmi2Fatal."""
        status, _, messages = answer
        self.calls.append({"call": what, "status": status, "log": [m for _, m in messages]})
        if status == FATAL:
            self.failures.append(f"{what}: fmi2Fatal")
        elif not self.stock:
            if status < ERROR:
                self.failures.append(f"{what}: status {status}, not fmi2Error")
            elif not any(s >= ERROR for s, _ in messages):
                self.failures.append(f"{what}: fmi2Error without an error message in the log")

    def discarded(self, what: str, answer, words: str):
        """A step the FMU does not take: fmi2Discard (stock: too), a message naming ``words``
        (logged with logging on; servofmu's export logs discards only then, as FMI says)."""
        status, _, messages = answer
        self.calls.append({"call": what, "status": status, "log": [m for _, m in messages]})
        if status != DISCARD:
            self.failures.append(f"{what}: status {status}, not fmi2Discard")
        elif messages and not any(words in m for _, m in messages):
            self.failures.append(f"{what}: the discard's message does not name {words!r}")

    def status(self, what: str, status: int, expected: int):
        """A call without an instance to log through: only its status."""
        self.calls.append({"call": what, "status": status, "log": []})
        if status != expected:
            self.failures.append(f"{what}: status {status}, not {expected}")

    def ok(self, what: str, answer):
        status, _, messages = answer
        self.calls.append({"call": what, "status": status, "log": [m for _, m in messages]})
        if status != OK:
            self.failures.append(f"{what}: status {status}, expected fmi2OK ({messages})")

    def finite_or_refused(self, what: str, host: Host):
        """The outputs: finite with fmi2OK (+inf where documented), or the read refused."""
        status, values = host.read_outputs()
        if status == OK:
            bad = [
                (v.name, x)
                for v, x in zip(host.outputs(), values, strict=True)
                if not math.isfinite(x) and not (x == math.inf and "inf when" in v.description)
            ]
            if bad:
                self.failures.append(f"{what}: fmi2OK with non-finite outputs {bad}")
        elif status == FATAL:
            self.failures.append(f"{what}: reading the outputs gave fmi2Fatal")

    def report(self) -> int:
        print(json.dumps({"calls": self.calls, "failures": self.failures}))
        return 1 if self.failures else 0


# ----------------------------------------------------------------------------- cases
def _choice_or_none(host: Host):
    """An Integer variable (a choice), or None."""
    return next((v for v in host.md.modelVariables if v.type in ("Integer", "Enumeration")), None)


def _a_real(host: Host, causality: str):
    return next(v for v in host.md.modelVariables if v.type == "Real" and v.causality == causality)


def _fixed_parameter(host: Host):
    return next(
        v
        for v in host.md.modelVariables
        if v.causality == "parameter" and v.variability == "fixed" and v.type == "Real"
    )


def unknown_references(path, check: Checker, stock: bool):
    """Unknown value references for every type, ten times over, then ordinary calls."""
    host = Host(path).init()
    huge = [2**31 - 1]
    for _ in range(10):
        for method in ("getReal", "getInteger", "getBoolean", "getString"):
            check.refused(f"{method}({huge})", host.call(method, huge))
            if not stock:  # the error state: restore the state saved before
                pass
        for method, value in (
            ("setReal", [1.0]),
            ("setInteger", [1]),
            ("setBoolean", [True]),
            ("setString", ["x"]),
        ):
            check.refused(f"{method}({huge})", host.call(method, huge, value))
    _after_refusals(host, check, stock)


def wrong_types(path, check: Checker, stock: bool):
    """Value references of another type: a Real as Integer, Boolean, String; a choice (an
    Integer) as Real; setters likewise."""
    host = Host(path).init()
    real = _a_real(host, "output").valueReference
    for _ in range(5):
        for method in ("getInteger", "getBoolean", "getString"):
            check.refused(f"{method}(Real {real})", host.call(method, [real]))
        check.refused("setInteger(a Real input)", host.call("setInteger", [real], [1]))
        check.refused("setBoolean(a Real input)", host.call("setBoolean", [real], [True]))
        check.refused("setString(a Real input)", host.call("setString", [real], ["1"]))
        choice = _choice_or_none(host)
        if choice is not None:
            check.refused("getReal(a choice)", host.call("getReal", [choice.valueReference]))
            check.refused("setReal(a choice)", host.call("setReal", [choice.valueReference], [1.0]))
    _after_refusals(host, check, stock)


def corrupt_states(path, check: Checker, stock: bool):
    """Bytes that are not a state of this FMU: fmi2DeSerializeFMUstate refuses each (and the
    instance, untouched, steps on); a refused state given to fmi2SetFMUstate is refused."""
    host = Host(path).init()
    state = host.slave.getFMUstate()
    good = bytes(host.slave.serializeFMUstate(state))
    host.slave.freeFMUstate(state)
    data = json.loads(good)
    wrong_model = dict(data, fmu="SomethingElse")
    extra = dict(data, method_override={"get_real": 1})
    values = dict(data, values={**data["values"], "get_real": 1.0})
    other_build = dict(data, package="0" * 64)
    typed = dict(data, values={k: "x" for k in data["values"]})
    blobs = {
        "junk": b"\x00\xffnot a state",
        "empty": b"",
        "not a table": b"[1, 2, 3]",
        "truncated": good[: len(good) // 2],
        "deep": b"[" * 100_000 + b"]" * 100_000,
        "another FMU": json.dumps(wrong_model).encode(),
        "an extra field": json.dumps(extra).encode(),
        "an extra variable": json.dumps(values).encode(),
        "another build": json.dumps(other_build).encode(),
        "values of the wrong type": json.dumps(typed).encode(),
    }
    for what, blob in blobs.items():
        status, restored, messages = host.call("deSerializeFMUstate", blob)
        check.refused(f"deSerializeFMUstate({what})", (status, restored, messages))
        if status == OK and restored is not None:  # stock: a refusal travels in the state
            check.refused(f"setFMUstate({what})", host.call("setFMUstate", restored))
            host.slave.freeFMUstate(restored)
            break  # the instance is in the error state now
    if not stock:  # servofmu's export: the instance was never touched, it steps on
        check.ok("doStep after refused bytes", host.call("doStep", 0.0, 1e-3))
        check.finite_or_refused("outputs after refused bytes", host)
    _after_refusals(host, check, stock, steps=False)


def foreign_states(path, check: Checker, stock: bool):
    """fmi2SetFMUstate with another FMU's state, and with a crafted Python object whose keys
    would replace methods: refused, and the instance's values stay as they were."""
    host = Host(path).init()
    other_path = _other_fmu(path)
    other = Host(other_path, "other").init()
    foreign = other.slave.getFMUstate()
    before = host.read_outputs()
    check.refused("setFMUstate(another FMU's state)", host.call("setFMUstate", foreign))
    after = host.read_outputs()
    if after[0] == OK and before[1] != after[1]:
        check.failures.append("a refused state changed the outputs")
    crafted = {"get_real": None, "do_step": None, "values": {}}
    ctypes.pythonapi.Py_IncRef(ctypes.py_object(crafted))  # the FMU owns one reference
    _KEEP.append(crafted)
    check.refused(
        "setFMUstate(a crafted object)", host.call("setFMUstate", ctypes.c_void_p(id(crafted)))
    )
    other.slave.freeFMUstate(foreign)
    _after_refusals(host, check, stock)
    other.free()


def state_machine(path, check: Checker, stock: bool):
    """Calls in states where FMI 2.0 forbids them, each on a fresh instance."""
    host = Host(path)
    output = _a_real(host, "output").valueReference
    fixed = _fixed_parameter(host)
    check.refused("getReal before initialization", host.call("getReal", [output]))
    _after_refusals(host, check, stock, initialised=False)

    def fresh(stage: str) -> Host:
        h = Host(path, stage)
        if stage in ("setup", "enter"):
            h.slave.setupExperiment(startTime=0.0)
        if stage == "enter":
            h.slave.enterInitializationMode()
        return h.init() if stage == "initialised" else h

    cases = [
        ("doStep before initialization", "new", "doStep", (0.0, 1e-3)),
        ("exitInitializationMode before enter", "setup", "exitInitializationMode", ()),
        ("doStep in initialization mode", "enter", "doStep", (0.0, 1e-3)),
        ("setReal(an output)", "enter", "setReal", ([output], [1.0])),
        (
            f"setReal(fixed parameter {fixed.name}) after initialization",
            "initialised",
            "setReal",
            ([fixed.valueReference], [float(fixed.start)]),
        ),
        ("setupExperiment after initialization", "initialised", "setupExperiment", ()),
        ("enterInitializationMode twice", "initialised", "enterInitializationMode", ()),
    ]
    for what, stage, method, args in cases:
        h = fresh(stage)
        check.refused(what, h.call(method, *args))
        h.free()
    h = fresh("initialised")
    check.ok("doStep", h.call("doStep", 0.0, 1e-3))
    check.ok("reset", h.call("reset"))
    check.refused("doStep after reset, not initialised", h.call("doStep", 1e-3, 1e-3))
    h.free()
    h = fresh("initialised")
    check.ok("terminate", h.call("terminate"))
    check.refused("doStep after terminate", h.call("doStep", 0.0, 1e-3))
    h.free()


def bad_steps(path, check: Checker, stock: bool):
    """Step sizes and communication points FMI 2.0 does not allow: zero, negative, NaN,
    infinite; a point that does not continue the last step (a jump, not caught up)."""
    for t, h in ((0.0, 0.0), (0.0, -1e-3), (math.nan, 1e-3), (0.0, math.inf), (0.0, math.nan)):
        host = Host(path, "steps").init()
        check.refused(f"doStep({t}, {h})", host.call("doStep", t, h))
        host.free()
    # a stepped FMU refuses a point that does not continue its last step; an algebraic one
    # (outputs from its inputs alone) takes a step at any point
    jump = check.ok if Path(path).stem in ALGEBRAIC else check.refused
    host = Host(path, "jump").init()
    check.ok("doStep(0, 1 ms)", host.call("doStep", 0.0, 1e-3))
    jump("doStep(1e5, 1 ms) after a step to 1 ms", host.call("doStep", 1e5, 1e-3))
    host.free()
    host = Host(path, "late").init()
    jump("a first doStep at 10 s after startTime 0", host.call("doStep", 10.0, 1e-3))
    _after_refusals(host, check, stock, steps=False)


def long_steps(path, check: Checker, stock: bool):
    """Steps of 1e7 s and 1e18 s: taken in bounded time with finite outputs, or discarded
    naming the limit; never a NaN with fmi2OK."""
    words = "at most" if Path(path).stem in ("DCMotor", "ServoController") else ""
    for h in (1e3, 1e7, 1e18):
        host = Host(path, "long", logging=True).init()
        status, result, messages = host.call("doStep", 0.0, h)
        if status == OK:
            check.finite_or_refused(f"outputs after doStep(0, {h:g})", host)
        else:
            check.discarded(f"doStep(0, {h:g})", (status, result, messages), words)
        host.free()


def non_finite_inputs(path, check: Checker, stock: bool):
    """NaN and infinite inputs: the step refused naming the input and its value; the outputs
    read then are finite (or the read refused)."""
    for value in (math.nan, math.inf, -math.inf, 1e308):
        host = Host(path, "nan").init()
        name = next(iter(GOOD_INPUTS[host.model]))
        host.slave.setReal([host.vr(name)], [value])
        status, result, messages = host.call("doStep", 0.0, 1e-3)
        if value == 1e308 and status == OK:
            check.finite_or_refused(f"outputs after {name} = 1e308", host)
        else:
            check.refused(f"doStep with {name} = {value}", (status, result, messages))
            if not stock and not any(f"{name} = {value!r}" in m for _, m in messages):
                check.failures.append(f"doStep with {name} = {value}: message does not name it")
        check.finite_or_refused(f"outputs after {name} = {value}", host)
        host.free()


def null_pointers(path, check: Checker, stock: bool):
    """C-level mistakes: NULL arrays, NULL states, a NULL component, a double free of a
    state, a wrong GUID, a model-exchange instance (servofmu's export only: pythonfmu's
    binary dereferences them)."""
    if stock:
        return
    host = Host(path).init()
    n = ctypes.c_size_t(1)
    for function in ("fmi2GetReal", "fmi2SetReal", "fmi2GetInteger", "fmi2GetBoolean"):
        status, messages = host.raw(function, None, n, None)
        check.refused(f"{function}(vr = NULL)", (status, None, messages))
    status, messages = host.raw("fmi2SetFMUstate", None)
    check.refused("fmi2SetFMUstate(NULL)", (status, None, messages))
    status, messages = host.raw("fmi2DeSerializeFMUstate", None, ctypes.c_size_t(8), None)
    check.refused("fmi2DeSerializeFMUstate(NULL, 8, NULL)", (status, None, messages))
    status = host.slave._functions["fmi2DoStep"](None, 0.0, 1e-3, 1)
    check.status("fmi2DoStep(NULL component)", status, ERROR)
    state = host.slave.getFMUstate()
    pointer = ctypes.c_void_p(state.value)
    host.slave.freeFMUstate(state)
    check.ok("freeFMUstate", (OK, None, []))
    if state.value is not None:
        check.failures.append("fmi2FreeFMUstate left the host's pointer set")
    del pointer
    check.ok("doStep after the C-level refusals", host.call("doStep", 0.0, 1e-3))
    host.free()
    # instantiation refused, with a message, and the process goes on
    for what, kwargs in (
        ("a wrong GUID", {"guid": "{00000000-0000-0000-0000-000000000000}"}),
        ("fmi2ModelExchange", {"fmuType": 0}),
    ):
        log = []
        status = _instantiate_raw(path, log, **kwargs)
        if status:
            check.failures.append(f"fmi2Instantiate with {what} gave an instance")
        elif not any(s >= ERROR for s, _ in log):
            check.failures.append(f"fmi2Instantiate with {what}: refused without a message")
        check.calls.append({"call": f"fmi2Instantiate({what})", "status": status, "log": log})


def _instantiate_raw(path, log, guid=None, fmuType=1) -> bool:
    """fmi2Instantiate with the given GUID and type; True when it returned an instance."""
    md = read_model_description(str(path))
    slave = FMU2Slave(
        guid=guid or md.guid,
        unzipDirectory=extract(str(path)),
        modelIdentifier=md.coSimulation.modelIdentifier,
        instanceName="raw",
    )

    def logger(env, instance, status, category, message):
        log.append((status, message.decode(errors="replace")))

    cb = fmi2CallbackFunctions()
    cb.logger = fmi2CallbackLoggerTYPE(logger)
    cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
    cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
    _KEEP.append((cb, logger))
    uri = Path(slave.unzipDirectory, "resources").as_uri()
    component = slave.fmi2Instantiate(
        b"raw", fmuType, slave.guid.encode(), uri.encode(), ctypes.byref(cb), 0, 0
    )
    if component:
        slave.fmi2FreeInstance(component)
    return bool(component)


def _other_fmu(path: Path) -> Path:
    """Another FMU of the same folder (DCMotor, or ServoController for DCMotor)."""
    other = "ServoController" if Path(path).stem == "DCMotor" else "DCMotor"
    return Path(path).with_name(f"{other}.fmu")


def _after_refusals(host: Host, check: Checker, stock: bool, steps=True, initialised=True):
    """After the refusals: the instance answers ordinary calls without crashing. servofmu's
    export: it is in the error state (FMI 2.0), so a step is refused, naming the first
    failure; a state saved before the error restores it, and it steps again. pythonfmu's
    binary: the next step is discarded."""
    if initialised and steps:
        answer = host.call("doStep", 0.0, 1e-3)
        if stock:
            check.discarded("doStep after the refusals", answer, "it failed with")
        else:
            check.refused("doStep in the error state", answer)
    check.finite_or_refused("outputs after the refusals", host)
    host.call("terminate")
    host.call("reset")
    host.init()
    check.ok("doStep after fmi2Reset", host.call("doStep", 0.0, 1e-3))
    check.finite_or_refused("outputs after fmi2Reset", host)
    host.free()


def free_at_once(path, check: Checker, stock: bool):
    """Instances freed right after fmi2Instantiate and right after fmi2Reset, with logging on
    (a message still queued in the slave was logged through a freed logger)."""
    for _ in range(3):
        Host(path, "brief", logging=True).free()
        host = Host(path, "reset", logging=True)
        check.ok("reset right after instantiate", host.call("reset"))
        host.free()
        host = Host(path, "stepped", logging=True).init()
        check.ok("doStep", host.call("doStep", 0.0, 1e-3))
        check.ok("reset after a step", host.call("reset"))
        host.free()


CASES = {
    f.__name__: f
    for f in (
        free_at_once,
        unknown_references,
        wrong_types,
        corrupt_states,
        foreign_states,
        state_machine,
        bad_steps,
        long_steps,
        non_finite_inputs,
        null_pointers,
    )
}


def _cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fmu", type=Path)
    parser.add_argument("case", choices=sorted(CASES))
    parser.add_argument("--stock", action="store_true", help="the FMU carries pythonfmu's binary")
    parser.add_argument("--limit", type=int, default=5, help="CPU seconds for the case's calls")
    parser.add_argument("--wall", type=int, default=60, help="seconds in all for the calls")
    args = parser.parse_args(argv)
    with zipfile.ZipFile(args.fmu) as zf:  # the FMU's own record of its export
        export = json.loads(zf.read("resources/servofmu_build.json"))["export"]
    if export != ("pythonfmu" if args.stock else "servofmu"):
        print(f"{args.fmu} carries the {export} export", file=sys.stderr)
        return 2
    check = Checker(args.stock)
    Host.logging = args.stock
    Host(args.fmu, "warm-up").free()  # the imports of the FMU's code, outside the limits
    used = _cpu()
    resource.setrlimit(resource.RLIMIT_CPU, (math.ceil(used + args.limit), resource.RLIM_INFINITY))
    signal.alarm(args.wall)  # the default actions of SIGXCPU and SIGALRM end the process
    wall = time.perf_counter()
    CASES[args.case](args.fmu, check, args.stock)
    signal.alarm(0)
    check.calls.append({"cpu_s": round(_cpu() - used, 3), "wall_s": time.perf_counter() - wall})
    rc = check.report()
    print("done", flush=True)
    return rc


if __name__ == "__main__":
    sys.exit(main())

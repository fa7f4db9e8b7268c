"""Property-based fuzzing of the servofmu FMUs through fmpy (hypothesis), run in a child
process by ``tests/fmus/test_robustness.py`` so that a crash of the host would show as a failed
test, not as a dead test run.

Two properties per FMU:

- **calls**: a random sequence of FMI calls, legal and illegal (get before initialization,
  steps before or after an error, zero, negative and non-finite step sizes, reset anywhere,
  state get/set/serialise anywhere, unknown and wrong-typed value references for every
  fmi2Get*/fmi2Set*, bytes that are not a state of the FMU), with random values for the
  inputs and the parameters (NaN, ±inf, huge and tiny magnitudes, negative temperatures, junk
  strings). Every call must return a valid FMI status and never fmi2Fatal; an unknown or
  wrong-typed value reference and corrupt bytes get fmi2Error with an error message (the
  servofmu export); a step that returns fmi2OK leaves every Real output finite (+inf only
  where the variable's description documents it, e.g. the stiffness of absent support
  bearings); a refused step logs a message naming a variable and its value (the badly set
  one when only bad values were set), the step's arguments, or the state that forbids it.
- **state**: random inputs and steps, the state saved at a random point, serialised to bytes
  and restored in the same and in a fresh instance: the continuations are bit-identical.

Under pythonfmu's own binary (``--stock``: the FMUs of an install without a C++ compiler),
which the slave never lets an exception reach, a host's mistake is answered with an error
message and a harmless value: an unknown or wrong-typed value reference returns fmi2OK with
the error logged, and corrupt bytes give a state that fmi2SetFMUstate refuses, logging why.

Usage: ``python tests/robustness/fmi_fuzz.py FMU_DIR [--examples N] [--fmu NAME ...]
[--stock]``.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
from collections import Counter
from pathlib import Path

from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # tests/: the shared FMU driver
from fmu_helpers import Fmu

NAMES = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController", "ThermalNetwork")
EXTREMES = (
    math.nan,
    math.inf,
    -math.inf,
    1e308,
    -1e308,
    1e-308,
    5e-324,
    0.0,
    -0.0,
    -273.15,
    -1.0,
    1e30,
)
STEPS = (1e-4, 1e-3, 1e-2, 0.1, 0.0, -1e-3, math.nan, math.inf, 1e-9, 5.0)
STRINGS = (
    "",
    "yu2017_gimbal",
    "ning_space_shaft",
    "71803",
    "71807C",
    "grease",
    "solid",
    "krytox_143aa",
    "mos2_film",
    "position",
    "speed",
    "liu2014_screw_support",
    "../../etc/passwd",
    "x" * 300,
    "\u00e9\u2013\U0001f600",
)


class Instance(Fmu):
    """One instance of ``target``; every call goes through :meth:`call`, which records the
    status."""

    def __init__(self, target: Target):
        super().__init__(target.path, "fuzz", unzip_dir=target.dir, md=target.md)
        self.states = []

    def call(self, name, *args):
        """(status, result): status 0 for a call that returned normally."""
        try:
            return 0, getattr(self.slave, name)(*args)
        except FMICallException as exc:
            return exc.status, None

    def close(self):  # no fmi2Terminate: the sequence may have left any state
        for s in self.states:
            self.call("freeFMUstate", s)
        self.slave.freeInstance()


class Target:
    """An FMU under test: its description, its unpacked folder, the variables used."""

    def __init__(self, path: Path):
        self.path = path
        self.md = read_model_description(str(path))
        self.dir = extract(str(path))
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.reals_out = [v for v in self.md.modelVariables if v.causality == "output" and
                          v.type == "Real"]  # fmt: skip
        self.settable = [
            v
            for v in self.md.modelVariables
            if v.causality == "input" or (v.causality == "parameter")
        ]


def _value(v):
    if v.type == "Real":
        lo = float(v.min) if v.min is not None else -1e6
        hi = float(v.max) if v.max is not None else 1e6
        good = st.floats(min_value=lo, max_value=hi)
        # a good value three times in five, so that calls reach deep states
        return st.one_of(good, good, good, st.sampled_from(EXTREMES), st.floats())
    if v.type == "String":
        return st.one_of(st.sampled_from(STRINGS), st.text(max_size=12))
    if v.type == "Boolean":
        return st.booleans()
    any_int = st.integers(-(2**31), 2**31 - 1)
    lo, hi = _int_range(v)
    if lo is None:
        return any_int
    good = st.integers(lo, hi)  # a choice's items, mostly
    return st.one_of(good, good, good, st.sampled_from([lo - 1, hi + 1, 0]), any_int)


def _int_range(v):
    """(min, max) of an Integer variable (a choice's items), or (None, None)."""
    if v.type == "Enumeration" and v.declaredType is not None:
        values = [int(item.value) for item in v.declaredType.items]
        return min(values), max(values)
    if v.min is not None and v.max is not None:
        return int(v.min), int(v.max)
    return None, None


#: FMI types a host may name, and the method names of fmpy's FMU2Slave
KINDS = ("Real", "Integer", "Boolean", "String")
#: The status of a call a host got wrong: fmi2Error under servofmu's export; fmi2OK and an
#: error message under pythonfmu's binary (--stock)
MISTAKE = {"status": 3}
CORRUPT = ("junk", "truncated", "another FMU", "extra field", "wrong type")


def operations(fmu: Target):
    """One FMI call: a set (any settable variable, a value mostly in range), a step (mostly
    a usual size), an output read, a value reference that is unknown or of another type, a
    corrupt state, or one of the rarer calls."""

    def sets(variables):
        return st.sampled_from(variables).flatmap(
            lambda v: st.tuples(st.just("set"), st.just(v.name), _value(v))
        )

    inputs = [v for v in fmu.settable if v.causality == "input"]
    usual = st.sampled_from((1e-4, 1e-3, 1e-2))
    step = st.tuples(st.just("step"), st.one_of(usual, usual, st.sampled_from(STEPS)))
    wrong = st.tuples(
        st.just("wrong"),
        st.sampled_from(("get", "set")),
        st.sampled_from(KINDS),
        st.one_of(
            st.sampled_from(sorted(v.valueReference for v in fmu.vars.values())),
            st.integers(len(fmu.vars), 2**32 - 1),  # unknown
        ),
    )
    rare = st.one_of(
        wrong,
        st.tuples(st.just("corrupt"), st.sampled_from(CORRUPT)),
        st.sampled_from(
            [
                ("setup",),
                ("enter",),
                ("exit",),
                ("reset",),
                ("restart",),
                ("terminate",),
                ("get_state",),
                ("set_state",),
                ("serialize",),
            ]
        ),
    )
    # inputs and steps most often, and a restart after a mistake (the error state allows little
    # else: FMI 2.0), so that sequences reach deep states between the mistakes
    return st.one_of(sets(inputs), sets(inputs), sets(fmu.settable), step, step, step,
                     st.just(("get",)), st.just(("restart",)), rare, rare)  # fmt: skip


def bad(v, value) -> bool:
    """Is ``value`` outside what variable ``v`` accepts (non-finite or outside min/max)?"""
    if v.type in ("Integer", "Enumeration"):
        lo, hi = _int_range(v)
        return lo is not None and not lo <= value <= hi
    if v.type != "Real":
        return False
    x = float(value)
    if not math.isfinite(x):
        return True
    return (v.min is not None and x < float(v.min)) or (v.max is not None and x > float(v.max))


def _fmi_type(v) -> str:
    return "Integer" if v.type == "Enumeration" else v.type


def _wrong_reference(fmu: Target, inst: Instance, op) -> int:
    """A get or set through a value reference that is unknown or of another FMI type than
    the call's: fmi2Error with an error message; 0 when the reference fits (a legal call)."""
    _, direction, kind, vr = op
    var = next((v for v in fmu.vars.values() if v.valueReference == vr), None)
    if var is not None and _fmi_type(var) == kind:
        return 0  # not a mistake: the property is about the others
    n_log = len(inst.log)
    if direction == "get":
        status, _ = inst.call(f"get{kind}", [vr])
    else:
        value = {"Real": 1.0, "Integer": 1, "Boolean": True, "String": "x"}[kind]
        status, _ = inst.call(f"set{kind}", [vr], [value])
    assert status == MISTAKE["status"], f"{op}: status {status}, not {MISTAKE['status']}"
    assert any(s == 3 for s, _ in inst.log[n_log:]), f"{op}: no error message"
    return status


def _corrupt_bytes(inst: Instance, what: str) -> bytes:
    """Bytes that are not a state of the FMU."""
    if what == "junk":
        return b"\x00\xff not a state"
    state = inst.slave.getFMUstate()
    data = bytes(inst.slave.serializeFMUstate(state))
    inst.slave.freeFMUstate(state)
    if what == "truncated":
        return data[: len(data) // 2]
    record = json.loads(data)
    if what == "another FMU":
        record["fmu"] = "NotThisOne"
    elif what == "extra field":
        record["values"]["do_step"] = 1.0
    else:
        record["values"] = {k: [v] for k, v in record["values"].items()}
    return json.dumps(record).encode()


def _initialise(inst: Instance) -> int:
    """fmi2SetupExperiment(0), fmi2EnterInitializationMode, fmi2ExitInitializationMode: the
    highest status."""
    status = 0
    for call, args in (("setupExperiment", (None, 0.0)), ("enterInitializationMode", ()),
                       ("exitInitializationMode", ())):  # fmt: skip
        status = max(status, inst.call(call, *args)[0])
    return status


def run_calls(fmu: Target, ops, stats: Counter, initialised: bool = False) -> None:
    """The ``ops`` on a new instance, initialised first when ``initialised`` (a host that
    starts right, then errs), else from instantiated."""
    inst = Instance(fmu)
    time = 0.0
    if initialised:
        assert _initialise(inst) == 0, inst.log
    recently_bad: dict[str, float] = {}  # names set to a bad value since the last good step
    recently_set: set[str] = set()  # every name set since the last good step
    saved_at: list[float] = []  # the time of each state in inst.states
    try:
        for op in ops:
            kind = op[0]
            if kind == "set":
                v = fmu.vars[op[1]]
                setter = {
                    "Real": "setReal",
                    "Integer": "setInteger",
                    "Boolean": "setBoolean",
                    "String": "setString",
                    "Enumeration": "setInteger",
                }[v.type]
                status, _ = inst.call(setter, [v.valueReference], [op[2]])
                recently_set.add(v.name)
                if bad(v, op[2]):
                    recently_bad[v.name] = op[2]
                else:
                    recently_bad.pop(v.name, None)
            elif kind == "step":
                n_log = len(inst.log)
                status, _ = inst.call("doStep", time, op[1])
                if status == 0:
                    time += op[1]
                    recently_set.clear()
                    values = [inst.slave.getReal([v.valueReference])[0] for v in fmu.reals_out]
                    bad_outputs = [  # +inf only where the description documents it
                        (v.name, x)
                        for v, x in zip(fmu.reals_out, values, strict=True)
                        if not math.isfinite(x)
                        and not (x == math.inf and "inf when" in (v.description or ""))
                    ]
                    assert not bad_outputs, f"fmi2OK step left non-finite outputs {bad_outputs}"
                elif status in (2, 3):
                    new = " ".join(m for _, m in inst.log[n_log:])
                    names = [*fmu.vars, "communicationStepSize", "currentCommunicationPoint"]
                    named = [n for n in names if re.search(rf"\b{re.escape(n)} = \S", new)]
                    sequence = "illegal call sequence: fmi2DoStep in state" in new
                    assert named or sequence, f"step refused with a log that names nothing: {new!r}"
                    good_step = math.isfinite(op[1]) and op[1] > 0
                    if (
                        good_step
                        and not sequence
                        and recently_bad
                        and not recently_set - set(recently_bad)
                    ):
                        assert set(named) & set(recently_bad), (
                            f"after bad {recently_bad} the log says {new!r}"
                        )
            elif kind == "wrong":
                status = _wrong_reference(fmu, inst, op)
            elif kind == "corrupt":
                n_log = len(inst.log)
                status, restored = inst.call("deSerializeFMUstate", _corrupt_bytes(inst, op[1]))
                if MISTAKE["status"] == 0:  # pythonfmu's binary: the refusal travels in the state
                    assert status == 0 and restored is not None, f"{op}: status {status}"
                    status, _ = inst.call("setFMUstate", restored)
                    inst.call("freeFMUstate", restored)
                    recently_bad.clear()
                else:
                    assert status == 3 and restored is None, f"{op}: status {status}"
                assert any(s == 3 for s, _ in inst.log[n_log:]), f"{op}: no error message"
            elif kind == "get":
                status = 0
                for v in fmu.reals_out:
                    s, _ = inst.call("getReal", [v.valueReference])
                    status = max(status, s)
            elif kind == "setup":
                status, _ = inst.call("setupExperiment", None, time)
            elif kind == "enter":
                status, _ = inst.call("enterInitializationMode")
            elif kind == "exit":
                status, _ = inst.call("exitInitializationMode")
            elif kind == "reset":
                status, _ = inst.call("reset")
                recently_bad.clear()
                time = 0.0
            elif kind == "restart":  # what a host does after an error: reset, initialise
                status, _ = inst.call("reset")
                recently_bad.clear()
                time = 0.0
                status = max(status, _initialise(inst))
            elif kind == "terminate":
                status, _ = inst.call("terminate")
            elif kind == "get_state":
                status, state = inst.call("getFMUstate")
                if state is not None:
                    inst.states.append(state)
                    saved_at.append(time)
            elif kind == "set_state":
                status = 0
                if inst.states:
                    status, _ = inst.call("setFMUstate", inst.states[-1])
                    recently_bad.clear()  # the restored values are the saved ones
                    time = saved_at[-1]  # and the time (a stepped FMU continues from there)
            elif kind == "serialize":
                status = 0
                if inst.states:
                    status, data = inst.call("serializeFMUstate", inst.states[-1])
                    if data is not None:
                        s2, state = inst.call("deSerializeFMUstate", data)
                        status = max(status, s2)
                        if state is not None:
                            inst.states.append(state)
                            saved_at.append(saved_at[-1])
            stats[(kind, status)] += 1
            assert status in (0, 1, 2, 3), f"{op} returned status {status}"
    finally:
        inst.close()


def run_state(fmu: Target, inputs, steps_before: int, steps_after: int, h: float) -> None:
    """Save at a point, continue; restore (same instance, and a fresh one from bytes) and
    continue again: identical outputs."""
    names = [v for v in fmu.settable if v.causality == "input" and v.type == "Real"]

    def start(inst):
        inst.slave.setupExperiment(startTime=0.0)
        inst.slave.enterInitializationMode()
        inst.slave.exitInitializationMode()

    def drive(inst, k0, n):
        out = []
        for k in range(k0, k0 + n):
            for v, x in zip(names, inputs[k % len(inputs)], strict=False):
                inst.slave.setReal([v.valueReference], [x])
            inst.slave.doStep(k * h, h)
            out.append(tuple(inst.slave.getReal([v.valueReference for v in fmu.reals_out])))
        return out

    a = Instance(fmu)
    b = Instance(fmu)
    try:
        start(a)
        drive(a, 0, steps_before)
        state = a.slave.getFMUstate()
        a.states.append(state)
        data = a.slave.serializeFMUstate(state)
        first = drive(a, steps_before, steps_after)
        a.slave.setFMUstate(state)
        again = drive(a, steps_before, steps_after)
        start(b)
        restored = b.slave.deSerializeFMUstate(bytes(data))
        b.states.append(restored)
        b.slave.setFMUstate(restored)
        fresh = drive(b, steps_before, steps_after)
        assert first == again, "restore in the same instance diverged"
        assert first == fresh, "restore from bytes in a fresh instance diverged"
    finally:
        a.close()
        b.close()


def in_range(v):
    lo = float(v.min) if v.min is not None else -1e3
    hi = float(v.max) if v.max is not None else 1e3
    # the middle of the range, where the physics runs (the edges are the calls property's)
    mid, half = 0.5 * (lo + hi), 0.5 * (hi - lo)
    return st.floats(min_value=mid - 0.01 * half, max_value=mid + 0.01 * half)


def _properties(fmu: Target, stats: Counter, common: dict, state_examples: int):
    """The two hypothesis tests of one FMU."""
    inputs = [v for v in fmu.settable if v.causality == "input" and v.type == "Real"]

    @settings(**common)
    @given(st.sampled_from((True, True, True, False)), st.lists(operations(fmu), max_size=30))
    def calls(initialised, ops):
        run_calls(fmu, ops, stats, initialised)

    @settings(**{**common, "max_examples": state_examples})
    @given(
        st.lists(st.tuples(*(in_range(v) for v in inputs)), min_size=1, max_size=5),
        st.integers(0, 20),
        st.integers(1, 20),
        st.sampled_from((1e-4, 1e-3, 1e-2)),
    )
    def state(values, before, after, h):
        run_state(fmu, values, before, after, h)

    return calls, state


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fmu_dir")
    parser.add_argument("--examples", type=int, default=200)
    parser.add_argument("--fmu", action="append", choices=NAMES)
    parser.add_argument("--seed", type=int, help="derandomised run with this seed")
    parser.add_argument("--stock", action="store_true", help="FMUs with pythonfmu's binary")
    args = parser.parse_args(argv)
    if args.stock:
        MISTAKE["status"] = 0
    for name in args.fmu or NAMES:
        fmu = Target(Path(args.fmu_dir) / f"{name}.fmu")
        stats: Counter = Counter()
        common = dict(
            max_examples=args.examples,
            deadline=None,
            database=None,
            derandomize=args.seed is None,
            suppress_health_check=list(HealthCheck),
            print_blob=True,
        )

        calls, state = _properties(fmu, stats, common, max(10, args.examples // 10))

        if args.seed is not None:
            from hypothesis import seed

            calls = seed(args.seed)(calls)
            state = seed(args.seed)(state)
        calls()
        state()
        summary = ", ".join(f"{k}:{s}×{n}" for (k, s), n in sorted(stats.items()))
        print(f"{name}: {args.examples} call sequences and state checks passed ({summary})")
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())

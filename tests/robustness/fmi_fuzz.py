"""Property-based fuzzing of the servofmu FMUs through fmpy (hypothesis), run in a child
process by ``tests/test_robustness.py`` so that a crash of the host would show as a failed
test, not as a dead test run.

Two properties per FMU:

- **calls**: a random sequence of FMI calls, legal and illegal (get before initialization,
  steps before or after an error, zero, negative and non-finite step sizes, reset anywhere,
  state get/set/serialise anywhere), with random values for the inputs and the parameters
  (NaN, ±inf, huge and tiny magnitudes, negative temperatures, junk strings). Every call must
  return a valid FMI status and never fmi2Fatal; a step that returns fmi2OK leaves every Real
  output finite (+inf only where the variable's description documents it, e.g. the stiffness
  of absent support bearings); a refused step logs a message naming a variable and its value,
  the badly set one when only bad values were set.
- **state**: random inputs and steps, the state saved at a random point, serialised to bytes
  and restored in the same and in a fresh instance: the continuations are bit-identical.

Usage: ``python tests/robustness/fmi_fuzz.py FMU_DIR [--examples N] [--fmu NAME ...]``.
"""

from __future__ import annotations

import argparse
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


def operations(fmu: Target):
    """One FMI call: a set (any settable variable, a value mostly in range), a step (mostly
    a usual size), an output read, or one of the rarer calls."""
    sets = st.sampled_from(fmu.settable).flatmap(
        lambda v: st.tuples(st.just("set"), st.just(v.name), _value(v))
    )
    usual = st.sampled_from((1e-4, 1e-3, 1e-2))
    return st.one_of(
        sets,
        st.tuples(st.just("step"), st.one_of(usual, usual, st.sampled_from(STEPS))),
        st.just(("get",)),
        st.sampled_from(
            [
                ("setup",),
                ("enter",),
                ("exit",),
                ("get",),
                ("get",),
                ("reset",),
                ("terminate",),
                ("get_state",),
                ("set_state",),
                ("serialize",),
            ]
        ),
    )


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


def run_calls(fmu: Target, ops, stats: Counter) -> None:
    inst = Instance(fmu)
    time = 0.0
    recently_bad: dict[str, float] = {}  # names set to a bad value since the last good step
    recently_set: set[str] = set()  # every name set since the last good step
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
                    assert named, f"step refused with a log that names no variable: {new!r}"
                    good_step = math.isfinite(op[1]) and op[1] >= 0
                    if good_step and recently_bad and not recently_set - set(recently_bad):
                        assert set(named) & set(recently_bad), (
                            f"after bad {recently_bad} the log says {new!r}"
                        )
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
            elif kind == "terminate":
                status, _ = inst.call("terminate")
            elif kind == "get_state":
                status, state = inst.call("getFMUstate")
                if state is not None:
                    inst.states.append(state)
            elif kind == "set_state":
                status = 0
                if inst.states:
                    status, _ = inst.call("setFMUstate", inst.states[-1])
                    recently_bad.clear()  # the restored values are the saved ones
            elif kind == "serialize":
                status = 0
                if inst.states:
                    status, data = inst.call("serializeFMUstate", inst.states[-1])
                    if data is not None:
                        s2, state = inst.call("deSerializeFMUstate", data)
                        status = max(status, s2)
                        if state is not None:
                            inst.states.append(state)
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
    @given(st.lists(operations(fmu), max_size=30))
    def calls(ops):
        run_calls(fmu, ops, stats)

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
    args = parser.parse_args(argv)
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

"""The dependencies the built FMUs declare in ModelStructure are true (an
InitialUnknown without them reads "depends on everything", and OMSimulator then finds loops
that are not there).

Through fmpy, for each FMU: the outputs right after initialization at a base point, then again
with each input and each parameter changed alone (a few values each; a choice: every other
item; a number tied to others, within 1 % when larger changes are refused). An output may
move only with the inputs and parameters its InitialUnknowns entry
declares, and it must move with at least one of them (unless it declares none). A change the
FMU refuses (its log says error) tells nothing about dependencies and is skipped, but every
variable must have at least one accepted change. The stepped FMUs' outputs must not move when
an input changes without a step (no direct feedthrough: their Outputs list none).
"""

from __future__ import annotations

import pytest
from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException
from fmu_helpers import Fmu

BASE = {
    "BearingFriction": dict(temperature=253.15, speed=0.2, axial_load=5.0, radial_load=3.0),
    "ActuatorStiffness": dict(temperature=253.15, speed=0.1, load_torque=150.0, angle=0.17),
    "DCMotor": dict(
        voltage=2.0,
        load_torque=1e-3,
        friction_running_torque=1e-3,
        friction_breakaway_torque=2e-3,
        initial_current=0.3,
        initial_speed=1.0,
        initial_angle=0.5,
    ),
    "ServoController": dict(reference=1.0, measurement=0.4, kp=2.0, ki=10.0, kd=0.1),
    "ThermalNetwork": dict(ambient_temperature=263.15, sink_temperature=250.0, power_loss=0.5),
}
# a change where the base value is 0, by unit
STEP = {"m": 2e-6, "N": 20.0, "N/m": 1e8, "rad/s": 0.3, "A": 0.5, "rad": 0.1, "V": 2.0}
# choice items that need other values to be accepted (a preload method needs its force or
# spring): changed together with them (their own dependencies are probed alone)
_PRELOAD = {2: {"assembly_preload": 50.0}, 3: {"spring_stiffness": 1e5, "spring_compression": 3e-4}}
COMPANIONS = {
    "preload_method": _PRELOAD,
    "support_preload_method": {
        i: {f"support_{k}": v for k, v in values.items()} for i, values in _PRELOAD.items()
    },
    "support_loop_reading": {2: {"support_shaft_length": 0.014}},
}


def _candidates(v, base):
    """Values to try for variable ``v`` (fmpy ModelVariable) whose base value is ``base``."""
    if v.name in _items:
        return [i for i in _items[v.name].values() if i != base]
    if v.type == "Boolean":
        return [not base]
    lo = -float("inf") if v.min is None else float(v.min)
    hi = float("inf") if v.max is None else float(v.max)
    if v.type == "Integer":
        return [x for x in (base + 1, base - 1) if lo <= x <= hi]
    if v.type != "Real":
        return []
    if v.unit == "K" and base > 100.0:  # an absolute temperature (else a difference)
        values = [base + 10.0, base + 100.0, base - 80.0]
    elif base == 0.0:
        step = STEP.get(v.unit, 0.5)
        values = [step, -step, 10 * step]
    else:
        values = [base * 1.1, base * 0.5, base * 0.1, base * 2.0]
    return [x for x in values if lo <= x <= hi]


_items: dict = {}


class _Probe:
    """Instantiates one FMU again and again and reads its outputs after initialization."""

    def __init__(self, path):
        self.path = path
        self.md = read_model_description(str(path))
        self.dir = extract(str(path))
        self.outputs = [v.name for v in self.md.modelVariables if v.causality == "output"]

    def initial(self, values):
        log = []
        fmu = Fmu(self.path, "dep", unzip_dir=self.dir, log=log, md=self.md)
        try:
            fmu.init(**values)
            if any(status >= 3 for status, _ in log):
                return None, fmu.items
            return {n: fmu.get(n) for n in self.outputs}, fmu.items
        except FMICallException:  # refused (fmi2Error at fmi2ExitInitializationMode)
            return None, fmu.items
        finally:
            fmu.close()


@pytest.mark.slow
@pytest.mark.parametrize("name", list(BASE))
def test_initial_unknowns_declare_their_true_dependencies(fmus, name):
    _check(fmus[name], name, BASE[name])


# BearingFriction under its other friction models, with the grease term on: the inputs and the
# parameters of the friction's groups, and two of the state (loads reach the SKF and EHL terms)
_FRICTION_GROUPS = ("friction_model", "skf", "density", "grease", "grease_start", "lubricant",
                    "lubrication", "hysteresis", "sliding", "viscous", "breakaway")  # fmt: skip


@pytest.mark.slow
@pytest.mark.parametrize("model", ["skf2004", "ehl_per_contact"])
def test_dependencies_hold_under_each_friction_model(fmus, model):
    from servofmu.parameters.bearing import parameter, parameters_in

    base = {
        **BASE["BearingFriction"],
        "friction_model": parameter("friction_model").item(model),
        "grease_f0": 50.0,
        "grease_starting_ratio": 2.0,
    }
    only = {"speed", "temperature", "axial_load", "radial_load", "shim", "n_balls"}
    # (lubrication solid refuses a grease term: probed at the default base above)
    friction = set(parameters_in(*_FRICTION_GROUPS)) - {"friction_model", "lubrication"}
    _check(fmus["BearingFriction"], "BearingFriction", base, only | friction)


def _check(path, name, base_values, only=None):
    """Every output of FMU ``path`` moves only with what its InitialUnknowns entry declares,
    probed from ``base_values`` by changing each input and parameter (of ``only``) alone."""
    probe = _Probe(path)
    base, items = probe.initial(base_values)
    assert base is not None, f"{name}: the base point is refused"
    _items.clear()
    _items.update(items)
    declared = {u.variable.name: {d.name for d in u.dependencies} for u in probe.md.initialUnknowns}
    knowns = [v for v in probe.md.modelVariables if v.causality in ("input", "parameter")]
    if only is not None:
        knowns = [v for v in knowns if v.name in only]
    moved = {o: set() for o in probe.outputs}
    untested = []
    for v in knowns:
        start = base_values.get(v.name, v.start)
        if v.type == "Boolean":
            start = start in (True, "true", "1")
        else:
            start = float(start) if v.type == "Real" else int(start)
        accepted = 0
        near = [start * 1.01, start * 0.99] if v.type == "Real" else []
        for value in [*_candidates(v, start), None, *near]:
            if value is None:  # a number tied to others (a pitch diameter between d and D)
                if accepted:  # is tried close to its start only when nothing else was taken
                    break
                continue
            with_it = COMPANIONS.get(v.name, {}).get(value, {})
            out, _ = probe.initial({**base_values, **with_it, v.name: value})
            if out is None:
                continue
            accepted += 1
            for o in probe.outputs:
                if out[o] != base[o]:
                    moved[o].add(v.name)
        if not accepted:
            untested.append(v.name)
    assert not untested, f"{name}: no accepted change of {untested}"
    for o in probe.outputs:
        undeclared = moved[o] - declared[o]
        assert not undeclared, f"{name}.{o} moves with {sorted(undeclared)}, not declared"
        if declared[o] and only is None:
            assert moved[o], f"{name}.{o} moves with none of its dependencies {declared[o]}"


@pytest.mark.parametrize("name", ["DCMotor", "ServoController"])
def test_stepped_outputs_do_not_feed_through(fmus, name):
    probe = _Probe(fmus[name])
    md = probe.md
    assert all(u.dependencies == [] for u in md.outputs)
    fmu = Fmu(fmus[name], "ft", unzip_dir=probe.dir, md=md).init(**BASE[name])
    try:
        before = {o: fmu.get(o) for o in probe.outputs}
        for v in md.modelVariables:
            if v.causality == "input":
                fmu.set(**{v.name: 2.0 * float(BASE[name].get(v.name, 1.0)) + 1.0})
        assert {o: fmu.get(o) for o in probe.outputs} == before
    finally:
        fmu.close()

"""The slowest single step of BearingFriction and ActuatorStiffness across their declared
parameter and input ranges (on demand: ``make bench``; not part of the tests).

Each configuration is a parameter set at a corner of the declared ranges (loop stiffness
1 N/m and 1e13 N/m, each arrangement and preload method, each friction model, a lubricant
with a cold point, the part-temperature modes) driven through one input history that visits
the inputs' corners: a temperature ramp over 173…473 K with changing axial and radial loads,
axial loads of ±1e4 and ±1e5 N, radial loads to 1e5 N, housing and shaft 300 K apart, and the
cold and hot ends. Every step is what a master does through fmpy's FMU2Slave (set the inputs,
fmi2DoStep, get one output), timed alone; the history runs ``--repeat`` times on fresh
instances and each step keeps its smallest time (the step's own cost: a time above it is the
machine's, another process or a collection), then the slowest step of each configuration is
reported with the inputs it had, and the slowest of all. ``--clock cpu`` (default) times this
process's CPU time, ``wall`` wall-clock time. The first solve is part of
fmi2ExitInitializationMode, reported apart ("init").
"""

from __future__ import annotations

import argparse
import json
import math
import tempfile
import time
from pathlib import Path

from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave
from results import save  # benchmarks/ is the script's folder

from servofmu.build.fmu import build_all
from servofmu.parameters.bearing import PARAMETERS, default_parameters

LIMIT = 10e-3  # s: the aim for one step

_RIGID = default_parameters("yu2017_gimbal_rigid") | {"outer_interference": 0.0}
#: BearingFriction configurations: parameter values (SI; choices as keys) over the defaults,
#: and the temperature mode (1 uniform, 2 housing_shaft, 3 parts).
BEARING_CONFIGS = {
    "default (Yu's gimbal, yoke)": ({}, 1),
    "loop_stiffness 1 N/m": ({"loop_stiffness": 1.0}, 1),
    "loop_stiffness 1e13 N/m": ({"loop_stiffness": 1.0e13}, 1),
    "rigid tube, members": (_RIGID, 1),
    "back_to_back (Ning's shaft, solid)": (default_parameters("ning_space_shaft"), 1),
    "face_to_face, Liu's screw support": (default_parameters("liu2014_screw_support"), 1),
    "tandem, force": (
        _RIGID | {"arrangement": "tandem", "preload_method": "force", "assembly_preload": 40.0},
        1,
    ),
    "tandem, spring": (
        _RIGID
        | {
            "arrangement": "tandem",
            "preload_method": "spring",
            "spring_stiffness": 2.0e5,
            "spring_compression": 2.0e-4,
        },
        1,
    ),
    "spring preload": (default_parameters("yu2017_gimbal_spring"), 1),
    "skf2004": ({"friction_model": "skf2004"}, 1),
    "ehl_per_contact": ({"friction_model": "ehl_per_contact"}, 1),
    "Pennzane (cold point: Vogel)": (default_parameters(lubricant="pennzane_2000"), 1),
    "housing_shaft mode": ({}, 2),
    "parts mode": ({}, 3),
}


def _bearing_history() -> list[tuple]:
    """(temperature, housing, shaft, outer ring, inner ring [K], speed [rad/s], axial, radial
    load [N]); the uniform temperature is the housing's."""
    out = []

    def at(t, axial=0.0, radial=0.0, shaft=None, speed=0.1):
        s = t if shaft is None else shaft
        out.append((t, t, s, t, s, speed, axial, radial))

    for k in range(60):  # a triangle 173 → 473 → 173 K
        t = 173.15 + 300.0 * (1.0 - abs(1.0 - k / 30.0))
        at(t, 20.0 + 10.0 * math.sin(0.7 * k), 10.0 + 10.0 * math.sin(1.1 * k))
    for k in range(20):
        at(293.15 + 0.5 * k)  # a slow ramp without load
    for f in (1.0e4, -1.0e4, 1.0e4, 0.0, 1.0e5, -1.0e5, 0.0):
        at(300.0, f)
    for fr in (100.0, 1.0e4, 1.0e5, 0.0):
        at(300.0, 20.0, fr)
    for housing, shaft in ((473.15, 173.15), (173.15, 473.15), (400.0, 250.0), (250.0, 400.0)):
        at(housing, 0.0, shaft=shaft)
        at(housing, -100.0, shaft=shaft)
    at(173.15, speed=1.0e4)
    at(473.15, speed=-1.0e4)
    return out


def _actuator_history() -> list[tuple]:
    """(temperature, housing, shaft, outer ring, inner ring [K], speed [rad/s], load torque
    [N·m], angle [rad])."""
    out = []
    for k in range(60):
        t = 173.15 + 300.0 * (1.0 - abs(1.0 - k / 30.0))
        s = min(t + 5.0, 473.15)  # the shaft 5 K warmer, inside the declared range
        out.append((t, t, s, t, s, 0.0, 150.0 + 140.0 * math.sin(0.3 * k), 0.17))
    for m in (10.0, 300.0, -300.0, 0.0, 1000.0):
        out.append((300.0, 300.0, 300.0, 300.0, 300.0, 0.0, m, 0.17))
    for housing, shaft in ((473.15, 173.15), (173.15, 473.15)):
        out.append((housing, housing, shaft, housing, shaft, 0.0, 150.0, 0.17))
    return out


_BEARING_INPUTS = (
    "temperature",
    "housing_temperature",
    "shaft_temperature",
    "outer_ring_temperature",
    "inner_ring_temperature",
    "speed",
    "axial_load",
    "radial_load",
)
_ACTUATOR_INPUTS = (*_BEARING_INPUTS[:5], "speed", "load_torque", "angle")


class Instance:
    """One FMU instance with name-based setting (choices by item number)."""

    def __init__(self, path: Path, md, unzip: str):
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.kind = {v.name: v.type for v in md.modelVariables}
        self.slave = FMU2Slave(
            guid=md.guid,
            unzipDirectory=unzip,
            modelIdentifier=md.coSimulation.modelIdentifier,
            instanceName="worst",
        )
        self.slave.instantiate()

    def init(self, reals: dict, integers: dict, clock) -> float:
        s = self.slave
        s.setupExperiment(startTime=0.0)
        s.enterInitializationMode()
        if reals:
            s.setReal([self.vr[n] for n in reals], list(reals.values()))
        if integers:
            s.setInteger([self.vr[n] for n in integers], list(integers.values()))
        t0 = clock()
        s.exitInitializationMode()
        return clock() - t0

    def close(self) -> None:
        self.slave.terminate()
        self.slave.freeInstance()


def _parameters(values: dict, mode: int) -> tuple[dict, dict]:
    """(reals, integers) of a BearingFriction parameter set over the defaults."""
    p = default_parameters() | values
    reals, integers = {}, {"temperature_mode": mode}
    for spec in PARAMETERS:
        v = p[spec.name]
        if spec.type == "Enumeration":
            integers[spec.name] = spec.item(v)
        elif spec.type == "Integer":
            integers[spec.name] = int(v)
        else:
            reals[spec.name] = float(v)
    return reals, integers


def _time_history(path, md, unzip, reals, integers, inputs, history, output, clock):
    """(init time, [time of each step]) [s] of one fresh instance through ``history``."""
    inst = Instance(path, md, unzip)
    first = dict(zip(inputs, history[0], strict=True))
    init = inst.init(reals | first, integers, clock)
    ins, out = [inst.vr[n] for n in inputs], [inst.vr[output]]
    slave, times, discarded, t = inst.slave, [], [], 0.0
    for values in history:
        t0 = clock()
        slave.setReal(ins, list(values))
        try:
            slave.doStep(t, 1e-3)
        except FMICallException:  # a discarded step (a point without a state): timed too
            discarded.append(len(times))
        slave.getReal(out)
        times.append(clock() - t0)
        t += 1e-3
        if discarded:  # FMI 2.0 after fmi2Discard: getters, terminate, reset; no more steps
            break
    inst.close()
    return init, times, discarded


def _worst(path, reals, integers, inputs, history, output, repeat, clock) -> dict:
    md = read_model_description(str(path))
    unzip = extract(str(path))
    runs = [
        _time_history(path, md, unzip, reals, integers, inputs, history, output, clock)
        for _ in range(repeat)
    ]
    init = min(r[0] for r in runs)
    steps = [min(ts) for ts in zip(*(r[1] for r in runs), strict=True)]
    k = max(range(len(steps)), key=steps.__getitem__)
    return {
        "discarded_steps": runs[0][2],
        "init_ms": init * 1e3,
        "worst_ms": steps[k] * 1e3,
        "median_ms": sorted(steps)[len(steps) // 2] * 1e3,
        "worst_step": k,
        "worst_inputs": dict(zip(inputs, history[k], strict=True)),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--clock", choices=("cpu", "wall"), default="cpu")
    parser.add_argument(
        "--save",
        metavar="FILE.json",
        help="also write the figures and the run's context to this JSON file (docs: Performance)",
    )
    args = parser.parse_args()
    clock = time.process_time if args.clock == "cpu" else time.perf_counter
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        paths = {p.stem: p for p in build_all(Path(tmp), ("BearingFriction", "ActuatorStiffness"))}
        history = _bearing_history()
        for label, (values, mode) in BEARING_CONFIGS.items():
            reals, integers = _parameters(values, mode)
            results[f"BearingFriction: {label}"] = _worst(
                paths["BearingFriction"], reals, integers, _BEARING_INPUTS, history,
                "friction_torque", args.repeat, clock,
            )  # fmt: skip
        history = _actuator_history()
        for label, mode in (("uniform", 1), ("parts mode", 3)):
            results[f"ActuatorStiffness: {label}"] = _worst(
                paths["ActuatorStiffness"], {}, {"temperature_mode": mode}, _ACTUATOR_INPUTS,
                history, "stiffness", args.repeat, clock,
            )  # fmt: skip
    slowest = max(results, key=lambda k: results[k]["worst_ms"])
    if args.save:
        save(args.save, {"limit_ms": LIMIT * 1e3, "slowest": slowest, **results})
    if args.json:
        print(json.dumps({"limit_ms": LIMIT * 1e3, "slowest": slowest, **results}, indent=2))
        return
    print(f"{'configuration':52s} {'init':>8s} {'median':>8s} {'worst':>8s}  worst step's inputs")
    for label, r in results.items():
        inputs = ", ".join(f"{k}={v:g}" for k, v in r["worst_inputs"].items())
        discarded = f" (steps {r['discarded_steps']} discarded)" if r["discarded_steps"] else ""
        print(
            f"{label:52s} {r['init_ms']:6.2f}ms {r['median_ms']:6.3f}ms {r['worst_ms']:6.2f}ms"
            f"  #{r['worst_step']}: {inputs}{discarded}"
        )
    w = results[slowest]["worst_ms"]
    print(f"slowest step: {w:.2f} ms ({slowest}); aim {LIMIT * 1e3:g} ms: "
          + ("met" if w <= LIMIT * 1e3 else "NOT met"))  # fmt: skip


if __name__ == "__main__":
    main()

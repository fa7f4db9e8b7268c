"""Per-step cost of each servofmu FMU next to an empty pythonfmu FMU, in one run (on demand:
``make bench``; not part of the tests).

Each loop is what a co-simulation master does per communication step through fmpy's
FMU2Slave: set the FMU's real inputs, fmi2DoStep, get one output. The empty FMU has four real
inputs, one output and a do_step that returns True. Reported: µs per step (median of
``--repeat`` runs of ``--steps`` steps; the loops take turns, and each run continues its
loop's input history where the last one stopped) and the ratio to the empty FMU.

``--clock cpu`` (the default) times the CPU time of this process (time.process_time): the
FMUs run in-process, so that is their cost, and other work on a shared machine does not
enter it; ``--clock wall`` times wall-clock time (time.perf_counter). On an idle machine the
two agree.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import tempfile
import time
from pathlib import Path

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from results import save  # benchmarks/ is the script's folder
from trajectories import BEARING_LOOPS  # benchmarks/ is the script's folder

from servofmu.build.fmu import FMUS, build_all

EMPTY = """
from pythonfmu import Fmi2Causality, Fmi2Slave, Real


class Empty(Fmi2Slave):
    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.a = self.b = self.c = self.d = 0.0
        self.y = 0.0
        for name in "abcd":
            self.register_variable(Real(name, causality=Fmi2Causality.input))
        self.register_variable(Real("y", causality=Fmi2Causality.output))

    def do_step(self, current_time, step_size):
        return True
"""


# BearingFriction's inputs changed every step (value at step k) and the output read back
_BEARING_INPUTS = ("temperature", "speed", "axial_load", "radial_load")
#: The other friction models (parameter friction_model: item) and their loops (--models).
OTHER_MODELS = {"skf2004": 2, "ehl_per_contact": 3}

# inputs changed every step (value at step k), the output read back, parameters set
LOOPS = {
    "Empty": (("a", "b", "c", "d"), lambda k: (1.0 + 1e-3 * k, 2.0, 3.0, 4.0), "y", {}),
    **{
        f"BearingFriction ({what})": (_BEARING_INPUTS, values, "friction_torque", {})
        for what, values in BEARING_LOOPS.items()
    },
    "ActuatorStiffness": (
        ("temperature", "speed", "load_torque", "angle"),
        lambda k: (293.15, 0.0, 150.0 + 50.0 * math.sin(1e-3 * k), 0.17),
        "stiffness",
        {},
    ),
    "DCMotor": (("voltage", "load_torque"), lambda k: (math.sin(1e-3 * k), 1e-3), "speed", {}),
    "ServoController": (
        ("reference", "measurement"),
        lambda k: (math.sin(1e-3 * k), 0.9 * math.sin(1e-3 * k)),
        "command",
        {},
    ),
    # a chamber ramp of 1 K/s seen at 1 ms steps: radiation re-linearised every 0.1 K (default)
    "ThermalNetwork (chamber ramp, power loss changes)": (
        ("ambient_temperature", "sink_temperature", "power_loss"),
        lambda k: (233.15 + 1e-3 * k, 233.15 + 1e-3 * k, 0.1 + 0.05 * math.sin(1e-3 * k)),
        "shaft_temperature",
        {},
    ),
}


def _model_loops() -> dict:
    """BearingFriction's loops under the other friction models (``--models``)."""
    return {
        f"BearingFriction {model} ({what})": (
            _BEARING_INPUTS,
            values,
            "friction_torque",
            {"friction_model": item},
        )
        for model, item in OTHER_MODELS.items()
        for what, values in BEARING_LOOPS.items()
    }


def _slave(path: Path, integers: dict):
    md = read_model_description(str(path))
    slave = FMU2Slave(
        guid=md.guid,
        unzipDirectory=extract(str(path)),
        modelIdentifier=md.coSimulation.modelIdentifier,
        instanceName="bench",
    )
    vr = {v.name: v.valueReference for v in md.modelVariables}
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    if integers:  # choices: FMI Integers
        slave.setInteger([vr[n] for n in integers], list(integers.values()))
    slave.exitInitializationMode()
    return slave, vr


class Loop:
    """One FMU instance driven through one input history: :meth:`run` times the next
    ``steps`` steps of it (the history continues from one call to the next, so that no call
    starts with a jump of its inputs)."""

    def __init__(self, path: Path, inputs, values, output, integers, total: int):
        self.slave, vr = _slave(path, integers)
        self.ins, self.out = [vr[n] for n in inputs], [vr[output]]
        self.series = [values(k) for k in range(total)]
        self.k, self.t = 0, 0.0

    def run(self, steps: int, clock) -> float:
        slave, ins, out, series = self.slave, self.ins, self.out, self.series
        first, t = self.k, self.t
        t0 = clock()
        for k in range(first, first + steps):
            slave.setReal(ins, series[k])
            slave.doStep(t, 1e-3)
            slave.getReal(out)
            t += 1e-3
        elapsed = clock() - t0
        self.k, self.t = first + steps, t
        return elapsed / steps

    def close(self) -> None:
        self.slave.terminate()
        self.slave.freeInstance()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=20000)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--json", action="store_true")
    parser.add_argument(
        "--save",
        metavar="FILE.json",
        help="also write the figures and the run's context to this JSON file (docs: Performance)",
    )
    parser.add_argument("--clock", choices=("cpu", "wall"), default="cpu")
    parser.add_argument(
        "--models",
        action="store_true",
        help="also BearingFriction's loops under friction_model skf2004 and ehl_per_contact",
    )
    args = parser.parse_args()
    clock = time.process_time if args.clock == "cpu" else time.perf_counter
    from pythonfmu.builder import FmuBuilder

    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        paths = {p.stem: p for p in build_all(tmp / "fmus", FMUS)}
        (tmp / "Empty.py").write_text(EMPTY)
        paths["Empty"] = Path(FmuBuilder.build_FMU(tmp / "Empty.py", dest=tmp / "fmus"))
        specs = LOOPS | (_model_loops() if args.models else {})
        loops = {
            label: Loop(paths[label.split(" ")[0]], *spec, args.steps * args.repeat)
            for label, spec in specs.items()
        }
        # the loops take turns, so that every one sees the same spells of other load
        runs = {label: [] for label in loops}
        for _ in range(args.repeat):
            for label, loop in loops.items():
                runs[label].append(loop.run(args.steps, clock))
        for loop in loops.values():
            loop.close()
        figures = {label: statistics.median(r) for label, r in runs.items()}
    empty = figures["Empty"]
    table = {k: {"us": v * 1e6, "ratio": v / empty} for k, v in figures.items()}
    if args.save:
        save(args.save, table)
    if args.json:
        print(json.dumps(table, indent=2))
        return
    for label, secs in figures.items():
        print(f"{label:60s} {secs * 1e6:8.2f} µs/step   {secs / empty:5.2f} × empty")


if __name__ == "__main__":
    main()

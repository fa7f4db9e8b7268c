"""Per-step cost of each servofmu FMU next to an empty pythonfmu FMU, in one run, for both
implementations of the per-step kernels (on demand: ``make bench``; not part of the tests).

Each loop is what a co-simulation master does per communication step through fmpy's
FMU2Slave: set the FMU's real inputs, fmi2DoStep, get one output. The empty FMU has four real
inputs, one output and a do_step that returns True. Reported: µs per step (median of
``--repeat`` runs of ``--steps`` steps; the loops take turns, and each run continues its
loop's input history where the last one stopped) and the ratio to the empty FMU, with the
aims of the speed table (:data:`AIMS`).

The FMUs are built once; each implementation runs in its own process (a process imports
servofmu once): the compiled modules (``servofmu.physics.compiled``, when built) and the
Python ones (``SERVOFMU_PURE_PYTHON=1``), each with its own empty FMU, so that every ratio is
measured within one process. ``--python-crossings`` adds a third: the compiled kernels with
every FMI call entering Python (``SERVOFMU_SHARED_VALUES=0``), as without the values the FMUs
share with servofmu's export library.

``--clock cpu`` (the default) times the CPU time of the process (time.process_time): the
FMUs run in-process, so that is their cost, and other work on a shared machine does not
enter it; ``--clock wall`` times wall-clock time (time.perf_counter). On an idle machine the
two agree.

The workers run with one BLAS thread (:data:`ONE_THREAD`). The FMUs' matrices are 4×4 to
8×8 (ThermalNetwork's matrix exponential, the solvers' exact starts); OpenBLAS's worker
threads, woken by such a call, spin for a while after it, and the process's CPU time counts
their spinning: the empty FMU's own step then read 16–17 µs instead of 8.3 µs, at random,
and every ratio with it.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from results import save  # benchmarks/ is the script's folder
from trajectories import BEARING_LOOPS  # benchmarks/ is the script's folder

from servofmu.build.fmu import FMUS, build_all
from servofmu.fmus.shared_values import ENVIRONMENT as SHARED_VALUES
from servofmu.parameters.bearing import PARAMETERS
from servofmu.physics.compiled import PURE_PYTHON

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
_SPEC = {p.name: p for p in PARAMETERS}


def _choice(name: str, key: str) -> int:
    """The enumeration value of BearingFriction's choice ``name`` = ``key``."""
    return _SPEC[name].item(key)


#: The other friction models (parameter friction_model: item) and their loops (--models).
OTHER_MODELS = {m: _choice("friction_model", m) for m in ("skf2004", "ehl_per_contact")}
#: A tandem pair under a constant 40 N (parameters set before initialization).
TANDEM = {
    "arrangement": _choice("arrangement", "tandem"),
    "preload_method": _choice("preload_method", "force"),
    "assembly_preload": 40.0,
}
#: The speed table's aims: loop label → largest ratio to the empty FMU.
AIMS = {
    "BearingFriction (speed changes)": 1.0,
    "BearingFriction (ramp -60..+80 degC, 20 N axial)": 1.3,
    "BearingFriction (ramp, axial 10-30 N, radial 0-20 N)": 1.6,
    "BearingFriction tandem (ramp -60..+80 degC, 20 N axial)": 1.6,
    "ThermalNetwork (chamber ramp, power loss changes)": 1.0,
    "ActuatorStiffness": 1.3,
}

# inputs changed every step (value at step k), the output read back, parameters set
LOOPS = {
    "Empty": (("a", "b", "c", "d"), lambda k: (1.0 + 1e-3 * k, 2.0, 3.0, 4.0), "y", {}),
    **{
        f"BearingFriction ({what})": (_BEARING_INPUTS, values, "friction_torque", {})
        for what, values in BEARING_LOOPS.items()
    },
    "BearingFriction tandem (ramp -60..+80 degC, 20 N axial)": (
        _BEARING_INPUTS,
        BEARING_LOOPS["ramp -60..+80 degC, 20 N axial"],
        "friction_torque",
        TANDEM,
    ),
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


#: Pre-rolling on (Dahl) with a given rest stiffness (--models); one derived from the contacts
#: costs an exact equilibrium at each new temperature or load, which a ramp makes every step.
PREROLLING = {"prerolling_model": 1, "prerolling_stiffness": 2.0}
#: Pre-rolling's aim: a loop with it on costs at most this ratio of the same loop with it off.
PREROLLING_AIM = 1.1
PREROLLING_LABEL = "BearingFriction prerolling ("


def prerolling_overheads(loops: dict) -> dict:
    """{trajectory: µs per step with pre-rolling on / with it off} of one process's loops."""
    return {
        label[len(PREROLLING_LABEL) : -1]: us
        / loops["BearingFriction (" + label[len(PREROLLING_LABEL) :]]
        for label, us in loops.items()
        if label.startswith(PREROLLING_LABEL)
    }


def _model_loops() -> dict:
    """BearingFriction's loops under the other friction models and with pre-rolling on
    (``--models``)."""
    return {
        **{
            f"BearingFriction {model} ({what})": (
                _BEARING_INPUTS,
                values,
                "friction_torque",
                {"friction_model": item},
            )
            for model, item in OTHER_MODELS.items()
            for what, values in BEARING_LOOPS.items()
        },
        **{
            f"{PREROLLING_LABEL}{what})": (
                _BEARING_INPUTS,
                values,
                "friction_torque",
                PREROLLING,
            )
            for what, values in BEARING_LOOPS.items()
        },
    }


def _slave(path: Path, parameters: dict):
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
    for name, value in parameters.items():  # choices are FMI Integers
        if isinstance(value, int):
            slave.setInteger([vr[name]], [value])
        else:
            slave.setReal([vr[name]], [value])
    slave.exitInitializationMode()
    return slave, vr


class Loop:
    """One FMU instance driven through one input history: :meth:`run` times the next
    ``steps`` steps of it (the history continues from one call to the next, so that no call
    starts with a jump of its inputs)."""

    def __init__(self, path: Path, inputs, values, output, parameters, total: int):
        self.slave, vr = _slave(path, parameters)
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


def measure(paths: dict, steps: int, repeat: int, clock, models: bool) -> dict:
    """{loop label: seconds per step} of every loop, in this process (the loops take turns)."""
    specs = LOOPS | (_model_loops() if models else {})
    loops = {
        label: Loop(paths[label.split(" ")[0]], *spec, steps * repeat)
        for label, spec in specs.items()
    }
    # the loops take turns, so that every one sees the same spells of other load
    runs = {label: [] for label in loops}
    for _ in range(repeat):
        for label, loop in loops.items():
            runs[label].append(loop.run(steps, clock))
    for loop in loops.values():
        loop.close()
    return {label: statistics.median(r) for label, r in runs.items()}


def _worker(args) -> None:
    """Measure the loops in this process and print {label: {"us", "ratio"}} as JSON."""
    from servofmu.physics import compiled as continuation

    clock = time.process_time if args.clock == "cpu" else time.perf_counter
    paths = {p.stem: p for p in Path(args.fmus).glob("*.fmu")}
    figures = measure(paths, args.steps, args.repeat, clock, args.models)
    empty = figures["Empty"]
    table = {k: {"us": v * 1e6, "ratio": v / empty} for k, v in figures.items()}
    how = continuation.describe()
    if os.environ.get(SHARED_VALUES) == "0":
        how += "; every FMI call entering Python"
    print(json.dumps({"implementation": how, "loops": table}))


def _run_worker(fmus: Path, implementation: str, args) -> dict:
    env = dict(os.environ) | ONE_THREAD
    env[PURE_PYTHON] = "1" if implementation == "python" else ""
    env[SHARED_VALUES] = "0" if implementation == CROSSINGS else "1"
    cmd = [sys.executable, __file__, "--worker", str(fmus), "--steps", str(args.steps),
           "--repeat", str(args.repeat), "--clock", args.clock]  # fmt: skip
    if args.models:
        cmd.append("--models")
    out = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"the {implementation} worker failed:\n{out.stderr}")
    return json.loads(out.stdout.strip().splitlines()[-1])


#: The environment of every worker: one thread for the BLAS libraries numpy and scipy may
#: load (module docstring).
ONE_THREAD = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}
#: The implementations of the per-step kernels measured, each in its own process.
IMPLEMENTATIONS = ("compiled", "python")
#: With --python-crossings: the compiled kernels, every FMI call entering Python.
CROSSINGS = "compiled, every call in Python"


def figures_of(results: dict) -> dict:
    """The saved figures: which kernels each process ran, and one row per loop with µs per
    step and the ratio to the empty FMU of each implementation, and the aim."""
    rows = []
    for label in results["python"]["loops"]:
        row = {"loop": label}
        for impl in results:
            fig = results[impl]["loops"][label]
            row[f"{impl} µs"] = fig["us"]
            row[f"{impl} ×"] = fig["ratio"]
        row["aim ×"] = AIMS.get(label, "")
        rows.append(row)
    kernels = {impl: results[impl]["implementation"] for impl in results}
    overheads = {
        impl: prerolling_overheads({k: v["us"] for k, v in results[impl]["loops"].items()})
        for impl in results
    }
    prerolling = {"aim ×": PREROLLING_AIM, "on / off ×": overheads} if overheads["python"] else {}
    return {"kernels": kernels, "loops": rows, "prerolling": prerolling}


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
    parser.add_argument(
        "--python-crossings",
        action="store_true",
        help="also the compiled kernels with every FMI call entering Python (no shared values)",
    )
    parser.add_argument("--worker", metavar="FMUS", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        args.fmus = args.worker
        _worker(args)
        return
    from pythonfmu.builder import FmuBuilder

    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        fmus = tmp / "fmus"
        build_all(fmus, FMUS, systems=False)
        (tmp / "Empty.py").write_text(EMPTY)
        FmuBuilder.build_FMU(tmp / "Empty.py", dest=fmus)
        measured = (*IMPLEMENTATIONS, *([CROSSINGS] if args.python_crossings else []))
        results = {impl: _run_worker(fmus, impl, args) for impl in measured}
    table = figures_of(results)
    if args.save:
        save(args.save, table)
    if args.json:
        print(json.dumps(table, indent=2, ensure_ascii=False))
        return
    for impl, what in table["kernels"].items():
        print(f"{impl}: kernels {what}")
    names = list(table["kernels"])
    print(f"{'loop':62s} " + " ".join(f"{n[:18]:>18s}" for n in names) + f" {'aim':>6s}")
    for row in table["loops"]:
        cells = [f"{row[f'{i} µs']:7.2f} µs {row[f'{i} ×']:5.2f}×" for i in names]
        aim = "" if row["aim ×"] == "" else f"≤ {row['aim ×']}"
        print(f"{row['loop']:62s} " + " ".join(f"{c:>18s}" for c in cells) + f" {aim:>6s}")
    if table["prerolling"]:
        print(f"\npre-rolling on / off, same loop (aim ≤ {PREROLLING_AIM}):")
        for what in table["prerolling"]["on / off ×"]["python"]:
            cells = [f"{table['prerolling']['on / off ×'][i][what]:5.3f}×" for i in names]
            print(f"  {what:60s} " + " ".join(f"{c:>18s}" for c in cells))


if __name__ == "__main__":
    main()

"""Does a Python (fmpy) host exit cleanly after using an FMU?

    python exit_check.py FMU_DIR [--runs N] [--fmu NAME]...

runs, for each FMU in FMU_DIR, N child processes (``exit_check.py --child FMU``) that each
instantiate the FMU with fmpy's FMU2Slave, step it, save and restore its state, have a NaN
input refused, restore the state and step on with a good input, print their outputs, free the
instance and leave
by a normal interpreter exit (finalisation, atexit handlers, library destructors). Prints one
JSON line per FMU: ``{"name": ..., "runs": N, "exit_0": k, "codes": {...}}``, and exits 1
unless every run exited 0 with its "done" line printed.

pythonfmu 0.7's library destructor released the interpreter holder twice at exit (see
``servofmu.fmus.interpreter_exit``), which aborted a few fmpy processes in a hundred
(``corrupted double-linked list``, exit status 134) after all their work was done.
Only fmpy is imported in the child: it is a plain user's process.
"""

from __future__ import annotations

import argparse
import collections
import json
import math
import subprocess
import sys
from pathlib import Path

NAMES = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController", "ThermalNetwork")
INPUTS = {  # FMU: (a good input set, the input that gets a NaN)
    "BearingFriction": ({"temperature": 253.15, "speed": 0.2, "axial_load": 5.0}, "speed"),
    "ActuatorStiffness": ({"angle": 0.17, "load_torque": 150.0, "temperature": 263.15}, "angle"),
    "DCMotor": ({"voltage": 6.0, "load_torque": 2e-3}, "voltage"),
    "ServoController": ({"reference": 1.0, "measurement": 0.25}, "measurement"),
    "ThermalNetwork": ({"ambient_temperature": 253.15, "power_loss": 0.05}, "power_loss"),
}


def child(path: Path) -> None:
    """One FMU's life in an fmpy process; the caller checks the exit status."""
    from fmpy import extract, read_model_description
    from fmpy.fmi1 import FMICallException
    from fmpy.fmi2 import FMU2Slave

    md = read_model_description(str(path))
    name = md.coSimulation.modelIdentifier
    vr = {v.name: v.valueReference for v in md.modelVariables}
    good, bad_input = INPUTS[name]
    slave = FMU2Slave(
        guid=md.guid,
        unzipDirectory=extract(str(path)),
        modelIdentifier=name,
        instanceName="exit_check",
    )
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.setReal([vr[k] for k in good], list(good.values()))
    slave.exitInitializationMode()
    outputs = [
        v.valueReference for v in md.modelVariables if v.causality == "output" and v.type == "Real"
    ]
    t, h = 0.0, 1e-3
    for _ in range(5):
        slave.doStep(t, h)
        t += h
    state = slave.getFMUstate()
    blob = slave.serializeFMUstate(state)
    before = slave.getReal(outputs)
    slave.doStep(t, h)
    restored = slave.deSerializeFMUstate(blob)
    slave.setFMUstate(restored)
    slave.freeFMUstate(state)
    assert slave.getReal(outputs) == before, "state not restored"
    slave.setReal([vr[bad_input]], [math.nan])
    try:
        slave.doStep(t, h)
        raise AssertionError(f"a NaN {bad_input} was not refused")
    except FMICallException as exc:  # fmi2Error (servofmu's export), fmi2Discard (pythonfmu's)
        assert exc.status in (2, 3), f"a NaN {bad_input} gave status {exc.status}"
    slave.setFMUstate(restored)  # FMI 2.0: on from a state saved before the refused step
    slave.freeFMUstate(restored)
    slave.setReal([vr[bad_input]], [good[bad_input]])
    slave.doStep(t, h)
    values = slave.getReal(outputs)
    assert all(math.isfinite(v) or v == math.inf for v in values), values
    slave.terminate()
    slave.freeInstance()
    print(f"done {name} {values[0]!r}", flush=True)


def run(fmu_dir: Path, runs: int, names) -> bool:
    ok = True
    for name in names:
        codes = collections.Counter()
        for _ in range(runs):
            proc = subprocess.run(
                [sys.executable, __file__, "--child", str(fmu_dir / f"{name}.fmu")],
                capture_output=True,
                text=True,
                timeout=300,
            )
            done = f"done {name}" in proc.stdout
            code = proc.returncode if done or proc.returncode else "no done line"
            codes[code] += 1
            if code != 0:
                sys.stderr.write(f"{name}: exit {proc.returncode}\n{proc.stderr[-2000:]}\n")
        exit_0 = codes.get(0, 0)
        ok &= exit_0 == runs
        summary = {"name": name, "runs": runs, "exit_0": exit_0, "codes": dict(codes)}
        print(json.dumps(summary), flush=True)
    return ok


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("fmu_dir", nargs="?", type=Path, help="folder with the four built FMUs")
    p.add_argument("--runs", type=int, default=30, help="child processes per FMU (30)")
    p.add_argument("--fmu", action="append", choices=NAMES, help="only these FMUs")
    p.add_argument("--child", type=Path, help=argparse.SUPPRESS)
    args = p.parse_args(argv)
    if args.child:
        child(args.child)
        return 0
    if args.fmu_dir is None:
        p.error("FMU_DIR is required")
    return 0 if run(args.fmu_dir, args.runs, args.fmu or NAMES) else 1


if __name__ == "__main__":
    sys.exit(main())

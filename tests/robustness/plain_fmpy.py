"""What a new user does with plain fmpy, in a fresh interpreter that has only fmpy, numpy and
scipy (``tests/fmus/test_plain_fmpy.py`` runs it in such a virtual environment):

    python plain_fmpy.py sequence FMU_A FMU_B      # simulate_fmu(A), then simulate_fmu(B)
    python plain_fmpy.py side_by_side FMU_A FMU_B  # both instantiated, A's folder deleted
    python plain_fmpy.py both FMU_A FMU_B          # sequence, then side by side
    python plain_fmpy.py visible CASE FMU [...]    # a mistake, with fmpy's defaults
    python plain_fmpy.py log FMU                    # simulate_fmu, printing the FMU's messages

``sequence`` and ``side_by_side`` print one JSON line per FMU run (rows, outputs finite) and
"done"; ``visible`` runs ``simulate_fmu`` with its defaults (logging off, no logger) on a
mistake a user makes and prints what fmpy raised, after fmpy printed the FMU's messages.
"""

from __future__ import annotations

import json
import math
import shutil
import sys
from pathlib import Path

import numpy as np
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi2 import FMU2Slave


def _finite(result) -> bool:
    return all(
        np.all(np.isfinite(result[name]))
        for name in result.dtype.names
        if result[name].dtype.kind == "f"
    )


def sequence(a: str, b: str) -> None:
    for path in (a, b):
        result = simulate_fmu(path, stop_time=0.01, output_interval=1e-3)
        print(json.dumps({"fmu": Path(path).stem, "rows": len(result), "finite": _finite(result)}))


def side_by_side(a: str, b: str) -> None:
    units = []
    for k, path in enumerate((a, b)):
        md = read_model_description(path)
        folder = extract(path)
        slave = FMU2Slave(
            guid=md.guid,
            unzipDirectory=folder,
            modelIdentifier=md.coSimulation.modelIdentifier,
            instanceName=f"unit{k}",
        )
        slave.instantiate()
        slave.setupExperiment(startTime=0.0)
        slave.enterInitializationMode()
        slave.exitInitializationMode()
        outputs = [
            v.valueReference
            for v in md.modelVariables
            if v.causality == "output" and v.type == "Real"
        ]
        units.append((Path(path).stem, slave, folder, outputs))
    t, h = 0.0, 1e-3
    for step in range(10):
        if step == 5:  # as simulate_fmu does when A's run ends: A's folder is gone
            shutil.rmtree(units[0][2], ignore_errors=True)
        for _, slave, _, _ in units:
            slave.doStep(t, h)
        t += h
    for name, slave, folder, outputs in units:
        values = slave.getReal(outputs)
        print(json.dumps({"fmu": name, "rows": 10, "finite": all(map(math.isfinite, values))}))
        slave.terminate()
        slave.freeInstance()
        shutil.rmtree(folder, ignore_errors=True)


def visible(case: str, path: str) -> None:
    """One mistake with simulate_fmu's defaults; fmpy prints the FMU's messages itself."""
    if case == "celsius":  # a temperature of 20 (°C meant) where kelvin are asked
        columns = [("time", float), ("temperature", float)]
        run = dict(input=np.array([(0.0, 20.0), (1.0, 20.0)], dtype=columns))
    elif case == "geometry":  # a ball too large for the bearing's rings
        run = dict(start_values={"ball_diameter": 5e-3})
    elif case == "no_scipy":  # a host without scipy
        sys.modules["scipy"] = None
        run = {}
    else:  # another build: the FMUs given first come from one, the last from another
        raise SystemExit(f"unknown case {case!r}")
    try:
        simulate_fmu(path, stop_time=0.01, output_interval=1e-3, **run)
        print("raised: nothing")
    except Exception as exc:  # what the user sees after fmpy's printed log messages
        print(f"raised: {type(exc).__name__}: {exc}")


def log(path: str) -> None:
    """simulate_fmu with logging on and a logger that prints every message of the FMU."""

    def printed(env, instance, status, category, message):
        print(f"log: {message.decode(errors='replace')}", flush=True)

    result = simulate_fmu(
        path, stop_time=0.01, output_interval=1e-3, debug_logging=True, logger=printed
    )
    print(json.dumps({"fmu": Path(path).stem, "rows": len(result), "finite": _finite(result)}))


def two_builds(first: str, other: str) -> None:
    """An FMU of another build after one of this build, in one process."""
    simulate_fmu(first, stop_time=0.01, output_interval=1e-3)
    try:
        simulate_fmu(other, stop_time=0.01, output_interval=1e-3)
        print("raised: nothing")
    except Exception as exc:
        print(f"raised: {type(exc).__name__}: {exc}")


def main(argv: list[str]) -> int:
    mode, *args = argv
    if mode == "sequence":
        sequence(*args)
    elif mode == "side_by_side":
        side_by_side(*args)
    elif mode == "both":
        sequence(*args)
        side_by_side(*args)
    elif mode == "visible":
        visible(*args)
    elif mode == "log":
        log(*args)
    elif mode == "two_builds":
        two_builds(*args)
    else:
        raise SystemExit(f"unknown mode {mode!r}")
    print("done", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

"""Soak: each FMU and the seeker-gimbal system for many steps, watching the memory (RSS) and
the outputs (``python tests/robustness/soak.py FMU_DIR [--steps N]``; the tests run it short,
``--long`` a million steps).

Per FMU: instantiate through fmpy, initialise, then set varying in-range inputs, fmi2DoStep
and read every Real output, ``steps`` times; every output must stay finite (or +inf where the
description documents it). Per system: the harness runs seeker_gimbal for ``steps`` macro
steps with a stepped chamber temperature and the speed loop holding 10 °/s, keeping a row
every 1000 steps. Memory: the RSS
after the first tenth of the run (allocators and caches warmed up) against the RSS at the
end; the growth must stay within ``--max-growth`` MB.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import psutil
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

NAMES = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController", "ThermalNetwork")


# inputs as functions of the step index k: in range, varying every step; the temperature
# moves every 1000 steps (a chamber's steps, each solved by the bearing's continuation)
def _chamber(k: int, mean: float, amplitude: float) -> float:
    return mean + amplitude * math.sin(0.1 * (k // 1000))


INPUTS = {
    "BearingFriction": {
        "temperature": lambda k: _chamber(k, 263.15, 20.0),
        "speed": lambda k: 0.3 * math.sin(1e-3 * k),
        "axial_load": lambda k: 10.0 * math.sin(3e-4 * k),
    },
    "ActuatorStiffness": {
        "load_torque": lambda k: 150.0 * math.sin(1e-3 * k),
        "angle": lambda k: 0.3 * math.sin(2e-4 * k),
        "temperature": lambda k: _chamber(k, 293.15, 30.0),
    },
    "DCMotor": {
        "voltage": lambda k: 2.0 * math.sin(1e-3 * k),
        "load_torque": lambda k: 1e-3 * math.sin(7e-4 * k),
        "friction_running_torque": lambda k: 2e-3,
        "friction_breakaway_torque": lambda k: 2.5e-3,
    },
    "ServoController": {
        "reference": lambda k: math.sin(1e-3 * k),
        "measurement": lambda k: 0.9 * math.sin(1e-3 * k - 0.1),
    },
    "ThermalNetwork": {
        "ambient_temperature": lambda k: _chamber(k, 263.15, 40.0),
        "sink_temperature": lambda k: _chamber(k, 253.15, 30.0),
        "power_loss": lambda k: 0.2 + 0.2 * math.sin(1e-3 * k),
    },
}


def rss_mb() -> float:
    return psutil.Process().memory_info().rss / 2**20


def soak_fmu(path: Path, steps: int, h: float = 1e-3) -> dict:
    md = read_model_description(str(path))
    name = md.coSimulation.modelIdentifier
    vr = {v.name: v.valueReference for v in md.modelVariables}
    outputs = [v for v in md.modelVariables if v.causality == "output" and v.type == "Real"]
    inf_ok = {v.valueReference for v in outputs if "inf when" in (v.description or "")}
    out_vr = [v.valueReference for v in outputs]
    slave = FMU2Slave(
        guid=md.guid,
        unzipDirectory=extract(str(path)),
        modelIdentifier=name,
        instanceName="soak",
    )
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.exitInitializationMode()
    inputs = [(vr[n], f) for n, f in INPUTS[name].items()]
    warm = max(1, steps // 10)
    before = None
    try:
        for k in range(steps):
            if k == warm:
                before = rss_mb()
            slave.setReal([r for r, _ in inputs], [f(k) for _, f in inputs])
            slave.doStep(k * h, h)
            values = slave.getReal(out_vr)
            for r, x in zip(out_vr, values, strict=True):
                if not math.isfinite(x) and not (x == math.inf and r in inf_ok):
                    raise AssertionError(f"{name}: output {r} = {x} at step {k}")
    finally:
        slave.terminate()
        slave.freeInstance()
    return {"name": name, "steps": steps, "rss_mb_after_warmup": before, "rss_mb_end": rss_mb()}


def soak_system(ssp: Path, steps: int) -> dict:
    from servofmu.harness import load_system, run

    system = load_system(ssp)
    h = system.step_size

    def chamber(t: float) -> float:  # a new chamber temperature every 1000 steps
        return _chamber(round(t / h), 283.15, 50.0)

    record = ["motor.speed", "motor.current", "bearing.running_torque"]
    try:
        warm = max(1, steps // 10)
        run(
            system,
            signals={"bearing.temperature": chamber},
            stop=warm * h,
            record=record,
            progress=False,
            output_interval=1000 * h,
        )
        before = rss_mb()
        res = run(
            system,
            signals={"bearing.temperature": chamber},
            stop=steps * h,
            record=record,
            progress=False,
            output_interval=1000 * h,
        )
    finally:
        system.close()
    for name in record:
        if not all(math.isfinite(x) for x in res[name]):
            raise AssertionError(f"seeker_gimbal: {name} not finite")
    return {
        "name": "seeker_gimbal system",
        "steps": steps,
        "rss_mb_after_warmup": before,
        "rss_mb_end": rss_mb(),
    }


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fmu_dir")
    parser.add_argument("--steps", type=int, default=1_000_000)
    parser.add_argument("--max-growth", type=float, default=20.0, help="MB")
    parser.add_argument("--only", choices=(*NAMES, "system"), action="append")
    args = parser.parse_args(argv)
    fmu_dir = Path(args.fmu_dir)
    failed = False
    for name in args.only or (*NAMES, "system"):
        if name == "system":
            r = soak_system(fmu_dir / "seeker_gimbal.ssp", args.steps)
        else:
            r = soak_fmu(fmu_dir / f"{name}.fmu", args.steps)
        r["growth_mb"] = r["rss_mb_end"] - r["rss_mb_after_warmup"]
        r["ok"] = r["growth_mb"] <= args.max_growth
        failed |= not r["ok"]
        print(json.dumps(r))
        sys.stdout.flush()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

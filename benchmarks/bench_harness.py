"""Real-time factor of the seeker-gimbal system through the servofmu harness next to libcosim
on the same .ssp, measured in one run (on demand: ``make bench``; not part of the tests).

The system is ``seeker_gimbal`` (ServoController, DCMotor, BearingFriction; 1 ms step, the
speed loop at 10 °/s), at its fixed temperature and, through the harness, under a
temperature ramp: a triangle −60 → +80 → −60 °C of period 2 s, 0.14 K per 1 ms step (the
ramp of benchmarks/bench_fmus.py), so that every step solves a new thermal state. Each run
covers ``--short`` and ``--long`` seconds of simulated time; the stepping rate is
(long − short) / (wall_long − wall_short), which takes loading, unpacking and instantiation
out; the wall time of the long run with its set-up is reported too. Median of ``--repeat``
runs.
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
from pathlib import Path

from results import save  # benchmarks/ is the script's folder

from servofmu.harness import load_system, run
from servofmu.harness.libcosim import run_libcosim
from servofmu.harness.scenarios.common import system_path
from servofmu.harness.signals import Cycle

SYSTEM = "seeker_gimbal"
RECORD = ["motor.speed", "motor.current", "bearing.running_torque"]
#: −60 → +80 → −60 °C in 2 s: 0.14 K per 1 ms step [K]
RAMP = {"bearing.temperature": Cycle(213.15, 353.15, 2.0, "triangle")}


def harness_wall(ssp: Path, stop: float, algorithm: str, signals=None) -> float:
    t0 = time.perf_counter()
    system = load_system(ssp)
    try:
        run(
            system,
            stop=stop,
            record=RECORD,
            algorithm=algorithm,
            progress=False,
            signals=signals,
        )
    finally:
        system.close()
    return time.perf_counter() - t0


def libcosim_wall(ssp: Path, stop: float) -> float:
    t0 = time.perf_counter()
    run_libcosim(ssp, RECORD, stop)
    return time.perf_counter() - t0


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--short", type=float, default=1.0, help="short run [s simulated]")
    parser.add_argument("--long", type=float, default=10.0, help="long run [s simulated]")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--json", action="store_true")
    parser.add_argument(
        "--save",
        metavar="FILE.json",
        help="also write the figures and the run's context to this JSON file (docs: Performance)",
    )
    args = parser.parse_args(argv)
    ssp = system_path(SYSTEM)
    engines = {
        "harness, Gauss-Seidel": lambda stop: harness_wall(ssp, stop, "gauss-seidel"),
        "harness, Jacobi": lambda stop: harness_wall(ssp, stop, "jacobi"),
        "harness, Gauss-Seidel, ramp": lambda stop: harness_wall(ssp, stop, "gauss-seidel", RAMP),
        "libcosim (fixed step, Jacobi)": lambda stop: libcosim_wall(ssp, stop),
    }
    results = {}
    for name, wall in engines.items():
        wall(args.short)  # warm-up: imports, first unpacking
        shorts = [wall(args.short) for _ in range(args.repeat)]
        longs = [wall(args.long) for _ in range(args.repeat)]
        w_short, w_long = statistics.median(shorts), statistics.median(longs)
        stepping = (args.long - args.short) / (w_long - w_short)
        results[name] = {
            "stepping real-time factor": stepping,
            "us per macro step": 1e6 * 1e-3 / stepping,
            "wall incl. set-up [s]": w_long,
            "real-time factor incl. set-up": args.long / w_long,
        }
    ref = results["libcosim (fixed step, Jacobi)"]["stepping real-time factor"]
    for r in results.values():
        r["speed vs libcosim"] = r["stepping real-time factor"] / ref
    if args.save:
        save(args.save, results, argv)
    if args.json:
        print(json.dumps(results, indent=2))
    else:
        print(
            f"{SYSTEM} (1 ms step), {args.long:g} s and {args.short:g} s simulated, "
            f"median of {args.repeat}"
        )
        head = (
            f"{'engine':32s} {'RTF stepping':>13s} {'µs/step':>9s} {'wall long [s]':>14s} "
            f"{'RTF incl. set-up':>17s} {'vs libcosim':>12s}"
        )
        print(head)
        for name, r in results.items():
            print(
                f"{name:32s} {r['stepping real-time factor']:13.1f} "
                f"{r['us per macro step']:9.1f} {r['wall incl. set-up [s]']:14.3f} "
                f"{r['real-time factor incl. set-up']:17.1f} {r['speed vs libcosim']:11.2f}×"
            )
    return results


if __name__ == "__main__":
    main()

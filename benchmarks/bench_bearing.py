"""Benchmarks of the bearing model (run on demand: ``make bench``; not part of the tests).

1. Per-step cost inside an FMU: BearingModel.evaluate at a fixed temperature with a changing
   speed, and with a changing speed and axial load; and at a new temperature every step (a
   ramp: the thermal state and the unloaded state are solved again).
2. A 1000-point temperature curve: vectorised (BearingModel.curves) versus a scalar loop over
   the same temperatures (thermal_state + load_state + bearing_outputs per point), measured
   in one run; the ratio is what matters.

Prints a small table; ``--json`` prints the figures as JSON.
"""

from __future__ import annotations

import argparse
import json
import statistics
import time

import numpy as np

from servofmu.physics.bearing import (
    BearingModel,
    BearingPair,
    bearing_outputs,
    load_state,
    thermal_state,
)


def _per_call(fn, n: int, repeat: int = 5) -> float:
    """Median over ``repeat`` runs of the time per call of ``fn(i)``, i = 0..n−1 [s]."""
    runs = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for i in range(n):
            fn(i)
        runs.append((time.perf_counter() - t0) / n)
    return statistics.median(runs)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--points", type=int, default=1000)
    args = parser.parse_args()

    pair = BearingPair.from_catalog("yu2017_gimbal_printed", "krytox_143aa")
    model = BearingModel(pair)
    t = 293.15
    n = 20000
    speeds = np.linspace(-1.0, 1.0, n).tolist()
    loads = np.linspace(-150.0, 150.0, n).tolist()
    model.evaluate(t, 0.1, 10.0)  # warm the caches (thermal state, axial-load table)
    step_speed = _per_call(lambda i: model.evaluate(t, speeds[i]), n)
    step_load = _per_call(lambda i: model.evaluate(t, speeds[i], loads[i]), n)
    ramp = np.linspace(253.15, 263.15, 500).tolist()
    step_temperature = _per_call(lambda i: model.evaluate(ramp[i], 0.1), len(ramp), repeat=3)
    t0 = time.perf_counter()
    BearingModel(pair).evaluate(t, 0.1, 10.0)
    table_build = time.perf_counter() - t0

    temps = np.linspace(233.15, 333.15, args.points)
    vec = _per_call(lambda i: model.curves(temps, 0.1), 1, repeat=5)

    def scalar_curve(_):
        for ti in temps:
            th = thermal_state(pair, float(ti))
            bearing_outputs(pair, th, load_state(pair, th), 0.1)

    loop = _per_call(scalar_curve, 1, repeat=1)
    figures = {
        "step_speed_us": step_speed * 1e6,
        "step_speed_and_axial_load_us": step_load * 1e6,
        "step_new_temperature_ms": step_temperature * 1e3,
        "axial_load_table_build_ms": table_build * 1e3,
        "curve_points": args.points,
        "curve_vectorised_ms": vec * 1e3,
        "curve_scalar_loop_ms": loop * 1e3,
        "curve_speedup": loop / vec,
    }
    if args.json:
        print(json.dumps(figures, indent=2))
        return
    print(f"per step, speed changes                 {figures['step_speed_us']:8.2f} µs")
    print(
        f"per step, speed and axial load change   {figures['step_speed_and_axial_load_us']:8.2f} µs"
    )
    print(f"per step, new temperature (a ramp)      {figures['step_new_temperature_ms']:8.2f} ms")
    print(f"axial-load table, once per temperature  {figures['axial_load_table_build_ms']:8.2f} ms")
    print(
        f"{args.points}-point curve, vectorised          {figures['curve_vectorised_ms']:8.2f} ms"
    )
    print(
        f"{args.points}-point curve, scalar loop         {figures['curve_scalar_loop_ms']:8.2f} ms"
    )
    print(f"vectorised / loop speed-up              {figures['curve_speedup']:8.1f} ×")


if __name__ == "__main__":
    main()

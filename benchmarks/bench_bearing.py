"""Benchmarks of the bearing model (run on demand: ``make bench``; not part of the tests).

1. Per-step cost inside an FMU, BearingModel.evaluate on the default BearingFriction pair
   (Yu's gimbal with the compliant yoke) in the loops of benchmarks/bench_fmus.py: speed
   changing at a fixed temperature and load (only the speed terms); speed and axial load
   changing (the continuation at a fixed thermal state); a −60 → +80 °C ramp over 1000 steps
   at 20 N (a new thermal state every step); the same ramp with the axial load 10–30 N and
   the radial load 0–20 N changing every step (every ball differs); and the first call, which
   the continuation solves from scratch (its cold start). Best of ``--repeat`` runs (the least
   disturbed by other load).
2. A 1000-point temperature curve: vectorised (BearingModel.curves) versus a scalar loop over
   the same temperatures (thermal_state + load_state + bearing_outputs per point, the exact
   path), measured in one run; the ratio is what matters.

3. The same pair as a tandem set (``arrangement = tandem``, 40 N constant-force preload) on
   the two ramps (the continuation with its two offsets moving together).

``--models`` also times the per-step loops under the other friction models (parameter
``friction_model``: skf2004, ehl_per_contact; Yu's gimbal, no grease term).

Prints a small table; ``--json`` prints the figures as JSON.
"""

from __future__ import annotations

import argparse
import json
import math
import time

import numpy as np
from results import save  # benchmarks/ is the script's folder
from trajectories import BEARING_LOOPS as LOOPS  # benchmarks/ is the script's folder

from servofmu.parameters.bearing import default_parameters, pair_from_parameters
from servofmu.physics.bearing import (
    BearingModel,
    bearing_outputs,
    load_state,
    thermal_state,
)


def per_step(pair, values, steps: int, repeat: int) -> tuple[float, int]:
    """Best time per evaluate call [s] over ``repeat`` runs of ``steps`` steps (each run a new
    model whose first call, a cold start, is not timed), and the exact steps of the last
    run."""
    series = [values(k) for k in range(steps + 1)]
    best = math.inf
    for _ in range(repeat):
        model = BearingModel(pair)
        model.evaluate(*series[0])
        t0 = time.perf_counter()
        for args in series[1:]:
            model.evaluate(*args)
        best = min(best, (time.perf_counter() - t0) / steps)
    return best, model.exact_steps


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true")
    parser.add_argument(
        "--save",
        metavar="FILE.json",
        help="also write the figures and the run's context to this JSON file (docs: Performance)",
    )
    parser.add_argument("--points", type=int, default=1000)
    parser.add_argument("--steps", type=int, default=4000)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument(
        "--models", action="store_true", help="also the per-step loops of skf2004, ehl_per_contact"
    )
    args = parser.parse_args()

    params = default_parameters("yu2017_gimbal")
    pair = pair_from_parameters(params)
    figures = {}
    models = {"": pair}
    if args.models:
        for m in ("skf2004", "ehl_per_contact"):
            models[f"{m}: "] = pair_from_parameters(params | {"friction_model": m})
    for prefix, p in models.items():
        for label, values in LOOPS.items():
            secs, fallbacks = per_step(p, values, args.steps, args.repeat)
            figures[f"step: {prefix}{label} [us]"] = secs * 1e6
            figures[f"step: {prefix}{label}, exact fallbacks"] = fallbacks
    tandem = pair_from_parameters(
        params | {"arrangement": "tandem", "preload_method": "force", "assembly_preload": 40.0}
    )
    for label, values in LOOPS.items():
        if label.startswith("ramp"):
            secs, _ = per_step(tandem, values, args.steps, args.repeat)
            figures[f"step: tandem: {label} [us]"] = secs * 1e6
    firsts = []
    for _ in range(3):
        t0 = time.perf_counter()
        BearingModel(pair).evaluate(253.15, 0.1, 20.0)
        firsts.append(time.perf_counter() - t0)
    figures["first call, cold start [ms]"] = min(firsts) * 1e3

    model = BearingModel(pair)
    temps = np.linspace(233.15, 333.15, args.points)
    vec = math.inf
    for _ in range(5):
        t0 = time.perf_counter()
        model.curves(temps, 0.1)
        vec = min(vec, time.perf_counter() - t0)
    t0 = time.perf_counter()
    for ti in temps:
        th = thermal_state(pair, float(ti))
        bearing_outputs(pair, th, load_state(pair, th), 0.1)
    loop = time.perf_counter() - t0
    figures |= {
        "curve points": args.points,
        "curve vectorised [ms]": vec * 1e3,
        "curve scalar loop [ms]": loop * 1e3,
        "curve speed-up [x]": loop / vec,
    }
    if args.save:
        save(args.save, figures)
    if args.json:
        print(json.dumps(figures, indent=2))
        return
    for name, value in figures.items():
        print(f"{name:58s} {value:10.2f}" if isinstance(value, float) else f"{name:58s} {value:7d}")


if __name__ == "__main__":
    main()

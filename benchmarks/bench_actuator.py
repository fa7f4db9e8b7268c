"""Benchmark of the actuator model (run on demand: ``make bench``; not part of the tests).

A 1000-point reduction-ratio curve and stiffness curve over the output angle (Liu Fig 2–4,
Liu's four elements) and a 1000-point stiffness-versus-load curve with the support bearings,
each vectorised versus a scalar loop over the same points, measured in one run.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import time

import numpy as np
from results import save  # benchmarks/ is the script's folder

from servofmu.physics.drives.actuator import Actuator, reduction_ratio, stiffness_breakdown


def _time(fn, repeat: int = 3) -> float:
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true")
    parser.add_argument(
        "--save",
        metavar="FILE.json",
        help="also write the figures and the run's context to this JSON file (docs: Performance)",
    )
    parser.add_argument("--points", type=int, default=1000)
    args = parser.parse_args()
    act = Actuator.from_catalog("liu2014_ema")
    bare = dataclasses.replace(act, support_mounting="")
    angles = np.linspace(-0.5, 0.5, args.points)
    loads = np.linspace(10.0, 300.0, args.points)
    cases = {
        "ratio_vs_angle": (
            lambda: reduction_ratio(act, angles),
            lambda: [reduction_ratio(act, float(a)) for a in angles],
        ),
        "stiffness_vs_angle": (
            lambda: stiffness_breakdown(bare, angles, 100.0),
            lambda: [stiffness_breakdown(bare, float(a), 100.0) for a in angles],
        ),
        "stiffness_vs_load_with_bearings": (
            lambda: stiffness_breakdown(act, 0.17, loads),
            lambda: [stiffness_breakdown(act, 0.17, float(m)) for m in loads],
        ),
    }
    figures = {"points": args.points}
    for name, (vec, loop) in cases.items():
        t_vec, t_loop = _time(vec), _time(loop, repeat=1)
        figures[name] = {
            "vectorised_ms": t_vec * 1e3,
            "loop_ms": t_loop * 1e3,
            "speedup": t_loop / t_vec,
        }
    if args.save:
        save(args.save, figures)
    if args.json:
        print(json.dumps(figures, indent=2))
        return
    for name, f in figures.items():
        if name == "points":
            continue
        print(
            f"{args.points}-point {name:32s} vectorised {f['vectorised_ms']:9.2f} ms   "
            f"loop {f['loop_ms']:9.1f} ms   {f['speedup']:7.1f} ×"
        )


if __name__ == "__main__":
    main()

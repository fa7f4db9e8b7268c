"""Sweep throughput on Dask with 2 worker processes against 1, in one run (on demand:
``make bench``; not part of the tests).

Two workloads, each timed on an already started LocalCluster (servofmu's settings:
``harness.sweep.local_cluster``) whose workers have run a warm-up chunk (imports, unpacked
FMUs), so that only the sweep itself is timed:

- co-simulations: the seeker_gimbal system for 1 s (1 ms step) at 48 chamber
  temperatures, through the harness in the workers;
- model evaluations: the Monte-Carlo tolerance study's points (fit and shim drawn, 11
  temperatures each).

Reported: runs per second with 1 and 2 workers, and their ratio (the machine's cores bound
it: 2 here).
"""

from __future__ import annotations

import argparse
import json
import os
import time

import numpy as np
from dask.distributed import Client
from results import save  # benchmarks/ is the script's folder

from servofmu.harness.scenarios.common import system_path
from servofmu.harness.sweep import ModelTask, SystemTask, grid_points, local_cluster, run_sweep
from servofmu.harness.tolerance import tolerance_points
from servofmu.parameters.bearing import default_parameters


def workloads(samples: int):
    ssp = system_path("seeker_gimbal").read_bytes()
    temps = list(np.linspace(233.15, 333.15, 48))
    return {
        "co-simulation (seeker_gimbal, 1 s)": (
            SystemTask(ssp, ("motor.current", "motor.speed"), stop=1.0),
            grid_points({"bearing.temperature": temps}),
            grid_points({"bearing.temperature": temps[:2]}),
        ),
        "model evaluation (tolerance study)": (
            ModelTask(default_parameters("yu2017_gimbal"), ("running_torque", "overloaded")),
            tolerance_points("yu2017_gimbal", samples, seed=3),
            tolerance_points("yu2017_gimbal", 4, seed=4),
        ),
    }


def throughput(n_workers: int, task, points, warmup) -> float:
    with local_cluster(n_workers) as cluster, Client(cluster) as client:
        run_sweep(task, warmup * n_workers, client=client, chunk_size=1, progress=False)
        t0 = time.perf_counter()
        res = run_sweep(task, points, client=client, progress=False)
        wall = time.perf_counter() - t0
        if res.failed:
            raise RuntimeError(f"{len(res.failed)} runs failed: {res.failed[0]}")
    return len(points) / wall


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=400, help="tolerance-study draws")
    parser.add_argument("--json", action="store_true")
    parser.add_argument(
        "--save",
        metavar="FILE.json",
        help="also write the figures and the run's context to this JSON file (docs: Performance)",
    )
    args = parser.parse_args(argv)
    results = {}
    for name, (task, points, warmup) in workloads(args.samples).items():
        one = throughput(1, task, points, warmup)
        two = throughput(2, task, points, warmup)
        results[name] = {
            "runs": len(points),
            "runs/s, 1 worker": one,
            "runs/s, 2 workers": two,
            "speed-up": two / one,
        }
    if args.save:
        save(args.save, results, argv)
    if args.json:
        print(json.dumps(results, indent=2))
    else:
        print(f"sweep throughput on Dask LocalCluster ({os.cpu_count()} cores)")
        print(f"{'workload':40s} {'runs':>6s} {'1 worker':>12s} {'2 workers':>12s} {'ratio':>7s}")
        for name, r in results.items():
            print(
                f"{name:40s} {r['runs']:6d} {r['runs/s, 1 worker']:10.1f}/s "
                f"{r['runs/s, 2 workers']:10.1f}/s {r['speed-up']:6.2f}×"
            )
    return results


if __name__ == "__main__":
    main()

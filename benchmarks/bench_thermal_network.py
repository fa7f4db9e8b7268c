"""Accuracy and cost of the ThermalNetwork stepping (on demand: ``make bench``; not part of
the tests, which assert the bounds in tests/physics/test_thermal_network.py).

Each preset starts soaked at −60 °C; at t = 0 the ambient and the sink jump to +80 °C with
0.05 W of bearing loss, and the network is stepped for 3 h with communication steps h. The
reference is scipy's Radau at rtol = atol = 1e-11. Reported per (h, linearisation tolerance):
the largest deviation over all parts and step ends [K], the number of matrix exponentials
(re-linearisations) and the library's time per step [µs].
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from results import save  # benchmarks/ is the script's folder

from servofmu.physics.thermal import network as tn

COLD, HOT, POWER = 213.15, 353.15, 0.05  # K, K, W


def stepped(net, start, ref, h, tolerance, horizon):
    """(largest error [K], matrix exponentials, seconds per step)."""
    x, lin, count, worst, spent = list(start), None, 0, 0.0, 0.0
    for k in range(round(horizon / h)):
        t0 = time.perf_counter()
        if lin is None or max(abs(a - b) for a, b in zip(x, lin, strict=True)) > tolerance:
            lin, count = tuple(x), count + 1
        x = tn.step_unchecked(net, x, HOT, HOT, POWER, h, lin)
        spent += time.perf_counter() - t0
        worst = max(worst, float(np.abs(np.asarray(x) - ref(h * (k + 1))).max()))
    return worst, count, spent / round(horizon / h)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--hours", type=float, default=3.0)
    parser.add_argument(
        "--save",
        metavar="FILE.json",
        help="also write the figures and the run's context to this JSON file (docs: Performance)",
    )
    args = parser.parse_args()
    horizon = 3600.0 * args.hours
    print(
        f"{'preset':24s} {'h [s]':>6s} {'tol [K]':>7s} {'max error [K]':>14s} {'expm':>6s} µs/step"
    )
    rows = []
    for key in tn.PRESETS:
        net = tn.network(tn.preset(key))
        start = tn.steady_state(net, COLD, COLD, 0.0)
        ref = tn.ode_solution(net, start, HOT, HOT, POWER, horizon)
        for h in (1.0, 10.0, 60.0, 600.0):
            for tol in (0.0, 0.1):
                err, count, cost = stepped(net, start, ref, h, tol, horizon)
                print(f"{key:24s} {h:6g} {tol:7g} {err:14.2e} {count:6d} {cost * 1e6:7.1f}")
                rows.append(
                    {
                        "preset": key,
                        "step [s]": h,
                        "linearisation tolerance [K]": tol,
                        "largest error [K]": err,
                        "matrix exponentials": count,
                        "us per step": cost * 1e6,
                    }
                )
    if args.save:
        save(args.save, {"hours": args.hours, "rows": rows})


if __name__ == "__main__":
    main()

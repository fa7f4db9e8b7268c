"""Memory and time of `servofmu calibrate` on long measurement files (on demand: ``make
bench``; not part of the tests).

A file of synthetic friction torque is written into a temporary folder (never into the
repository): Yu's gimbal (mounting yu2017_gimbal_printed, s0 = 0.8, μ = 0.1) at six chamber
temperatures −40…+60 °C, forward and reverse, 3 % noise, repeated until the file has the
requested size (the default 200 MB is about 10 million rows). A fresh Python process then
reads and calibrates it (s0 and μ, 10 °/s) and reports its peak resident memory (``ru_maxrss``)
against the same process after the imports only, and the wall times of reading and fitting.
The same is done at a tenth of the size: the memory should not grow with the file.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from results import save  # benchmarks/ is the script's folder

TEMPS_C = (-40.0, -20.0, 0.0, 20.0, 40.0, 60.0)


def write_file(path: Path, size_mb: float, seed: int = 1) -> int:
    """Write the synthetic CSV of about ``size_mb`` MB; returns the number of rows."""
    from servofmu.calibration import running_torque
    from servofmu.parameters.bearing import default_parameters
    from servofmu.physics.kernels.units import DEG, NMM, ZERO_CELSIUS

    truth = dict(default_parameters("yu2017_gimbal_printed"), palmgren_s0=0.8, sliding_friction=0.1)
    temps = np.array(TEMPS_C) + ZERO_CELSIUS
    model = running_torque(truth, temps, np.full(temps.shape, 10 * DEG)) / NMM
    rng = np.random.default_rng(seed)
    rows, written, target = 0, 0, size_mb * 1e6
    block = 120_000  # rows per block, a multiple of the 12 groups
    with path.open("w") as fh:
        fh.write("# synthetic: yu2017_gimbal_printed, s0 = 0.8, mu = 0.1, 3 % noise\n")
        fh.write("temperature [degC],torque [N.mm],direction\n")
        while written < target:
            g = np.arange(block) % 12
            torque = model[g // 2] * (1.0 + 0.03 * rng.standard_normal(block))
            text = "".join(
                f"{TEMPS_C[k // 2]:g},{m:.6g},{'forward' if k % 2 == 0 else 'reverse'}\n"
                for k, m in zip(g.tolist(), torque.tolist(), strict=True)
            )
            fh.write(text)
            written += len(text)
            rows += block
    return rows


def child(path: str) -> None:
    """In a fresh process: peak RSS after the imports, then after reading and fitting."""
    import resource

    from servofmu.calibration import calibrate, read_measurements
    from servofmu.parameters.bearing import default_parameters
    from servofmu.physics.kernels.units import DEG

    base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    t0 = time.perf_counter()
    data = read_measurements(path)
    t1 = time.perf_counter()
    cal = calibrate(
        data,
        default_parameters("yu2017_gimbal_printed"),
        ["palmgren_s0", "sliding_friction"],
        speed=10 * DEG,
    )
    t2 = time.perf_counter()
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    print(
        json.dumps(
            {
                "rows": len(data),
                "groups": data.groups,
                "rss_imports_mb": base / 1024,
                "rss_peak_mb": peak / 1024,
                "read_s": t1 - t0,
                "fit_s": t2 - t1,
                "estimate": cal.estimate.tolist(),
                "standard_error": cal.standard_error.tolist(),
                "poor": cal.poor,
            }
        )
    )


def measure(size_mb: float) -> dict:
    with tempfile.TemporaryDirectory(prefix="servofmu_bench_cal_") as tmp:
        path = Path(tmp) / "long.csv"
        rows = write_file(path, size_mb)
        size = path.stat().st_size
        out = subprocess.run(
            [sys.executable, __file__, "--child", str(path)],
            check=True,
            capture_output=True,
            text=True,
        )
    result = json.loads(out.stdout)
    result.update(file_mb=size / 1e6, rows_written=rows)
    return result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size-mb", type=float, default=200.0)
    parser.add_argument("--child", help=argparse.SUPPRESS)
    parser.add_argument(
        "--save",
        metavar="FILE.json",
        help="also write the figures and the run's context to this JSON file (docs: Performance)",
    )
    args = parser.parse_args()
    if args.child:
        child(args.child)
        return
    columns = ("file [MB]", "rows", "groups", "RSS imports", "RSS peak", "growth", "read [s]")
    print(" ".join(columns) + " fit [s]  s0, mu (SE)")
    runs = []
    for size in (args.size_mb / 10.0, args.size_mb):
        r = measure(size)
        runs.append(r)
        growth = r["rss_peak_mb"] - r["rss_imports_mb"]
        est = ", ".join(
            f"{e:.4f} ({s:.1g})" for e, s in zip(r["estimate"], r["standard_error"], strict=True)
        )
        print(
            f"{r['file_mb']:9.1f} {r['rows']:10d} {r['groups']:6d} {r['rss_imports_mb']:9.0f} MB "
            f"{r['rss_peak_mb']:6.0f} MB {growth:4.0f} MB {r['read_s']:8.1f} {r['fit_s']:7.2f}  "
            f"{est}{'  POOR FIT' if r['poor'] else ''}"
        )
    if args.save:
        save(args.save, {"runs": runs})


if __name__ == "__main__":
    main()

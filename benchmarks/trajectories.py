"""The input trajectories the bearing benchmarks share (bench_bearing.py: the library's
per-step path; bench_fmus.py: the same loops through fmpy), so both measure the same steps."""

from __future__ import annotations

import math


def ramp(k: int) -> float:
    """−60 → +80 °C over 1000 steps and back (a triangle of period 2000 steps) [K]."""
    phase = (k % 2000) / 1000.0
    return 213.15 + 140.0 * (phase if phase <= 1.0 else 2.0 - phase)


#: (temperature [K], speed [rad/s], axial load [N], radial load [N]) at step k
BEARING_LOOPS = {
    "speed changes": lambda k: (253.15, 0.2 * math.sin(1e-3 * k), 5.0, 0.0),
    "speed and axial load change": lambda k: (
        253.15,
        0.2 * math.sin(1e-3 * k),
        5.0 + math.sin(2e-3 * k),
        0.0,
    ),
    "ramp -60..+80 degC, 20 N axial": lambda k: (ramp(k), 0.2 * math.sin(1e-3 * k), 20.0, 0.0),
    "ramp, axial 10-30 N, radial 0-20 N": lambda k: (
        ramp(k),
        0.2 * math.sin(1e-3 * k),
        20.0 + 10.0 * math.sin(7e-3 * k),
        10.0 + 10.0 * math.sin(1.1e-2 * k),
    ),
}

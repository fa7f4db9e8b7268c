"""Synthetic friction measurements: the model's running torque at chosen temperatures and
speeds with multiplicative Gaussian noise, for tests and for the example data set (the
truth is known, so a calibration can be checked against it)."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import numpy as np

from ..files import write_text
from ..physics.kernels.units import DEG, NMM, ZERO_CELSIUS
from .fit import running_torque
from .measurements import FrictionMeasurements


def synthesise(
    parameters: Mapping[str, object],
    temperatures,
    speeds,
    noise: float = 0.02,
    seed: int = 0,
    directions=("forward", "reverse"),
) -> FrictionMeasurements:
    """Every combination of ``temperatures`` [K], ``speeds`` [rad/s, magnitudes] and
    ``directions``: torque = model·(1 + noise·N(0, 1)), one draw per point (numpy
    ``default_rng(seed)``)."""
    t, w, d = np.meshgrid(
        np.asarray(temperatures, float),
        np.asarray(speeds, float),
        np.arange(len(directions)),
        indexing="ij",
    )
    t, w, d = t.ravel(), w.ravel(), d.ravel()
    model = running_torque(parameters, t, w)
    rng = np.random.default_rng(seed)
    torque = model * (1.0 + noise * rng.standard_normal(model.shape))
    return FrictionMeasurements(
        source="synthetic",
        temperature=t,
        torque=torque,
        speed=w,
        direction=tuple(directions[i] for i in d),
        lines=tuple(range(2, 2 + t.size)),
    )


def write_measurements(data: FrictionMeasurements, path, comment: str = "", speed=True) -> Path:
    """Write ``data`` in the format :func:`~.measurements.read_measurements` reads (°C, N·mm,
    °/s, direction), ``comment`` as leading ``#`` lines; ``speed=False`` leaves the speed
    column out (a test at one, separately stated speed)."""
    path = Path(path)
    lines = [f"# {c}" for c in comment.splitlines()]
    lines.append(
        "temperature [degC],torque [N.mm]," + ("speed [deg/s]," if speed else "") + "direction"
    )
    for i in range(len(data)):
        cells = [f"{data.temperature[i] - ZERO_CELSIUS:.6g}", f"{data.torque[i] / NMM:.6g}"]
        if speed:
            cells.append(f"{data.speed[i] / DEG:.6g}")
        lines.append(",".join([*cells, data.direction[i]]))
    write_text(path, "\n".join(lines) + "\n")
    return path

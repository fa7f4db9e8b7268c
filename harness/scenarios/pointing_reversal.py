"""Pointing at small angles: the seeker gimbal's position loop follows small-angle reversals
(sine and triangle commands of ±0.02°, 2 Hz) at −40, 20 and 60 °C, with pre-rolling
friction (the ``seeker_gimbal_prerolling`` system: Dahl's state, its rest stiffness from the
contacts, loads the motor) and without (``seeker_gimbal_position``: the motor applies the
bearing's running and breakaway torque as Coulomb friction, implicitly on sub-steps).

Both run at the pre-rolling system's step, 20 µs, which resolves the Dahl resonance of the
rotor on the contacts' rest stiffness (about 1.1 kHz at 20 °C). Per run:

- rms and largest tracking error;
- the tracking error at the reversals of the command (mean and largest |error| over the
  reversals: the "quadrant glitch");
- speed reversals against the command's: more is hunting or a limit cycle;
- the friction torque's swing; the torque–angle loops (friction torque against the rotor's
  angle) are in the figure and in each run's CSV.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from servofmu.files import save_figure

from .. import load_system
from .. import run as run_system
from ..signals import Cycle
from .common import ScenarioResult, system_path

AMPLITUDE = math.radians(0.02)  # rad
PERIOD = 0.5  # s
STEP = 2e-5  # s: resolves the Dahl resonance (about 1.1 kHz at 20 °C, 1.5 kHz at −40 °C)
TEMPERATURES = (("-40 °C", "cold"), ("20 °C", None), ("60 °C", "warm"))
SHAPES = ("sine", "triangle")
SYSTEMS = (("Dahl", "seeker_gimbal_prerolling"), ("none", "seeker_gimbal_position"))


def command(shape: str) -> Cycle:
    """The position command [rad]: ±:data:`AMPLITUDE` of ``shape`` with period :data:`PERIOD`,
    starting at 0 and rising, as the gimbal starts (a triangle a quarter period in: no step
    at the start).

    Returns
    -------
    Cycle

    Examples
    --------
    >>> [round(command(s)(t) / AMPLITUDE, 12) for s in SHAPES for t in (0.0, PERIOD / 4)]
    [0.0, 1.0, 0.0, 1.0]
    """
    start = -PERIOD / 4 if shape == "triangle" else 0.0
    return Cycle(-AMPLITUDE, AMPLITUDE, PERIOD, shape, start=start)


def reversal_times(shape: str, stop: float, period: float = PERIOD) -> np.ndarray:
    """Times [s] at which :func:`command` of ``shape`` reverses, up to about ``stop`` [s]:
    (k + 1/4)·P and (k + 3/4)·P for both shapes.

    Returns
    -------
    numpy.ndarray
        The times [s], one reversal beyond ``stop`` included.

    Examples
    --------
    >>> reversal_times("sine", 0.5).tolist(), reversal_times("triangle", 0.5).tolist()
    ([0.125, 0.375, 0.625], [0.125, 0.375, 0.625])
    """
    if shape not in SHAPES:
        raise ValueError(f"shape = {shape!r} is not one of {list(SHAPES)}")
    return (0.25 + 0.5 * np.arange(int(2.0 * stop / period) + 1)) * period


def reversal_metrics(time, reference, angle, speed, shape: str) -> dict:
    """Tracking figures of one run (arrays over time [s], reference/angle [rad], speed
    [rad/s]): the error over the run and near each reversal of the command (within a tenth of
    a period after it).

    Returns
    -------
    dict
        Errors [µrad] and reversal counts, keyed by column name (units in the names).

    Examples
    --------
    >>> t = np.linspace(0.0, PERIOD, 501)
    >>> ref = AMPLITUDE * np.sin(2.0 * np.pi * t / PERIOD)
    >>> m = reversal_metrics(t, ref, ref - 1e-6, np.gradient(ref, t), "sine")
    >>> round(m["max error after reversal [urad]"], 6), m["speed reversals"]
    (1.0, 2)
    """
    error = reference - angle
    at = reversal_times(shape, time[-1])
    at = at[at + 0.1 * PERIOD <= time[-1]]
    near = [np.max(np.abs(error[(time >= t) & (time <= t + 0.1 * PERIOD)])) for t in at]
    moving = speed[speed != 0.0]
    return {
        "rms error [urad]": 1e6 * float(np.sqrt(np.mean(error**2))),
        "max error [urad]": 1e6 * float(np.max(np.abs(error))),
        "mean error after reversal [urad]": 1e6 * float(np.mean(near)) if near else 0.0,
        "max error after reversal [urad]": 1e6 * float(np.max(near)) if near else 0.0,
        "speed reversals": int(np.count_nonzero(np.diff(np.sign(moving)) != 0)),
        "command reversals": int(np.count_nonzero(reversal_times(shape, time[-1]) < time[-1])),
    }


def run(out_dir, fmu_dir=None, coarse: bool = False) -> ScenarioResult:
    """The scenario on the standard mechanism, its systems from ``fmu_dir`` (default: the
    build folder, built when missing or stale), its files in ``out_dir``; ``coarse``: one
    period of each command (else three).

    Returns
    -------
    ScenarioResult
        One row per system, temperature and command; the files: each run's CSV, the table's
        CSV and the figure.

    Examples
    --------
    The runs (each at the step :data:`STEP` [s]):

    >>> [name for _, name in SYSTEMS]
    ['seeker_gimbal_prerolling', 'seeker_gimbal_position']
    >>> [label for label, _ in TEMPERATURES], SHAPES, STEP
    (['-40 °C', '20 °C', '60 °C'], ('sine', 'triangle'), 2e-05)
    """
    out = Path(out_dir)
    stop = PERIOD if coarse else 3.0 * PERIOD
    rows, files, traces = [], [], {}
    for friction, name in SYSTEMS:
        system = load_system(system_path(name, fmu_dir))
        torque = "bearing.friction_torque" if friction == "Dahl" else "motor.friction_torque"
        try:
            for label, variant in TEMPERATURES:
                for shape in SHAPES:
                    res = run_system(
                        system,
                        parameters=variant,
                        signals={"controller.reference": command(shape)},
                        stop=stop,
                        step=STEP,
                        record=["controller.reference", "motor.angle", "motor.speed", torque],
                        out_dir=out / f"{friction.lower()}_{variant or 'base'}_{shape}",
                        progress=False,
                    )
                    files.append(res.csv)
                    traces[(friction, label, shape)] = (res, torque)
                    m = reversal_metrics(
                        res["time"],
                        res["controller.reference"],
                        res["motor.angle"],
                        res["motor.speed"],
                        shape,
                    )
                    t = res[torque]
                    rows.append(
                        {
                            "pre-rolling": friction,
                            "temperature": label,
                            "command": shape,
                            **m,
                            "torque swing [N.mm]": 1e3 * float(np.max(t) - np.min(t)),
                        }
                    )
        finally:
            system.close()
    by = {(r["pre-rolling"], r["temperature"], r["command"]): r for r in rows}
    summary = {
        f"{label} {shape}: error after reversal, Dahl/none": by[("Dahl", label, shape)][
            "mean error after reversal [urad]"
        ]
        / max(by[("none", label, shape)]["mean error after reversal [urad]"], 1e-12)
        for label, _ in TEMPERATURES
        for shape in SHAPES
    }
    result = ScenarioResult(
        "pointing_reversal",
        f"Seeker gimbal pointing: sine and triangle commands of ±{math.degrees(AMPLITUDE):g}° at "
        f"{1 / PERIOD:g} Hz, −40/20/60 °C, with pre-rolling (Dahl, rest stiffness from the "
        f"contacts) and without; step {STEP * 1e6:g} µs",
        list(rows[0]),
        rows,
        summary=summary,
        files=files,
        notes=[
            "pre-rolling none: the motor applies the bearing's running/breakaway torque as "
            "Coulomb friction (seeker_gimbal_position); Dahl: the bearing's friction_torque "
            "from Dahl's state loads the motor (seeker_gimbal_prerolling).",
            "error after reversal: the largest |command − angle| within a tenth of a period "
            "after each reversal of the command; speed reversals beyond the command's are "
            "hunting or a limit cycle.",
            "at 60 °C the compliant yoke has lost the preload: no ball is loaded, the rest "
            "stiffness from the contacts is 0 and the bearing falls back to the regularised "
            "sign (its friction_torque is then the one without pre-rolling).",
        ],
    )
    result.write_table(out / "pointing_reversal.csv")
    result.files.append(_plot(traces, out / "pointing_reversal.png"))
    return result


def _plot(traces, path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, len(TEMPERATURES), figsize=(12, 6.4), squeeze=False)
    for col, (label, _) in enumerate(TEMPERATURES):
        ax_loop, ax_err = axes[0, col], axes[1, col]
        for friction, _ in SYSTEMS:
            res, torque = traces[(friction, label, "sine")]
            ax_loop.plot(
                1e6 * res["motor.angle"], 1e3 * res[torque], lw=0.8, label=f"pre-rolling {friction}"
            )
            ax_err.plot(
                res["time"],
                1e6 * (res["controller.reference"] - res["motor.angle"]),
                lw=0.8,
                label=f"pre-rolling {friction}",
            )
        ax_loop.set_title(f"{label}, sine command", fontsize=10)
        ax_loop.set_xlabel("rotor angle [µrad]")
        ax_loop.set_ylabel("friction torque [N·mm]")
        ax_err.set_xlabel("time [s]")
        ax_err.set_ylabel("tracking error [µrad]")
        for ax in (ax_loop, ax_err):
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, path, dpi=100)
    plt.close(fig)
    return path

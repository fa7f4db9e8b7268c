"""Low-speed tracking of the seeker gimbal: a sine position reference (±0.01 rad, 0.2 Hz) on the
position loop at 20 °C and −40 °C (the ``cold`` variant), at communication steps of 0.5, 1 and
2 ms.

Near each reversal of the reference the motor speed passes through zero and the bearing's
breakaway torque holds it: the motor sticks until the controller's output has grown past
the breakaway torque, and the tracking error grows meanwhile (the friction dead zone; at
−40 °C the preload and the grease viscosity multiply the friction). Per run:

- rms and largest tracking error;
- stuck fraction (time with the rotor held by friction, speed exactly 0 in the DCMotor's
  implicit stick/slip) and stick→slip transitions (one at the start and one per reversal
  when the motion is clean; more is stick-slip hunting);
- speed reversals (the reference reverses twice per period: more would be chatter);
- mean stick time (from the rotor stopping to its breaking away again).

The friction is applied inside the DCMotor's sub-steps (bearing magnitudes in, sign from the
motor's own state), so the communication step cannot make the friction chatter; what it still
changes is the delay in the loop, which the step-size comparison shows.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from servofmu.files import save_figure

from .. import load_system
from .. import run as run_system
from ..signals import Cycle
from .common import ScenarioResult, mechanism_notes, system_path

AMPLITUDE = 0.01  # rad
PERIOD = 5.0  # s (0.2 Hz)
CASES = (("20 °C", None), ("-40 °C", "cold"))  # (label, variant of seeker_gimbal_position)
STEPS = (0.5e-3, 1.0e-3, 2.0e-3)  # s, communication steps compared


def tracking_metrics(time, reference, angle, speed, period: float = PERIOD) -> dict:
    """Tracking figures of one run (arrays over time [s], reference/angle [rad], speed
    [rad/s]); reversals of the sine reference at (k + 1/4)·period."""
    error = reference - angle
    stuck = speed == 0.0
    moving = speed[speed != 0.0]
    reversals = (0.25 + 0.5 * np.arange(int(2.0 * time[-1] / period) + 1)) * period
    # stuck intervals that begin after the first motion (the rotor starts at rest) and end
    # before the run does: [time the rotor stops, time it breaks away)
    change = np.flatnonzero(np.diff(stuck.astype(np.int8))) + 1
    stops = change[stuck[change]]
    breaks = change[~stuck[change]]
    stick_times = (
        [time[b] - time[a] for a, b in zip(stops, breaks[breaks > stops[0]], strict=False)]
        if len(stops)
        else []
    )
    return {
        "rms error [mrad]": 1e3 * float(np.sqrt(np.mean(error**2))),
        "max error [mrad]": 1e3 * float(np.max(np.abs(error))),
        "stuck fraction": float(np.mean(stuck)),
        "stick-slip transitions": int(np.count_nonzero(stuck[:-1] & ~stuck[1:])),
        "speed reversals": int(np.count_nonzero(np.diff(np.sign(moving)) != 0)),
        "reference reversals": int(np.count_nonzero(reversals < time[-1])),
        "mean stick time [ms]": 1e3 * float(np.mean(stick_times)) if stick_times else 0.0,
    }


def run(out_dir, fmu_dir=None, coarse: bool = False, mechanism=None) -> ScenarioResult:
    """The scenario on ``mechanism`` (default: the standard one): its
    ``seeker_gimbal_position`` system."""
    out = Path(out_dir)
    stop = PERIOD if coarse else 2.0 * PERIOD
    system = load_system(system_path("seeker_gimbal_position", fmu_dir, mechanism))
    reference = Cycle(-AMPLITUDE, AMPLITUDE, PERIOD, "sine")
    rows, files, traces = [], [], {}
    try:
        for label, variant in CASES:
            for h in STEPS:
                tag = f"{variant or 'base'}_{h * 1e3:g}ms"
                res = run_system(
                    system,
                    parameters=variant,
                    signals={"controller.reference": reference},
                    stop=stop,
                    step=h,
                    record=[
                        "controller.reference",
                        "motor.angle",
                        "motor.speed",
                        "motor.friction_torque",
                        "bearing.breakaway_torque",
                        "controller.command",
                    ],
                    out_dir=out / tag,
                    progress=False,
                )
                files.append(res.csv)
                traces[(label, h)] = res
                m = tracking_metrics(
                    res["time"], res["controller.reference"], res["motor.angle"], res["motor.speed"]
                )
                rows.append(
                    {
                        "temperature": label,
                        "step [ms]": h * 1e3,
                        **m,
                        "breakaway [N.mm]": 1e3 * float(res["bearing.breakaway_torque"][-1]),
                    }
                )
    finally:
        system.close()
    by = {(r["temperature"], r["step [ms]"]): r for r in rows}
    summary = {
        "cold/warm rms error at 1 ms": by[("-40 °C", 1.0)]["rms error [mrad]"]
        / by[("20 °C", 1.0)]["rms error [mrad]"],
    }
    for label, _ in CASES:
        ref = by[(label, 1.0)]["rms error [mrad]"]
        for h in (0.5, 2.0):
            summary[f"{label}: rms error at {h:g} ms vs 1 ms [%]"] = 100.0 * (
                by[(label, h)]["rms error [mrad]"] / ref - 1.0
            )
    standard = mechanism is None or mechanism.standard
    result = ScenarioResult(
        "low_speed_tracking",
        f"{'Seeker gimbal' if standard else f'Mechanism {mechanism.key} (position loop)'}, "
        f"sine position reference ±{AMPLITUDE * 1e3:g} mrad at "
        f"{1 / PERIOD:g} Hz: friction dead zone at 20 °C and −40 °C, communication step "
        "0.5/1/2 ms",
        list(rows[0]),
        rows,
        summary=summary,
        files=files,
        notes=[
            *mechanism_notes(mechanism),
            "stick-slip transitions: one at the start plus one per reference reversal is clean "
            "tracking; more means hunting (stick-slip) between reversals. speed reversals equal "
            "to the reference reversals mean no chatter.",
        ],
    )
    result.write_table(out / "low_speed_tracking.csv")
    result.files.append(_plot(traces, out / "low_speed_tracking.png"))
    return result


def _plot(traces, path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, len(CASES), sharex=True, figsize=(10, 5.6), squeeze=False)
    for col, (label, _) in enumerate(CASES):
        ax_e, ax_w = axes[0, col], axes[1, col]
        for h in STEPS:
            r = traces[(label, h)]
            ax_e.plot(
                r["time"],
                1e3 * (r["controller.reference"] - r["motor.angle"]),
                lw=0.9,
                label=f"{h * 1e3:g} ms",
            )
            ax_w.plot(r["time"], r["motor.speed"], lw=0.9, label=f"{h * 1e3:g} ms")
        ax_e.set_title(f"{label}", fontsize=10)
        ax_e.set_ylabel("tracking error [mrad]")
        ax_w.set_ylabel("motor speed [rad/s]")
        ax_w.set_xlabel("time [s]")
        for ax in (ax_e, ax_w):
            ax.grid(True, alpha=0.3)
        ax_e.legend(fontsize=8, title="communication step", title_fontsize=8)
    fig.tight_layout()
    save_figure(fig, path, dpi=100)
    plt.close(fig)
    return path

"""Yu 2017's electrical method on the seeker gimbal: in each chamber temperature (−40…+60 °C in
20 K steps) the speed loop holds a constant low speed, forward then reverse; at steady state the
friction torque is read from the motor current as k_t·i and set next to the bearing model's
running torque (the BearingFriction output at that speed).

One run of the seeker_gimbal system with the chamber temperature and the speed reference as
stepped signals, as in a climatic-chamber test. k_t·i also carries the motor's own viscous
damping b·ω (0.0017 N·mm at 10 °/s), which the electrical method cannot separate either.
"""

from __future__ import annotations

from pathlib import Path

from servofmu.physics.units import DEG, NMM, celsius_to_kelvin

from .. import load_system
from .. import run as run_system
from ..signals import Steps
from .common import ScenarioResult, plateau_mean, system_path

TEMPS_C = (-40.0, -20.0, 0.0, 20.0, 40.0, 60.0)  # Yu §3 chamber temperatures
SPEED = 10.0 * DEG  # rad/s, the assumed test speed of the Yu reproduction


def run(out_dir, fmu_dir=None, coarse: bool = False) -> ScenarioResult:
    out = Path(out_dir)
    plateau = 1.0 if coarse else 2.0  # s per temperature: forward half, reverse half
    system = load_system(system_path("seeker_gimbal", fmu_dir))
    try:
        kt = system.components["motor"].parameters["torque_constant"][1]
        starts = [i * plateau for i in range(len(TEMPS_C))]
        temperature = Steps(tuple(starts), tuple(celsius_to_kelvin(t) for t in TEMPS_C))
        ref_times = tuple(t for s in starts for t in (s, s + plateau / 2))
        reference = Steps(ref_times, tuple(d * SPEED for _ in starts for d in (1.0, -1.0)))
        res = run_system(
            system,
            signals={"bearing.temperature": temperature, "controller.reference": reference},
            stop=len(TEMPS_C) * plateau,
            record=[
                "motor.current",
                "motor.speed",
                "bearing.running_torque",
                "bearing.preload",
                "bearing.overloaded",
                "bearing.locked",
                "bearing.unloaded",
                "bearing.temperature",
            ],
            out_dir=out,
        )
    finally:
        system.close()
    t = res["time"]
    rows = []
    for temp, s in zip(TEMPS_C, starts, strict=True):
        for direction, (a, b) in (
            ("forward", (s, s + plateau / 2)),
            ("reverse", (s + plateau / 2, s + plateau)),
        ):
            speed = plateau_mean(t, res["motor.speed"], a, b)
            measured = abs(kt * plateau_mean(t, res["motor.current"], a, b))
            model = plateau_mean(t, res["bearing.running_torque"], a, b)
            rows.append(
                {
                    "temperature [degC]": temp,
                    "direction": direction,
                    "speed [deg/s]": speed / DEG,
                    "measured k_t*i [N.mm]": measured / NMM,
                    "model [N.mm]": model / NMM,
                    "difference [%]": 100.0 * (measured / model - 1.0),
                    "preload [N]": plateau_mean(t, res["bearing.preload"], a, b),
                    **{
                        flag: bool(plateau_mean(t, res[f"bearing.{flag}"], a, b) > 0.5)
                        for flag in ("overloaded", "locked", "unloaded")
                    },
                }
            )
    result = ScenarioResult(
        "friction_vs_temperature",
        "Friction torque of the seeker gimbal by the electrical method (Yu 2017 §3), "
        f"speed loop at ±{SPEED / DEG:g} °/s",
        list(rows[0]),
        rows,
        summary={"largest |difference| [%]": max(abs(r["difference [%]"]) for r in rows)},
        files=[res.csv],
        notes=[
            "measured: k_t·i of the DCMotor at steady state; model: BearingFriction running "
            "torque. The model is symmetric in the direction; Yu's measured forward/reverse "
            "difference (grease redistribution) is not modelled.",
        ],
    )
    result.write_table(out / "friction_vs_temperature.csv")
    result.files.append(_plot(rows, out / "friction_vs_temperature.png"))
    return result


def _plot(rows, path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=110)
    for direction, marker in (("forward", "o"), ("reverse", "s")):
        sel = [r for r in rows if r["direction"] == direction]
        ax.semilogy(
            [r["temperature [degC]"] for r in sel],
            [r["measured k_t*i [N.mm]"] for r in sel],
            marker,
            mfc="none",
            label=f"measured k_t·i, {direction}",
        )
    fwd = [r for r in rows if r["direction"] == "forward"]
    ax.semilogy(
        [r["temperature [degC]"] for r in fwd],
        [r["model [N.mm]"] for r in fwd],
        "k-",
        label="bearing model",
    )
    from matplotlib.ticker import FormatStrFormatter

    for axis_format in (ax.yaxis.set_major_formatter, ax.yaxis.set_minor_formatter):
        axis_format(FormatStrFormatter("%g"))  # 2, 3, 0.5 [N·mm]: no powers of ten
    ax.tick_params(axis="y", which="minor", labelsize=7)
    ax.set_xlabel("chamber temperature [°C]")
    ax.set_ylabel("friction torque [N·mm]")
    ax.set_title("Seeker gimbal: electrical method in the co-simulation", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path

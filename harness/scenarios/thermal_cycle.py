"""Ning's space bearing (71807C, MoS2, titanium shaft and housing) under alternating
temperature: the speed loop holds 10 rpm while the temperature follows a triangle
−60 → +80 → −60 °C; friction torque (k_t·i of the motor and the bearing's running torque),
preload, contact angle and the two fit interferences versus temperature, on the rising and
the falling branch.

The bearing model is quasi-static in temperature (uniform temperature, no thermal lag between
rings, shaft and housing), so the cycle's duration only has to be long against the speed
loop's settling; one cycle of 60 s (20 s coarse) stands for the hours of a chamber cycle, and
the two branches coincide. A measured hysteresis between them would be thermal lag, which this
model does not have.

A further table sets each friction model of BearingFriction (``friction_model``) in the same
system at −40 °C (every number from the co-simulation or BearingFriction's outputs).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from servofmu.physics.friction import registry
from servofmu.physics.kernels.units import NMM, UM, celsius_to_kelvin

from .. import load_system
from .. import run as run_system
from ..signals import Cycle, Steps
from .common import ScenarioResult, Table, plateau_mean, system_path

LOW_C, HIGH_C = -60.0, 80.0  # °C, the alternating-temperature range
TABLE_C = tuple(range(-60, 81, 20))  # °C, rows of the table on each branch
MODELS_C = -40.0  # °C of the friction-model table
#: BearingFriction's friction models, and what each is for Ning's dry MoS2 film.
#: What this scenario's numbers are for each friction model (the models run are the
#: registry's, servofmu.physics.friction.registry).
MODEL_NOTES = {
    "yu2017": "Ning's hysteresis, sliding and inner-race spin (α_r and μ assumed): no fluid, "
    "no viscous term",
    "skf2004": "SKF 2004 with catalogue constants (72 B fallback) and its boundary μbl = 0.15 "
    "for lubricated contacts: a dry film is outside the model (no oil, no rolling term)",
    "ehl_per_contact": "as yu2017: no fluid, so no hydrodynamic rolling torque",
}


def _note(model: str) -> str:
    return MODEL_NOTES.get(model, "not assessed in this scenario")


#: Yu 2017's measured −40 °C torque of the gimbal's 71803 pair [N·mm]: another bearing, for scale.
YU_M40 = 3.17


def run(out_dir, fmu_dir=None, coarse: bool = False) -> ScenarioResult:
    out = Path(out_dir)
    period = 20.0 if coarse else 60.0  # s per cycle
    hold = 1.0  # s at the low temperature first: the speed loop starts from rest
    system = load_system(system_path("space_bearing", fmu_dir))
    try:
        kt = system.components["motor"].parameters["torque_constant"][1]
        # a row holds the outputs computed from the temperature of one step before, so the
        # branches are split one step late and the run ends one step past the cycle
        h = system.step_size
        res = run_system(
            system,
            signals={
                "bearing.temperature": Cycle(
                    celsius_to_kelvin(LOW_C),
                    celsius_to_kelvin(HIGH_C),
                    period,
                    "triangle",
                    start=hold,
                )
            },
            stop=hold + period + h,
            record=[
                "bearing.temperature",
                "motor.speed",
                "motor.current",
                "bearing.running_torque",
                "bearing.preload",
                "bearing.contact_angle",
                "bearing.outer_fit_interference",
                "bearing.inner_fit_interference",
                "bearing.overloaded",
                "bearing.locked",
                "bearing.unloaded",
            ],
            out_dir=out,
        )
        models = _model_table(system, kt)
    finally:
        system.close()
    t = res["time"]
    temp_c = res["bearing.temperature"] - 273.15
    measured = kt * res["motor.current"]
    rows = []
    middle = hold + 0.5 * period + h
    for branch, sel in (("rising", (t >= hold + h) & (t <= middle)), ("falling", t >= middle)):
        order = np.argsort(temp_c[sel])
        x = temp_c[sel][order]

        def at(values, temp, x=x, sel=sel, order=order):
            return float(np.interp(temp, x, values[sel][order]))

        for temp in TABLE_C:
            model = at(res["bearing.running_torque"], temp)
            rows.append(
                {
                    "temperature [degC]": float(temp),
                    "branch": branch,
                    "measured k_t*i [N.mm]": at(measured, temp) / NMM,
                    "model [N.mm]": model / NMM,
                    "difference [%]": 100.0 * (at(measured, temp) / model - 1.0),
                    "preload [N]": at(res["bearing.preload"], temp),
                    "contact angle [deg]": np.degrees(at(res["bearing.contact_angle"], temp)),
                    "outer fit [um]": at(res["bearing.outer_fit_interference"], temp) / UM,
                    "inner fit [um]": at(res["bearing.inner_fit_interference"], temp) / UM,
                    "speed [rpm]": at(res["motor.speed"], temp) * 30.0 / np.pi,
                }
            )
    both = {}
    for r in rows:
        both.setdefault(r["temperature [degC]"], {})[r["branch"]] = r
    gaps = [
        abs(b["rising"]["model [N.mm]"] / b["falling"]["model [N.mm]"] - 1.0)
        for b in both.values()
        if len(b) == 2
    ]
    result = ScenarioResult(
        "thermal_cycle",
        f"Space bearing (Ning), triangle {LOW_C:g} → {HIGH_C:+g} → {LOW_C:g} °C in {period:g} s, "
        "speed loop at 10 rpm",
        list(rows[0]),
        rows,
        summary={
            "largest |difference| [%]": max(abs(r["difference [%]"]) for r in rows),
            "largest rising/falling torque gap [%]": 100.0 * max(gaps) if gaps else float("nan"),
            **{
                f"{flag} anywhere": bool(np.any(res[f"bearing.{flag}"] > 0.5))
                for flag in ("overloaded", "locked", "unloaded")
            },
        },
        files=[res.csv],
        notes=[
            "measured: k_t·i of the DCMotor (includes its viscous damping b·ω and the "
            "acceleration torque of the speed loop); model: BearingFriction running torque. "
            "Rows are interpolated on each branch at the listed temperatures.",
            f"friction models: the system held at {MODELS_C:g} °C, BearingFriction's "
            "friction_model set in it; "
            + "; ".join(f"{m}: {_note(m)}" for m in registry.names())
            + f". Yu 2017's {YU_M40} N·mm is the gimbal's 71803 pair, not this bearing: a "
            "scale, not a reference.",
        ],
        tables=[models],
    )
    result.write_table(out / "thermal_cycle.csv")
    result.write_table(out / "friction_models.csv", models)
    result.files.append(
        res.plot(
            out / "thermal_cycle.png",
            [
                "bearing.temperature",
                "bearing.running_torque",
                "bearing.preload",
                "bearing.outer_fit_interference",
                "bearing.inner_fit_interference",
            ],
            title=result.title,
        )
    )
    return result


def _model_table(system, kt) -> Table:
    """Each friction model with the system held at :data:`MODELS_C`: k_t·i and BearingFriction's
    running and breakaway torque at steady state (2 s each)."""
    stop = 2.0
    rows = []
    for model in registry.names():
        res = run_system(
            system,
            parameters=[{"bearing.friction_model": model}],
            signals={"bearing.temperature": Steps((0.0,), (celsius_to_kelvin(MODELS_C),))},
            stop=stop,
            record=["motor.current", "bearing.running_torque", "bearing.breakaway_torque"],
        )
        t, end = res["time"], stop + 1e-9
        rows.append(
            {
                "friction model": model,
                "k_t*i [N.mm]": kt * plateau_mean(t, res["motor.current"], 0.0, end) / NMM,
                "running [N.mm]": plateau_mean(t, res["bearing.running_torque"], 0.0, end) / NMM,
                "breakaway [N.mm]": plateau_mean(t, res["bearing.breakaway_torque"], 0.0, end)
                / NMM,
                "Yu 2017, gimbal 71803 (scale) [N.mm]": YU_M40,
            }
        )
    return Table(
        f"Friction models at {MODELS_C:g} °C, 10 rpm (Ning's 71807C pair, MoS2 film)",
        list(rows[0]),
        rows,
    )

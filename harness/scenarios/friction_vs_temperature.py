"""Yu 2017's electrical method on the seeker gimbal: in each chamber temperature (−40…+60 °C in
20 K steps) the speed loop holds a constant low speed, forward then reverse; at steady state the
friction torque is read from the motor current as k_t·i and set next to the bearing model's
running torque (the BearingFriction output at that speed).

One run of the seeker_gimbal system with the chamber temperature and the speed reference as
stepped signals, as in a climatic-chamber test. k_t·i also carries the motor's own viscous
damping b·ω (0.0017 N·mm at 10 °/s), which the electrical method cannot separate either.

A further table sets each friction model of BearingFriction (``friction_model``) in the same
system at −40 °C, without and with the grease term of Molykote G-1074 (variant
``grease_g1074``: f0 and ks calibrated on the grease's JIS K 2220 −40 °C datasheet point by
``servofmu calibrate --datasheet``, with its base oil), next to Yu's 3.17 N·mm: every number
from the co-simulation (k_t·i) or from BearingFriction's outputs.
"""

from __future__ import annotations

from pathlib import Path

from servofmu.files import save_figure
from servofmu.physics.friction import registry
from servofmu.physics.kernels.units import DEG, NMM, celsius_to_kelvin

from .. import load_system
from .. import run as run_system
from ..signals import Steps
from .common import ScenarioResult, Table, mechanism_notes, plateau_mean, system_path

TEMPS_C = (-40.0, -20.0, 0.0, 20.0, 40.0, 60.0)  # Yu §3 chamber temperatures
SPEED = 10.0 * DEG  # rad/s, the assumed test speed of the Yu reproduction
#: BearingFriction's flags, each a column of the rows (outside_lubricant_range: the chamber
#: left the range of the lubricant's data: held below a flow limit, else extrapolated)
FLAGS = ("overloaded", "locked", "unloaded", "outside_lubricant_range")
#: The gimbal's mounting variants (ssp/seeker_gimbal/variants: each a catalogue preset bound in
#: full), after the system's own default, the yoke: what the design choice of the frame does.
DEFAULT_LABEL = "yoke (default)"
MOUNTINGS = {
    DEFAULT_LABEL: None,
    "rigid tube (Yu's stated data)": "rigid",
    "rigid, eq 14 as printed": "printed",
    "spring preload": "spring",
}
#: Yu 2017's measured (Fig 9) and computed (Fig 8) total friction torque at −40 °C [N·mm].
YU_M40 = 3.17
#: BearingFriction's friction models and what in each was calibrated (what its −40 °C value is).
#: What this scenario's numbers are for each friction model (the models run are the
#: registry's, servofmu.physics.friction.registry).
MODEL_NOTES = {
    "yu2017": "s0 and μ calibrated on Yu's −40 °C values, in the yoke chosen knowing them: "
    "consistent with Yu, not a prediction",
    "skf2004": "SKF 2004 with catalogue constants (the 72 B series as labelled fallback for the "
    "718 series) and μbl = 0.15: a prediction",
    "ehl_per_contact": "contact EHL rolling (Biboulet & Houpert, literature constants; Krytox "
    "density assumed) + Yu's hysteresis (α_r assumed) and spin (μ calibrated on Yu)",
}


def _note(model: str) -> str:
    return MODEL_NOTES.get(model, "not assessed in this scenario")


#: The variant with the grease term of Molykote G-1074 (ssp/seeker_gimbal/variants).
GREASE_VARIANT = "grease_g1074"


def run(out_dir, fmu_dir=None, coarse: bool = False, mechanism=None) -> ScenarioResult:
    """The scenario on ``mechanism`` (default: the standard one, Yu's gimbal): its
    ``seeker_gimbal`` system. Yu's own figures (his −40 °C torque, the variants of his
    mounting) appear only for Yu's mechanisms."""
    out = Path(out_dir)
    plateau = 1.0 if coarse else 2.0  # s per temperature: forward half, reverse half
    yu = mechanism is None or mechanism.yu
    system = load_system(system_path("seeker_gimbal", fmu_dir, mechanism))
    try:
        kt = system.components["motor"].parameters["torque_constant"][1]
        variants = {k: v for k, v in MOUNTINGS.items() if v is None or v in system.variants}
        runs = {
            label: _electrical_method(system, variant, plateau, out if variant is None else None)
            for label, variant in variants.items()
        }
        grease = GREASE_VARIANT in system.variants
        models = _model_table(system, kt, plateau, yu, grease)
    finally:
        system.close()
    res = runs[DEFAULT_LABEL]
    rows = _rows(res, kt, plateau)
    standard = mechanism is None or mechanism.standard
    what = "the seeker gimbal" if standard else f"mechanism {mechanism.key}"
    result = ScenarioResult(
        "friction_vs_temperature",
        f"Friction torque of {what} by the electrical method (Yu 2017 §3), speed loop at "
        f"±{SPEED / DEG:g} °/s",
        list(rows[0]),
        rows,
        summary={
            "largest |difference| [%]": max(abs(r["difference [%]"]) for r in rows),
            **({} if standard else {"friction coefficients": mechanism.coefficients.kind}),
        },
        files=[res.csv],
        notes=[
            *mechanism_notes(mechanism),
            "measured: k_t·i of the DCMotor at steady state; model: BearingFriction running "
            "torque. The model is symmetric in the direction; Yu's measured forward/reverse "
            "difference (grease redistribution) is not modelled.",
        ],
        tables=[models],
    )
    if len(runs) > 1:
        result.tables.insert(0, _mounting_table(runs, kt, plateau, yu))
        result.notes.append(
            f"mountings: the same run with each variant of the system; Yu's {YU_M40} N·mm "
            "at −40 °C is his measurement (Fig 9) and his model's total (Fig 8). The default "
            "yoke's arm section was chosen knowing it (s0 and μ are calibrated in it): its "
            "−40 °C value is consistent with Yu, not a prediction; the other mountings use the "
            "same coefficients."
        )
    result.notes.append(_models_note(yu, grease, mechanism))
    result.write_table(out / "friction_vs_temperature.csv")
    mountings = result.tables[0] if len(runs) > 1 else None
    if mountings is not None:
        result.write_table(out / "mountings.csv", mountings)
    result.write_table(out / "friction_models.csv", models)
    kind = "" if mechanism is None else mechanism.coefficients.kind
    png = _plot(rows, mountings, models, out / "friction_vs_temperature.png", what, yu, kind)
    result.files.append(png)
    return result


def _models_note(yu: bool, grease: bool, mechanism) -> str:
    """What the friction-model table is, and what in each model was calibrated."""
    where = "the default yoke" if yu else "the mechanism"
    text = (
        f"friction models: {where} at −40 °C and +10 °/s, BearingFriction's friction_model set "
        "in the system"
    )
    if grease:
        text += (
            f", without and with the grease term of Molykote G-1074 (variant {GREASE_VARIANT}: "
            "f0 and ks calibrated on its JIS K 2220 −40 °C datasheet point on a full 6204, "
            "carried to the bearing by Palmgren's dm³ and the base oil's ν(T); as if the "
            "bearing were packed full of it)"
        )
    if yu:
        return text + ". Calibrated: " + "; ".join(f"{m}: {_note(m)}" for m in registry.names())
    coefficients = mechanism.coefficients.label if mechanism is not None else ""
    return text + (
        f". yu2017 and the hysteresis and spin of ehl_per_contact take the mechanism's "
        f"coefficients ({coefficients}); skf2004 and the EHL rolling torque take literature "
        "constants (SKF's series constants, or the labelled fallback; μbl 0.15): predictions, "
        "not calibrations."
    )


def _electrical_method(system, variant, plateau, out):
    """One run of the system (``variant`` of ssp/seeker_gimbal/variants, or its default):
    the chamber temperature stepped through :data:`TEMPS_C`, ±10 °/s at each."""
    starts = [i * plateau for i in range(len(TEMPS_C))]
    temperature = Steps(tuple(starts), tuple(celsius_to_kelvin(t) for t in TEMPS_C))
    ref_times = tuple(t for s in starts for t in (s, s + plateau / 2))
    reference = Steps(ref_times, tuple(d * SPEED for _ in starts for d in (1.0, -1.0)))
    return run_system(
        system,
        parameters=[] if variant is None else [variant],
        signals={"bearing.temperature": temperature, "controller.reference": reference},
        stop=len(TEMPS_C) * plateau,
        record=[
            "motor.current",
            "motor.speed",
            "bearing.running_torque",
            "bearing.preload",
            *(f"bearing.{flag}" for flag in FLAGS),
            "bearing.temperature",
        ],
        out_dir=out,
    )


_MODEL_OUTPUTS = ("running_torque", "breakaway_torque", "viscous_torque", "grease_torque")


def _model_table(system, kt, plateau, yu: bool = True, with_grease: bool = True) -> Table:
    """Each friction model at −40 °C, forward at +10 °/s, without and (when the system has
    the variant) with the grease term: k_t·i and BearingFriction's running, breakaway,
    viscous and grease torques at steady state (one run of half a plateau each); Yu's −40 °C
    torque beside them for Yu's gimbal."""
    cold = celsius_to_kelvin(TEMPS_C[0])
    rows = []
    for grease in (False, True) if with_grease else (False,):
        for model in registry.names():
            variant = [GREASE_VARIANT] if grease else []
            res = run_system(
                system,
                parameters=[*variant, {"bearing.friction_model": model}],
                signals={
                    "bearing.temperature": Steps((0.0,), (cold,)),
                    "controller.reference": Steps((0.0,), (SPEED,)),
                },
                stop=plateau / 2,
                record=["motor.current", *(f"bearing.{n}" for n in _MODEL_OUTPUTS)],
            )
            t, end = res["time"], plateau / 2 + 1e-9

            def mean(name, res=res, t=t, end=end):
                return plateau_mean(t, res[name], 0.0, end) / NMM

            rows.append(
                {
                    "friction model": model,
                    "grease term": "G-1074 (calibrated)" if grease else "none",
                    "k_t*i [N.mm]": kt * mean("motor.current"),
                    "running [N.mm]": mean("bearing.running_torque"),
                    "breakaway [N.mm]": mean("bearing.breakaway_torque"),
                    "viscous/rolling [N.mm]": mean("bearing.viscous_torque"),
                    "grease [N.mm]": mean("bearing.grease_torque"),
                    **({"Yu 2017 [N.mm]": YU_M40} if yu else {}),
                }
            )
    title = f"Friction models at {TEMPS_C[0]:g} °C (+{SPEED / DEG:g} °/s)"
    if yu:
        title = (
            f"Friction models at {TEMPS_C[0]:g} °C (default yoke, +{SPEED / DEG:g} °/s) next to "
            f"Yu 2017's {YU_M40} N·mm"
        )
    if with_grease:
        title += "; grease term: Molykote G-1074 calibrated on its datasheet"
    return Table(title, list(rows[0]), rows)


def _plateaus(plateau):
    """(temperature [°C], direction, start, end [s]) of every plateau half."""
    for i, temp in enumerate(TEMPS_C):
        s = i * plateau
        yield temp, "forward", s, s + plateau / 2
        yield temp, "reverse", s + plateau / 2, s + plateau


def _rows(res, kt, plateau) -> list[dict]:
    t = res["time"]
    rows = []
    for temp, direction, a, b in _plateaus(plateau):
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
                    for flag in FLAGS
                },
            }
        )
    return rows


def _mounting_table(runs, kt, plateau, yu: bool = True) -> Table:
    """Torque (k_t·i, forward), preload and state of every mounting at every temperature."""
    rows = []
    for label, res in runs.items():
        for r in _rows(res, kt, plateau):
            if r["direction"] != "forward":
                continue
            state = [flag for flag in FLAGS if r[flag]]
            rows.append(
                {
                    "mounting": label,
                    "temperature [degC]": r["temperature [degC]"],
                    "k_t*i [N.mm]": r["measured k_t*i [N.mm]"],
                    "preload [N]": r["preload [N]"],
                    "state": "+".join(state) or "preloaded",
                    **(
                        {"Yu 2017 [N.mm]": YU_M40 if r["temperature [degC]"] == -40.0 else ""}
                        if yu
                        else {}
                    ),
                }
            )
    return Table(
        f"Mounting variants side by side (forward, ±{SPEED / DEG:g} °/s): torque, preload, "
        "overload, looseness and the lubricant's range",
        list(rows[0]),
        rows,
    )


def _plot(rows, mountings: Table | None, models: Table, path: Path, what: str = "",
          yu: bool = True, coefficients: str = "") -> Path:  # fmt: skip
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(9.6, 4.6), dpi=110)
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
        label="bearing model (yoke, default)" if mountings is not None else "bearing model",
    )
    labels = list(dict.fromkeys(r["mounting"] for r in mountings.rows)) if mountings else []
    for label, style in zip(labels[1:], (":", "-.", "--"), strict=False):
        sel = [r for r in mountings.rows if r["mounting"] == label]
        ax.semilogy(
            [r["temperature [degC]"] for r in sel],
            [r["k_t*i [N.mm]"] for r in sel],
            style,
            lw=1.2,
            label=f"k_t·i, {label}",
        )
    if yu:
        ax.plot([-40.0], [YU_M40], "r*", ms=10, label=f"Yu 2017: {YU_M40} N·mm at −40 °C")
    for r, marker in zip(models.rows, ("x", "+", "1", "x", "+", "1"), strict=False):
        if r["friction model"] == "yu2017" and r["grease term"] == "none":
            continue  # the default model: the black line
        grease = ", G-1074 grease" if r["grease term"] != "none" else ""
        ax.plot(
            [-40.0], [r["k_t*i [N.mm]"]], marker, ms=9, mew=1.5,
            label=f"k_t·i, {r['friction model']}{grease}" + (" (yoke)" if mountings else ""),
        )  # fmt: skip
    from matplotlib.ticker import FormatStrFormatter, FuncFormatter

    ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))  # 0.1, 1, 10 [N·mm]
    ax.yaxis.set_minor_formatter(  # 2, 3, 5 × a decade: readable, no powers of ten
        FuncFormatter(lambda v, _: f"{v:g}" if f"{v:.0e}"[0] in "235" else "")
    )
    ax.tick_params(axis="y", which="minor", labelsize=7)
    ax.set_xlabel("chamber temperature [°C]")
    ax.set_ylabel("friction torque [N·mm]")
    ax.set_title(
        (
            "Seeker gimbal: electrical method in the co-simulation, four mountings; friction "
            "models at −40 °C"
        )
        if mountings is not None
        else f"{what[0].upper()}{what[1:]}: electrical method in the co-simulation; friction "
        f"models at −40 °C\n(friction coefficients: {coefficients})",
        fontsize=10,
    )
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    fig.tight_layout()
    save_figure(fig, path)
    plt.close(fig)
    return path

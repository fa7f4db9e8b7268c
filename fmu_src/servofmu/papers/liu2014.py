"""Reproduction of Liu Yuan, Wang Yongle, Cao Donghai, Liu Tao (2014): "A stiffness calculation
method of servo mechanism", Navigation Positioning and Timing 2014(2):46–49.

The paper's figures (ratio and compliance shares versus output angle) lost their numbers;
Table 1 survives: component stiffnesses at +10° for 100/200/300 N·m, the series theory and
the measurement. Rows:

- the series total of Table 1 from its own component values (eq 6) — arithmetic check;
- the screw force F3 and the linkage stiffness K_rod: the unknown linkage dimensions are
  calibrated on the 100 N·m column (crank length on F3, output-arm length on K_rod); 200 and
  300 N·m are predictions. Eq 9–20 are linear in the load, so the model's K_rod cannot rise
  with load as Table 1's does;
- the theory total with the model's elements;
- this project's extension: the support-bearing pair (Hertzian, from the bearing core) in
  series; its one unknown (the seat stiffness in series with the bearings) is calibrated on
  the measured 100 N·m; the measured 200 and 300 N·m are predictions.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
from scipy.optimize import brentq

from ..physics import catalog
from ..physics.actuator import (
    Actuator,
    per_degree,
    reduction_ratio,
    screw_force,
    series_stiffness,
    stiffness_breakdown,
    support_axial_stiffness,
)
from ..physics.units import DEG, MM, celsius_to_kelvin
from .common import bearing_parameters, material_parameters, mounting_parameters
from .report import Parameter, Report, calibrated, compare, plot, trend, write_csv

TITLE = "Liu, Wang, Cao, Liu (2014) A stiffness calculation method of servo mechanism"
KEY = "liu2014_ema"
TEST_ANGLE = 10.0 * DEG  # Liu §3
LOADS = np.array([100.0, 200.0, 300.0])  # N·m, Table 1
TABLE1 = {  # Liu Table 1, N·m/° (forces in N)
    "F3": np.array([1957.9, 3915.7, 5873.6]),
    "gear": np.array([1096623.0, 1096628.0, 1096632.0]),
    "screw": np.array([8256825.0, 8256837.0, 8256846.0]),
    "housing": np.array([1696.8, 1696.8, 1696.8]),
    "rod": np.array([1021.5, 1048.44, 1082.99]),
    "theory": np.array([637.65, 648.03, 661.06]),
    "measured": np.array([434.25, 467.96, 482.42]),
}
ANGLES = np.linspace(-30.0, 30.0, 121) * DEG  # Fig 2–4 range
T_ROOM = celsius_to_kelvin(20.0)


def calibrate_crank_length() -> float:
    """L1 [m] that gives Table 1's F3 = 1957.9 N at 100 N·m and +10° (other dimensions as
    catalogued); F3 falls as the crank grows."""
    return brentq(
        lambda l1: (
            float(screw_force(catalog.actuator(KEY, crank_length=l1), TEST_ANGLE, 100.0))
            - TABLE1["F3"][0]
        ),
        0.02,
        0.12,
        xtol=1e-12,
    )


def calibrate_arm_length(crank_length: float) -> float:
    """Output-arm length l [m] that gives K_rod = 1021.5 N·m/° at 100 N·m (eq 17–19 make the
    arm softer as it grows)."""
    from ..physics.actuator import linkage_stiffness

    def gap(arm):
        act = catalog.actuator(KEY, crank_length=crank_length, arm_length=arm)
        return float(per_degree(linkage_stiffness(act, TEST_ANGLE, 100.0))) - TABLE1["rod"][0]

    return brentq(gap, 1e-4, 1.0, xtol=1e-12)


def calibrate_seat_stiffness(crank_length: float, arm_length: float) -> float:
    """Seat stiffness [N/m] in series with the support bearings that gives the measured
    434.25 N·m/° at 100 N·m; raises ValueError when the bearings alone are already softer."""
    base = dict(crank_length=crank_length, arm_length=arm_length)

    def gap(log_k):
        act = catalog.actuator(KEY, **base, seat_stiffness=10.0**log_k)
        k = stiffness_breakdown(act, TEST_ANGLE, 100.0, T_ROOM).total
        return float(per_degree(k)) - TABLE1["measured"][0]

    if gap(15.0) < 0:
        raise ValueError("the support bearings alone are softer than Liu's measurement")
    return 10.0 ** brentq(gap, 5.0, 15.0, xtol=1e-13)


def calibrated_actuator() -> tuple[Actuator, dict]:
    """The actuator with its three calibrated values fitted by code (as
    ``data/actuators.toml`` should hold them)."""
    l1 = calibrate_crank_length()
    arm = calibrate_arm_length(l1)
    seat = calibrate_seat_stiffness(l1, arm)
    act = catalog.actuator(KEY, crank_length=l1, arm_length=arm, seat_stiffness=seat)
    return act, {"crank_length": l1, "arm_length": arm, "seat_stiffness": seat}


def reproduce(out_dir) -> Report:
    """Compute every row, write CSV/PNG to ``out_dir``, return the :class:`Report`."""
    out = Path(out_dir)
    rep = Report(paper="liu2014", title=TITLE)
    act, fit = calibrated_actuator()
    liu_only = dataclasses.replace(act, support_mounting="")  # Liu's four elements only

    # --- Table 1: series total of the listed components (eq 6) -------------------------
    for i, m in enumerate(LOADS):
        total = float(
            series_stiffness(
                TABLE1["gear"][i], TABLE1["screw"][i], TABLE1["housing"][i], TABLE1["rod"][i]
            )
        )
        rep.rows.append(
            compare(
                f"table1.series.{m:.0f}",
                f"eq 6 series total of Table 1's listed components at {m:.0f} N·m",
                float(TABLE1["theory"][i]),
                total,
                "N·m/°",
                rel=0.005,
                note="arithmetic check of the paper's own column",
            )
        )

    # --- Table 1: F3, K_rod, theory total with the model's linkage ---------------------
    f3 = screw_force(act, TEST_ANGLE, LOADS)
    br = stiffness_breakdown(liu_only, TEST_ANGLE, LOADS, T_ROOM)
    k_rod = per_degree(br.linkage)
    k_theory = per_degree(br.total)
    for i, m in enumerate(LOADS):
        if i == 0:
            rep.rows.append(
                calibrated(
                    "table1.F3.100",
                    "screw force F3 at 100 N·m",
                    float(TABLE1["F3"][0]),
                    float(f3[0]),
                    "N",
                    f"crank length L1 = {fit['crank_length'] / MM:.3f} mm",
                )
            )
            rep.rows.append(
                calibrated(
                    "table1.K_rod.100",
                    "linkage stiffness K_rod at 100 N·m",
                    float(TABLE1["rod"][0]),
                    float(k_rod[0]),
                    "N·m/°",
                    f"output-arm length l = {fit['arm_length'] / MM:.2f} mm",
                )
            )
        else:
            rep.rows.append(
                compare(
                    f"table1.F3.{m:.0f}",
                    f"screw force F3 at {m:.0f} N·m",
                    float(TABLE1["F3"][i]),
                    float(f3[i]),
                    "N",
                    rel=0.001,
                    note="eq 10–11 are linear in M",
                )
            )
            rep.rows.append(
                compare(
                    f"table1.K_rod.{m:.0f}",
                    f"linkage stiffness K_rod at {m:.0f} N·m",
                    float(TABLE1["rod"][i]),
                    float(k_rod[i]),
                    "N·m/°",
                    rel=0.01,
                    miss_note=(
                        "every term of eq 9–20 is linear in the load (the closure of eq 14–16 "
                        "and the arctan of eq 19 to within "
                        f"{abs(k_rod[i] / k_rod[0] - 1):.1e}), so K_rod is constant; the "
                        "paper's rise of 2.6 % and 6.0 % needs a load-stiffening element"
                    ),
                )
            )
        rep.rows.append(
            compare(
                f"table1.theory.{m:.0f}",
                f"theory total stiffness at {m:.0f} N·m (model's K_rod, Table 1's others)",
                float(TABLE1["theory"][i]),
                float(k_theory[i]),
                "N·m/°",
                rel=0.005,
                miss_note="differs where the model's constant K_rod differs from Table 1's",
            )
        )

    # --- extension: support bearings in series -----------------------------------------
    full = stiffness_breakdown(act, TEST_ANGLE, LOADS, T_ROOM)
    k_meas = per_degree(full.total)
    for i, m in enumerate(LOADS):
        if i == 0:
            rep.rows.append(
                calibrated(
                    "extension.measured.100",
                    "measured stiffness at 100 N·m, with the support-bearing element",
                    float(TABLE1["measured"][0]),
                    float(k_meas[0]),
                    "N·m/°",
                    f"seat stiffness {fit['seat_stiffness']:.4g} N/m in series with the "
                    "71807C pair",
                    note="this project's extension of Liu's model. " + _extension_note(act),
                )
            )
        else:
            rep.rows.append(
                compare(
                    f"extension.measured.{m:.0f}",
                    f"measured stiffness at {m:.0f} N·m, with the support-bearing element",
                    float(TABLE1["measured"][i]),
                    float(k_meas[i]),
                    "N·m/°",
                    rel=0.05,
                    note=(
                        "this project's extension: a prediction from the Hertzian pair "
                        f"({100 * (k_meas[i] / TABLE1['measured'][i] - 1):+.1f} %)"
                    ),
                    miss_note="the calibrated seat compliance does not stiffen with load",
                )
            )
    # --- Fig 2–4 and curves ------------------------------------------------------------
    ratios = reduction_ratio(act, ANGLES)
    ang = stiffness_breakdown(liu_only, ANGLES, 100.0, T_ROOM)
    write_csv(
        out / "fig2_reduction_ratio.csv",
        {
            "output_angle [deg]": ANGLES / DEG,
            "total_ratio [-]": ratios.total,
            "linkage_ratio [-]": ratios.linkage,
            "screw_ratio [-]": np.full_like(ANGLES, ratios.screw),
        },
    )
    plot(
        out / "fig2_reduction_ratio.png",
        ANGLES / DEG,
        {"total i = i_g·i_s·i_r": ratios.total},
        "output angle [°]",
        "reduction ratio [-]",
        "Liu Fig 2: total reduction ratio (i_g, p, L2 assumed)",
    )
    shares = {e: ang.share(e) for e in ("gear", "screw", "linkage", "housing")}
    write_csv(
        out / "compliance_shares.csv",
        {"output_angle [deg]": ANGLES / DEG, **{f"{e}_share [-]": v for e, v in shares.items()}},
    )
    for fig, element, title in (
        ("fig3_gear_share", "gear", "Liu Fig 3: gear-train share of the compliance at 100 N·m"),
        ("fig4_screw_share", "screw", "Liu Fig 4: ball-screw share of the compliance at 100 N·m"),
    ):
        write_csv(
            out / f"{fig}.csv",
            {"output_angle [deg]": ANGLES / DEG, f"{element}_share [-]": shares[element]},
        )
        plot(
            out / f"{fig}.png",
            ANGLES / DEG,
            {element: shares[element]},
            "output angle [°]",
            "share of the total compliance [-]",
            title,
        )
    plot(
        out / "compliance_shares.png",
        ANGLES / DEG,
        shares,
        "output angle [°]",
        "share of the total compliance [-]",
        "Compliance shares of Liu's four elements at 100 N·m",
        decorate=lambda ax: ax.set_yscale("log"),
    )
    i10 = int(np.argmin(np.abs(ANGLES - TEST_ANGLE)))
    g_share = float(shares["gear"][i10])
    rep.rows.append(
        trend(
            "fig3.gear_share",
            "gear-train share of the compliance",
            "of order 1e-4, negligible",
            bool(1e-5 <= shares["gear"].max() < 1e-3),
            f"{g_share:.2e} at +10°, {shares['gear'].min():.2e}…{shares['gear'].max():.2e} "
            "over ±30°",
        )
    )
    rep.rows.append(
        trend(
            "fig4.screw_share",
            "ball-screw share of the compliance",
            "much smaller than housing and linkage: not the weak link",
            bool(np.all(shares["screw"] < 0.01 * np.minimum(shares["housing"], shares["linkage"]))),
            f"{float(shares['screw'][i10]):.2e} at +10° against housing "
            f"{float(shares['housing'][i10]):.2f} and linkage {float(shares['linkage'][i10]):.2f}",
        )
    )
    rep.rows.append(
        trend(
            "fig2.varies",
            "reduction ratio over ±30°",
            "not constant; follows the crank's sinusoid",
            bool(
                np.ptp(ratios.total) > 0.05 * ratios.total.max() and np.argmax(ratios.total) == 60
            ),
            f"{ratios.total.min():.1f}…{ratios.total.max():.1f}, largest at 0°",
            note="shape from the assumed neutral geometry (crank square to the rod at 0°)",
        )
    )
    loads = np.linspace(10.0, 300.0, 59)
    by_load = stiffness_breakdown(act, TEST_ANGLE, loads, T_ROOM)
    write_csv(
        out / "stiffness_vs_load.csv",
        {
            "load_torque [N.m]": loads,
            "total [N.m/deg]": per_degree(by_load.total),
            "support_bearing [N.m/deg]": per_degree(by_load.support_bearing),
            "linkage [N.m/deg]": per_degree(by_load.linkage),
            "screw_force [N]": by_load.screw_force,
        },
    )
    plot(
        out / "stiffness_vs_load.png",
        loads,
        {
            "model with support bearings": per_degree(by_load.total),
            "model without (Liu's elements)": per_degree(
                stiffness_breakdown(liu_only, TEST_ANGLE, loads, T_ROOM).total
            ),
        },
        "hinge moment [N·m]",
        "stiffness at the output [N·m/°]",
        "Liu Table 1: stiffness versus load at +10°",
        decorate=lambda ax: (
            ax.plot(LOADS, TABLE1["measured"], "ko", label="Liu measured"),
            ax.plot(LOADS, TABLE1["theory"], "ks", mfc="none", label="Liu theory"),
        ),
    )
    temps_c = np.linspace(-40.0, 60.0, 51)
    cols = {"temperature [degC]": temps_c}
    series = {}
    for m in LOADS:
        k = per_degree(stiffness_breakdown(act, TEST_ANGLE, m, celsius_to_kelvin(temps_c)).total)
        cols[f"total_{m:.0f}Nm [N.m/deg]"] = k
        series[f"{m:.0f} N·m"] = k
    write_csv(out / "stiffness_vs_temperature.csv", cols)
    plot(
        out / "stiffness_vs_temperature.png",
        temps_c,
        series,
        "temperature [°C]",
        "stiffness at the output [N·m/°]",
        "Actuator stiffness versus temperature (support-bearing preload, +10°)",
    )
    rep.parameters = parameters(act, fit)
    rep.files = sorted(str(p) for p in out.glob("*") if p.suffix in (".csv", ".png"))
    return rep


def _extension_note(act: Actuator) -> str:
    """What the support-bearing element can and cannot explain (numbers for the note)."""
    from ..physics.bearing import BearingModel

    missing = 1.0 / (1.0 / TABLE1["measured"] - 1.0 / TABLE1["theory"])
    alone = _bearing_only(act, LOADS)
    pair = BearingModel(_support_pair_of(act))
    p300 = pair.evaluate(T_ROOM, 0.0, float(screw_force(act, TEST_ANGLE, 300.0)))
    return (
        "The gap between Liu's theory and measurement is an element of "
        + "/".join(f"{x:.0f}" for x in missing)
        + " N·m/° at 100/200/300 N·m; the 71807C pair alone gives "
        + "/".join(f"{x:.0f}" for x in alone)
        + " N·m/°, stiffer than the gap at every load, so a linear seat compliance is "
        f"fitted in series and the pair supplies the load stiffening. At 300 N·m its contact "
        f"pressure reaches {p300.max_contact_pressure / 1e6:.0f} MPa"
        + (
            " (above 4200 MPa: overloaded, permanent deformation; the pair is undersized)"
            if p300.overloaded
            else ""
        )
    )


def _support_pair_of(act: Actuator):
    from ..physics.bearing import BearingPair

    return BearingPair.from_catalog(act.support_mounting, "mos2_film")


def _bearing_only(act: Actuator, loads) -> np.ndarray:
    """Reflected stiffness of the support pair without the seat [N·m/°]."""
    rigid = dataclasses.replace(act, seat_stiffness=np.inf)
    f3 = screw_force(rigid, TEST_ANGLE, loads)
    lever = float(screw_force(rigid, TEST_ANGLE, 1.0)) ** -1
    return per_degree(lever**2 * support_axial_stiffness(rigid, f3, T_ROOM))


def parameters(act: Actuator, fit: dict) -> list[Parameter]:
    """Every parameter of the reproduction with its provenance."""
    ps = [Parameter("actuator", act.key, "", act.name)]
    units = {
        "gear_ratio": ("", 1.0),
        "screw_lead": ("mm", MM),
        "crank_length": ("mm", MM),
        "rod_length": ("mm", MM),
        "neutral_crank_angle": ("deg", DEG),
        "neutral_rod_angle": ("deg", DEG),
        "crank_area": ("mm2", MM**2),
        "rod_area": ("mm2", MM**2),
        "arm_length": ("mm", MM),
        "shaft_polar_moment": ("mm4", MM**4),
        "arm_second_moment": ("mm4", MM**4),
        "youngs_modulus": ("GPa", 1e9),
        "shear_modulus": ("GPa", 1e9),
        "gear_stiffness": ("N.m/rad", 1.0),
        "screw_stiffness": ("N/m", 1.0),
        "housing_stiffness": ("N/m", 1.0),
        "seat_stiffness": ("N/m", 1.0),
    }
    for name, (unit, scale) in units.items():
        src = act.source(name)
        if name in fit:
            src = f"calibrated by code: {fit[name] / scale:.6g} {unit} (data/actuators.toml)"
        ps.append(Parameter(name, getattr(act, name) / scale, unit, src))
    ps.append(
        Parameter("slide_offset Y1", act.slide_offset / MM, "mm", "derived: eq 9 at the neutral")
    )
    bp = _support_pair_of(act)
    ps += bearing_parameters(bp) + material_parameters(bp) + mounting_parameters(bp)
    return ps

"""What a calibration gives the engineer: a text report, the residual table (CSV), a plot of
data and fitted model, and the fitted parameter set as an SSP ``.ssv`` file for the
BearingFriction FMU and the systems."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..parameter_sets import write_ssv
from ..physics.units import DEG, NMM, ZERO_CELSIUS
from .fit import UNKNOWNS, Calibration, running_torque

__all__ = ["plot", "to_text", "write_residuals", "write_ssv"]


def _configuration(p) -> str:
    """The fixed set in a line: bearing, arrangement and preload, lubrication."""
    mm = 1e3
    lube = p["lubrication"]
    if lube == "grease":
        lube += f" (ν40 = {p['lubricant_viscosity_40'] * 1e6:.4g} cSt)"
    return (
        f"bearing {p['bore'] * mm:g}×{p['outer_diameter'] * mm:g}×{p['width'] * mm:g} mm, "
        f"{p['n_balls']} balls of {p['ball_diameter'] * mm:.4g} mm, "
        f"α0 = {np.degrees(p['nominal_contact_angle']):.4g}°; {p['arrangement']}, preload by "
        f"{p['preload_method']}; {lube}"
    )


def to_text(cal: Calibration) -> str:
    """The calibration report: data, fixed configuration, estimates with standard errors,
    correlations, residuals and warnings."""
    d = cal.data
    speeds = np.unique(np.round(cal.speed / DEG, 9))
    lines = [
        f"Calibration of {', '.join(cal.unknowns)} on {d.source}: {len(d)} points, "
        f"{(d.temperature.min() - ZERO_CELSIUS):g}…{(d.temperature.max() - ZERO_CELSIUS):g} °C, "
        f"speed {', '.join(f'{s:g}' for s in speeds)} °/s"
        + (" (assumed: no speed column)" if cal.speed_assumed else ""),
        "",
        "configuration (fixed): " + _configuration(cal.parameters),
        "",
        f"{'unknown':18s} {'estimate':>12s} {'std error':>11s} {'rel':>7s} {'start':>11s}  bounds",
    ]
    for name, est, se, x0 in zip(
        cal.unknowns, cal.estimate, cal.standard_error, cal.initial, strict=True
    ):
        u = UNKNOWNS[name]
        rel = f"{100 * se / abs(est):6.1f}%" if est else "    – "
        lines.append(
            f"{name:18s} {est:12.5g} {se:11.3g} {rel:>7s} {x0:11.4g}  [{u.lower:g}, {u.upper:g}]"
        )
    if len(cal.unknowns) > 1:
        lines += ["", "correlations:"]
        width = max(len(n) for n in cal.unknowns)
        for name, row in zip(cal.unknowns, cal.correlation, strict=True):
            lines.append(f"  {name:{width}s} " + " ".join(f"{r:+8.4f}" for r in row))
    unit = "%" if cal.residual_kind == "relative" else "N.mm"
    scale = 100.0 if cal.residual_kind == "relative" else 1.0 / NMM
    lines += [
        "",
        f"residuals ({cal.residual_kind}): rms {scale * cal.rms:.3g} {unit}, "
        f"{cal.dof} degrees of freedom; optimizer: {cal.optimizer} ({cal.evaluations} "
        "evaluations)",
        f"{'line':>5s} {'T [degC]':>9s} {'speed [deg/s]':>13s} {'direction':>9s} "
        f"{'measured [N.mm]':>15s} {'model [N.mm]':>12s} {'residual [' + unit + ']':>14s}",
    ]
    for i, line in enumerate(d.lines):
        lines.append(
            f"{line:5d} {d.temperature[i] - ZERO_CELSIUS:9.4g} {cal.speed[i] / DEG:13.4g} "
            f"{d.direction[i]:>9s} {d.torque[i] / NMM:15.4g} {cal.model[i] / NMM:12.4g} "
            f"{scale * cal.residuals[i]:14.3g}"
        )
    directions = {x for x in d.direction if x}
    if len(directions) == 2:
        for x in sorted(directions):
            sel = np.array([di == x for di in d.direction])
            lines.append(
                f"mean residual, {x}: {scale * cal.residuals[sel].mean():+.3g} {unit} "
                "(the model has no direction dependence)"
            )
    if d.ignored_columns:
        lines.append(f"columns not read: {list(d.ignored_columns)}")
    lines += [""] + ([f"WARNING: {w}" for w in cal.warnings] or ["no identifiability warnings"])
    return "\n".join(lines)


def write_residuals(cal: Calibration, path) -> Path:
    """Per-point table: line, temperature [°C], speed [°/s], direction, measured and model
    torque [N·mm], residual."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    d = cal.data
    with path.open("w") as fh:
        fh.write(
            "line,temperature [degC],speed [deg/s],direction,measured [N.mm],model [N.mm],"
            f"residual ({cal.residual_kind})\n"
        )
        for i, line in enumerate(d.lines):
            fh.write(
                f"{line},{d.temperature[i] - ZERO_CELSIUS:.6g},{cal.speed[i] / DEG:.6g},"
                f"{d.direction[i]},{d.torque[i] / NMM:.6g},{cal.model[i] / NMM:.6g},"
                f"{cal.residuals[i]:.6g}\n"
            )
    return path


def plot(cal: Calibration, path) -> Path:
    """Measured torque (forward ○, reverse □) and the fitted model versus temperature at each
    measured speed, with the residuals below."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    d = cal.data
    t_c = d.temperature - ZERO_CELSIUS
    fig, (ax, axr) = plt.subplots(
        2, 1, sharex=True, figsize=(6.8, 5.6), gridspec_kw={"height_ratios": [3, 1.3]}
    )
    grid = np.linspace(d.temperature.min(), d.temperature.max(), 121)
    for k, w in enumerate(np.unique(cal.speed)):
        model = running_torque(cal.parameters, grid, np.full_like(grid, w))
        ax.semilogy(grid - ZERO_CELSIUS, model / NMM, "-", color=f"C{k}", lw=1.2)
        sel = cal.speed == w
        for direction, marker in (("forward", "o"), ("reverse", "s"), ("", "^")):
            pick = sel & np.array([x == direction for x in d.direction])
            if pick.any():
                ax.semilogy(
                    t_c[pick],
                    d.torque[pick] / NMM,
                    marker,
                    color=f"C{k}",
                    mfc="none",
                    label=f"{w / DEG:g} °/s {direction or 'measured'}",
                )
    ax.plot([], [], "k-", label="fitted model")
    ax.set_ylabel("friction torque [N·mm]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fit = ", ".join(
        f"{n} = {e:.4g} ± {s:.2g}"
        for n, e, s in zip(cal.unknowns, cal.estimate, cal.standard_error, strict=True)
    )
    ax.set_title(f"{d.source}\n{fit}", fontsize=9)
    from matplotlib.ticker import FormatStrFormatter

    ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
    ax.yaxis.set_minor_formatter(FormatStrFormatter("%g"))
    ax.tick_params(axis="y", which="minor", labelsize=7)
    scale, unit = (100.0, "%") if cal.residual_kind == "relative" else (1.0 / NMM, "N·mm")
    axr.axhline(0.0, color="k", lw=0.8)
    axr.plot(t_c, scale * cal.residuals, "o", mfc="none", color="C3")
    axr.set_ylabel(f"residual [{unit}]")
    axr.set_xlabel("temperature [°C]")
    axr.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path

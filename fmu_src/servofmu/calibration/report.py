"""What a calibration gives the engineer: a text report, the residual table (CSV), a plot of
data and fitted model, and the fitted parameter set as an SSP ``.ssv`` file for the
BearingFriction FMU and the systems."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from servofmu.files import save_figure, write_text, written

from ..parameter_sets import write_ssv
from ..physics.kernels.units import DEG, NMM, ZERO_CELSIUS
from .fit import UNKNOWNS, Calibration, running_torque

#: Plot markers of the measured points per direction.
MARKERS = (("forward", "o"), ("reverse", "s"), ("", "^"))

__all__ = ["plot", "to_text", "write_coefficients", "write_residuals", "write_ssv"]


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
    """The calibration report: a poor fit's problems first, then data, fixed configuration,
    estimates with standard errors, correlations, the fit against the data's scatter, the
    residual of every group of points (one temperature, speed and direction) and warnings."""
    d = cal.data
    speeds = np.unique(np.round(cal.speed / DEG, 9))
    lines = []
    if cal.poor:
        lines += [
            "POOR FIT: this is not a calibration, and its values must not be used as one",
            *(f"  - {p}" for p in cal.problems),
            "",
        ]
    lines += [
        f"Calibration of {', '.join(cal.unknowns)} on {d.source}: {len(d)} points at "
        f"{cal.operating_points} operating points, "
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
    ]
    if cal.scatter is not None:
        p_text = (
            "" if cal.lack_of_fit_p is None else f"; lack-of-fit F test p = {cal.lack_of_fit_p:.3g}"
        )
        lines.append(
            f"scatter of repeated points {scale * cal.scatter:.3g} {unit}; model against the "
            f"measured means: rms {scale * cal.deviation:.3g} {unit}{p_text}"
        )
    lines.append(
        f"{'line':>5s} {'points':>6s} {'T [degC]':>9s} {'speed [deg/s]':>13s} {'direction':>9s} "
        f"{'measured [N.mm]':>15s} {'sd [N.mm]':>9s} {'model [N.mm]':>12s} "
        f"{'residual [' + unit + ']':>14s}"
    )
    sd = d.torque_sd
    for i, line in enumerate(d.lines):
        spread = f"{sd[i] / NMM:9.3g}" if d.count[i] > 1 else f"{'–':>9s}"
        lines.append(
            f"{line:5d} {d.count[i]:6d} {d.temperature[i] - ZERO_CELSIUS:9.4g} "
            f"{cal.speed[i] / DEG:13.4g} {d.direction[i]:>9s} {d.torque[i] / NMM:15.4g} "
            f"{spread} {cal.model[i] / NMM:12.4g} {scale * cal.residuals[i]:14.3g}"
        )
    directions = {x for x in d.direction if x}
    if len(directions) == 2:
        for x in sorted(directions):
            sel = np.array([di == x for di in d.direction])
            mean = np.average(cal.residuals[sel], weights=d.count[sel])
            lines.append(
                f"mean residual, {x}: {scale * mean:+.3g} {unit} "
                "(the model has no direction dependence)"
            )
    if d.ignored_columns:
        lines.append(f"columns not read: {list(d.ignored_columns)}")
    lines += [""] + ([f"WARNING: {w}" for w in cal.warnings] or ["no identifiability warnings"])
    if cal.poor:
        lines += [f"POOR FIT: {p}" for p in cal.problems]
    return "\n".join(lines)


def _toml_string(text: str) -> str:
    """A TOML basic string (JSON's escapes are TOML's)."""
    import json

    return json.dumps(str(text), ensure_ascii=False)


def _toml_table(items: dict) -> str:
    """An inline TOML table of strings and numbers."""
    cells = []
    for key, value in items.items():
        text = _toml_string(value) if isinstance(value, str) else repr(value)
        cells.append(f"{key} = {text}")
    return "{ " + ", ".join(cells) + " }"


def write_coefficients(cal: Calibration, path, mounting: str, data, sources) -> Path:
    """The fitted coefficients as a user catalogue (``[coefficients.MOUNTING]``, the format of
    ``parameters/data/coefficients.toml``): each fitted value with kind ``calibrated``, its
    standard error and the data it came from; the coefficients not fitted with the value and
    provenance they had (``sources``: the preset's, e.g.
    :func:`~servofmu.parameters.bearing.default_sources`). With the catalogue that
    defines the mounting, ``servofmu build --catalog …`` then builds FMUs and systems whose
    defaults are the calibrated set (a user's set of a mounting takes precedence over the
    package's).

    Parameters
    ----------
    cal : Calibration
        A fit (:func:`~.fit.calibrate`).
    path : str or pathlib.Path
        The .toml file to write (folders are created).
    mounting : str
        The catalogue mounting the data were measured on (the set's key).
    data : str or pathlib.Path
        The data file (named in the set, with the SHA-256 of its content).
    sources : dict
        Provenance ``"kind: reference"`` of each parameter before the fit.

    Returns
    -------
    pathlib.Path
        ``path``.

    Examples
    --------
    A fit on data made from Yu's printed-reading gimbal, written as a catalogue and read back
    as the mounting's set:

    >>> import tempfile
    >>> from servofmu.calibration import calibrate
    >>> from servofmu.calibration.synthetic import synthesise, write_measurements
    >>> from servofmu.parameters import catalog
    >>> from servofmu.parameters.bearing import default_parameters, default_sources
    >>> from servofmu.build import catalogs
    >>> p = default_parameters("yu2017_gimbal_printed")
    >>> data = synthesise(p | {"sliding_friction": 0.1}, [233.15, 263.15, 293.15], [0.17])
    >>> cal = calibrate(data, p, ["sliding_friction"])
    >>> cal.poor, round(float(cal.estimate[0]), 2)
    (False, 0.1)
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     csv = write_measurements(data, Path(tmp) / "data.csv")
    ...     toml = write_coefficients(cal, Path(tmp) / "cal.toml", "yu2017_gimbal_printed",
    ...                               csv, default_sources("yu2017_gimbal_printed"))
    ...     _ = catalogs.load([toml])
    ...     mu = catalog.mounting_coefficients("yu2017_gimbal_printed").sliding_friction
    ...     catalogs.unload()
    >>> mu == float(cal.estimate[0])  # the fitted value, to the last bit
    True
    """
    import hashlib

    from ..parameters.catalog import CALIBRATION_RECORD, COEFFICIENT_FIELDS, PROVENANCE_KINDS

    path = Path(path)
    d = cal.data
    speeds = sorted({float(x) for x in np.round(cal.speed / DEG, 9)})
    t_lo, t_hi = (float(x) - ZERO_CELSIUS for x in (d.temperature.min(), d.temperature.max()))
    record = {
        "data": str(data),
        "sha256": hashlib.sha256(Path(data).read_bytes()).hexdigest(),
        "points": len(d),
        "operating_points": int(cal.operating_points),
        "temperatures": f"{t_lo:g} to {t_hi:g} degC",
        "speeds": ", ".join(f"{x:g}" for x in speeds)
        + " deg/s"
        + (" (assumed: no speed column)" if cal.speed_assumed else ""),
        "residual": cal.residual_kind,
        "rms_residual": float(cal.rms),
        "fitted": ", ".join(cal.unknowns),
        "poor_fit": "; ".join(cal.problems) if cal.poor else "no",
    }
    fitted = dict(zip(cal.unknowns, zip(cal.estimate, cal.standard_error, strict=True),
                      strict=True))  # fmt: skip
    lines = [
        f"# Friction coefficients of mounting {mounting}, calibrated by servofmu calibrate on "
        f"{data}.",
        "# Pass this file after the catalogue that defines the mounting, e.g.",
        f"#   servofmu build --catalog my.toml --catalog {path.name}",
        "# a user's set of a mounting takes precedence over the catalogue's own.",
        "",
        f"[coefficients.{mounting}]",
        f"{CALIBRATION_RECORD} = {_toml_table(record)}",
    ]
    for field in COEFFICIENT_FIELDS:
        unit = "N/m" if field == "loop_stiffness" else "-"
        if field in fitted:
            value, se = (float(x) for x in fitted[field])
            others = [u for u in cal.unknowns if u != field]
            ref = (
                f"servofmu calibrate on {data} ({len(d)} points, {record['temperatures']}, "
                f"{record['speeds']}): {value:.6g} ± {se:.3g} (1 standard error)"
                + (f", fitted with {', '.join(others)}" if others else "")
            )
            entry = {"value": value, "unit": unit, "kind": "calibrated", "ref": ref,
                     "standard_error": se}  # fmt: skip
        elif field == "loop_stiffness":
            continue  # the mounting's own
        else:
            kind, _, ref = sources[field].partition(": ")
            if kind not in PROVENANCE_KINDS:
                kind, ref = "assumed", sources[field]
            entry = {"value": float(cal.parameters[field]), "unit": unit, "kind": kind,
                     "ref": f"not fitted: {ref}"}  # fmt: skip
        lines.append(f"{field} = {_toml_table(entry)}")
    write_text(path, "\n".join(lines) + "\n")
    return path


def write_residuals(cal: Calibration, path) -> Path:
    """Per group of points (one temperature, speed and direction): first line, number of
    points, temperature [°C], speed [°/s], direction, mean and standard deviation of the
    measured torque [N·mm], model torque [N·mm], mean residual [% or N·mm]."""
    path = Path(path)
    d = cal.data
    relative = cal.residual_kind == "relative"
    scale, unit = (100.0, "%") if relative else (1.0 / NMM, "N.mm")
    sd = d.torque_sd
    with written(path) as part, part.open("w") as fh:
        fh.write(
            "line,points,temperature [degC],speed [deg/s],direction,measured [N.mm],"
            f"measured sd [N.mm],model [N.mm],residual ({cal.residual_kind}) [{unit}]\n"
        )
        for i, line in enumerate(d.lines):
            fh.write(
                f"{line},{d.count[i]},{d.temperature[i] - ZERO_CELSIUS:.6g},"
                f"{cal.speed[i] / DEG:.6g},{d.direction[i]},{d.torque[i] / NMM:.6g},"
                f"{sd[i] / NMM:.6g},{cal.model[i] / NMM:.6g},{scale * cal.residuals[i]:.6g}\n"
            )
    return path


def plot(cal: Calibration, path) -> Path:
    """Measured torque (forward ○, reverse □; the mean and ± one standard deviation where a
    temperature was measured several times) and the fitted model (a line of the same colour)
    versus temperature at each measured speed, with the residuals below; a poor fit says so
    in red in the title."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FormatStrFormatter

    path = Path(path)
    d = cal.data
    t_c = d.temperature - ZERO_CELSIUS
    sd = d.torque_sd
    fig, (ax, axr) = plt.subplots(
        2, 1, sharex=True, figsize=(6.8, 5.6), gridspec_kw={"height_ratios": [3, 1.3]}
    )
    ax.set_yscale("log")
    grid = np.linspace(d.temperature.min(), d.temperature.max(), 121)
    for k, w in enumerate(np.unique(cal.speed)):
        colour = f"C{k}"
        model = running_torque(cal.parameters, grid, np.full_like(grid, w))
        ax.plot(grid - ZERO_CELSIUS, model / NMM, "-", color=colour, lw=1.2,
                label=f"fitted model, {w / DEG:g} °/s")  # fmt: skip
        sel = cal.speed == w
        for direction, marker in MARKERS:
            pick = sel & np.array([x == direction for x in d.direction])
            if not pick.any():
                continue
            ax.plot(t_c[pick], d.torque[pick] / NMM, marker, color=colour, mfc="none",
                    label=f"measured, {w / DEG:g} °/s {direction}".rstrip())  # fmt: skip
            spread = pick & (d.count > 1)  # repeated points: mean ± one standard deviation
            if spread.any():
                ax.errorbar(t_c[spread], d.torque[spread] / NMM, yerr=sd[spread] / NMM,
                            fmt="none", ecolor=colour, capsize=2, lw=0.8)  # fmt: skip
    ax.set_ylabel("friction torque [N·mm]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fit = ", ".join(
        f"{n} = {e:.4g} ± {s:.2g}"
        for n, e, s in zip(cal.unknowns, cal.estimate, cal.standard_error, strict=True)
    )
    if cal.poor:
        ax.set_title(f"{d.source}: POOR FIT, not a calibration\n{fit}", fontsize=9, color="tab:red")
    else:
        ax.set_title(f"{d.source}\n{fit}", fontsize=9)
    ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
    ax.yaxis.set_minor_formatter(FormatStrFormatter("%g"))
    ax.tick_params(axis="y", which="minor", labelsize=7)
    scale, unit = (100.0, "%") if cal.residual_kind == "relative" else (1.0 / NMM, "N·mm")
    axr.axhline(0.0, color="k", lw=0.8)
    for k, w in enumerate(np.unique(cal.speed)):
        for direction, marker in MARKERS:
            pick = (cal.speed == w) & np.array([x == direction for x in d.direction])
            axr.plot(t_c[pick], scale * cal.residuals[pick], marker, mfc="none", color=f"C{k}")
    axr.set_ylabel(f"residual [{unit}]")
    axr.set_xlabel("temperature [°C]")
    axr.grid(True, alpha=0.3)
    fig.tight_layout()
    save_figure(fig, path, dpi=110)
    plt.close(fig)
    return path

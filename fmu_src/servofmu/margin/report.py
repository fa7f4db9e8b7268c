"""The report of a margin study: the table (text), the CSV files (units in their headers) and
the plot (margin against temperature, the zero line and the worst point marked)."""

from __future__ import annotations

import csv
import math
import textwrap
from pathlib import Path

import numpy as np

from servofmu.files import save_figure, written
from servofmu.physics.kernels.units import DEG, NMM, ZERO_CELSIUS

from .inputs import CASES
from .standard import CATEGORIES, TERMS
from .study import BEARING_TERMS, FLAG_MEANINGS, FLAGS, PARTS_COLUMNS, MarginResult

CASE_LABELS = {"start": "start (breakaway)", "run": "running"}
SYMBOLS = {
    "inertia": "I",
    "spring": "S",
    "motor_magnetic_losses": "H_M",
    "friction": "F_R",
    "hysteresis": "H_Y",
    "harness": "H_A",
    "adhesion": "H_D",
}


def _celsius(v):
    return v - ZERO_CELSIUS


def _nmm(v):
    return v / NMM


#: CSV columns: (row key, header, conversion from SI).
COLUMNS = (
    ("life", "life", str),
    ("case", "case", str),
    ("draw", "draw", int),
    ("time", "time [s]", float),
    ("temperature", "temperature [degC]", _celsius),
    ("chamber", "chamber temperature [degC]", _celsius),
    *((p, f"{p.replace('_', ' ')} temperature [degC]", _celsius) for p in PARTS_COLUMNS),
    ("speed", "speed [deg/s]", lambda v: v / DEG),
    ("bearing_torque", "bearing torque [N.mm]", _nmm),
    *((k, f"bearing {k.replace('_', ' ')} [N.mm]", _nmm) for k in BEARING_TERMS),
    ("preload", "preload [N]", float),
    ("max_contact_pressure", "max contact pressure [MPa]", lambda v: v / 1e6),
    *((f, f, lambda v: int(bool(v))) for f in FLAGS),
    *(
        (f"factored_{c}", f"{c.replace('_', ' ')} {SYMBOLS[c]} factored [N.mm]", _nmm)
        for c in CATEGORIES
    ),
    ("inertial_resistance", "inertial resistance T_D [N.mm]", _nmm),
    ("deliverable", "deliverable T_L [N.mm]", _nmm),
    ("factored_sum", "factored sum [N.mm]", _nmm),
    ("minimum", "minimum actuation torque T_min [N.mm]", _nmm),
    ("available", "actuation torque T [N.mm]", _nmm),
    ("margin", "margin T/T_min-1 [-]", float),
    ("ecss_ratio", "ECSS ratio MR=(T-1.25T_D-T_L)/sum(u.R) [-]", float),
    ("verdict", "verdict", str),
    ("flags", "flags", str),
)


def write_csv(rows: list[dict], path) -> Path:
    """Write rows of a :class:`~.study.MarginResult` block as CSV, a header ``name [unit]`` (°C,
    N·mm, deg/s, N; a drawn parameter in SI, its unit in its header), the columns the rows
    have.

    Parameters
    ----------
    rows : list of dict
        A block (``result.steady``, ``result.draws`` or ``result.transient``).
    path : str or pathlib.Path
        The file to write (its folder is made).

    Returns
    -------
    pathlib.Path
        ``path``.

    Examples
    --------
    >>> import tempfile
    >>> row = {"life": "as given", "case": "run", "temperature": 233.15, "margin": 0.25}
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     text = write_csv([row], Path(tmp) / "m.csv").read_text()
    >>> text.splitlines()
    ['life,case,temperature [degC],margin T/T_min-1 [-]', 'as given,run,-40,0.25']
    """
    path = Path(path)
    keys = set().union(*(r.keys() for r in rows)) if rows else set()
    columns = [c for c in COLUMNS if c[0] in keys]
    known = {c[0] for c in COLUMNS}
    extra = sorted(keys - known)  # drawn parameters (SI)
    with written(path) as part, part.open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow([c[1] for c in columns] + [f"{k} [SI]" for k in extra])
        for r in rows:
            w.writerow(
                [_fmt(conv(r[k])) if k in r else "" for k, _, conv in columns]
                + [_fmt(r.get(k, "")) for k in extra]
            )
    return path


def _fmt(v):
    if isinstance(v, float):
        return f"{v:.10g}"
    return v


def _key(r) -> tuple:
    return r["life"], r["case"], round(r["temperature"], 9)


def _draw_stats(result: MarginResult) -> dict:
    """{(life, case, temperature): (the governing draw (smallest margin), P(margin < 0), n,
    the number of draws not verified)} over the draws."""
    groups: dict = {}
    for r in result.draws:
        groups.setdefault(_key(r), []).append(r)
    out = {}
    for key, rows in groups.items():
        a = np.asarray([r["margin"] for r in rows], dtype=float)
        worst = rows[int(np.argmin(np.where(np.isnan(a), -np.inf, a)))]
        unverified = sum(1 for r in rows if r["verdict"] == "not verified")
        out[key] = (worst, float((~(a >= 0.0)).mean()), len(rows), unverified)
    return out


def _verdict_text(verdict: str, flags: str) -> str:
    """The verdict with the flags that made a row not verified (or that a row not met has)."""
    return f"{verdict} ({flags})" if flags else verdict


def where(block: str, row: dict) -> str:
    """Where a row lies, in words: life, case, temperature, and its draw or transient time.

    Parameters
    ----------
    block : str
        "steady", "draws" or "transient".
    row : dict
        A row of that block.

    Returns
    -------
    str

    Examples
    --------
    >>> where("steady", {"life": "EOL", "case": "run", "temperature": 233.15})
    'running, EOL, at -40 °C (uniform, nominal parts)'
    """
    case = f"{CASE_LABELS[row['case']]}, {row['life']}"
    t = f"{row['temperature'] - ZERO_CELSIUS:.4g} °C"
    if block == "draws":
        return f"{case}, at {t}, Monte-Carlo draw {row['draw']}"
    if block == "transient":
        parts = ", ".join(
            f"{p.replace('_', ' ')} {row[p] - ZERO_CELSIUS:.4g}" for p in PARTS_COLUMNS
        )
        return (
            f"{case}, chamber transient at t = {row['time'] / 60:.4g} min (chamber {t}; {parts} °C)"
        )
    return f"{case}, at {t} (uniform, nominal parts)"


def to_text(result: MarginResult, files=()) -> str:
    """The report as text: what was computed (rule, factors and their sources, mechanism,
    motor), the table of margins, the worst case and where it occurs, the transient and the
    Monte-Carlo summary, the notes.

    Parameters
    ----------
    result : MarginResult
    files : sequence of paths
        Files written, listed at the end.

    Returns
    -------
    str

    Examples
    --------
    >>> from dataclasses import replace
    >>> from servofmu.margin.inputs import example_input, load_inputs
    >>> from servofmu.margin.study import run
    >>> inputs = replace(load_inputs(example_input()), tolerances=None, transient=None)
    >>> text = to_text(run(inputs))
    >>> "T_min = 2 × Σ u·R + 1.25 × T_D + T_L" in text, "worst:" in text
    (True, True)
    """
    inp = result.inputs
    f = inp.factors
    lines = [
        f"Motorisation (torque) margin — {f.name}",
        f"  T_min = {f.motorisation:g} × Σ u·R + {f.inertial_resistance:g} × T_D + T_L; "
        "margin = T / T_min − 1 (≥ 0 meets T ≥ T_min); the same rule as a ratio: "
        f"MR = (T − {f.inertial_resistance:g} × T_D − T_L) / Σ u·R (≥ {f.motorisation:g} meets "
        "it)",
        "  verdict per row: met (margin ≥ 0, nothing flagged), not met (margin < 0 or no "
        "bearing state), not verified (margin ≥ 0 with a flag that affects the row)",
    ]
    if inp.title:
        lines.append(f"  {inp.title}")
    lines += [
        f"  input: {inp.source}",
        f"  mechanism: {inp.mounting} (from {inp.mounting_from}); bearing friction from the "
        f"bearing library, basis '{inp.friction_basis}' (Table 4-2 column); running at "
        f"{inp.speed / DEG:g} °/s",
    ]
    for life, m in inp.motors.items():
        label = "" if len(inp.motors) == 1 else f" ({life})"
        what = (
            f"k_t {m.torque_constant:g} N·m/A × I_max {m.current_limit:g} A"
            if m.curve_speed is None
            else "torque–speed curve"
        )
        lines.append(
            f"  motor{label}: {what}, gear {m.gear_ratio:g} × η {m.gear_efficiency:g}"
            + (f"; {m.provenance}" if m.provenance else "")
        )
    for t in inp.torques:
        u = (
            f"u = {f.factor(t.category, t.basis):g} ({t.basis})"
            if t.category in CATEGORIES
            else (
                "× "
                + (f"{f.inertial_resistance:g}" if t.category == "inertial_resistance" else "1")
            )
        )
        lines.append(
            f"  torque '{t.name}': {t.category} {u}, cases {'/'.join(t.cases)}"
            + (f"; {t.provenance}" if t.provenance else "")
        )
    lines += ["", *_table(result), ""]
    lines += _worst(result)
    if result.transient:
        lines += ["", *_transient_summary(result)]
    lines += ["", "Factors:"]
    lines += [f"  {k}: {v}" for k, v in f.sources.items()]
    if result.notes:
        lines += ["", "Notes:"] + [f"  - {n}" for n in result.notes]
    lines += [f"file: {p}" for p in files]
    return "\n".join(lines)


def _table(result: MarginResult) -> list[str]:
    stats = _draw_stats(result)
    mc = bool(stats)
    head = (
        f"{'life':>8} {'case':>17} {'T [°C]':>7} {'bearing [N·mm]':>14} {'Σu·R [N·mm]':>12} "
        f"{'T_min [N·mm]':>12} {'T [N·mm]':>9} {'margin [-]':>10} {'MR [-]':>7} "
        f"{'verdict (flags)':<20}"
    )
    if mc:
        n = next(iter(stats.values()))[2]
        head += (
            f" {f'min of {n} draws':>16} {'P(margin<0)':>11} {'not verified':>12} "
            "governing draw (flags)"
        )
    lines = [head]
    for r in result.steady:
        line = (
            f"{r['life']:>8} {CASE_LABELS[r['case']]:>17} "
            f"{r['temperature'] - ZERO_CELSIUS:>7.1f} {r['bearing_torque'] / NMM:>14.4g} "
            f"{r['factored_sum'] / NMM:>12.4g} {r['minimum'] / NMM:>12.4g} "
            f"{r['available'] / NMM:>9.4g} {r['margin']:>+10.3f} {r['ecss_ratio']:>7.3g} "
            f"{_verdict_text(r['verdict'], r['flags']):<20}"
        )
        if _key(r) in stats:
            worst, p, n, unverified = stats[_key(r)]
            line += (
                f" {worst['margin']:>+16.3f} {p:>11.3f} {f'{unverified} of {n}':>12} "
                f"draw {worst['draw']}: {_verdict_text(worst['verdict'], worst['flags'])}"
            )
        lines.append(line.rstrip())
    lines.append("flags (each puts the rows it affects in doubt: not verified, or a not met "
                 "that may be worse):")  # fmt: skip
    lines += [f"  {letter} {FLAG_MEANINGS[letter]}" for letter in FLAGS.values()]
    return lines


def _worst(result: MarginResult) -> list[str]:
    block, r = result.worst
    total = sum(1 for _ in result.rows())
    counts = {v: 0 for v in ("met", "not met", "not verified")}
    letters = dict.fromkeys(FLAGS.values(), 0)
    for _, row in result.rows():
        counts[row["verdict"]] += 1
        for letter in row["flags"]:
            letters[letter] += 1
    flags = (
        "flags: " + ", ".join(f"{x} {FLAG_MEANINGS[x].split(':')[0]}" for x in r["flags"])
        if r["flags"]
        else "no flag"
    )
    lines = [
        f"worst: margin {r['margin']:+.3f}, MR {r['ecss_ratio']:.3g} — {where(block, r)} — "
        f"{r['verdict']}; {flags}",
        f"  T = {r['available'] / NMM:.4g} N·mm against T_min = {r['minimum'] / NMM:.4g} N·mm; "
        f"bearing {r['bearing_torque'] / NMM:.4g} N·mm; factored [N·mm]: "
        + ", ".join(
            f"{SYMBOLS[c]} {r[f'factored_{c}'] / NMM:.4g}" for c in CATEGORIES if r[f"factored_{c}"]
        )
        + "".join(
            f", {'T_D' if k == 'inertial_resistance' else 'T_L'} {r[k] / NMM:.4g}"
            for k in TERMS
            if r[k]
        ),
    ]
    flagged = ", ".join(f"{x} {n}" for x, n in letters.items() if n)
    lines.append(
        f"T ≥ T_min (ECSS-E-ST-33-01C 4.7.5.3.2 b): {result.verdict.upper()} — of {total} rows "
        f"computed, {counts['met']} met, {counts['not met']} not met (negative margin or no "
        f"state), {counts['not verified']} not verified"
        + (f" (rows flagged: {flagged})" if flagged else "")
    )
    return lines


def _transient_summary(result: MarginResult) -> list[str]:
    tr = result.inputs.transient
    rate = "a step" if tr.rate is None else f"{tr.rate * 60:g} K/min"
    lines = [
        f"Chamber transient {tr.start - ZERO_CELSIUS:g} → {tr.end - ZERO_CELSIUS:g} °C at "
        f"{rate}, held {tr.hold / 60:g} min, in {tr.environment} (steps of {tr.step:g} s):"
    ]
    steady = {
        (r["life"], r["case"]): r for r in result.steady if abs(r["temperature"] - tr.end) < 1e-6
    }
    for life in result.inputs.lives:
        for case in CASES:
            rows = [r for r in result.transient if r["life"] == life and r["case"] == case]
            if not rows:
                continue
            worst = min(rows, key=lambda r: -math.inf if math.isnan(r["margin"]) else r["margin"])
            ref = steady.get((life, case))
            tail = f"; steady at {tr.end - ZERO_CELSIUS:g} °C: {ref['margin']:+.3f}" if ref else ""
            lines.append(
                f"  {CASE_LABELS[case]}, {life}: lowest {worst['margin']:+.3f} at "
                f"t = {worst['time'] / 60:.4g} min (chamber "
                f"{worst['chamber'] - ZERO_CELSIUS:.4g} °C, shaft "
                f"{worst['shaft'] - ZERO_CELSIUS:.4g} °C, housing "
                f"{worst['housing'] - ZERO_CELSIUS:.4g} °C){tail}"
            )
    return lines


def plot(result: MarginResult, path) -> Path:
    """Margin against temperature (each life and case, the range of the Monte-Carlo draws) and,
    in a second panel, along a chamber transient against time (with the chamber's, housing's
    and shaft's temperatures); the zero line, and the worst point marked.

    Parameters
    ----------
    result : MarginResult
    path : str or pathlib.Path
        The PNG to write (its folder is made).

    Returns
    -------
    pathlib.Path
        ``path``.

    Examples
    --------
    >>> import tempfile
    >>> from dataclasses import replace
    >>> from servofmu.margin.inputs import example_input, load_inputs
    >>> from servofmu.margin.study import run
    >>> inputs = replace(load_inputs(example_input()), tolerances=None, transient=None)
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     png = plot(run(inputs), Path(tmp) / "margin.png")
    ...     png.stat().st_size > 10000
    True
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = Path(path)
    transient = bool(result.transient)
    fig, axes = plt.subplots(2 if transient else 1, 1, figsize=(7.4, 8.4 if transient else 5.2))
    ax = axes[0] if transient else axes
    styles = {life: ls for life, ls in zip(result.inputs.lives, ("-", "--"), strict=False)}
    colours = {"start": "tab:blue", "run": "tab:orange"}
    for life in result.inputs.lives:
        for case in CASES:
            label = CASE_LABELS[case] + ("" if life == "as given" else f", {life}")
            rows = [r for r in result.steady if r["life"] == life and r["case"] == case]
            ax.plot(
                [r["temperature"] - ZERO_CELSIUS for r in rows],
                [r["margin"] for r in rows],
                styles[life],
                color=colours[case],
                marker="o",
                ms=3,
                label=label,
            )
            doubt = [r for r in rows if r["verdict"] == "not verified"]
            ax.plot(
                [r["temperature"] - ZERO_CELSIUS for r in doubt],
                [r["margin"] for r in doubt],
                "o",
                mfc="none",
                mec="k",
                ms=7,
                label=None,
            )
            draws = [r for r in result.draws if r["life"] == life and r["case"] == case]
            if draws:
                lo, hi = _band(draws)
                t = sorted(lo)
                ax.fill_between(
                    t, [lo[k] for k in t], [hi[k] for k in t], color=colours[case], alpha=0.25, lw=0
                )
            if transient:
                rows = [r for r in result.transient if r["life"] == life and r["case"] == case]
                axes[1].plot(
                    [r["time"] / 60.0 for r in rows],
                    [r["margin"] for r in rows],
                    styles[life],
                    color=colours[case],
                    label=label,
                )
    if any(r["verdict"] == "not verified" for r in result.steady):
        ax.plot([], [], "o", mfc="none", mec="k", ms=7, label="not verified (a flag: the table)")
    if result.draws:
        n = len({r["draw"] for r in result.draws})
        ax.fill_between(
            [], [], [], color="0.6", alpha=0.4, lw=0, label=f"range of {n} Monte-Carlo draws"
        )
    block, w = result.worst
    text = f"worst {w['margin']:+.3f} ({w['verdict']}{', ' + w['flags'] if w['flags'] else ''})"
    if block == "transient":
        axes[1].plot([w["time"] / 60.0], [w["margin"]], "r*", ms=14, zorder=5, label="worst")
        axes[1].annotate(
            text,
            (w["time"] / 60.0, w["margin"]),
            textcoords="offset points",
            xytext=(6, 8),
            color="r",
            fontsize=8,
        )
    else:
        x = w["temperature"] - ZERO_CELSIUS
        ax.plot(
            [x],
            [w["margin"]],
            "r*",
            ms=14,
            zorder=5,
            label="worst" + (" (a Monte-Carlo draw)" if block == "draws" else ""),
        )
        ax.annotate(
            text, (x, w["margin"]), textcoords="offset points", xytext=(6, 8), color="r", fontsize=8
        )
    for a in [ax, *([axes[1]] if transient else [])]:
        a.axhline(0.0, color="k", lw=1.0)
        a.grid(True, alpha=0.3)
        a.set_ylabel("margin T / T_min − 1 [-]")
    ax.set_xlabel("temperature, uniform [°C]")
    ax.legend(fontsize=7, loc="upper left", ncol=2)
    title = f"{result.inputs.title or result.inputs.mounting} — {result.inputs.factors.name}"
    ax.set_title("\n".join(textwrap.wrap(title, 90)), fontsize=8)
    if transient:
        tr = result.inputs.transient
        rate = "step" if tr.rate is None else f"{tr.rate * 60:g} K/min"
        axes[1].set_title(
            f"chamber transient {tr.start - ZERO_CELSIUS:g} → "
            f"{tr.end - ZERO_CELSIUS:g} °C ({rate}, {tr.environment})",
            fontsize=9,
        )
        axes[1].set_xlabel("time since the chamber started moving [min]")
        axes[1].legend(fontsize=7, loc="upper right")
        twin = axes[1].twinx()
        rows = [
            r
            for r in result.transient
            if r["case"] == CASES[0] and r["life"] == result.inputs.lives[0]
        ]
        minutes = [r["time"] / 60.0 for r in rows]
        for key, ls in (("chamber", "-"), ("housing", "-."), ("shaft", ":")):
            twin.plot(
                minutes,
                [r[key] - ZERO_CELSIUS for r in rows],
                color="0.45",
                lw=0.9,
                ls=ls,
                label=f"{key} temperature",
            )
        twin.set_ylabel("temperature [°C]", color="0.35")
        twin.legend(fontsize=7, loc="center right")
    fig.tight_layout()
    save_figure(fig, path, dpi=110)
    plt.close(fig)
    return path


def _band(draws) -> tuple[dict, dict]:
    lo: dict = {}
    hi: dict = {}
    for r in draws:
        t = r["temperature"] - ZERO_CELSIUS
        m = r["margin"]
        lo[t] = min(lo.get(t, m), m)
        hi[t] = max(hi.get(t, m), m)
    return lo, hi


def write_all(result: MarginResult, out_dir) -> list[Path]:
    """Write the study's files into ``out_dir``: ``margin.csv`` (uniform temperatures, nominal
    parts), ``margin_draws.csv`` and ``margin_transient.csv`` when there are draws and a
    transient, and ``margin.png``.

    Parameters
    ----------
    result : MarginResult
    out_dir : str or pathlib.Path

    Returns
    -------
    list of pathlib.Path
        The files written.

    Examples
    --------
    >>> import tempfile
    >>> from dataclasses import replace
    >>> from servofmu.margin.inputs import example_input, load_inputs
    >>> from servofmu.margin.study import run
    >>> inputs = replace(load_inputs(example_input()), tolerances=None, transient=None)
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     [p.name for p in write_all(run(inputs), tmp)]
    ['margin.csv', 'margin.png']
    """
    out = Path(out_dir)
    files = [write_csv(result.steady, out / "margin.csv")]
    if result.draws:
        files.append(write_csv(result.draws, out / "margin_draws.csv"))
    if result.transient:
        files.append(write_csv(result.transient, out / "margin_transient.csv"))
    files.append(plot(result, out / "margin.png"))
    return files

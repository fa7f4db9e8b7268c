"""Monte-Carlo tolerance study of a bearing pair (``servofmu montecarlo``): the fitted
dimensions of a mounting drawn from their manufacturing tolerances (``data/tolerances.toml``,
or a user catalogue's ``[tolerances.MOUNTING]``), the friction torque and the probability of an
overload (Hertz pressure above the static limit) and of a lost preload versus temperature, run
as a Dask sweep of bearing-model evaluations.

Each band is drawn uniformly (a machined dimension anywhere in its band), centred so that
mid-tolerance parts give the nominal values:

- ``ring_outer_diameter`` and ``housing_bore``: the outer seat's diametral interference,
  Δ = Δ_nominal + (d_ring − mid_ring) − (d_bore − mid_bore);
- ``shaft_diameter`` and ``ring_bore``: the inner seat's likewise,
  Δ = Δ_nominal + (d_shaft − mid_shaft) − (d_bore − mid_bore);
- any parameter of the BearingFriction set (``shim``, ``spring_compression``,
  ``assembly_preload``, …): its nominal value plus the drawn deviation.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np

from servofmu.files import save_figure
from servofmu.parameters import catalog
from servofmu.parameters.bearing import PARAMETER_NAMES, default_parameters
from servofmu.parameters.presets import coefficient_set
from servofmu.physics.kernels.units import DEG, NMM, UM, celsius_to_kelvin

from .scenarios.common import ScenarioResult
from .sweep import ModelTask, Uniform, cross, grid_points, run_sweep, sample_points

TEMPS_C = tuple(float(t) for t in range(-40, 61, 10))
SPEED = 10.0 * DEG  # rad/s, the speed of the Yu reproduction
OUTPUTS = ("running_torque", "preload", "max_contact_pressure", "overloaded", "unloaded")
#: The flags whose probability the study reports: an overload (ISO 76) and a lost preload.
FLAGS = ("overloaded", "unloaded")
#: Pairs of toleranced diameters that make a seat's interference: (parameter, the part that
#: adds to it, the part that takes from it).
SEATS = (
    ("outer_interference", "ring_outer_diameter", "housing_bore"),
    ("inner_interference", "shaft_diameter", "ring_bore"),
)
#: Bands of the seat dimensions whose deviations make the rings' interferences.
SEAT_BANDS = tuple(part for _, *parts in SEATS for part in parts)


def tolerance_draws(nominal, bands, samples: int, seed: int) -> list[dict]:
    """``samples`` draws of parameter values from tolerance bands, each uniform in its band.

    The bands of a seat's two diameters (:data:`SEATS`: ``ring_outer_diameter`` and
    ``housing_bore`` for the outer ring, ``shaft_diameter`` and ``ring_bore`` for the inner)
    move its interference by (part that adds − mid) − (part that takes − mid), a missing one
    counting as exact; a band of any other name moves the parameter of that name by
    (draw − mid). The bands are centred: mid-band parts give the nominal value.

    Parameters
    ----------
    nominal : mapping
        The parameter set (SI) the deviations apply to.
    bands : mapping
        {name: (low, high, provenance)}: deviations from nominal in SI
        (:func:`servofmu.parameters.catalog.tolerances`).
    samples : int
        Number of draws, ≥ 1.
    seed : int
        Seed of numpy's ``default_rng``.

    Returns
    -------
    list of dict
        Per draw: ``sample`` (its index) and the drawn parameter values (SI).

    Examples
    --------
    >>> draws = tolerance_draws({"shim": 1e-4}, {"shim": (-2e-6, 2e-6, "±2 µm")}, 3, 1)
    >>> [d["sample"] for d in draws], all(abs(d["shim"] - 1e-4) <= 2e-6 for d in draws)
    ([0, 1, 2], True)
    >>> bands = {"shaft_diameter": (-2.5e-6, 2.5e-6, ""), "ring_bore": (-4e-6, 0.0, "")}
    >>> d = tolerance_draws({"inner_interference": 2e-6}, bands, 1, 1)[0]
    >>> sorted(d), abs(d["inner_interference"] - 2e-6) <= 4.5e-6
    (['inner_interference', 'sample'], True)
    """
    draws = sample_points({n: Uniform(lo, hi) for n, (lo, hi, _) in bands.items()}, samples, seed)
    mids = {name: 0.5 * (lo + hi) for name, (lo, hi, _) in bands.items()}
    for d in draws:
        for parameter, plus, minus in SEATS:
            if plus in mids or minus in mids:
                change = sum(sign * (d.pop(n) - mids[n]) for sign, n in ((1, plus), (-1, minus))
                             if n in mids)  # fmt: skip
                d[parameter] = nominal[parameter] + change
        for name in set(mids) - set(SEAT_BANDS):
            d[name] = nominal[name] + d[name] - mids[name]
    return draws


def tolerance_bands(mounting: str) -> dict[str, tuple[float, float, str]]:
    """The tolerance bands of ``mounting`` ({name: (low, high [SI], provenance)}), checked:
    each name is a seat diameter (:data:`SEATS`) or a parameter of the set; ValueError naming
    the mounting and what to add otherwise.

    Returns
    -------
    dict

    Examples
    --------
    >>> bands = tolerance_bands("yu2017_gimbal")
    >>> sorted(bands), [round(x * 1e6, 1) for x in bands["shim"][:2]]  # µm
    (['housing_bore', 'ring_outer_diameter', 'shim'], [-2.0, 2.0])
    """
    from servofmu.physics._checks import suggest

    if mounting not in catalog.keys("tolerances"):
        raise ValueError(
            f"mounting {mounting!r} has no tolerance bands: add [tolerances.{mounting}] to your "
            "catalogue (ring_outer_diameter and housing_bore, shaft_diameter and ring_bore, or "
            "any parameter such as shim or spring_compression, each { low, high, unit, kind, "
            f"ref }}; the bands of {catalog.keys('tolerances')} are in the package's "
            "data/tolerances.toml)"
        )
    bands = catalog.tolerances(mounting)
    for name in bands:
        if name not in SEAT_BANDS and name not in PARAMETER_NAMES:
            hint = suggest(name, [*SEAT_BANDS, *PARAMETER_NAMES])
            raise ValueError(
                f"tolerances.{mounting}: {name!r} is neither a seat diameter "
                f"{list(SEAT_BANDS)} nor a parameter{hint}"
            )
    return bands


def tolerance_points(
    mounting: str, samples: int, seed: int, nominal: dict | None = None
) -> list[dict]:
    """``samples`` draws of the toleranced values of ``mounting`` (:func:`tolerance_bands`,
    :func:`tolerance_draws`) around ``nominal`` (default: the mounting's parameter set), each
    crossed with the temperatures of :data:`TEMPS_C` at :data:`SPEED`."""
    nominal = default_parameters(mounting) if nominal is None else nominal
    draws = tolerance_draws(nominal, tolerance_bands(mounting), samples, seed)
    return cross(draws, _grid())


def _grid() -> list[dict]:
    """The temperatures of :data:`TEMPS_C` at :data:`SPEED`."""
    return grid_points({"temperature": [celsius_to_kelvin(t) for t in TEMPS_C], "speed": [SPEED]})


def run(
    out_dir,
    samples: int = 500,
    seed: int = 1,
    workers: int | None = None,
    scheduler: str | None = None,
    mounting: str = "yu2017_gimbal",
    progress: bool = True,
    base: dict | None = None,
) -> ScenarioResult:
    """Run the study on ``mounting`` (its parameter set ``base``, default the mounting's
    preset); table, summary and files (CSV of every run, CSV of the summary, PNG)."""
    out = Path(out_dir)
    base = default_parameters(mounting) if base is None else base
    points = tolerance_points(mounting, samples, seed, base)
    sweep = run_sweep(
        ModelTask(base, OUTPUTS), points, workers=workers, scheduler=scheduler, progress=progress
    )
    runs_file = sweep.write(out / "runs.csv")
    if sweep.interrupted:  # Ctrl-C: the finished runs are on disk; no statistics of a part
        raise KeyboardInterrupt(f"the finished runs are in {runs_file}")
    temps = np.array([p["temperature"] for p in points])
    torque = sweep.column("running_torque")
    flags = {f: sweep.column(f) for f in FLAGS}
    nominal = ModelTask(base, OUTPUTS)(_grid())
    rows = []
    for k, t_c in enumerate(TEMPS_C):
        sel = np.isclose(temps, celsius_to_kelvin(t_c)) & np.isfinite(torque)
        n = int(sel.sum())
        q5, q50, q95 = (np.percentile(torque[sel], [5, 50, 95]) / NMM) if n else [math.nan] * 3
        row = {
            "temperature [degC]": t_c,
            "nominal [N.mm]": nominal[k]["running_torque"] / NMM,
            "p5 [N.mm]": float(q5),
            "median [N.mm]": float(q50),
            "p95 [N.mm]": float(q95),
        }
        for flag, values in flags.items():
            p = float(np.mean(values[sel])) if n else math.nan
            lo, hi = _wilson(p, n)
            row |= {f"P({flag})": p, f"P({flag}) low (95%)": lo, f"P({flag}) high (95%)": hi}
        rows.append(row | {"runs": n})
    tol = tolerance_bands(mounting)
    drawn = sorted(
        n for n in points[0] if n in PARAMETER_NAMES and n not in ("temperature", "speed")
    )
    result = ScenarioResult(
        "montecarlo",
        f"Monte-Carlo tolerance study, {mounting}: {samples} draws of "
        f"{', '.join(drawn[:-1]) + ' and ' if len(drawn) > 1 else ''}{drawn[-1]}, running "
        "torque at "
        f"{SPEED / DEG:g} °/s and the probabilities of an overload and of a lost preload versus "
        "temperature",
        list(rows[0]),
        rows,
        summary={
            "runs": len(sweep.rows),
            "failed runs": len(sweep.failed),
            "workers": sweep.workers,
            "wall time [s]": sweep.wall_time,
            **{
                f"{name} [{_unit(name)[0]}]": _spread([p[name] for p in points], _unit(name)[1])
                for name in drawn
            },
        },
        files=[runs_file],
        notes=[
            f"{name}: {lo / UM:+g}…{hi / UM:+g} µm ({src})" for name, (lo, hi, src) in tol.items()
        ]
        + [
            f"friction coefficients: {coefficient_set(mounting).label}",
            "P(overloaded): fraction of draws whose largest Hertz pressure exceeds 4200 MPa "
            "(ISO 76); P(unloaded): fraction whose preload is lost (a bearing without axial "
            "load); each with its 95 % Wilson interval.",
        ],
    )
    result.write_table(out / "montecarlo.csv")
    result.files.append(_plot(rows, out / "montecarlo.png", result.title))
    for failure in sweep.failed[:5]:
        result.notes.append(f"failed run: {failure}")
    return result


def _unit(name: str) -> tuple[str, float]:
    """(unit, its size in SI) of a drawn parameter in the summary: µm for lengths."""
    from servofmu.parameters.bearing import parameter

    unit = parameter(name).unit or "-"
    return ("um", UM) if unit == "m" else (unit, 1.0)


def _spread(values, unit) -> str:
    v = np.asarray(values) / unit
    return f"{v.mean():.3f} ± {v.std():.3f} (min {v.min():.3f}, max {v.max():.3f})"


def _wilson(p: float, n: int, z: float = 1.96) -> tuple[float, float]:
    """95 % Wilson score interval of a proportion p over n trials."""
    if not n or not math.isfinite(p):
        return math.nan, math.nan
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


def _plot(rows, path: Path, title: str) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = [r["temperature [degC]"] for r in rows]
    fig, (ax, axp) = plt.subplots(
        2, 1, sharex=True, figsize=(6.8, 5.8), gridspec_kw={"height_ratios": [2.2, 1]}
    )
    ax.fill_between(
        t, [r["p5 [N.mm]"] for r in rows], [r["p95 [N.mm]"] for r in rows], alpha=0.3,
        label="5–95 % of draws",
    )  # fmt: skip
    ax.semilogy(t, [r["median [N.mm]"] for r in rows], "-", label="median")
    ax.semilogy(t, [r["nominal [N.mm]"] for r in rows], "k--", lw=1, label="nominal parts")
    ax.set_ylabel("running torque [N·mm]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("\n".join(textwrap.wrap(title, 85)), fontsize=9)
    for flag in FLAGS:
        p = np.array([r[f"P({flag})"] for r in rows])
        lo = np.array([r[f"P({flag}) low (95%)"] for r in rows])
        hi = np.array([r[f"P({flag}) high (95%)"] for r in rows])
        yerr = np.clip([p - lo, hi - p], 0.0, None)  # Wilson bounds hold p up to rounding
        axp.errorbar(t, p, yerr=yerr, fmt="o-", ms=4, capsize=3, label=flag)
    axp.set_ylabel("probability [-]")
    axp.legend(fontsize=8)
    axp.set_ylim(-0.05, 1.05)
    axp.set_xlabel("temperature [°C]")
    axp.grid(True, alpha=0.3)
    fig.tight_layout()
    save_figure(fig, path, dpi=110)
    plt.close(fig)
    return path

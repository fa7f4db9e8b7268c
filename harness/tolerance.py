"""Monte-Carlo tolerance study of a bearing pair (``servofmu montecarlo``): the outer ring's
fit and the preload washer drawn from their manufacturing tolerances
(``physics/data/tolerances.toml``), the friction torque and the probability of an overload
(Hertz pressure above the static limit) versus temperature, run as a Dask sweep of
bearing-model evaluations.

Diametral interference Δ = Δ_nominal + (d_ring − mid_ring) − (d_bore − mid_bore): the ring's
outside diameter and the housing bore each anywhere in their band (uniform), the bands
centred so that mid-tolerance parts give the drawn interference; the shim likewise around its
nominal thickness.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np

from servofmu.physics import catalog
from servofmu.physics.bearing_parameters import default_parameters
from servofmu.physics.units import DEG, NMM, UM, celsius_to_kelvin

from .scenarios.common import ScenarioResult
from .sweep import ModelTask, Uniform, cross, grid_points, run_sweep, sample_points

TEMPS_C = tuple(float(t) for t in range(-40, 61, 10))
SPEED = 10.0 * DEG  # rad/s, the speed of the Yu reproduction
OUTPUTS = ("running_torque", "preload", "max_contact_pressure", "overloaded", "unloaded")
#: The flags whose probability the study reports: an overload (ISO 76) and a lost preload.
FLAGS = ("overloaded", "unloaded")


#: Bands of the two seat dimensions whose deviations make the outer ring's interference.
SEAT_BANDS = ("ring_outer_diameter", "housing_bore")


def tolerance_draws(nominal, bands, samples: int, seed: int) -> list[dict]:
    """``samples`` draws of parameter values from tolerance bands, each uniform in its band.

    A band of ``ring_outer_diameter`` or ``housing_bore`` (deviations of the ring's outside
    diameter and of the housing bore) moves ``outer_interference`` by (ring − mid) − (bore −
    mid); a band of any other name moves the parameter of that name by (draw − mid). The
    bands are centred: mid-band parts give the nominal value.

    Parameters
    ----------
    nominal : mapping
        The parameter set (SI) the deviations apply to.
    bands : mapping
        {name: (low, high, provenance)}: deviations from nominal in SI
        (:func:`servofmu.physics.catalog.tolerances`).
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
    """
    draws = sample_points({n: Uniform(lo, hi) for n, (lo, hi, _) in bands.items()}, samples, seed)
    mids = {name: 0.5 * (lo + hi) for name, (lo, hi, _) in bands.items()}
    for d in draws:
        seat = [d.pop(n) - mids[n] if n in mids else 0.0 for n in SEAT_BANDS]
        if any(n in mids for n in SEAT_BANDS):
            d["outer_interference"] = nominal["outer_interference"] + seat[0] - seat[1]
        for name in set(mids) - set(SEAT_BANDS):
            d[name] = nominal[name] + d[name] - mids[name]
    return draws


def tolerance_points(mounting: str, samples: int, seed: int) -> list[dict]:
    """``samples`` draws of (outer_interference, shim) of ``mounting`` (its bands in
    ``physics/data/tolerances.toml``, :func:`tolerance_draws`), each crossed with the
    temperatures of :data:`TEMPS_C` at :data:`SPEED`."""
    draws = tolerance_draws(
        default_parameters(mounting), catalog.tolerances(mounting), samples, seed
    )
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
) -> ScenarioResult:
    """Run the study; table, summary and files (CSV of every run, CSV of the summary, PNG)."""
    out = Path(out_dir)
    base = default_parameters(mounting)
    points = tolerance_points(mounting, samples, seed)
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
    tol = catalog.tolerances(mounting)
    result = ScenarioResult(
        "montecarlo",
        f"Monte-Carlo tolerance study, {mounting}: {samples} draws of fit and shim, running "
        f"torque at {SPEED / DEG:g} °/s and the probabilities of an overload and of a lost preload "
        "versus temperature",
        list(rows[0]),
        rows,
        summary={
            "runs": len(sweep.rows),
            "failed runs": len(sweep.failed),
            "workers": sweep.workers,
            "wall time [s]": sweep.wall_time,
            "outer interference [um]": _spread([p["outer_interference"] for p in points], UM),
            "shim [um]": _spread([p["shim"] for p in points], UM),
        },
        files=[runs_file],
        notes=[
            f"{name}: {lo / UM:+g}…{hi / UM:+g} µm ({src})" for name, (lo, hi, src) in tol.items()
        ]
        + [
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
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path

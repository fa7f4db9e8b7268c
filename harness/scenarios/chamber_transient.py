"""Thermal transients in a chamber: the part temperatures of a ThermalNetwork drive
the bearing, and its preload and torque are set against the quasi-static curve, the bearing
library at a uniform temperature equal to the chamber's.

- Yu's seeker gimbal (``seeker_gimbal_chamber``: speed loop at 10 °/s, 71803 pair, the network
  ``yu2017_gimbal_chamber`` in chamber air): soaked at one end of −40…+60 °C, the chamber then
  steps or ramps at 5 K/min or 1 K/min to the other end and holds. Reported: the largest
  frame − shaft difference, how far the preload and the torque run above and below the
  quasi-static values, the time each flag is set (unloaded, locked, overloaded), and how long
  the chamber must hold its final temperature before torque and preload stay within 2 % of
  their quasi-static values — Yu held every temperature 30 min before measuring; his own
  20 K step into −40 °C is run too.
- Ning's space bearing (``space_bearing_vacuum``: 10 rpm, 71807C, MoS2): two triangle cycles
  −60 → +80 → −60 °C at 1 K/min (10 K/min coarse), in thermal vacuum (plate and shroud follow
  the cycle) and, with the variant ``chamber_air``, on his rig in the air of a high-low
  temperature chamber, where his test ran. Per cycle the same figures, and the change of the
  torque's maximum and minimum from the first cycle to the second against Ning's measured
  1.7 / 0.9 N·mm. Ning gives no rates; 1 K/min without dwell is assumed (a dwell lets the
  lag die out, so it can only shrink a cycle-to-cycle change).

Steps (``ssp/README.md``): the gimbal's loop steps at 10 ms (its grease's viscous torque is fed
back to the motor one step late, which needs a step well below 23 ms when cold) and its
network once a second (``rates``); Ning's system steps at 1 s (a MoS2 film's torque does not
depend on speed). The network is exact at any step, and the bearing sees the part
temperatures every step. Each run first soaks 1 min at the start temperature with the speed
loop running (it settles within 2 s), the network soaked too; then the chamber moves. Rows
are kept every 10 s. Holds at the final temperature: 60 min after heating, 150 min after
cooling (the slow shaft). ``coarse`` (the tests): the two Yu steps with 15 min holds and Ning
in vacuum at 10 K/min.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from servofmu.files import save_figure, written
from servofmu.physics.kernels.units import DEG, NMM, ZERO_CELSIUS

from .. import load_system
from .. import run as run_system
from ..pool import run_parallel
from ..signals import PiecewiseLinear
from .common import ScenarioResult, mechanism_notes, system_path

YU, NING = "seeker_gimbal_chamber", "space_bearing_vacuum"
YU_RANGE_C = (-40.0, 60.0)  # °C, Yu's chamber range
YU_STEP_C = (-20.0, -40.0)  # °C, the last of Yu's 20 K steps (Yu §3: −40…+60 °C in 20 K)
NING_RANGE_C = (-60.0, 80.0)  # °C, Ning's alternating temperature
RATES = (("step", None), ("5 K/min", 5.0 / 60.0), ("1 K/min", 1.0 / 60.0))  # K/s
SOAK = 60.0  # s at the start temperature before the chamber moves (the speed loop settles)
THERMAL_STEP = 1.0  # s: the network's step where the system steps faster (harness rates)
HOLDS = {"heating": 60.0, "cooling": 150.0}  # min at the final temperature (full run)
COARSE_HOLD = 15.0  # min, both directions (coarse: the steps only)
ROW = 10.0  # s between kept rows
TOLERANCE = 0.02  # within 2 % of the quasi-static value
YU_HOLD = 30.0  # min: Yu's hold at each chamber temperature
NING_CHANGES = (1.7, 0.9)  # N·mm: Ning's drop of the maximum, rise of the minimum
FLAGS = ("unloaded", "locked", "overloaded", "outside_lubricant_range")
PARTS = ("housing", "shaft", "outer_ring", "inner_ring")
RECORD = (
    *(f"thermal.{p}_temperature" for p in PARTS),
    "thermal.ambient_temperature",
    "bearing.preload",
    "bearing.running_torque",
    *(f"bearing.{f}" for f in FLAGS),
    "motor.current",
    "motor.speed",
)


@dataclass(frozen=True)
class Profile:
    """One chamber run: ``chamber`` [K] over time [s]; the chamber reaches its final
    temperature at ``end`` [s] (Yu) or cycles with period ``period`` [s] (Ning)."""

    key: str
    system: str
    label: str
    chamber: PiecewiseLinear
    stop: float
    end: float | None = None
    period: float | None = None
    variant: str | None = None


def yu_profiles(coarse: bool) -> list[Profile]:
    """Heating −40 → +60 °C and cooling +60 → −40 °C, each as a step and as ramps."""
    rates = RATES[:1] if coarse else RATES
    out = []
    for direction, (a, b) in (("heating", YU_RANGE_C), ("cooling", YU_RANGE_C[::-1])):
        hold = 60.0 * (COARSE_HOLD if coarse else HOLDS[direction])
        for name, rate in rates:
            ramp = 0.0 if rate is None else abs(b - a) / rate
            end = SOAK + ramp
            times = (SOAK, end if ramp else SOAK + 1.0)  # a step: the next step's value
            chamber = PiecewiseLinear(times, (a + ZERO_CELSIUS, b + ZERO_CELSIUS))
            key = f"yu_{direction}_{name.replace(' ', '').replace('/', 'per')}"
            out.append(Profile(key, YU, f"{direction} {name}", chamber, end + hold, end=end))
    if not coarse:  # Yu's own procedure: 20 K steps, the coldest last (then 30 min of hold)
        a, b = (t + ZERO_CELSIUS for t in YU_STEP_C)
        chamber = PiecewiseLinear((SOAK, SOAK + 1.0), (a, b))
        label = f"cooling step {YU_STEP_C[0]:g} → {YU_STEP_C[1]:g} °C"
        hold = 60.0 * HOLDS["cooling"]
        out.append(Profile("yu_cooling_20K", YU, label, chamber, SOAK + hold, end=SOAK))
    return out


def ning_profiles(coarse: bool) -> list[Profile]:
    """Two triangle cycles −60 → +80 → −60 °C in vacuum (and in chamber air, full run)."""
    rate = (10.0 if coarse else 1.0) / 60.0  # K/s
    low, high = (t + ZERO_CELSIUS for t in NING_RANGE_C)
    half = (high - low) / rate
    times = [SOAK + k * half for k in range(5)]
    chamber = PiecewiseLinear(tuple(times), (low, high, low, high, low))
    label = f"{rate * 60:g} K/min"
    out = [Profile("ning_vacuum", NING, f"vacuum {label}", chamber, times[-1], period=2 * half)]
    if not coarse:
        out.append(
            Profile(
                "ning_air",
                NING,
                f"air {label}",
                chamber,
                times[-1],
                period=2 * half,
                variant="chamber_air",
            )
        )
    return out


# ---------------------------------------------------------------------------- one run
@dataclass
class Trace:
    """A run's kept rows: time [s], chamber and part temperatures [K], the bearing's preload
    [N] and running torque [N·m], k_t·i [N·m], speed [rad/s], flags, and the quasi-static
    preload, torque and flags at the chamber temperature."""

    t: np.ndarray
    chamber: np.ndarray
    parts: dict[str, np.ndarray]
    preload: np.ndarray
    torque: np.ndarray
    kti: np.ndarray
    speed: np.ndarray
    flags: dict[str, np.ndarray]
    qs_preload: np.ndarray
    qs_torque: np.ndarray
    qs_flags: dict[str, np.ndarray]
    reference: float


def library_model(system):
    """The bearing library model of the system's ``bearing`` component: the FMU's defaults
    with the component's bindings (the quasi-static reference)."""
    from servofmu.parameters.bearing import PARAMETERS, pair_from_parameters
    from servofmu.physics.bearing import BearingModel

    values = {p.name: p.default for p in PARAMETERS}
    specs = {p.name: p for p in PARAMETERS}
    for name, (_, value) in system.components["bearing"].parameters.items():
        if name in specs:
            values[name] = specs[name].key(value) if specs[name].choices else value
    return BearingModel(pair_from_parameters(values))


def _steps(system, profile: Profile) -> int:
    """The communication steps of ``profile`` on ``system``."""
    return round(profile.stop / system.step_size)


def _simulate_profile(ssp: Path, profile: Profile, out: Path, progress=False) -> Trace:
    """:func:`simulate` on the system in ``ssp`` (loaded here: a worker process's call)."""
    system = load_system(ssp)
    try:
        return simulate(system, profile, out, progress)
    finally:
        system.close()


def simulate(system, profile: Profile, out: Path, progress=False) -> Trace:
    """Run ``profile`` on the loaded ``system`` (results under ``out/<key>/``; ``progress``:
    a progress bar to advance by the steps, see :func:`~servofmu.harness.master.run`) and set
    the quasi-static curve beside it."""
    # the network starts soaked at the chamber's start temperature (after the variant)
    soak = {"thermal.initial_temperature": profile.chamber(0.0)}
    res = run_system(
        system,
        parameters=[profile.variant, soak] if profile.variant else soak,
        signals={
            "thermal.ambient_temperature": profile.chamber,
            "thermal.sink_temperature": profile.chamber,
        },
        stop=profile.stop,
        record=list(RECORD),
        out_dir=out / profile.key,
        output_interval=ROW,
        progress=progress,
        rates={"thermal": max(1, round(THERMAL_STEP / system.step_size))},
    )
    t = res["time"]
    chamber = np.array([profile.chamber(x) for x in t])  # at the row's time
    speed = system.components["controller"].parameters["reference"][1]
    qs = library_model(system).curves(chamber, speed)
    kt = system.components["motor"].parameters["torque_constant"][1]
    return Trace(
        t=t,
        chamber=chamber,
        parts={p: res[f"thermal.{p}_temperature"] for p in PARTS},
        preload=res["bearing.preload"],
        torque=res["bearing.running_torque"],
        kti=kt * res["motor.current"],
        speed=res["motor.speed"],
        flags={f: res[f"bearing.{f}"] > 0.5 for f in FLAGS},
        qs_preload=np.asarray(qs.preload, float),
        qs_torque=np.asarray(qs.running_torque, float),
        qs_flags={f: np.asarray(getattr(qs, f), bool) for f in FLAGS},
        reference=speed,
    )


# ---------------------------------------------------------------------------- figures
def hold_time(t, values, final, t_end):
    """Time [s] after ``t_end`` from which ``values`` stay within TOLERANCE of ``final``
    (None when they do not by the end of the run)."""
    band = TOLERANCE * abs(final)
    after = t >= t_end
    outside = np.flatnonzero(after & (np.abs(values - final) > band))
    if len(outside) == 0:
        return 0.0
    last = outside[-1]
    return None if last == len(t) - 1 else float(t[last + 1] - t_end)


def _window_figures(tr: Trace, sel) -> dict:
    """The figures every row shares, over the rows ``sel``."""
    lag = tr.parts["housing"][sel] - tr.parts["shaft"][sel]
    minutes = ROW / 60.0
    return {
        "frame-shaft max [K]": float(lag[np.argmax(np.abs(lag))]),
        "preload above qs [N]": float(np.max(tr.preload[sel] - tr.qs_preload[sel])),
        "preload below qs [N]": float(np.max(tr.qs_preload[sel] - tr.preload[sel])),
        "torque min [N.mm]": float(np.min(tr.torque[sel])) / NMM,
        "torque max [N.mm]": float(np.max(tr.torque[sel])) / NMM,
        "qs torque min [N.mm]": float(np.min(tr.qs_torque[sel])) / NMM,
        "qs torque max [N.mm]": float(np.max(tr.qs_torque[sel])) / NMM,
        "unloaded [min]": float(np.sum(tr.flags["unloaded"][sel])) * minutes,
        "qs unloaded [min]": float(np.sum(tr.qs_flags["unloaded"][sel])) * minutes,
        "locked [min]": float(np.sum(tr.flags["locked"][sel])) * minutes,
        "overloaded [min]": float(np.sum(tr.flags["overloaded"][sel])) * minutes,
        "outside lubricant range [min]": (
            float(np.sum(tr.flags["outside_lubricant_range"][sel])) * minutes
        ),
    }


def _minutes(seconds) -> float | str:
    return "never" if seconds is None else seconds / 60.0


def yu_row(profile: Profile, tr: Trace) -> dict:
    """The row of a Yu profile: window from the chamber's start to the end of the hold."""
    sel = tr.t >= SOAK
    final_preload, final_torque = tr.qs_preload[-1], tr.qs_torque[-1]
    at_30 = np.searchsorted(tr.t, profile.end + YU_HOLD * 60.0)
    after_30 = 100.0 * (tr.torque[at_30] / final_torque - 1.0) if at_30 < len(tr.t) else ""
    return {
        "system": "Yu gimbal in air",
        "profile": profile.label,
        **_window_figures(tr, sel),
        "hold 2% torque [min]": _minutes(hold_time(tr.t, tr.torque, final_torque, profile.end)),
        "hold 2% preload [min]": _minutes(hold_time(tr.t, tr.preload, final_preload, profile.end)),
        "torque after 30 min [%]": after_30,
    }


def ning_rows(profile: Profile, tr: Trace) -> list[dict]:
    """One row per cycle of a Ning profile."""
    rows = []
    for k in range(2):
        lo, hi = SOAK + k * profile.period, SOAK + (k + 1) * profile.period
        sel = (tr.t >= lo) & ((tr.t < hi) if k == 0 else (tr.t <= hi))
        rows.append(
            {
                "system": "Ning bearing in " + profile.label.split()[0],
                "profile": f"cycle {k + 1} at {profile.label.split(maxsplit=1)[1]}",
                **_window_figures(tr, sel),
                "hold 2% torque [min]": "",
                "hold 2% preload [min]": "",
                "torque after 30 min [%]": "",
            }
        )
    return rows


def cycle_changes(rows: list[dict]) -> tuple[float, float]:
    """(drop of the maximum torque, rise of the minimum) from cycle 1 to cycle 2 [N·mm]."""
    first, second = rows
    return (
        first["torque max [N.mm]"] - second["torque max [N.mm]"],
        second["torque min [N.mm]"] - first["torque min [N.mm]"],
    )


# ---------------------------------------------------------------------------- the scenario
def run(
    out_dir, fmu_dir=None, coarse: bool = False, mechanism=None, workers=None
) -> ScenarioResult:
    """The scenario on ``mechanism`` (default: the standard one): the chamber profiles on its
    ``seeker_gimbal_chamber`` system (the ThermalNetwork of its parts); Ning's cycles on his
    space bearing for the standard mechanism only. The profiles are independent runs, on
    ``workers`` processes (default one per core; 1: one after another, here) behind one
    progress bar."""
    out = Path(out_dir)
    standard = mechanism is None or mechanism.standard
    label = "Yu gimbal in air" if standard else f"{mechanism.key} in air"
    runs = [(YU, yu_profiles(coarse))] + ([(NING, ning_profiles(coarse))] if standard else [])
    calls, counts = [], []
    for name, profiles in runs:
        ssp = system_path(name, fmu_dir, mechanism)
        system = load_system(ssp)  # checked here once, before any run
        try:
            counts += [_steps(system, p) for p in profiles]
        finally:
            system.close()
        calls += [(ssp, p, out) for p in profiles]
    done = run_parallel(
        _simulate_profile, calls, steps=counts, workers=workers, desc="chamber_transient"
    )
    traces = {p.key: (p, tr) for (_, p, _), tr in zip(calls, done, strict=True)}
    rows, changes = [], {}
    for profile, tr in traces.values():
        if profile.system == YU:
            rows.append(yu_row(profile, tr) | {"system": label})
        else:
            cycles = ning_rows(profile, tr)
            rows += cycles
            changes[profile.label] = cycle_changes(cycles)
    notes = _notes(coarse)
    if not standard:
        from servofmu.build.mechanism import thermal_notes

        notes = [*mechanism_notes(mechanism), *thermal_notes(mechanism), *notes]
    result = ScenarioResult(
        "chamber_transient",
        "Thermal transients in a chamber: part temperatures (ThermalNetwork) → bearing, against "
        "the quasi-static curve (every part at the chamber temperature)"
        + ("" if standard else f"; mechanism {mechanism.key}"),
        list(rows[0]),
        rows,
        summary=_summary(traces, changes),
        notes=notes,
    )
    result.write_table(out / "chamber_transient.csv")
    for profile, tr in traces.values():
        result.files.append(write_trace(out / f"{profile.key}.csv", tr))
    result.files.append(
        plot(traces, out / "chamber_transient.png", "" if standard else mechanism.key)
    )
    return result


def _summary(traces, changes) -> dict:
    summary = {}
    for label, (drop, rise) in changes.items():
        summary[f"Ning {label}: drop of the maximum torque, cycle 1 → 2 [N.mm]"] = drop
        summary[f"Ning {label}: rise of the minimum torque, cycle 1 → 2 [N.mm]"] = rise
    if changes:
        summary["Ning measured: drop / rise [N.mm]"] = "{:g} / {:g}".format(*NING_CHANGES)
    settled = [
        float(np.max(np.abs(tr.speed[tr.t >= SOAK] / tr.reference - 1.0)))
        for _, tr in traces.values()
    ]
    summary["largest speed error after the soak [%]"] = 100.0 * max(settled)
    return summary


def _notes(coarse: bool) -> list[str]:
    return [
        "qs: the bearing library with every part at the chamber temperature (quasi-static), "
        "at the loop's reference speed. above/below qs: the largest excess of the transient "
        "value over the quasi-static one at the same time, and the largest shortfall.",
        "frame-shaft: housing minus shaft temperature at its largest magnitude (the shaft "
        "lags: positive on heating, negative on cooling).",
        f"hold 2%: minutes after the chamber reached its final temperature until the value "
        f"stays within {TOLERANCE:.0%} of its quasi-static value there (Yu held {YU_HOLD:g} "
        "min); 'never': not within the run. torque after 30 min: its deviation then.",
        "flags [min]: time the transient bearing was unloaded (preload lost), locked (no "
        "radial clearance left), overloaded (4200 MPa) or outside the range of its "
        "lubricant's data (its viscosity held below a flow limit, else extrapolated); qs "
        "unloaded: the same quasi-statically.",
        "Steps: gimbal loop 10 ms, its network 1 s; Ning's system 1 s (ssp/README.md); rows "
        f"every {ROW:g} s; {SOAK / 60:g} min soak with the loop running before the chamber "
        "moves."
        + (
            f" Coarse: the Yu steps, {COARSE_HOLD:g} min holds; Ning at 10 K/min." if coarse else ""
        ),
    ]


# ---------------------------------------------------------------------------- files
def write_trace(path: Path, tr: Trace) -> Path:
    """One run's rows as CSV, headers with units (time from the chamber's start)."""
    columns = {
        "time [min]": (tr.t - SOAK) / 60.0,
        "chamber [degC]": tr.chamber - ZERO_CELSIUS,
        **{f"{p.replace('_', ' ')} [degC]": v - ZERO_CELSIUS for p, v in tr.parts.items()},
        "preload [N]": tr.preload,
        "qs preload [N]": tr.qs_preload,
        "torque [N.mm]": tr.torque / NMM,
        "qs torque [N.mm]": tr.qs_torque / NMM,
        "k_t*i [N.mm]": tr.kti / NMM,
        "speed [deg/s]": tr.speed / DEG,
        **{f"{f} [0/1]": v.astype(float) for f, v in tr.flags.items()},
        **{f"qs {f} [0/1]": v.astype(float) for f, v in tr.qs_flags.items()},
    }
    with written(path) as part:
        np.savetxt(
            part,
            np.column_stack(list(columns.values())),
            delimiter=",",
            header=",".join(columns),
            comments="",
            fmt="%.9g",
        )
    return path


def plot(traces, path: Path, name: str = "") -> Path:
    """Part temperatures, preload and torque against time, transient and quasi-static: Yu
    heating, Yu cooling, Ning (columns); ``name``: the mechanism in Yu's profiles instead."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    groups = {
        "Yu gimbal: heating −40 → +60 °C": [v for v in traces.values() if "heating" in v[0].key],
        "Yu gimbal: cooling +60 → −40 °C": [v for v in traces.values() if "cooling" in v[0].key],
        "Ning bearing: cycles −60…+80 °C": [v for v in traces.values() if v[0].system == NING],
    }
    if name:  # another mechanism in Yu's chamber profiles; no Ning runs
        groups = {title.replace("Yu gimbal", name): runs for title, runs in groups.items() if runs}
    fig, axes = plt.subplots(
        3, len(groups), figsize=(14 * len(groups) / 3, 10), dpi=100, sharex="col", squeeze=False
    )
    for col, (title, runs) in enumerate(groups.items()):
        _plot_temperatures(axes[0, col], runs)
        _plot_pair(axes[1, col], runs, "preload", 1.0, "preload [N]")
        _plot_pair(axes[2, col], runs, "torque", 1.0 / NMM, "friction torque [N·mm]")
        axes[0, col].set_title(title, fontsize=10)
        axes[2, col].set_xlabel("time from the chamber's start [min]")
    title = (
        "Chamber transients: solid = part temperatures through the ThermalNetwork, "
        "dashed = quasi-static (every part at the chamber temperature)"
    )
    fig.suptitle(textwrap.fill(title, 60 * len(groups)), fontsize=10)
    fig.tight_layout()
    save_figure(fig, path)
    plt.close(fig)
    return path


def _plot_temperatures(ax, runs):
    profile, tr = runs[0]  # the step (Yu) or the vacuum run (Ning): all four parts
    x = (tr.t - SOAK) / 60.0
    ax.plot(x, tr.chamber - ZERO_CELSIUS, "k-", lw=1.0, label=f"chamber ({profile.label})")
    for part, style in zip(PARTS, ("C0-", "C1-", "C0:", "C1:"), strict=True):
        ax.plot(x, tr.parts[part] - ZERO_CELSIUS, style, lw=1.2, label=part.replace("_", " "))
    for i, (_, otr) in enumerate(runs[1:]):
        x = (otr.t - SOAK) / 60.0
        if not np.array_equal(otr.chamber, tr.chamber):
            ax.plot(x, otr.chamber - ZERO_CELSIUS, color="0.6", lw=0.8)
        shaft = f"shaft ({', '.join(o.label for o, _ in runs[1:])})" if i == 0 else None
        ax.plot(x, otr.parts["shaft"] - ZERO_CELSIUS, "C1--", lw=0.7, label=shaft)
    ax.set_ylabel("temperature [°C]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="best")


def _plot_pair(ax, runs, what, scale, label):
    for i, (profile, tr) in enumerate(runs):
        x = (tr.t - SOAK) / 60.0
        colour = f"C{i + 2}"
        ax.plot(x, getattr(tr, what) * scale, "-", color=colour, lw=1.2, label=profile.label)
        ax.plot(x, getattr(tr, f"qs_{what}") * scale, "--", color=colour, lw=1.0)
        # the transient flags as bands: locked (no radial clearance), overloaded
        for flag, shade in (("locked", "red"), ("overloaded", "black")):
            on = tr.flags[flag]
            for j, k in _spans(on):
                ax.axvspan(x[j], x[k], color=shade, alpha=0.12, lw=0)
            if what == "preload" and i == 0 and any(np.any(r.flags[flag]) for _, r in runs):
                ax.axvspan(np.nan, np.nan, color=shade, alpha=0.12, label=f"{flag} (any run)")
    ax.set_ylabel(label)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="best")


def _spans(on: np.ndarray) -> list[tuple[int, int]]:
    """Index ranges [j, k] of the runs of True in ``on``."""
    edges = np.flatnonzero(np.diff(np.concatenate(([0], on.astype(int), [0]))))
    return [(j, min(k, len(on) - 1)) for j, k in zip(edges[::2], edges[1::2], strict=True)]

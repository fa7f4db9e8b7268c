"""The ``servofmu`` command line: a thin layer over the library API."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from . import __version__
from .harness.scenarios import SCENARIOS
from .papers import PAPERS


def _paper(args) -> int:
    from .papers import run

    report = run(args.name, Path(args.out or f"out/{args.name}"))
    print(report.dumps() if args.json else report.to_text())
    return 0


def _build(args) -> int:
    from servofmu.build import catalogs
    from servofmu.build.fmu import FMUS, build_all

    # user catalogues and presets are checked before anything is built (exit 2 on an error)
    defaults = catalogs.load(args.catalog, args.preset, args.lubricant, args.support_mounting)
    try:
        for path in build_all(Path(args.out), args.names or FMUS, defaults=defaults):
            print(path)
    finally:
        catalogs.unload()
    _note_export()
    return 0


def _note_export() -> None:
    """Say on stderr when the FMUs carry pythonfmu's binary (no compiled servofmu export)."""
    from servofmu.build.exportlib import PYTHONFMU, export_used

    if export_used() == PYTHONFMU:
        print(
            "servofmu: note: servofmu's export library was not compiled when servofmu was "
            "installed (it needs a C++17 compiler): the FMUs carry pythonfmu's binary, under "
            "which a host's mistake is logged and discards the next step instead of getting "
            "fmi2Error (README, 'Bad input and careless hosts')",
            file=sys.stderr,
        )


def _catalog(args) -> int:
    """List the catalogue, or print (and write as .ssv) one preset's parameter set."""
    from servofmu.build import catalogs

    catalogs.load(args.catalog)
    try:
        if not (args.preset or args.bearing or args.lubricant):
            if args.ssv:
                raise ValueError("--ssv writes a preset: name it with --preset MOUNTING")
            print(catalogs.listing())
            return 0
        from servofmu.parameter_sets import write_ssv
        from servofmu.physics.bearing_parameters import (
            DEFAULT_MOUNTING,
            default_parameters,
            default_sources,
        )

        mounting = args.preset or DEFAULT_MOUNTING
        kw = {"bearing": args.bearing, "lubricant": args.lubricant}
        values = default_parameters(mounting, **kw)
        what = ", ".join(f"{k} {v}" for k, v in {"mounting": mounting, **kw}.items() if v)
        print(f"preset: {what}")
        print(catalogs.preset_table(values, default_sources(mounting, **kw)))
        if args.ssv:
            print(f"file: {write_ssv(values, args.ssv, args.component, comment='preset: ' + what)}")
    finally:
        catalogs.unload()
    return 0


def _validate(args) -> int:
    from servofmu.build.validate import validate

    failed = 0
    for path in args.fmus:
        problems = validate(path)
        print(f"{path}: {'OK' if not problems else f'{len(problems)} problem(s)'}")
        for p in problems:
            print(f"  - {p}")
        failed += bool(problems)
    return 1 if failed else 0


def _host_env(args) -> int:
    from servofmu.build.host import host_environment_text

    print(host_environment_text())
    return 0


def _system_path(arg: str) -> tuple[Path, Path | None]:
    """(path, fmu_dir) for ``servofmu run``: an .ssp, a system folder (its FMUs taken from the
    build), or the name of a system in ssp/ (its built .ssp)."""
    from servofmu.build.fmu import DEFAULT_OUT, ensure_built
    from servofmu.build.ssp import systems
    from servofmu.harness.scenarios.common import system_path

    names = [s.name for s in systems()]
    path = Path(arg)
    if path.exists():
        return path, (ensure_built(DEFAULT_OUT) if path.is_dir() or path.suffix == ".ssd" else None)
    if arg in names:
        return system_path(arg), None
    raise ValueError(f"system = {arg!r}: no such file or folder, nor one of {names}")


def _value(text: str):
    """A float when the text reads as one, else the text (catalogue keys)."""
    try:
        return float(text)
    except ValueError:
        return text.strip()


def _set_known(params: dict, items: list[str]) -> dict:
    """Apply --set NAME=VALUE items to ``params``: NAME must be one of its keys; the value is
    text where the parameter is text, else a number."""
    for item in items:
        key, sep, text = item.partition("=")
        key = key.strip()
        if not sep or key not in params:
            raise ValueError(f"--set {item!r}: write NAME=VALUE with NAME one of {list(params)}")
        if isinstance(params[key], str):  # a catalogue key stays text, even "71803"
            params[key] = text.strip()
            continue
        value = _value(text)
        if isinstance(value, str):
            raise ValueError(f"--set {item!r}: {key} takes a number")
        params[key] = value
    return params


def _parameters(items: list[str]) -> list:
    """--parameters values: a variant name, or comp.var=value (text: the harness converts it
    to the variable's type)."""
    out = []
    for item in items:
        if "=" not in item:
            out.append(item)
            continue
        target, _, text = item.partition("=")
        out.append({target.strip(): text.strip()})
    return out


def _signals(items: list[str]) -> dict:
    """--signal comp.input=FILE.csv:column (piecewise linear over the CSV's time column)."""
    from servofmu.harness import from_csv

    out = {}
    for item in items:
        target, sep, spec = item.partition("=")
        file, sep2, column = spec.rpartition(":")
        if not sep or not sep2:
            raise ValueError(f"--signal {item!r}: write it as comp.input=FILE.csv:column")
        out[target.strip()] = from_csv(file, column)
    return out


def _run(args) -> int:
    from servofmu.harness import HarnessError, load_system, run
    from servofmu.harness.interrupt import interruptible
    from servofmu.harness.master import check_run

    path, fmu_dir = _system_path(args.system)
    try:
        system = load_system(path, fmu_dir=fmu_dir)
    except HarnessError as exc:  # also an unreadable archive: bad input, exit 2
        print(f"servofmu: error: {exc}", file=sys.stderr)
        return 2
    out = Path(args.out or f"out/{system.name}")
    try:  # a failed run (HarnessError) is reported by main(): exit 1, partial results kept
        signals = _signals(args.signal)
        _check_plot(system, args.plot or [], signals)
        record = [*args.record, *(n for n in args.plot or [] if n not in args.record)]
        kwargs = dict(
            parameters=_parameters(args.parameters),
            signals=signals,
            start=args.start,
            stop=args.stop,
            step=args.step,
            algorithm=args.algorithm,
            record=record if args.record else None,
            output_interval=args.output_interval,
        )
        plan = check_run(system, **kwargs)  # every argument, before any FMU is instantiated
        with interruptible():  # Ctrl-C from here on: stop at a step boundary, exit 130
            print(
                f"{system.name}: {plan.n_steps} steps of {plan.step:g} s from t = "
                f"{plan.start:g} to {plan.stop:g} s (Ctrl-C stops at the next step and keeps "
                "the results)",
                flush=True,
            )
            res = run(system, out_dir=out, **kwargs)
    finally:
        system.close()
    span = res["time"][-1] - res["time"][0]
    print(
        f"{res.system}: {len(res.data) - 1} steps to t = {res['time'][-1]:.6g} s in "
        f"{res.wall_time:.3g} s wall, set-up included ({span / res.wall_time:.3g}× real time)"
    )
    print(f"results: {res.csv}")
    if args.plot:
        print(f"plot: {res.plot(out / 'results.png', args.plot)}")
    return 0


def _check_plot(system, names: list[str], signals: dict) -> None:
    """--plot names: variables the run records (outputs, or inputs driven by --signal)."""
    from servofmu.harness import HarnessError
    from servofmu.harness.errors import ArgumentError

    for name in names:
        try:
            _, var = system.variable(name)
        except HarnessError as exc:
            raise ArgumentError(f"--plot {exc}") from None
        if not (var.causality == "output" and var.type in ("Real", "Boolean")) and (
            name not in signals
        ):
            raise ArgumentError(
                f"--plot {name!r}: it is a {var.type} {var.causality}; only Real and Boolean "
                "outputs and inputs driven by --signal are recorded"
            )


def _scenario(args) -> int:
    from servofmu.harness.scenarios import run

    result = run(args.name, Path(args.out or f"out/{args.name}"), coarse=args.coarse)
    print(result.to_text())
    return 0


def _mounting_for(bearing: str) -> str:
    """The catalogue mounting of ``bearing`` when it has exactly one; otherwise the user must
    name it (the mounting decides fits, preload loop and materials: a wrong default fits
    nothing, or fits wrong coefficients)."""
    from .physics import catalog

    keys = [k for k in catalog.keys("mountings") if catalog.mounting(k).bearing_key == bearing]
    if len(keys) == 1:
        return keys[0]
    if not keys:
        raise ValueError(
            f"bearing = {bearing!r}: no catalogue mounting for it; name one with --mounting "
            f"({catalog.keys('mountings')})"
        )
    raise ValueError(
        f"--mounting is required: bearing {bearing} has {len(keys)} catalogue mountings, and "
        f"the one the data were measured on decides fits, preload loop and materials; name "
        f"one of {keys} (physics/data/mountings.toml describes each)"
    )


def _calibrate_datasheet(args) -> int:
    """``servofmu calibrate --datasheet LUBRICANT``: the grease term on a datasheet's
    low-temperature torque (calibration/datasheet.py)."""
    from .calibration import write_ssv
    from .calibration.datasheet import GREASE_PARAMETERS, calibrate_datasheet, to_text

    other = [
        f"--{n.replace('_', '-')}"
        for n in ("data", "bearing", "mounting", "lubricant", "fit", "speed")
        if getattr(args, n)
    ] + (["--set"] if args.set else [])
    if other:
        raise ValueError(
            f"--datasheet fits the grease term on the datasheet's own test bearing: "
            f"{', '.join(other)} do not apply (bind the written set on your bearing's)"
        )
    cal = calibrate_datasheet(args.datasheet, args.test)
    out = Path(args.out or f"out/calibration/datasheet_{args.datasheet}")
    out.mkdir(parents=True, exist_ok=True)
    ssv = out / "calibrated.ssv"
    files = [out / "report.txt"]
    if cal.poor and not args.allow_poor_fit:
        ssv.unlink(missing_ok=True)
    else:
        comment = (
            f"grease term of {cal.lubricant} calibrated on its {cal.test} datasheet torque "
            f"(servofmu calibrate --datasheet {cal.lubricant}), with its base oil"
        )
        files.append(
            write_ssv(
                cal.parameters, ssv, component=args.component, only=GREASE_PARAMETERS,
                comment=comment,
            )
        )  # fmt: skip
    text = to_text(cal)
    (out / "report.txt").write_text(text + "\n")
    if args.json:
        import json

        print(json.dumps(cal.as_dict(), indent=2))
    else:
        print(text)
        print("\n".join(f"file: {f}" for f in files))
    if cal.poor:
        if not args.allow_poor_fit:
            print(
                f"servofmu: calibration failed: {cal.problems[0]}; no calibrated.ssv written "
                f"(report in {out / 'report.txt'}; --allow-poor-fit writes it anyway)",
                file=sys.stderr,
            )
            return 1
        print(f"servofmu: warning: poor fit accepted (--allow-poor-fit): {cal.problems[0]}",
              file=sys.stderr)  # fmt: skip
    return 0


def _calibrate(args) -> int:
    if args.datasheet:
        return _calibrate_datasheet(args)
    if args.test:
        raise ValueError("--test names the datasheet test of --datasheet")
    if not args.data:
        raise ValueError("name DATA.csv of measured friction torque, or --datasheet LUBRICANT")
    from .calibration import (
        UNKNOWNS,
        calibrate,
        parse_quantity,
        plot,
        read_measurements,
        to_text,
        write_residuals,
        write_ssv,
    )
    from .physics.bearing_parameters import default_parameters, pair_from_parameters

    # every argument first: nothing is read or fitted with a bad one
    mounting = args.mounting or _mounting_for(args.bearing or "71803")
    params = default_parameters(  # the presets' numbers; --set numbers win
        mounting, args.lubrication, bearing=args.bearing, lubricant=args.lubricant
    )
    _set_known(params, args.set)
    pair_from_parameters(params)  # a catalogue key or value that does not fit: exit 2
    speed = parse_quantity(args.speed, "speed") if args.speed else None
    if speed is not None and not (np.isfinite(speed) and speed >= 0.0):
        raise ValueError(f"--speed {args.speed!r}: the test speed must be finite and ≥ 0")
    unknowns = (
        [u.strip() for u in args.fit.split(",") if u.strip()]
        if args.fit
        else (
            ["palmgren_s0", "sliding_friction"]
            if args.lubrication == "grease"
            else ["sliding_friction"]
        )
    )
    for name in unknowns:
        if name not in UNKNOWNS:
            raise ValueError(f"--fit {args.fit}: {name!r} is not one of {list(UNKNOWNS)}")
    data = read_measurements(args.data)
    cal = calibrate(data, params, unknowns, speed=speed, residual=args.residual)
    out = Path(args.out or f"out/calibration/{Path(args.data).stem}")
    files = [write_residuals(cal, out / "residuals.csv"), plot(cal, out / "calibration.png")]
    ssv = out / "calibrated.ssv"
    if cal.poor and not args.allow_poor_fit:
        ssv.unlink(missing_ok=True)  # no parameter set of an earlier run passes for this one
    else:
        files.append(write_ssv(cal.parameters, ssv, component=args.component))
    text = to_text(cal)
    (out / "report.txt").write_text(text + "\n")
    if args.json:
        import json

        print(json.dumps(cal.as_dict(), indent=2))
    else:
        print(text)
        print("\n".join(f"file: {f}" for f in [out / "report.txt", *files]))
    if cal.poor:
        what = f"{cal.problems[0]}" + (
            f" (and {len(cal.problems) - 1} more)" if len(cal.problems) > 1 else ""
        )
        if not args.allow_poor_fit:
            print(
                f"servofmu: calibration failed: {what}; no calibrated.ssv written (report in "
                f"{out / 'report.txt'}; --allow-poor-fit writes it anyway)",
                file=sys.stderr,
            )
            return 1
        print(f"servofmu: warning: poor fit accepted (--allow-poor-fit): {what}", file=sys.stderr)
    return 0


def _axis(item: str) -> tuple[str, list]:
    """--grid NAME=V1,V2,... or NAME=LO:HI:N (N values, ends included)."""
    name, sep, spec = item.partition("=")
    if not sep or not spec:
        raise ValueError(f"--grid {item!r}: write NAME=V1,V2,... or NAME=LO:HI:N")
    if ":" in spec:
        try:
            lo, hi, n = spec.split(":")
            values = [float(v) for v in np.linspace(float(lo), float(hi), int(n))]
        except ValueError:
            raise ValueError(f"--grid {item!r}: LO:HI:N needs two numbers and a count") from None
        return name.strip(), values
    return name.strip(), [_value(v) for v in spec.split(",")]


def _distribution(item: str):
    """--sample NAME=uniform:LO:HI | normal:MEAN:SD | choice:A,B,..."""
    from servofmu.harness.sweep import Choice, Normal, Uniform

    name, _, spec = item.partition("=")
    kind, _, rest = spec.partition(":")
    try:
        if kind == "uniform":
            lo, hi = (float(v) for v in rest.split(":"))
            return name.strip(), Uniform(lo, hi)
        if kind == "normal":
            mean, sd = (float(v) for v in rest.split(":"))
            return name.strip(), Normal(mean, sd)
        if kind == "choice" and rest:
            return name.strip(), Choice(tuple(_value(v) for v in rest.split(",")))
    except ValueError:
        pass
    raise ValueError(
        f"--sample {item!r}: write NAME=uniform:LO:HI, NAME=normal:MEAN:SD or NAME=choice:A,B"
    )


def _sweep(args) -> int:
    from servofmu.harness.interrupt import received
    from servofmu.harness.sweep import (
        ModelTask,
        SystemTask,
        check_table_path,
        cross,
        grid_points,
        run_sweep,
        sample_points,
    )
    from servofmu.physics.bearing_parameters import default_parameters

    out = Path(args.out or "out/sweep/results.csv")
    check_table_path(out)
    axes = dict(_axis(g) for g in args.grid)
    dists = dict(_distribution(s) for s in args.sample)
    samples = sample_points(dists, args.samples, args.seed) if dists else []
    points = cross(samples, grid_points(axes) if axes else [])
    if not points:
        raise ValueError("give at least one --grid or --sample")
    if args.target == "model":
        base = _set_known(default_parameters(args.mounting, args.lubrication), args.set)
        task = ModelTask(base, tuple(args.record)) if args.record else ModelTask(base)
    else:
        if args.set or not args.record:
            raise ValueError(
                "a system sweep takes --record comp.var (what to report) and no --set "
                "(give fixed values as a one-value --grid)"
            )
        path, fmu_dir = _system_path(args.target)
        if fmu_dir is not None or path.suffix != ".ssp":
            raise ValueError(f"{args.target}: a system sweep needs a packed .ssp or a system name")
        task = SystemTask(
            path.read_bytes(), tuple(args.record), args.stop, args.step, tail=args.tail
        )
    result = run_sweep(
        task, points, workers=args.workers, scheduler=args.scheduler, chunk_size=args.chunk
    )
    result.write(out)
    if result.interrupted:
        done = len(result.rows) - len(result.failed)
        print(
            f"servofmu: interrupted: {done} of {len(result.rows)} runs finished; the others are "
            f"marked 'interrupted' in {out}",
            file=sys.stderr,
        )
        return 128 + received()
    print(
        f"{len(result.rows)} runs on {result.workers} worker(s) in {result.wall_time:.3g} s; "
        f"{len(result.failed)} failed; table: {out}"
    )
    for row in result.failed[:10]:
        print(f"  failed: {row}")
    return 1 if result.failed and len(result.failed) == len(result.rows) else 0


def _montecarlo(args) -> int:
    from servofmu.harness.tolerance import run

    result = run(
        Path(args.out or "out/montecarlo"),
        samples=args.samples,
        seed=args.seed,
        workers=args.workers,
        scheduler=args.scheduler,
        mounting=args.mounting,
    )
    print(result.to_text())
    return 0


class _Parser(argparse.ArgumentParser):
    """argparse with its errors on one line (no usage block): exit 2."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def _seconds(text: str) -> float:
    """A finite time [s] (argparse type)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of seconds") from None
    if not np.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text!r} s is not finite")
    return value


def _positive_seconds(text: str) -> float:
    """A finite time > 0 [s] (argparse type)."""
    value = _seconds(text)
    if not value > 0:
        raise argparse.ArgumentTypeError(f"{text!r} s must be > 0")
    return value


def _count(text: str) -> int:
    """A whole number ≥ 1 (argparse type)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text!r} must be ≥ 1")
    return value


def _fraction(text: str) -> float:
    """A fraction in [0, 1) (argparse type)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not 0.0 <= value < 1.0:
        raise argparse.ArgumentTypeError(f"{text!r} must lie in [0, 1)")
    return value


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="servofmu", description="Temperature-aware servo-mechanism physics and FMUs."
    )
    parser.add_argument("--version", action="version", version=f"servofmu {__version__}")
    parser.add_argument(
        "--debug", action="store_true", help="show the traceback of an internal error"
    )
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser(
        "paper",
        help="reproduce a source paper: validation report, CSV curves, PNG figures",
    )
    p.add_argument("name", choices=PAPERS, help="which paper")
    p.add_argument("--json", action="store_true", help="print the report as JSON")
    p.add_argument("--out", help="directory for CSV and PNG files (default out/NAME)")
    p.set_defaults(func=_paper)
    b = sub.add_parser("build", help="build the FMUs (pythonfmu) into build/out")
    b.add_argument("names", nargs="*", help="FMUs to build (default: all five)")
    b.add_argument("--out", default="build/out", help="output directory (default build/out)")
    b.add_argument(
        "--catalog",
        action="append",
        default=[],
        metavar="FILE.toml",
        help="a user catalogue (bearings, lubricants, materials, mountings; format: "
        "examples/my_gimbal_catalog.toml) merged into the presets; its [defaults] fill the "
        "start values",
    )
    b.add_argument("--preset", metavar="MOUNTING", help="mounting whose numbers (its bearing "
                   "and lubricant) become BearingFriction's start values")  # fmt: skip
    b.add_argument("--lubricant", help="lubricant of BearingFriction's start values")
    b.add_argument("--support-mounting", metavar="MOUNTING",
                   help="mounting of ActuatorStiffness's support pair (start values)")  # fmt: skip
    b.set_defaults(func=_build)
    k = sub.add_parser(
        "catalog",
        help="list the catalogue (bearings, lubricants, materials, mountings) or print a "
        "preset's parameter set (and write it as .ssv)",
    )
    k.add_argument("--catalog", action="append", default=[], metavar="FILE.toml",
                   help="a user catalogue merged into the listing")  # fmt: skip
    k.add_argument("--preset", metavar="MOUNTING", help="print this mounting's parameter set")
    k.add_argument("--bearing", help="with the numbers of this catalogue bearing")
    k.add_argument("--lubricant", help="with this catalogue lubricant")
    k.add_argument("--ssv", metavar="FILE.ssv", help="write the preset as an SSP parameter set")
    k.add_argument("--component", help="prefix the names in the .ssv (a system variant)")
    k.set_defaults(func=_catalog)
    v = sub.add_parser(
        "validate", help="validate FMUs (fmpy + servofmu checks); exit 1 on problems"
    )
    v.add_argument("fmus", nargs="+", help="FMU files")
    v.set_defaults(func=_validate)
    r = sub.add_parser(
        "run", help="co-simulate an SSP system with the harness; results as CSV (and a plot)"
    )
    r.add_argument(
        "system", help="an .ssp archive, a system folder, or a system name (e.g. seeker_gimbal)"
    )
    r.add_argument(
        "--parameters",
        action="append",
        default=[],
        metavar="NAME|comp.var=VALUE",
        help="a parameter-set variant (variants/NAME.ssv) or one value; repeatable, in order",
    )
    r.add_argument(
        "--signal",
        action="append",
        default=[],
        metavar="comp.input=FILE.csv:column",
        help="drive an unconnected input from a CSV column over its 'time' column; repeatable",
    )
    r.add_argument("--start", type=_seconds, help="start time [s] (default: the SSD's)")
    r.add_argument("--stop", type=_seconds, help="stop time [s] (default: the SSD's)")
    r.add_argument(
        "--step", type=_positive_seconds, help="communication step [s] (default: the SSD's)"
    )
    r.add_argument("--algorithm", choices=("gauss-seidel", "jacobi"), default="gauss-seidel")
    r.add_argument(
        "--output-interval",
        type=_positive_seconds,
        help="keep a row every this many seconds, a multiple of the step (default: all)",
    )
    r.add_argument(
        "--record", action="append", default=[], metavar="comp.var", help="record only these"
    )
    r.add_argument("--plot", nargs="+", metavar="comp.var", help="plot these to results.png")
    r.add_argument("--out", help="output directory (default out/SYSTEM)")
    r.set_defaults(func=_run)
    s = sub.add_parser(
        "scenario", help="run a system-level scenario (the papers' experiments in co-simulation)"
    )
    s.add_argument("name", choices=SCENARIOS, help="which scenario")
    s.add_argument("--coarse", action="store_true", help="shorter runs (as the tests use)")
    s.add_argument("--out", help="directory for CSV and PNG files (default out/NAME)")
    s.set_defaults(func=_scenario)
    w = sub.add_parser(
        "sweep",
        help="many independent model evaluations or co-simulations on Dask (grid / sample)",
        description="Run the bearing model ('model') or an SSP system over a grid and/or a "
        "random sample of parameters on a Dask LocalCluster (or --scheduler). Values in SI. "
        "Every sample is crossed with every grid point. Model parameters: the BearingFriction "
        "parameter names and the inputs temperature, speed, axial_load, radial_load; system "
        "parameters: component.variable.",
    )
    w.add_argument("target", help="'model', or an .ssp / system name (e.g. seeker_gimbal)")
    w.add_argument("--grid", action="append", default=[], metavar="NAME=V1,V2|LO:HI:N")
    w.add_argument(
        "--sample",
        action="append",
        default=[],
        metavar="NAME=uniform:LO:HI|normal:MEAN:SD|choice:A,B",
    )
    w.add_argument("--samples", type=_count, default=100, help="random draws (default 100)")
    w.add_argument("--seed", type=int, default=0)
    w.add_argument("--mounting", default="yu2017_gimbal", help="model: catalogue mounting")
    w.add_argument("--lubrication", choices=("grease", "solid"), default="grease")
    w.add_argument("--set", action="append", default=[], metavar="NAME=VALUE", help="model")
    w.add_argument(
        "--record", action="append", default=[], help="outputs to report (system: required)"
    )
    w.add_argument("--stop", type=_seconds, help="system: stop time [s]")
    w.add_argument("--step", type=_positive_seconds, help="system: communication step [s]")
    w.add_argument(
        "--tail", type=_fraction, default=0.0, help="system: average over this last fraction"
    )
    w.add_argument("--workers", type=_count, help="LocalCluster worker processes (default: cores)")
    w.add_argument("--scheduler", help="address of a running Dask scheduler")
    w.add_argument("--chunk", type=_count, help="points per task (default: ~4 tasks per worker)")
    w.add_argument("--out", help="table: .csv or .parquet (default out/sweep/results.csv)")
    w.set_defaults(func=_sweep)
    mc = sub.add_parser(
        "montecarlo",
        help="Monte-Carlo tolerance study: fit and shim from their tolerances, torque and "
        "overload probability versus temperature",
    )
    mc.add_argument("--samples", type=_count, default=500)
    mc.add_argument("--seed", type=int, default=1)
    mc.add_argument("--mounting", default="yu2017_gimbal")
    mc.add_argument("--workers", type=_count)
    mc.add_argument("--scheduler")
    mc.add_argument("--out", help="directory (default out/montecarlo)")
    mc.set_defaults(func=_montecarlo)
    c = sub.add_parser(
        "calibrate",
        help="fit a bearing pair's unknown coefficients to measured friction torque (CSV)",
        description="Fit the unknown coefficients of a bearing pair to measured running "
        "friction torque versus temperature. DATA.csv has a header naming each column with "
        "its unit: 'temperature [degC]' or '[K]', 'torque [N.mm]' or '[N.m]', optionally "
        "'speed [deg/s]', '[rad/s]' or '[rpm]' and 'direction' (forward/reverse); '#' lines "
        "are comments. Or, with --datasheet LUBRICANT, calibrate the grease term (grease_f0, "
        "grease_starting_ratio) on the grease's published low-temperature torque test "
        "(physics/data/grease_torques.toml).",
    )
    c.add_argument("data", nargs="?", help="CSV file of measured friction torque")
    c.add_argument(
        "--datasheet",
        metavar="LUBRICANT",
        help="calibrate the grease term on this grease's datasheet low-temperature torque "
        "(ASTM D1478 / JIS K 2220 points of physics/data/grease_torques.toml) instead of DATA",
    )
    c.add_argument(
        "--test",
        metavar="KEY",
        help="with --datasheet: the test whose points to use (jis_k2220, astm_d1478) when the "
        "grease has points of several",
    )
    c.add_argument(
        "--bearing", help="bearing designation (default: the mounting's; 71803 without one)"
    )
    c.add_argument(
        "--mounting",
        help="catalogue mounting the data were measured on (required when the bearing has "
        "more than one, as the 71803: yu2017_gimbal, yu2017_gimbal_printed, …)",
    )
    c.add_argument("--lubrication", choices=("grease", "solid"), default="grease")
    c.add_argument("--lubricant", help="catalogue lubricant (default: the lubrication's)")
    c.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="a known value of the pair in SI (e.g. outer_interference=1.6e-5); repeatable",
    )
    c.add_argument(
        "--fit",
        metavar="A,B,...",
        help="unknowns: palmgren_s0, hysteresis_loss, sliding_friction, loop_stiffness "
        "(default: palmgren_s0,sliding_friction for grease, sliding_friction for solid)",
    )
    c.add_argument(
        "--speed", metavar="'VALUE UNIT'", help="test speed when DATA has no speed column"
    )
    c.add_argument("--residual", choices=("relative", "absolute"), default="relative")
    c.add_argument(
        "--component",
        help="write component.name parameters (an SSP variant) instead of bare names",
    )
    c.add_argument(
        "--allow-poor-fit",
        action="store_true",
        help="accept a fit at a bound or missing the data beyond their scatter: write "
        "calibrated.ssv and exit 0 (the report still says POOR FIT)",
    )
    c.add_argument("--json", action="store_true", help="print the result as JSON")
    c.add_argument("--out", help="output directory (default out/calibration/DATA)")
    c.set_defaults(func=_calibrate)
    h = sub.add_parser("host-env", help="environment a non-Python FMI host must set for our FMUs")
    h.set_defaults(func=_host_env)
    return parser


def _error_log() -> Path:
    """The traceback of the exception being handled, in a new file only the user can read
    (``mkstemp``: a fresh name, created exclusively, mode 0600); its path."""
    import os
    import tempfile
    import traceback

    fd, name = tempfile.mkstemp(prefix="servofmu-error-", suffix=".log")
    with os.fdopen(fd, "w", encoding="utf-8") as fh:
        fh.write(traceback.format_exc())
    return Path(name)


def main(argv: list[str] | None = None) -> int:
    """Exit codes: 0 done, 1 a run failed (partial results kept), 2 bad input (data,
    arguments, system description), 3 an internal error (traceback in a private log file),
    130 interrupted by Ctrl-C and 143 by SIGTERM (a run stops at a step boundary and keeps its
    results either way)."""
    from .harness.errors import ArgumentError, HarnessError, Interrupted, SystemError_
    from .harness.interrupt import received, terminate_as_interrupt

    args = build_parser().parse_args(argv)
    terminate_as_interrupt()  # SIGTERM keeps the results so far, as Ctrl-C does
    try:
        return args.func(args)
    except (SystemError_, ArgumentError) as exc:  # bad input, found before any run
        print(f"servofmu: error: {exc}", file=sys.stderr)
        return 2
    except Interrupted as exc:
        print(f"servofmu: {exc}", file=sys.stderr)
        return 128 + exc.signum
    except KeyboardInterrupt as exc:
        print(f"servofmu: interrupted{f'; {exc}' if str(exc) else ''}", file=sys.stderr)
        return 128 + received()
    except HarnessError as exc:
        print(f"servofmu: run failed: {exc}", file=sys.stderr)
        return 1
    except (ValueError, OSError) as exc:
        print(f"servofmu: error: {exc}", file=sys.stderr)
        return 2
    except Exception as exc:
        if args.debug:
            raise
        log = _error_log()
        print(
            f"servofmu: internal error: {type(exc).__name__}: {exc} (traceback in {log}; "
            "run again with --debug to see it here)",
            file=sys.stderr,
        )
        return 3


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

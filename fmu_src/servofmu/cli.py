"""The ``servofmu`` command line: a thin layer over the library API."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from . import __version__
from .files import EXIT_OUTPUT, OutputError, output_folder, write_text
from .harness.scenarios import SCENARIOS
from .papers import PAPERS


def _paper(args) -> int:
    from .papers import run

    report = run(args.name, Path(args.out or f"out/{args.name}"))
    print(report.dumps() if args.json else report.to_text())
    return 0


def _mechanism(args):
    """The mechanism of a command's --catalog, --mounting (and --lubricant,
    --support-mounting where it has them): a context manager yielding a
    :class:`~servofmu.build.mechanism.Mechanism`, its catalogues merged until it exits. Every
    error (a bad file, entry or key) is a ValueError before any work starts."""
    from servofmu.build.mechanism import open_mechanism

    return open_mechanism(
        getattr(args, "catalog", ()),
        getattr(args, "mounting", None),
        getattr(args, "lubricant", None),
        getattr(args, "support_mounting", None),
    )


def _build(args) -> int:
    from servofmu.build.fmu import FMUS, build_all, refuse_other_mechanism

    # user catalogues and presets are checked before anything is built (exit 2 on an error)
    with _mechanism(args) as mechanism:
        out = Path(args.out) if args.out else mechanism.build_dir
        refuse_other_mechanism(out, mechanism)
        _say_mechanism(mechanism)
        for path in build_all(out, args.names or FMUS, defaults=mechanism.defaults):
            print(path)
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

    with _mechanism(argparse.Namespace(catalog=args.catalog)):
        if not (args.mounting or args.bearing or args.lubricant):
            if args.ssv:
                raise ValueError("--ssv writes a preset: name it with --mounting KEY")
            print(catalogs.listing())
            return 0
        from servofmu.parameter_sets import write_ssv
        from servofmu.parameters.bearing import (
            DEFAULT_MOUNTING,
            default_parameters,
            default_sources,
        )
        from servofmu.parameters.presets import coefficient_set

        mounting = args.mounting or DEFAULT_MOUNTING
        kw = {"bearing": args.bearing, "lubricant": args.lubricant}
        values = default_parameters(mounting, **kw)
        what = ", ".join(f"{k} {v}" for k, v in {"mounting": mounting, **kw}.items() if v)
        coefficients = coefficient_set(mounting).label
        print(f"preset: {what}")
        print(f"friction coefficients: {coefficients}")
        print(catalogs.preset_table(values, default_sources(mounting, **kw)))
        if args.ssv:
            comment = f"preset: {what}; friction coefficients {coefficients}"
            print(f"file: {write_ssv(values, args.ssv, args.component, comment=comment)}")
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


def _examples(args) -> int:
    """List the shipped example files, or copy them into a folder."""
    from servofmu.examples_files import copy_examples, example_files

    if args.dest is None:
        for path in example_files():
            print(path)
        return 0
    for path in copy_examples(Path(args.dest), overwrite=args.force):
        print(path)
    return 0


def _host_env(args) -> int:
    from servofmu.build.host import host_environment_text

    print(host_environment_text())
    return 0


def _system_path(arg: str, mechanism=None) -> tuple[Path, Path | None]:
    """(path, fmu_dir) for ``servofmu run`` and ``sweep``: an .ssp, a system folder (its FMUs
    taken from the mechanism's build), or the name of a system of the mechanism's build (its
    .ssp in the build folder, built there when missing or stale; default: the standard
    mechanism in build/out)."""
    from servofmu.build.fmu import ensure_built
    from servofmu.build.mechanism import resolve
    from servofmu.build.ssp import SSP_DIR, systems
    from servofmu.physics._checks import suggest

    path = Path(arg)
    if path.exists():
        if path.suffix == ".ssp" and mechanism is not None and not mechanism.standard:
            raise ValueError(
                f"system = {arg!r}: an .ssp carries its own FMUs and bindings; --catalog and "
                "--mounting choose the mechanism of a system name or folder"
            )
        folder = path.is_dir() or path.suffix == ".ssd"
        return path, (ensure_built(mechanism=mechanism) if folder else None)
    mechanism = mechanism or resolve(_standard())
    names = [s.name for s in systems(names=mechanism.systems)]
    if arg in names:
        return ensure_built(mechanism=mechanism) / f"{arg}.ssp", None
    others = [s.name for s in systems() if s.name not in names]
    raise ValueError(
        f"system = {arg!r}: no such .ssp file or system folder here, nor a system of "
        f"{mechanism.key}{suggest(arg, names)}; its systems are {names} (sources in "
        f"{SSP_DIR}, built into {mechanism.build_dir} by `servofmu build`)"
        + (f"; {others} run the standard mechanism only" if others else "")
    )


def _standard():
    from servofmu.build.catalogs import Defaults

    return Defaults()


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
            from .physics._checks import suggest

            raise ValueError(
                f"--set {item!r}: write NAME=VALUE with NAME one of {list(params)}"
                + (suggest(key, params) if sep else "")
            )
        if isinstance(params[key], str):  # a catalogue key stays text, even "71803"
            params[key] = text.strip()
            continue
        value = _value(text)
        if isinstance(value, str):
            raise ValueError(f"--set {item!r}: {key} takes a number")
        params[key] = value
    return params


def _parameters(items: list[str], system=None) -> list:
    """--parameters values: a variant name, an .ssv file (a parameter set: a variant's
    ``comp.var`` names, or a component's bare names), or comp.var=value (text: the harness
    converts it to the variable's type)."""
    from servofmu.harness.system import parameter_file

    out = []
    for item in items:
        if item.endswith(".ssv") and "=" not in item:
            out.append(parameter_file(system, item))
        elif "=" not in item:
            out.append(item)
        else:
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
    with _mechanism(args) as mechanism:
        path, fmu_dir = _system_path(args.system, mechanism)
        _say_mechanism(mechanism)
        return _run_system(args, path, fmu_dir)


def _say_mechanism(mechanism) -> None:
    """One line on a mechanism other than the standard one: what it is, and its friction
    coefficients (uncalibrated until calibrated)."""
    if not mechanism.standard:
        print(
            f"mechanism {mechanism.describe()}; friction coefficients "
            f"{mechanism.coefficients.label}",
            flush=True,
        )


def _run_system(args, path, fmu_dir) -> int:
    from servofmu.harness import HarnessError, load_system, run
    from servofmu.harness.interrupt import interruptible
    from servofmu.harness.master import check_run

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
            parameters=_parameters(args.parameters, system),
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
    for text in res.warnings:  # the model left its data, a value was clipped, ...
        print(f"warning: {text}", file=sys.stderr)
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
    from servofmu.harness.scenarios import check_mechanism, run

    with _mechanism(args) as mechanism:
        check_mechanism(args.name, mechanism)
        out = Path(args.out or f"out/{args.name}")
        result = run(args.name, out, coarse=args.coarse, mechanism=mechanism, workers=args.workers)
    print(result.to_text())
    return 0


def _mounting_for(bearing: str) -> str:
    """The catalogue mounting of ``bearing`` when it has exactly one; otherwise the user must
    name it (the mounting decides fits, preload loop and materials: a wrong default fits
    nothing, or fits wrong coefficients)."""
    from .parameters import catalog

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
        f"one of {keys} (parameters/data/mountings.toml describes each)"
    )


def _calibrate_datasheet(args) -> int:
    """``servofmu calibrate --datasheet LUBRICANT``: the grease term on a datasheet's
    low-temperature torque (calibration/datasheet.py)."""
    from .calibration import write_ssv
    from .calibration.datasheet import GREASE_PARAMETERS, calibrate_datasheet, to_text

    other = [
        f"--{n.replace('_', '-')}"
        for n in ("data", "catalog", "bearing", "mounting", "lubricant", "fit", "speed")
        if getattr(args, n)
    ] + (["--set"] if args.set else [])
    if other:
        raise ValueError(
            f"--datasheet fits the grease term on the datasheet's own test bearing: "
            f"{', '.join(other)} do not apply (bind the written set on your bearing's)"
        )
    cal = calibrate_datasheet(args.datasheet, args.test)
    out = Path(args.out or f"out/calibration/datasheet_{args.datasheet}")
    output_folder(out)
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
    write_text(out / "report.txt", text + "\n")
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
    with _mechanism(args) as mechanism:
        return _calibrate_data(args, mechanism)


def _calibrate_data(args, mechanism) -> int:
    from .calibration import (
        UNKNOWNS,
        calibrate,
        parse_quantity,
        plot,
        read_measurements,
        to_text,
        write_coefficients,
        write_residuals,
        write_ssv,
    )
    from .parameters.bearing import (
        default_parameters,
        default_sources,
        pair_from_parameters,
    )

    # every argument first: nothing is read or fitted with a bad one
    mounting = mechanism.mounting if mechanism.chosen else _mounting_for(args.bearing or "71803")
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
            if params["lubrication"] == "grease"
            else ["sliding_friction"]
        )
    )
    for name in unknowns:
        if name not in UNKNOWNS:
            raise ValueError(f"--fit {args.fit}: {name!r} is not one of {list(UNKNOWNS)}")
    from .parameters.presets import coefficient_set

    before = coefficient_set(mounting).label
    data = read_measurements(args.data)
    cal = calibrate(data, params, unknowns, speed=speed, residual=args.residual)
    out = Path(args.out or f"out/calibration/{Path(args.data).stem}")
    files = [write_residuals(cal, out / "residuals.csv"), plot(cal, out / "calibration.png")]
    ssv, toml = out / "calibrated.ssv", out / "calibrated.toml"
    if cal.poor and not args.allow_poor_fit:
        for stale in (ssv, toml):  # no result of an earlier run passes for this one
            stale.unlink(missing_ok=True)
    else:
        what = f"calibrated by servofmu calibrate on {args.data} (mounting {mounting})"
        files.append(write_ssv(cal.parameters, ssv, component=args.component, comment=what))
        sources = default_sources(
            mounting, args.lubrication, bearing=args.bearing, lubricant=args.lubricant
        )
        files.append(write_coefficients(cal, toml, mounting, args.data, sources))
    text = to_text(cal)
    text += f"\n\nmounting {mounting}; friction coefficients before this fit: {before}"
    write_text(out / "report.txt", text + "\n")
    if args.json:
        import json

        print(json.dumps(cal.as_dict(), indent=2))
    else:
        print(text)
        print("\n".join(f"file: {f}" for f in [out / "report.txt", *files]))
        if toml in files:
            build = " ".join(["servofmu build", *(f"--catalog {f}" for f in [*args.catalog, toml])])
            if args.mounting or not mechanism.chosen:  # no catalogue's [defaults] names it
                build += f" --mounting {mounting}"
            print(f"next: {build} (the FMUs and systems of {mounting} with these coefficients)")
    if cal.poor:
        what = f"{cal.problems[0]}" + (
            f" (and {len(cal.problems) - 1} more)" if len(cal.problems) > 1 else ""
        )
        if not args.allow_poor_fit:
            print(
                f"servofmu: calibration failed: {what}; no calibrated.ssv or calibrated.toml "
                f"written (report in {out / 'report.txt'}; --allow-poor-fit writes them anyway)",
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
    from servofmu.harness.sweep import require_sweep_extra

    require_sweep_extra()
    with _mechanism(args) as mechanism:
        return _sweep_mechanism(args, mechanism)


def _sweep_mechanism(args, mechanism) -> int:
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
    from servofmu.parameters.bearing import default_parameters

    out = Path(args.out or "out/sweep/results.csv")
    check_table_path(out)
    _say_mechanism(mechanism)
    axes = dict(_axis(g) for g in args.grid)
    dists = dict(_distribution(s) for s in args.sample)
    samples = sample_points(dists, args.samples, args.seed) if dists else []
    points = cross(samples, grid_points(axes) if axes else [])
    if not points:
        raise ValueError("give at least one --grid or --sample")
    if args.target == "model":
        base = (
            default_parameters(mechanism.mounting, args.lubrication)
            if args.lubrication
            else mechanism.parameters()
        )
        base = _set_known(base, args.set)
        task = ModelTask(base, tuple(args.record)) if args.record else ModelTask(base)
    else:
        if args.set or not args.record:
            raise ValueError(
                "a system sweep takes --record comp.var (what to report) and no --set "
                "(give fixed values as a one-value --grid)"
            )
        path, fmu_dir = _system_path(args.target, mechanism)
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
    return 1 if result.failed else 0  # a failed run is in the table, marked: not a success


def _montecarlo(args) -> int:
    from servofmu.harness.sweep import require_sweep_extra
    from servofmu.harness.tolerance import run

    require_sweep_extra()
    with _mechanism(args) as mechanism:
        result = run(
            Path(args.out or "out/montecarlo"),
            samples=args.samples,
            seed=args.seed,
            workers=args.workers,
            scheduler=args.scheduler,
            mounting=mechanism.mounting,
            base=mechanism.parameters(),
        )
    print(result.to_text())
    return 0


def _margin(args) -> int:
    """``servofmu margin [FILE]``: the motorisation margin (servofmu.margin); exit 0 when every
    row is met, 1 when a margin is negative, 3 when none is but a row is not verified. Ctrl-C
    writes the rows computed so far."""
    from .harness.interrupt import protected
    from .margin import MarginResult, example_input, load_inputs, run, to_text, write_all

    # the whole input is read and checked before any computation (exit 2 naming the field)
    inputs = load_inputs(args.file or example_input(), args.catalog, args.mounting)
    out = Path(args.out)
    result = MarginResult(inputs)
    try:
        run(inputs, result)
    except KeyboardInterrupt:
        with protected(reraise=False):  # a second signal does not cut the rows so far short
            files = write_all(result, out) if result.steady else []
        raise KeyboardInterrupt(
            f"the rows computed so far are in {', '.join(map(str, files))}" if files else ""
        ) from None
    with protected():  # every file written before a signal acts
        files = write_all(result, out)
    print(to_text(result, files))
    return result.exit_code


class _Parser(argparse.ArgumentParser):
    """argparse with its errors on one line (no usage block): exit 2."""

    def error(self, message):
        import re

        from .physics._checks import suggest

        typo = re.search(r"invalid choice: '(.*?)' \(choose from (.*)\)", message)
        if typo:  # argparse lists the choices; add the closest one
            choices = re.findall(r"'([^']*)'", typo.group(2))
            message += suggest(typo.group(1), choices)
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


def add_mechanism_options(parser, mounting_help: str | None = None) -> None:
    """``--catalog FILE`` (repeatable) and ``--mounting KEY``: the mechanism a command works
    on (:func:`_mechanism` resolves them); the catalogue's ``[defaults] mounting`` applies
    when no --mounting is given.

    Returns
    -------
    None

    Examples
    --------
    >>> p = argparse.ArgumentParser()
    >>> add_mechanism_options(p)
    >>> p.parse_args(["--catalog", "a.toml", "--catalog", "b.toml", "--mounting", "m"])
    Namespace(catalog=['a.toml', 'b.toml'], mounting='m')
    """
    parser.add_argument(
        "--catalog",
        action="append",
        default=[],
        metavar="FILE.toml",
        help="a user catalogue (bearings, lubricants, materials, mountings, coefficients, "
        "tolerances; format: servofmu examples → my_gimbal_catalog.toml), merged in; "
        "repeatable",
    )
    parser.add_argument(
        "--mounting",
        metavar="KEY",
        help=mounting_help
        or "the catalogue mounting of the mechanism (default: the last catalogue's [defaults] "
        "mounting, else yu2017_gimbal); its build lives in build/KEY (build/out for the "
        "standard one), built there when missing or stale",
    )


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
    b = sub.add_parser(
        "build",
        help="build the FMUs (pythonfmu) and systems of a mechanism into build/out (the "
        "standard one) or build/MOUNTING",
    )
    b.add_argument("names", nargs="*", help="FMUs to build (default: all five)")
    b.add_argument(
        "--out",
        help="output directory (default: build/out for the standard mechanism, build/MOUNTING "
        "for another)",
    )
    add_mechanism_options(
        b,
        "mounting whose numbers (its bearing, lubricant and coefficients) become "
        "BearingFriction's start values and the systems' bindings (alias --preset)",
    )
    b.add_argument("--preset", dest="mounting", help=argparse.SUPPRESS)
    b.add_argument("--lubricant", help="lubricant of BearingFriction's start values")
    b.add_argument("--support-mounting", metavar="MOUNTING",
                   help="mounting of ActuatorStiffness's support pair (start values)")  # fmt: skip
    b.set_defaults(func=_build)
    k = sub.add_parser(
        "catalog",
        help="list the catalogue (bearings, lubricants, materials, mountings) or print a "
        "preset's parameter set (and write it as .ssv)",
    )
    add_mechanism_options(
        k, "print this mounting's parameter set, each value with its source (alias --preset)"
    )
    k.add_argument("--preset", dest="mounting", help=argparse.SUPPRESS)
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
        metavar="NAME|FILE.ssv|comp.var=VALUE",
        help="a parameter-set variant (variants/NAME.ssv), a parameter set file (.ssv: a "
        "variant's comp.var names, or one component's bare names) or one value; repeatable, "
        "in order",
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
    add_mechanism_options(r)
    r.set_defaults(func=_run)
    s = sub.add_parser(
        "scenario", help="run a system-level scenario (the papers' experiments in co-simulation)"
    )
    s.add_argument("name", choices=SCENARIOS, help="which scenario")
    s.add_argument("--coarse", action="store_true", help="shorter runs (as the tests use)")
    s.add_argument("--out", help="directory for CSV and PNG files (default out/NAME)")
    s.add_argument(
        "--workers",
        type=_count,
        help="processes for the scenario's independent runs (chamber_transient; default: "
        "one per core; 1: one after another)",
    )
    add_mechanism_options(s)
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
    add_mechanism_options(w)
    w.add_argument(
        "--lubrication",
        choices=("grease", "solid"),
        help="model: the catalogue's default lubricant of this kind (default: the mounting's own)",
    )
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
    add_mechanism_options(
        mc,
        "the catalogue mounting whose tolerance bands ([tolerances.KEY]) are drawn (default: "
        "the last catalogue's [defaults] mounting, else yu2017_gimbal)",
    )
    mc.add_argument("--workers", type=_count)
    mc.add_argument("--scheduler")
    mc.add_argument("--out", help="directory (default out/montecarlo)")
    mc.set_defaults(func=_montecarlo)
    mg = sub.add_parser(
        "margin",
        help="motorisation (torque) margin of a mechanism, ECSS-E-ST-33-01C 4.7.5.3, over "
        "temperature, a chamber transient and tolerances: table, CSV, plot; a verdict per row "
        "(met, not met, not verified); exit 1 when a margin is negative, 3 when a row is not "
        "verified",
        description="The minimum actuation torque T_min = 2 × Σ u·R + 1.25 × T_D + T_L "
        "(ECSS-E-ST-33-01C 4.7.5.3.1, Table 4-2's uncertainty factors u) with the bearing "
        "pair's friction from the bearing model, the margin T / T_min − 1 and the ratio MR = "
        "(T − 1.25 × T_D − T_L) / Σ u·R, at every temperature (default: the mounting's declared "
        "operating range), case (start, running), life (BOL, EOL), Monte-Carlo draw and "
        "transient time of FILE, each row met, not met or not verified (a flag of the model "
        "affects it). Without FILE: the documented example (Yu's gimbal, motor and other "
        "torques assumed). Exit 0: every row met; 1: a margin negative; 3: none negative, a row "
        "not verified; 2: a bad input.",
    )
    mg.add_argument(
        "file", nargs="?", metavar="FILE.toml",
        help="margin input file (format: examples/margin_yu_gimbal.toml, the default)",
    )  # fmt: skip
    mg.add_argument("--catalog", action="append", default=[], metavar="FILE.toml",
                    help="a user catalogue (format: examples/my_gimbal_catalog.toml); its "
                    "[defaults] mounting wins over the input file's")  # fmt: skip
    mg.add_argument("--mounting", metavar="KEY", help="catalogue mounting to study (wins over "
                    "the catalogues' [defaults] and the input file)")  # fmt: skip
    mg.add_argument("--out", default="out/margin", help="output folder (default out/margin)")
    mg.set_defaults(func=_margin)
    c = sub.add_parser(
        "calibrate",
        help="fit a bearing pair's unknown coefficients to measured friction torque (CSV)",
        description="Fit the unknown coefficients of a bearing pair to measured running "
        "friction torque versus temperature. DATA.csv has a header naming each column with "
        "its unit: 'temperature [degC]' or '[K]', 'torque [N.mm]' or '[N.m]', optionally "
        "'speed [deg/s]', '[rad/s]' or '[rpm]' and 'direction' (forward/reverse); '#' lines "
        "are comments. Or, with --datasheet LUBRICANT, calibrate the grease term (grease_f0, "
        "grease_starting_ratio) on the grease's published low-temperature torque test "
        "(parameters/data/grease_torques.toml).",
    )
    c.add_argument("data", nargs="?", help="CSV file of measured friction torque")
    c.add_argument(
        "--datasheet",
        metavar="LUBRICANT",
        help="calibrate the grease term on this grease's datasheet low-temperature torque "
        "(ASTM D1478 / JIS K 2220 points of parameters/data/grease_torques.toml) instead of DATA",
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
    add_mechanism_options(
        c,
        "catalogue mounting the data were measured on (default: the last catalogue's "
        "[defaults] mounting; required when the bearing has more than one, as the 71803: "
        "yu2017_gimbal, yu2017_gimbal_printed, …)",
    )
    c.add_argument(
        "--lubrication",
        choices=("grease", "solid"),
        help="the catalogue's default lubricant of this kind (default: the mounting's own)",
    )
    c.add_argument("--lubricant", help="catalogue lubricant (default: the mounting's own)")
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
    e = sub.add_parser(
        "examples",
        help="list the example files shipped with servofmu, or copy them into a folder",
        description="The example files shipped with servofmu: a user catalogue "
        "(my_gimbal_catalog.toml), a measured-friction data file (data/*.csv) and a "
        "plain-fmpy script. Without DEST: list where they are installed; with DEST: copy "
        "them there (existing files are kept unless --force).",
    )
    e.add_argument("dest", nargs="?", help="folder to copy the examples into")
    e.add_argument("--force", action="store_true", help="overwrite files already in DEST")
    e.set_defaults(func=_examples)
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


#: Exit code of an internal error (3 is ``servofmu margin``'s "some row not verified").
INTERNAL_ERROR = 4


def main(argv: list[str] | None = None) -> int:
    """Exit codes: 0 done, 1 a run failed (partial results kept; ``margin``: a margin is
    negative), 2 bad input (data, arguments, system description), 3 ``margin`` only: no margin
    negative but a row not verified, 4 an internal error (traceback in a private log file),
    74 a result could not be written (a full disk, a folder that cannot be written: the path
    is named, and no partial file stays under its name), 130 interrupted by Ctrl-C and 143 by
    SIGTERM (a run stops at a step boundary and keeps its results either way)."""
    from .harness.errors import (
        ArgumentError,
        HarnessError,
        Interrupted,
        MissingExtra,
        SystemError_,
    )
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
    except OutputError as exc:  # a full disk, a folder that cannot be written: not bad input
        print(f"servofmu: error: {exc}", file=sys.stderr)
        return EXIT_OUTPUT
    except (ValueError, OSError, MissingExtra) as exc:
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
        return INTERNAL_ERROR


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

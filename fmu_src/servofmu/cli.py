"""The ``servofmu`` command line: a thin layer over the library API."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import __version__
from .papers import PAPERS


def _paper(args) -> int:
    from .papers import run

    report = run(args.name, Path(args.out or f"out/{args.name}"))
    print(report.dumps() if args.json else report.to_text())
    return 0


def _build(args) -> int:
    from servofmu.build.fmu import FMUS, build_all

    for path in build_all(Path(args.out), args.names or FMUS):
        print(path)
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


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="servofmu", description="Temperature-aware servo-mechanism physics and FMUs."
    )
    parser.add_argument("--version", action="version", version=f"servofmu {__version__}")
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
    b.add_argument("names", nargs="*", help="FMUs to build (default: all four)")
    b.add_argument("--out", default="build/out", help="output directory (default build/out)")
    b.set_defaults(func=_build)
    v = sub.add_parser(
        "validate", help="validate FMUs (fmpy + servofmu checks); exit 1 on problems"
    )
    v.add_argument("fmus", nargs="+", help="FMU files")
    v.set_defaults(func=_validate)
    h = sub.add_parser("host-env", help="environment a non-Python FMI host must set for our FMUs")
    h.set_defaults(func=_host_env)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except ValueError as exc:
        print(f"servofmu: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

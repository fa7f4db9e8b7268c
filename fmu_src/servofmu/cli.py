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

"""The benchmarks' saved results: each benchmark's ``--save FILE.json`` writes its figures
with the context of the run (command, date, versions, machine, load), and the
documentation's Performance page reads these files (``make bench`` writes them to
``benchmarks/results/``)."""

from __future__ import annotations

import datetime
import json
import os
import platform
import sys
from pathlib import Path


def record(figures, argv=None) -> dict:
    """The figures of one run with its context: what a reader needs to judge them."""
    import servofmu

    script = Path(sys.argv[0]).name
    args = sys.argv[1:] if argv is None else list(argv)
    return {
        "benchmark": Path(script).stem,
        "command": " ".join(["python", f"benchmarks/{script}", *args]),
        "date": datetime.date.today().isoformat(),
        "servofmu": servofmu.__version__,
        "python": platform.python_version(),
        "machine": {
            "platform": platform.platform(),
            "cpus": os.cpu_count(),
            "load_average_1min": os.getloadavg()[0],
        },
        "figures": figures,
    }


def save(path, figures, argv=None) -> Path:
    """Write :func:`record` of ``figures`` to ``path`` (JSON, UTF-8); returns the path."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    text = json.dumps(record(figures, argv), indent=2, ensure_ascii=False)
    path.write_text(text + "\n", encoding="utf-8")
    return path


def add_output_options(parser) -> None:
    """The options every benchmark takes: ``--json`` (print the figures as JSON) and
    ``--save FILE.json`` (:func:`save` them too)."""
    parser.add_argument("--json", action="store_true")
    parser.add_argument(
        "--save",
        metavar="FILE.json",
        help="also write the figures and the run's context to this JSON file (docs: Performance)",
    )


def emit(args, figures, argv=None) -> bool:
    """Save ``figures`` when ``--save`` was given and print them as JSON when ``--json`` was;
    True when printed (the caller prints its table otherwise)."""
    if args.save:
        save(args.save, figures, argv)
    if args.json:
        print(json.dumps(figures, indent=2))
    return bool(args.json)

"""Pages generated from the project's own data when the documentation is built, into
``docs/_generated/`` (not kept in git):

- ``fmus/NAME.rst`` and ``NAME.png``: the FMU reference, from the same reStructuredText as
  each FMU's ``documentation/index.html`` (``servofmu.build.documentation.page_rst``) and the
  characteristic curve computed by the FMU's own code;
- ``validation/PAPER.rst`` and its figures: each paper reproduction run now
  (``servofmu.papers.run``), its report's rows, rules, parameters and figures;
- ``performance.rst``: the benchmarks' saved results (``benchmarks/results/*.json``, written
  by ``make bench``).

A file is rewritten only when its text changes, so that Sphinx rebuilds only what changed.
The paper reproductions take about a minute: their reports are kept in
``_generated/validation/`` with the hash of the package sources they were computed from, and
computed again when that hash changes.
"""

from __future__ import annotations

import hashlib
import importlib
import json
import shutil
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from sphinx.util import logging

logger = logging.getLogger(__name__)

DOCS = Path(__file__).resolve().parents[1]
ROOT = DOCS.parent
OUT = DOCS / "_generated"
RESULTS = ROOT / "benchmarks" / "results"
#: First lines of a generated page with wide tables (reports, variables): no page-toc sidebar,
#: so that the tables get the page's width.
WIDE = ":html_theme.sidebar_secondary.remove: true\n\n"
ROW_WIDTHS = "9 12 6 12 13 5 8 7 28"  # columns of a report's rows, readable at 1280 px
TITLES = {
    "yu2017": "Yu 2017: seeker-gimbal bearings",
    "ning": "Ning: space bearing under alternating temperature",
    "liu2014": "Liu 2014: actuator stiffness",
    "validation": "Friction models against measured torques",
}


def _write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def _escape(text) -> str:
    from servofmu.build.documentation import _escape as escape

    return escape(text)


def _table(title: str, header, rows, widths: str | None = None) -> str:
    css = "variables report" if widths else "variables"  # report: the widths are kept
    lines = [f".. list-table:: {title}", "   :header-rows: 1", f"   :class: {css}"]
    if widths:
        lines.append(f"   :widths: {widths}")
    lines.append("")
    for row in (header, *rows):
        cells = [_escape(c) if str(c) != "" else r"\ " for c in row]
        lines.append(f"   * - {cells[0]}")
        lines += [f"     - {c}" for c in cells[1:]]
    return "\n".join(lines) + "\n"


# ----------------------------------------------------------------------------- FMUs
def fmu_pages() -> list[str]:
    """``fmus/NAME.rst`` and ``fmus/NAME.png`` for every FMU; returns the names."""
    from servofmu.build import documentation as doc
    from servofmu.build.fmu import FMUS

    folder = OUT / "fmus"
    folder.mkdir(parents=True, exist_ok=True)
    for name in FMUS:
        curve = doc.CURVES[name]()
        png = folder / f"{name}.png"
        doc.plot_curve(curve, png)
        _write(folder / f"{name}.rst", WIDE + doc.page_rst(name, png.name, curve.caption))
    return list(FMUS)


# ----------------------------------------------------------------------------- papers
def _sources_hash() -> str:
    """SHA-256 of the package's .py and .toml files: the inputs of the reproductions."""
    import servofmu

    root = Path(servofmu.__file__).resolve().parent
    digest = hashlib.sha256()
    for f in sorted(p for p in root.rglob("*") if p.suffix in (".py", ".toml")):
        digest.update(f.relative_to(root).as_posix().encode())
        digest.update(f.read_bytes())
    return digest.hexdigest()


def _reproduce(paper: str, folder: str) -> str:
    """Run one reproduction into ``folder`` (a worker process); returns its report as JSON."""
    import matplotlib

    matplotlib.use("Agg")
    from servofmu.papers import run

    return run(paper, folder).dumps()


def _fmt(x) -> str:
    if isinstance(x, float):
        return f"{x:.4g}"
    if isinstance(x, list):
        return ", ".join(_fmt(v) for v in x)
    return str(x)


def _paper_rst(paper: str, report: dict, folder: Path) -> str:
    from servofmu.build.documentation import _docstring
    from servofmu.papers.report import summary_line

    module = importlib.import_module(f"servofmu.papers.{paper}")
    title = TITLES.get(paper, paper)
    doc = _docstring(module)
    rules = "\n".join(f"- **{_escape(k)}**: {_escape(v)}" for k, v in report["rules"].items())
    rows = [
        (
            r["id"],
            r["quantity"],
            r["kind"],
            _fmt(r["published"]),
            _fmt(r["computed"]),
            r["unit"],
            r["status"],
            r["tolerance"],
            r["note"],
        )
        for r in report["rows"]
    ]
    params = [
        (p["name"], _fmt(p["value"]), p["unit"], p["provenance"]) for p in report["parameters"]
    ]
    head = ("id", "quantity", "kind", "published", "computed", "unit", "status", "tolerance")
    head += ("note",)
    table = _table("Every published number and what the model gives", head, rows, ROW_WIDTHS)
    figures = "\n".join(
        f".. figure:: {paper}/{Path(f).name}\n   :width: 80%\n\n   ``{Path(f).name}``\n"
        for f in report["files"]
        if f.endswith(".png")
    )
    return f"""{WIDE}{title}
{"=" * len(title)}

*{_escape(report["title"])}*: computed by ``servofmu paper {paper}`` when this page was
built.

.. currentmodule:: servofmu.papers.{paper}

{doc}

Summary
-------

{_escape(summary_line(report["summary"]))}

Tolerance rules used:

{rules}

Rows
----

{table}

Parameters and their provenance
-------------------------------

{_table("Parameters", ("name", "value", "unit", "provenance"), params, "20 10 6 64")}

Figures
-------

{figures}
"""


def validation_pages() -> list[str]:
    """``validation/PAPER.rst`` and the figures of every reproduction; returns the papers."""
    from servofmu.papers import PAPERS

    folder = OUT / "validation"
    key = _sources_hash()
    stale = [p for p in PAPERS if _cached(folder, p) != key]
    if stale:
        logger.info("running the paper reproductions %s (about a minute)", ", ".join(stale))
        for p in stale:
            shutil.rmtree(folder / p, ignore_errors=True)
        with ProcessPoolExecutor(max_workers=2) as pool:
            jobs = {p: pool.submit(_reproduce, p, str(folder / p)) for p in stale}
            for p, job in jobs.items():
                _write(folder / f"{p}.json", job.result())
                _write(folder / f"{p}.key", key)
    for p in PAPERS:
        report = json.loads((folder / f"{p}.json").read_text(encoding="utf-8"))
        _write(folder / f"{p}.rst", _paper_rst(p, report, folder))
    return list(PAPERS)


def _cached(folder: Path, paper: str) -> str | None:
    key = folder / f"{paper}.key"
    ok = key.exists() and (folder / f"{paper}.json").exists() and (folder / paper).is_dir()
    return key.read_text() if ok else None


# ----------------------------------------------------------------------------- benchmarks
def _flatten(figures, prefix="") -> list[tuple[str, object]]:
    """(name, value) pairs of a benchmark's figures: nested tables become "outer: inner"."""
    if isinstance(figures, dict):
        out = []
        for k, v in figures.items():
            out += _flatten(v, f"{prefix}{k}: " if isinstance(v, dict) else f"{prefix}{k}")
        return out
    return [(prefix, figures)]


def _value(v) -> str:
    if isinstance(v, float):
        return f"{v:.3g}" if abs(v) < 1e4 else f"{v:.4g}"
    return str(v)


def _benchmark_rst(record: dict, title: str, doc: str) -> str:
    m = record["machine"]
    head = (
        f"Measured with ``{record['command']}`` on {record['date']}: servofmu "
        f"{record['servofmu']}, Python {record['python']}, {m['cpus']} cores, load average "
        f"{m['load_average_1min']:.1f} at the end of the run."
    )
    figures = record["figures"]
    tables = []
    for key, value in figures.items():
        if isinstance(value, list) and value and isinstance(value[0], dict):  # rows
            header = tuple(value[0])
            rows = [tuple(_value(r[h]) for h in header) for r in value]
            tables.append(_table(key, header, rows))
    scalars = [(k, _value(v)) for k, v in _flatten(figures) if not isinstance(v, list)]
    if scalars:
        tables.insert(0, _table("figures", ("quantity", "value"), scalars, "80 20"))
    if m["load_average_1min"] > m["cpus"]:
        tables.insert(
            0,
            f".. warning::\n\n   The machine was shared during this run (load average "
            f"{m['load_average_1min']:.1f} on {m['cpus']} cores): absolute times are inflated, "
            "and ratios less trustworthy than on a quiet machine. ``make bench`` measures "
            "again.\n",
        )
    return f"{title}\n{'-' * len(title)}\n\n{doc}\n\n{head}\n\n" + "\n".join(tables)


def performance_page() -> str:
    """``performance.rst``: one section per saved benchmark result."""
    parts = []
    for path in sorted(RESULTS.glob("*.json")):
        record = json.loads(path.read_text(encoding="utf-8"))
        script = ROOT / "benchmarks" / f"{record['benchmark']}.py"
        doc = _first_paragraph(script)
        parts.append(_benchmark_rst(record, record["benchmark"], doc))
    if not parts:
        parts.append("No saved benchmark results: run ``make bench``.\n")
    text = "\n".join(parts)
    _write(OUT / "performance.rst", text)
    return text


def _first_paragraph(script: Path) -> str:
    import ast

    from servofmu.build.documentation import escape_bars

    doc = ast.get_docstring(ast.parse(script.read_text(encoding="utf-8"))) or ""
    return escape_bars(doc.split("\n\n")[0])


def generate(app) -> None:
    import time

    OUT.mkdir(exist_ok=True)
    for make in (fmu_pages, validation_pages, performance_page):
        t0 = time.perf_counter()
        make()
        logger.info("%s: %.1f s", make.__name__, time.perf_counter() - t0)


def setup(app):
    app.connect("builder-inited", generate)
    return {"parallel_read_safe": True, "parallel_write_safe": True}

"""``documentation/index.html`` of each FMU: what it computes, its equations (the docstrings of
the physics modules it uses) and every variable with unit, start, range and provenance."""

from __future__ import annotations

import html
import importlib
from pathlib import Path

import servofmu


def slave_class(name: str):
    """The slave class ``name`` from ``servofmu.fmus``."""
    return getattr(importlib.import_module(f"servofmu.fmus.{name}"), name)


def render(name: str) -> str:
    """The HTML page of FMU ``name``."""
    cls = slave_class(name)
    module = importlib.import_module(cls.__module__)
    rows = []
    for v in cls.VARIABLES:
        rng = "" if v.min is None and v.max is None else f"[{v.min:g}, {v.max:g}]"
        start = "" if v.causality == "output" else html.escape(repr(v.start))
        cells = (
            v.name,
            v.causality,
            v.type,
            v.unit or "",
            v.display_unit or "",
            start,
            rng,
            v.description,
            v.source,
        )
        rows.append("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in cells) + "</tr>")
    physics = []
    for mod_name in cls.PHYSICS:
        mod = importlib.import_module(mod_name)
        physics.append(f"<h3>{mod_name}</h3>\n<pre>{html.escape(mod.__doc__ or '')}</pre>")
    head = "".join(
        f"<th>{h}</th>"
        for h in (
            "name",
            "causality",
            "type",
            "unit",
            "display",
            "start",
            "range",
            "description",
            "provenance",
        )
    )
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{name}</title>
<style>body{{font-family:sans-serif;max-width:75em;margin:2em auto}}
table{{border-collapse:collapse}}td,th{{border:1px solid #ccc;padding:2px 6px;font-size:90%}}
pre{{background:#f6f6f6;padding:1em;white-space:pre-wrap}}</style></head><body>
<h1>{name}</h1>
<p>{html.escape(cls.description)}</p>
<p>servofmu {servofmu.__version__}: FMI 2.0 co-simulation, built with pythonfmu. The FMU runs
inside a Python interpreter with numpy and scipy (see the project README, "Host
requirements").</p>
<pre>{html.escape(module.__doc__ or "")}</pre>
<h2>Variables</h2>
<p>SI units; display units are declared in the modelDescription. Bad inputs or parameters
(outside the range, or not finite) make the next step return fmi2Discard with a logged message
naming the variable and its value.</p>
<table><tr>{head}</tr>
{"".join(rows)}
</table>
<h2>Equations</h2>
{"".join(physics)}
</body></html>
"""


def write_documentation(name: str, folder: Path) -> Path:
    """Write ``index.html`` of FMU ``name`` into ``folder``."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "index.html"
    path.write_text(render(name), encoding="utf-8")
    return path

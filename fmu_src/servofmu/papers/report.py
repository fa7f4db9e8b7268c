"""Validation report of a paper reproduction (DESIGN §5).

Each published number becomes a :class:`Row` whose ``status`` is computed by comparing the
computed value with the published one at the stated tolerance — never written as a literal:

- ``reproduced``: a prediction within tolerance;
- ``calibrated``: a coefficient was fitted on this number (the row names it);
- ``qualitative``: a published trend that the model shows;
- ``not-reproduced``: outside tolerance, trend not shown, or no fit possible (the note says why).
"""

from __future__ import annotations

import csv
import json
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

STATUSES = ("reproduced", "calibrated", "qualitative", "not-reproduced")


@dataclass
class Row:
    """One published number or statement and what the model gives."""

    id: str
    quantity: str
    published: float | str
    computed: float | str
    unit: str
    status: str
    tolerance: str
    note: str = ""


@dataclass
class Parameter:
    """One model parameter with its provenance."""

    name: str
    value: float | str
    unit: str
    provenance: str


@dataclass
class Report:
    """The validation report of one paper, plus the files written for it."""

    paper: str
    title: str
    rows: list[Row] = field(default_factory=list)
    parameters: list[Parameter] = field(default_factory=list)
    files: list[str] = field(default_factory=list)

    def to_json(self) -> dict:
        return {
            "paper": self.paper,
            "title": self.title,
            "rows": [asdict(r) for r in self.rows],
            "parameters": [asdict(p) for p in self.parameters],
            "files": self.files,
        }

    def dumps(self) -> str:
        return json.dumps(self.to_json(), indent=2, ensure_ascii=False, default=_json_default)

    def to_text(self) -> str:
        lines = [f"{self.paper}: {self.title}", ""]
        for r in self.rows:
            lines.append(
                f"[{r.status:>14}] {r.id}: {r.quantity}\n"
                f"{'':17}published {_fmt(r.published)} {r.unit} | computed {_fmt(r.computed)} "
                f"{r.unit} | tolerance {r.tolerance}"
            )
            if r.note:
                lines.append(f"{'':17}{r.note}")
        counts = {s: sum(r.status == s for r in self.rows) for s in STATUSES}
        lines += ["", "summary: " + ", ".join(f"{n} {s}" for s, n in counts.items())]
        lines += ["", "parameters:"]
        for p in self.parameters:
            lines.append(f"  {p.name} = {_fmt(p.value)} {p.unit}  [{p.provenance}]")
        if self.files:
            lines += ["", "files:"] + [f"  {f}" for f in self.files]
        return "\n".join(lines)


def _json_default(x):
    if isinstance(x, (np.floating, np.integer)):
        return x.item()
    if isinstance(x, np.bool_):
        return bool(x)
    raise TypeError(f"{type(x)} is not JSON serialisable")


def _fmt(x) -> str:
    if isinstance(x, (float, np.floating)):
        return f"{x:.4g}"
    return str(x)


def compare(
    id: str,
    quantity: str,
    published: float,
    computed: float,
    unit: str,
    *,
    rel: float | None = None,
    abs_tol: float | None = None,
    note: str = "",
    miss_note: str = "",
) -> Row:
    """A predicted number: ``reproduced`` when |computed − published| is within ``rel``
    (relative to |published|) or ``abs_tol``; else ``not-reproduced`` with ``miss_note``."""
    tol = (abs(published) * rel) if rel is not None else abs_tol
    if tol is None:
        raise ValueError("compare needs rel or abs_tol")
    tol_s = f"±{rel * 100:g} %" if rel is not None else f"±{abs_tol:g} {unit}"
    ok = bool(np.isfinite(computed)) and abs(computed - published) <= tol
    status = "reproduced" if ok else "not-reproduced"
    text = note if ok or not miss_note else " ".join(s for s in (note, miss_note) if s)
    return Row(id, quantity, published, float(computed), unit, status, tol_s, text)


def calibrated(
    id: str,
    quantity: str,
    published: float,
    computed: float,
    unit: str,
    coefficient: str,
    *,
    rel: float = 1e-3,
    note: str = "",
) -> Row:
    """A number a coefficient was fitted on: ``calibrated`` when the fit reached it within
    ``rel``, else ``not-reproduced`` (the fit failed; the note says why)."""
    ok = bool(np.isfinite(computed)) and abs(computed - published) <= rel * abs(published)
    status = "calibrated" if ok else "not-reproduced"
    text = f"calibrated: {coefficient}. {note}".strip()
    return Row(id, quantity, published, float(computed), unit, status, f"±{rel * 100:g} %", text)


def trend(
    id: str,
    quantity: str,
    published: str,
    holds: bool,
    computed: str,
    *,
    note: str = "",
    miss_note: str = "",
) -> Row:
    """A published trend: ``qualitative`` when ``holds`` (computed by the caller from the
    model's curve), else ``not-reproduced``."""
    status = "qualitative" if holds else "not-reproduced"
    text = note if holds or not miss_note else " ".join(s for s in (note, miss_note) if s)
    return Row(id, quantity, published, computed, "", status, "trend", text)


def write_csv(path: Path, columns: dict[str, Sequence[float]]) -> Path:
    """Write equal-length columns (header "name [unit]") to ``path``."""
    path.parent.mkdir(parents=True, exist_ok=True)
    names = list(columns)
    data = np.column_stack([np.asarray(columns[n], dtype=float) for n in names])
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(names)
        for row in data:
            w.writerow([f"{v:.9g}" for v in row])
    return path


def plot(
    path: Path,
    x,
    series: dict[str, Sequence[float]],
    xlabel: str,
    ylabel: str,
    title: str,
    decorate: Callable | None = None,
) -> Path:
    """Line plot of ``series`` against ``x`` to a PNG (matplotlib, Agg backend)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path.parent.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=110)
    for label, y in series.items():
        ax.plot(x, y, label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.3)
    if decorate is not None:
        decorate(ax)
    if len(series) > 1:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path

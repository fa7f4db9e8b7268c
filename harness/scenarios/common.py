"""What every scenario shares: the built systems, a result record and plateau averaging."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from servofmu.files import written


@dataclass
class Table:
    """A further table of a scenario: a title, one header (units in the names) and rows."""

    title: str
    columns: list[str]
    rows: list[dict]


def _cell(v) -> str:
    return f"{v:.4g}" if isinstance(v, float) else str(v)


def format_table(columns: list[str], rows: list[dict]) -> list[str]:
    """Lines of a right-aligned text table (floats to 4 significant digits)."""
    widths = [max(10, len(c), *(len(_cell(r[c])) for r in rows)) for c in columns]
    lines = ["  ".join(c.rjust(w) for c, w in zip(columns, widths, strict=True))]
    for row in rows:
        lines.append(
            "  ".join(_cell(row[c]).rjust(w) for c, w in zip(columns, widths, strict=True))
        )
    return lines


def write_csv(path: Path, columns: list[str], rows: list[dict]) -> Path:
    """A table as CSV (quoted where a cell needs it): one header, floats to 9 significant
    digits."""
    import csv

    path = Path(path)
    with written(path) as part, part.open("w", newline="") as fh:
        out = csv.writer(fh, lineterminator="\n")
        out.writerow(columns)
        for row in rows:
            out.writerow(f"{row[c]:.9g}" if isinstance(row[c], float) else row[c] for c in columns)
    return path


@dataclass
class ScenarioResult:
    """A scenario's table (rows of dicts, one header), further tables, summary figures, notes
    and files."""

    name: str
    title: str
    columns: list[str]
    rows: list[dict]
    summary: dict = field(default_factory=dict)
    files: list[Path] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    tables: list[Table] = field(default_factory=list)

    def to_text(self) -> str:
        lines = [self.title, "", *format_table(self.columns, self.rows)]
        if self.summary:
            lines += [""] + [f"{k}: {_cell(v)}" for k, v in self.summary.items()]
        for table in self.tables:
            lines += ["", table.title, "", *format_table(table.columns, table.rows)]
        lines += [""] + self.notes + [f"file: {f}" for f in self.files]
        return "\n".join(lines)

    def write_table(self, path: Path, table: Table | None = None) -> Path:
        """Write the main table (or ``table``) as CSV and list the file."""
        columns, rows = (self.columns, self.rows) if table is None else (table.columns, table.rows)
        path = write_csv(path, columns, rows)
        self.files.append(path)
        return path


def system_path(name: str, fmu_dir=None, mechanism=None) -> Path:
    """The built ``.ssp`` of system ``name`` of ``mechanism`` (default: the standard one) in
    ``fmu_dir`` (default: the mechanism's build folder), building FMUs and systems there if
    they are missing or stale."""
    from servofmu.build.fmu import ensure_built

    out = ensure_built(Path(fmu_dir) if fmu_dir else None, mechanism)
    return out / f"{name}.ssp"


def mechanism_notes(mechanism) -> list[str]:
    """What a scenario's mechanism is (its mounting and friction coefficients), as notes.

    Returns
    -------
    list of str

    Examples
    --------
    >>> mechanism_notes(None)[1].split(":")[:2]
    ['friction coefficients', ' Yu-calibrated']
    """
    if mechanism is None:
        from servofmu.build.catalogs import Defaults
        from servofmu.build.mechanism import resolve

        mechanism = resolve(Defaults())
    return [
        f"mechanism: {mechanism.describe()}",
        f"friction coefficients: {mechanism.coefficients.label}",
    ]


def plateau_mean(time: np.ndarray, values: np.ndarray, t0: float, t1: float, tail: float = 0.3):
    """Mean of ``values`` over the last ``tail`` fraction of [t0, t1) (steady state)."""
    start = t1 - tail * (t1 - t0)
    sel = (time >= start) & (time < t1)
    return float(np.mean(values[sel]))

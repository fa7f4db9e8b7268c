"""What every scenario shares: the built systems, a result record and plateau averaging."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np


@dataclass
class ScenarioResult:
    """A scenario's table (rows of dicts, one header), summary figures and files."""

    name: str
    title: str
    columns: list[str]
    rows: list[dict]
    summary: dict = field(default_factory=dict)
    files: list[Path] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def to_text(self) -> str:
        widths = [max(len(c), 10) for c in self.columns]
        lines = [self.title, ""]
        lines.append("  ".join(c.rjust(w) for c, w in zip(self.columns, widths, strict=True)))
        for row in self.rows:
            cells = []
            for c, w in zip(self.columns, widths, strict=True):
                v = row[c]
                cells.append((f"{v:.4g}" if isinstance(v, float) else str(v)).rjust(w))
            lines.append("  ".join(cells))
        if self.summary:
            lines += [""] + [
                f"{k}: {v:.4g}" if isinstance(v, float) else f"{k}: {v}"
                for k, v in self.summary.items()
            ]
        lines += [""] + self.notes + [f"file: {f}" for f in self.files]
        return "\n".join(lines)

    def write_table(self, path: Path) -> Path:
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        with path.open("w") as fh:
            fh.write(",".join(self.columns) + "\n")
            for row in self.rows:
                fh.write(
                    ",".join(
                        f"{row[c]:.9g}" if isinstance(row[c], float) else str(row[c])
                        for c in self.columns
                    )
                    + "\n"
                )
        self.files.append(path)
        return path


def system_path(name: str, fmu_dir=None) -> Path:
    """The built ``.ssp`` of system ``name`` (building FMUs and systems if they are stale)."""
    from servofmu.build.fmu import DEFAULT_OUT, ensure_built

    out = ensure_built(Path(fmu_dir) if fmu_dir else DEFAULT_OUT)
    return out / f"{name}.ssp"


def plateau_mean(time: np.ndarray, values: np.ndarray, t0: float, t1: float, tail: float = 0.3):
    """Mean of ``values`` over the last ``tail`` fraction of [t0, t1) (steady state)."""
    start = t1 - tail * (t1 - t0)
    sel = (time >= start) & (time < t1)
    return float(np.mean(values[sel]))

"""Validation report of a paper reproduction.

Each published number or statement becomes a :class:`Row` that says what it is (``kind``) and
how it came out (``status``). The status is computed by comparing the computed value with the
published one at a tolerance that a stated :class:`Rule` gives, never written as a literal.

Kinds:

- ``prediction``: nothing was fitted on the number, nor on a quantity it follows from
  arithmetically; the only rows that test the model;
- ``check``: the paper's own printed values through the paper's own equation (no model
  parameter enters);
- ``calibration``: a coefficient was fitted on the number (the row names it);
- ``consequence``: follows arithmetically from a calibrated row (the row names it), so its
  agreement is no evidence for the model, while a miss still is a finding;
- ``trend``: a published trend, tested on the model's curve.

Statuses: ``reproduced`` (a prediction or check within tolerance), ``calibrated`` (the fit
reached its target), ``consequence`` (a consequence within tolerance), ``qualitative`` (the
trend holds) and ``not-reproduced`` (outside tolerance, trend not shown or fit failed; the note
says why).

Tolerance rules (:data:`RULES`) are fixed per kind of published number before any comparison,
and a report prints those its rows use.
"""

from __future__ import annotations

import csv
import json
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field
from decimal import Decimal
from pathlib import Path

import numpy as np

from servofmu.files import save_figure, written

KINDS = ("prediction", "check", "calibration", "consequence", "trend")
STATUSES = ("reproduced", "calibrated", "consequence", "qualitative", "not-reproduced")
#: the status of a row of each kind that is within its tolerance (trends: that holds)
_MET = {
    "prediction": "reproduced",
    "check": "reproduced",
    "calibration": "calibrated",
    "consequence": "consequence",
    "trend": "qualitative",
}


@dataclass(frozen=True)
class Rule:
    """How a tolerance follows from the published number alone (never from the result).

    Attributes
    ----------
    key : short name printed with each row's tolerance
    text : the rule and its reason, printed by the report
    rel : fraction of |published|
    half_digit : the tolerance is at least half a unit of the last printed digit
    of_change : fraction of |published − reference|, the published change from a reference
        point (then ``rel`` and ``half_digit`` are unused)
    """

    key: str
    text: str
    rel: float = 0.0
    half_digit: bool = False
    of_change: float = 0.0

    def tolerance(self, published: float, printed: str | None = None, reference=None) -> float:
        """Tolerance [unit of ``published``] for ``published`` as printed (``printed``, the
        paper's text of the number) and, for a change rule, the published ``reference``."""
        if self.of_change:
            if reference is None:
                raise ValueError(f"rule {self.key!r} needs the published reference value")
            return self.of_change * abs(published - reference)
        tol = self.rel * abs(published)
        if self.half_digit:
            if printed is None:
                raise ValueError(f"rule {self.key!r} needs the number as printed")
            tol = max(tol, 0.5 * last_digit(printed))
        return tol


def last_digit(printed: str) -> float:
    """Value of one unit in the last printed digit of a number, e.g. 0.01 for "-0.05".

    >>> last_digit("0.38"), last_digit("72")
    (0.01, 1.0)
    """
    exponent = Decimal(printed.strip().replace("−", "-")).as_tuple().exponent
    return float(Decimal(1).scaleb(exponent))


FIT = Rule(
    "fit",
    "±0.1 % of the target: a coefficient fitted on the number must reach it (the root "
    "finders converge to 1e-9 or better), so a miss means the fit failed",
    rel=1e-3,
)
ARITHMETIC = Rule(
    "arithmetic",
    "±0.1 %: a number recomputed from the paper's printed values, or following "
    "arithmetically from a calibrated row, differs only by rounding (up to two intermediate "
    "values to 4 significant figures, ≤ 0.05 % each)",
    rel=1e-3,
)
PAPER_MODEL = Rule(
    "paper model",
    "±10 % of the published value, and at least half a unit of its last printed digit: a "
    "number the paper computed with its own model, recomputed here with the inputs the paper "
    "does not state (assumed or derived, see the parameters)",
    rel=0.10,
    half_digit=True,
)
MEASURED_CHANGE = Rule(
    "measured change",
    "± half the measured change from the reference point (the calibration point, or the "
    "first cycle): a model without the effect misses by the whole change and fails",
    of_change=0.5,
)
MEASURED_TORQUE = Rule(
    "measured torque",
    "±30 % of a measured friction torque: the aim fixed before any comparison for a model "
    "with literature constants alone (repeat measurements of such rigs scatter by 10–20 %)",
    rel=0.30,
)
VISCOSITY_FIT = Rule(
    "viscosity fit",
    "±3 % of a recorded viscosity that the lubricant's law is built from (through two or three "
    "points exactly, through more by least squares in ln ν): the aim fixed for a fit through "
    "every point, larger than the datasheets' rounding (three significant figures, ≤ 0.5 %)",
    rel=0.03,
)
RANGE = Rule("range", "inside the published range, its bounds as printed")
TREND = Rule("trend", "the published trend holds on the model's curve (the row states the test)")
RULES = (
    FIT,
    ARITHMETIC,
    PAPER_MODEL,
    MEASURED_CHANGE,
    MEASURED_TORQUE,
    VISCOSITY_FIT,
    RANGE,
    TREND,
)


@dataclass
class Row:
    """One published number or statement and what the model gives."""

    id: str
    quantity: str
    kind: str
    published: float | str
    computed: float | str
    unit: str
    status: str
    tolerance: str
    rule: str
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

    def rules(self) -> list[Rule]:
        """The tolerance rules the rows use, in the order of :data:`RULES`."""
        used = {r.rule for r in self.rows}
        return [rule for rule in RULES if rule.key in used]

    def summary(self) -> dict[str, dict[str, int]]:
        """Number of rows per kind and status (kinds and statuses in their fixed order)."""
        out = {}
        for kind in KINDS:
            statuses = [r.status for r in self.rows if r.kind == kind]
            if statuses:
                out[kind] = {s: statuses.count(s) for s in STATUSES if s in statuses}
        return out

    def to_json(self) -> dict:
        return {
            "paper": self.paper,
            "title": self.title,
            "rules": {rule.key: rule.text for rule in self.rules()},
            "summary": self.summary(),
            "rows": [asdict(r) for r in self.rows],
            "parameters": [asdict(p) for p in self.parameters],
            "files": self.files,
        }

    def dumps(self) -> str:
        return json.dumps(self.to_json(), indent=2, ensure_ascii=False, default=_json_default)

    def to_text(self) -> str:
        lines = [f"{self.paper}: {self.title}", ""]
        lines.append("tolerance rules (one per kind of published number, fixed before comparing):")
        lines += [f"  {rule.key}: {rule.text}" for rule in self.rules()]
        lines.append("")
        for r in self.rows:
            lines.append(
                f"[{r.status:>14}] {r.id} ({r.kind}): {r.quantity}\n"
                f"{'':17}published {_fmt(r.published)} {r.unit} | computed {_fmt(r.computed)} "
                f"{r.unit} | tolerance {r.tolerance}"
            )
            if r.note:
                lines.append(f"{'':17}{r.note}")
        lines += ["", "summary: " + summary_line(self.summary())]
        lines += ["", "parameters:"]
        for p in self.parameters:
            lines.append(f"  {p.name} = {_fmt(p.value)} {p.unit}  [{p.provenance}]")
        if self.files:
            lines += ["", "files:"] + [f"  {f}" for f in self.files]
        return "\n".join(lines)


def assemble(
    paper: str,
    title: str,
    sections: Sequence[Callable],
    shared,
    parameters: list[Parameter],
) -> Report:
    """The report of ``paper``: the rows of each section in order (a section is a function
    of the ``shared`` reproduction state that writes its CSV/PNG into ``shared.out`` and
    returns its rows), the ``parameters`` and the CSV/PNG files found in ``shared.out``.

    >>> import types, tempfile
    >>> shared = types.SimpleNamespace(out=Path(tempfile.mkdtemp()))
    >>> rep = assemble("p", "t", [lambda s: [check("x", "q", 1.0, 1.0, "N")]], shared, [])
    >>> [r.status for r in rep.rows]
    ['reproduced']
    """
    rep = Report(paper=paper, title=title, parameters=parameters)
    for section in sections:
        rep.rows += section(shared)
    out = Path(shared.out)
    rep.files = sorted(str(f) for f in out.glob("*") if f.suffix in (".csv", ".png"))
    return rep


def summary_line(summary: dict[str, dict[str, int]]) -> str:
    """One line: the rows counted per kind (predictions first) and status.

    >>> summary_line({"prediction": {"reproduced": 2}, "calibration": {"calibrated": 1}})
    'predictions: 2 reproduced | calibrations: 1 calibrated'
    """
    return " | ".join(
        f"{kind}s: " + ", ".join(f"{n} {s}" for s, n in counts.items())
        for kind, counts in summary.items()
    )


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


def _tolerance_text(rule: Rule, tol: float, unit: str) -> str:
    if rule.rel and not rule.half_digit and not rule.of_change:
        return f"±{rule.rel * 100:g} % [{rule.key}]"
    return f"±{tol:.3g} {unit} [{rule.key}]".replace("  ", " ")


def _join(*parts: str) -> str:
    """The non-empty parts as sentences: a part that does not end in punctuation gets a full
    stop, and the part after a full stop starts with a capital."""
    out = []
    for p in (p.strip() for p in parts if p and p.strip()):
        if out and out[-1].endswith("."):
            p = p[0].upper() + p[1:]
        elif out and not out[-1].endswith((":", ";")):
            out[-1] += "."
            p = p[0].upper() + p[1:]
        out.append(p)
    return " ".join(out)


def _numeric(
    kind: str,
    id: str,
    quantity: str,
    published: float,
    computed: float,
    unit: str,
    rule: Rule,
    *,
    printed: str | None = None,
    reference: float | None = None,
    note: str = "",
    miss_note: str = "",
) -> Row:
    tol = rule.tolerance(published, printed, reference)
    ok = bool(np.isfinite(computed)) and abs(computed - published) <= tol
    status = _MET[kind] if ok else "not-reproduced"
    text = note if ok else _join(note, miss_note)
    return Row(
        id,
        quantity,
        kind,
        published,
        float(computed),
        unit,
        status,
        _tolerance_text(rule, tol, unit),
        rule.key,
        text,
    )


def prediction(
    id: str, quantity: str, published: float, computed: float, unit: str, rule: Rule, **options
) -> Row:
    """A predicted number: ``reproduced`` when |computed − published| is within the
    tolerance of ``rule``, else ``not-reproduced``. ``options``: ``printed`` (the paper's text
    of the number) and ``reference`` (the published reference of a change) as the rule needs
    them, ``note``, and ``miss_note`` (added when missed).

    >>> prediction("x", "q", 2.0, 2.1, "N", PAPER_MODEL, printed="2.0").status
    'reproduced'
    """
    return _numeric("prediction", id, quantity, published, computed, unit, rule, **options)


def check(
    id: str,
    quantity: str,
    published: float,
    computed: float,
    unit: str,
    *,
    note: str = "",
    miss_note: str = "",
) -> Row:
    """The paper's own printed values through its own equation, at the arithmetic rule:
    ``reproduced`` or ``not-reproduced``.

    >>> check("x", "q", 100.0, 100.05, "N").status
    'reproduced'
    """
    return _numeric(
        "check", id, quantity, published, computed, unit, ARITHMETIC, note=note, miss_note=miss_note
    )


def consequence(
    id: str,
    quantity: str,
    published: float,
    computed: float,
    unit: str,
    of: str,
    *,
    rule: Rule = ARITHMETIC,
    note: str = "",
    **options,
) -> Row:
    """A number that follows arithmetically from the calibrated row(s) ``of`` (how, in
    ``note``): ``consequence`` within the tolerance of ``rule``, else ``not-reproduced``;
    ``options`` as for :func:`prediction`.

    >>> consequence("x", "q", 2.0, 2.0, "N", "x.1", note="2 × x.1").status
    'consequence'
    """
    note = _join(f"follows from {of}:", note)
    return _numeric(
        "consequence", id, quantity, published, computed, unit, rule, note=note, **options
    )


def calibrated(
    id: str,
    quantity: str,
    published: float,
    computed: float,
    unit: str,
    coefficient: str,
    *,
    note: str = "",
    rule: Rule = FIT,
) -> Row:
    """A number a coefficient was fitted on: ``calibrated`` when the fit reached it (rule
    :data:`FIT`, or ``rule`` for a fit through more points than coefficients), else
    ``not-reproduced`` (the fit failed).

    >>> calibrated("x", "q", 2.3, 2.3, "N", "s0 = 0.7").status
    'calibrated'
    """
    return _numeric(
        "calibration",
        id,
        quantity,
        published,
        computed,
        unit,
        rule,
        note=_join(f"calibrated: {coefficient}.", note),
        miss_note="the fit did not reach its target",
    )


def in_range(
    id: str,
    quantity: str,
    low: str,
    high: str,
    computed: float,
    unit: str,
    *,
    note: str = "",
    miss_note: str = "",
) -> Row:
    """A prediction of a number published as a range (``low``, ``high`` as printed):
    ``reproduced`` inside it, else ``not-reproduced``.

    >>> in_range("x", "q", "1.2", "1.5", 1.3, "").status
    'reproduced'
    """
    ok = bool(np.isfinite(computed)) and float(low) <= computed <= float(high)
    status = "reproduced" if ok else "not-reproduced"
    text = note if ok else _join(note, miss_note)
    bounds = f"{low}…{high}"
    return Row(
        id,
        quantity,
        "prediction",
        bounds,
        float(computed),
        unit,
        status,
        f"{bounds} [{RANGE.key}]",
        RANGE.key,
        text,
    )


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
    model's curve), else ``not-reproduced``.

    >>> trend("x", "q", "rises", True, "rises by 2 N").status
    'qualitative'
    """
    status = "qualitative" if bool(holds) else "not-reproduced"
    text = note if holds else _join(note, miss_note)
    return Row(id, quantity, "trend", published, computed, "", status, TREND.key, TREND.key, text)


def write_csv(path: Path, columns: dict[str, Sequence[float]]) -> Path:
    """Write equal-length columns (header "name [unit]") to ``path``."""
    names = list(columns)
    data = np.column_stack([np.asarray(columns[n], dtype=float) for n in names])
    with written(path) as part, part.open("w", newline="") as fh:
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
    save_figure(fig, path)
    plt.close(fig)
    return path

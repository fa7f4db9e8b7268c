"""Measured friction torque from a CSV file, converted to SI at this edge.

The file has a header row whose columns name a quantity and its unit in brackets:

- ``temperature [degC]`` or ``temperature [K]`` — required;
- ``torque [N.mm]`` or ``torque [N.m]`` — required; signed values are read as magnitudes;
- ``speed [deg/s]``, ``speed [rad/s]`` or ``speed [rpm]`` — optional; its sign gives the
  direction when there is no direction column;
- ``direction`` — optional, ``forward`` or ``reverse``.

Lines starting with ``#`` are comments (provenance of the data); blank lines are skipped;
other columns are ignored and listed. Every problem is a :class:`DataError` naming the file,
the line and the column (the first problem in the file).

The file is read in blocks of :data:`BLOCK_CHARS` characters, parsed by numpy's C reader
(``numpy.loadtxt``; a block with a problem is read again line by line for the message), and
each block is reduced at once to per-group statistics: points of one temperature, speed and
direction form a group, which keeps its count, the mean and the sum of squared deviations of
the torque and of its reciprocal (Welford/Chan, exact to rounding), and its first line. The
memory a file needs grows with its number of distinct operating points, not with its length;
least squares on these statistics is the same as on the points (see :mod:`.fit`).
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..physics.kernels.units import DEG, NMM, RPM, ZERO_CELSIUS

#: Valid temperatures of the bearing model [K] (the BearingFriction FMU's input range).
TEMPERATURE_RANGE = (173.15, 473.15)

#: Units accepted per quantity: SI value = factor·value + offset.
UNITS: dict[str, dict[str, tuple[float, float]]] = {
    "temperature": {"degC": (1.0, ZERO_CELSIUS), "K": (1.0, 0.0)},
    "torque": {"N.mm": (NMM, 0.0), "N.m": (1.0, 0.0)},
    "speed": {"deg/s": (DEG, 0.0), "rad/s": (1.0, 0.0), "rpm": (RPM, 0.0)},
}
DIRECTIONS = ("forward", "reverse")
_HEADER = re.compile(r"^\s*([A-Za-z_]+)\s*(?:\[\s*([^\]]*?)\s*\])?\s*$")


class DataError(ValueError):
    """Measured data that cannot be used; the message names file, line and column."""


#: Characters read and reduced at once (bounds the memory of a long file: about 10 times
#: this while a block is parsed).
BLOCK_CHARS = 1 << 22
#: Longest line of a measurements file [characters] (a file without line breaks is refused).
MAX_LINE_CHARS = 1 << 20


@dataclass(frozen=True)
class FrictionMeasurements:
    """Measured running friction torque of a bearing pair (SI), as groups of points that
    share temperature, speed and direction (a group per point when built from arrays).

    Attributes
    ----------
    source : file name
    temperature : T [K] per group
    torque : mean |M| [N·m] per group
    speed : |ω| [rad/s] per group, or None when the file has no speed column
    direction : "forward", "reverse" or "" per group
    lines : line number in the file of each group's first point
    ignored_columns : columns that were not read
    count : points per group (default: one each)
    torque_ss : Σ(|M| − mean)² per group [N²·m²] (default 0)
    inverse_mean : mean of 1/|M| per group [1/(N·m)] (default 1/torque)
    inverse_ss : Σ(1/|M| − inverse_mean)² per group [1/(N·m)²] (default 0)
    """

    source: str
    temperature: np.ndarray
    torque: np.ndarray
    speed: np.ndarray | None
    direction: tuple[str, ...]
    lines: tuple[int, ...]
    ignored_columns: tuple[str, ...] = ()
    count: np.ndarray = field(default=None)
    torque_ss: np.ndarray = field(default=None)
    inverse_mean: np.ndarray = field(default=None)
    inverse_ss: np.ndarray = field(default=None)

    def __post_init__(self):
        torque = np.asarray(self.torque, dtype=float)
        defaults = {
            "count": np.ones(torque.shape, dtype=np.int64),
            "torque_ss": np.zeros(torque.shape),
            "inverse_mean": 1.0 / torque,
            "inverse_ss": np.zeros(torque.shape),
        }
        for name, default in defaults.items():
            if getattr(self, name) is None:
                object.__setattr__(self, name, default)

    def __len__(self) -> int:
        """Number of points (rows of the file)."""
        return int(np.sum(self.count))

    @property
    def groups(self) -> int:
        """Number of groups (distinct temperature, speed and direction)."""
        return len(self.torque)

    @property
    def torque_sd(self) -> np.ndarray:
        """Sample standard deviation of |M| per group [N·m] (0 for a single point)."""
        n = self.count
        return np.sqrt(np.where(n > 1, self.torque_ss / np.maximum(n - 1, 1), 0.0))


def parse_quantity(text: str, quantity: str) -> float:
    """``"10 deg/s"`` → 0.1745 (SI) for ``quantity`` "speed" (or "temperature", "torque")."""
    parts = text.split()
    units = UNITS[quantity]
    if len(parts) != 2 or parts[1] not in units:
        raise ValueError(
            f"{quantity} = {text!r}: write a number and one of the units {list(units)}, "
            f"e.g. '10 {next(iter(units))}'"
        )
    try:
        value = float(parts[0])
    except ValueError:
        raise ValueError(f"{quantity} = {text!r}: {parts[0]!r} is not a number") from None
    factor, offset = units[parts[1]]
    return factor * value + offset


def _columns(header: list[str], where: str) -> tuple[dict[str, tuple[int, str, str]], list[str]]:
    """{quantity: (index, column text, unit)} and the ignored columns."""
    found, ignored = {}, []
    for i, text in enumerate(header):
        m = _HEADER.match(text)
        name = m.group(1).lower() if m else None
        if name not in (*UNITS, "direction"):
            ignored.append(text)
            continue
        if name in found:
            raise DataError(f"{where}: two {name!r} columns ({found[name][1]!r}, {text!r})")
        unit = m.group(2)
        if name in UNITS:
            if unit not in UNITS[name]:
                raise DataError(
                    f"{where}, column {text!r}: unit {unit!r} is not one of {list(UNITS[name])} "
                    f"(write the header as '{name} [{next(iter(UNITS[name]))}]')"
                )
        found[name] = (i, text, unit)
    for name in ("temperature", "torque"):
        if name not in found:
            raise DataError(
                f"{where}: no {name!r} column; the header must name it with its unit, e.g. "
                f"'{name} [{next(iter(UNITS[name]))}]' (columns: {header})"
            )
    return found, ignored


def read_measurements(path) -> FrictionMeasurements:
    """Read measured friction torque versus temperature (and speed) from ``path``; raises
    :class:`DataError` naming the line and column of the first unusable value. The file is
    read in blocks and reduced to per-group statistics as it goes (bounded memory)."""
    path = Path(path)
    name = path.name
    try:
        fh = path.open(encoding="utf-8")
    except OSError as exc:
        raise DataError(f"{path}: cannot read ({exc.strerror})") from None
    groups = _Groups()
    with fh:
        try:
            header_line, header = _header(fh, name)
            cols, ignored = _columns(header, f"{name} line {header_line}")
            line, pending = header_line, ""
            while True:
                chunk = fh.read(BLOCK_CHARS)
                text, pending = pending + chunk, ""
                cut = text.rfind("\n")
                if chunk and cut < len(text) - 1:  # keep a partial last line for the next block
                    text, pending = text[: cut + 1], text[cut + 1 :]
                    if len(pending) > MAX_LINE_CHARS:  # /dev/zero, a binary file
                        raise DataError(
                            f"{name}: line {line + text.count(chr(10)) + 1} is longer than "
                            f"{MAX_LINE_CHARS} characters: not a table of measurements"
                        )
                if text:
                    block = _block(text, line + 1, header, cols, name)
                    groups.add(*block[:5])
                    line += block[5]
                if not chunk:
                    break
        except UnicodeDecodeError as exc:
            raise DataError(f"{name}: not a text file ({exc.reason})") from None
    if not groups.keys:
        raise DataError(f"{name}: a header but no data rows")
    return groups.measurements(name, "speed" in cols, tuple(ignored))


def _header(fh, name: str) -> tuple[int, list[str]]:
    """(line number, cells) of the first line that is neither blank nor a comment."""
    n = 0
    while text := fh.readline(MAX_LINE_CHARS + 1):
        n += 1
        if len(text) > MAX_LINE_CHARS:
            raise DataError(
                f"{name}: line {n} is longer than {MAX_LINE_CHARS} characters: not a table of "
                "measurements"
            )
        if text.strip() and not text.lstrip().startswith("#"):
            return n, next(csv.reader([text]))
    raise DataError(f"{name}: no header and no data")


_BLANK = re.compile(r"^[ \t\r\f\v]*$", re.MULTILINE)


def _block(text: str, first: int, header, cols, name):
    """The arrays of :func:`_parse` for the lines of ``text`` (numbered from ``first``) and
    their number: numpy's C reader when the block is clean, else line by line (which raises
    the first problem)."""
    lines = text.split("\n")
    if lines[-1] == "":
        lines.pop()
    numbers = np.arange(first, first + len(lines))
    if "#" not in text and not _BLANK.search(text.rstrip("\n")):  # no comment, blank line
        fast = _fast(lines, numbers, header, cols)
        if fast is not None:
            return (*fast, len(lines))
    return (*_slow(lines, numbers, header, cols, name), len(lines))


def _slow(lines, numbers, header, cols, name):
    rows = [
        (n, x) for n, x in zip(numbers.tolist(), lines, strict=True)
        if x.strip() and not x.lstrip().startswith("#")
    ]  # fmt: skip
    if not rows:
        return (np.zeros(0, int), np.zeros(0), np.zeros(0), np.zeros(0), np.zeros(0, int))
    fast = _fast([x for _, x in rows], np.array([n for n, _ in rows]), header, cols)
    return fast if fast is not None else _parse(rows, header, cols, name)


def _fast(lines, numbers, header, cols):
    """:func:`_parse` by ``numpy.loadtxt`` (every row must have the header's cells), or None
    when any value is missing, not a number, out of range or the direction unknown (then
    :func:`_parse` finds and names it)."""
    quantities = {cols[q][0]: q for q in UNITS if q in cols}
    i_dir = cols["direction"][0] if "direction" in cols else None
    dtype = [
        (f"c{i}", float if i in quantities else "U16" if i == i_dir else "U1")
        for i in range(len(header))
    ]
    try:
        table = np.loadtxt(lines, delimiter=",", dtype=dtype, comments=None, quotechar='"', ndmin=1)
    except ValueError:
        return None
    if len(table) != len(lines):
        return None
    values = {}
    for i, q in quantities.items():
        factor, offset = UNITS[q][cols[q][2]]
        values[q] = factor * table[f"c{i}"] + offset
        if not np.all(np.isfinite(values[q])):
            return None
    t, m = values["temperature"], values["torque"]
    lo, hi = TEMPERATURE_RANGE
    if not (np.all((t >= lo) & (t <= hi)) and np.all(m != 0.0)):
        return None
    w = values.get("speed", np.zeros(len(lines)))
    direction = np.where(w > 0, 1, np.where(w < 0, 2, 0))
    if i_dir is not None:
        text = table[f"c{i_dir}"]
        direction = np.where(text == DIRECTIONS[0], 1, np.where(text == DIRECTIONS[1], 2, -1))
        odd = direction < 0
        if np.any(odd):  # spaces or capitals: normalise those few
            norm = np.char.lower(np.char.strip(text[odd]))
            direction[odd] = np.where(
                norm == DIRECTIONS[0], 1, np.where(norm == DIRECTIONS[1], 2, -1)
            )
            if np.any(direction < 0):
                return None
    return numbers, t, np.abs(m), np.abs(w), direction


def _parse(rows, header, cols, name):
    """Arrays of one block: line numbers, T [K], |M| [N·m], |ω| [rad/s] (0 without a speed
    column) and direction codes (index into ("",) + DIRECTIONS); DataError for the first
    problem of the block, in the order of the lines and, within a line, of the columns."""
    numbers = np.array([n for n, _ in rows])
    cells = list(csv.reader(text for _, text in rows))
    problems = []  # (row index, order within the row, message)
    widths = np.fromiter(map(len, cells), dtype=np.int64, count=len(cells))
    if np.any(widths != len(header)):
        i = int(np.flatnonzero(widths != len(header))[0])
        problems.append((i, 0, f"{name} line {numbers[i]}: {widths[i]} cells for "
                               f"{len(header)} columns ({header})"))  # fmt: skip
        cells = [c if len(c) == len(header) else [""] * len(header) for c in cells]
    values = {}
    for order, q in enumerate(("temperature", "torque", "speed"), start=1):
        if q in cols:
            values[q], problem = _column(q, cols[q], cells, numbers, name)
            if problem:
                problems.append((problem[0], order, problem[1]))
    t, m = values["temperature"], values["torque"]
    lo, hi = TEMPERATURE_RANGE
    for i in np.flatnonzero(~((t >= lo) & (t <= hi)))[:1]:
        _, col, unit = cols["temperature"]
        f, o = UNITS["temperature"][unit]
        problems.append((int(i), 1.5, (
            f"{name} line {numbers[i]}, column {col!r}: {(t[i] - o) / f:g} {unit} is outside the "
            f"model's range [{(lo - o) / f:g}, {(hi - o) / f:g}] {unit}"
        )))  # fmt: skip
    for i in np.flatnonzero(m == 0.0)[:1]:
        problems.append((int(i), 2.5, (
            f"{name} line {numbers[i]}, column {cols['torque'][1]!r}: a torque of 0 is no "
            "friction measurement"
        )))  # fmt: skip
    w = values.get("speed", np.zeros(len(cells)))
    direction = np.where(w > 0, 1, np.where(w < 0, 2, 0))
    if "direction" in cols:
        i_col, col, _ = cols["direction"]
        text = [c[i_col] for c in cells]
        codes = {d: k for k, d in enumerate(DIRECTIONS, start=1)}
        direction = np.array([codes.get(x.strip().lower(), -1) for x in text])
        for i in np.flatnonzero(direction < 0)[:1]:
            problems.append((int(i), 4, (
                f"{name} line {numbers[i]}, column {col!r}: {text[i]!r} is not one of "
                f"{list(DIRECTIONS)}"
            )))  # fmt: skip
    if problems:
        raise DataError(min(problems, key=lambda pr: (pr[0], pr[1]))[2])
    return numbers, t, np.abs(m), np.abs(w), direction


def _column(q, spec, cells, numbers, name):
    """(SI values, first problem as (row index, message) or None) of quantity ``q``."""
    i_col, col, unit = spec
    raw = [c[i_col] for c in cells]
    try:
        x = np.array(raw, dtype=float)
    except ValueError:
        x = np.array([_number(c) for c in raw])
    bad = ~np.isfinite(x)
    problem = None
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        cell = raw[i].strip()
        why = "empty" if not cell else (
            f"{cell!r} is not a number" if math.isnan(_number(cell)) and cell.lower() != "nan"
            else f"{cell!r} is not finite"
        )  # fmt: skip
        problem = (i, f"{name} line {numbers[i]}, column {col!r}: {why}")
        x[bad] = np.nan
    factor, offset = UNITS[q][unit]
    return factor * x + offset, problem


def _number(cell: str) -> float:
    """float(cell), NaN when it is none."""
    try:
        return float(cell)
    except ValueError:
        return math.nan


class _Groups:
    """Per-group statistics of the points read so far, merged block by block (Chan et al.'s
    pairwise update of count, mean and sum of squared deviations), in order of first
    appearance."""

    def __init__(self):
        self.keys: dict[tuple[float, float, int], int] = {}
        self.stats: list[list] = []  # n, mean M, ss M, mean 1/M, ss 1/M, first line

    def add(self, numbers, t, m, w, direction):
        if not len(numbers):
            return
        codes = [np.unique(x, return_inverse=True)[1].ravel() for x in (t, w)]
        key = (codes[0] * (codes[1].max() + 1) + codes[1]) * 3 + direction
        _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
        inverse = inverse.ravel()
        uniq = np.column_stack([t[first], w[first], direction[first]])
        n = np.bincount(inverse)
        stats = [n]
        for y in (m, 1.0 / m):
            mean = np.bincount(inverse, y) / n
            stats += [mean, np.bincount(inverse, (y - mean[inverse]) ** 2)]
        for g in np.argsort(first):  # the block's groups in file order
            key = (float(uniq[g, 0]), float(uniq[g, 1]), int(uniq[g, 2]))
            new = [int(n[g]), stats[1][g], stats[2][g], stats[3][g], stats[4][g]]
            k = self.keys.get(key)
            if k is None:
                self.keys[key] = len(self.stats)
                self.stats.append([*new, int(numbers[first[g]])])
            else:
                self.stats[k][:5] = _merge(self.stats[k][:5], new)

    def measurements(self, source, has_speed, ignored) -> FrictionMeasurements:
        keys = list(self.keys)
        s = list(zip(*self.stats, strict=True))
        return FrictionMeasurements(
            source=source,
            temperature=np.array([k[0] for k in keys]),
            torque=np.array(s[1]),
            speed=np.array([k[1] for k in keys]) if has_speed else None,
            direction=tuple(("", *DIRECTIONS)[k[2]] for k in keys),
            lines=tuple(s[5]),
            ignored_columns=ignored,
            count=np.array(s[0], dtype=np.int64),
            torque_ss=np.array(s[2]),
            inverse_mean=np.array(s[3]),
            inverse_ss=np.array(s[4]),
        )


def _merge(a, b):
    """Count, mean and sum of squared deviations of two samples' union (two quantities)."""
    na, nb = a[0], b[0]
    n = na + nb
    out = [n]
    for j in (1, 3):
        delta = b[j] - a[j]
        out += [a[j] + delta * nb / n, a[j + 1] + b[j + 1] + delta * delta * na * nb / n]
    return out

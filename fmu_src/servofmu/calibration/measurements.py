"""Measured friction torque from a CSV file, converted to SI at this edge.

The file has a header row whose columns name a quantity and its unit in brackets:

- ``temperature [degC]`` or ``temperature [K]`` — required;
- ``torque [N.mm]`` or ``torque [N.m]`` — required; signed values are read as magnitudes;
- ``speed [deg/s]``, ``speed [rad/s]`` or ``speed [rpm]`` — optional; its sign gives the
  direction when there is no direction column;
- ``direction`` — optional, ``forward`` or ``reverse``.

Lines starting with ``#`` are comments (provenance of the data); blank lines are skipped;
other columns are ignored and listed. Every problem is a :class:`DataError` naming the file,
the line and the column.
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..physics.units import DEG, NMM, RPM, ZERO_CELSIUS

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


@dataclass(frozen=True)
class FrictionMeasurements:
    """Measured running friction torque of a bearing pair (SI).

    Attributes
    ----------
    source : file name
    temperature : T [K] per point
    torque : |M| [N·m] per point
    speed : |ω| [rad/s] per point, or None when the file has no speed column
    direction : "forward", "reverse" or "" per point
    lines : line number in the file of each point
    ignored_columns : columns that were not read
    """

    source: str
    temperature: np.ndarray
    torque: np.ndarray
    speed: np.ndarray | None
    direction: tuple[str, ...]
    lines: tuple[int, ...]
    ignored_columns: tuple[str, ...] = ()

    def __len__(self) -> int:
        return len(self.torque)


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
    :class:`DataError` naming the line and column of any unusable value."""
    path = Path(path)
    name = path.name
    try:
        text = path.read_text()
    except OSError as exc:
        raise DataError(f"{path}: cannot read ({exc.strerror})") from None
    lines = [
        (n, line)
        for n, line in enumerate(text.splitlines(), start=1)
        if line.strip() and not line.lstrip().startswith("#")
    ]
    if not lines:
        raise DataError(f"{name}: no header and no data")
    header_line, header_text = lines[0]
    header = next(csv.reader([header_text]))
    cols, ignored = _columns(header, f"{name} line {header_line}")
    temps, torques, speeds, directions, numbers = [], [], [], [], []
    for n, line in lines[1:]:
        cells = next(csv.reader([line]))
        if len(cells) != len(header):
            raise DataError(
                f"{name} line {n}: {len(cells)} cells for {len(header)} columns ({header})"
            )

        def number(q, n=n, cells=cells):
            i, col, unit = cols[q]
            cell = cells[i].strip()
            if not cell:
                raise DataError(f"{name} line {n}, column {col!r}: empty")
            try:
                value = float(cell)
            except ValueError:
                raise DataError(
                    f"{name} line {n}, column {col!r}: {cell!r} is not a number"
                ) from None
            if not math.isfinite(value):
                raise DataError(f"{name} line {n}, column {col!r}: {cell!r} is not finite")
            factor, offset = UNITS[q][unit]
            return factor * value + offset, value, col, unit

        t, t_raw, t_col, t_unit = number("temperature")
        lo, hi = TEMPERATURE_RANGE
        if not lo <= t <= hi:
            f, o = UNITS["temperature"][t_unit]
            raise DataError(
                f"{name} line {n}, column {t_col!r}: {t_raw:g} {t_unit} is outside the model's "
                f"range [{(lo - o) / f:g}, {(hi - o) / f:g}] {t_unit}"
            )
        m, _, m_col, _ = number("torque")
        if m == 0.0:
            raise DataError(
                f"{name} line {n}, column {m_col!r}: a torque of 0 is no friction measurement"
            )
        direction = ""
        if "speed" in cols:
            w, _, _, _ = number("speed")
            speeds.append(abs(w))
            direction = "forward" if w > 0 else "reverse" if w < 0 else ""
        if "direction" in cols:
            i, col, _ = cols["direction"]
            direction = cells[i].strip().lower()
            if direction not in DIRECTIONS:
                raise DataError(
                    f"{name} line {n}, column {col!r}: {cells[i]!r} is not one of "
                    f"{list(DIRECTIONS)}"
                )
        temps.append(t)
        torques.append(abs(m))
        directions.append(direction)
        numbers.append(n)
    if not torques:
        raise DataError(f"{name}: a header but no data rows")
    return FrictionMeasurements(
        source=name,
        temperature=np.array(temps),
        torque=np.array(torques),
        speed=np.array(speeds) if "speed" in cols else None,
        direction=tuple(directions),
        lines=tuple(numbers),
        ignored_columns=tuple(ignored),
    )

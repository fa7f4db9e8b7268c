"""Units of recorded variables, for the people who read the results: CSV headers
``name [unit]`` in the FMUs' SI units, plot axes in the display units the FMUs declare
(``N.mm``, ``degC``, …), and the results CSV read back by name.

The unit of a variable is its FMU's (modelDescription ``unit``, or its declared type's); a
variable that declares none takes the unit of the variable connected to it, then the unit its
SSD connector declares. A display unit converts as ``display = factor·SI + offset`` (FMI 2.0
``DisplayUnit``).
"""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

#: How units are written on plots (the CSV keeps the FMI spelling, as ``servofmu calibrate``
#: reads it).
PRETTY = {
    "degC": "°C",
    "deg": "°",
    "deg/s": "°/s",
    "N.m": "N·m",
    "N.mm": "N·mm",
    "N.m/rad": "N·m/rad",
    "N.m/deg": "N·m/°",
    "um": "µm",
    "m2/s": "m²/s",
    "N/um": "N/µm",
    "1": "-",
}
_HEADER = re.compile(r"^(?P<name>.*?)\s*\[(?P<unit>[^\]]*)\]\s*$")


@dataclass(frozen=True)
class Scale:
    """How one recorded quantity is labelled and shown: SI ``unit`` (None: none declared),
    the ``display`` unit with ``display = factor·value + offset``, and whether it is a
    Boolean (recorded as 0/1)."""

    unit: str | None
    display: str | None = None
    factor: float = 1.0
    offset: float = 0.0
    boolean: bool = False

    @property
    def csv_unit(self) -> str:
        """The unit written in a CSV header: the SI unit, ``-`` when dimensionless, ``0/1``
        for a Boolean, ``unit not declared`` when the FMU gives none.

        >>> Scale("N.m", "N.mm", 1000.0).csv_unit, Scale("1").csv_unit
        ('N.m', '-')
        """
        if self.boolean:
            return "0/1"
        if self.unit is None:
            return "unit not declared"
        return "-" if self.unit in ("1", "") else self.unit

    def shown(self, values) -> np.ndarray:
        """``values`` [SI] in the display unit.

        >>> float(Scale("K", "degC", 1.0, -273.15).shown(293.15))
        20.0
        """
        return self.factor * np.asarray(values, dtype=float) + self.offset

    @property
    def shown_unit(self) -> str:
        """The unit of :meth:`shown`, as printed on a plot.

        >>> Scale("N.m", "N.mm", 1000.0).shown_unit
        'N·mm'
        """
        if self.boolean:
            return "0/1"
        unit = self.display or self.unit
        if unit is None:
            return "unit not declared"
        return pretty(unit)


TIME = Scale("s")


def pretty(unit: str) -> str:
    """An FMI unit string as printed on a plot.

    >>> pretty("N.mm"), pretty("degC"), pretty("rad/s")
    ('N·mm', '°C', 'rad/s')
    """
    return PRETTY.get(unit, unit.replace(".", "·"))


def header(name: str, scale: Scale) -> str:
    """A CSV header cell ``name [unit]``.

    >>> header("bearing.running_torque", Scale("N.m", "N.mm", 1000.0))
    'bearing.running_torque [N.m]'
    """
    return f"{name} [{scale.csv_unit}]"


def label(name: str, scale: Scale) -> str:
    """A plot axis label ``name [display unit]``.

    >>> label("bearing.temperature", Scale("K", "degC", 1.0, -273.15))
    'bearing.temperature [°C]'
    """
    return f"{name} [{scale.shown_unit}]"


def split_header(cell: str) -> tuple[str, str | None]:
    """(name, unit) of a CSV header cell ``name [unit]``; unit None when there is none.

    >>> split_header("motor.speed [rad/s]")
    ('motor.speed', 'rad/s')
    """
    m = _HEADER.match(cell)
    return (m["name"], m["unit"]) if m else (cell.strip(), None)


def read_results(path) -> tuple[np.ndarray, dict[str, str | None]]:
    """A results CSV written by the harness (:meth:`~.master.RunResult.to_csv`): a
    structured array whose fields are the variable names (``time``, ``motor.speed``, …) and
    the unit of each field as its header gives it."""
    path = Path(path)
    with path.open(newline="") as fh:
        cells = next(csv.reader(fh))
    names, units = zip(*(split_header(c) for c in cells), strict=True)
    values = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    data = np.rec.fromarrays(values.T, dtype=[(n, float) for n in names]).view(np.ndarray)
    return data, dict(zip(names, units, strict=True))

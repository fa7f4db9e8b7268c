"""Temperatures of the parts of a bearing mounting.

Yu 2017 and Ning hold every part at one uniform temperature (their chambers soak for 30 min
before each measurement). While the temperature changes, the parts differ: the frame follows
the chamber within minutes and the shaft inside lags (a thermal network gives the part
temperatures). The thermal state of a bearing pair (:func:`bearing.thermal_state`) therefore
takes either one uniform temperature or a :class:`PartTemperatures` record, and each part grows
with its own temperature:

- ``housing``: the frame or housing around the outer rings (bore, boss, and the loop members
  of ``part = "housing"``);
- ``shaft``: the shaft inside the inner rings (and loop members of ``part = "shaft"``, e.g. an
  inner spacer);
- ``outer_ring``, ``inner_ring``: the bearing rings (their raceways and groove radii);
- the balls sit between the rings and take their mean, 0.5·(outer_ring + inner_ring), and so
  does the lubricant in the contacts (its viscosity); the bearing widths in the preload loop
  (``part = "rings"``) take the same mean.

A uniform temperature T is the record with every part at T; the model evaluates both through
the same equations, so equal part temperatures give exactly the uniform result.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._checks import check_operating_temperature

#: The temperature inputs of a mounting, in the order of :class:`PartTemperatures`.
PARTS = ("housing", "shaft", "outer_ring", "inner_ring")
#: Parts a preload-loop member can follow (``rings``: the mean of the two ring temperatures).
MEMBER_PARTS = ("housing", "shaft", "rings")


@dataclass(frozen=True)
class PartTemperatures:
    """Temperatures [K] of housing, shaft, outer ring and inner ring (floats or arrays that
    broadcast together).

    >>> t = PartTemperatures(253.15, 263.15, 255.15, 261.15)
    >>> t.balls
    258.15
    """

    housing: float | np.ndarray
    shaft: float | np.ndarray
    outer_ring: float | np.ndarray
    inner_ring: float | np.ndarray

    @classmethod
    def uniform(cls, temperature) -> PartTemperatures:
        """Every part at ``temperature`` [K] (float or array).

        >>> PartTemperatures.uniform(293.15).shaft
        293.15
        """
        t = check_operating_temperature("temperature", temperature)
        return cls(t, t, t, t)

    @property
    def balls(self):
        """Ball (and lubricant film) temperature [K]: the mean of the ring temperatures."""
        return 0.5 * (self.outer_ring + self.inner_ring)

    @property
    def lubricant(self):
        """Temperature of the lubricant in the contacts [K]: the balls' temperature."""
        return self.balls

    def of(self, part: str):
        """Temperature [K] of ``part``: one of :data:`PARTS`, or ``rings`` (the balls' mean).

        >>> PartTemperatures(250.0, 260.0, 270.0, 280.0).of("rings")
        275.0
        """
        return self.balls if part == "rings" else getattr(self, part)

    @property
    def is_uniform(self) -> bool:
        """Whether every part has the same temperature (everywhere, for arrays)."""
        return bool(
            np.all(np.asarray(self.housing) == self.shaft)
            and np.all(np.asarray(self.shaft) == self.outer_ring)
            and np.all(np.asarray(self.outer_ring) == self.inner_ring)
        )


def part_temperatures(temperature) -> PartTemperatures:
    """``temperature`` as a checked :class:`PartTemperatures`: a float or array [K] is a
    uniform temperature; a record has each of its parts checked (within the FMUs' 173.15…473.15 K).

    Returns
    -------
    PartTemperatures
        Temperatures in kelvin, float fields for float input.

    >>> part_temperatures(300.0).inner_ring
    300.0
    """
    if isinstance(temperature, PartTemperatures):
        return PartTemperatures(
            *(
                check_operating_temperature(f"{p}_temperature", getattr(temperature, p))
                for p in PARTS
            )
        )
    return PartTemperatures.uniform(temperature)

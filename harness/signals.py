"""External input signals for the harness: functions of time applied to unconnected inputs
(e.g. a chamber temperature profile). Each signal is a callable ``s(t) -> float``."""

from __future__ import annotations

import bisect
import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path

from servofmu.files import read_input


@dataclass(frozen=True)
class Constant:
    """value for all t."""

    value: float

    def __call__(self, t: float) -> float:
        return self.value


@dataclass(frozen=True)
class Steps:
    """values[i] from times[i] on (values[0] before times[0]); times ascending [s]."""

    times: tuple[float, ...]
    values: tuple[float, ...]

    def __post_init__(self):
        if len(self.times) != len(self.values) or not self.times:
            raise ValueError("Steps needs as many times as values (at least one)")
        if any(b <= a for a, b in zip(self.times, self.times[1:], strict=False)):
            raise ValueError(f"Steps times = {self.times} must increase")

    def __call__(self, t: float) -> float:
        return self.values[max(bisect.bisect_right(self.times, t) - 1, 0)]


@dataclass(frozen=True)
class PiecewiseLinear:
    """Linear interpolation between (times[i], values[i]), constant outside."""

    times: tuple[float, ...]
    values: tuple[float, ...]

    def __post_init__(self):
        if len(self.times) != len(self.values) or len(self.times) < 2:
            raise ValueError("PiecewiseLinear needs as many times as values (at least two)")
        if any(b <= a for a, b in zip(self.times, self.times[1:], strict=False)):
            raise ValueError(f"PiecewiseLinear times = {self.times} must increase")

    def __call__(self, t: float) -> float:
        ts, vs = self.times, self.values
        if t <= ts[0]:
            return vs[0]
        if t >= ts[-1]:
            return vs[-1]
        i = bisect.bisect_right(ts, t) - 1
        w = (t - ts[i]) / (ts[i + 1] - ts[i])
        return vs[i] + w * (vs[i + 1] - vs[i])


def Ramp(t0: float, t1: float, v0: float, v1: float) -> PiecewiseLinear:
    """v0 until t0, linear to v1 at t1, v1 after."""
    return PiecewiseLinear((t0, t1), (v0, v1))


@dataclass(frozen=True)
class Cycle:
    """A periodic signal between low and high: "triangle" (starts at low, rises) or "sine"
    (starts at the mid value, rises), period [s], from ``start`` [s] (low/mid before)."""

    low: float
    high: float
    period: float
    shape: str = "triangle"
    start: float = 0.0

    def __post_init__(self):
        if self.shape not in ("triangle", "sine"):
            raise ValueError(f"Cycle shape = {self.shape!r} is not one of ['sine', 'triangle']")
        if not self.period > 0:
            raise ValueError(f"Cycle period = {self.period!r} s must be > 0")

    def __call__(self, t: float) -> float:
        mid, amp = 0.5 * (self.high + self.low), 0.5 * (self.high - self.low)
        x = max(t - self.start, 0.0) / self.period
        if self.shape == "sine":
            return mid + amp * math.sin(2.0 * math.pi * x)
        frac = x - math.floor(x)
        return self.low + 2.0 * (self.high - self.low) * (frac if frac < 0.5 else 1.0 - frac)


def from_csv(path, column: str, time_column: str = "time") -> PiecewiseLinear:
    """A piecewise-linear signal from two columns of a CSV file (header row)."""
    path = Path(path)
    rows = list(csv.DictReader(io.StringIO(read_input(path, "signal table"), newline="")))
    if not rows:
        raise ValueError(f"{path}: no data rows")
    for name in (time_column, column):
        if name not in rows[0]:
            raise ValueError(f"{path}: no column {name!r} (columns: {list(rows[0])})")
    try:
        times = tuple(float(r[time_column]) for r in rows)
        values = tuple(float(r[column]) for r in rows)
    except ValueError as exc:
        raise ValueError(
            f"{path}: non-numeric value in {time_column!r} or {column!r}: {exc}"
        ) from None
    return PiecewiseLinear(times, values)

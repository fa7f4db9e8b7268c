"""The input file of ``servofmu margin`` (TOML): a mechanism, a motor, the other resistive
torques, a temperature range, optionally end-of-life changes, tolerance bands and a chamber
transient, and factor overrides. The format is documented by the example
``examples/margin_yu_gimbal.toml`` (:func:`example_input`) and in the user guide.

:func:`load_inputs` reads a file into :class:`MarginInputs` (SI, checked): every problem is
found before any computation, and ValueError carries the first, naming the field
(``torques[2].category = 'frction' is not one of [...]``). :func:`input_problems` lists them
all.

Every quantity is ``{ value = …, unit = "…" }`` (tables ``{ values = [...], unit = "…" }``),
optionally with ``kind`` (paper | catalogue | handbook | assumed | calibrated | derived |
measured) and ``ref``: the provenance travels into the report.
"""

from __future__ import annotations

import itertools
import math
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from servofmu.files import read_input
from servofmu.physics._checks import suggest
from servofmu.physics.kernels.units import DEG, GRAM_FORCE_CM, RPM, ZERO_CELSIUS, to_si

from .schema import schema_problems
from .standard import (
    BASES,
    CATEGORIES,
    DATA_FILE,
    TERMS,
    Factors,
    ecss_factors,
    factors_from_table,
)

#: Units accepted per kind of quantity: factor to SI (temperatures: also an offset).
UNITS = {
    "torque": {"N.m": 1.0, "mN.m": 1.0e-3, "N.mm": 1.0e-3, "uN.m": 1.0e-6, "g.cm": GRAM_FORCE_CM},
    "temperature": {"K": 1.0, "degC": 1.0},
    "temperature difference": {"K": 1.0},
    "speed": {"rad/s": 1.0, "deg/s": DEG, "rpm": RPM},
    "acceleration": {"rad/s2": 1.0, "deg/s2": DEG},
    "inertia": {"kg.m2": 1.0, "kg.mm2": 1.0e-6, "g.cm2": 1.0e-7},
    "torque constant": {"N.m/A": 1.0, "mN.m/A": 1.0e-3},
    "current": {"A": 1.0, "mA": 1.0e-3},
    "time": {"s": 1.0, "min": 60.0, "h": 3600.0},
    "temperature rate": {"K/s": 1.0, "K/min": 1.0 / 60.0, "K/h": 1.0 / 3600.0},
    "force": {"N": 1.0},
    "air speed": {"m/s": 1.0},
    "temperature coefficient": {"1/K": 1.0, "%/K": 1.0e-2},
    "ratio": {"-": 1.0},
}
KINDS = ("paper", "catalogue", "handbook", "assumed", "calibrated", "derived", "measured")
#: The two load cases: starting from rest (the bearing's breakaway torque, the motor at zero
#: speed) and running at the operating speed (running torque, the motor at that speed).
CASES = ("start", "run")
SECTIONS = (
    "title",
    "mechanism",
    "temperatures",
    "motor",
    "torques",
    "end_of_life",
    "tolerances",
    "transient",
    "factors",
)
#: The example input file (Yu's gimbal) that ``servofmu margin`` runs without arguments.
EXAMPLE = "margin_yu_gimbal.toml"


def example_input() -> Path:
    """The documented example input file, ``margin_yu_gimbal.toml`` of the shipped examples
    (:func:`servofmu.examples_files.examples_dir`).

    Returns
    -------
    pathlib.Path
        Its path.

    Examples
    --------
    >>> example_input().name
    'margin_yu_gimbal.toml'
    """
    from servofmu.examples_files import examples_dir

    return examples_dir() / EXAMPLE


# ------------------------------------------------------------------------------ the inputs
@dataclass(frozen=True)
class Motor:
    """The actuator: a torque constant [N·m/A] and current limit [A], or a torque–speed curve
    (motor speed [rad/s], torque [N·m]); through a gear of ``gear_ratio`` [-] and
    ``gear_efficiency`` [-]; the torque scaled by 1 + α·(T − T_ref) with
    ``temperature_coefficient`` α [1/K] and ``reference_temperature`` T_ref [K]."""

    torque_constant: float | None = None
    current_limit: float | None = None
    curve_speed: tuple[float, ...] | None = None
    curve_torque: tuple[float, ...] | None = None
    gear_ratio: float = 1.0
    gear_efficiency: float = 1.0
    temperature_coefficient: float = 0.0
    reference_temperature: float = 293.15
    provenance: str = ""


@dataclass(frozen=True)
class Resistance:
    """A resistive torque the user states: its ECSS category (:data:`CATEGORIES` or
    :data:`TERMS`), whether theoretical or measured, its value [N·m] (constant, or a table
    over ``temperatures`` [K]) at beginning and at end of life, the cases it acts in."""

    name: str
    category: str
    basis: str
    torque: tuple[float, ...]
    temperatures: tuple[float, ...] | None = None
    end_of_life: tuple[float, ...] | None = None
    cases: tuple[str, ...] = CASES
    provenance: str = ""

    def at(self, temperature, life: str):
        """The torque [N·m] at ``temperature`` [K] (array) at ``life`` ("EOL": its end-of-life
        value when it has one); outside the table's temperatures its end value
        (:meth:`outside` flags those)."""
        values = self.end_of_life if (life == "EOL" and self.end_of_life) else self.torque
        t = np.asarray(temperature, dtype=float)
        if self.temperatures is None:
            return np.full(t.shape, values[0])
        return np.interp(t, self.temperatures, values)

    def outside(self, temperature):
        """True where ``temperature`` [K] (array) lies outside the table's temperatures (never
        for a constant torque)."""
        t = np.asarray(temperature, dtype=float)
        if self.temperatures is None:
            return np.zeros(t.shape, bool)
        lo, hi = min(self.temperatures), max(self.temperatures)
        return (t < lo - 1e-9) | (t > hi + 1e-9)


@dataclass(frozen=True)
class Tolerances:
    """Monte-Carlo draws of the mechanism's parameters: ``bands`` {name: (low, high [SI],
    provenance)} (:func:`servofmu.harness.tolerance.tolerance_draws`), ``samples`` draws with
    ``seed``; ``source`` says where the bands come from."""

    bands: Mapping[str, tuple[float, float, str]]
    samples: int
    seed: int
    source: str


@dataclass(frozen=True)
class Transient:
    """A chamber transient: soaked at ``start`` [K], the chamber goes to ``end`` [K] at
    ``rate`` [K/s] (None: a step) and holds ``hold`` [s]; the thermal network is stepped every
    ``step`` [s], in ``environment`` ("air" or "vacuum") with ``air_speed`` [m/s] across the
    housing, the housing bolted to a plate at the chamber temperature when ``mounted``; the
    ball contacts' conductance at ``reference_preload`` [N] (None: the model's preload at the
    assembly temperature); ``network``: the mechanism's
    :class:`~servofmu.physics.thermal.network.ThermalParameters` (set when the file is
    loaded, from the catalogue mounting's geometry and materials)."""

    start: float
    end: float
    rate: float | None
    hold: float
    step: float
    environment: str = "air"
    air_speed: float = 0.0
    mounted: bool = False
    reference_preload: float | None = None
    network: object = None


@dataclass(frozen=True)
class MarginInputs:
    """A checked margin study (SI throughout; see the module docstring for the file)."""

    title: str
    source: str
    mounting: str
    mounting_from: str
    parameters: Mapping[str, Mapping[str, object]]
    friction_basis: str
    speed: float
    axial_load: float
    radial_load: float
    temperatures: tuple[float, ...]
    motors: Mapping[str, Motor]
    torques: tuple[Resistance, ...]
    factors: Factors
    tolerances: Tolerances | None = None
    transient: Transient | None = None
    notes: tuple[str, ...] = field(default=())

    @property
    def lives(self) -> tuple[str, ...]:
        """("BOL", "EOL") when end-of-life values are given, else ("as given",)."""
        return tuple(self.parameters)


# ------------------------------------------------------------------------------ reading
class _Reader:
    """Collects the problems of one input file while it converts its quantities to SI."""

    def __init__(self):
        self.problems: list[str] = []

    def fail(self, message: str) -> None:
        if message not in self.problems:
            self.problems.append(message)

    def table(self, data: Mapping, key: str, where: str, required: bool = False) -> dict:
        value = data.get(key)
        if value is None:
            if required:
                self.fail(f"{where}{key}: missing")
            return {}
        if not isinstance(value, Mapping):
            self.fail(f"{where}{key} = {value!r} must be a table")
            return {}
        return dict(value)

    def known(self, data: Mapping, allowed, where: str) -> None:
        unknown = sorted(set(data) - set(allowed))
        if unknown:
            self.fail(
                f"{where.rstrip('.') or 'input'}: unknown keys {unknown}"
                f"{suggest(unknown[0], allowed)} (known: {sorted(allowed)})"
            )

    def quantity(
        self,
        data: Mapping,
        key: str,
        dimension: str,
        where: str,
        *,
        required: bool = True,
        minimum: float | None = None,
        positive: bool = False,
    ) -> float | None:
        """The SI value of ``data[key]`` = {value, unit[, kind, ref]}; None (and a problem
        when required) when missing or wrong."""
        spec = data.get(key)
        name = f"{where}{key}"
        if spec is None:
            if required:
                self.fail(
                    f'{name}: missing (write {{ value = …, unit = "…" }}, unit one of '
                    f"{list(UNITS[dimension])})"
                )
            return None
        if not isinstance(spec, Mapping) or "value" not in spec or "unit" not in spec:
            self.fail(f'{name} = {spec!r} must be {{ value = …, unit = "…" }}')
            return None
        value = self._si(spec["value"], spec["unit"], dimension, f"{name}.value", name)
        self._provenance(spec, name)
        if value is None:
            return None
        return self._bounded(value, spec["value"], spec["unit"], name, minimum, positive)

    def values(
        self, data: Mapping, key: str, dimension: str, where: str, *, minimum: float | None = None
    ) -> tuple[float, ...] | None:
        """The SI values of ``data[key]`` = {values = [...], unit}."""
        spec = data.get(key)
        name = f"{where}{key}"
        if not isinstance(spec, Mapping) or "values" not in spec or "unit" not in spec:
            self.fail(f'{name} = {spec!r} must be {{ values = [...], unit = "…" }}')
            return None
        raw = spec["values"]
        if not isinstance(raw, list) or len(raw) < 2:
            self.fail(f"{name}.values = {raw!r} must be a list of at least two numbers")
            return None
        self._provenance(spec, name)
        out = []
        for k, v in enumerate(raw):
            si = self._si(v, spec["unit"], dimension, f"{name}.values[{k}]", name)
            if (
                si is None
                or self._bounded(si, v, spec["unit"], f"{name}.values[{k}]", minimum, False) is None
            ):
                return None
            out.append(si)
        return tuple(out)

    def _si(self, value, unit, dimension: str, name: str, where: str) -> float | None:
        units = UNITS[dimension]
        if unit not in units:
            self.fail(f"{where}.unit = {unit!r} is not a unit of {dimension}: one of {list(units)}")
            return None
        if isinstance(value, bool) or not isinstance(value, int | float):
            self.fail(f"{name} = {value!r} must be a number")
            return None
        if not math.isfinite(value):
            self.fail(f"{name} = {value!r} must be finite")
            return None
        if dimension == "temperature" and unit == "degC":
            return value + ZERO_CELSIUS
        return value * units[unit]

    def _bounded(self, si, value, unit, name, minimum, positive):
        if positive and not si > 0.0:
            self.fail(f"{name} = {value!r} {unit} must be > 0")
            return None
        if minimum is not None and si < minimum:
            if minimum == 0.0:
                hint = (
                    ": a torque that helps is actuation (ECSS-E-ST-33-01C 4.7.5.3.1 a, "
                    "NOTE 2), not a negative resistance"
                    if unit in UNITS["torque"]
                    else ""
                )
                self.fail(f"{name} = {value!r} {unit} is negative (valid range [0, inf)){hint}")
            else:
                self.fail(f"{name} = {value!r} {unit} is below {minimum:g} (SI)")
            return None
        return si

    def _provenance(self, spec: Mapping, name: str) -> None:
        kind = spec.get("kind")
        if kind is not None and kind not in KINDS:
            self.fail(f"{name}.kind = {kind!r} is not one of {list(KINDS)}")
        self.known(spec, ("value", "values", "unit", "kind", "ref"), f"{name}.")

    def choice(self, data: Mapping, key: str, choices, where: str, default):
        value = data.get(key, default)
        if value not in choices:
            self.fail(f"{where}{key} = {value!r} is not one of {list(choices)}")
            return default
        return value


def provenance(spec) -> str:
    """The provenance of a quantity table: "kind: ref", "kind", "ref" or "".

    Parameters
    ----------
    spec : mapping or None
        ``{value, unit, kind, ref}``.

    Returns
    -------
    str

    Examples
    --------
    >>> provenance({"value": 1, "unit": "A", "kind": "assumed", "ref": "driver limit"})
    'assumed: driver limit'
    """
    if not isinstance(spec, Mapping):
        return ""
    return ": ".join(str(spec[k]) for k in ("kind", "ref") if spec.get(k))


def read_toml(path) -> dict:
    """The TOML file ``path`` as a dict; ValueError naming the file when it cannot be read or
    is not valid TOML.

    Parameters
    ----------
    path : str or pathlib.Path

    Returns
    -------
    dict

    Examples
    --------
    >>> read_toml(example_input())["mechanism"]["mounting"]
    'yu2017_gimbal'
    """
    path = Path(path)
    try:
        return tomllib.loads(read_input(path, "margin input"))
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{path}: not valid TOML ({exc})") from None


# ------------------------------------------------------------------------------ sections
#: The step of the study's temperatures over the mounting's declared operating range [K].
OPERATING_STEP = 10.0


def _temperatures(r: _Reader, data: Mapping) -> tuple[float, ...] | None:
    """The study's temperatures [K], or None without a [temperatures] table (then the
    mounting's declared operating range: :func:`_operating_temperatures`)."""
    if "temperatures" not in data:
        return None
    t = r.table(data, "temperatures", "", required=True)
    where = "temperatures."
    r.known(t, ("from", "to", "step", "values"), where)
    if "values" in t:
        values = r.values(t, "values", "temperature", where, minimum=0.0)
        return tuple(sorted(values)) if values else ()
    lo = r.quantity(t, "from", "temperature", where, positive=True)
    hi = r.quantity(t, "to", "temperature", where, positive=True)
    step = r.quantity(t, "step", "temperature difference", where, positive=True)
    if None in (lo, hi, step):
        return ()
    return _steps(r, lo, hi, step)


def _operating_temperatures(r: _Reader, mounting: str, notes: list) -> tuple[float, ...]:
    """The mounting's declared operating range (``operating_minimum_temperature`` and
    ``operating_maximum_temperature`` of its catalogue entry) in steps of
    :data:`OPERATING_STEP`; a problem when it declares none."""
    from servofmu.parameters import catalog

    entry = catalog.mounting_entry(mounting)
    names = ("operating_minimum_temperature", "operating_maximum_temperature")
    if not all(n in entry for n in names):
        r.fail(
            f"temperatures: missing, and mounting {mounting!r} declares no operating range "
            f"({', '.join(names)} in its catalogue entry): give [temperatures]"
        )
        return ()
    (lo, lo_src), (hi, hi_src) = (catalog.quantity(entry[n], n) for n in names)
    notes.append(
        f"temperatures: the operating range mounting {mounting} declares, "
        f"{lo - ZERO_CELSIUS:g}…{hi - ZERO_CELSIUS:g} °C in steps of {OPERATING_STEP:g} K "
        f"({lo_src}" + ("" if hi_src in lo_src else f"; {hi_src}") + ")"
    )  # one source given for both ends is cited once
    return _steps(r, lo, hi, OPERATING_STEP)


def _steps(r: _Reader, lo: float, hi: float, step: float) -> tuple[float, ...]:
    """lo, lo + step, … up to hi, and hi [K]."""
    if not hi >= lo:
        r.fail(
            f"temperatures.to = {hi - ZERO_CELSIUS:g} °C must be ≥ temperatures.from = "
            f"{lo - ZERO_CELSIUS:g} °C"
        )
        return ()
    n = math.floor((hi - lo) / step + 1e-9) + 1
    if n > 1001:
        r.fail(
            f"temperatures: {n} temperatures from {lo - ZERO_CELSIUS:g} to "
            f"{hi - ZERO_CELSIUS:g} °C: at most 1001 (a coarser step)"
        )
        return ()
    values = [lo + k * step for k in range(n)]
    if values[-1] < hi - 1e-9:
        values.append(hi)
    return tuple(values)


def _motor(r: _Reader, m: Mapping, where: str) -> Motor | None:
    r.known(
        m,
        (
            "torque_constant",
            "current_limit",
            "torque_speed",
            "gear_ratio",
            "gear_efficiency",
            "temperature_coefficient",
            "reference_temperature",
        ),
        where,
    )
    curve = m.get("torque_speed")
    kw = {}
    if curve is not None:
        if "torque_constant" in m or "current_limit" in m:
            r.fail(f"{where}: give torque_constant and current_limit, or torque_speed, not both")
        if not isinstance(curve, Mapping):
            r.fail(f"{where}torque_speed = {curve!r} must be a table {{ speed, torque }}")
            return None
        speed = r.values(curve, "speed", "speed", f"{where}torque_speed.", minimum=0.0)
        torque = r.values(curve, "torque", "torque", f"{where}torque_speed.", minimum=0.0)
        r.known(curve, ("speed", "torque"), f"{where}torque_speed.")
        if speed and torque:
            if len(speed) != len(torque):
                r.fail(f"{where}torque_speed: {len(speed)} speeds and {len(torque)} torques")
            elif any(b <= a for a, b in itertools.pairwise(speed)):
                r.fail(f"{where}torque_speed.speed.values must increase")
        kw |= {"curve_speed": speed, "curve_torque": torque}
    else:
        kw["torque_constant"] = r.quantity(
            m, "torque_constant", "torque constant", where, positive=True
        )
        kw["current_limit"] = r.quantity(m, "current_limit", "current", where, positive=True)
    for key in ("gear_ratio", "gear_efficiency"):
        value = m.get(key)
        if isinstance(value, int | float) and not isinstance(value, bool):  # a bare ratio
            value = {"value": value, "unit": "-"}
        if value is not None:
            kw[key] = r.quantity({key: value}, key, "ratio", where, positive=True)
    if kw.get("gear_efficiency") is not None and kw["gear_efficiency"] > 1.0:
        r.fail(f"{where}gear_efficiency = {kw['gear_efficiency']!r} must lie in (0, 1]")
    if "temperature_coefficient" in m:
        kw["temperature_coefficient"] = r.quantity(
            m, "temperature_coefficient", "temperature coefficient", where
        )
        kw["reference_temperature"] = r.quantity(
            m, "reference_temperature", "temperature", where, positive=True
        )
    kw = {k: v for k, v in kw.items() if v is not None}
    parts = [f"{k}: {provenance(m[k])}" for k in m if provenance(m.get(k))]
    return Motor(**kw, provenance="; ".join(parts))


def _merged_motor(base: Mapping, changes: Mapping) -> dict:
    """The motor table with the end-of-life changes: a torque–speed curve replaces a
    constant and current limit, and the other way round."""
    out = dict(base)
    if "torque_speed" in changes:
        out.pop("torque_constant", None)
        out.pop("current_limit", None)
    if "torque_constant" in changes or "current_limit" in changes:
        out.pop("torque_speed", None)
    return out | dict(changes)


def _torque(r: _Reader, k: int, t, eol_given: bool) -> Resistance | None:
    where = f"torques[{k}]."
    if not isinstance(t, Mapping):
        r.fail(f"torques[{k}] = {t!r} must be a table ([[torques]])")
        return None
    r.known(
        t,
        (
            "name",
            "category",
            "basis",
            "torque",
            "temperature",
            "inertia",
            "acceleration",
            "end_of_life",
            "cases",
        ),
        where,
    )
    name = t.get("name")
    if not isinstance(name, str) or not name.strip():
        r.fail(f"{where}name: missing (say what the torque is)")
        name = f"torques[{k}]"
    category = r.choice(t, "category", (*CATEGORIES, *TERMS), where, None)
    basis = r.choice(t, "basis", BASES, where, t.get("basis", "theoretical"))
    if category in CATEGORIES and "basis" not in t:
        r.fail(
            f"{where}basis: missing: 'theoretical' or 'measured' (Table 4-2 has a factor for each)"
        )
    cases = t.get("cases", list(CASES))
    if not isinstance(cases, list) or not cases or any(c not in CASES for c in cases):
        r.fail(f"{where}cases = {cases!r} must be a non-empty list of {list(CASES)}")
        cases = list(CASES)
    temps, values, eol, prov = _torque_values(r, t, where)
    if "end_of_life" in t and not eol_given:
        r.fail(
            f"{where}end_of_life: an end-of-life value needs an [end_of_life] table saying "
            "where the end-of-life values come from (its source)"
        )
    if values is None or category is None:
        return None
    return Resistance(
        name=name,
        category=category,
        basis=basis,
        torque=values,
        temperatures=temps,
        end_of_life=eol,
        cases=tuple(cases),
        provenance=prov,
    )


def _torque_values(r: _Reader, t: Mapping, where: str):
    """(temperatures [K] or None, torques [N·m], end-of-life torques or None, provenance)."""
    if "inertia" in t or "acceleration" in t:
        if "torque" in t or "temperature" in t:
            r.fail(f"{where}: give a torque, or an inertia and an acceleration, not both")
        j = r.quantity(t, "inertia", "inertia", where, minimum=0.0)
        a = r.quantity(t, "acceleration", "acceleration", where, minimum=0.0)
        if "end_of_life" in t:
            r.fail(f"{where}end_of_life: not for an inertia × acceleration torque")
        prov = "; ".join(
            f"{k}: {provenance(t[k])}" for k in ("inertia", "acceleration") if provenance(t.get(k))
        )
        return None, (None if None in (j, a) else (j * a,)), None, prov
    if "temperature" in t:
        temps = r.values(t, "temperature", "temperature", where, minimum=0.0)
        values = r.values(t, "torque", "torque", where, minimum=0.0)
        eol = (
            r.values(t, "end_of_life", "torque", where, minimum=0.0) if "end_of_life" in t else None
        )
        for label, v in (("torque", values), ("end_of_life", eol)):
            if temps and v and len(v) != len(temps):
                r.fail(f"{where}{label}: {len(v)} values for {len(temps)} temperatures")
                return None, None, None, ""
        if temps and any(b <= a for a, b in itertools.pairwise(temps)):
            r.fail(f"{where}temperature.values must increase")
        return temps, values, eol, provenance(t.get("torque"))
    value = r.quantity(t, "torque", "torque", where, minimum=0.0)
    eol = r.quantity(t, "end_of_life", "torque", where, minimum=0.0) if "end_of_life" in t else None
    return (
        None,
        None if value is None else (value,),
        None if eol is None else (eol,),
        provenance(t.get("torque")),
    )


def _tolerances(r: _Reader, data: Mapping, mounting: str, nominal: Mapping, notes: list):
    t = r.table(data, "tolerances", "")
    if not t:
        return None
    where = "tolerances."
    r.known(t, ("bands", "samples", "seed"), where)
    samples, seed = t.get("samples", 100), t.get("seed", 1)
    if isinstance(samples, bool) or not isinstance(samples, int) or not 1 <= samples <= 100000:
        r.fail(f"tolerances.samples = {samples!r} must be a whole number in [1, 100000]")
        return None
    if isinstance(seed, bool) or not isinstance(seed, int):
        r.fail(f"tolerances.seed = {seed!r} must be a whole number")
        return None
    bands = t.get("bands", "catalogue")
    if bands == "catalogue":
        from servofmu.parameters import catalog

        try:
            found = catalog.tolerances(mounting)
        except ValueError:
            notes.append(
                f"tolerances: the catalogue has no tolerance bands for mounting {mounting!r} "
                "(parameters/data/tolerances.toml, or a user catalogue's [tolerances.MOUNTING]): "
                "no Monte-Carlo draws; give them in [tolerances.bands] of the input file"
            )
            return None
        where = catalog.origin("tolerances", mounting)
        return Tolerances(found, samples, seed, f"catalogue ({where}, {mounting})")
    if not isinstance(bands, Mapping) or not bands:
        r.fail(f'tolerances.bands = {bands!r} must be "catalogue" or a table of bands')
        return None
    from servofmu.harness.tolerance import SEAT_BANDS

    out = {}
    for name, spec in bands.items():
        field = f"tolerances.bands.{name}"
        numeric = isinstance(nominal.get(name), int | float) and not isinstance(
            nominal.get(name), bool
        )
        if name not in SEAT_BANDS and not numeric:
            r.fail(
                f"{field}: not a numeric parameter of the mechanism, nor one of {list(SEAT_BANDS)}"
            )
            continue
        band = _band(r, spec, field)
        if band is not None:
            out[name] = band
    return Tolerances(out, samples, seed, "input file") if out else None


def _band(r: _Reader, spec, field: str):
    if not isinstance(spec, Mapping) or not {"low", "high", "unit"} <= set(spec):
        r.fail(f"{field} = {spec!r} must be {{ low, high, unit, kind, ref }} (deviations)")
        return None
    r.known(spec, ("low", "high", "unit", "kind", "ref"), f"{field}.")
    try:
        low, high = (to_si(float(spec[k]), spec["unit"]) for k in ("low", "high"))
    except (TypeError, ValueError) as exc:
        r.fail(f"{field}: {exc}")
        return None
    if not (math.isfinite(low) and math.isfinite(high) and high >= low):
        r.fail(f"{field}: high = {spec['high']!r} must be ≥ low = {spec['low']!r}, both finite")
        return None
    return low, high, provenance(spec) or "input file"


def _transient(r: _Reader, data: Mapping) -> Transient | None:
    t = r.table(data, "transient", "")
    if not t:
        return None
    where = "transient."
    r.known(
        t,
        (
            "from",
            "to",
            "rate",
            "hold",
            "step",
            "environment",
            "air_speed",
            "mounted",
            "reference_preload",
        ),
        where,
    )
    start = r.quantity(t, "from", "temperature", where, positive=True)
    end = r.quantity(t, "to", "temperature", where, positive=True)
    rate = None
    if t.get("rate", "step") != "step":
        rate = r.quantity(t, "rate", "temperature rate", where, positive=True)
    hold = r.quantity(t, "hold", "time", where, minimum=0.0)
    step = r.quantity(t, "step", "time", where, positive=True) if "step" in t else 10.0
    env = r.choice(t, "environment", ("air", "vacuum"), where, "air")
    air = r.quantity(t, "air_speed", "air speed", where, minimum=0.0) if "air_speed" in t else 0.0
    mounted = t.get("mounted", False)
    if not isinstance(mounted, bool):
        r.fail(f"transient.mounted = {mounted!r} must be true or false")
    preload = (
        r.quantity(t, "reference_preload", "force", where, positive=True)
        if "reference_preload" in t
        else None
    )
    if None in (start, end, hold, step, air) or (
        "rate" in t and t["rate"] != "step" and rate is None
    ):
        return None
    ramp = 0.0 if rate is None else abs(end - start) / rate
    if (ramp + hold) / step > 100000:
        r.fail(
            f"transient: {(ramp + hold) / step:.0f} steps of {step:g} s: at most 100000 "
            "(a longer transient.step)"
        )
        return None
    return Transient(start, end, rate, hold, step, env, air, bool(mounted), preload)


def _factors(r: _Reader, data: Mapping, base_dir: Path) -> Factors:
    t = r.table(data, "factors", "")
    if not t:
        return ecss_factors()
    r.known(
        t, ("file", "standard", "motorisation", "inertial_resistance", "uncertainty"), "factors."
    )
    if "file" in t:
        try:
            table = read_toml(base_dir / str(t["file"]))
        except ValueError as exc:
            r.fail(f"factors.file: {exc}")
            return ecss_factors()
    else:
        table = tomllib.loads(DATA_FILE.read_text(encoding="utf-8"))
    table = _override(table, t)
    try:
        return factors_from_table(table, "factors")
    except ValueError as exc:
        r.fail(str(exc))
        return ecss_factors()


def _override(table: Mapping, changes: Mapping) -> dict:
    """The factor table with the input file's entries: a changed entry must name its own
    source (the package's source does not cover a value it did not give)."""
    out = {k: (dict(v) if isinstance(v, Mapping) else v) for k, v in table.items()}
    out["uncertainty"] = {k: dict(v) for k, v in table.get("uncertainty", {}).items()}
    for key in ("motorisation", "inertial_resistance"):
        if key in changes:
            out[key] = dict(changes[key]) if isinstance(changes[key], Mapping) else changes[key]
    for category, entry in dict(changes.get("uncertainty", {})).items():
        if isinstance(entry, Mapping):
            old = out["uncertainty"].get(category, {})
            out["uncertainty"][category] = {
                **{k: v for k, v in old.items() if k != "source"},
                **entry,
            }
        else:
            out["uncertainty"][category] = entry
    if "standard" in changes:
        out["standard"] = {"name": str(changes["standard"]), "revision": "(input file)"}
    elif (
        changes.get("motorisation")
        or changes.get("inertial_resistance")
        or changes.get("uncertainty")
    ):
        std = dict(out.get("standard", {}))
        std["revision"] = f"{std.get('revision', '')} with the input file's overrides".strip()
        out["standard"] = std
    return out


# ------------------------------------------------------------------------------ the file
def input_problems(data: Mapping, base_dir=".", catalogs=(), mounting=None) -> list[str]:
    """Every problem of an input file's content (already read from TOML), each naming its
    field; empty when it can be run. Loads the catalogues to check the mechanism, and forgets
    them again.

    Parameters
    ----------
    data : mapping
        The input file as read (:func:`read_toml`).
    base_dir : str or pathlib.Path
        Where relative paths in the file (catalogues, a factor file) start.
    catalogs : sequence of str or pathlib.Path
        User catalogues given on the command line (``--catalog``).
    mounting : str, optional
        The mounting given on the command line (``--mounting``).

    Returns
    -------
    list of str

    Examples
    --------
    >>> data = read_toml(example_input())
    >>> input_problems(data, example_input().parent)
    []
    >>> data["torques"][0]["category"] = "frction"
    >>> input_problems(data, example_input().parent)  # doctest: +ELLIPSIS
    ["torques[0].category = 'frction' is not one of ['inertia', 'spring', ...]"]
    """
    try:
        _parse(data, Path(base_dir), "(input)", catalogs, mounting)
    except _Problems as exc:
        return exc.problems
    return []


class _Problems(ValueError):
    def __init__(self, problems: list[str]):
        super().__init__(
            problems[0] + (f" (and {len(problems) - 1} more problems)" if len(problems) > 1 else "")
        )
        self.problems = problems


def load_inputs(path, catalogs=(), mounting=None) -> MarginInputs:
    """Read and check a margin input file; ValueError naming the file and the first problem's
    field (:func:`input_problems`), before anything is computed.

    Parameters
    ----------
    path : str or pathlib.Path
        The input file (TOML).
    catalogs : sequence of str or pathlib.Path
        User catalogues from the command line, merged after the file's own
        (``mechanism.catalog``).
    mounting : str, optional
        The mounting from the command line; it wins over a catalogue's ``[defaults]`` and the
        file's ``mechanism.mounting``.

    Returns
    -------
    MarginInputs

    Examples
    --------
    >>> inputs = load_inputs(example_input())
    >>> inputs.mounting, inputs.lives, len(inputs.temperatures)
    ('yu2017_gimbal', ('BOL', 'EOL'), 11)
    """
    path = Path(path)
    try:
        return _parse(read_toml(path), path.parent, str(path), catalogs, mounting)
    except ValueError as exc:
        raise ValueError(f"{path}: {exc}") from None


def _parse(data, base_dir: Path, source: str, catalogs, mounting) -> MarginInputs:
    from servofmu.build import catalogs as cat

    r = _Reader()
    r.known(data, SECTIONS, "")
    for problem in schema_problems(data):  # the types of what the reader hands on
        r.fail(problem)
    mech = r.table(data, "mechanism", "")
    r.known(
        mech,
        (
            "mounting",
            "catalog",
            "friction_basis",
            "speed",
            "axial_load",
            "radial_load",
            "parameters",
        ),
        "mechanism.",
    )
    temperatures = _temperatures(r, data)
    speed = r.quantity(mech, "speed", "speed", "mechanism.", positive=True)
    axial = r.quantity(mech, "axial_load", "force", "mechanism.") if "axial_load" in mech else 0.0
    radial = (
        r.quantity(mech, "radial_load", "force", "mechanism.", minimum=0.0)
        if "radial_load" in mech
        else 0.0
    )
    basis = r.choice(mech, "friction_basis", BASES, "mechanism.", "theoretical")
    eol = r.table(data, "end_of_life", "")
    r.known(eol, ("source", "parameters", "scale", "motor"), "end_of_life.")
    if eol and not str(eol.get("source", "")).strip():
        r.fail("end_of_life.source: missing: say where the end-of-life values come from")
    motor_table = r.table(data, "motor", "", required=True)
    motors = {}
    lives = ("BOL", "EOL") if eol else ("as given",)
    for life in lives:
        changes = r.table(eol, "motor", "end_of_life.") if life == "EOL" else {}
        table = _merged_motor(motor_table, changes)
        where = "end_of_life.motor." if changes and life == "EOL" else "motor."
        motors[life] = _motor(r, table, where) if motor_table else None
    raw_torques = data.get("torques", [])
    if not isinstance(raw_torques, list):
        r.fail("torques must be an array of tables ([[torques]])")
        raw_torques = []
    torques = [_torque(r, k, t, bool(eol)) for k, t in enumerate(raw_torques)]
    factors = _factors(r, data, base_dir)
    transient = _transient(r, data)
    if r.problems:  # the mechanism is only built once the rest reads well
        raise _Problems(r.problems)
    notes: list[str] = []
    file_catalogs = [base_dir / str(c) for c in mech.get("catalog", [])]
    chosen, chosen_from = _choose_mounting(mounting, catalogs, mech, file_catalogs, source)
    own = chosen_from.startswith(source)
    try:
        defaults = cat.load([*file_catalogs, *catalogs], mounting=chosen)
        if temperatures is None:
            temperatures = _operating_temperatures(r, chosen, notes)
        title = str(data.get("title", "")) if own else _mechanism_title(chosen, chosen_from)
        parameters = _parameters(r, mech, eol, chosen, lives, defaults.lubricant)
        nominal = next(iter(parameters.values()), {})
        tolerances = _tolerances(r, data, chosen, nominal, notes) if nominal else None
        if transient is not None and nominal:
            transient = _reference_preload(r, transient, nominal, notes)
            transient = _network(r, transient, chosen)
            _check_transient_range(r, transient, temperatures)
    finally:
        cat.unload()
    _check_speed_range(r, motors, speed)
    if r.problems:
        raise _Problems(r.problems)
    if not own:
        notes.append(
            f"mounting {chosen} comes from {chosen_from}: the input file's motor and other "
            "torques were written for its own mechanism, and are applied to this one"
        )
    return MarginInputs(
        title=title,
        source=source,
        mounting=chosen,
        mounting_from=chosen_from,
        parameters=parameters,
        friction_basis=basis,
        speed=speed,
        axial_load=axial,
        radial_load=radial,
        temperatures=temperatures,
        motors=motors,
        torques=tuple(t for t in torques if t is not None),
        factors=factors,
        tolerances=tolerances,
        transient=transient,
        notes=(*notes, *([f"end of life: {eol['source']}"] if eol else [])),
    )


def _mechanism_title(mounting: str, chosen_from: str) -> str:
    """The title of a study run on another mechanism than its file's: that mounting's name."""
    from servofmu.parameters import catalog

    return f"{catalog.mounting(mounting).name} (mounting {mounting}, from {chosen_from})"


def _choose_mounting(mounting, catalogs, mech: Mapping, file_catalogs, source: str):
    """(mounting, where it was chosen): the command line's --mounting, else the last
    --catalog's [defaults], else the file's mechanism.mounting, else its catalogues'
    [defaults], else the package default."""
    from servofmu.build import catalogs as cat
    from servofmu.parameters.bearing import DEFAULT_MOUNTING

    if mounting:
        return mounting, "--mounting"
    for p in reversed(list(catalogs)):
        key = cat.read(p)[1].get("mounting")
        if key:
            return key, f"{p}: [defaults] (--catalog)"
    if mech.get("mounting"):
        return str(mech["mounting"]), f"{source}: mechanism.mounting"
    for p in reversed(file_catalogs):
        key = cat.read(p)[1].get("mounting")
        if key:
            return key, f"{p}: [defaults] (mechanism.catalog)"
    return DEFAULT_MOUNTING, "the package default"


def _parameters(r: _Reader, mech: Mapping, eol: Mapping, mounting: str, lives,
                lubricant=None) -> dict:  # fmt: skip
    """{life: parameter set (SI)}: the mounting's preset (with a catalogue's ``[defaults]``
    lubricant when one names it), the file's changes, and at end of life the end-of-life
    changes; each checked."""
    from servofmu.parameters.bearing import (
        default_parameters,
        pair_from_parameters,
        parameter_problems,
        resolve,
    )

    out = {}
    try:
        base = default_parameters(mounting, lubricant=lubricant)
    except (KeyError, ValueError) as exc:
        r.fail(f"mechanism.mounting = {mounting!r}: {exc}")
        return out
    for life in lives:
        changes = dict(mech.get("parameters", {}))
        where = "mechanism.parameters"
        try:
            params = resolve(base, changes)
            if life == "EOL":
                where = "end_of_life.parameters"
                params = resolve(params, dict(eol.get("parameters", {})))
                where = "end_of_life.scale"
                params = _scaled(params, eol.get("scale", {}))
            where = "end_of_life" if life == "EOL" else "mechanism"
            problems = parameter_problems(params)
            if problems:
                raise ValueError(problems[0])
            pair_from_parameters(params)
        except (KeyError, ValueError, TypeError) as exc:
            r.fail(f"{where}: {exc} (mounting {mounting})")
            return out
        out[life] = params
    return out


def _scaled(params: Mapping, scale) -> dict:
    """``params`` with the numeric parameters named in ``scale`` multiplied by their factor
    (end of life relative to the beginning: ``{palmgren_s0 = 1.5}``)."""
    if not isinstance(scale, Mapping):
        raise ValueError(f"= {scale!r} must be a table {{ parameter = factor }}")
    out = dict(params)
    for name, factor in scale.items():
        value = params.get(name)
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise ValueError(f"{name}: not a numeric parameter of the mechanism")
        if (
            isinstance(factor, bool)
            or not isinstance(factor, int | float)
            or not (math.isfinite(factor) and factor >= 0.0)
        ):
            raise ValueError(f"{name} = {factor!r} must be a finite factor ≥ 0")
        out[name] = value * factor
    return out


def _check_speed_range(r: _Reader, motors: Mapping, speed) -> None:
    for life, m in motors.items():
        if m is None or m.curve_speed is None or speed is None:
            continue
        w = speed * m.gear_ratio
        if m.curve_speed[0] > 0.0 or w > m.curve_speed[-1]:
            where = "end_of_life.motor" if life == "EOL" else "motor"
            r.fail(
                f"{where}.torque_speed: the curve covers {m.curve_speed[0]:g}…"
                f"{m.curve_speed[-1]:g} rad/s at the motor, not 0 (start) and the operating "
                f"{w:g} rad/s (speed × gear_ratio): extend it (no extrapolation)"
            )


def _reference_preload(r: _Reader, transient: Transient, params: Mapping, notes: list):
    """The transient with its ball contacts' reference preload: as given, else the model's
    preload at the assembly temperature (a problem when there is none)."""
    if transient.reference_preload is not None:
        return transient
    from dataclasses import replace

    from servofmu.parameters.bearing import pair_from_parameters
    from servofmu.physics.bearing import BearingModel

    pair = pair_from_parameters(params)
    t0 = pair.mounting.assembly_temperature
    preload = BearingModel(pair).evaluate(t0, 0.0).preload
    if not preload > 0.0:
        r.fail(
            f"transient.reference_preload: missing, and the mechanism has no preload at its "
            f"assembly temperature ({t0 - ZERO_CELSIUS:g} °C) to take instead: give the "
            "preload [N] at which the ball contacts' conductance is evaluated"
        )
        return transient
    notes.append(
        f"transient: ball contacts' conductance at the preload {preload:.4g} N (the "
        f"model's at the assembly temperature, {t0 - ZERO_CELSIUS:g} °C)"
    )
    return replace(transient, reference_preload=preload)


def _network(r: _Reader, transient: Transient, mounting: str) -> Transient:
    """The transient with the thermal network of the catalogue mounting (its geometry and its
    materials' density, specific heat, conductivity and emissivity)."""
    from dataclasses import replace

    from servofmu.parameters import catalog
    from servofmu.physics.thermal.network import mechanism_parameters

    if transient.reference_preload is None:
        return transient
    m = catalog.mounting(mounting)
    try:
        network = mechanism_parameters(
            catalog.bearing(m.bearing_key),
            m,
            vacuum=transient.environment == "vacuum",
            air_speed=transient.air_speed,
            reference_preload=transient.reference_preload,
            mounted=transient.mounted,
        )
    except (KeyError, ValueError) as exc:
        r.fail(
            f"transient: the thermal network of mounting {mounting!r}: {exc} (the "
            "catalogue's material entries take density, specific_heat, "
            "thermal_conductivity and emissivity)"
        )
        return transient
    return replace(transient, network=network)


def _check_transient_range(r: _Reader, transient: Transient, temperatures) -> None:
    """The chamber's end points within the study's temperatures (the other torques' tables
    are checked over those)."""
    if not temperatures:
        return
    lo, hi = min(temperatures), max(temperatures)
    for key, t in (("from", transient.start), ("to", transient.end)):
        if not lo - 1e-9 <= t <= hi + 1e-9:
            r.fail(
                f"transient.{key} = {t - ZERO_CELSIUS:g} °C lies outside the study's "
                f"temperatures {lo - ZERO_CELSIUS:g}…{hi - ZERO_CELSIUS:g} °C"
            )

"""The margin study of :class:`~.inputs.MarginInputs`: for each life (beginning and end), case
(starting from rest, running) and temperature — and for each Monte-Carlo draw of the
tolerances and each time of a chamber transient when given — the bearing's friction torques
from the bearing library at those conditions, the factored torques per ECSS category, the
minimum actuation torque, the available torque and the margin (:mod:`.standard`), and the
worst case.

The bearing pair's torques (:func:`servofmu.physics.bearing.operating_outputs`, the exact
path; a transient steps :class:`~servofmu.physics.bearing.BearingModel`, the FMU's path) enter
as two components of resistance: its hysteresis torque as ECSS "hysteresis" (H_Y), the rest
(spin, sliding, viscous and grease terms, and at start the excess of breakaway over running)
as "friction" (F_R), both with the basis ``mechanism.friction_basis``: their sum is the
library's breakaway torque (start) or running torque (run).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from .inputs import CASES, MarginInputs, Motor
from .standard import (
    CATEGORIES,
    Factors,
    factored_torque,
    minimum_actuation_torque,
    motorisation_ratio,
    torque_margin,
)

#: The bearing library's torque terms reported with each row [N·m].
BEARING_TERMS = (
    "hysteresis_torque",
    "spin_torque",
    "sliding_torque",
    "viscous_torque",
    "grease_torque",
)
#: The flags a margin row carries, with the letter the table shows for each: the bearing
#: model's, and whether a torque table was read outside its temperatures (held at its end).
FLAGS = {
    "overloaded": "O",
    "unloaded": "U",
    "locked": "L",
    "outside_lubricant_range": "X",
    "breakaway_lower_bound": "B",
    "table_extrapolated": "T",
}
#: What each flag says about the row's numbers.
FLAG_MEANINGS = {
    "O": "overloaded: a contact pressure above ISO 76's 4200 MPa, the balls dent the races",
    "U": "unloaded: no ball carries load (preload lost, no external load): the bearing torque "
    "is only its lubricant's drag, without the unloaded balls' skid and cage drag",
    "L": "locked: no operating clearance left or no load equilibrium",
    "X": "outside the range of the lubricant's data: its viscosity extrapolated, or held below "
    "its flow limit",
    "B": "breakaway only a lower bound: the lubricant has no published starting torque",
    "T": "a torque table read outside its temperatures, held at its end value",
}
#: A row's verdict: its margin ≥ 0 and nothing flagged that affects it; a negative (or no)
#: margin; a margin ≥ 0 that a flag puts in doubt.
VERDICTS = ("met", "not met", "not verified")
#: The exit code of ``servofmu margin`` for each verdict of the study (2: a bad input).
EXIT_CODES = {"met": 0, "not met": 1, "not verified": 3}


def row_flags(row: Mapping) -> str:
    """The letters of the flags (:data:`FLAGS`) that affect a margin row: every one set, except
    ``unloaded`` where a ball still carries load (one bearing of the pair carries the external
    load: the torque model holds) and ``breakaway_lower_bound`` in a running row.

    Parameters
    ----------
    row : mapping
        A margin row (its flags, ``case`` and ``max_contact_pressure`` [Pa]).

    Returns
    -------
    str
        The letters, in the order of :data:`FLAGS`; "" when nothing affects the row.

    Examples
    --------
    >>> row_flags({"case": "run", "unloaded": True, "max_contact_pressure": 1e9,
    ...            "breakaway_lower_bound": True, "outside_lubricant_range": True})
    'X'
    >>> row_flags({"case": "start", "unloaded": True, "max_contact_pressure": 0.0,
    ...            "breakaway_lower_bound": True})
    'UB'
    """
    letters = []
    for name, letter in FLAGS.items():
        if not row.get(name):
            continue
        if name == "unloaded" and row.get("max_contact_pressure", 0.0) > 0.0:
            continue
        if name == "breakaway_lower_bound" and row.get("case") != "start":
            continue
        letters.append(letter)
    return "".join(letters)


def row_verdict(margin: float, flags: str) -> str:
    """One of :data:`VERDICTS`: "not met" when the margin is negative or not a number (no
    bearing state), else "not verified" when a flag affects the row, else "met".

    Parameters
    ----------
    margin : float
        T/T_min − 1 [-].
    flags : str
        :func:`row_flags`.

    Returns
    -------
    str
        The verdict.

    >>> row_verdict(0.2, ""), row_verdict(0.2, "X"), row_verdict(-0.1, "X")
    ('met', 'not verified', 'not met')
    """
    if not margin >= 0.0:
        return "not met"
    return "not verified" if flags else "met"


def available_torque(motor: Motor, temperature, speed):
    """The actuation torque at the mechanism's shaft [N·m]: gear ratio × gear efficiency ×
    (1 + α·(T − T_ref)) × (k_t·I_max, or the torque–speed curve at the motor's speed,
    linearly interpolated).

    Parameters
    ----------
    motor : Motor
        The actuator (:class:`~.inputs.Motor`).
    temperature : float or array_like
        The motor's temperature [K].
    speed : float
        The mechanism's speed [rad/s] (the motor turns gear ratio times faster).

    Returns
    -------
    ndarray
        T [N·m], shaped like ``temperature``.

    Examples
    --------
    >>> m = Motor(torque_constant=0.05, current_limit=0.8, gear_ratio=2.0)
    >>> [round(float(v), 12) for v in available_torque(m, [233.15, 333.15], 0.17)]  # 2·0.05·0.8
    [0.08, 0.08]
    >>> curve = Motor(curve_speed=(0.0, 100.0), curve_torque=(0.04, 0.0))
    >>> round(float(available_torque(curve, 293.15, 25.0)), 12)  # a quarter down the line
    0.03
    """
    t = np.asarray(temperature, dtype=float)
    if motor.curve_speed is None:
        torque = motor.torque_constant * motor.current_limit
    else:
        torque = float(
            np.interp(abs(speed) * motor.gear_ratio, motor.curve_speed, motor.curve_torque)
        )
    scale = 1.0 + motor.temperature_coefficient * (t - motor.reference_temperature)
    return motor.gear_ratio * motor.gear_efficiency * torque * scale


def bearing_components(outputs, case: str) -> dict:
    """The bearing pair's torque in ``case`` and its split into ECSS components [N·m]:
    ``bearing_torque`` (breakaway torque at start, running torque when running), ``hysteresis``
    (H_Y: the contacts' hysteresis torque) and ``friction`` (F_R: the rest).

    Parameters
    ----------
    outputs : BearingOutputs
        The library's outputs (:func:`servofmu.physics.bearing.operating_outputs` or
        :meth:`~servofmu.physics.bearing.BearingModel.evaluate`).
    case : str
        "start" or "run".

    Returns
    -------
    dict
        ``bearing_torque``, ``hysteresis``, ``friction`` [N·m] (arrays or floats).

    Examples
    --------
    >>> from servofmu.physics.bearing import BearingPair, operating_outputs
    >>> out = operating_outputs(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"),
    ...                         233.15, 0.17)
    >>> c = bearing_components(out, "start")
    >>> bool(c["hysteresis"] + c["friction"] == out.breakaway_torque)
    True
    """
    torque = outputs.breakaway_torque if case == "start" else outputs.running_torque
    hysteresis = outputs.hysteresis_torque
    return {"bearing_torque": torque, "hysteresis": hysteresis, "friction": torque - hysteresis}


def margin_terms(
    bearing: Mapping,
    friction_basis: str,
    torques,
    temperature,
    case: str,
    life: str,
    available,
    factors: Factors,
) -> dict:
    """Every term of the rule at the given conditions [N·m]: the factored torques per
    category (``factored_<category>``), T_D, T_L, their sum, T_min, T and the margin.

    Parameters
    ----------
    bearing : mapping
        :func:`bearing_components` of the pair.
    friction_basis : str
        "theoretical" or "measured": the basis of the bearing's components.
    torques : sequence of Resistance
        The other resistive torques (:class:`~.inputs.Resistance`).
    temperature : array_like
        Where the other torques are evaluated [K].
    case, life : str
        The case ("start", "run") and life ("BOL", "EOL", "as given").
    available : array_like
        T [N·m] (:func:`available_torque`).
    factors : Factors
        The rule's factors.

    Returns
    -------
    dict
        ``factored_<category>`` for each of :data:`~.standard.CATEGORIES`,
        ``inertial_resistance`` (T_D), ``deliverable`` (T_L), ``factored_sum``,
        ``minimum``, ``available`` [N·m], ``margin`` and ``ecss_ratio`` [-]
        (:func:`~.standard.torque_margin`, :func:`~.standard.motorisation_ratio`), and
        ``table_extrapolated`` (a table torque read outside its temperatures).

    Examples
    --------
    >>> from servofmu.margin.inputs import Resistance
    >>> from servofmu.margin.standard import ecss_factors
    >>> harness = Resistance("harness", "harness", "measured", (0.5e-3,))
    >>> t = margin_terms({"hysteresis": 0.0, "friction": 2.0e-3}, "theoretical", [harness],
    ...                  [293.15], "run", "as given", [20.0e-3], ecss_factors())
    >>> round(float(t["minimum"][0]) * 1e3, 9)  # 2 × (3 × 2 + 1.5 × 0.5) mN·m
    13.5
    """
    t = np.asarray(temperature, dtype=float)
    zero = np.zeros(t.shape)
    out = {f"factored_{c}": zero.copy() for c in CATEGORIES}
    out["inertial_resistance"] = zero.copy()
    out["deliverable"] = zero.copy()
    for category in ("hysteresis", "friction"):
        out[f"factored_{category}"] = out[f"factored_{category}"] + factored_torque(
            np.asarray(bearing[category], dtype=float), category, friction_basis, factors
        )
    for r in torques:
        if case not in r.cases:
            continue
        value = r.at(t, life)
        if r.category in CATEGORIES:
            out[f"factored_{r.category}"] += factored_torque(value, r.category, r.basis, factors)
        else:
            out[r.category] += value
    out["factored_sum"] = sum(out[f"factored_{c}"] for c in CATEGORIES)
    out["minimum"] = minimum_actuation_torque(
        out["factored_sum"], out["inertial_resistance"], out["deliverable"], factors
    )
    out["available"] = np.broadcast_to(np.asarray(available, dtype=float), t.shape).copy()
    out["margin"] = np.asarray(torque_margin(out["available"], out["minimum"]))
    out["ecss_ratio"] = np.asarray(
        motorisation_ratio(out["available"], out["factored_sum"], out["inertial_resistance"],
                           out["deliverable"], factors)
    )  # fmt: skip
    out["table_extrapolated"] = np.zeros(t.shape, bool)
    for r in torques:
        if case in r.cases:
            out["table_extrapolated"] |= r.outside(t)
    return out


# ------------------------------------------------------------------------------ the study
@dataclass
class MarginResult:
    """The rows of a study (dicts of SI values, one per life × case × temperature, and per
    draw and per transient time) and what the report needs.

    Attributes
    ----------
    inputs : the study
    steady : rows at uniform temperature with the nominal parts
    draws : rows of the Monte-Carlo draws (key ``draw``)
    transient : rows of the chamber transient (keys ``time``, ``chamber`` and the parts'
        temperatures)
    notes : what the report must say
    """

    inputs: MarginInputs
    steady: list[dict] = field(default_factory=list)
    draws: list[dict] = field(default_factory=list)
    transient: list[dict] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def rows(self):
        """Every row, with the block it belongs to ("steady", "draws", "transient")."""
        for block in ("steady", "draws", "transient"):
            for row in getattr(self, block):
                yield block, row

    @property
    def worst(self) -> tuple[str, dict]:
        """(block, row) of the smallest margin; a row without a margin (NaN: no state) is the
        worst of all."""

        def key(item):
            m = item[1]["margin"]
            return -math.inf if math.isnan(m) else m

        return min(self.rows(), key=key)

    @property
    def verdict(self) -> str:
        """The study's verdict (:data:`VERDICTS`): "not met" when any row is, else "not
        verified" when any row is, else "met"."""
        found = {row["verdict"] for _, row in self.rows()}
        return next((v for v in ("not met", "not verified") if v in found), "met")

    @property
    def exit_code(self) -> int:
        """0 every row met, 1 a margin negative (or none), 3 none negative but a row not
        verified (:data:`EXIT_CODES`)."""
        return EXIT_CODES[self.verdict]

    @property
    def passed(self) -> bool:
        """True when every row is met: its margin a number ≥ 0 and nothing flagged."""
        return self.verdict == "met"


def run(inputs: MarginInputs, result: MarginResult | None = None) -> MarginResult:
    """The margin study of ``inputs`` (module docstring).

    Parameters
    ----------
    inputs : MarginInputs
        A checked study (:func:`~.inputs.load_inputs`).
    result : MarginResult, optional
        Filled as the study goes (an interrupted study keeps its rows there); default a new
        one.

    Returns
    -------
    MarginResult

    Examples
    --------
    >>> from servofmu.margin.inputs import example_input, load_inputs
    >>> from dataclasses import replace
    >>> inputs = replace(load_inputs(example_input()), tolerances=None, transient=None)
    >>> result = run(inputs)
    >>> len(result.steady)  # 2 lives × 2 cases × 11 temperatures
    44
    >>> block, row = result.worst
    >>> block, row["life"], row["case"], round(row["temperature"] - 273.15, 2)
    ('steady', 'EOL', 'run', -40.0)
    """
    from servofmu.parameters.bearing import pair_from_parameters

    result = MarginResult(inputs) if result is None else result
    result.notes[:] = list(inputs.notes)
    temps = np.asarray(inputs.temperatures, dtype=float)
    for life, params in inputs.parameters.items():
        pair = pair_from_parameters(params)
        out = _outputs(pair, temps, inputs, result.notes, f"{life}, nominal parts")
        result.steady += _rows(inputs, life, temps, out, {})
        if inputs.tolerances is not None:
            result.draws += _draw_rows(inputs, life, params, temps, result.notes)
        if inputs.transient is not None:
            result.transient += _transient_rows(inputs, life, pair, result.notes)
    return result


def _outputs(pair, temps, inputs: MarginInputs, notes: list, label: str):
    """The library's outputs over ``temps`` at the operating speed and loads (exact path;
    vectorised without a radial load); where it finds no state, point by point, NaN at the
    points without one (:func:`_point`)."""
    from servofmu.physics.bearing import BearingModel, operating_outputs

    try:
        if inputs.radial_load == 0.0:
            return operating_outputs(pair, temps, inputs.speed, inputs.axial_load)
        speed, axial, radial = inputs.speed, inputs.axial_load, inputs.radial_load
        return _stack([operating_outputs(pair, float(t), speed, axial, radial) for t in temps])
    except (ValueError, ArithmeticError):
        model = BearingModel(pair)
        return _stack([_point(model, float(t), inputs, notes, label) for t in temps])


def _point(model, temperature, inputs: MarginInputs, notes: list, label: str):
    """The model's outputs at one point (a temperature [K] or the parts' temperatures), or
    NaN outputs and a note where it has no state there: that point's margin is NaN, which
    counts as not met."""
    try:
        return model.evaluate(temperature, inputs.speed, inputs.axial_load, inputs.radial_load)
    except (ValueError, ArithmeticError) as exc:
        notes.append(f"no bearing state ({label}): {exc}; the margin there is NaN (not met)")
        return _nan_outputs()


def _nan_outputs():
    from dataclasses import fields

    from servofmu.physics.bearing import BearingOutputs

    return BearingOutputs(**{f.name: (False if f.name in FLAGS else math.nan)
                             for f in fields(BearingOutputs)})  # fmt: skip


def _rows(
    inputs: MarginInputs, life: str, temps, out, extra: Mapping, motor_temperature=None
) -> list[dict]:
    """The rows of one life over ``temps`` (the other torques' and motor's temperature:
    ``motor_temperature``, default ``temps``) for both cases; ``extra`` values (a scalar, or
    an array over ``temps``) are added to the rows."""
    motor = inputs.motors[life]
    t_motor = temps if motor_temperature is None else motor_temperature
    rows = []
    for case in CASES:
        speed = 0.0 if case == "start" else inputs.speed
        bearing = bearing_components(out, case)
        terms = margin_terms(
            bearing,
            inputs.friction_basis,
            inputs.torques,
            t_motor,
            case,
            life,
            available_torque(motor, t_motor, speed),
            inputs.factors,
        )
        columns = {
            "bearing_torque": bearing["bearing_torque"],
            **{k: getattr(out, k) for k in BEARING_TERMS},
            "preload": out.preload,
            "max_contact_pressure": out.max_contact_pressure,
            **{f: getattr(out, f) for f in FLAGS if f != "table_extrapolated"},
            **terms,
        }
        columns = {k: np.broadcast_to(np.asarray(v), np.shape(temps)) for k, v in columns.items()}
        for k, t in enumerate(np.atleast_1d(temps)):
            row = {"life": life, "case": case, "speed": speed, "temperature": float(t)}
            row |= {key: (_scalar(v[k]) if np.ndim(v) else v) for key, v in extra.items()}
            row |= {key: _scalar(v[k]) for key, v in columns.items()}
            row["flags"] = row_flags(row)
            row["verdict"] = row_verdict(row["margin"], row["flags"])
            rows.append(row)
    return rows


def _scalar(v):
    if isinstance(v, np.bool_ | bool):
        return bool(v)
    return int(v) if isinstance(v, np.integer | int) else float(v)


def _draw_rows(inputs: MarginInputs, life: str, params: Mapping, temps, notes) -> list[dict]:
    """The rows of every Monte-Carlo draw of one life: the parameters drawn from the bands
    around this life's values (the same seed at every life: the same parts)."""
    from servofmu.harness.tolerance import tolerance_draws
    from servofmu.parameters.bearing import pair_from_parameters
    from servofmu.physics.bearing import BearingModel

    tol = inputs.tolerances
    rows = []
    for draw in tolerance_draws(params, tol.bands, tol.samples, tol.seed):
        index = draw.pop("sample")
        model = BearingModel(pair_from_parameters(dict(params) | draw))
        label = f"{life}, draw {index}"
        out = _stack([_point(model, float(t), inputs, notes, label) for t in temps])
        rows += _rows(inputs, life, temps, out, {"draw": index, **draw})
    return rows


def chamber_temperature(transient, time):
    """The chamber's temperature [K] at ``time`` [s] of a transient: its ``start`` before 0,
    then a ramp at ``rate`` (a step when None) to ``end``, held there.

    Parameters
    ----------
    transient : Transient
        The profile (:class:`~.inputs.Transient`).
    time : float or array_like
        Time since the chamber started moving [s].

    Returns
    -------
    float or ndarray
        [K].

    Examples
    --------
    >>> from servofmu.margin.inputs import Transient
    >>> tr = Transient(293.15, 233.15, 1.0 / 60.0, 600.0, 10.0)  # 1 K/min down by 60 K
    >>> [round(float(chamber_temperature(tr, t)), 2) for t in (-1.0, 1800.0, 7200.0)]
    [293.15, 263.15, 233.15]
    """
    t = np.asarray(time, dtype=float)
    if transient.rate is None:
        out = np.where(t > 0.0, transient.end, transient.start)
    else:
        delta = transient.end - transient.start
        moved = np.clip(transient.rate * t, 0.0, abs(delta))
        out = transient.start + math.copysign(1.0, delta) * moved
    return float(out) if out.ndim == 0 else out


def _transient_rows(inputs: MarginInputs, life: str, pair, notes: list) -> list[dict]:
    """Rows along the chamber transient of one life: the thermal network of the pair
    (:mod:`servofmu.physics.thermal.network`) stepped with the chamber as its ambient and
    sink and the bearing's power loss at the operating speed as its heat input; the bearing
    (:class:`~servofmu.physics.bearing.BearingModel`) at the parts' temperatures each step; the
    motor and the other torques at the housing's temperature."""
    from servofmu.physics.bearing import BearingModel
    from servofmu.physics.thermal import network as tn

    tr = inputs.transient
    model = BearingModel(pair)
    net = tn.network(tr.network)
    ramp = 0.0 if tr.rate is None else abs(tr.end - tr.start) / tr.rate
    n = math.ceil((ramp + tr.hold) / tr.step - 1e-9)
    times = np.arange(n + 1) * tr.step
    parts = [tr.start] * 4
    reference = None
    history, outs = [], []
    for k, time in enumerate(times):
        label = f"{life}, transient at t = {time:g} s"
        outs.append(_point(model, tuple(float(p) for p in parts), inputs, notes, label))
        history.append(parts)
        if k < n:  # zero-order hold over the step, the chamber at its midpoint
            chamber = chamber_temperature(tr, time + 0.5 * tr.step)
            power = abs(outs[-1].running_torque * inputs.speed)
            power = power if math.isfinite(power) else 0.0  # no state: no heat
            if (
                reference is None
                or max(abs(a - b) for a, b in zip(parts, reference, strict=True)) > RELINEARISE
            ):
                reference = tuple(float(p) for p in parts)
            parts = tn.step(net, parts, chamber, chamber, power, tr.step, reference)
    parts = np.array(history, dtype=float)
    extra = {
        "time": times,
        "chamber": chamber_temperature(tr, times),
        **{name: parts[:, k] for k, name in enumerate(PARTS_COLUMNS)},
    }
    return _rows(inputs, life, extra["chamber"], _stack(outs), extra, motor_temperature=parts[:, 0])


#: The parts' temperatures of a transient row (housing, shaft, outer ring, inner ring) [K].
PARTS_COLUMNS = ("housing", "shaft", "outer_ring", "inner_ring")


#: Radiation is linearised again once a part has moved this far from the last linearisation
#: [K] (the ThermalNetwork FMU's default ``linearisation_tolerance``).
RELINEARISE = 0.1


def _stack(outs):
    """A list of BearingOutputs of floats as one BearingOutputs of arrays."""
    fields = outs[0].as_dict()
    return type(outs[0])(**{k: np.array([getattr(o, k) for o in outs]) for k in fields})

"""Calibration of the grease term (:mod:`servofmu.physics.friction.grease`) on a grease
datasheet's low-temperature torque test (``servofmu calibrate --datasheet LUBRICANT``).

The datasheet points are data (``parameters/data/grease_torques.toml``: the test's bearing, speed
and load, and the grease's published starting and running torques; its base-oil viscosities
are its entry of ``parameters/data/lubricants.toml``).
For each point i, Palmgren's law at f0 = 1 gives u_i = M0(ν_i, n_test, dm_test)
(:func:`~servofmu.physics.friction.grease.grease_factor`: f0_i = M_run,i/u_i), and

- f0 minimises Σ (f0·u_i/M_run,i − 1)², i.e. f0 = Σ(1/f0_i)/Σ(1/f0_i)² (relative least squares;
  one point: f0 = f0_1 exactly);
- ks minimises Σ (ks·f0·u_i/M_start,i − 1)² (the model's starting torque ks times its own
  running torque at the test speed; one point: ks = M_start/M_run exactly).

**A poor fit is no calibration** (the rules of :mod:`.fit`): an estimate at a bound of its
parameter's range (``grease_f0``, ``grease_starting_ratio`` of the FMU's parameter table), or,
with two or more points, an rms relative residual above
:data:`~servofmu.calibration.fit.UNREPLICATED_LIMIT` (a datasheet repeats no point, so its
scatter is unknown). One point determines f0 and ks exactly: no degree of freedom is left to
test the law, and the report says so. Points of different tests (JIS K 2220 reads the running
torque after 10 min, ASTM D1478 after 60 min: not the same quantity) are not mixed: the test
must be named when the data hold several.

The result is a partial parameter set of the BearingFriction FMU: the grease's lubricant preset
(``lubrication`` = grease, its base oil's ``lubricant_viscosity_40``/``_100``,
``lubricant_walther_c``, ``lubricant_density``, ``skf_film_friction`` and the range of its data,
since f0 holds with the viscosity it was calibrated with) with the grease term calibrated here
(``grease_f0``, ``grease_starting_ratio``, ``grease_reference_speed``). The same calibration is
what the lubricant's preset carries by default
(:func:`~servofmu.physics.friction.grease.lubricant_term`); this command reports it, and
calibrates on one test of several.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..parameters.presets import lubricant_values
from ..parameters.table import LUBRICANT_FIELDS, spec
from ..physics.friction.grease import (
    base_oil_viscosity,
    fit_points,
    grease_torque_points,
    torque_test,
)
from ..physics.kernels.units import CST, RPM, kelvin_to_celsius
from .fit import UNREPLICATED_LIMIT

#: The parameters a datasheet calibration writes, in the order of the parameter table: the
#: grease's base oil as its lubricant preset sets it, and the grease term calibrated here.
GREASE_PARAMETERS = LUBRICANT_FIELDS


@dataclass
class DatasheetCalibration:
    """Result of :func:`calibrate_datasheet` (SI).

    Attributes
    ----------
    lubricant, test : the grease and the test standard (keys of ``grease_torques.toml``)
    points : per point (temperature [K], ν [m²/s], M_start, M_run [N·m], f0_i [-])
    f0, ks : the estimates [-]
    running_residuals, starting_residuals : (model − published)/published per point [-]
    parameters : the partial BearingFriction parameter set (:data:`GREASE_PARAMETERS`)
    sources : provenance of each parameter
    warnings, problems : what limits the calibration; why it is none (poor fit)
    """

    lubricant: str
    test: str
    points: list[tuple[float, float, float, float, float]]
    f0: float
    ks: float
    running_residuals: list[float]
    starting_residuals: list[float]
    parameters: dict[str, object]
    sources: dict[str, str]
    warnings: list[str] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)

    @property
    def poor(self) -> bool:
        return bool(self.problems)

    def as_dict(self) -> dict:
        """JSON-ready summary."""
        return {
            "lubricant": self.lubricant,
            "test": self.test,
            "points": [
                {
                    "temperature_K": t,
                    "base_oil_viscosity_m2_s": nu,
                    "starting_torque_N_m": s,
                    "running_torque_N_m": r,
                    "f0_of_point": f,
                }
                for t, nu, s, r, f in self.points
            ],
            "grease_f0": self.f0,
            "grease_starting_ratio": self.ks,
            "running_residuals": self.running_residuals,
            "starting_residuals": self.starting_residuals,
            "poor_fit": self.poor,
            "problems": list(self.problems),
            "warnings": list(self.warnings),
            "parameters": dict(self.parameters),
            "sources": dict(self.sources),
        }


def _rms(values: list[float]) -> float:
    return math.sqrt(sum(v * v for v in values) / len(values))


def calibrate_datasheet(lubricant: str, test: str | None = None) -> DatasheetCalibration:
    """Calibrate the grease term of ``lubricant`` on its published low-temperature torques of
    test ``test`` (default: the one test its points come from), see the module docstring.

    Parameters
    ----------
    lubricant : key of ``[greases.KEY]`` in ``parameters/data/grease_torques.toml``
    test : key of ``[tests.KEY]`` (``jis_k2220``, ``astm_d1478``)

    Returns
    -------
    DatasheetCalibration

    >>> cal = calibrate_datasheet("molykote_g1074")
    >>> round(cal.f0, 2), round(cal.ks, 2), cal.poor
    (10.89, 1.98, False)
    """
    points = grease_torque_points(lubricant)
    if not points:
        from ..parameters.catalog import _table

        known = sorted(k for k, v in _table("grease_torques")["greases"].items() if v.get("points"))
        raise ValueError(
            f"--datasheet {lubricant!r}: no published low-temperature torque in "
            f"parameters/data/grease_torques.toml; greases with points: {known}"
        )
    tests = sorted({p.test for p in points})
    if test is None:
        if len(tests) > 1:
            raise ValueError(
                f"--datasheet {lubricant!r} has points of the tests {tests}: name one with "
                "--test (their running torques are read after different times)"
            )
        test = tests[0]
    chosen = [p for p in points if p.test == test]
    if not chosen:
        raise ValueError(f"--test {test!r}: {lubricant!r} has points of {tests} only")
    rig = torque_test(test)
    visc = base_oil_viscosity(lubricant)
    f0, ks, rows = fit_points(chosen, rig, visc)
    # the model's running torque at the test speed: f0·u_i = r_run·f0/f0_i
    model_run = [r[3] * f0 / r[4] for r in rows]
    cal = DatasheetCalibration(
        lubricant=lubricant,
        test=test,
        points=rows,
        f0=f0,
        ks=ks,
        running_residuals=[m / r[3] - 1.0 for m, r in zip(model_run, rows, strict=True)],
        starting_residuals=[ks * m / r[2] - 1.0 for m, r in zip(model_run, rows, strict=True)],
        parameters={},
        sources={},
    )
    cal.parameters, cal.sources = _parameters(cal, rig)
    cal.problems = _problems(cal)
    cal.warnings = _warnings(cal, rig)
    return cal


def _parameters(cal: DatasheetCalibration, rig) -> tuple[dict, dict]:
    """The lubricant's preset (its base oil, the range of its data: a lubricant preset) with
    the grease term calibrated here."""
    values, sources = lubricant_values(cal.lubricant)
    where = f"calibrated: {cal.test} datasheet point(s) of {cal.lubricant} (servofmu calibrate)"
    values |= {"grease_f0": cal.f0, "grease_starting_ratio": cal.ks,
               "grease_reference_speed": rig.speed}  # fmt: skip
    sources |= {
        "grease_f0": where,
        "grease_starting_ratio": where,
        "grease_reference_speed": f"{rig.source('speed')} ({cal.test})",
    }
    return values, sources


def _problems(cal: DatasheetCalibration) -> list[str]:
    found = []
    for name, value in (("grease_f0", cal.f0), ("grease_starting_ratio", cal.ks)):
        sp = spec(name)
        if not sp.min < value < sp.max:
            found.append(
                f"{name} = {value:.4g} sits outside or at a bound of its range "
                f"[{sp.min:g}, {sp.max:g}]"
            )
    if len(cal.points) >= 2:
        for what, res in (("running", cal.running_residuals), ("starting", cal.starting_residuals)):
            rms = _rms(res)
            if rms > UNREPLICATED_LIMIT:
                found.append(
                    f"the law misses the published {what} torques: rms relative residual "
                    f"{100 * rms:.3g} %, more than the {100 * UNREPLICATED_LIMIT:g} % a model "
                    "within the scatter of friction measurements leaves (assumed)"
                )
    return found


def _warnings(cal: DatasheetCalibration, rig) -> list[str]:
    notes = []
    if len(cal.points) == 1:
        notes.append(
            "one datasheet point: f0 and ks are determined exactly (two numbers, two unknowns), "
            "so nothing tests the law; the term's torque at another temperature (through the "
            "base oil's ν(T)^(2/3)), speed or bearing (dm³) is a prediction, untested"
        )
    notes.append(
        f"the test bearing (d = {rig.bore * 1e3:g} mm, D = {rig.outer_diameter * 1e3:g} mm) is "
        "packed full; a bearing filled to 20-40 % churns less, so the term over-predicts it by "
        "an unknown factor (limits: physics/friction/grease.py)"
    )
    if cal.test == "jis_k2220":
        notes.append(
            "JIS K 2220 reads the running torque after 10 min of rotation (ASTM D1478: 60 min): "
            "f0 holds for that reading"
        )
    return notes


def to_text(cal: DatasheetCalibration) -> str:
    """The report as text (units in every heading)."""
    head = "POOR FIT: " + "; ".join(cal.problems) if cal.poor else "calibrated"
    lines = [
        f"grease term of {cal.lubricant} on its {cal.test} datasheet torque: {head}",
        "",
        "T [degC]  nu [cSt]   start [mN.m]  run [mN.m]  f0 of point  run resid [%]  "
        "start resid [%]",
    ]
    for (t, nu, s, r, f), rr, sr in zip(
        cal.points, cal.running_residuals, cal.starting_residuals, strict=True
    ):
        lines.append(
            f"{kelvin_to_celsius(t):8.1f}  {nu / CST:9.4g}  {s * 1e3:12.4g}  {r * 1e3:10.4g}  "
            f"{f:11.4g}  {100 * rr:13.3g}  {100 * sr:15.3g}"
        )
    lines += [
        "",
        f"grease_f0 = {cal.f0:.6g} (calibrated)",
        f"grease_starting_ratio = {cal.ks:.6g} (calibrated)",
        f"grease_reference_speed = {cal.parameters['grease_reference_speed'] / RPM:g} rpm "
        f"({cal.sources['grease_reference_speed']})",
        "",
        "parameters written (calibrated.ssv):",
        *(f"  {n} = {cal.parameters[n]!r}  [{cal.sources[n]}]" for n in GREASE_PARAMETERS),
    ]
    lines += ["", *(f"warning: {w}" for w in cal.warnings)]
    return "\n".join(lines)

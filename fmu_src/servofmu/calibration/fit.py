"""Least-squares calibration of a bearing pair's unknown coefficients on measured running
friction torque versus temperature (and speed).

The model is the library's running torque of the pair (Yu 2017 eq 1–9 for grease; Ning's
hysteresis, differential sliding and spin for a solid film), with the thermal coupling of
frame, shaft and rings (Yu eq 10–17), built from the BearingFriction FMU's parameter set
(:mod:`servofmu.physics.bearing_parameters`), so the fitted set gives the same torques in
the FMU. The unknowns are fitted with ``scipy.optimize.least_squares`` (trust-region
reflective, within physical bounds); standard errors and correlations come from the
Jacobian at the optimum (Gauss-Newton covariance s²·(JᵀJ)⁻¹, s² = RSS/(n − p)).

Identifiability is checked on the same Jacobian, with each column scaled to a relative change
of its parameter: a parameter that does not move the model over the data, a combination that
the data do not determine (small singular value), pairs correlated beyond 0.99, standard
errors above half the estimate, estimates at a bound; and, for Palmgren's s0, the speed: Yu
eq 8 gives the viscous torque as s0·(ν·n)^(2/3), so data at one speed determine only
s0·n^(2/3), and the fitted s0 holds for that speed.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from ..physics.bearing import operating_outputs
from ..physics.bearing_parameters import PARAMETER_NAMES, pair_from_parameters
from ..physics.units import DEG
from .measurements import FrictionMeasurements


@dataclass(frozen=True)
class Unknown:
    """A coefficient that can be fitted: physical bounds, typical scale, log-scaled or not."""

    name: str
    lower: float
    upper: float
    scale: float
    log: bool
    description: str
    bounds_source: str


UNKNOWNS: dict[str, Unknown] = {
    u.name: u
    for u in (
        Unknown(
            "palmgren_s0",
            0.0,
            20.0,
            1.0,
            False,
            "Palmgren factor s0 of the viscous torque (Yu 2017 eq 8)",
            "assumed: grease f0 lies within 0.5–10 (Harris & Kotzalas); bounds widened to 0–20",
        ),
        Unknown(
            "hysteresis_loss",
            0.0,
            0.05,
            0.01,
            False,
            "elastic hysteresis loss factor α_r (Yu 2017 eq 1)",
            "handbook: below 1 % for bearing steel (Yu 2017 §1.1); bound at 5 %",
        ),
        Unknown(
            "sliding_friction",
            0.0,
            0.5,
            0.1,
            False,
            "sliding friction coefficient μ of spin and differential sliding (Yu eq 5–7, Ning)",
            "handbook: boundary friction of steel or MoS2 stays below 0.5",
        ),
        Unknown(
            "loop_stiffness",
            1.0e5,
            1.0e11,
            1.0,
            True,
            "structural axial stiffness of the preload loop [N/m] (Yu 2017 eq 14–17)",
            "assumed: from a very compliant yoke (1e5 N/m) to rigid steel (1e11 N/m)",
        ),
    )
}
RESIDUALS = ("relative", "absolute")


def running_torque(parameters: Mapping[str, object], temperature, speed) -> np.ndarray:
    """Running friction torque [N·m] of the pair of parameter set ``parameters`` (names of
    :data:`~servofmu.physics.bearing_parameters.PARAMETER_NAMES`) at temperatures [K] and
    speed magnitudes [rad/s] (arrays of one shape), no external load: Yu 2017 eq 9 (grease)
    or Ning's sum (solid), through :mod:`servofmu.physics.bearing`."""
    return _running(_outputs(parameters, temperature, speed), temperature)


def _outputs(parameters, temperature, speed):
    pair = pair_from_parameters(parameters)
    return operating_outputs(pair, np.asarray(temperature, float), np.asarray(speed, float))


def _running(out, temperature) -> np.ndarray:
    shape = np.shape(temperature)
    return np.broadcast_to(np.asarray(out.running_torque, dtype=float), shape).copy()


@dataclass
class Calibration:
    """Result of :func:`calibrate` (SI; ``estimate``/``standard_error`` in the parameters'
    own units, ``correlation`` between the unknowns)."""

    data: FrictionMeasurements
    parameters: dict[str, object]  # the whole set, fitted values in
    unknowns: tuple[str, ...]
    initial: np.ndarray
    estimate: np.ndarray
    standard_error: np.ndarray
    correlation: np.ndarray
    speed: np.ndarray  # speed used per point [rad/s]
    speed_assumed: bool
    model: np.ndarray  # fitted torque per point [N·m]
    residual_kind: str
    residuals: np.ndarray  # (model − measured)/measured, or model − measured [N·m]
    rms: float
    dof: int
    optimizer: str
    evaluations: int
    warnings: list[str] = field(default_factory=list)

    def as_dict(self) -> dict:
        """JSON-ready summary."""
        return {
            "data": self.data.source,
            "points": len(self.data),
            "unknowns": [
                {
                    "name": n,
                    "estimate": float(e),
                    "standard_error": float(s),
                    "initial": float(i),
                    "lower": UNKNOWNS[n].lower,
                    "upper": UNKNOWNS[n].upper,
                }
                for n, e, s, i in zip(
                    self.unknowns, self.estimate, self.standard_error, self.initial, strict=True
                )
            ],
            "correlation": self.correlation.tolist(),
            "residual_kind": self.residual_kind,
            "rms_residual": self.rms,
            "degrees_of_freedom": self.dof,
            "warnings": list(self.warnings),
            "parameters": dict(self.parameters),
        }


def calibrate(
    data: FrictionMeasurements,
    parameters: Mapping[str, object],
    unknowns: Sequence[str],
    speed: float | None = None,
    residual: str = "relative",
) -> Calibration:
    """Fit ``unknowns`` (names of :data:`UNKNOWNS`) of parameter set ``parameters`` to
    ``data``. ``speed`` [rad/s] is the test speed of every point when the data have no speed
    column (required then). ``residual``: "relative" ((model − measured)/measured, for data
    spanning decades) or "absolute" (N·m)."""
    unknowns = tuple(unknowns)
    if not unknowns:
        raise ValueError("unknowns = (): name at least one of " + ", ".join(UNKNOWNS))
    for name in unknowns:
        if name not in UNKNOWNS:
            raise ValueError(f"unknown = {name!r} is not one of {list(UNKNOWNS)}")
    if len(set(unknowns)) != len(unknowns):
        raise ValueError(f"unknowns = {list(unknowns)} names one twice")
    if residual not in RESIDUALS:
        raise ValueError(f"residual = {residual!r} is not one of {list(RESIDUALS)}")
    missing = [n for n in PARAMETER_NAMES if n not in parameters]
    if missing:
        raise ValueError(f"parameters lack {missing}")
    if "palmgren_s0" in unknowns and parameters["lubrication"] != "grease":
        raise ValueError("palmgren_s0 has no effect with lubrication = 'solid' (no viscous term)")
    n, p = len(data), len(unknowns)
    if n <= p:
        raise ValueError(
            f"{data.source}: {n} points for {p} unknowns {list(unknowns)}; at least {p + 1} "
            "are needed (one more than the unknowns, for the standard errors)"
        )
    if data.speed is None:
        if speed is None:
            raise ValueError(
                f"{data.source} has no speed column: give the test speed (e.g. --speed '10 deg/s')"
            )
        if not (math.isfinite(speed) and speed >= 0.0):
            raise ValueError(f"speed = {speed!r} rad/s must be finite and ≥ 0")
        w = np.full(n, float(speed))
    else:
        w = data.speed
    base = dict(parameters)
    specs = [UNKNOWNS[u] for u in unknowns]
    x0 = np.array([_to_x(s, _initial(s, base[s.name])) for s in specs])
    lower = np.array([_to_x(s, s.lower) for s in specs])
    upper = np.array([_to_x(s, s.upper) for s in specs])
    y = data.torque

    def with_x(x):
        q = dict(base)
        for s, xi in zip(specs, x, strict=True):
            q[s.name] = _from_x(s, xi)
        return q

    def resid(x):
        m = running_torque(with_x(x), data.temperature, w)
        return (m - y) / y if residual == "relative" else m - y

    sol = least_squares(resid, x0, bounds=(lower, upper), method="trf", diff_step=1e-6)
    theta = np.array([_from_x(s, xi) for s, xi in zip(specs, sol.x, strict=True)])
    fitted = with_x(sol.x)
    out = _outputs(fitted, data.temperature, w)  # the fitted model, once: torque and flags
    model = _running(out, data.temperature)
    r = sol.fun
    dof = n - p
    s2 = float(r @ r) / dof
    jac = np.asarray(sol.jac, dtype=float)
    sing, vt = np.linalg.svd(jac, full_matrices=False)[1:]
    keep = sing > (sing[0] * 1e-12 if sing.size else 0.0)
    cov_x = (vt[keep].T / sing[keep] ** 2) @ vt[keep] * s2
    se_x = np.sqrt(np.clip(np.diag(cov_x), 0.0, None))
    se = np.array(
        [se_x[i] * (theta[i] * math.log(10.0) if s.log else s.scale) for i, s in enumerate(specs)]
    )
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov_x / np.outer(se_x, se_x)
    corr[~np.isfinite(corr)] = np.nan
    np.fill_diagonal(corr, 1.0)
    cal = Calibration(
        data=data,
        parameters=fitted,
        unknowns=unknowns,
        initial=np.array([_from_x(s, xi) for s, xi in zip(specs, x0, strict=True)]),
        estimate=theta,
        standard_error=se,
        correlation=corr,
        speed=w,
        speed_assumed=data.speed is None,
        model=model,
        residual_kind=residual,
        residuals=r,
        rms=float(np.sqrt(np.mean(r**2))),
        dof=dof,
        optimizer=sol.message,
        evaluations=int(sol.nfev),
    )
    cal.warnings = identifiability_warnings(cal, jac, specs, sol.x, sol.active_mask)
    overloaded_at = np.broadcast_to(np.asarray(out.overloaded, dtype=bool), w.shape)
    overloaded = [line for line, s in zip(data.lines, overloaded_at, strict=True) if s]
    if overloaded:
        cal.warnings.append(
            f"the model calls the pair overloaded (Hertz pressure above the limit: permanent "
            f"deformation) at lines {overloaded}: its torque there is outside the model's validity"
        )
    return cal


def identifiability_warnings(cal: Calibration, jac, specs, x, active) -> list[str]:
    """The identifiability problems of a fit (see module docstring), one sentence each."""
    warnings = []
    names = [s.name for s in specs]
    # sensitivity of the residuals to a relative change of each parameter
    sens = np.column_stack(
        [
            jac[:, i] * (1.0 / math.log(10.0) if s.log else max(abs(x[i]), 1.0))
            for i, s in enumerate(specs)
        ]
    )
    norms = np.linalg.norm(sens, axis=0)
    flat = norms <= 1e-8 * max(norms.max(), 1e-300)
    for i in np.flatnonzero(flat):
        warnings.append(
            f"{names[i]} is not identifiable: it does not change the model at any data point "
            "(e.g. the preload loop is open, or the term it scales is zero, over these data)"
        )
    live = np.flatnonzero(~flat)
    if live.size >= 2:
        sv, vt = np.linalg.svd(sens[:, live] / norms[live], full_matrices=False)[1:]
        if sv[-1] < 1e-3 * sv[0]:
            weights = vt[-1] / np.abs(vt[-1]).max()
            involved = [names[live[j]] for j in np.flatnonzero(np.abs(weights) > 0.1)]
            warnings.append(
                f"{' and '.join(involved)} are not separately identifiable: the data determine "
                f"only a combination of them (condition number {sv[0] / sv[-1]:.3g}); fix all "
                "but one"
            )
    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            rho = cal.correlation[i, j]
            if np.isfinite(rho) and abs(rho) > 0.99:
                warnings.append(
                    f"{names[i]} and {names[j]} are correlated {rho:+.4f}: the data hardly tell "
                    "them apart"
                )
    for i, name in enumerate(names):
        est, se = cal.estimate[i], cal.standard_error[i]
        if active[i] != 0:
            bound = "lower" if active[i] < 0 else "upper"
            warnings.append(
                f"{name} = {est:.4g} sits at its {bound} bound: the data push it out of the "
                "physical range, and its standard error means little"
            )
        elif not flat[i] and est != 0 and se > 0.5 * abs(est):
            warnings.append(
                f"{name} is poorly determined: standard error {se:.3g} is "
                f"{100 * se / abs(est):.0f} % of the estimate {est:.4g}"
            )
    if "palmgren_s0" in names:
        speeds = np.unique(np.round(cal.speed, 12))
        if cal.speed_assumed or speeds.size == 1:
            how = "assumed" if cal.speed_assumed else "the only one in the data"
            warnings.append(
                "palmgren_s0 and the speed are not separately identifiable (Yu 2017 eq 8 gives "
                "the viscous torque as s0·(ν·n)^(2/3)): the data determine s0·n^(2/3) only, and "
                f"the fitted s0 holds for {speeds[0] / DEG:.4g} °/s ({how})"
            )
    return warnings


def _initial(spec: Unknown, value) -> float:
    """Start value: the parameter set's value, moved into the bounds (mid-range when it is
    0 or unset for a log-scaled unknown)."""
    v = float(value)
    if spec.log and v <= 0.0:
        return math.sqrt(spec.lower * spec.upper)
    if v == 0.0 and spec.lower == 0.0:
        v = spec.scale  # a zero start has no scale for the finite differences
    return min(max(v, spec.lower), spec.upper)


def _to_x(spec: Unknown, value: float) -> float:
    return math.log10(value) if spec.log else value / spec.scale


def _from_x(spec: Unknown, x: float) -> float:
    return 10.0**x if spec.log else x * spec.scale

"""Least-squares calibration of a bearing pair's unknown coefficients on measured running
friction torque versus temperature (and speed), and the checks that keep a failed fit from
being reported as a result.

The model is the library's running torque of the pair (Yu 2017 eq 1–9 for grease; Ning's
hysteresis, differential sliding and spin for a solid film), with the thermal coupling of
frame, shaft and rings (Yu eq 10–17), built from the BearingFriction FMU's parameter set
(:mod:`servofmu.parameters.bearing`), so the fitted set gives the same torques in
the FMU. The unknowns are fitted with ``scipy.optimize.least_squares`` (trust-region
reflective, within physical bounds).

**Operating points.** The model is evaluated once per distinct operating point (temperature,
speed); the points measured there enter through their count, mean and scatter
(:class:`~.measurements.FrictionMeasurements`). For relative residuals r_i = m·u_i − 1
(u_i = 1/M_i) the sum over a point's n measurements is n·(ū² + v)·(m − ū/(ū² + v))² +
n·v/(ū² + v) (ū, v: mean and variance of u), for absolute ones n·(m − M̄)² + Σ(M_i − M̄)²:
least squares on one weighted residual per operating point is least squares on every
measurement, and the second terms are the pure-error sum of squares of repeated points.

**Standard errors** come from the Jacobian at the optimum (Gauss-Newton covariance
s²·(JᵀJ)⁻¹, s² = RSS/(n − p)), computed here by finite differences that stay inside the
bounds (``scipy.differentiate.jacobian``, one-sided next to a bound): the Jacobian that
``least_squares`` returns is that of its scaled problem, with zero columns for a parameter
held at a bound, which would call a parameter at a bound "without effect on the data".

**Identifiability** is checked on the same Jacobian, each column scaled to a relative change
of its parameter: a parameter that does not move the model over the data, a combination that
the data do not determine (small singular value), pairs correlated beyond 0.99, standard
errors above half the estimate; and, for Palmgren's s0, the speed: Yu eq 8 gives the viscous
torque as s0·(ν·n)^(2/3), so data at one speed determine only s0·n^(2/3), and the fitted s0
holds for that speed.

**A poor fit is not a calibration** (:attr:`Calibration.problems`; ``servofmu calibrate``
exits 1 unless ``--allow-poor-fit``): an estimate at a bound of its physical range; a model
that misses the data by more than their scatter — with repeated operating points, the
lack-of-fit F test (NIST/SEMATECH e-Handbook of Statistical Methods §4.4.4.3) rejects the
model at :data:`LACK_OF_FIT_P` and the rms deviation of the model from the measured means
exceeds the scatter of single points; without repeated points, an rms relative residual
above :data:`UNREPLICATED_LIMIT` (assumed); an optimizer that did not converge.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy.differentiate import jacobian
from scipy.optimize import least_squares
from scipy.stats import f as f_distribution

from ..parameters.bearing import PARAMETER_NAMES, pair_from_parameters
from ..physics.bearing import operating_outputs
from ..physics.kernels.units import DEG
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

#: Significance at which the lack-of-fit F test rejects the model.
LACK_OF_FIT_P = 1e-3
#: Without repeated operating points the data's scatter is unknown: a fit whose rms relative
#: residual exceeds this is refused (assumed: repeatability of friction-torque measurements
#: is a few per cent; a model off by more than 10 % rms does not describe the data).
UNREPLICATED_LIMIT = 0.10
#: Largest finite-difference step in the scaled parameters (0.01 of a unit of scale, or of a
#: decade for a log-scaled unknown); smaller where the range is narrower.
JACOBIAN_STEP = 1e-2


def running_torque(parameters: Mapping[str, object], temperature, speed) -> np.ndarray:
    """Running friction torque [N·m] of the pair of parameter set ``parameters`` (names of
    :data:`~servofmu.parameters.bearing.PARAMETER_NAMES`) at temperatures [K] and
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
    own units, ``correlation`` between the unknowns). Per-group arrays follow the groups of
    ``data`` (points of one temperature, speed and direction)."""

    data: FrictionMeasurements
    parameters: dict[str, object]  # the whole set, fitted values in
    unknowns: tuple[str, ...]
    initial: np.ndarray
    estimate: np.ndarray
    standard_error: np.ndarray
    correlation: np.ndarray
    speed: np.ndarray  # speed used per group [rad/s]
    speed_assumed: bool
    model: np.ndarray  # fitted torque per group [N·m]
    residual_kind: str
    residuals: np.ndarray  # mean per group of (model − measured)/measured, or model − measured
    rms: float  # rms residual over all points
    dof: int
    optimizer: str
    evaluations: int
    operating_points: int = 0  # distinct (temperature, speed)
    scatter: float | None = None  # rms of repeated points about their mean (residual kind)
    deviation: float | None = None  # rms over operating points of model − measured mean
    lack_of_fit_p: float | None = None  # p-value of the lack-of-fit F test
    warnings: list[str] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)  # why this is no calibration

    @property
    def poor(self) -> bool:
        """True when the fit is not a calibration (:attr:`problems` says why)."""
        return bool(self.problems)

    def as_dict(self) -> dict:
        """JSON-ready summary."""
        return {
            "data": self.data.source,
            "points": len(self.data),
            "operating_points": self.operating_points,
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
            "scatter": self.scatter,
            "deviation_from_means": self.deviation,
            "lack_of_fit_p": self.lack_of_fit_p,
            "degrees_of_freedom": self.dof,
            "poor_fit": self.poor,
            "problems": list(self.problems),
            "warnings": list(self.warnings),
            "parameters": dict(self.parameters),
        }


@dataclass(frozen=True)
class _Points:
    """The distinct operating points of the data with the statistics of their measurements
    in the residual kind: residual e = weight·(model − target) per point; ``pure`` the
    pure-error sum of squares; ``group`` maps each data group to its point."""

    temperature: np.ndarray
    speed: np.ndarray
    count: np.ndarray
    target: np.ndarray
    weight: np.ndarray
    pure: np.ndarray
    group: np.ndarray


def _operating_points(data: FrictionMeasurements, speed: np.ndarray, residual: str) -> _Points:
    keys = np.column_stack([data.temperature, speed])
    uniq, group = np.unique(keys, axis=0, return_inverse=True)
    group = group.ravel()
    n_g = data.count.astype(float)
    n = np.bincount(group, n_g)

    def pooled(mean_g, ss_g):  # count-weighted mean and Σ of squared deviations per point
        mean = np.bincount(group, n_g * mean_g) / n
        return mean, np.bincount(group, ss_g) + np.bincount(
            group, n_g * (mean_g - mean[group]) ** 2
        )

    if residual == "relative":
        u, ss_u = pooled(data.inverse_mean, data.inverse_ss)
        q = u * u + ss_u / n
        target, weight, pure = u / q, np.sqrt(n * q), ss_u / q
    else:
        y, ss_y = pooled(data.torque, data.torque_ss)
        target, weight, pure = y, np.sqrt(n), ss_y
    return _Points(uniq[:, 0], uniq[:, 1], n, target, weight, pure, group)


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
    spanning decades) or "absolute" (N·m). A fit that is no calibration (at a bound, missing
    the data beyond their scatter, not converged) is returned with :attr:`Calibration.problems`
    saying why."""
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
        w = np.full(data.groups, float(speed))
    else:
        w = data.speed
    ops = _operating_points(data, w, residual)
    base = dict(parameters)
    specs = [UNKNOWNS[u] for u in unknowns]
    x0 = np.array([_to_x(s, _initial(s, base[s.name])) for s in specs])
    lower = np.array([_to_x(s, s.lower) for s in specs])
    upper = np.array([_to_x(s, s.upper) for s in specs])

    def with_x(x):
        q = dict(base)
        for s, xi in zip(specs, x, strict=True):
            q[s.name] = _from_x(s, xi)
        return q

    def model_at(x):  # the model once per distinct operating point [N·m]
        return running_torque(with_x(x), ops.temperature, ops.speed)

    def resid(x):
        return ops.weight * (model_at(x) - ops.target)

    sol = least_squares(resid, x0, bounds=(lower, upper), method="trf", diff_step=1e-6)
    theta = np.array([_from_x(s, xi) for s, xi in zip(specs, sol.x, strict=True)])
    fitted = with_x(sol.x)
    out = _outputs(fitted, ops.temperature, ops.speed)  # the fitted model, once: torque, flags
    m = _running(out, ops.temperature)
    jac = ops.weight[:, None] * model_jacobian(model_at, sol.x, lower, upper)
    e = ops.weight * (m - ops.target)
    rss = float(e @ e + ops.pure.sum())
    dof = n - p
    s2 = rss / dof
    sing, vt = np.linalg.svd(jac, full_matrices=False)[1:]
    keep = sing > (sing[0] * 1e-12 if sing.size and sing[0] > 0 else np.inf)
    cov_x = (vt[keep].T / sing[keep] ** 2) @ vt[keep] * s2
    se_x = np.sqrt(np.clip(np.diag(cov_x), 0.0, None))
    se_x[~np.isfinite(se_x)] = np.nan
    se = np.array(
        [se_x[i] * (theta[i] * math.log(10.0) if s.log else s.scale) for i, s in enumerate(specs)]
    )
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov_x / np.outer(se_x, se_x)
    corr[~np.isfinite(corr)] = np.nan
    np.fill_diagonal(corr, 1.0)
    model_g = m[ops.group]
    if residual == "relative":
        residuals = model_g * data.inverse_mean - 1.0
    else:
        residuals = model_g - data.torque
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
        model=model_g,
        residual_kind=residual,
        residuals=residuals,
        rms=math.sqrt(rss / n),
        dof=dof,
        optimizer=sol.message,
        evaluations=int(sol.nfev),
        operating_points=len(ops.count),
    )
    at_bound = _at_bounds(sol.x, lower, upper, sol.active_mask)
    cal.warnings = identifiability_warnings(cal, jac, specs, sol.x, at_bound)
    cal.problems = [
        f"{s.name} = {theta[i]:.4g} sits at its {'lower' if at_bound[i] < 0 else 'upper'} bound "
        f"{s.lower if at_bound[i] < 0 else s.upper:g}: the data push it out of its physical "
        f"range [{s.lower:g}, {s.upper:g}] ({s.bounds_source})"
        for i, s in enumerate(specs)
        if at_bound[i]
    ]
    cal.problems += _fit_quality(cal, ops, m, p)
    if sol.status <= 0:
        cal.problems.append(f"the optimizer did not converge: {sol.message}")
    overloaded_at = np.broadcast_to(np.asarray(out.overloaded, dtype=bool), m.shape)[ops.group]
    overloaded = [line for line, s in zip(data.lines, overloaded_at, strict=True) if s]
    if overloaded:
        cal.warnings.append(
            f"the model calls the pair overloaded (Hertz pressure above the limit: permanent "
            f"deformation) at lines {overloaded}: its torque there is outside the model's validity"
        )
    return cal


def model_jacobian(model, x, lower, upper) -> np.ndarray:
    """d model / d x at ``x`` (one row per model value, one column per parameter) by finite
    differences that never leave [lower, upper]: central where the stencil fits, one-sided
    (into the range) next to a bound; ``scipy.differentiate.jacobian`` with steps from
    :data:`JACOBIAN_STEP` down. ``model`` maps a parameter vector to an array."""
    x = np.asarray(x, dtype=float)
    h = np.minimum(JACOBIAN_STEP, (upper - lower) / 4.0)
    direction = np.where(x - lower < h, 1, np.where(upper - x < h, -1, 0))

    def f(xs):
        flat = xs.reshape(len(x), -1)
        out = np.column_stack([model(flat[:, k]) for k in range(flat.shape[1])])
        return out.reshape(out.shape[0], *xs.shape[1:])

    res = jacobian(
        f,
        x,
        initial_step=h,
        step_direction=direction,
        order=4,
        maxiter=5,
        tolerances={"rtol": 1e-6},
    )
    return np.atleast_2d(np.asarray(res.df, dtype=float))


def _at_bounds(x, lower, upper, active) -> np.ndarray:
    """-1 / +1 where a parameter sits at its lower / upper bound (within 1e-6 of its range,
    or held there by the optimizer), else 0."""
    tol = 1e-6 * (upper - lower)
    at = np.where(x - lower <= tol, -1, np.where(upper - x <= tol, 1, 0))
    return np.where(at != 0, at, np.asarray(active, dtype=int))


def _fit_quality(cal: Calibration, ops: _Points, m, p: int) -> list[str]:
    """Why the model misses the data by more than their scatter (see the module docstring);
    fills ``cal.scatter``, ``cal.deviation`` and ``cal.lack_of_fit_p``; notes go to
    ``cal.warnings``."""
    n, k = len(cal.data), len(ops.count)
    unit, scale = ("%", 100.0) if cal.residual_kind == "relative" else ("N·mm", 1e3)
    # deviation of the model from each point's measured mean, in the residual's kind
    dev = ops.weight * (m - ops.target) / np.sqrt(ops.count)
    cal.deviation = float(np.sqrt(np.mean(dev**2)))
    if n == k:  # no repeated operating point: the scatter of the data is unknown
        relative = m[ops.group] * cal.data.inverse_mean - 1.0
        rms = float(np.sqrt(np.mean(relative**2)))
        cal.warnings.append(
            "the data repeat no operating point, so their scatter is unknown: the fit is judged "
            f"against an assumed {100 * UNREPLICATED_LIMIT:g} % rms relative residual"
        )
        if rms > UNREPLICATED_LIMIT:
            return [
                f"the model misses the data: rms relative residual {100 * rms:.3g} %, more than "
                f"the {100 * UNREPLICATED_LIMIT:g} % a model within the scatter of friction "
                "measurements leaves (assumed); the fixed configuration (mounting, bearing, "
                "lubricant, --set values) does not describe this pair, or the unknowns cannot "
                "absorb the difference"
            ]
        return []
    pure = float(ops.pure.sum())
    cal.scatter = math.sqrt(pure / (n - k))
    if k <= p:
        cal.warnings.append(
            f"{k} distinct operating points for {p} unknowns: no degrees of freedom are left to "
            "test the model against the scatter of repeated points"
        )
        return []
    lack = float(np.sum((ops.weight * (m - ops.target)) ** 2))
    if pure > 0:
        f_stat = (lack / (k - p)) / (pure / (n - k))
        cal.lack_of_fit_p = float(f_distribution.sf(f_stat, k - p, n - k))
    else:  # repeated points without scatter: any lack of fit is significant
        cal.lack_of_fit_p = 0.0 if lack > 0 else 1.0
    if cal.lack_of_fit_p >= LACK_OF_FIT_P:
        return []
    ratio = cal.deviation / cal.scatter if cal.scatter > 0 else math.inf
    summary = (
        f"rms deviation of the model from the measured means at the {k} operating points "
        f"{scale * cal.deviation:.3g} {unit}, {ratio:.3g} times the scatter of repeated points "
        f"({scale * cal.scatter:.3g} {unit}, {n - k} degrees of freedom); lack-of-fit F test "
        f"p = {cal.lack_of_fit_p:.2g}"
    )
    if cal.deviation <= cal.scatter:
        cal.warnings.append(
            "the lack of fit is significant but smaller than the scatter of single points: "
            + summary
        )
        return []
    return [
        f"the model misses the data by more than their scatter: {summary}; the fixed "
        "configuration (mounting, bearing, lubricant, --set values) does not describe this "
        "pair, or the unknowns cannot absorb the difference"
    ]


def identifiability_warnings(cal: Calibration, jac, specs, x, at_bound) -> list[str]:
    """The identifiability problems of a fit (see module docstring), one sentence each;
    ``jac`` the Jacobian of the residuals in the scaled parameters ``x``; ``at_bound`` the
    parameters held at a bound (their standard errors are not judged here)."""
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
        if sv.size < live.size or sv[-1] < 1e-3 * sv[0]:
            weights = vt[-1] / np.abs(vt[-1]).max()
            involved = [names[live[j]] for j in np.flatnonzero(np.abs(weights) > 0.1)]
            condition = sv[0] / sv[-1] if sv.size == live.size and sv[-1] > 0 else math.inf
            warnings.append(
                f"{' and '.join(involved)} are not separately identifiable: the data determine "
                f"only a combination of them (condition number {condition:.3g}); fix all "
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
        if not at_bound[i] and not flat[i] and est != 0 and se > 0.5 * abs(est):
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

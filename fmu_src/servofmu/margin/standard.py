"""The motorisation (torque) margin rule of ECSS-E-ST-33-01C, clause 4.7.5.3, as small pure
functions over torques [N·m], and its factors as data (``data/ecss_e_st_33_01c.toml``).

ECSS-E-ST-33-01C (6 March 2009), 4.7.5.3.1 b, d and 4.7.5.3.2 b: every component of
resistance R_k at in-orbit worst-case conditions is multiplied by its minimum uncertainty
factor u_k of Table 4-2 (by kind, and by whether the component is theoretical or measured);
the minimum actuation torque is

    T_min = m × Σ_k u_k·R_k + f_D·T_D + T_L      (m = 2, the motorisation factor; f_D = 1.25)

with T_D the inertial resistance torque of the customer's worst-case acceleration and T_L
the deliverable output torque; the actuation torque T must be ≥ T_min. The margin reported
here is T / T_min − 1 (≥ 0: the rule is met), and beside it the rule read as a ratio,
MR = (T − 1.25·T_D − T_L) / Σ u·R (≥ m = 2: the rule is met; :func:`motorisation_ratio`).
Which revision the factors come from, and what could not be checked, is written in the data
file and in :attr:`Factors.name`.

The kinds of resistance (:data:`CATEGORIES`) are Table 4-2's rows; :data:`TERMS` are the two
torques the equation adds outside the factored sum.
"""

from __future__ import annotations

import functools
import math
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np

#: Table 4-2's components of resistance (symbols I, S, H_M, F_R, H_Y, H_A, H_D).
CATEGORIES = (
    "inertia",
    "spring",
    "motor_magnetic_losses",
    "friction",
    "hysteresis",
    "harness",
    "adhesion",
)
#: The torques added outside the factored sum: T_D (times its factor) and T_L.
TERMS = ("inertial_resistance", "deliverable")
#: Whether a component was computed or measured (Table 4-2's two columns).
BASES = ("theoretical", "measured")
#: The package's factors: ECSS-E-ST-33-01C (data/ecss_e_st_33_01c.toml).
DATA_FILE = Path(__file__).with_name("data") / "ecss_e_st_33_01c.toml"


@dataclass(frozen=True)
class Factors:
    """The factors of a margin rule: Table 4-2's uncertainty factors, the motorisation factor
    and the factor of T_D, each with its source. Every factor is ≥ 1.

    Attributes
    ----------
    uncertainty : {category: {"theoretical": u, "measured": u}} [-]
    motorisation : m [-], the factor of the sum
    inertial_resistance : f_D [-], the factor of T_D
    sources : {"motorisation" | "inertial_resistance" | category: source}
    name : the standard and revision the factors come from
    """

    uncertainty: Mapping[str, Mapping[str, float]]
    motorisation: float
    inertial_resistance: float
    sources: Mapping[str, str]
    name: str

    def factor(self, category: str, basis: str) -> float:
        """u of ``category`` (:data:`CATEGORIES`) for ``basis`` (:data:`BASES`) [-]."""
        return self.uncertainty[category][basis]


def factor_problems(data: Mapping, where: str = "factors") -> list[str]:
    """The problems of a factor table in the format of ``data/ecss_e_st_33_01c.toml``
    (``motorisation``, ``inertial_resistance`` and ``uncertainty.CATEGORY`` with
    ``theoretical``, ``measured`` and ``source``): a missing or unknown entry, a factor that is
    not a finite number ≥ 1, a missing source. Each problem names its field under ``where``.

    Parameters
    ----------
    data : mapping
        The table as read from TOML.
    where : str
        Prefix of the field names in the messages.

    Returns
    -------
    list of str
        One line per problem; empty when the table is complete and valid.

    Examples
    --------
    >>> import tomllib
    >>> data = tomllib.loads(DATA_FILE.read_text())
    >>> factor_problems(data)
    []
    >>> data["uncertainty"]["friction"]["measured"] = 0.9
    >>> factor_problems(data)  # doctest: +ELLIPSIS
    ['factors.uncertainty.friction.measured = 0.9 is below 1: a factor of the rule ...']
    """
    problems = []
    for key in ("motorisation", "inertial_resistance"):
        entry = data.get(key)
        if not isinstance(entry, Mapping):
            problems.append(f"{where}.{key}: missing (a table {{ value, source }})")
            continue
        problems += _factor_problem(f"{where}.{key}.value", entry.get("value"))
        problems += _source_problem(f"{where}.{key}.source", entry.get("source"))
    table = data.get("uncertainty")
    if not isinstance(table, Mapping):
        return [
            *problems,
            f"{where}.uncertainty: missing (a table per category {list(CATEGORIES)})",
        ]
    unknown = sorted(set(table) - set(CATEGORIES))
    if unknown:
        problems.append(
            f"{where}.uncertainty: {unknown} are not categories of Table 4-2 {list(CATEGORIES)}"
        )
    for category in CATEGORIES:
        entry = table.get(category)
        if not isinstance(entry, Mapping):
            problems.append(f"{where}.uncertainty.{category}: missing")
            continue
        for basis in BASES:
            problems += _factor_problem(f"{where}.uncertainty.{category}.{basis}", entry.get(basis))
        problems += _source_problem(f"{where}.uncertainty.{category}.source", entry.get("source"))
    return problems


def _factor_problem(field: str, value) -> list[str]:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return [f"{field} = {value!r} must be a finite number ≥ 1"]
    if value < 1.0:
        return [
            f"{field} = {value!r} is below 1: a factor of the rule may only raise the "
            "minimum actuation torque (valid range [1, inf))"
        ]
    return []


def _source_problem(field: str, value) -> list[str]:
    if not isinstance(value, str) or not value.strip():
        return [
            f"{field}: missing: every factor states where it comes from (clause, table, revision)"
        ]
    return []


def factors_from_table(data: Mapping, where: str = "factors") -> Factors:
    """:class:`Factors` from a table in the format of ``data/ecss_e_st_33_01c.toml``;
    ValueError with the first of :func:`factor_problems`.

    Parameters
    ----------
    data : mapping
        The table as read from TOML.
    where : str
        Prefix of the field names in the messages.

    Returns
    -------
    Factors

    Examples
    --------
    >>> import tomllib
    >>> f = factors_from_table(tomllib.loads(DATA_FILE.read_text()))
    >>> f.factor("friction", "theoretical"), f.factor("friction", "measured"), f.motorisation
    (3.0, 1.5, 2.0)
    """
    problems = factor_problems(data, where)
    if problems:
        raise ValueError(problems[0])
    table = data["uncertainty"]
    standard = data.get("standard", {})
    name = " ".join(str(standard[k]) for k in ("name", "revision") if k in standard)
    return Factors(
        uncertainty={c: {b: float(table[c][b]) for b in BASES} for c in CATEGORIES},
        motorisation=float(data["motorisation"]["value"]),
        inertial_resistance=float(data["inertial_resistance"]["value"]),
        sources={
            "motorisation": data["motorisation"]["source"],
            "inertial_resistance": data["inertial_resistance"]["source"],
            **{c: table[c]["source"] for c in CATEGORIES},
        },
        name=name or where,
    )


@functools.cache
def ecss_factors() -> Factors:
    """The factors of ECSS-E-ST-33-01C as recorded in ``data/ecss_e_st_33_01c.toml`` (its
    6 March 2009 edition; see the file for what was not checked).

    Returns
    -------
    Factors

    Examples
    --------
    >>> f = ecss_factors()
    >>> [f.factor(c, "theoretical") for c in CATEGORIES]
    [1.1, 1.2, 1.5, 3.0, 3.0, 3.0, 3.0]
    >>> [f.factor(c, "measured") for c in CATEGORIES]
    [1.1, 1.2, 1.2, 1.5, 1.5, 1.5, 3.0]
    >>> f.motorisation, f.inertial_resistance
    (2.0, 1.25)
    """
    return factors_from_table(tomllib.loads(DATA_FILE.read_text(encoding="utf-8")), "factors")


def factored_torque(torque, category: str, basis: str, factors: Factors):
    """A component of resistance times its minimum uncertainty factor, u·R (ECSS-E-ST-33-01C
    4.7.5.3.1 b, Table 4-2).

    Parameters
    ----------
    torque : float or array_like
        The component R [N·m], ≥ 0.
    category : str
        Its kind, one of :data:`CATEGORIES`.
    basis : str
        "theoretical" or "measured".
    factors : Factors
        The rule's factors (:func:`ecss_factors`).

    Returns
    -------
    float or ndarray
        u·R [N·m].

    Examples
    --------
    >>> factored_torque(2.0e-3, "friction", "theoretical", ecss_factors())  # 3 × 2 mN·m
    0.006
    """
    return factors.factor(category, basis) * torque


def minimum_actuation_torque(factored_sum, inertial_resistance, deliverable, factors: Factors):
    """T_min = m·Σ u_k·R_k + f_D·T_D + T_L (ECSS-E-ST-33-01C 4.7.5.3.1 d).

    Parameters
    ----------
    factored_sum : float or array_like
        Σ u_k·R_k [N·m], the factored components of resistance.
    inertial_resistance : float or array_like
        T_D [N·m], the inertial resistance torque of the specified worst-case acceleration.
    deliverable : float or array_like
        T_L [N·m], the deliverable output torque (0 when none is specified).
    factors : Factors
        m and f_D.

    Returns
    -------
    float or ndarray
        T_min [N·m].

    Examples
    --------
    >>> # 2 × 7.95 mN·m + 1.25 × 0.4 mN·m + 0.3 mN·m = 16.7 mN·m
    >>> round(minimum_actuation_torque(7.95e-3, 0.4e-3, 0.3e-3, ecss_factors()) * 1e3, 12)
    16.7
    """
    return (
        factors.motorisation * factored_sum
        + factors.inertial_resistance * inertial_resistance
        + deliverable
    )


def motorisation_ratio(available, factored_sum, inertial_resistance, deliverable,
                       factors: Factors):  # fmt: skip
    """The rule read as a ratio: MR = (T − f_D·T_D − T_L) / Σ u_k·R_k, the actuation torque
    left for the factored resistances over their sum; ECSS-E-ST-33-01C 4.7.5.3.1 d and
    4.7.5.3.2 b (T ≥ T_min) hold exactly when MR ≥ m (the motorisation factor, 2). +inf where
    the sum is 0.

    Beside the margin T/T_min − 1 (:func:`torque_margin`): both cross their thresholds (MR = 2,
    margin = 0) at the same point, but the margin relates T to everything it must overcome,
    T_D and T_L included, while MR measures how many times T covers the factored resistances
    alone once T_D and T_L are served (the factor the rule requires, 2, is what an engineer
    used to a "motorisation ratio" checks).

    Parameters
    ----------
    available : float or array_like
        T [N·m].
    factored_sum : float or array_like
        Σ u_k·R_k [N·m].
    inertial_resistance, deliverable : float or array_like
        T_D, T_L [N·m].
    factors : Factors
        f_D.

    Returns
    -------
    float or ndarray
        MR [-].

    Examples
    --------
    >>> # (20 − 1.25 × 0.4 − 0.3) mN·m / 7.95 mN·m
    >>> round(motorisation_ratio(20.0e-3, 7.95e-3, 0.4e-3, 0.3e-3, ecss_factors()), 6)
    2.415094
    """
    left = np.asarray(available, dtype=float) - (
        factors.inertial_resistance * np.asarray(inertial_resistance, dtype=float)
        + np.asarray(deliverable, dtype=float)
    )
    total = np.asarray(factored_sum, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(total == 0.0, np.inf, left / total)
    return float(ratio) if ratio.ndim == 0 else ratio


def torque_margin(available, minimum):
    """The margin T / T_min − 1 of the actuation torque over the minimum (≥ 0: ECSS-E-ST-33-01C
    4.7.5.3.2 b, T ≥ T_min, is met); +inf where T_min is 0, NaN where either is NaN.

    Parameters
    ----------
    available : float or array_like
        T [N·m], the actuation torque at worst-case conditions.
    minimum : float or array_like
        T_min [N·m], > 0 (:func:`minimum_actuation_torque`).

    Returns
    -------
    float or ndarray
        The margin [-].

    Examples
    --------
    >>> round(torque_margin(20.0e-3, 16.7e-3), 6)  # 20 / 16.7 − 1
    0.197605
    """
    available = np.asarray(available, dtype=float)
    minimum = np.asarray(minimum, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        margin = np.where(minimum == 0.0, np.inf, available / minimum - 1.0)  # NaN stays NaN
    return float(margin) if margin.ndim == 0 else margin

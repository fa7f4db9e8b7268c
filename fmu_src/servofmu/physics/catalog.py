"""Catalogue of records kept as data (``physics/data/*.toml``) with per-value provenance.

Each numeric entry in the data files is ``{ value, unit, kind, ref }`` where ``kind`` is one of
``paper``, ``catalogue``, ``handbook``, ``assumed``, ``calibrated`` or ``derived``; the loaders
convert to SI and keep ``"kind: ref"`` as the provenance of each field.
"""

from __future__ import annotations

import functools
import math
import tomllib
from importlib import resources

from .geometry import BallBearing, ball_diameter_from_grooves, free_contact_angle
from .materials import Material
from .units import to_si
from .viscosity import WaltherViscosity, walther_from_two_points

PROVENANCE_KINDS = ("paper", "catalogue", "handbook", "assumed", "calibrated", "derived")


@functools.cache
def _table(name: str) -> dict:
    with resources.files(__package__).joinpath(f"data/{name}.toml").open("rb") as fh:
        return tomllib.load(fh)


def quantity(entry: dict, field: str) -> tuple[float, str]:
    """(SI value, provenance) of one ``{value, unit, kind, ref}`` data entry."""
    try:
        value, unit, kind, ref = (entry[k] for k in ("value", "unit", "kind", "ref"))
    except (KeyError, TypeError):
        raise ValueError(f"{field} = {entry!r} must be {{value, unit, kind, ref}}") from None
    if kind not in PROVENANCE_KINDS:
        raise ValueError(f"{field}: kind = {kind!r} is not one of {PROVENANCE_KINDS}")
    return to_si(float(value), unit), f"{kind}: {ref}"


def _lookup(table: str, key: str) -> dict:
    data = _table(table)
    if key not in data:
        raise ValueError(f"{table[:-1]} key = {key!r} is not one of {sorted(data)}")
    return data[key]


def keys(table: str) -> list[str]:
    """Keys of one data table: ``materials``, ``lubricants``, ``bearings`` or ``mountings``."""
    return sorted(_table(table))


@functools.cache
def material(key: str) -> Material:
    """The :class:`Material` ``key`` from ``data/materials.toml``."""
    entry = _lookup("materials", key)
    values, prov = {}, []
    for field in ("youngs_modulus", "poisson_ratio", "expansion"):
        values[field], src = quantity(entry[field], field)
        prov.append((field, src))
    return Material(key=key, name=entry["name"], provenance=tuple(prov), **values)


@functools.cache
def lubricant(key: str) -> WaltherViscosity | None:
    """The viscosity model of lubricant ``key``; ``None`` for a solid (dry-film) lubricant."""
    entry = _lookup("lubricants", key)
    if entry["model"] == "solid":
        return None
    if entry["model"] != "walther":
        raise ValueError(f"lubricant {key!r}: model = {entry['model']!r} is not walther or solid")
    c, c_src = quantity(entry["c"], "c")
    c_cst = c / to_si(1.0, "cSt")
    if "a" in entry:
        a, a_src = quantity(entry["a"], "a")
        b, b_src = quantity(entry["b"], "b")
        prov = (("a", a_src), ("b", b_src), ("c", c_src))
        return WaltherViscosity(key=key, name=entry["name"], a=a, b=b, c=c_cst, provenance=prov)
    pts = {f: quantity(entry[f], f) for f in ("t1", "nu1", "t2", "nu2")}
    fit = walther_from_two_points(
        pts["t1"][0], pts["nu1"][0], pts["t2"][0], pts["nu2"][0], c=c_cst, key=key
    )
    src = "derived: ASTM D341 fit through " + "; ".join(f"{f} ({s})" for f, (_, s) in pts.items())
    return WaltherViscosity(
        key=key,
        name=entry["name"],
        a=fit.a,
        b=fit.b,
        c=c_cst,
        provenance=(("a", src), ("b", src), ("c", c_src)),
    )


@functools.cache
def bearing(key: str) -> BallBearing:
    """The :class:`BallBearing` ``key`` (e.g. "71803", "71807C") from ``data/bearings.toml``.

    Either the groove diameters are given (the ball diameter is derived with
    :func:`geometry.ball_diameter_from_grooves`), or the pitch and ball diameters (the groove
    diameters are derived so that the free contact angle equals ``contact_angle``).
    """
    entry = _lookup("bearings", key)
    v, prov = {}, {}
    for field, spec in entry.items():
        if isinstance(spec, dict):
            v[field], prov[field] = quantity(spec, field)
    f_i, f_o, alpha0 = v["inner_curvature"], v["outer_curvature"], v["contact_angle"]
    if "inner_groove_diameter" in v:
        v["ball_diameter"] = ball_diameter_from_grooves(
            v["inner_groove_diameter"], v["outer_groove_diameter"], f_i, f_o, alpha0
        )
        prov["ball_diameter"] = "derived: from the groove diameters and the free contact angle"
    else:
        dw, dm = v["ball_diameter"], v["pitch_diameter"]
        clearance = 2.0 * (f_i + f_o - 1.0) * dw * (1.0 - math.cos(alpha0))
        v["inner_groove_diameter"] = dm - dw - 0.5 * clearance
        v["outer_groove_diameter"] = dm + dw + 0.5 * clearance
        for g in ("inner_groove_diameter", "outer_groove_diameter"):
            prov[g] = "derived: from pitch and ball diameters and the free contact angle"
    result = BallBearing(
        key=key,
        name=entry["name"],
        bore=v["bore"],
        outer_diameter=v["outer_diameter"],
        width=v["width"],
        n_balls=round(v["n_balls"]),
        ball_diameter=v["ball_diameter"],
        inner_groove_diameter=v["inner_groove_diameter"],
        outer_groove_diameter=v["outer_groove_diameter"],
        inner_curvature=f_i,
        outer_curvature=f_o,
        ring_material=material(entry["ring_material"]),
        ball_material=material(entry["ball_material"]),
        provenance=tuple(sorted(prov.items())),
    )
    check = free_contact_angle(result.clearance, result.curvature_distance)
    if abs(check - alpha0) > 1e-9:  # pragma: no cover - guards the derivation above
        raise ValueError(f"bearing {key!r}: derived geometry gives α0 = {check} rad, not {alpha0}")
    return result


def mounting_entry(key: str) -> dict:
    """The raw data of mounting ``key`` (``data/mountings.toml``), with ``base`` resolved:
    an entry may name a ``base`` entry and override some of its fields."""
    entry = dict(_lookup("mountings", key))
    if "base" in entry:
        base = mounting_entry(entry.pop("base"))
        base.update(entry)
        entry = base
    return entry


@functools.cache
def mounting(key: str):
    """The :class:`bearing.Mounting` ``key`` from ``data/mountings.toml``."""
    from .bearing import Mounting
    from .fits import RadialFit
    from .preload import LoopMember, PreloadLoop

    entry = mounting_entry(key)
    prov = {}

    def q(field):
        value, prov[field] = quantity(entry[field], field)
        return value

    fit = RadialFit(
        housing_material=material(entry["housing_material"]),
        housing_outer_diameter=q("housing_outer_diameter"),
        outer_interference=q("outer_interference"),
        shaft_material=material(entry["shaft_material"]),
        shaft_bore=q("shaft_bore"),
        inner_interference=q("inner_interference"),
    )
    members = []
    for i, m in enumerate(entry["loop"]):
        length, prov[f"loop.{m['name']}.length"] = quantity(m["length"], f"loop[{i}].length")
        area = None
        if "area" in m:
            area, prov[f"loop.{m['name']}.area"] = quantity(m["area"], f"loop[{i}].area")
        members.append(LoopMember(m["name"], m["role"], length, material(m["material"]), area))
    shim = q("shim") if "shim" in entry else 0.0
    stiffness = q("loop_stiffness") if "loop_stiffness" in entry else None
    loop = PreloadLoop(tuple(members), shim=shim, stiffness=stiffness)
    return Mounting(
        key=key,
        name=entry["name"],
        bearing_key=entry["bearing"],
        assembly_temperature=q("assembly_temperature"),
        fit=fit,
        loop=loop,
        assembly_preload=q("assembly_preload") if "assembly_preload" in entry else None,
        provenance=tuple(sorted(prov.items())),
    )


@functools.cache
def actuator(key: str, **overrides):
    """The :class:`actuator.Actuator` ``key`` from ``data/actuators.toml``, with the
    reflected stiffnesses of the data turned into intrinsic ones at the reference angle.
    ``overrides`` (SI) replace data values before that conversion (used by the calibration)."""
    import dataclasses

    from .actuator import Actuator, kinematics

    entry = _lookup("actuators", key)
    v, prov = {}, {}
    for field, spec in entry.items():
        if isinstance(spec, dict):
            v[field], prov[field] = quantity(spec, field)
    reflected = {
        "gear_stiffness": v.pop("gear_stiffness_reflected"),
        "screw_stiffness": v.pop("screw_stiffness_reflected"),
        "housing_stiffness": v.pop("housing_stiffness_reflected"),
    }
    ref_angle = v.pop("reference_angle")
    for field, value in overrides.items():
        if field not in v:
            raise ValueError(f"actuator override {field!r} is not one of {sorted(v)}")
        v[field] = value
        prov[field] = "override"
    act = Actuator(
        key=key,
        name=entry["name"],
        support_mounting=entry.get("support_mounting", ""),
        gear_stiffness=1.0,
        screw_stiffness=1.0,
        housing_stiffness=1.0,
        **v,
    )
    lever2 = float(kinematics(act, ref_angle).lever) ** 2
    screw_rev = (2.0 * math.pi / act.screw_lead) ** 2
    intrinsic = {
        "gear_stiffness": reflected["gear_stiffness"] / (screw_rev * lever2),
        "screw_stiffness": reflected["screw_stiffness"] / lever2,
        "housing_stiffness": reflected["housing_stiffness"] / lever2,
    }
    for f in intrinsic:
        prov[f] = "derived: " + prov.pop(f"{f}_reflected") + ", through the kinematics"
    prov.pop("reference_angle", None)
    return dataclasses.replace(act, **intrinsic, provenance=tuple(sorted(prov.items())))


@functools.cache
def coefficients(key: str):
    """The :class:`friction.FrictionCoefficients` of mounting ``key`` from
    ``data/coefficients.toml``."""
    from .friction import FrictionCoefficients

    entry = _lookup("coefficients", key)
    values, prov = {}, []
    for field, spec in entry.items():
        values[field], src = quantity(spec, field)
        prov.append((field, src))
    return FrictionCoefficients(**values, provenance=tuple(prov))


def tolerances(key: str) -> dict[str, tuple[float, float, str]]:
    """Tolerance bands of mounting ``key`` from ``data/tolerances.toml``: {dimension: (low,
    high, provenance)}, deviations from nominal in SI."""
    out = {}
    for field, spec in _lookup("tolerances", key).items():
        try:
            low, high = float(spec["low"]), float(spec["high"])
            entry = {"value": 0.0, **{k: spec[k] for k in ("unit", "kind", "ref")}}
        except (KeyError, TypeError, ValueError):
            raise ValueError(f"{field} = {spec!r} must be {{low, high, unit, kind, ref}}") from None
        _, source = quantity(entry, field)
        if not high >= low:
            raise ValueError(f"{field}: high = {high!r} must be ≥ low = {low!r}")
        out[field] = (to_si(low, spec["unit"]), to_si(high, spec["unit"]), source)
    return out


TABLES = (
    "materials",
    "lubricants",
    "bearings",
    "mountings",
    "actuators",
    "coefficients",
    "tolerances",
)


def preload() -> None:
    """Read every data table now (they are cached): see :func:`servofmu.physics.load_all`."""
    for name in TABLES:
        _table(name)

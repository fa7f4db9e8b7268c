"""Catalogue entries as presets of the parameter set: :func:`default_parameters` turns a
catalogue mounting (with its bearing, lubricant and coefficients; ``data/*.toml`` or a user
catalogue) into the numbers of :mod:`.parameters.table`, with each value's provenance
(:func:`default_sources`); :func:`resolve` applies presets, then numbers, to a parameter set.

A mounting whose loop the parameter set cannot express (two members of one kind, a member of
another material than its part's, an arm of another material than the housing) raises a
ValueError naming the mounting, the member and the field.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass

from ..physics.contact.geometry import BallBearing
from ..physics.friction.grease import lubricant_term
from ..physics.friction.models import SKF_SOURCES, FrictionModel, lubricant_numbers
from ..physics.friction.models import preset as friction_preset
from ..physics.friction.terms import FrictionCoefficients
from ..physics.kernels.units import CST, RPM
from ..physics.lubrication.viscosity import T40, T100, VogelViscosity
from ..physics.materials import Material
from ..physics.pair.configuration import PRESSURE_LIMIT
from ..physics.pair.mounting import Mounting
from ..physics.pair.preload import TANDEM, LoopMember, member_kind
from . import catalog
from .table import LUBRICANT_FIELDS, PARAMETER_NAMES, SKF_SERIES_FIELDS

#: Catalogue mounting whose values are the defaults (Yu 2017's seeker gimbal).
DEFAULT_MOUNTING = "yu2017_gimbal"
#: Catalogue lubricant for each lubrication when none is named.
DEFAULT_LUBRICANT = {"grease": "krytox_143aa", "solid": "mos2_film"}
#: The preset kinds a change of :func:`resolve` may name.
PRESETS = ("mounting", "bearing", "lubricant")


def _source(record, field: str, fallback: str) -> str:
    return record.source(field) or fallback


def _material_values(prefix: str, mat: Material, poisson: bool = True) -> tuple[dict, dict]:
    fields = ("youngs_modulus", "poisson_ratio", "expansion") if poisson else (
        "youngs_modulus", "expansion")  # fmt: skip
    values = {f"{prefix}_{f}": float(getattr(mat, f)) for f in fields}
    sources = {
        f"{prefix}_{f}": f"{_source(mat, f, 'catalogue: data/materials.toml')} ({mat.key})"
        for f in fields
    }
    return values, sources


def bearing_values(b: BallBearing) -> tuple[dict, dict]:
    """(values, sources) of the bearing numbers of :data:`BEARING_FIELDS` for a
    :class:`BallBearing` (a catalogue bearing: a preset), and the SKF constants of its series
    (:data:`SKF_SERIES_FIELDS`; the SKF model's ``series_constants``, a labelled fallback when
    the series is not in the table).

    Returns
    -------
    tuple of dict
        (values in SI: m, rad, counts, dimensionless constants; sources: str per name).

    Examples
    --------
    >>> values, sources = bearing_values(catalog.bearing("71803"))
    >>> values["n_balls"], sources["bore"], sources["skf_r1"][:18]
    (15, 'paper: Yu 2017 §2', 'fallback (assumed)')
    """
    geometry = ("bore", "outer_diameter", "width", "ball_diameter", "pitch_diameter",
                "nominal_contact_angle", "inner_curvature", "outer_curvature")  # fmt: skip
    values = {f: float(getattr(b, f)) for f in geometry} | {"n_balls": int(b.n_balls)}
    where = f"catalogue: bearing {b.key}"
    sources = {f: _source(b, f, where) for f in values}
    for prefix, mat in (("ring", b.ring_material), ("ball", b.ball_material)):
        v, s = _material_values(prefix, mat)
        values |= v
        sources |= {k: (b.source(f"{prefix}_material") or src) for k, src in s.items()}
    skf = friction_preset(b).skf
    for name in SKF_SERIES_FIELDS:
        field = name.removeprefix("skf_")
        values[name] = float(getattr(skf, field))
        sources[name] = f"{skf.source(field)} (bearing {b.key})"
    return values, sources


def lubricant_values(key: str) -> tuple[dict, dict]:
    """(values, sources) of :data:`LUBRICANT_FIELDS` for catalogue lubricant ``key``: a fluid
    gives its ν40, ν100, Walther c, the range of its data and (when its model is Vogel's law)
    a third viscosity with lubrication "grease" (:func:`viscosity_values`); a dry film gives
    lubrication "solid" and leaves the viscosity numbers out (they are not used).

    Returns
    -------
    tuple of dict
        (values: ν40, ν100, c, cold viscosity [m²/s], temperatures [K], density [kg/m³],
        lubrication; sources: str per name).

    Examples
    --------
    >>> values, _ = lubricant_values("iso_vg32")
    >>> round(values["lubricant_viscosity_40"] * 1e6, 6)  # cSt
    32.0
    """
    rec = catalog.lubricant_record(key)
    if rec.viscosity is None:
        return {"lubrication": "solid"}, {"lubrication": f"catalogue: lubricant {key} (dry film)"}
    (film, film_src), (density, density_src) = lubricant_numbers(rec)
    values, sources = viscosity_values(rec)
    values |= {
        "lubrication": "grease",
        "lubricant_density": density,
        "skf_film_friction": film,
    }
    sources |= {
        "lubrication": f"catalogue: lubricant {key} ({rec.lubricant_type})",
        "lubricant_density": density_src,
        "skf_film_friction": film_src,
    }
    grease, grease_src = grease_values(key)
    return values | grease, sources | grease_src


def grease_values(key: str) -> tuple[dict, dict]:
    """(values, sources) of the grease term of catalogue lubricant ``key``: calibrated on its
    published low-temperature torques (:func:`.friction.grease.lubricant_term`: f0 and the cold
    start ks), else none (f0 = ks = 0: no starting data, ``breakaway_lower_bound``).

    Returns
    -------
    tuple of dict
        (values: f0 [-], ks [-], test speed [rad/s]; sources).

    Examples
    --------
    >>> v, s = grease_values("krytox_143aa")
    >>> v["grease_starting_ratio"], s["grease_starting_ratio"][:30]
    (0.0, 'none: no published starting to')
    >>> round(grease_values("molykote_g1074")[0]["grease_starting_ratio"], 2)
    1.98
    """
    term = lubricant_term(key)
    if term is None:
        none = f"none: no published starting torque of {key} (grease_torques.toml)"
        values = {"grease_f0": 0.0, "grease_starting_ratio": 0.0, "grease_reference_speed": RPM}
        sources = {
            "grease_f0": f"{none}: no grease term",
            "grease_starting_ratio": f"{none}: the breakaway is a lower bound",
            "grease_reference_speed": "not used: the 1 r/min of ASTM D1478 and JIS K 2220",
        }
        return values, sources
    prov = dict(term.provenance)
    return (
        {
            "grease_f0": term.f0,
            "grease_starting_ratio": term.starting_ratio,
            "grease_reference_speed": term.reference_speed,
        },
        {
            "grease_f0": prov["f0"],
            "grease_starting_ratio": prov["starting_ratio"],
            "grease_reference_speed": prov["reference_speed"],
        },
    )


def viscosity_values(rec) -> tuple[dict, dict]:
    """(values, sources) of the viscosity parameters (ν40, ν100, Walther c, the cold point and
    the range) that make :func:`.lubrication.viscosity.viscosity_model` the model of lubricant
    record ``rec``: its published ν40/ν100 (and, for Vogel's law through three points, its third
    point) when the model passes through them, else three points of its fitted curve (Vogel's
    law fitted to more than three points: the same law through three of its points).

    Returns
    -------
    tuple of dict
        (values [m²/s, K], sources).

    Examples
    --------
    >>> v, s = viscosity_values(catalog.lubricant_record("pennzane_2000"))
    >>> round(v["lubricant_viscosity_cold"] * 1e6), round(v["lubricant_cold_temperature"], 2)
    (80500, 233.15)
    """
    model, key = rec.viscosity, rec.key
    values = {
        "lubricant_viscosity_40": float(rec.viscosity_40),
        "lubricant_viscosity_100": float(rec.viscosity_100),
        "lubricant_minimum_temperature": float(model.flow_limit),
        "lubricant_maximum_temperature": float(model.upper_limit),
        # the record's data end; its viscosity points give theirs themselves (0)
        "lubricant_data_minimum_temperature": float(rec.data_minimum_temperature or 0.0),
    }
    sources = {
        "lubricant_viscosity_40": f"{rec.source('viscosity_40')} ({key})",
        "lubricant_viscosity_100": f"{rec.source('viscosity_100')} ({key})",
        "lubricant_minimum_temperature": f"{model.source('flow_limit')} ({key})",
        "lubricant_maximum_temperature": f"{model.source('upper_limit')} ({key})",
        "lubricant_data_minimum_temperature": (
            f"{rec.source('data_minimum_temperature')} ({key})"
            if rec.data_minimum_temperature
            else f"none: its data end at its coldest viscosity point ({key})"
        ),
    }
    if not isinstance(model, VogelViscosity):
        values |= {
            "lubricant_walther_c": walther_c_si(model.c),
            "lubricant_viscosity_cold": 0.0,
            "lubricant_cold_temperature": 0.0,
        }
        sources |= {
            "lubricant_walther_c": f"{model.source('c')} ({key})",
            "lubricant_viscosity_cold": f"none: two viscosities known ({key})",
            "lubricant_cold_temperature": f"none: two viscosities known ({key})",
        }
        return values, sources
    t_cold, nu_cold = min(p for p in model.points if p[0] not in (T40, T100))
    values |= {
        "lubricant_walther_c": walther_c_si(0.7),
        "lubricant_viscosity_cold": float(nu_cold),
        "lubricant_cold_temperature": float(t_cold),
    }
    cold_src = f"{rec.source('viscosity_points[0]')} ({key})"
    sources |= {
        "lubricant_walther_c": "not used (a cold point: Vogel's law): ASTM D341's 0.7 cSt",
        "lubricant_viscosity_cold": cold_src,
        "lubricant_cold_temperature": cold_src,
    }
    temps = {t for t, _ in model.points}
    if len(model.points) > 3 or not {T40, T100} <= temps:  # three points of the fitted law
        fitted = f"derived: Vogel's law fitted to the {len(model.points)} points of {key}, at "
        for name, t in (("lubricant_viscosity_40", T40), ("lubricant_viscosity_100", T100),
                        ("lubricant_viscosity_cold", t_cold)):  # fmt: skip
            values[name] = float(model.kinematic_viscosity(t))
            sources[name] = f"{fitted}{t:g} K"
    return values, sources


def walther_c_si(c_cst: float) -> float:
    """Walther's c [cSt] in m²/s, chosen among the neighbours of c·1e-6 so that dividing it by
    1 cSt gives ``c_cst`` back exactly (the FMU parameter reproduces the catalogue's model bit
    for bit).

    Returns
    -------
    float
        c [m²/s].

    Examples
    --------
    >>> walther_c_si(0.932) / CST == 0.932
    True
    """
    x = c_cst * CST
    for candidate in (x, math.nextafter(x, math.inf), math.nextafter(x, -math.inf)):
        if candidate / CST == c_cst:
            return candidate
    return x


def _same(a: Material, b: Material) -> bool:
    return all(
        getattr(a, f) == getattr(b, f) for f in ("youngs_modulus", "poisson_ratio", "expansion")
    )


def _members(m: Mounting, bearing: BallBearing) -> tuple[dict, str]:
    """{kind: member} of a mounting's loop and its reading ("stated" or "printed"); a loop
    the parameter set cannot express raises ValueError naming the member and the field."""
    where = f"mounting {m.key!r}"
    kinds: dict[str, LoopMember] = {}
    for mem in m.loop.members:
        kind = member_kind(mem.name)
        if kind in kinds:
            raise ValueError(f"{where}: a second loop member of kind {kind!r} ({mem.name!r})")
        part = {"housing": "housing", "shaft": "shaft", "spacer": "shaft", "bearings": "rings"}
        if mem.part != part[kind]:
            raise ValueError(
                f"{where}: loop member {mem.name!r} part = {mem.part!r}: the parameter set "
                f"takes a {kind} member at the {part[kind]} temperature"
            )
        kinds[kind] = mem
    fit = m.fit
    housing, shaft = kinds.get("housing"), kinds.get("shaft")
    printed = (
        "bearings" not in kinds
        and housing is not None
        and shaft is not None
        and not _same(fit.housing_material, fit.shaft_material)
        and _same(housing.material, fit.shaft_material)
        and _same(shaft.material, fit.housing_material)
    )
    expect = {"housing": fit.housing_material, "shaft": fit.shaft_material}
    if printed:
        expect = {"housing": fit.shaft_material, "shaft": fit.housing_material}
    expect["bearings"] = bearing.ring_material
    for kind, mat in expect.items():
        mem = kinds.get(kind)
        if mem is not None and not _same(mem.material, mat):
            raise ValueError(
                f"{where}: loop member {mem.name!r} material = {mem.material.key!r} differs "
                f"from {mat.key!r}: the parameter set takes it from the "
                f"{'rings' if kind == 'bearings' else kind} material"
            )
    if "bearings" in kinds:
        ring_stack = kinds["bearings"]
        if abs(ring_stack.length - 2.0 * bearing.width) > 1e-12 or ring_stack.area:
            raise ValueError(
                f"{where}: loop member 'bearings' length = {ring_stack.length!r} m must be "
                f"2·width = {2.0 * bearing.width!r} m of bearing {bearing.key!r}, without area"
            )
    elif not printed and m.arrangement != TANDEM:  # a tandem pair's rings cancel
        raise ValueError(f"{where}: the loop lacks the member 'bearings' (the rings' widths)")
    return kinds, "printed" if printed else "stated"


def _loop_values(m: Mounting, bearing: BallBearing, defaults: dict) -> tuple[dict, dict]:
    """The loop numbers of mounting ``m``; arm and spacer-material numbers it does not use come
    from ``defaults`` (the default mounting's) with a source that says so."""
    kinds, reading = _members(m, bearing)
    where = f"catalogue: {catalog.origin('mountings', m.key)} [{m.key}]"
    values = {"arrangement": m.arrangement, "loop_reading": reading, "loop_model": m.loop.model}
    sources = {
        "arrangement": f"{where}: arrangement (the roles of its loop members)",
        "loop_reading": f"{where}: the materials of its loop members",
        "loop_model": f"{where}: loop_model",
    }
    for kind in ("housing", "shaft", "spacer"):
        mem = kinds.get(kind)
        values[f"{kind}_length"] = mem.length if mem else 0.0
        values[f"{kind}_area"] = (mem.area or 0.0) if mem else 0.0
        for f in ("length", "area"):
            src = m.source(f"loop.{mem.name}.{f}") if mem else ""
            sources[f"{kind}_{f}"] = src or f"{where}: no {kind} {f} (0: none)"
    if "spacer" in kinds:
        v, s = _material_values("spacer", kinds["spacer"].material, poisson=False)
    else:
        v, s = _material_values("spacer", bearing.ring_material, poisson=False)
        s = {k: f"not used (no spacer): the ring material's value, {src}" for k, src in s.items()}
    values |= v
    sources |= s
    arms = m.loop.arms
    if len(arms) > 1:
        raise ValueError(f"mounting {m.key!r}: the parameter set takes one kind of yoke arm")
    if arms and not _same(arms[0].material, m.fit.housing_material):
        raise ValueError(
            f"mounting {m.key!r}: arm material = {arms[0].material.key!r} differs from the "
            f"housing material {m.fit.housing_material.key!r}"
        )
    for f in ("count", "length", "width", "thickness"):
        name = f"arm_{f}"
        if arms:
            values[name] = getattr(arms[0], f)
            sources[name] = m.source(f"arms.{arms[0].name}.{f}") or f"{where}: arms"
        else:
            values[name] = defaults[name]
            sources[name] = f"not used (no yoke): the default mounting's value ({DEFAULT_MOUNTING})"
    values["loop_stiffness"] = m.loop.stiffness or 0.0
    sources["loop_stiffness"] = m.source("loop_stiffness") or (
        "derived: 0 = from the loop members (Σ L/(E·A)) or the yoke arms"
    )
    return values, sources


def _preload_values(m: Mounting) -> tuple[dict, dict]:
    where = f"catalogue: {catalog.origin('mountings', m.key)} [{m.key}]"
    method, loop = m.preload_method, m.loop
    spring = method == "spring"
    values = {
        "preload_method": method,
        "shim": loop.shim,
        "assembly_preload": m.assembly_preload if method == "force" else 0.0,
        "spring_stiffness": loop.spring_stiffness if spring else 0.0,
        "spring_compression": loop.spring_compression if spring else 0.0,
    }
    unused = f"not used (preload_method = {method})"
    sources = {
        "preload_method": f"{where}: preload by {method}",
        "shim": m.source("shim") or f"{where}: no shim (0)",
        "assembly_preload": m.source("assembly_preload") if method == "force" else unused,
        "spring_stiffness": m.source("spring_stiffness") if spring else unused,
        "spring_compression": m.source("spring_compression") if spring else unused,
    }
    if method != "shim" and not m.source("shim"):
        sources["shim"] = f"{unused}: 0"
    return values, sources


def _fit_values(m: Mounting) -> tuple[dict, dict]:
    fit = m.fit
    fields = ("housing_outer_diameter", "outer_interference", "shaft_bore", "inner_interference")
    values = {f: float(getattr(fit, f)) for f in fields}
    values["assembly_temperature"] = float(m.assembly_temperature)
    sources = {f: m.source(f) for f in values}
    for prefix, mat in (("housing", fit.housing_material), ("shaft", fit.shaft_material)):
        v, s = _material_values(prefix, mat)
        values |= v
        sources |= s
    return values, sources


@dataclass(frozen=True)
class Preset:
    """A full parameter set made from catalogue entries, with each value's provenance."""

    values: Mapping[str, object]
    sources: Mapping[str, str]


def _preset(mounting: str, lubrication: str | None, bearing: str | None,
            lubricant: str | None) -> Preset:  # fmt: skip
    return _cached_preset(catalog.generation(), mounting, lubrication, bearing, lubricant)


@functools.lru_cache(maxsize=128)
def _cached_preset(_generation: int, mounting: str, lubrication: str | None,
                   bearing: str | None, lubricant: str | None) -> Preset:  # fmt: skip
    mnt = catalog.mounting(mounting)
    bear = catalog.bearing(bearing or mnt.bearing_key)
    defaults = {} if mounting == DEFAULT_MOUNTING else _preset(DEFAULT_MOUNTING, None, None, None)
    values, sources = {}, {}
    parts = [
        bearing_values(bear),
        _fit_values(mnt),
        _loop_values(mnt, catalog.bearing(mnt.bearing_key), getattr(defaults, "values", {})),
        _preload_values(mnt),
    ]
    if lubrication not in (None, *DEFAULT_LUBRICANT):
        raise ValueError(f"lubrication = {lubrication!r} is not one of {sorted(DEFAULT_LUBRICANT)}")
    own = catalog.mounting_entry(mounting).get("lubricant", DEFAULT_LUBRICANT["grease"])
    lub_key = lubricant or (DEFAULT_LUBRICANT[lubrication] if lubrication else own)
    lub_values, lub_sources = lubricant_values(lub_key)
    if lubrication is not None and lub_values["lubrication"] != lubrication:
        raise ValueError(
            f"lubricant = {lub_key!r} is a {lub_values['lubrication']} lubricant, not for "
            f"lubrication = {lubrication!r}"
        )
    if lub_values["lubrication"] == "solid":  # the viscosity numbers stay the grease default's
        grease, grease_src = lubricant_values(DEFAULT_LUBRICANT["grease"])
        for f in LUBRICANT_FIELDS[1:]:
            lub_values[f] = grease[f]
            lub_sources[f] = f"not used (solid lubrication): {grease_src[f]}"
    parts.append((lub_values, lub_sources))
    parts.append(_coefficient_values(mounting, lub_values["lubrication"] == "solid"))
    calibrated = catalog.calibrated_loop_stiffness(mounting)
    if calibrated is not None:  # a user's calibration fitted the loop's stiffness
        parts.append(({"loop_stiffness": calibrated[0]}, {"loop_stiffness": calibrated[1]}))
    for v, s in parts:
        values |= v
        sources |= s
    return Preset(values, sources)


@dataclass(frozen=True)
class CoefficientSet:
    """What a mounting's friction coefficients (α_r, μ, μ_s/μ, s0 of the default friction
    model) are.

    Attributes
    ----------
    key : the coefficient set's key (``data/coefficients.toml`` or a user catalogue), or None
        for the library's defaults
    kind : "calibrated" (some fitted on measurements), "assumed" (a catalogue set, none
        fitted) or "uncalibrated" (the library's defaults: no set for the mounting)
    label : one line for reports, plots and documentation
    """

    key: str | None
    kind: str
    label: str

    @property
    def calibrated(self) -> bool:
        """Whether any coefficient of the set was fitted on measurements."""
        return self.kind == "calibrated"


def coefficient_set(mounting: str) -> CoefficientSet:
    """The friction coefficients mounting ``mounting`` takes, said plainly: the Yu-calibrated
    set, a user's calibration (``servofmu calibrate``), a catalogue set of assumed values, or
    the library's uncalibrated defaults (a new bearing until it is calibrated). The other
    friction models (:mod:`~servofmu.physics.friction.registry`) use literature constants
    besides.

    Returns
    -------
    CoefficientSet

    Examples
    --------
    >>> label = coefficient_set("yu2017_gimbal_spring").label
    >>> label.split(":")[0], "palmgren_s0 fitted on Yu 2017's −40 °C torques" in label
    ('Yu-calibrated', True)
    >>> coefficient_set("liu2014_screw_support").kind
    'uncalibrated'
    """
    name = catalog.coefficient_set_name(mounting)
    if name is None:
        d = FrictionCoefficients()
        return CoefficientSet(
            None,
            "uncalibrated",
            f"uncalibrated: the library's defaults (α_r {d.hysteresis_loss:g}, μ "
            f"{d.sliding_friction:g}, μ_s/μ {d.static_friction_ratio:g}, s0 "
            f"{d.palmgren_s0:g}); torques are estimates until calibrated (servofmu calibrate)",
        )
    coef = catalog.coefficients(name)
    fitted = [
        f for f, src in coef.provenance if src.startswith("calibrated") and f != "loop_stiffness"
    ]
    fitted += ["loop_stiffness"] if catalog.calibrated_loop_stiffness(mounting) else []
    where = catalog.origin("coefficients", name)
    if not fitted:
        return CoefficientSet(
            name, "assumed", f"assumed: set {name} ({where}), none fitted on measurements"
        )
    if where.startswith("data/"):  # the package's sets: Yu's is its only calibrated one
        on = " on Yu 2017's −40 °C torques" if name == DEFAULT_MOUNTING else ""
        return CoefficientSet(
            name,
            "calibrated",
            f"{'Yu-' if on else ''}calibrated: {', '.join(fitted)} fitted{on}, the others "
            f"assumed (set {name}, {where})",
        )
    record = catalog.calibration_record(name)
    data = f" on {record['data']}" if "data" in record else ""
    return CoefficientSet(
        name,
        "calibrated",
        f"calibrated by the user (set {name}, {where}){data}: {', '.join(fitted)} fitted",
    )


def _coefficient_values(mounting: str, solid: bool) -> tuple[dict, dict]:
    coef = catalog.mounting_coefficients(mounting) or FrictionCoefficients()
    fields = ("hysteresis_loss", "sliding_friction", "static_friction_ratio", "palmgren_s0")
    values = {f: float(getattr(coef, f)) for f in fields}
    default = "assumed: uncalibrated library default (physics.friction.FrictionCoefficients)"
    sources = {f: coef.source(f) or default for f in fields}
    if solid:
        values["palmgren_s0"] = 0.0
        sources["palmgren_s0"] = "assumed: dry film, no viscous torque"
    values |= {"regularisation_speed": 1.0e-3, "stribeck_speed": 1.0e-2}
    values["pressure_limit"] = PRESSURE_LIMIT
    sources |= {
        "regularisation_speed": "assumed",
        "stribeck_speed": "assumed",
        "pressure_limit": "handbook: ISO 76, 4200 MPa for ball bearings",
    }
    fm = FrictionModel()  # the catalogue's SKF coefficients (μbl, Krs)
    values |= {
        "friction_model": fm.model,  # the registry's first: the default
        "skf_replenishment": fm.skf_replenishment,
        "skf_boundary_friction": fm.skf_boundary_friction,
        "lubricant_below_flow_limit": "hold",
    }
    sources |= {
        "friction_model": "assumed: Yu 2017's model, the default for the paper reproductions",
        **SKF_SOURCES,
        "lubricant_below_flow_limit": "assumed: hold the viscosity at the flow limit (finite "
        "torques; outside_lubricant_range says they are not backed by data)",
    }
    return values, sources


def default_parameters(
    mounting: str = DEFAULT_MOUNTING,
    lubrication: str | None = None,
    *,
    bearing: str | None = None,
    lubricant: str | None = None,
) -> dict[str, object]:
    """The parameter set of catalogue mounting ``mounting`` (``data/mountings.toml``, or a
    user catalogue): its bearing (or catalogue bearing ``bearing``), seats, loop and preload, its
    friction coefficients (``data/coefficients.toml``; the library defaults when it has none),
    and the lubricant ``lubricant`` (default: the catalogue default of ``lubrication`` when
    given, else the mounting's own ``lubricant``, else Krytox 143AA). SI values, choices as
    keys.

    Parameters
    ----------
    mounting, bearing, lubricant : catalogue keys (presets)
    lubrication : "grease" or "solid" (default: the lubricant's kind)

    Returns
    -------
    dict
        ``{name: value}`` for every name of :data:`PARAMETER_NAMES` (m, K, N, N/m, Pa, 1/K,
        m²/s; choices as keys).

    Examples
    --------
    >>> p = default_parameters("yu2017_gimbal")
    >>> p["shim"], p["n_balls"], p["arrangement"], p["preload_method"]
    (3e-05, 15, 'face_to_face', 'shim')
    """
    return dict(_preset(mounting, lubrication, bearing, lubricant).values)


def default_sources(
    mounting: str = DEFAULT_MOUNTING,
    lubrication: str | None = None,
    *,
    bearing: str | None = None,
    lubricant: str | None = None,
) -> dict[str, str]:
    """Provenance of each value of :func:`default_parameters` (same arguments), read from the
    catalogue records ("kind: reference (record)").

    Returns
    -------
    dict
        Parameter name → provenance string.

    Examples
    --------
    >>> default_sources("yu2017_gimbal")["shim"].startswith("paper: Yu 2017")
    True
    """
    return dict(_preset(mounting, lubrication, bearing, lubricant).sources)


def resolve(base: Mapping[str, object], changes: Mapping[str, object]) -> dict[str, object]:
    """``base`` (a full parameter set) with ``changes``: the presets a change names first —
    ``mounting`` (that mounting's whole set, with base's lubrication unless a lubricant is
    named), then ``bearing`` (its :data:`BEARING_FIELDS`), then ``lubricant`` (its
    :data:`LUBRICANT_FIELDS`) — and then every number and choice named, which win over the
    presets. The library's way of saying "this catalogue entry, but with …" (sweeps,
    calibration); an FMU has numbers only.

    Returns
    -------
    dict
        The full parameter set (SI numbers, choices as item names).

    Examples
    --------
    >>> base = default_parameters()
    >>> p = resolve(base, {"bearing": "7002C", "width": 0.01})
    >>> p["bore"], p["width"], p["shim"] == base["shim"]
    (0.015, 0.01, True)
    """
    params = dict(base)
    mounting, bearing, lubricant = (changes.get(k) for k in PRESETS)
    if mounting is not None:
        params = default_parameters(str(mounting), None if lubricant else base["lubrication"])
    if bearing is not None:
        values, _ = bearing_values(catalog.bearing(str(bearing)))
        params |= values
    if lubricant is not None:
        values, _ = lubricant_values(str(lubricant))
        params |= values
        if values["lubrication"] == "solid" and "palmgren_s0" not in changes:
            params["palmgren_s0"] = 0.0
    unknown = sorted(set(changes) - set(PARAMETER_NAMES) - set(PRESETS))
    if unknown:
        raise ValueError(f"{unknown} are neither parameters nor presets {list(PRESETS)}")
    params |= {k: v for k, v in changes.items() if k not in PRESETS}
    return params

"""Catalogue of records kept as data (``parameters/data/*.toml``) with per-value provenance.

Each numeric entry in the data files is ``{ value, unit, kind, ref }`` where ``kind`` is one of
``paper``, ``catalogue``, ``handbook``, ``assumed``, ``calibrated`` or ``derived``; the loaders
convert to SI and keep ``"kind: ref"`` as the provenance of each field.
"""

from __future__ import annotations

import dataclasses
import functools
import tomllib
from importlib import resources

from ..physics._checks import suggest
from ..physics.contact.geometry import (
    BallBearing,
    BallSetRule,
    ball_diameter_from_grooves,
    clearance_from_group,
    free_contact_angle,
)
from ..physics.kernels.units import MM, UM, to_si
from ..physics.lubrication.lubricant import LubricantRecord, TorqueTest
from ..physics.lubrication.viscosity import (
    T40,
    T100,
    ViscosityRange,
    WaltherViscosity,
    vogel_from_points,
    walther_from_reference,
    walther_from_two_points,
)
from ..physics.materials import Material
from ..physics.pair.mounting import Mounting
from ..physics.pair.preload import LoopMember, PreloadLoop, YokeArm
from ..physics.thermal.fits import RadialFit

PROVENANCE_KINDS = ("paper", "catalogue", "handbook", "assumed", "calibrated", "derived")


@functools.cache
def _package_table(name: str) -> dict:
    with resources.files(__package__).joinpath(f"data/{name}.toml").open("rb") as fh:
        return tomllib.load(fh)


#: Tables a user catalogue may add entries to (``servofmu build --catalog``).
USER_TABLES = ("materials", "lubricants", "bearings", "mountings", "coefficients", "tolerances")
#: User tables keyed by a mounting whose entries take precedence over the package's for that
#: mounting (a user's calibration, a user's tolerance bands), so their keys may exist already.
MOUNTING_TABLES = ("coefficients", "tolerances")
#: Entries added by user catalogues: {table: {key: (entry, file)}}, in the order added.
_USER: dict[str, dict[str, tuple[dict, str]]] = {t: {} for t in USER_TABLES}
_generation = [0]
#: The merged tables (package entries, then the user's), built once per :func:`generation`:
#: a lookup costs O(1), not a copy of the table.
_MERGED: dict[str, dict] = {}


def _table(name: str) -> dict:
    """One data table: the package's ``data/<name>.toml``, then the user catalogues' entries."""
    table = _package_table(name)
    extra = _USER.get(name)
    if not extra:
        return table
    merged = _MERGED.get(name)
    if merged is None:
        merged = _MERGED[name] = {**table, **{key: entry for key, (entry, _) in extra.items()}}
    return merged


def origin(table: str, key: str) -> str:
    """Where entry ``key`` of ``table`` comes from: ``data/<table>.toml`` or a user file.

    Parameters
    ----------
    table : str
        "materials", "lubricants", "bearings" or "mountings".
    key : str
        The entry.

    Returns
    -------
    str
        The file's path.

    Examples
    --------
    >>> origin("bearings", "71803").endswith("data/bearings.toml")
    True
    """
    if key in _USER.get(table, {}):
        return _USER[table][key][1]
    _lookup(table, key)
    return f"data/{table}.toml"


def generation() -> int:
    """A number that changes whenever user catalogues are added or removed (caches of derived
    records key on it).

    Returns
    -------
    int

    Examples
    --------
    >>> isinstance(generation(), int)
    True
    """
    return _generation[0]


def _changed() -> None:
    _generation[0] += 1
    _MERGED.clear()
    for cached in (material, lubricant_record, lubricant, bearing, mounting,
                   mounting_coefficients, calibrated_loop_stiffness):  # fmt: skip
        cached.cache_clear()


def add_entries(tables: dict[str, dict], file: str) -> None:
    """Add user entries ``{table: {key: entry}}`` (tables of :data:`USER_TABLES`, entries in
    the format of the package's data files) read from ``file``. A key that exists already
    raises ValueError naming the file, the table and the key; nothing is added then. Each
    entry is checked when it is loaded (:func:`check_entries`).

    Parameters
    ----------
    tables : dict
        ``{table: {key: entry}}``.
    file : str
        Where they were read (for messages).

    Returns
    -------
    None

    Examples
    --------
    >>> try:
    ...     add_entries({"bearings": {"71803": {"name": "again"}}}, "mine.toml")
    ... except ValueError as e:
    ...     print(e)
    mine.toml: bearings.71803 exists already (in data/bearings.toml): choose another key
    """
    unknown = sorted(set(tables) - set(USER_TABLES))
    if unknown:
        raise ValueError(f"{file}: tables {unknown} are not among {list(USER_TABLES)}")
    for table, entries in tables.items():
        if not isinstance(entries, dict):
            raise ValueError(f"{file}: [{table}] must be a table of entries")
        for key, entry in entries.items():
            taken = key in _USER[table] if table in MOUNTING_TABLES else key in _table(table)
            if taken:
                raise ValueError(
                    f"{file}: {table}.{key} exists already (in {origin(table, key)}): choose "
                    "another key"
                )
            if not isinstance(entry, dict):
                raise ValueError(f"{file}: {table}.{key} must be a table")
    for table, entries in tables.items():
        for key, entry in entries.items():
            _USER[table][key] = (entry, file)
    _changed()


def remove_user_entries() -> None:
    """Forget every user catalogue entry (the package's data stay).

    Returns
    -------
    None

    Examples
    --------
    >>> remove_user_entries()
    >>> "71803" in keys("bearings")  # the package's stay
    True
    """
    for table in _USER.values():
        table.clear()
    _changed()


def check_entries(table: str, keys_: list[str]) -> None:
    """Load each entry ``keys_`` of ``table``; a bad one raises ValueError naming the file,
    the entry and the field.

    Parameters
    ----------
    table : str
        The table.
    keys_ : list of str
        The entries.

    Returns
    -------
    None

    Examples
    --------
    >>> check_entries("bearings", ["71803", "7002C"])
    """
    loader = {"materials": material, "lubricants": lubricant_record, "bearings": bearing,
              "mountings": mounting, "coefficients": _user_coefficients,
              "tolerances": tolerances}[table]  # fmt: skip
    for key in keys_:
        try:
            if table in MOUNTING_TABLES and key not in _table("mountings"):
                raise ValueError(
                    f"{table} are given per mounting, and {key!r} is no mounting"
                    f"{suggest(key, _table('mountings'))}"
                )
            loader(key)
        except (KeyError, ValueError, TypeError) as err:
            msg = f"field {err.args[0]!r} is missing" if isinstance(err, KeyError) else str(err)
            raise ValueError(f"{origin(table, key)}: {table}.{key}: {msg}") from None


def quantity(entry: dict, field: str) -> tuple[float, str]:
    """(SI value, provenance) of one ``{value, unit, kind, ref}`` data entry.

    Parameters
    ----------
    entry : dict
        ``{value, unit, kind, ref}``.
    field : str
        Its field's name (for messages).

    Returns
    -------
    tuple
        (value in SI, "kind: ref").

    Examples
    --------
    >>> e = {"value": 17, "unit": "mm", "kind": "catalogue", "ref": "ISO 15"}
    >>> quantity(e, "bore")  # m
    (0.017, 'catalogue: ISO 15')
    """
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
        raise ValueError(
            f"{table[:-1]} key = {key!r} is not one of {sorted(data)}{suggest(key, data)}"
        )
    return data[key]


def keys(table: str) -> list[str]:
    """Keys of one data table: ``materials``, ``lubricants``, ``bearings`` or ``mountings``.

    Parameters
    ----------
    table : str
        "materials", "lubricants", "bearings" or "mountings".

    Returns
    -------
    list of str

    Examples
    --------
    >>> keys("materials")[:3]
    ['9cr18', 'bearing_steel_yu', 'cast_aluminium']
    """
    return sorted(_table(table))


def titles(table: str) -> dict[str, str]:
    """``{key: name}`` of one data table in the order of its file (entries added at the end
    keep the positions of the others: FMU enumeration values are numbered in this order).

    Returns
    -------
    dict
        key → name.

    >>> list(titles("lubricants"))[:2]
    ['krytox_143aa', 'iso_vg32']
    """
    return {key: entry.get("name", key) for key, entry in _table(table).items()}


#: Thermal properties a material entry may give (heat-transfer models need them).
OPTIONAL_MATERIAL_FIELDS = ("density", "specific_heat", "thermal_conductivity", "emissivity")


@functools.cache
def material(key: str) -> Material:
    """The :class:`Material` ``key`` from ``data/materials.toml``; the thermal properties
    (:data:`OPTIONAL_MATERIAL_FIELDS`) are optional.

    Parameters
    ----------
    key : str
        A key of ``data/materials.toml``.

    Returns
    -------
    Material
        E [Pa], ν [-], α [1/K] (and thermal properties where given).

    Examples
    --------
    >>> m = material("cast_aluminium")
    >>> round(m.youngs_modulus / 1e9, 1), m.expansion  # GPa, 1/K
    (72.0, 2.17e-05)
    """
    entry = _lookup("materials", key)
    values, prov = {}, []
    for field in ("youngs_modulus", "poisson_ratio", "expansion", *OPTIONAL_MATERIAL_FIELDS):
        if field in OPTIONAL_MATERIAL_FIELDS and field not in entry:
            continue
        values[field], src = quantity(entry[field], field)
        prov.append((field, src))
    return Material(key=key, name=entry["name"], provenance=tuple(prov), **values)


def _quantities(entry: dict, owner: str, skip=()) -> tuple[dict, dict]:
    """SI values and provenance of every ``{value, unit, kind, ref}`` field of ``entry``."""
    values, prov = {}, {}
    for field, spec in entry.items():
        if isinstance(spec, dict) and field not in skip:
            values[field], prov[field] = quantity(spec, f"{owner} {field}")
    return values, prov


def _walther(key: str, entry: dict, v: dict, prov: dict) -> WaltherViscosity:
    """The ASTM D341 model of a lubricant entry's two reference viscosities, always as the fit
    through ν40 and ν100 (:func:`viscosity.walther_from_reference`, the FMU's parameters): the
    entry gives ν40/ν100, or a, b (and c), or two points t1/nu1, t2/nu2, from which ν40 and
    ν100 follow first. c defaults to ASTM D341's 0.7 cSt. Without a range (see
    :func:`_viscosity_model`)."""
    if "c" in v:
        c_cst, c_src = v["c"] / to_si(1.0, "cSt"), prov["c"]
    else:
        c_cst, c_src = 0.7, "handbook: ASTM D341 (c = 0.7 cSt)"
    name = entry["name"]
    if "viscosity_40" in v and "viscosity_100" in v:
        nu40, nu100 = v["viscosity_40"], v["viscosity_100"]
        src = f"viscosity_40 ({prov['viscosity_40']}); viscosity_100 ({prov['viscosity_100']})"
    else:
        if "a" in v and "b" in v:
            model = WaltherViscosity(key=key, name=name, a=v["a"], b=v["b"], c=c_cst)
            src = f"Walther a = {v['a']:g} ({prov['a']}), b = {v['b']:g} ({prov['b']})"
        elif all(f in v for f in ("t1", "nu1", "t2", "nu2")):
            model = walther_from_two_points(v["t1"], v["nu1"], v["t2"], v["nu2"], c=c_cst)
            src = "; ".join(f"{f} ({prov[f]})" for f in ("t1", "nu1", "t2", "nu2"))
        else:
            raise ValueError(
                "a walther model needs a and b, viscosity_40 and viscosity_100, or t1, nu1, "
                f"t2, nu2; the entry has {sorted(v)}"
            )
        nu40, nu100 = (float(model.kinematic_viscosity(t)) for t in (T40, T100))
        for field, t_c in (("viscosity_40", 40), ("viscosity_100", 100)):
            prov[field] = f"derived: the entry's Walther model at {t_c} °C ({src})"
    fit = walther_from_reference(nu40, nu100, c=c_cst, key=key, name=name)
    src = f"derived: ASTM D341 fit through ν40 and ν100 ({src})"
    prov_fit = (("a", src), ("b", src), ("c", c_src))
    return WaltherViscosity(key=key, name=name, a=fit.a, b=fit.b, c=c_cst, provenance=prov_fit)


def _reference_points(v: dict, nu: dict) -> list[tuple[float, float]]:
    """The entry's own two reference (T [K], ν [m²/s]) points: t1/nu1, t2/nu2 when it gives
    them, else 40 and 100 °C with ``nu`` (:func:`_reference_viscosities`)."""
    if "viscosity_40" not in v and all(f in v for f in ("t1", "nu1", "t2", "nu2")):
        return [(v["t1"], v["nu1"]), (v["t2"], v["nu2"])]
    return [(T40, nu["viscosity_40"]), (T100, nu["viscosity_100"])]


def _range(v: dict, prov: dict, temperatures) -> tuple[dict, tuple]:
    """The range of a lubricant's data and its flow limit (see :mod:`.lubrication.viscosity`) as
    keyword arguments of a viscosity model, with their sources: ``lower_limit`` = the coldest of its
    viscosity points and its ``data_minimum_temperature`` (the coldest temperature a paper's
    fit was used at); ``upper_limit`` = its ``maximum_temperature``, else its highest
    viscosity point; ``flow_limit`` = its ``pour_point``, else its ``minimum_temperature``
    (the maker's lower operating temperature), else 0 (none published)."""
    low = [(t, "the coldest viscosity point") for t in temperatures]
    if "data_minimum_temperature" in v:
        low.append((v["data_minimum_temperature"],
                    f"data_minimum_temperature ({prov['data_minimum_temperature']})"))  # fmt: skip
    lower, lo_src = min(low)
    if "maximum_temperature" in v:
        upper, hi_src = (
            v["maximum_temperature"],
            f"maximum_temperature ({prov['maximum_temperature']})",
        )
    else:
        upper, hi_src = max(temperatures), "the highest viscosity point"
    flow, flow_src = (
        0.0,
        (
            "assumed: none: no pour point or lower operating temperature published, so the law is "
            "extrapolated at every temperature below its data"
        ),
    )
    for field, what in (("pour_point", "pour point"), ("minimum_temperature", "lower operating "
                        "temperature")):  # fmt: skip
        if field in v:
            flow, flow_src = v[field], f"derived: its {what}, {field} ({prov[field]})"
            break
    limits = {"lower_limit": lower, "upper_limit": upper, "flow_limit": flow}
    sources = (
        ("lower_limit", f"derived: {lo_src}"),
        ("upper_limit", f"derived: {hi_src}"),
        ("flow_limit", flow_src),
    )
    return limits, sources


def _viscosity_model(walther: WaltherViscosity, v: dict, prov: dict, nu: dict, points):
    """The viscosity model of a fluid lubricant entry (:mod:`.lubrication.viscosity`), with its
    range and flow limit: the ASTM D341 model of its reference pair (``walther``, :func:`_walther`)
    when it has no further ``viscosity_points``, else Vogel's law through the reference pair and
    every point (a lubricant's published points are used, not only checked)."""
    ref = _reference_points(v, nu)
    all_points = [*ref, *points]
    limits, range_prov = _range(v, prov, [t for t, _ in all_points])
    if not points:
        return dataclasses.replace(walther, provenance=walther.provenance + range_prov, **limits)
    model = vogel_from_points(all_points, walther.key, walther.name, **limits)
    return dataclasses.replace(model, provenance=model.provenance + range_prov)


def _named(where: str, err: Exception) -> ValueError:
    """``err`` as a ValueError whose message starts with ``where`` (the entry it is about)."""
    msg = err.args[0] if isinstance(err, KeyError) else str(err)
    if isinstance(err, KeyError):
        msg = f"{msg} is missing"
    return ValueError(msg if msg.startswith(where) else f"{where}: {msg}")


def _torque_test(key: str, i: int, spec: dict) -> TorqueTest:
    where = f"lubricant {key!r} low_temperature_torque[{i}]"
    try:
        v, prov = _quantities(spec, where)
        return TorqueTest(
            standard=spec["standard"],
            bearing=spec["bearing"],
            temperature=v["temperature"],
            starting_torque=v.get("starting_torque"),
            running_torque=v.get("running_torque"),
            provenance=tuple(sorted(prov.items())),
        )
    except (KeyError, ValueError) as err:
        raise _named(where, err) from None


def _reference_viscosities(walther: WaltherViscosity, v: dict) -> dict:
    """ν at 40 and 100 °C [m²/s]: the entry's, or its Walther model's (provenance set by
    :func:`_walther`)."""
    return {
        field: v[field] if field in v else float(walther.kinematic_viscosity(t))
        for field, t in (("viscosity_40", T40), ("viscosity_100", T100))
    }


def _viscosity_points(key: str, entry: dict, prov: dict) -> tuple[tuple[float, float], ...]:
    """The entry's further published (T [K], ν [m²/s]) points."""
    points = []
    for i, pt in enumerate(entry.get("viscosity_points", [])):
        pv, pp = _quantities(pt, f"lubricant {key!r} viscosity_points[{i}]")
        points.append((pv["temperature"], pv["viscosity"]))
        prov[f"viscosity_points[{i}]"] = pp["viscosity"]
    return tuple(points)


def lubricant_record_from_entry(key: str, entry: dict) -> LubricantRecord:
    """The :class:`lubricant.LubricantRecord` of one ``data/lubricants.toml``-format entry.

    Parameters
    ----------
    key : the entry's key (named in error messages)
    entry : the entry's table: ``name``, ``model`` ("walther" or "solid"), optional ``type``
        ("oil", "grease", "solid"), ``base_oil``, the viscosity (a, b, c; or viscosity_40 and
        viscosity_100; or t1, nu1, t2, nu2), optional ``viscosity_points``, ``density``,
        ``density_temperature``, ``pour_point`` and ``low_temperature_torque`` tests, every
        number as ``{value, unit, kind, ref}``

    Returns
    -------
    LubricantRecord, SI: viscosities [m²/s], density [kg/m³], temperatures [K], torques [N·m]

    Examples
    --------
    >>> def q(value, unit):
    ...     return {"value": value, "unit": unit, "kind": "assumed", "ref": "example"}
    >>> entry = {"name": "ISO VG 32 oil", "model": "walther",
    ...          "viscosity_40": q(32, "cSt"), "viscosity_100": q(5.4, "cSt")}
    >>> rec = lubricant_record_from_entry("vg32", entry)
    >>> round(float(rec.viscosity.kinematic_viscosity(313.15)) * 1e6, 6)  # cSt at 40 °C
    32.0
    """
    try:
        return _lubricant_record(key, entry)
    except (KeyError, ValueError) as err:
        raise _named(f"lubricant {key!r}", err) from None


def _lubricant_record(key: str, entry: dict) -> LubricantRecord:
    model = entry.get("model")
    if model not in ("walther", "solid"):
        raise ValueError(f"model = {model!r} is not walther or solid")
    v, prov = _quantities(entry, f"lubricant {key!r}")
    solid = model == "solid"
    points = _viscosity_points(key, entry, prov)
    visc, nu = None, {}
    if not solid:
        walther = _walther(key, entry, v, prov)
        nu = _reference_viscosities(walther, v)
        visc = _viscosity_model(walther, v, prov, nu, points)
    torques = tuple(
        _torque_test(key, i, t) for i, t in enumerate(entry.get("low_temperature_torque", []))
    )
    prov.update(dict(visc.provenance) if visc else {})
    return LubricantRecord(
        key=key,
        name=entry["name"],
        lubricant_type=entry.get("type", "solid" if solid else "oil"),
        base_oil=entry.get("base_oil", ""),
        viscosity=visc,
        viscosity_40=nu.get("viscosity_40"),
        viscosity_100=nu.get("viscosity_100"),
        viscosity_points=points,
        density=v.get("density"),
        density_temperature=v.get("density_temperature"),
        pour_point=v.get("pour_point"),
        minimum_temperature=v.get("minimum_temperature"),
        data_minimum_temperature=v.get("data_minimum_temperature"),
        maximum_temperature=v.get("maximum_temperature"),
        oil_class=entry.get("oil_class", ""),
        low_temperature_torque=torques,
        provenance=tuple(sorted(prov.items())),
    )


@functools.cache
def lubricant_record(key: str) -> LubricantRecord:
    """The full record of lubricant ``key`` from ``data/lubricants.toml``: base-oil viscosity at
    40 and 100 °C and its Walther model, density, pour point and the datasheet's
    low-temperature torque tests, every value with its provenance.

    Parameters
    ----------
    key : catalogue key, one of ``keys("lubricants")``

    Returns
    -------
    LubricantRecord, SI: viscosities [m²/s], density [kg/m³], temperatures [K], torques [N·m]

    Examples
    --------
    >>> rec = lubricant_record("pennzane_2000")
    >>> round(rec.viscosity_40 * 1e6, 1), round(rec.pour_point - 273.15, 1)  # cSt, °C
    (107.0, -55.0)
    """
    return lubricant_record_from_entry(key, _lookup("lubricants", key))


@functools.cache
def lubricant(key: str) -> ViscosityRange | None:
    """The viscosity model of lubricant ``key``; ``None`` for a solid (dry-film) lubricant.

    Parameters
    ----------
    key : str
        A key of ``data/lubricants.toml``.

    Returns
    -------
    WaltherViscosity or None

    Examples
    --------
    >>> round(float(lubricant("iso_vg32").kinematic_viscosity(313.15)) * 1e6, 6)  # cSt at 40 °C
    32.0
    >>> lubricant("mos2_film") is None  # a dry film
    True
    """
    return lubricant_record(key).viscosity


@functools.cache
def ball_set_rule() -> BallSetRule:
    """The catalogue's design rule for ball sets that are not published
    (``data/bearing_rules.toml``): coefficients calibrated on the bearings with a published
    ball set, and the rule's stated leave-one-out error on them.

    Returns
    -------
    BallSetRule (dimensionless coefficients and error bounds)

    Examples
    --------
    >>> rule = ball_set_rule()
    >>> dm, dw, z = rule.ball_set(0.015, 0.032)  # 7002: d = 15 mm, D = 32 mm
    >>> round(dw * 1e3, 2), z, rule.calibration_bearings[0]
    (4.86, 9, '71803')
    """
    entry = _table("bearing_rules")["ball_set"]
    v, prov = _quantities(entry, "bearing_rules ball_set")
    return BallSetRule(
        section_ratio=v["section_ratio"],
        fill=v["fill"],
        calibration_bearings=tuple(entry["calibration_bearings"]),
        ball_diameter_error=v["ball_diameter_error"],
        ball_count_error=round(v["ball_count_error"]),
        pitch_diameter_error=v["pitch_diameter_error"],
        provenance=tuple(sorted(prov.items())),
    )


def _apply_ball_set_rule(rule_name: str, v: dict, prov: dict) -> None:
    if rule_name != "ball_set":
        raise ValueError(f"design_rule = {rule_name!r} is not one of ['ball_set']")
    rule = ball_set_rule()
    dm, dw, z = rule.ball_set(v["bore"], v["outer_diameter"])
    why = (
        f"design rule ball_set (data/bearing_rules.toml), coefficients calibrated on "
        f"{', '.join(rule.calibration_bearings)}"
    )
    for field, value, formula, err in (
        ("pitch_diameter", dm, "dm = (d + D)/2", f"±{rule.pitch_diameter_error:.1%}"),
        ("ball_diameter", dw, f"Dw = {rule.section_ratio:g}·(D − d)",
         f"±{rule.ball_diameter_error:.0%}"),
        ("n_balls", z, f"Z = round({rule.fill:g}·π·dm/Dw)", f"±{rule.ball_count_error} ball"),
    ):  # fmt: skip
        if field in v:
            raise ValueError(f"{field} is given and design_rule = 'ball_set' would replace it")
        v[field] = value
        prov[field] = f"derived: {formula}, {why}; leave-one-out error {err}"


def _radial_clearance(entry: dict, v: dict, prov: dict) -> None:
    """Put the mid-point of the entry's ISO 5753-1 clearance group into ``v``."""
    group = entry["radial_clearance_group"]
    if "radial_clearance" in v:
        raise ValueError("give radial_clearance or radial_clearance_group, not both")
    table = _table("bearing_rules")["radial_clearance"]
    low, high = clearance_from_group(v["bore"], group, table["rows"])
    v["radial_clearance"] = 0.5 * (low + high)
    prov["radial_clearance"] = (
        f"assumed: clearance group {group} (the bearing's own group is not published), "
        f"mid-point of its {low / UM:g}…{high / UM:g} µm for d = {v['bore'] / MM:g} mm "
        f"({table['kind']}: {table['ref']})"
    )


def _ball_set(entry: dict, v: dict, prov: dict) -> tuple[float, float, float]:
    """(dm, Dw, α0) [m, m, rad] of an entry: from the groove diameters and the free contact
    angle (Dw and dm follow), or from the ball set with either the free contact angle
    (angular-contact) or the radial clearance (deep-groove: α0 follows from it)."""
    f_i, f_o = v["inner_curvature"], v["outer_curvature"]
    if "inner_groove_diameter" in v:
        d_i, d_o = v["inner_groove_diameter"], v["outer_groove_diameter"]
        grooves = f"{prov['inner_groove_diameter']}; {prov['outer_groove_diameter']}"
        prov["ball_diameter"] = "derived: from the groove diameters and the free contact angle"
        prov["pitch_diameter"] = f"derived: mean of the groove diameters ({grooves})"
        prov["nominal_contact_angle"] = prov["contact_angle"]
        dw = float(ball_diameter_from_grooves(d_i, d_o, f_i, f_o, v["contact_angle"]))
        return 0.5 * (d_i + d_o), dw, v["contact_angle"]
    if "radial_clearance_group" in entry:
        _radial_clearance(entry, v, prov)
    if ("contact_angle" in v) == ("radial_clearance" in v):
        raise ValueError(
            "give contact_angle (angular-contact: the free contact angle sets the clearance) or "
            "radial_clearance / radial_clearance_group (deep-groove: the clearance sets the "
            "free contact angle), exactly one of them"
        )
    dw, dm = v["ball_diameter"], v["pitch_diameter"]
    for g, sign in (("inner_groove_diameter", "−"), ("outer_groove_diameter", "+")):
        prov[g] = f"derived: dm {sign} Dw {sign} Pd/2, Pd from the free contact angle"
    if "contact_angle" in v:
        prov["nominal_contact_angle"] = prov["contact_angle"]
        return dm, dw, v["contact_angle"]
    alpha = float(free_contact_angle(v["radial_clearance"], (f_i + f_o - 1.0) * dw))
    prov["nominal_contact_angle"] = (
        "derived: free contact angle of the radial clearance (" + prov["radial_clearance"] + ")"
    )
    return dm, dw, alpha


def _material_source(where: str, entry: dict, prov: dict) -> None:
    spec = entry.get("material_source")
    if spec is None:
        return
    kind, ref = spec.get("kind"), spec.get("ref")
    if kind not in PROVENANCE_KINDS or not ref:
        raise ValueError(f"{where} material_source = {spec!r} must be {{kind, ref}} with kind "
                         f"one of {PROVENANCE_KINDS}")  # fmt: skip
    prov["ring_material"] = prov["ball_material"] = f"{kind}: {ref}"


def bearing_from_entry(key: str, entry: dict) -> BallBearing:
    """The :class:`BallBearing` of one ``data/bearings.toml``-format entry.

    The ball set is given (``ball_diameter``, ``n_balls``, ``pitch_diameter``) or, with
    ``design_rule = "ball_set"``, sized by :func:`ball_set_rule`. The groove diameters are given
    (the ball diameter then follows from them and ``contact_angle``), or derived from the ball
    set and either the free ``contact_angle`` (angular-contact bearings) or the unmounted radial
    internal clearance (deep-groove bearings: ``radial_clearance``, or ``radial_clearance_group``
    "N"/"C3"… for the mid-point of the ISO 5753-1 range), from which the free contact angle
    follows (:func:`geometry.free_contact_angle`).

    Parameters
    ----------
    key : the entry's key (named in error messages)
    entry : the entry's table; numbers as ``{value, unit, kind, ref}``, ``ring_material`` and
        ``ball_material`` as keys of ``data/materials.toml``

    Returns
    -------
    BallBearing, SI [m]; geometry that cannot be a bearing raises ValueError naming the entry
    and the values

    Examples
    --------
    >>> def q(value, unit):
    ...     return {"value": value, "unit": unit, "kind": "assumed", "ref": "example"}
    >>> entry = {"name": "6205-like", "bore": q(25, "mm"), "outer_diameter": q(52, "mm"),
    ...          "width": q(15, "mm"), "ball_diameter": q(7.94, "mm"), "n_balls": q(9, "-"),
    ...          "pitch_diameter": q(39.04, "mm"), "radial_clearance": q(12.5, "um"),
    ...          "inner_curvature": q(0.52, "-"), "outer_curvature": q(0.53, "-"),
    ...          "ring_material": "bearing_steel_yu", "ball_material": "bearing_steel_yu"}
    >>> import math
    >>> b = bearing_from_entry("example", entry)
    >>> round(b.clearance * 1e6, 2), round(math.degrees(b.contact_angle), 2)  # µm, deg
    (12.5, 10.18)
    """
    where = f"bearing {key!r}"
    v, prov = _quantities(entry, where, skip=("material_source",))
    try:
        if "design_rule" in entry:
            _apply_ball_set_rule(entry["design_rule"], v, prov)
        dm, dw, alpha = _ball_set(entry, v, prov)
        _material_source(where, entry, prov)
        result = BallBearing(
            key=key,
            name=entry["name"],
            bore=v["bore"],
            outer_diameter=v["outer_diameter"],
            width=v["width"],
            n_balls=round(v["n_balls"]),
            ball_diameter=dw,
            pitch_diameter=dm,
            nominal_contact_angle=alpha,
            inner_curvature=v["inner_curvature"],
            outer_curvature=v["outer_curvature"],
            ring_material=material(entry["ring_material"]),
            ball_material=material(entry["ball_material"]),
            provenance=tuple(sorted(prov.items())),
        )
    except (KeyError, ValueError) as err:
        raise _named(where, err) from None
    return result


@functools.cache
def bearing(key: str) -> BallBearing:
    """The :class:`BallBearing` ``key`` (e.g. "71803", "7002C", "61804") from
    ``data/bearings.toml``; see :func:`bearing_from_entry` for the ways an entry gives its
    geometry.

    Parameters
    ----------
    key : str
        A key of ``data/bearings.toml``.

    Returns
    -------
    BallBearing
        Dimensions [m], ball count, contact angle [rad], curvatures [-], materials.

    Examples
    --------
    >>> b = bearing("7002C")
    >>> round(b.bore * 1e3, 3), round(b.outer_diameter * 1e3, 3), b.n_balls  # mm, mm, -
    (15.0, 32.0, 9)
    """
    return bearing_from_entry(key, _lookup("bearings", key))


def mounting_entry(key: str) -> dict:
    """The raw data of mounting ``key`` (``data/mountings.toml``), with ``base`` resolved:
    an entry may name a ``base`` entry and override some of its fields.

    Parameters
    ----------
    key : str
        A key of ``data/mountings.toml``.

    Returns
    -------
    dict
        The entry's fields as written (units and provenance kept).

    Examples
    --------
    >>> mounting_entry("yu2017_gimbal_spring")["bearing"]  # from its base
    '71803'
    """
    entry = dict(_lookup("mountings", key))
    if "base" in entry:
        base = mounting_entry(entry.pop("base"))
        base.update(entry)
        entry = base
    return entry


@functools.cache
def mounting(key: str):
    """The :class:`mounting.Mounting` ``key`` from ``data/mountings.toml``.

    Parameters
    ----------
    key : str
        A key of ``data/mountings.toml``.

    Returns
    -------
    Mounting

    Examples
    --------
    >>> m = mounting("ning_space_shaft")
    >>> m.arrangement, m.preload_method
    ('back_to_back', 'force')
    """
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
        members.append(
            LoopMember(m["name"], m["role"], length, material(m["material"]), area, m.get("part"))
        )
    arms = []
    for i, a in enumerate(entry.get("arms", ())):
        size = []
        for f in ("length", "width", "thickness"):
            value, prov[f"arms.{a['name']}.{f}"] = quantity(a[f], f"arms[{i}].{f}")
            size.append(value)
        arms.append(YokeArm(a["name"], *size, material(a["material"]), int(a.get("count", 1))))
    shim = q("shim") if "shim" in entry else 0.0
    stiffness = q("loop_stiffness") if "loop_stiffness" in entry else None
    spring = q("spring_stiffness") if "spring_stiffness" in entry else None
    preload = q("assembly_preload") if "assembly_preload" in entry else None
    if spring is not None:  # a spring compressed by c at assembly pushes k·c on the pair
        preload = spring * q("spring_compression")
        prov["assembly_preload"] = "derived: spring_stiffness × spring_compression"
    loop = PreloadLoop(
        tuple(members),
        shim=shim,
        stiffness=stiffness,
        model=entry.get("loop_model", "members"),
        arms=tuple(arms),
        spring_stiffness=spring,
        spring_compression=q("spring_compression") if spring is not None else None,
    )
    return Mounting(
        key=key,
        name=entry["name"],
        bearing_key=entry["bearing"],
        assembly_temperature=q("assembly_temperature"),
        fit=fit,
        loop=loop,
        assembly_preload=preload,
        provenance=tuple(sorted(prov.items())),
        arrangement=entry.get("arrangement", "face_to_face"),
    )


def actuator_entry(key: str) -> tuple[dict, dict, dict]:
    """Entry ``key`` of ``data/actuators.toml`` as data: its text fields (``name``,
    ``support_mounting``), its SI values and their provenance. The model record is built by
    :meth:`actuator.Actuator.from_catalog` (the catalogue imports no model).

    Returns
    -------
    tuple of dict
        (text fields, SI values, provenance).

    >>> text, values, prov = actuator_entry("liu2014_ema")
    >>> text["support_mounting"], values["gear_ratio"], prov["crank_length"].split(":")[0]
    ('liu2014_screw_support', 3.0, 'calibrated')
    """
    entry = _lookup("actuators", key)
    values, prov = _quantities(entry, f"actuator {key!r}")
    text = {k: entry[k] for k in ("name", "support_mounting") if k in entry}
    return text, dict(values), dict(prov)  # the caller's to change


@functools.cache
def mounting_coefficients(key: str):
    """The friction coefficients that go with mounting ``key``: a user catalogue's set of that
    mounting (``[coefficients.KEY]``, e.g. written by ``servofmu calibrate``), else the set its
    entry names (``coefficients = ...``; the variants of one gimbal share one calibration),
    else the set of its own key, else None.

    Returns
    -------
    FrictionCoefficients or None

    >>> mounting_coefficients("yu2017_gimbal_rigid") == coefficients("yu2017_gimbal")
    True
    """
    name = key if key in _USER["coefficients"] else mounting_entry(key).get("coefficients", key)
    return coefficients(name) if name in _table("coefficients") else None


def coefficient_set_name(key: str) -> str | None:
    """The coefficient set mounting ``key`` takes (see :func:`mounting_coefficients`): its
    key, or None when the mounting has none.

    Returns
    -------
    str or None

    >>> coefficient_set_name("yu2017_gimbal_spring"), coefficient_set_name("liu2014_screw_support")
    ('yu2017_gimbal', None)
    """
    name = key if key in _USER["coefficients"] else mounting_entry(key).get("coefficients", key)
    return name if name in _table("coefficients") else None


#: Fields of a coefficient set (``data/coefficients.toml``, a user's ``[coefficients.KEY]``):
#: the friction coefficients, and the loop stiffness a calibration may have fitted.
COEFFICIENT_FIELDS = (
    "hysteresis_loss",
    "sliding_friction",
    "static_friction_ratio",
    "palmgren_s0",
    "loop_stiffness",
)
#: Where a calibration's data are recorded in a set (``servofmu calibrate``): free-form text.
CALIBRATION_RECORD = "calibrated_on"


def _coefficient_quantities(key: str) -> dict[str, tuple[float, str]]:
    entry = _lookup("coefficients", key)
    extra = sorted(set(entry) - set(COEFFICIENT_FIELDS) - {CALIBRATION_RECORD})
    if extra:
        raise ValueError(
            f"fields {extra} are not among {list(COEFFICIENT_FIELDS)} (and "
            f"{CALIBRATION_RECORD!r}){suggest(extra[0], COEFFICIENT_FIELDS)}"
        )
    return {f: quantity(spec, f) for f, spec in entry.items() if f in COEFFICIENT_FIELDS}


def coefficients(key: str):
    """The :class:`friction.FrictionCoefficients` of set ``key`` (``data/coefficients.toml``,
    or a user catalogue's ``[coefficients.KEY]``).

    Parameters
    ----------
    key : str
        A key of ``data/coefficients.toml`` or of a user catalogue's coefficients.

    Returns
    -------
    FrictionCoefficients
        α_r [-], μ [-], μ_s/μ [-], s0 [-] with provenance.

    Examples
    --------
    >>> round(coefficients("yu2017_gimbal").sliding_friction, 4)  # calibrated on Yu
    0.0817
    """
    from ..physics.friction.terms import FrictionCoefficients

    q = _coefficient_quantities(key)
    q.pop("loop_stiffness", None)
    return FrictionCoefficients(
        **{f: v for f, (v, _) in q.items()}, provenance=tuple((f, s) for f, (_, s) in q.items())
    )


def _user_coefficients(key: str) -> None:
    """Check a user catalogue's set ``key``: its friction coefficients and loop stiffness."""
    coefficients(key)
    calibrated_loop_stiffness(key)


@functools.cache
def calibrated_loop_stiffness(key: str) -> tuple[float, str] | None:
    """(loop stiffness [N/m], provenance) that a user catalogue's set of mounting ``key``
    gives (a calibration that fitted it), else None.

    Returns
    -------
    tuple or None

    >>> calibrated_loop_stiffness("yu2017_gimbal") is None
    True
    """
    if key not in _USER["coefficients"]:
        return None
    found = _coefficient_quantities(key).get("loop_stiffness")
    if found is not None and not found[0] > 0:
        raise ValueError(f"loop_stiffness = {found[0]!r} N/m must be > 0")
    return found


def calibration_record(key: str) -> dict:
    """The ``calibrated_on`` table of coefficient set ``key`` (what a calibration was fitted
    on), ``{}`` without one.

    Returns
    -------
    dict

    >>> calibration_record("yu2017_gimbal")
    {}
    """
    record = _lookup("coefficients", key).get(CALIBRATION_RECORD, {})
    return dict(record) if isinstance(record, dict) else {"note": str(record)}


def tolerances(key: str) -> dict[str, tuple[float, float, str]]:
    """Tolerance bands of mounting ``key`` from ``data/tolerances.toml``: {dimension: (low,
    high, provenance)}, deviations from nominal in SI.

    Parameters
    ----------
    key : str
        A mounting with tolerance bands.

    Returns
    -------
    dict
        dimension → (low, high [SI], provenance).

    Examples
    --------
    >>> sorted(tolerances("yu2017_gimbal"))[:2]
    ['housing_bore', 'ring_outer_diameter']
    """
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


def thermal(key: str) -> dict:
    """Entry ``key`` of ``data/thermal.toml`` (``handbook`` or a preset of
    :mod:`.thermal.network`): numeric values as (SI value, provenance), other values as given.

    Parameters
    ----------
    key : str
        A key of ``data/thermal.toml``.

    Returns
    -------
    dict
        field → (SI value, provenance) or the value as given.

    Examples
    --------
    >>> sorted(thermal("handbook"))[:2]
    ['air_conductivity', 'air_filled_contact_resistance']
    """
    data = _table("thermal")
    if key not in data:
        raise ValueError(f"thermal key = {key!r} is not one of {sorted(data)}")
    return {
        field: quantity(spec, field) if isinstance(spec, dict) else spec
        for field, spec in data[key].items()
    }


def preload() -> None:
    """Read every data table now, each ``data/*.toml`` of the package (they are cached): see
    :func:`servofmu.physics.load_all`.

    Returns
    -------
    None

    Examples
    --------
    >>> preload()
    >>> _package_table.cache_info().currsize >= 11  # the package's eleven tables
    True
    """
    for entry in resources.files(__package__).joinpath("data").iterdir():
        if entry.name.endswith(".toml"):
            _package_table(entry.name.removesuffix(".toml"))

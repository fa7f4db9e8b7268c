"""Schemas of the catalogue tables: every key an entry may have (the optional ones too), its
type (a Boolean is not a number, a count is an integer) and, for every quantity
``{ value, unit, kind, ref }``, the units of its dimension.

The schemas are JSON Schema (draft 2020-12), checked with :mod:`fastjsonschema` (compiled:
linear and fast) and, for the messages of an entry that fails, :mod:`jsonschema`; the units a
quantity accepts are those of :data:`servofmu.physics.kernels.units.TO_SI` whose dimension, as
:mod:`pint` reads them, is the quantity's. A plane angle is a dimension of its own here (rad,
deg, and rpm per time), so that an angle is not a ratio and a torque is not a rotational
stiffness. These libraries are used at build time only: an FMU reads no catalogue and imports
none of them.

:func:`catalogue_problems` lists every problem of a user catalogue as read from TOML, each
naming the file, the table, the entry, the key, what was given and what is allowed, with the
closest allowed key or item ("did you mean"). The work is linear in the number of entries:
one compiled check per table, each entry checked once. :func:`data_problems` checks the
package's other data files (:data:`DATA_SCHEMAS`: the bearing rules, the grease torques, the
friction measurements) with the same messages.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Mapping

from servofmu.physics._checks import suggest
from servofmu.physics.kernels.units import TO_SI

#: Provenance kinds of a catalogue quantity (as
#: :data:`servofmu.parameters.catalog.PROVENANCE_KINDS`).
KINDS = ("paper", "catalogue", "handbook", "assumed", "calibrated", "derived")

#: Units whose pint spelling differs from the catalogue's (the rest: "." → "*", "m2" → "m**2").
_PINT_SPELLING = {
    "-": "dimensionless",
    "in": "inch",
    "g.cm": "gram_force * centimeter",  # gram-force centimetre (ASTM D1478 torques), not g·cm
    "rad": "plane_angle",
    "deg": "pi / 180 * plane_angle",
    "rpm": "2 * pi * plane_angle / minute",
    "N.m/rad": "newton * meter / plane_angle",
    "N.m/deg": "newton * meter / (pi / 180 * plane_angle)",
}
#: Names of the dimensions, for messages (keyed by a unit of each).
DIMENSION_NAMES = {
    "m": "length",
    "m2": "area",
    "m4": "second moment of area",
    "Pa": "pressure",
    "1/K": "thermal expansion (1/temperature)",
    "K": "temperature",
    "-": "ratio (dimensionless)",
    "rad": "plane angle",
    "N": "force",
    "N/m": "stiffness (force/length)",
    "N.m": "torque",
    "N.m/rad": "rotational stiffness (torque/angle)",
    "m2/s": "kinematic viscosity",
    "Pa.s": "dynamic viscosity",
    "kg/m3": "density",
    "kg": "mass",
    "J/kg/K": "specific heat",
    "W/m/K": "thermal conductivity",
    "W/m2/K": "heat transfer coefficient",
    "m2.K/W": "thermal contact resistance",
    "W/K": "thermal conductance",
    "m/s": "speed",
    "rpm": "rotational speed",
}
ALL_UNITS = (*TO_SI, "degC")


def pint_spelling(unit: str) -> str:
    """A catalogue unit string as pint reads it.

    Parameters
    ----------
    unit : str
        A key of :data:`~servofmu.physics.kernels.units.TO_SI` or "degC".

    Returns
    -------
    str

    Examples
    --------
    >>> pint_spelling("m2.K/W"), pint_spelling("N.m/deg")
    ('m**2*K/W', 'newton * meter / (pi / 180 * plane_angle)')
    """
    if unit in _PINT_SPELLING:
        return _PINT_SPELLING[unit]
    return re.sub(r"([A-Za-z])(\d)", r"\1**\2", unit).replace(".", "*")


@functools.cache
def registry():
    """pint's unit registry with a plane angle of its own dimension (``plane_angle``).

    Returns
    -------
    pint.UnitRegistry

    Examples
    --------
    >>> str(registry().parse_expression("plane_angle").dimensionality)  # rad, deg: not "-"
    '[angle]'
    """
    import pint

    ureg = pint.UnitRegistry()
    ureg.define("plane_angle = [angle]")
    return ureg


def pint_quantity(unit: str):
    """One ``unit`` as a pint quantity (:func:`registry`).

    Returns
    -------
    pint.Quantity

    Examples
    --------
    >>> round(pint_quantity("N.m/deg").to_base_units().magnitude, 4)  # N·m/rad
    57.2958
    """
    return registry().parse_expression(pint_spelling(unit))


@functools.cache
def _dimensions() -> dict:
    """{unit: its pint dimensionality} (compared as pint's containers, not as text)."""
    return {u: pint_quantity(u).dimensionality for u in ALL_UNITS}


def units_of(unit: str) -> tuple[str, ...]:
    """The catalogue units of the dimension of ``unit`` (itself included).

    Parameters
    ----------
    unit : str
        A catalogue unit.

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> units_of("m")
    ('m', 'mm', 'in', 'um')
    >>> units_of("K")
    ('K', 'degC')
    """
    dims = _dimensions()
    return tuple(u for u in ALL_UNITS if dims[u] == dims[unit])


def dimension_name(unit: str) -> str:
    """The name of the dimension of ``unit`` ("length", "pressure", …), else pint's
    dimensionality.

    Returns
    -------
    str

    Examples
    --------
    >>> dimension_name("MPa"), dimension_name("g.cm")
    ('pressure', 'torque')
    """
    dims = _dimensions()
    for ref, name in DIMENSION_NAMES.items():
        if dims.get(unit) == dims[ref]:
            return name
    return str(dims[unit]) if unit in dims else "unknown"


# ----------------------------------------------------------------------------- building blocks
TEXT = {"type": "string"}
FLAG = {"type": "boolean"}


def _quantity(unit: str, count: bool = False) -> dict:
    """The schema of a ``{ value, unit, kind, ref }`` quantity of the dimension of ``unit``;
    ``count``: its value is a whole number."""
    return {
        "type": "object",
        "x-dimension": unit,
        "properties": {
            "value": {"type": "integer" if count else "number"},
            "unit": {"enum": list(units_of(unit))},
            "kind": {"enum": list(KINDS)},
            "ref": TEXT,
        },
        "required": ["value", "unit", "kind", "ref"],
        "additionalProperties": False,
    }


def _entry(fields: dict, required=("name",)) -> dict:
    """The schema of a table entry: these fields and no others, ``required`` among them."""
    return {
        "type": "object",
        "properties": fields,
        "required": list(required),
        "additionalProperties": False,
    }


def _choice(values) -> dict:
    return {"enum": list(values)}


def _array_of(item: dict) -> dict:
    return {"type": "array", "items": item}


def _choices():
    from servofmu.physics.pair.preload import ARRANGEMENTS, LOOP_MODELS, ROLES
    from servofmu.physics.thermal.temperatures import MEMBER_PARTS

    return ARRANGEMENTS, LOOP_MODELS, ROLES, MEMBER_PARTS


# ----------------------------------------------------------------------------- the tables
def _material() -> dict:
    return _entry(
        {
            "name": TEXT,
            "youngs_modulus": _quantity("Pa"),
            "poisson_ratio": _quantity("-"),
            "expansion": _quantity("1/K"),
            "density": _quantity("kg/m3"),
            "specific_heat": _quantity("J/kg/K"),
            "thermal_conductivity": _quantity("W/m/K"),
            "emissivity": _quantity("-"),
        },
        ("name", "youngs_modulus", "poisson_ratio", "expansion"),
    )


def _lubricant() -> dict:
    torque_test = _entry(
        {
            "standard": TEXT,
            "bearing": TEXT,
            "temperature": _quantity("K"),
            "starting_torque": _quantity("N.m"),
            "running_torque": _quantity("N.m"),
        },
        ("standard", "bearing", "temperature"),
    )
    point = _entry({"temperature": _quantity("K"), "viscosity": _quantity("m2/s")},
                  ("temperature", "viscosity"))  # fmt: skip
    return _entry(
        {
            "name": TEXT,
            "model": _choice(("walther", "solid")),
            "type": _choice(("oil", "grease", "solid")),
            "base_oil": TEXT,
            "oil_class": _choice(("mineral", "synthetic")),
            "a": _quantity("-"),
            "b": _quantity("-"),
            "c": _quantity("m2/s"),
            "viscosity_40": _quantity("m2/s"),
            "viscosity_100": _quantity("m2/s"),
            "t1": _quantity("K"),
            "nu1": _quantity("m2/s"),
            "t2": _quantity("K"),
            "nu2": _quantity("m2/s"),
            "viscosity_points": _array_of(point),
            "density": _quantity("kg/m3"),
            "density_temperature": _quantity("K"),
            "data_minimum_temperature": _quantity("K"),
            "pour_point": _quantity("K"),
            "minimum_temperature": _quantity("K"),
            "maximum_temperature": _quantity("K"),
            "low_temperature_torque": _array_of(torque_test),
        },
        ("name", "model"),
    )


def _bearing() -> dict:
    length = _quantity("m")
    return _entry(
        {
            "name": TEXT,
            "bore": length,
            "outer_diameter": length,
            "width": length,
            "n_balls": _quantity("-", count=True),
            "ball_diameter": length,
            "pitch_diameter": length,
            "contact_angle": _quantity("rad"),
            "inner_groove_diameter": length,
            "outer_groove_diameter": length,
            "radial_clearance": length,
            "radial_clearance_group": _choice(("C2", "N", "C3", "C4")),
            "design_rule": _choice(("ball_set",)),
            "inner_curvature": _quantity("-"),
            "outer_curvature": _quantity("-"),
            "ring_material": TEXT,
            "ball_material": TEXT,
            "material_source": _entry({"kind": _choice(KINDS), "ref": TEXT}, ("kind", "ref")),
        },
        ("name", "bore", "outer_diameter", "width", "inner_curvature", "outer_curvature",
         "ring_material", "ball_material"),
    )  # fmt: skip


def _mounting() -> dict:
    arrangements, loop_models, roles, parts = _choices()
    length = _quantity("m")
    member = _entry(
        {
            "name": TEXT,
            "role": _choice(roles),
            "material": TEXT,
            "length": length,
            "area": _quantity("m2"),
            "part": _choice(parts),
        },
        ("name", "role", "material", "length"),
    )
    arm = _entry(
        {
            "name": TEXT,
            "count": {"type": "integer", "minimum": 1},
            "material": TEXT,
            "length": length,
            "width": length,
            "thickness": length,
        },
        ("name", "material", "length", "width", "thickness"),
    )
    return _entry(
        {
            "name": TEXT,
            "base": TEXT,
            "bearing": TEXT,
            "lubricant": TEXT,
            "coefficients": TEXT,
            "arrangement": _choice(arrangements),
            "loop_model": _choice(loop_models),
            "assembly_temperature": _quantity("K"),
            "assembly_preload": _quantity("N"),
            "operating_minimum_temperature": _quantity("K"),
            "operating_maximum_temperature": _quantity("K"),
            "housing_material": TEXT,
            "housing_outer_diameter": length,
            "outer_interference": length,
            "shaft_material": TEXT,
            "shaft_bore": length,
            "inner_interference": length,
            "shim": length,
            "loop_stiffness": _quantity("N/m"),
            "spring_stiffness": _quantity("N/m"),
            "spring_compression": length,
            "loop": _array_of(member),
            "arms": _array_of(arm),
        },
    )


def _calibrated(unit: str) -> dict:
    """A quantity that a calibration may have fitted: with its ``standard_error`` (a number,
    in its unit) as ``servofmu calibrate`` writes it."""
    schema = _quantity(unit)
    schema["properties"]["standard_error"] = {"type": "number", "minimum": 0}
    return schema


def _coefficients() -> dict:
    return _entry(
        {
            "hysteresis_loss": _calibrated("-"),
            "sliding_friction": _calibrated("-"),
            "static_friction_ratio": _calibrated("-"),
            "palmgren_s0": _calibrated("-"),
            "loop_stiffness": _calibrated("N/m"),
            "calibrated_on": {"type": ["object", "string"]},
        },
        (),
    )


def tolerance_band(unit: str | None = None) -> dict:
    """The schema of a tolerance band ``{ low, high, unit, kind, ref }`` (deviations from
    nominal) of the dimension of ``unit`` (any catalogue unit when None).

    Returns
    -------
    dict

    Examples
    --------
    >>> tolerance_band("m")["properties"]["unit"]
    {'enum': ['m', 'mm', 'in', 'um']}
    """
    return _entry(
        {
            "low": {"type": "number"},
            "high": {"type": "number"},
            "unit": {"enum": list(units_of(unit) if unit else ALL_UNITS)},
            "kind": _choice(KINDS),
            "ref": TEXT,
        },
        ("low", "high", "unit", "kind", "ref"),
    )


def _tolerances() -> dict:
    """Bands by name: a parameter's band has its unit; the others are the seats' diameters
    (lengths), whose names the Monte-Carlo study checks (:mod:`servofmu.harness.tolerance`)."""
    from servofmu.parameters.bearing import PARAMETERS

    props = {
        spec.name: tolerance_band(spec.unit if spec.unit in TO_SI else None)
        for spec in PARAMETERS
        if spec.type == "Real"
    }
    return {"type": "object", "properties": props, "additionalProperties": tolerance_band("m")}


def _defaults() -> dict:
    return _entry({"mounting": TEXT, "lubricant": TEXT, "support_mounting": TEXT}, ())


def _actuator() -> dict:
    length, area = _quantity("m"), _quantity("m2")
    return _entry(
        {
            "name": TEXT,
            "support_mounting": TEXT,
            "reference_angle": _quantity("rad"),
            "gear_ratio": _quantity("-"),
            "screw_lead": length,
            "crank_length": length,
            "rod_length": length,
            "neutral_crank_angle": _quantity("rad"),
            "neutral_rod_angle": _quantity("rad"),
            "crank_area": area,
            "rod_area": area,
            "arm_length": length,
            "shaft_polar_moment": _quantity("m4"),
            "arm_second_moment": _quantity("m4"),
            "youngs_modulus": _quantity("Pa"),
            "shear_modulus": _quantity("Pa"),
            "gear_stiffness_reflected": _quantity("N.m/rad"),
            "screw_stiffness_reflected": _quantity("N.m/rad"),
            "housing_stiffness_reflected": _quantity("N.m/rad"),
            "seat_stiffness": _quantity("N/m"),
        },
    )


def _thermal() -> dict:
    """The handbook entry or a preset (a mounting in an environment)."""
    return _entry(
        {
            "name": TEXT,
            "mounting": TEXT,
            "vacuum": FLAG,
            "mounted": FLAG,
            "air_speed": _quantity("m/s"),
            "reference_preload": _quantity("N"),
            "inner_ring_heat_fraction": _quantity("-"),
            "pressed_contact_resistance": _quantity("m2.K/W"),
            "light_contact_pressure": _quantity("Pa"),
            "pressed_contact_pressure": _quantity("Pa"),
            "light_contact_resistance": _quantity("m2.K/W"),
            "air_filled_contact_resistance": _quantity("m2.K/W"),
            "contact_reference_conductivity": _quantity("W/m/K"),
            "air_conductivity": _quantity("W/m/K"),
            "air_kinematic_viscosity": _quantity("m2/s"),
            "air_prandtl": _quantity("-"),
        },
        (),
    )


def _skf_friction() -> dict:
    return _entry(
        {
            "name": TEXT,
            "bearing_type": _choice(("deep_groove", "angular_contact")),
            "series_prefix": TEXT,
            "contact_angle": _quantity("rad"),
            **{k: _quantity("-") for k in ("r1", "r2", "r3", "s1", "s2", "s3", "kz")},
        },
        ("name", "bearing_type"),
    )


#: The schema of one entry of each catalogue table, by table.
ENTRY_SCHEMAS = {
    "materials": _material,
    "lubricants": _lubricant,
    "bearings": _bearing,
    "mountings": _mounting,
    "coefficients": _coefficients,
    "tolerances": _tolerances,
    "actuators": _actuator,
    "thermal": _thermal,
    "skf_friction": _skf_friction,
}
#: Tables a user catalogue may hold (with ``defaults``), as :data:`catalog.USER_TABLES`.
USER_TABLES = ("materials", "lubricants", "bearings", "mountings", "coefficients", "tolerances")


# ----------------------------------------------------------------------------- the data files
def _keyed(entry: dict) -> dict:
    """A table of entries by key, each fitting ``entry`` (``[table.KEY]``)."""
    return {"type": "object", "additionalProperties": entry}


def _bearing_rules() -> dict:
    """``parameters/data/bearing_rules.toml``: the ball-set design rule and the radial
    clearance groups (rows: the bore in mm, over < d <= incl; each group's [min, max] in the
    table's unit, which :func:`servofmu.physics.contact.geometry.clearance_from_group` reads as
    µm, so that unit only)."""
    ratio = _quantity("-")
    band = {"type": "array", "items": {"type": "number"}, "minItems": 2, "maxItems": 2}
    row = _entry(
        {"over": {"type": "number"}, "incl": {"type": "number"},
         **{group: band for group in ("C2", "N", "C3", "C4")}},
        ("over", "incl"),
    )  # fmt: skip
    ball_set = _entry(
        {
            "name": TEXT,
            "calibration_bearings": _array_of(TEXT),
            "section_ratio": ratio,
            "fill": ratio,
            "ball_diameter_error": ratio,
            "ball_count_error": _quantity("-", count=True),
            "pitch_diameter_error": ratio,
        },
        ("name", "calibration_bearings", "section_ratio", "fill", "ball_diameter_error",
         "ball_count_error", "pitch_diameter_error"),
    )  # fmt: skip
    radial_clearance = _entry(
        {
            "name": TEXT,
            "unit": {"enum": ["um"]},
            "kind": _choice(KINDS),
            "ref": TEXT,
            "rows": _array_of(row),
        },
        ("name", "unit", "kind", "ref", "rows"),
    )
    return _entry({"ball_set": ball_set, "radial_clearance": radial_clearance}, ())


def _grease_torques() -> dict:
    """``parameters/data/grease_torques.toml``: the test standards (``[tests.KEY]``) and the
    published torque points of greases (``[greases.KEY]``, keyed by lubricant)."""
    length, torque = _quantity("m"), _quantity("N.m")
    test = _entry(
        {
            "name": TEXT,
            "bore": length,
            "outer_diameter": length,
            "speed": _quantity("rpm"),
            "housing_mass": _quantity("kg"),
            "fill": TEXT,
            "hold": TEXT,
            "torques": TEXT,
        },
        ("name", "bore", "outer_diameter", "speed", "housing_mass"),
    )
    point = _entry(
        {
            "test": TEXT,
            "temperature": _quantity("K"),
            "starting_torque": torque,
            "running_torque": torque,
        },
        ("test", "temperature", "starting_torque", "running_torque"),
    )
    grease = _entry({"name": TEXT, "points": _array_of(point)})
    return _entry({"tests": _keyed(test), "greases": _keyed(grease)}, ())


def _friction_measurements() -> dict:
    """``papers/data/friction_measurements.toml``: one table per source of measured torques
    (its rig, its series and their points) and the candidates searched (``[[searched]]``)."""
    length = _quantity("m")
    point = _entry(
        {"speed": _quantity("rpm"), "k_star": _quantity("N.m"), "exponent": _quantity("-")},
        ("speed", "k_star", "exponent"),
    )
    series = _entry(
        {
            "id": TEXT,
            "table": TEXT,
            "ball_diameter": length,
            "ball_load": _quantity("N"),
            "dynamic_viscosity": _quantity("Pa.s"),
            "lambda_range": TEXT,
            "points": _array_of(point),
        },
        ("id", "table", "ball_diameter", "ball_load", "dynamic_viscosity", "points"),
    )
    source = _entry(
        {
            "title": TEXT,
            "ref": TEXT,
            "rig": TEXT,
            "lubrication": TEXT,
            "measured": TEXT,
            "race_radius": length,
            "groove_radius": length,
            "reduced_modulus": _quantity("Pa"),
            "n_balls": _quantity("-", count=True),
            "temperature": _quantity("K"),
            "series": _array_of(series),
        },
        ("title", "ref", "series"),
    )
    searched = _entry(
        {"cite": TEXT, "source": TEXT, "stored": TEXT, "why": TEXT, "details": TEXT},
        ("cite", "source", "stored", "why"),
    )
    return {
        "type": "object",
        "properties": {"searched": _array_of(searched)},
        "additionalProperties": source,
    }


#: The schema of each of the package's other data files (the whole file), by its path under
#: the package ``servofmu``.
DATA_SCHEMAS = {
    "parameters/data/bearing_rules.toml": _bearing_rules,
    "parameters/data/grease_torques.toml": _grease_torques,
    "papers/data/friction_measurements.toml": _friction_measurements,
}


@functools.cache
def entry_schema(table: str) -> dict:
    """The JSON Schema of one entry of catalogue table ``table`` (or of ``defaults``).

    Parameters
    ----------
    table : str
        A key of :data:`ENTRY_SCHEMAS`, or "defaults".

    Returns
    -------
    dict

    Examples
    --------
    >>> entry_schema("materials")["properties"]["expansion"]["properties"]["unit"]
    {'enum': ['1/K']}
    """
    return _defaults() if table == "defaults" else ENTRY_SCHEMAS[table]()


@functools.cache
def _validator(table: str):
    """:mod:`jsonschema`'s validator of one entry of ``table``: every error, for messages."""
    import jsonschema

    schema = entry_schema(table)
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


@functools.cache
def _fast(table: str):
    """:mod:`fastjsonschema`'s compiled check of one entry of ``table`` (the same schema, about
    20 times faster than :func:`_validator`; it stops at the first error)."""
    import fastjsonschema

    return fastjsonschema.compile(entry_schema(table))


# ----------------------------------------------------------------------------- messages
def _type_name(value) -> str:
    if isinstance(value, bool):
        return "a Boolean"
    if isinstance(value, int):
        return "an integer"
    if isinstance(value, float):
        return "a number with a fraction" if not value.is_integer() else "a number"
    if isinstance(value, str):
        return "text"
    if isinstance(value, Mapping):
        return "a table"
    if isinstance(value, list):
        return "an array"
    return type(value).__name__


_WANTED = {
    "number": "a number",
    "integer": "a whole number (a count)",
    "string": "text",
    "boolean": "true or false",
    "object": "a table",
    "array": "an array of tables",
}


def _given(value) -> str:
    """A value as TOML writes it (true/false for Booleans)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value)


def _path(parts) -> str:
    out = ""
    for p in parts:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out


def message(error, where: str) -> str:
    """One line for a :class:`jsonschema.ValidationError` of an entry at ``where`` ("FILE:
    [table.KEY]"): the key, what was given, what is allowed, and the closest allowed word.

    Returns
    -------
    str

    Examples
    --------
    >>> error = next(_validator("defaults").iter_errors({"mountng": "x"}))
    >>> message(error, "mine.toml: [defaults]")  # doctest: +ELLIPSIS
    "mine.toml: [defaults] mountng: unknown key 'mountng' (did you mean 'mounting'?); ..."
    """
    path = list(error.absolute_path)
    field = _path(path)
    at = f"{where} {field}" if field else where
    v = error.validator
    if v == "additionalProperties":
        allowed = sorted(error.schema.get("properties", {}))
        extra = sorted(set(error.instance) - set(allowed))
        return (
            f"{where} {_path([*path, extra[0]])}: unknown key {extra[0]!r}"
            f"{suggest(extra[0], allowed)}; allowed keys: {allowed}"
            + (f" (and {len(extra) - 1} more unknown)" if len(extra) > 1 else "")
        )
    if v == "required":
        missing = next(k for k in error.validator_value if k not in error.instance)
        return (
            f"{where} {_path([*path, missing])}: missing (required keys: {error.validator_value})"
        )
    if v == "enum" and path and path[-1] == "unit":
        allowed = error.validator_value
        given = error.instance
        given_dim = f" (a unit of {dimension_name(given)})" if given in ALL_UNITS else ""
        if given in ALL_UNITS and given in units_of(allowed[0]):  # the dimension, not the unit
            return f"{at} = {given!r} is not the unit this value is read in: one of {allowed}"
        return (
            f"{at} = {given!r}{given_dim} is not a unit of {dimension_name(allowed[0])}: "
            f"one of {allowed}{suggest(given, allowed)}"
        )
    if v == "enum":
        allowed = error.validator_value
        return (
            f"{at} = {error.instance!r} is not one of {allowed}{suggest(error.instance, allowed)}"
        )
    if v == "type":
        wanted = error.validator_value
        wanted = " or ".join(_WANTED.get(w, w) for w in ([wanted] if isinstance(wanted, str)
                                                         else wanted))  # fmt: skip
        return f"{at} = {_given(error.instance)} is {_type_name(error.instance)}, not {wanted}"
    if v == "minimum":
        return f"{at} = {error.instance!r} is below {error.validator_value}"
    return f"{at}: {error.message}"


def entry_problems(table: str, key: str, value, where: str) -> list[str]:
    """The problems of one entry ``key`` of ``table`` (each a line starting with ``where``).

    Returns
    -------
    list of str
        Empty when the entry fits the table's schema.

    Examples
    --------
    >>> entry_problems("coefficients", "mine", {"palmgren_s0": 1.0}, "x.toml:")
    ['x.toml: [coefficients.mine] palmgren_s0 = 1.0 is a number, not a table']
    """
    import fastjsonschema

    try:
        _fast(table)(value)
        return []
    except fastjsonschema.JsonSchemaException:
        pass
    errors = sorted(  # what was given wrong first, then what is missing
        _validator(table).iter_errors(value),
        key=lambda e: (e.validator == "required", list(e.absolute_path), e.validator),
    )
    return [message(e, f"{where} [{table}.{key}]") for e in errors]


@functools.cache
def _data_validator(name: str):
    """:mod:`jsonschema`'s validator of the data file ``name`` (a key of
    :data:`DATA_SCHEMAS`)."""
    import jsonschema

    schema = DATA_SCHEMAS[name]()
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def data_problems(name: str, data: Mapping, file: str | None = None) -> list[str]:
    """Every problem of the package's data file ``name`` as read from TOML (``data``): an
    unknown key, a wrong type, a unit of another dimension, a missing key; each line names the
    file, the table and key (as a dotted path), what was given and what is allowed.

    Parameters
    ----------
    name : str
        A key of :data:`DATA_SCHEMAS`.
    data : mapping
        The file as read.
    file : str, optional
        The file's name in the messages (``name`` when None).

    Returns
    -------
    list of str
        Empty when the file fits its schema.

    Examples
    --------
    >>> q = {"value": 1.0, "unit": "N.mm", "kind": "handbook", "ref": "demo"}
    >>> data = {"tests": {"t": {"name": "t", "bore": q}}, "greases": {"g": {"nmae": "g"}}}
    >>> for line in data_problems("parameters/data/grease_torques.toml", data, "g.toml"):
    ...     print(line[:72])
    g.toml: greases.g.nmae: unknown key 'nmae' (did you mean 'name'?); allow
    g.toml: tests.t.bore.unit = 'N.mm' (a unit of torque) is not a unit of l
    g.toml: greases.g.name: missing (required keys: ['name'])
    g.toml: tests.t.outer_diameter: missing (required keys: ['name', 'bore',
    """
    errors = sorted(
        _data_validator(name).iter_errors(data),
        key=lambda e: (e.validator == "required", list(map(str, e.absolute_path)), e.validator),
    )
    # one line per entry missing keys (the required keys listed), not one per key missing
    return list(dict.fromkeys(message(e, f"{file or name}:") for e in errors))


def catalogue_problems(data: Mapping, file: str, limit: int = 20) -> list[str]:
    """Every problem of a user catalogue ``data`` (as read from TOML) read from ``file``:
    unknown tables, entries that are not tables, unknown keys, wrong types and units of
    another dimension; at most ``limit`` of them.

    Parameters
    ----------
    data : mapping
        The catalogue as read (``[defaults]`` included).
    file : str
        Its path, named in every message.
    limit : int
        Stop after this many problems.

    Returns
    -------
    list of str
        One line per problem; empty when the catalogue fits its schema.

    Examples
    --------
    >>> q = lambda v, u: {"value": v, "unit": u, "kind": "assumed", "ref": "demo"}
    >>> data = {"materials": {"my_alu": {"name": "Al", "youngs_modulus": q(70, "GPa"),
    ...     "poisson_ratio": q(0.33, "-"), "expansion": q(23e-6, "m"), "densty": q(2.7, "g/cm3")}}}
    >>> for line in catalogue_problems(data, "mine.toml"):
    ...     print(line)  # doctest: +NORMALIZE_WHITESPACE
    mine.toml: [materials.my_alu] densty: unknown key 'densty' (did you mean 'density'?);
    allowed keys: ['density', 'emissivity', 'expansion', 'name', 'poisson_ratio',
    'specific_heat', 'thermal_conductivity', 'youngs_modulus']
    mine.toml: [materials.my_alu] expansion.unit = 'm' (a unit of length) is not a unit of
    thermal expansion (1/temperature): one of ['1/K']
    """
    problems: list[str] = []
    tables = (*USER_TABLES, "defaults")
    for table, entries in data.items():
        if table not in tables:
            problems.append(
                f"{file}: table [{table}] is not a catalogue table{suggest(table, tables)}; "
                f"allowed: {list(tables)}"
            )
            continue
        if table == "defaults":
            problems += _flat_problems("defaults", entries, f"{file}: [defaults]")
            continue
        if not isinstance(entries, Mapping):
            problems.append(f"{file}: [{table}] = {entries!r} must be a table of entries")
            continue
        for key, value in entries.items():
            if not isinstance(value, Mapping):
                problems.append(
                    f"{file}: [{table}.{key}] = {value!r} is {_type_name(value)}, not a table "
                    "(an entry)"
                )
            else:
                problems += entry_problems(table, key, value, f"{file}:")
            if len(problems) >= limit:
                return problems[:limit]
    return problems[:limit]


def _flat_problems(table: str, value, where: str) -> list[str]:
    if not isinstance(value, Mapping):
        return [f"{where} = {value!r} is {_type_name(value)}, not a table"]
    errors = sorted(_validator(table).iter_errors(value), key=lambda e: list(e.absolute_path))
    return [message(e, where) for e in errors]

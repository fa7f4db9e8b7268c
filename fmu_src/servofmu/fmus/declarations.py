"""The variables of a servofmu FMU, declared once: what each slave's ``VARIABLES`` holds.

A slave class declares its variables as a tuple of :class:`Var`, built with the keyword-only
constructors of this module (:func:`real_input`, :func:`real_parameter`, :func:`output`,
:func:`spec_parameter`); the runtime (:mod:`.runtime`) registers them with pythonfmu and checks
values against them, the modelDescription writer (:mod:`.model_description`) and the FMU's
documentation write them out. pythonfmu numbers value references in declaration order: a new
variable is appended last, so that the references of the others stay.

Units are keys of :data:`UNITS` (SI, with the display units a host may show); a choice is an
``Enumeration``: an integer 1…n naming one of its :class:`Item`\\ s.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

# SI base-unit exponents and display units (factor, offset: display = factor·value + offset)
UNITS: dict[str, tuple[dict[str, int], tuple[tuple[str, float, float], ...]]] = {
    "K": ({"K": 1}, (("degC", 1.0, -273.15),)),
    "rad/s": ({"rad": 1, "s": -1}, (("rpm", 30.0 / math.pi, 0.0), ("deg/s", 180.0 / math.pi, 0.0))),
    "rad": ({"rad": 1}, (("deg", 180.0 / math.pi, 0.0),)),
    "N": ({"kg": 1, "m": 1, "s": -2}, ()),
    "N.m": ({"kg": 1, "m": 2, "s": -2}, (("N.mm", 1.0e3, 0.0),)),
    "m": ({"m": 1}, (("mm", 1.0e3, 0.0), ("um", 1.0e6, 0.0))),
    "m2": ({"m": 2}, (("mm2", 1.0e6, 0.0),)),
    "m4": ({"m": 4}, (("mm4", 1.0e12, 0.0),)),
    "m2/s": ({"m": 2, "s": -1}, (("cSt", 1.0e6, 0.0),)),
    "N/m": ({"kg": 1, "s": -2}, (("N/um", 1.0e-6, 0.0),)),
    "N.m/rad": ({"kg": 1, "m": 2, "s": -2, "rad": -1}, (("N.m/deg", math.pi / 180.0, 0.0),)),
    "W": ({"kg": 1, "m": 2, "s": -3}, ()),
    "Pa": ({"kg": 1, "m": -1, "s": -2}, (("MPa", 1.0e-6, 0.0), ("GPa", 1.0e-9, 0.0))),
    "V": ({"kg": 1, "m": 2, "s": -3, "A": -1}, ()),
    "A": ({"A": 1}, ()),
    "Ohm": ({"kg": 1, "m": 2, "s": -3, "A": -2}, ()),
    "H": ({"kg": 1, "m": 2, "s": -2, "A": -2}, (("mH", 1.0e3, 0.0),)),
    "N.m/A": ({"kg": 1, "m": 2, "s": -2, "A": -1}, ()),
    "V.s/rad": ({"kg": 1, "m": 2, "s": -3, "A": -1, "rad": -1}, ()),
    "kg.m2": ({"kg": 1, "m": 2}, ()),
    "N.m.s/rad": ({"kg": 1, "m": 2, "s": -1, "rad": -1}, ()),
    "s": ({"s": 1}, (("ms", 1.0e3, 0.0),)),
    "J/K": ({"kg": 1, "m": 2, "s": -2, "K": -1}, ()),
    "W/K": ({"kg": 1, "m": 2, "s": -3, "K": -1}, ()),
    "W/(m2.K)": ({"kg": 1, "s": -3, "K": -1}, ()),
    "1/K": ({"K": -1}, ()),
    "kg/m3": ({"kg": 1, "m": -3}, (("g/cm3", 1.0e-3, 0.0),)),
    "1": ({}, ()),
}

#: The kinds of variable a slave declares, and the FMI type through which hosts get and set
#: each (FMI 2.0 hosts access enumerations through fmi2Get/SetInteger)
FMI_TYPE = {"Real": "Real", "Integer": "Integer", "Boolean": "Boolean", "Enumeration": "Integer"}
CAUSALITIES = ("input", "output", "parameter")
#: Start values (and their provenance) that a build gives an FMU instead of its class's
#: defaults (``servofmu build --catalog/--preset``): {model name: {variable: (start,
#: source)}}, set by the build process; a built FMU reads its own from
#: ``resources/servofmu_build.json`` ("start"), so the package it ships stays the same.
BUILD_START: dict[str, dict[str, tuple[object, str]]] = {}


@dataclass(frozen=True)
class Item:
    """One item of an enumeration: its name (what users read and type) and meaning."""

    name: str
    description: str = ""


@dataclass(frozen=True, kw_only=True)
class Var:
    """One FMU variable (keyword arguments only).

    Attributes
    ----------
    name : FMI name (public API: tests, SSPs and users depend on it)
    type : "Real", "Integer", "Boolean" or "Enumeration" (a choice: an integer 1…n naming one
        of ``items``)
    causality : "input", "output" or "parameter"
    description : one line, with the unit in words where it helps
    start : start value (inputs, parameters; the item number of an Enumeration); outputs are
        calculated
    unit, display_unit : keys of :data:`UNITS` (Real only)
    min, max : valid range (inclusive), checked at run time as well
    variability : parameters "fixed" (default) or "tunable"; inputs "continuous"/"discrete"
    depends : outputs: the inputs they depend on directly while stepping (() for none)
    initial_depends : outputs: every input and parameter their value right after
        initialization depends on (ModelStructure/InitialUnknowns); required for outputs
    field : outputs: the attribute of the model's result record that the output copies
    source : provenance of the default (paper, catalogue, handbook, assumed, calibrated)
    items : Enumeration: the items, numbered 1, 2, … in this order
    declared_type : Enumeration: the name of its item type (variables may share one)
    allow_inf : Real outputs: +inf is a value (its description says when), not a failure
    """

    name: str
    type: str
    causality: str
    description: str
    start: object = None
    unit: str | None = None
    display_unit: str | None = None
    min: float | None = None
    max: float | None = None
    variability: str | None = None
    depends: tuple[str, ...] = ()
    initial_depends: tuple[str, ...] | None = None
    field: str | None = None
    source: str = ""
    items: tuple[Item, ...] = ()
    declared_type: str | None = None
    allow_inf: bool = False

    def item_name(self, value) -> str:
        """The item name of Enumeration value ``value`` (1-based)."""
        return self.items[value - 1].name


def real_input(
    name: str,
    description: str,
    *,
    start: float,
    unit: str | None = None,
    display_unit: str | None = None,
    min: float | None = None,
    max: float | None = None,
    **kw,
) -> Var:
    """A continuous Real input with its start value, unit and valid range.

    Parameters
    ----------
    name, description : the FMI name and one line of description
    start : the start value [unit]
    unit, display_unit : keys of :data:`UNITS`
    min, max : the valid range [unit], inclusive (a step with the input outside is refused)
    **kw : any other attribute of :class:`Var`

    Returns
    -------
    Var

    Examples
    --------
    >>> v = real_input("voltage", "Armature voltage", start=0.0, unit="V", min=-1e3, max=1e3)
    >>> v.causality, v.type, v.min, v.max
    ('input', 'Real', -1000.0, 1000.0)
    """
    return Var(
        name=name,
        type="Real",
        causality="input",
        description=description,
        start=start,
        unit=unit,
        display_unit=display_unit,
        min=min,
        max=max,
        **kw,
    )


def real_parameter(
    name: str,
    description: str,
    *,
    start: float,
    unit: str | None = None,
    display_unit: str | None = None,
    min: float | None = None,
    max: float | None = None,
    source: str = "",
    **kw,
) -> Var:
    """A Real parameter with its default, unit, valid range and provenance (``variability``
    "fixed" unless given).

    Parameters
    ----------
    name, description : the FMI name and one line of description
    start : the default [unit]
    unit, display_unit : keys of :data:`UNITS`
    min, max : the valid range [unit], inclusive (fmi2ExitInitializationMode refuses a value
        outside)
    source : the default's provenance (paper, catalogue, handbook, assumed, calibrated)
    **kw : any other attribute of :class:`Var` (``variability="tunable"``)

    Returns
    -------
    Var

    Examples
    --------
    >>> p = real_parameter("inertia", "Rotor plus load inertia J", start=1e-4, unit="kg.m2",
    ...                    min=1e-12, max=1e6, source="assumed")
    >>> p.causality, p.variability, p.source
    ('parameter', None, 'assumed')
    """
    field = real_input(name, description, start=start, unit=unit, display_unit=display_unit,
                       min=min, max=max, source=source, **kw)  # fmt: skip
    return dataclasses.replace(field, causality="parameter")


def output(
    name: str,
    description: str,
    *,
    unit: str | None = None,
    display_unit: str | None = None,
    type: str = "Real",
    **kw,
) -> Var:
    """An output (Real unless ``type`` says otherwise).

    Parameters
    ----------
    name, description : the FMI name and one line of description
    unit, display_unit : keys of :data:`UNITS` (Real)
    type : "Real" or "Boolean"
    **kw : any other attribute of :class:`Var`: ``initial_depends`` (required), ``depends``,
        ``field``, ``allow_inf``

    Returns
    -------
    Var

    Examples
    --------
    >>> y = output("speed", "Rotor speed", unit="rad/s", display_unit="rpm",
    ...            initial_depends=("initial_speed",))
    >>> y.causality, y.depends, y.initial_depends
    ('output', (), ('initial_speed',))
    """
    return Var(
        name=name,
        type=type,
        causality="output",
        description=description,
        unit=unit,
        display_unit=display_unit,
        **kw,
    )


def items(choices) -> tuple[Item, ...]:
    """Enumeration items of physics choices.

    Parameters
    ----------
    choices : objects with ``name`` and ``description`` (e.g. the physics' choice records)

    Returns
    -------
    tuple of Item
        In the order given: item 1, 2, …

    Examples
    --------
    >>> items([Item("air", "chamber air"), Item("vacuum")])[1]
    Item(name='vacuum', description='')
    """
    return tuple(Item(c.name, c.description) for c in choices)


def spec_parameter(spec) -> Var:
    """The parameter variable of a physics parameter specification.

    Parameters
    ----------
    spec : an object with the attributes of
        :class:`servofmu.parameters.table.ParameterSpec`

    Returns
    -------
    Var
        A parameter with the specification's name, type, unit, range, variability,
        provenance and (a choice) items, its start the default (a choice: the default's item
        number).

    Examples
    --------
    >>> from servofmu.parameters.table import spec
    >>> v = spec_parameter(spec("ball_diameter"))
    >>> v.causality, v.unit, v.display_unit
    ('parameter', 'm', 'mm')
    """
    choice = spec.type == "Enumeration"
    return Var(
        name=spec.name,
        type=spec.type,
        causality="parameter",
        description=spec.description,
        start=spec.item(spec.default) if choice else spec.default,
        unit=spec.unit,
        display_unit=spec.display_unit,
        min=spec.min,
        max=spec.max,
        variability=spec.variability,
        source=spec.source,
        items=items(spec.choices),
        declared_type=spec.declared_type,
    )


def variables_of(cls, start: dict[str, tuple[object, str]] | None = None) -> tuple[Var, ...]:
    """The variables of a slave class as its modelDescription and documentation show them.

    Parameters
    ----------
    cls : a slave class (its ``VARIABLES``)
    start : {variable: (start value, provenance)} to replace the class's defaults (default:
        the class's entry of :data:`BUILD_START`)

    Returns
    -------
    tuple of Var
        ``cls.VARIABLES`` with those start values and sources.

    Raises
    ------
    ValueError
        When ``start`` names a variable the class does not have.

    Examples
    --------
    >>> class Demo:
    ...     VARIABLES = (real_input("u", "an input", start=0.0),)
    >>> variables_of(Demo, {"u": (2.0, "assumed")})[0].start
    2.0
    """
    start = BUILD_START.get(cls.__name__, {}) if start is None else start
    by_name = {v.name for v in cls.VARIABLES}
    unknown = sorted(set(start) - by_name)
    if unknown:
        raise ValueError(f"{cls.__name__}: start values for unknown variables {unknown}")
    return tuple(
        dataclasses.replace(v, start=start[v.name][0], source=start[v.name][1])
        if v.name in start
        else v
        for v in cls.VARIABLES
    )


def check_variables(variables) -> list[str]:
    """Every problem of a VARIABLES table: types, causalities, units, enumeration items, and
    outputs' dependencies naming inputs and parameters that exist.

    Parameters
    ----------
    variables : sequence of Var

    Returns
    -------
    list of str
        One message per problem; empty when the table is fine.

    Examples
    --------
    >>> u = real_input("u", "an input", start=0.0, unit="furlong")
    >>> check_variables((u, output("y", "an output", initial_depends=("u", "k"))))
    ["u: unit 'furlong' is not one of UNITS", "output y: dependencies ['k'] are not inputs/parameters"]
    """  # noqa: E501
    problems, names = [], [v.name for v in variables]
    knowns = {v.name: v.causality for v in variables if v.causality in ("input", "parameter")}
    if len(set(names)) != len(names):
        problems.append(f"duplicate variable names in {names}")
    for v in variables:
        if v.type not in FMI_TYPE or v.causality not in CAUSALITIES:
            problems.append(f"{v.name}: type {v.type!r} / causality {v.causality!r}")
        if (v.type == "Enumeration") != bool(v.items) or (v.items and not v.declared_type):
            problems.append(
                f"{v.name}: an Enumeration needs items and a declared_type, and only it"
            )
        if v.unit is not None and v.unit not in UNITS:
            problems.append(f"{v.name}: unit {v.unit!r} is not one of UNITS")
        elif v.display_unit is not None and v.display_unit not in _display_units(v.unit):
            problems.append(f"{v.name}: {v.display_unit!r} is not a display unit of {v.unit!r}")
        if v.causality != "output":
            continue
        if v.initial_depends is None:
            problems.append(f"output {v.name}: initial_depends not declared")
        wrong = [d for d in v.depends if knowns.get(d) != "input"]
        wrong += [d for d in v.initial_depends or () if d not in knowns]
        wrong += [d for d in v.depends if d not in (v.initial_depends or ())]
        if wrong:
            problems.append(f"output {v.name}: dependencies {wrong} are not inputs/parameters")
    return problems


def _display_units(unit: str | None) -> tuple[str, ...]:
    return tuple(d for d, _, _ in UNITS[unit][1]) if unit in UNITS else ()

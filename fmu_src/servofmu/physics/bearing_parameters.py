"""The flat parameter set of a bearing pair, as the BearingFriction FMU and its ``.ssv`` files
name it, and the :class:`~.bearing.BearingPair` it stands for.

One mapping, used by the FMU (its parameter table is generated from :data:`PARAMETERS`, and
``BearingFriction.configure`` calls :func:`pair_from_parameters`) and by the calibration
(``servofmu calibrate``), so that a parameter set fitted to measurements gives the same
torques inside the FMU. Values are SI (m, K, N, N/m); a choice is a catalogue key, ``""`` for
"the mounting's own". This module knows nothing of FMI: the FMU layer turns each
:class:`ParameterSpec` into a variable, and a choice's :class:`Choice` list into enumeration
items numbered 1, 2, … in the order given here (catalogue entries in the order of their file,
so that entries added at the end keep the numbers of the others).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass

from . import catalog
from .bearing import PRESSURE_LIMIT, BearingPair, with_mounting
from .friction import FrictionCoefficients

#: Catalogue mounting whose values are the defaults (Yu 2017's seeker gimbal).
DEFAULT_MOUNTING = "yu2017_gimbal"
#: Catalogue lubricant for each lubrication when none is named.
DEFAULT_LUBRICANT = {"grease": "krytox_143aa", "solid": "mos2_film"}
#: The item of a choice that means "the catalogue mounting's own" (key "").
FROM_MOUNTING = "from_mounting"


@dataclass(frozen=True)
class Choice:
    """One allowed value of a choice parameter.

    Attributes
    ----------
    key : what :func:`pair_from_parameters` receives (a catalogue key; "" = the mounting's own)
    name : the name users see and type (the FMU's enumeration item)
    description : what it stands for, in words
    """

    key: str
    name: str
    description: str


@dataclass(frozen=True, kw_only=True)
class ParameterSpec:
    """One parameter of the pair: everything an FMU variable or a report needs to know.

    Attributes
    ----------
    name : public name (FMU variable, ``.ssv`` parameter, calibration key)
    type : "Real" or "Enumeration" (a choice among :attr:`choices`)
    description : one line
    group : the part of the model it enters (:data:`GROUPS`); the FMU declares which outputs
        depend on which groups
    unit, display_unit : SI unit and display unit (Real)
    min, max : valid range, inclusive (Real)
    variability : "fixed" or "tunable" (changeable between steps)
    choices : the allowed values of an Enumeration, in item order
    declared_type : name of the enumeration type (several parameters may share one)
    default : the value of :data:`DEFAULT_MOUNTING` (SI, or a catalogue key)
    source : provenance of the default
    """

    name: str
    type: str
    description: str
    group: str
    unit: str | None = None
    display_unit: str | None = None
    min: float | None = None
    max: float | None = None
    variability: str = "fixed"
    choices: tuple[Choice, ...] = ()
    declared_type: str | None = None
    default: object = None
    source: str = ""

    def item(self, key: str) -> int:
        """The enumeration value (1, 2, …) of catalogue key ``key``; ValueError when it is not
        one of the choices."""
        for i, c in enumerate(self.choices, start=1):
            if c.key == key:
                return i
        raise ValueError(
            f"{self.name} = {key!r} is not one of {[c.key or c.name for c in self.choices]}"
        )

    def key(self, value: int) -> str:
        """The catalogue key of enumeration value ``value`` (1-based); ValueError outside."""
        if not 1 <= value <= len(self.choices):
            raise ValueError(f"{self.name} = {value!r} is not an item 1…{len(self.choices)}")
        return self.choices[value - 1].key


#: Groups of parameters by the part of the model they enter.
GROUPS = {
    "fit": "geometry, materials and radial fits: clearance, fit interference, contact geometry",
    "loop": "axial preload loop: shim, assembly preload, loop stiffness",
    "lubrication": "grease or dry film: viscous term, race of spin, differential sliding",
    "lubricant": "the grease's viscosity model",
    "hysteresis": "elastic hysteresis loss",
    "sliding": "sliding friction of spin and differential sliding",
    "breakaway": "static over kinetic friction",
    "viscous": "Palmgren factor",
    "regularisation": "smooth sign and breakaway decay through zero speed",
    "limit": "overload pressure",
}


def catalogue_choices(table: str, empty: Choice | None = None) -> tuple[Choice, ...]:
    """The entries of catalogue ``table`` as choices (item name = key, in file order), after
    ``empty`` (the meaning of key "") when given.

    >>> [c.name for c in catalogue_choices("lubricants")]
    ['krytox_143aa', 'iso_vg32', 'mos2_film']
    """
    first = () if empty is None else (empty,)
    return first + tuple(Choice(k, k, t) for k, t in catalog.titles(table).items())


def _own(what: str) -> Choice:
    return Choice("", FROM_MOUNTING, f"the catalogue mounting's own {what}")


_LUBRICATIONS = (
    Choice("grease", "grease", "grease or oil: viscous Palmgren torque (Yu 2017 eq 8-9)"),
    Choice("solid", "solid", "dry film: no viscous term, differential sliding (Ning)"),
)


def _real(name, description, group, unit, display, lo, hi, variability="fixed"):
    return ParameterSpec(
        name=name,
        type="Real",
        description=description,
        group=group,
        unit=unit,
        display_unit=display,
        min=lo,
        max=hi,
        variability=variability,
    )


def _choice(name, description, group, declared_type, choices):
    return ParameterSpec(
        name=name,
        type="Enumeration",
        description=description,
        group=group,
        declared_type=declared_type,
        choices=choices,
    )


def _table() -> tuple[ParameterSpec, ...]:
    bearings = catalogue_choices("bearings", _own("bearing"))
    materials = catalogue_choices("materials", _own("material"))
    return (
        _choice(
            "mounting",
            "Catalogue mounting: loop geometry, seats and base of the pair",
            "fit",
            "Mounting",
            catalogue_choices("mountings"),
        ),
        _choice("bearing", "Catalogue bearing designation", "fit", "Bearing", bearings),
        _choice(
            "lubrication",
            "grease (Yu eq 9) or solid (Ning: no viscous term)",
            "lubrication",
            "Lubrication",
            _LUBRICATIONS,
        ),
        _choice(
            "lubricant",
            "Catalogue lubricant (viscosity model) for grease lubrication",
            "lubricant",
            "Lubricant",
            catalogue_choices("lubricants"),
        ),
        _choice("frame_material", "Material of frame/housing", "fit", "Material", materials),
        _choice("shaft_material", "Material of the shaft", "fit", "Material", materials),
        _real(
            "outer_interference",
            "Diametral interference of outer ring and housing bore at assembly",
            "fit",
            "m",
            "um",
            -1.0e-3,
            1.0e-3,
        ),
        _real(
            "inner_interference",
            "Diametral interference of shaft and inner ring at assembly",
            "fit",
            "m",
            "um",
            -1.0e-3,
            1.0e-3,
        ),
        _real(
            "shim",
            "Axial interference added after the play is taken up at assembly",
            "loop",
            "m",
            "mm",
            -1.0e-3,
            1.0e-3,
        ),
        _real(
            "assembly_preload",
            "Preload at assembly; 0: set by the shim",
            "loop",
            "N",
            None,
            0.0,
            1e5,
        ),
        _real(
            "assembly_temperature",
            "Temperature at which fits and shim are set",
            "fit",
            "K",
            "degC",
            173.15,
            473.15,
        ),
        _real(
            "loop_stiffness",
            "Structural axial stiffness of the preload loop; 0: from the parts' E·A/L",
            "loop",
            "N/m",
            None,
            0.0,
            1.0e13,
        ),
        _real(
            "hysteresis_loss",
            "Elastic hysteresis loss factor α_r",
            "hysteresis",
            "1",
            None,
            0.0,
            1.0,
            "tunable",
        ),
        _real(
            "sliding_friction",
            "Sliding friction coefficient μ (spin, differential sliding)",
            "sliding",
            "1",
            None,
            0.0,
            2.0,
            "tunable",
        ),
        _real(
            "static_friction_ratio",
            "Static over kinetic friction coefficient (breakaway)",
            "breakaway",
            "1",
            None,
            1.0,
            10.0,
            "tunable",
        ),
        _real(
            "palmgren_s0",
            "Palmgren factor s0 (Yu eq 8)",
            "viscous",
            "1",
            None,
            0.0,
            100.0,
            "tunable",
        ),
        _real(
            "regularisation_speed",
            "Width of the smooth sign through zero speed",
            "regularisation",
            "rad/s",
            None,
            1.0e-9,
            1.0e3,
            "tunable",
        ),
        _real(
            "stribeck_speed",
            "Decay speed of the breakaway excess",
            "regularisation",
            "rad/s",
            None,
            1.0e-9,
            1.0e3,
            "tunable",
        ),
        _real(
            "pressure_limit",
            "Hertz pressure at which the pair counts as overloaded (permanent deformation)",
            "limit",
            "Pa",
            "MPa",
            1.0e8,
            1.0e11,
        ),
    )


def default_parameters(mounting: str, lubrication: str = "grease") -> dict[str, object]:
    """The parameter set of catalogue mounting ``mounting`` (``data/mountings.toml``) with its
    friction coefficients (``data/coefficients.toml``; the library defaults when the mounting
    has none) and ``lubrication`` ("grease" or "solid") with its default lubricant.

    >>> default_parameters("yu2017_gimbal")["shim"]
    3e-05
    """
    mnt = catalog.mounting(mounting)
    coef = _coefficients(mounting)
    if lubrication not in DEFAULT_LUBRICANT:
        raise ValueError(f"lubrication = {lubrication!r} is not one of {sorted(DEFAULT_LUBRICANT)}")
    return {
        "mounting": mounting,
        "bearing": "",
        "lubrication": lubrication,
        "lubricant": DEFAULT_LUBRICANT[lubrication],
        "frame_material": "",
        "shaft_material": "",
        "outer_interference": mnt.fit.outer_interference,
        "inner_interference": mnt.fit.inner_interference,
        "shim": mnt.loop.shim,
        "assembly_preload": mnt.assembly_preload or 0.0,
        "assembly_temperature": mnt.assembly_temperature,
        "loop_stiffness": mnt.loop.stiffness or 0.0,
        "hysteresis_loss": coef.hysteresis_loss,
        "sliding_friction": coef.sliding_friction,
        "static_friction_ratio": coef.static_friction_ratio,
        "palmgren_s0": coef.palmgren_s0 if lubrication == "grease" else 0.0,
        "regularisation_speed": 1.0e-3,
        "stribeck_speed": 1.0e-2,
        "pressure_limit": PRESSURE_LIMIT,
    }


def _coefficients(mounting: str) -> FrictionCoefficients:
    return catalog.mounting_coefficients(mounting) or FrictionCoefficients()


def default_sources(mounting: str) -> dict[str, str]:
    """Provenance of each value of :func:`default_parameters` (``mounting``, grease), read
    from the catalogue records.

    >>> default_sources("yu2017_gimbal")["shim"].startswith("paper: Yu 2017")
    True
    """
    mnt, coef = catalog.mounting(mounting), _coefficients(mounting)
    catalogue = "catalogue: data/mountings.toml"
    sources = {
        "mounting": f"{catalogue} [{mounting}]",
        "bearing": f"catalogue: data/bearings.toml (the mounting's {mnt.bearing_key})",
        "lubrication": "paper: Yu 2017",
        "lubricant": "paper: Yu 2017 eq 18",
        "frame_material": f"{catalogue}: {mnt.fit.housing_material.name}",
        "shaft_material": f"{catalogue}: {mnt.fit.shaft_material.name}",
        "assembly_preload": mnt.source("assembly_preload") or "assumed: 0 = use the shim",
        "loop_stiffness": mnt.source("loop_stiffness")
        or "derived: Σ L/(E·A) of the mounting's loop members",
        "regularisation_speed": "assumed",
        "stribeck_speed": "assumed",
        "pressure_limit": "handbook: ISO 76, 4200 MPa for ball bearings",
    }
    for field in ("outer_interference", "inner_interference", "shim", "assembly_temperature"):
        sources[field] = mnt.source(field)
    for field in ("hysteresis_loss", "sliding_friction", "static_friction_ratio", "palmgren_s0"):
        sources[field] = coef.source(field) or "assumed: library default"
    return sources


def parameter_specs(mounting: str = DEFAULT_MOUNTING) -> tuple[ParameterSpec, ...]:
    """Every parameter of the pair with the default and provenance of catalogue mounting
    ``mounting`` (grease lubrication).

    >>> [p.name for p in parameter_specs()][:3]
    ['mounting', 'bearing', 'lubrication']
    """
    values, sources = default_parameters(mounting), default_sources(mounting)
    return tuple(
        dataclasses.replace(p, default=values[p.name], source=sources[p.name]) for p in _table()
    )


#: The parameters of the pair with the defaults of :data:`DEFAULT_MOUNTING`, in the order of
#: the FMU's modelDescription.
PARAMETERS = parameter_specs()
#: Their names.
PARAMETER_NAMES = tuple(p.name for p in PARAMETERS)
_BY_NAME = {p.name: p for p in PARAMETERS}


def parameter(name: str) -> ParameterSpec:
    """The :class:`ParameterSpec` ``name`` of :data:`PARAMETERS`.

    >>> parameter("lubrication").item("solid")
    2
    """
    try:
        return _BY_NAME[name]
    except KeyError:
        raise ValueError(f"parameter {name!r} is not one of {list(PARAMETER_NAMES)}") from None


def parameters_in(*groups: str) -> tuple[str, ...]:
    """Names of the parameters in ``groups`` (keys of :data:`GROUPS`), in table order.

    >>> parameters_in("loop")
    ('shim', 'assembly_preload', 'loop_stiffness')
    """
    unknown = sorted(set(groups) - set(GROUPS))
    if unknown:
        raise ValueError(f"groups {unknown} are not among {sorted(GROUPS)}")
    return tuple(p.name for p in PARAMETERS if p.group in groups)


def pair_from_parameters(p: Mapping[str, object]) -> BearingPair:
    """The :class:`BearingPair` of parameter set ``p`` (every name of
    :data:`PARAMETER_NAMES`). ``loop_stiffness`` 0 means "from the parts' E·A/L",
    ``assembly_preload`` 0 means "set by the shim", empty material or bearing keys the
    mounting's own. Raises ValueError (naming the parameter) on a bad key or value."""
    missing = [n for n in PARAMETER_NAMES if n not in p]
    if missing:
        raise ValueError(f"parameter set lacks {missing}")
    mnt = catalog.mounting(p["mounting"])
    fit, loop = mnt.fit, mnt.loop
    if p["frame_material"]:
        frame = catalog.material(p["frame_material"])
        fit = dataclasses.replace(fit, housing_material=frame)
        loop = _with_member_material(loop, ("frame", "housing"), frame)
    if p["shaft_material"]:
        shaft = catalog.material(p["shaft_material"])
        fit = dataclasses.replace(fit, shaft_material=shaft)
        loop = _with_member_material(loop, ("shaft",), shaft)
    solid = p["lubrication"] == "solid"
    pair = BearingPair(
        bearing=catalog.bearing(p["bearing"] or mnt.bearing_key),
        mounting=dataclasses.replace(mnt, fit=fit, loop=loop),
        lubrication=p["lubrication"],
        lubricant=None if solid else catalog.lubricant(p["lubricant"]),
        coefficients=FrictionCoefficients(
            hysteresis_loss=p["hysteresis_loss"],
            sliding_friction=p["sliding_friction"],
            static_friction_ratio=p["static_friction_ratio"],
            palmgren_s0=p["palmgren_s0"],
        ),
        regularisation_speed=p["regularisation_speed"],
        stribeck_speed=p["stribeck_speed"],
        pressure_limit=p["pressure_limit"],
    )
    return with_mounting(
        pair,
        outer_interference=p["outer_interference"],
        inner_interference=p["inner_interference"],
        shim=p["shim"],
        assembly_temperature=p["assembly_temperature"],
        loop_stiffness=p["loop_stiffness"] or None,
        assembly_preload=p["assembly_preload"] or None,
    )


def _with_member_material(loop, names, material):
    members = tuple(
        dataclasses.replace(m, material=material) if m.name in names else m for m in loop.members
    )
    return dataclasses.replace(loop, members=members)

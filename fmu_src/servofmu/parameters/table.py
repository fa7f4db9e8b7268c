"""The table of a bearing pair's parameters: name, type, unit, range, group and meaning of
each (:class:`ParameterSpec`), and the items of its choices (:class:`Choice`). No defaults
here: :mod:`.parameters.presets` fills them from the catalogue, and :mod:`.parameters.bearing` maps
the numbers to the physics. One more parameter (or one more choice) is one more entry of
:func:`_table`.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..physics.contact.geometry import MAX_CONTACT_ANGLE
from ..physics.friction import registry
from ..physics.pair.mounting import PRELOAD_METHODS
from ..physics.pair.preload import ARRANGEMENTS, LOOP_MODELS


@dataclass(frozen=True)
class Choice:
    """One allowed value of a choice parameter.

    Attributes
    ----------
    key : what :func:`pair_from_parameters` receives
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
    type : "Real", "Integer" or "Enumeration" (a choice among :attr:`choices`)
    description : one line
    group : the part of the model it enters (:data:`GROUPS`); the FMU declares which outputs
        depend on which groups
    unit, display_unit : SI unit and display unit (Real)
    min, max : valid range, inclusive (Real, Integer)
    variability : "fixed" or "tunable" (changeable between steps)
    choices : the allowed values of an Enumeration, in item order
    declared_type : name of the enumeration type (several parameters may share one)
    default : the value of :data:`DEFAULT_MOUNTING` (SI, or a choice key)
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
        """The enumeration value (1, 2, …) of choice key ``key``; ValueError when it is not
        one of the choices."""
        for i, c in enumerate(self.choices, start=1):
            if c.key == key:
                return i
        raise ValueError(f"{self.name} = {key!r} is not one of {[c.key for c in self.choices]}")

    def key(self, value: int) -> str:
        """The choice key of enumeration value ``value`` (1-based); ValueError outside."""
        if not 1 <= value <= len(self.choices):
            raise ValueError(f"{self.name} = {value!r} is not an item 1…{len(self.choices)}")
        return self.choices[value - 1].key


#: Groups of parameters by the part of the model they enter.
GROUPS = {
    "fit": "bearing geometry, materials and radial fits: clearance, fits, contact geometry",
    "loop": "axial preload loop: arrangement, members, yoke, preload method, loop stiffness",
    "lubrication": "grease or dry film: viscous term, race of spin, differential sliding",
    "lubricant": "the grease's viscosity model and the range of its data",
    "hysteresis": "elastic hysteresis loss",
    "sliding": "sliding friction of spin and differential sliding",
    "breakaway": "static over kinetic friction",
    "viscous": "Palmgren factor",
    "regularisation": "smooth sign and breakaway decay through zero speed",
    "limit": "overload pressure",
    "friction_model": "which friction model: Yu 2017, SKF 2004 or the contacts' EHL rolling",
    "skf": "the SKF model's series constants and friction coefficients",
    "density": "the (base) oil's density (EHL rolling torque)",
    "grease": "the grease term's factor f0 (running torque)",
    "grease_start": "the cold start: the lubricant's starting ratio and test speed (breakaway)",
}

_LUBRICATIONS = (
    Choice("grease", "grease", "grease or oil: viscous Palmgren torque (Yu 2017 eq 8-9)"),
    Choice("solid", "solid", "dry film: no viscous term, differential sliding (Ning)"),
)
_BELOW_FLOW_LIMIT = (
    Choice("hold", "hold", "the viscosity held at its value at the flow limit (finite torques)"),
    Choice("extrapolate", "extrapolate", "the viscosity law extrapolated on (its steep rise)"),
)
_ARRANGEMENTS = (
    Choice(
        "face_to_face",
        "face_to_face",
        "DF (X): the housing around the outer rings is stretched by the preload; a growing "
        "shaft raises the preload, a growing housing relieves it",
    ),
    Choice(
        "back_to_back",
        "back_to_back",
        "DB (O): the shaft between shoulder and nut is stretched by the preload; a growing "
        "shaft relieves the preload, a growing housing raises it",
    ),
    Choice(
        "tandem",
        "tandem",
        "DT: both bearings face the same way and share the thrust of a spring or force preload "
        "(preload_method spring or force) and the axial load; a shaft growing against the "
        "housing between them shifts the thrust onto bearing B",
    ),
)
_PRELOAD_METHODS = (
    Choice("shim", "shim", "rigid: the shim (axial interference) sets the preload"),
    Choice("force", "force", "assembly_preload at the assembly temperature, then rigid"),
    Choice(
        "spring",
        "spring",
        "a spring of spring_stiffness compressed by spring_compression, in series with the "
        "structure",
    ),
)
_LOOP_MODELS = (
    Choice("members", "members", "the structure's compliance is Σ L/(E·A) of the members"),
    Choice("yoke", "yoke", "the housing is a yoke whose arms bend (cantilevers, E·I/L³)"),
)
_LOOP_READINGS = (
    Choice("stated", "stated", "each loop member of its part's material, the ring widths grow"),
    Choice(
        "printed",
        "printed",
        "Yu 2017 eq 14 as printed: housing members with the shaft material's α and E, shaft "
        "members with the housing material's, the ring widths not counted",
    ),
)
assert {c.key for c in _ARRANGEMENTS} == set(ARRANGEMENTS)
assert tuple(c.key for c in _PRELOAD_METHODS) == PRELOAD_METHODS
assert tuple(c.key for c in _LOOP_MODELS) == LOOP_MODELS


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


def _integer(name, description, group, lo, hi):
    return ParameterSpec(
        name=name, type="Integer", description=description, group=group, min=lo, max=hi
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


def _material_specs(prefix: str, what: str, group: str, poisson: bool = True) -> tuple:
    specs = [
        _real(f"{prefix}_youngs_modulus", f"Young's modulus of {what}", group, "Pa", "GPa",
              1.0e8, 1.0e13),
        _real(f"{prefix}_poisson_ratio", f"Poisson's ratio of {what}", group, "1", None,
              0.0, 0.499),
        _real(f"{prefix}_expansion", f"Linear thermal expansion coefficient of {what}", group,
              "1/K", None, -1.0e-4, 1.0e-4),
    ]  # fmt: skip
    return tuple(specs if poisson else (specs[0], specs[2]))


def _length(name, description, group, lo=0.0, hi=10.0, display="mm"):
    return _real(name, description, group, "m", display, lo, hi)


def _table() -> tuple[ParameterSpec, ...]:
    return (
        # ---- the bearing (datasheet and internal design); group fit
        _length("bore", "Bore diameter d of each bearing", "fit", 1.0e-4),
        _length("outer_diameter", "Outside diameter D of each bearing", "fit", 1.0e-4),
        _length(
            "width", "Width B of each bearing (the rings' widths count in the loop)", "fit", 1.0e-5
        ),
        _length("ball_diameter", "Ball diameter Dw", "fit", 1.0e-5),
        _integer("n_balls", "Number of balls Z per bearing", "fit", 3, 1000),
        _length(
            "pitch_diameter", "Pitch diameter dm (mean of the groove diameters)", "fit", 1.0e-4
        ),
        _real(
            "nominal_contact_angle",
            "Free contact angle α0 of the unmounted bearing (sets "
            "its clearance; the output contact_angle is the operating one)",
            "fit",
            "rad",
            "deg",
            0.0,
            MAX_CONTACT_ANGLE,
        ),
        _real(
            "inner_curvature",
            "Inner groove curvature f_i = r_i/Dw (> 0.5)",
            "fit",
            "1",
            None,
            0.5,
            1.0,
        ),
        _real(
            "outer_curvature",
            "Outer groove curvature f_o = r_o/Dw (> 0.5)",
            "fit",
            "1",
            None,
            0.5,
            1.0,
        ),
        *_material_specs("ring", "the bearing rings", "fit"),
        *_material_specs("ball", "the balls", "fit"),
        # ---- seats (Yu eq 10-13); group fit
        *_material_specs("housing", "the housing (frame)", "fit"),
        *_material_specs("shaft", "the shaft", "fit"),
        _length(
            "housing_outer_diameter",
            "Outside diameter of the housing around the outer ring (Lamé annulus)",
            "fit",
            1.0e-4,
        ),
        _real(
            "outer_interference",
            "Diametral interference of outer ring and housing bore at "
            "assembly (negative: clearance)",
            "fit",
            "m",
            "um",
            -1.0e-3,
            1.0e-3,
        ),
        _length("shaft_bore", "Bore of a hollow shaft (0: solid)", "fit"),
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
            "assembly_temperature",
            "Temperature at which fits and preload are set",
            "fit",
            "K",
            "degC",
            173.15,
            473.15,
        ),
        # ---- the axial preload loop (Yu eq 14-15); group loop
        _choice(
            "arrangement",
            "How the two bearings face each other (decides which parts' growth raises the preload, "
            "or in tandem how the thrust is shared)",
            "loop",
            "Arrangement",
            _ARRANGEMENTS,
        ),
        _length(
            "housing_length",
            "Housing in the loop: between the outer-ring abutments (tandem: between the two "
            "outer rings; 0: none)",
            "loop",
        ),
        _real(
            "housing_area",
            "Axial section of the housing member (0: rigid, not counted)",
            "loop",
            "m2",
            "mm2",
            0.0,
            10.0,
        ),
        _length(
            "shaft_length",
            "Shaft in the loop: between the inner-ring abutments (tandem: between the two inner "
            "rings; 0: none)",
            "loop",
        ),
        _real(
            "shaft_area",
            "Axial section of the shaft member (0: rigid, not counted)",
            "loop",
            "m2",
            "mm2",
            0.0,
            10.0,
        ),
        _length("spacer_length", "Spacer between the bearings in the loop (0: none)", "loop"),
        _real(
            "spacer_area",
            "Axial section of the spacer (0: rigid, not counted)",
            "loop",
            "m2",
            "mm2",
            0.0,
            10.0,
        ),
        *_material_specs("spacer", "the spacer", "loop", poisson=False),
        _choice(
            "loop_model",
            "Compliance of the structure: members (E·A/L) or a yoke whose arms bend",
            "loop",
            "LoopModel",
            _LOOP_MODELS,
        ),
        _integer(
            "arm_count", "Yoke arms the loop passes through (loop_model yoke)", "loop", 1, 100
        ),
        _length(
            "arm_length",
            "Yoke arm from its root to the bearing centre (housing material)",
            "loop",
            1.0e-5,
        ),
        _length("arm_width", "Yoke arm section across the bending plane", "loop", 1.0e-5),
        _length("arm_thickness", "Yoke arm section along the shaft axis", "loop", 1.0e-5),
        _real(
            "loop_stiffness",
            "Structural axial stiffness of the preload loop; 0: from the members or the yoke",
            "loop",
            "N/m",
            "N/um",
            0.0,
            1.0e13,
        ),
        _choice(
            "loop_reading",
            "Yu 2017 eq 14 as stated or as printed (materials swapped)",
            "loop",
            "LoopReading",
            _LOOP_READINGS,
        ),
        _choice(
            "preload_method",
            "How the preload is set at assembly",
            "loop",
            "PreloadMethod",
            _PRELOAD_METHODS,
        ),
        _real(
            "shim",
            "Axial interference added after the play is taken up (preload_method shim)",
            "loop",
            "m",
            "mm",
            -1.0e-3,
            1.0e-3,
        ),
        _real(
            "assembly_preload",
            "Preload at the assembly temperature (preload_method force)",
            "loop",
            "N",
            None,
            0.0,
            1.0e5,
        ),
        _real(
            "spring_stiffness",
            "Preload spring rate (preload_method spring)",
            "loop",
            "N/m",
            "N/um",
            0.0,
            1.0e13,
        ),
        _length(
            "spring_compression",
            "Preload spring compression at assembly (preload_method spring)",
            "loop",
            0.0,
            1.0,
        ),
        # ---- lubrication and lubricant
        _choice(
            "lubrication",
            "grease (Yu eq 9) or solid (Ning: no viscous term)",
            "lubrication",
            "Lubrication",
            _LUBRICATIONS,
        ),
        _real(
            "lubricant_viscosity_40",
            "Kinematic viscosity of the (base) oil at 40 °C",
            "lubricant",
            "m2/s",
            "cSt",
            1.0e-8,
            1.0,
        ),
        _real(
            "lubricant_viscosity_100",
            "Kinematic viscosity of the (base) oil at 100 °C",
            "lubricant",
            "m2/s",
            "cSt",
            1.0e-8,
            1.0,
        ),
        _real(
            "lubricant_walther_c",
            "Additive constant c of Walther's lg lg(ν + c) (ASTM D341: 0.7 cSt)",
            "lubricant",
            "m2/s",
            "cSt",
            1.0e-9,
            1.0e-5,
        ),
        # ---- friction coefficients and numerics
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
        # ---- appended in the order they came, so that earlier value references stay
        *_friction_model_specs(),
        *_lubricant_range_specs(),
    )


def _lubricant_range_specs() -> tuple[ParameterSpec, ...]:
    """The range of the lubricant's data and its optional third viscosity point."""
    return (
        _real(
            "lubricant_minimum_temperature",
            "The lubricant's flow limit: its pour point, else the maker's lower operating "
            "temperature (below it lubricant_below_flow_limit: the viscosity held at its value "
            "there, or the law extrapolated). 0: none published: the law is extrapolated below "
            "the data at every temperature",
            "lubricant",
            "K",
            "degC",
            0.0,
            1.0e4,
        ),
        _real(
            "lubricant_maximum_temperature",
            "Upper end of the lubricant's data: the maker's upper operating temperature, else "
            "its highest published viscosity (above it: outside_lubricant_range)",
            "lubricant",
            "K",
            "degC",
            1.0,
            1.0e4,
        ),
        _real(
            "lubricant_viscosity_cold",
            "A third viscosity of the (base) oil, at lubricant_cold_temperature: with it the "
            "viscosity is Vogel's law through the three points (0: none, the ASTM D341 line "
            "through ν40 and ν100)",
            "lubricant",
            "m2/s",
            "cSt",
            0.0,
            100.0,
        ),
        _real(
            "lubricant_cold_temperature",
            "Temperature of lubricant_viscosity_cold (0: none)",
            "lubricant",
            "K",
            "degC",
            0.0,
            1.0e4,
        ),
        # ---- declared after BearingFriction's appended outputs (LATER_PARAMETERS)
        _real(
            "lubricant_data_minimum_temperature",
            "Coldest temperature the lubricant's viscosity data reach (a paper's fit: the "
            "coldest temperature it was used at); below it outside_lubricant_range and the law "
            "extrapolated down to the flow limit. 0: its coldest viscosity point (40 °C, or "
            "lubricant_cold_temperature)",
            "lubricant",
            "K",
            "degC",
            0.0,
            1.0e4,
        ),
        _choice(
            "lubricant_below_flow_limit",
            "Below lubricant_minimum_temperature (the flow limit: no law holds there): hold the "
            "viscosity at its value at the limit, or extrapolate the law; "
            "outside_lubricant_range stays set either way",
            "lubricant",
            "BelowFlowLimit",
            _BELOW_FLOW_LIMIT,
        ),
    )


#: Parameters that BearingFriction declares after its outputs that were appended before them
#: (pythonfmu numbers value references in declaration order: new variables come last).
LATER_PARAMETERS = ("lubricant_data_minimum_temperature", "lubricant_below_flow_limit")


def _skf(name, description, lo, hi):
    return _real(f"skf_{name}", f"SKF model: {description}", "skf", "1", None, lo, hi)


def _friction_model_specs() -> tuple[ParameterSpec, ...]:
    """The friction-model choice (its items from :mod:`~servofmu.physics.friction.registry`,
    in its order) and the SKF model's numbers."""
    models = registry.entries()
    first, *others = (m.name for m in models)
    return (
        _choice(
            "friction_model",
            f"Friction model: {first} (default), {registry.listed(others)}",
            "friction_model",
            "FrictionModel",
            tuple(Choice(m.name, m.name, m.description) for m in models),
        ),
        _skf("r1", "rolling constant R1 (Table 2b; catalogue units)", 1.0e-12, 1.0),
        _skf("r2", "rolling constant R2 of the axial load", 1.0e-6, 100.0),
        _skf("r3", "rolling constant R3 of the centrifugal load", 0.0, 1.0e-6),
        _skf("s1", "sliding constant S1 (Table 2b; catalogue units)", 1.0e-12, 1.0),
        _skf("s2", "sliding constant S2 of the axial load", 1.0e-6, 1000.0),
        _skf("s3", "sliding constant S3 of the centrifugal load", 0.0, 1.0e-6),
        _skf("kz", "geometry constant Kz of the replenishment factor", 1.0e-3, 100.0),
        _skf(
            "replenishment",
            "replenishment/starvation constant Krs (6e-8 grease, 3e-8 oil bath)",
            0.0,
            1.0e-5,
        ),
        _skf("boundary_friction", "boundary sliding coefficient μbl (≈ 0.15)", 0.0, 1.0),
        _skf("film_friction", "full-film sliding coefficient μEHL (0.05 mineral)", 0.0, 1.0),
        _real(
            "lubricant_density",
            "Density of the (base) oil: dynamic viscosity ν·ρ of the EHL rolling torque",
            "density",
            "kg/m3",
            "g/cm3",
            100.0,
            5000.0,
        ),
        _real(
            "grease_f0",
            "Grease term: Palmgren factor f0 calibrated on a datasheet torque (0: off)",
            "grease",
            "1",
            None,
            0.0,
            1.0e5,
        ),
        _real(
            "grease_starting_ratio",
            "Cold start: the lubricant's starting/running torque ratio ks in its published "
            "starting-torque test; the breakaway after a soak at rest adds ks times the "
            "lubricant's torque at grease_reference_speed. 0: no starting data "
            "(breakaway_lower_bound)",
            "grease_start",
            "1",
            None,
            0.0,
            1000.0,
        ),
        _real(
            "grease_reference_speed",
            "Cold start: speed of the starting-torque test (ks holds there)",
            "grease_start",
            "rad/s",
            "rpm",
            1.0e-6,
            1.0e4,
        ),
    )


#: Every parameter (without default), in the order of the FMU's modelDescription.
TABLE = _table()
#: The parameter names, in the order of the FMU's modelDescription.
PARAMETER_NAMES = tuple(p.name for p in TABLE)
_SPEC = {p.name: p for p in TABLE}
#: The numbers of each preset kind (what :func:`.parameters.presets.resolve` replaces for a named
# preset).
BEARING_FIELDS = PARAMETER_NAMES[: PARAMETER_NAMES.index("ball_expansion") + 1]
LUBRICANT_FIELDS = (
    "lubrication",
    "lubricant_viscosity_40",
    "lubricant_viscosity_100",
    "lubricant_walther_c",
    "lubricant_density",
    "skf_film_friction",
    "lubricant_minimum_temperature",
    "lubricant_maximum_temperature",
    "lubricant_viscosity_cold",
    "lubricant_cold_temperature",
    "lubricant_data_minimum_temperature",
    # the grease term of its published low-temperature torques (its cold start; 0: none)
    "grease_f0",
    "grease_starting_ratio",
    "grease_reference_speed",
)
#: The SKF series constants: a bearing preset sets them (its series, or the fallback).
SKF_SERIES_FIELDS = ("skf_r1", "skf_r2", "skf_r3", "skf_s1", "skf_s2", "skf_s3", "skf_kz")


def spec(name: str) -> ParameterSpec:
    """The :class:`ParameterSpec` ``name`` of :data:`TABLE` (no default); ValueError
    naming the known ones.

    Returns
    -------
    ParameterSpec
        Its name, type, unit (SI), range, group and description.

    Examples
    --------
    >>> spec("n_balls").type
    'Integer'
    """
    try:
        return _SPEC[name]
    except KeyError:
        raise ValueError(f"parameter {name!r} is not one of {list(PARAMETER_NAMES)}") from None


def parameters_in(*groups: str) -> tuple[str, ...]:
    """Names of the parameters in ``groups`` (keys of :data:`GROUPS`), in table order.

    Returns
    -------
    tuple of str
        The parameter names.

    Examples
    --------
    >>> parameters_in("lubricant")[:3]
    ('lubricant_viscosity_40', 'lubricant_viscosity_100', 'lubricant_walther_c')
    """
    unknown = sorted(set(groups) - set(GROUPS))
    if unknown:
        raise ValueError(f"groups {unknown} are not among {sorted(GROUPS)}")
    return tuple(p.name for p in TABLE if p.group in groups)


#: The parameters that set a pair's thermal and load state (bearing, materials, seats, loop,
#: preload): what a pair contributes as a stiffness (ActuatorStiffness's support bearings).
STATE_PARAMETERS = parameters_in("fit", "loop")

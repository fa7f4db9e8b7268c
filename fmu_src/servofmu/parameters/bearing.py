"""The flat parameter set of a bearing pair, as the BearingFriction FMU and its ``.ssv`` files
name it, and the :class:`~servofmu.physics.bearing.BearingPair` it stands for.

One mapping, used by the FMU (its parameter table is generated from :data:`PARAMETERS`, and
``BearingFriction.configure`` calls :func:`pair_from_parameters`), by the calibration
(``servofmu calibrate``) and by the sweeps, so that a parameter set fitted to measurements gives
the same torques inside the FMU. This module knows nothing of FMI: the FMU layer turns each
:class:`~.parameters.table.ParameterSpec` into a variable, and a choice's
:class:`~.parameters.table.Choice` list into enumeration items numbered 1, 2, … (the table:
:mod:`.parameters.table`; the presets: :mod:`.parameters.presets`).

**Numbers define, presets fill.** Every physical input of the model is a number here (SI: m,
K, N, N/m, Pa, 1/K, m²/s): the bearing's internal geometry, the materials of rings, balls,
housing, shaft and spacer, the seats, the loop geometry, the preload, the lubricant's
viscosity, the friction coefficients. The model uses exactly these numbers
(:func:`pair_from_parameters`, no catalogue lookup). A catalogue entry (mounting, bearing,
lubricant of ``data/*.toml`` or of a user catalogue) is a *preset*: :func:`default_parameters`
turns it into the numbers, with each value's provenance (:func:`default_sources`). Presets are
applied where the order of things is defined: at build time (the FMU's start values are the
default preset's numbers, ``servofmu build --preset``), in a parameter set written from a preset
(``servofmu catalog --ssv``), and in the library (:func:`resolve`: the presets a change names
first, then its numbers). An FMU has no preset choice at run time: engines set parameters in
no defined order, and a preset choice that overrode numbers (or numbers that overrode a preset)
would silently depend on it.

The choices that remain are structural: ``lubrication``, ``arrangement``, ``preload_method``,
``loop_model``, ``loop_reading`` and ``friction_model``. One more choice is one more
``_choice`` entry of ``parameter_table._table`` (and its use in :func:`pair_from_parameters`).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping

from ..physics.contact.geometry import BallBearing, bearing_geometry_problems
from ..physics.friction.grease import GreaseTorqueTerm
from ..physics.friction.models import FrictionModel, model_numbers
from ..physics.friction.terms import FrictionCoefficients
from ..physics.kernels.units import CST
from ..physics.lubrication.viscosity import T40, T100, viscosity_model
from ..physics.materials import Material
from ..physics.pair.configuration import BearingPair
from ..physics.pair.mounting import Mounting
from ..physics.pair.preload import ARRANGEMENTS, TANDEM, LoopMember, PreloadLoop, YokeArm
from ..physics.thermal.fits import RadialFit
from .presets import (
    DEFAULT_LUBRICANT,
    DEFAULT_MOUNTING,
    PRESETS,
    bearing_values,
    default_parameters,
    default_sources,
    lubricant_values,
    resolve,
    walther_c_si,
)
from .table import (
    BEARING_FIELDS,
    GROUPS,
    LUBRICANT_FIELDS,
    PARAMETER_NAMES,
    STATE_PARAMETERS,
    TABLE,
    Choice,
    ParameterSpec,
    parameters_in,
    spec,
)

__all__ = [
    "BEARING_FIELDS",
    "DEFAULT_LUBRICANT",
    "DEFAULT_MOUNTING",
    "GROUPS",
    "LUBRICANT_FIELDS",
    "PARAMETERS",
    "PARAMETER_NAMES",
    "PRESETS",
    "STATE_PARAMETERS",
    "Choice",
    "ParameterSpec",
    "bearing_from_parameters",
    "bearing_values",
    "default_parameters",
    "default_sources",
    "lubricant_values",
    "pair_from_parameters",
    "parameter",
    "parameter_problems",
    "parameter_specs",
    "parameters_in",
    "prefixed_specs",
    "resolve",
    "walther_c_si",
]


def parameter_specs(values: Mapping | None = None, sources: Mapping | None = None):
    """Every parameter of the pair with the defaults ``values`` and their provenance
    ``sources`` (default: :data:`DEFAULT_MOUNTING` with grease).

    Returns
    -------
    list of ParameterSpec
        Name, type, unit (SI), range, default and provenance of each parameter.

    >>> [p.name for p in parameter_specs()][:3]
    ['bore', 'outer_diameter', 'width']
    """
    values = default_parameters() if values is None else values
    sources = default_sources() if sources is None else sources
    return tuple(
        dataclasses.replace(p, default=values[p.name], source=sources[p.name]) for p in TABLE
    )


#: The parameters of the pair with the defaults of :data:`DEFAULT_MOUNTING`, in the order of
#: the FMU's modelDescription.
PARAMETERS = parameter_specs()


def parameter(name: str) -> ParameterSpec:
    """The :class:`ParameterSpec` ``name`` of :data:`PARAMETERS`.

    Returns
    -------
    ParameterSpec

    >>> parameter("lubrication").item("solid")
    2
    """
    try:
        return next(p for p in PARAMETERS if p.name == name)
    except StopIteration:
        raise ValueError(f"parameter {name!r} is not one of {list(PARAMETER_NAMES)}") from None


def prefixed_specs(prefix: str, what: str, names, values: Mapping, sources: Mapping):
    """The specs of ``names`` renamed ``prefix + name``, described as parts of ``what``, with
    the defaults ``values`` and provenance ``sources`` (keyed by the unprefixed names): one
    table for a second pair in another FMU.

    Returns
    -------
    list of ParameterSpec
        The renamed specs.

    >>> specs = prefixed_specs("support_", "support pair", ("bore",), {"bore": 0.035},
    ...                        {"bore": "catalogue"})
    >>> specs[0].name, specs[0].default
    ('support_bore', 0.035)
    """
    return tuple(
        dataclasses.replace(
            spec(n),
            name=prefix + n,
            description=f"{what}: {spec(n).description}",
            default=values[n],
            source=sources[n],
        )
        for n in names
    )


def _checked(p: Mapping[str, object]) -> dict[str, object]:
    """The parameter set with choices as keys, counts as int and numbers as float; ValueError
    naming the parameter for a missing name, an unknown choice, a non-integer count or a
    non-finite number. (The declared ranges are the FMU's own check: the library takes any
    value its physics takes, e.g. in a sweep.)"""
    missing = [n for n in PARAMETER_NAMES if n not in p]
    if missing:
        raise ValueError(f"parameter set lacks {missing}")
    out = {}
    for sp in TABLE:
        v = p[sp.name]
        if sp.type == "Enumeration":
            keys = [c.key for c in sp.choices]
            if v not in keys:
                raise ValueError(f"{sp.name} = {v!r} is not one of {keys}")
        elif sp.type == "Integer":
            if isinstance(v, bool) or not (isinstance(v, int) or float(v).is_integer()):
                raise ValueError(f"{sp.name} = {v!r} must be an integer")
            v = int(v)
        else:
            v = float(v)
            if not math.isfinite(v):
                raise ValueError(f"{sp.name} = {v!r} must be finite")
        out[sp.name] = v
    return out


def parameter_problems(p: Mapping[str, object]) -> list[str]:
    """Every inconsistency of a parameter set (after :func:`_checked`), each naming the
    values: a geometry that cannot be a bearing (:func:`geometry.bearing_geometry_problems`),
    seats that do not surround the rings, ν100 ≥ ν40, a cold viscosity no Vogel law falls
    through, a lubricant range that is empty, a spring preload without a stiffness or
    compression, a force preload without a force, a tandem pair preloaded by a shim, a yoke
    without arms, a loop with nothing in it.

    Returns
    -------
    list of str
        One message per problem, each naming the parameters and values (empty: none).

    >>> p = default_parameters() | {"preload_method": "spring", "spring_stiffness": 0.0}
    >>> parameter_problems(p)[0]
    'preload_method = spring needs spring_stiffness > 0 N/m (got 0.0)'
    """
    found = bearing_geometry_problems(*(p[f] for f in (
        "bore", "outer_diameter", "width", "ball_diameter", "n_balls", "pitch_diameter",
        "nominal_contact_angle", "inner_curvature", "outer_curvature")))  # fmt: skip
    if not p["housing_outer_diameter"] > p["outer_diameter"]:
        found.append(
            f"housing_outer_diameter = {p['housing_outer_diameter']!r} m must exceed "
            f"outer_diameter = {p['outer_diameter']!r} m"
        )
    if not p["shaft_bore"] < p["bore"]:
        found.append(f"shaft_bore = {p['shaft_bore']!r} m must be below bore = {p['bore']!r} m")
    nu40, nu100 = p["lubricant_viscosity_40"], p["lubricant_viscosity_100"]
    if p["lubrication"] == "grease" and not nu100 < nu40:
        found.append(
            f"lubricant_viscosity_100 = {nu100!r} m2/s must be below lubricant_viscosity_40 "
            f"= {nu40!r} m2/s (a lubricant thins on heating)"
        )
    c = p["lubricant_walther_c"]
    for name in ("lubricant_viscosity_40", "lubricant_viscosity_100"):
        if p["lubrication"] == "grease" and not p[name] + c > CST:
            found.append(
                f"{name} = {p[name]!r} m2/s with lubricant_walther_c = {c!r} m2/s gives "
                f"ν + c = {(p[name] + c) / CST:.4g} cSt; Walther's lg lg(ν + c) needs > 1 cSt"
            )
    if p["lubrication"] == "grease":
        found += _lubricant_problems(p)
    method = p["preload_method"]
    if method == "spring":
        for name, unit in (("spring_stiffness", "N/m"), ("spring_compression", "m")):
            if not p[name] > 0:
                found.append(f"preload_method = spring needs {name} > 0 {unit} (got {p[name]!r})")
    if method == "force" and not p["assembly_preload"] > 0:
        found.append(
            f"preload_method = force needs assembly_preload > 0 N (got {p['assembly_preload']!r})"
        )
    if p["arrangement"] == TANDEM and method == "shim":
        found.append(
            "arrangement = tandem needs preload_method = spring or force (got shim): a tandem "
            "pair has no opposed bearing to be shimmed against"
        )
    if p["loop_reading"] == "printed" and not (p["housing_length"] and p["shaft_length"]):
        found.append("loop_reading = printed needs a housing and a shaft member (lengths > 0)")
    for name in ("grease_f0", "grease_starting_ratio"):
        if p[name] > 0 and p["lubrication"] != "grease":
            found.append(
                f"{name} = {p[name]!r} (a grease term) needs lubrication = grease (the base "
                f"oil's viscosity), not {p['lubrication']}"
            )
    return found


def _lubricant_problems(p: Mapping[str, object]) -> list[str]:
    """The cold point and the range of the lubricant's data, each problem naming the values."""
    found = []
    lo, hi = p["lubricant_minimum_temperature"], p["lubricant_maximum_temperature"]
    for name in ("lubricant_minimum_temperature", "lubricant_data_minimum_temperature"):
        if not p[name] < hi:
            found.append(
                f"lubricant_maximum_temperature = {hi!r} K must lie above {name} = {p[name]!r} K"
            )
    nu, t = p["lubricant_viscosity_cold"], p["lubricant_cold_temperature"]
    if nu != 0.0 and (not t > 0.0 or min(abs(t - T40), abs(t - T100)) < 1.0):
        found.append(
            f"lubricant_cold_temperature = {t!r} K must be > 0 K and at least 1 K from 313.15 "
            f"and 373.15 K (lubricant_viscosity_cold = {nu!r} m2/s is given)"
        )
        return found
    nu40, nu100, c = (p[n] for n in ("lubricant_viscosity_40", "lubricant_viscosity_100",
                                      "lubricant_walther_c"))  # fmt: skip
    if found or not (nu100 < nu40 and nu100 + c > CST):
        return found  # (ν100 ≥ ν40 and ν + c ≤ 1 cSt are named by parameter_problems)
    try:
        _viscosity(p)
    except ValueError as err:
        cold = (
            f"lubricant_viscosity_cold = {nu!r} m2/s at lubricant_cold_temperature = {t!r} K, "
            if nu != 0.0
            else f"lubricant_walther_c = {p['lubricant_walther_c']!r} m2/s, "
        )
        found.append(
            f"{cold}lubricant_viscosity_40 = {p['lubricant_viscosity_40']!r} and "
            f"lubricant_viscosity_100 = {p['lubricant_viscosity_100']!r} m2/s with "
            f"lubricant_minimum_temperature = {lo!r} K and lubricant_below_flow_limit = "
            f"{p['lubricant_below_flow_limit']}: {err}"
        )
    return found


def _viscosity(p: Mapping[str, object]):
    """The viscosity model of parameter set ``p`` (:func:`.lubrication.viscosity.viscosity_model`):
    its data run from the coldest of its viscosity points and ``lubricant_data_minimum_temperature``
    (0: none) to ``lubricant_maximum_temperature``; its flow limit is
    ``lubricant_minimum_temperature`` (0: none), below which ``lubricant_below_flow_limit``
    holds or extrapolates (:mod:`.lubrication.viscosity`)."""
    nu_cold, t_cold = p["lubricant_viscosity_cold"], p["lubricant_cold_temperature"]
    data = p["lubricant_data_minimum_temperature"]
    coldest = min(T40, t_cold) if nu_cold > 0.0 else T40
    return viscosity_model(
        p["lubricant_viscosity_40"],
        p["lubricant_viscosity_100"],
        p["lubricant_walther_c"] / CST,
        (t_cold, nu_cold) if nu_cold > 0.0 else None,
        key="parameters",
        lower_limit=min(data, coldest) if data > 0.0 else coldest,
        upper_limit=p["lubricant_maximum_temperature"],
        flow_limit=p["lubricant_minimum_temperature"],
        below_flow_limit=p["lubricant_below_flow_limit"],
    )


def friction_from_parameters(p: Mapping[str, object]) -> FrictionModel:
    """The :class:`~.friction.models.FrictionModel` of the numbers ``friction_model``,
    ``lubricant_density``, ``grease_*`` and the friction models' own (``skf_*``: their modules'
    ``parameter_numbers``) of parameter set ``p`` (checked).

    Parameters
    ----------
    p : Mapping
        A full, checked parameter set (SI; choices as keys).

    Returns
    -------
    FrictionModel

    Examples
    --------
    >>> from servofmu.physics.friction import registry
    >>> fm = friction_from_parameters(default_parameters())
    >>> fm.model == registry.names()[0], fm.grease is None  # the default model
    (True, True)
    """
    grease = None
    if p["grease_f0"] > 0 or p["grease_starting_ratio"] > 0:
        grease = GreaseTorqueTerm(
            f0=p["grease_f0"],
            starting_ratio=p["grease_starting_ratio"],
            reference_speed=p["grease_reference_speed"],
        )
    return FrictionModel(
        model=p["friction_model"],
        lubricant_density=p["lubricant_density"],
        grease=grease,
        **model_numbers("parameter_numbers", p),
    )


def _material(name: str, p: Mapping, prefix: str, poisson: float | None = None) -> Material:
    nu = p[f"{prefix}_poisson_ratio"] if poisson is None else poisson
    return Material(
        key=prefix,
        name=name,
        youngs_modulus=p[f"{prefix}_youngs_modulus"],
        poisson_ratio=nu,
        expansion=p[f"{prefix}_expansion"],
    )


def bearing_from_parameters(p: Mapping[str, object]) -> BallBearing:
    """The :class:`BallBearing` of the numbers :data:`BEARING_FIELDS` of parameter set ``p``
    (checked by :func:`pair_from_parameters`).

    Parameters
    ----------
    p : Mapping
        A full, checked parameter set (SI).

    Returns
    -------
    BallBearing
        Dimensions [m], ball count, contact angle [rad], curvatures [-] and materials.

    Examples
    --------
    >>> b = bearing_from_parameters(default_parameters())
    >>> b.n_balls, round(b.pitch_diameter * 1e3, 3)  # -, mm: the 71803
    (15, 21.5)
    """
    return BallBearing(
        key="parameters",
        name="bearing given by parameters",
        **{f: p[f] for f in BEARING_FIELDS[:9]},
        ring_material=_material("ring material", p, "ring"),
        ball_material=_material("ball material", p, "ball"),
    )


def _loop(p: Mapping, bearing: BallBearing, housing: Material, shaft: Material) -> PreloadLoop:
    printed = p["loop_reading"] == "printed"
    arrangement = ARRANGEMENTS[p["arrangement"]]
    # the spacer's Poisson ratio enters no equation (an axial member: E·A/L and α·L only)
    spacer = _material("spacer material", p, "spacer", poisson=0.3)
    members = []
    for kind, name, mat in (
        ("housing", "frame", shaft if printed else housing),
        ("shaft", "shaft", housing if printed else shaft),
        ("bearings", "bearings", bearing.ring_material),
        ("spacer", "spacer", spacer),
    ):
        if kind not in arrangement:  # a tandem pair's rings lie in both paths and cancel
            continue
        if kind == "bearings":
            if printed:
                continue
            length, area = 2.0 * bearing.width, None
        else:
            length, area = p[f"{kind}_length"], p[f"{kind}_area"] or None
        if length > 0:
            members.append(LoopMember(name, arrangement[kind], length, mat, area))
    yoke = p["loop_model"] == "yoke"
    arms = (
        (
            YokeArm(
                "arm", p["arm_length"], p["arm_width"], p["arm_thickness"], housing, p["arm_count"]
            ),
        )
        if yoke
        else ()
    )
    spring = p["preload_method"] == "spring"
    return PreloadLoop(
        tuple(members),
        shim=p["shim"] if p["preload_method"] == "shim" else 0.0,
        stiffness=p["loop_stiffness"] or None,
        model=p["loop_model"],
        arms=arms,
        spring_stiffness=p["spring_stiffness"] if spring else None,
        spring_compression=p["spring_compression"] if spring else None,
    )


def pair_from_parameters(p: Mapping[str, object]) -> BearingPair:
    """The :class:`BearingPair` of parameter set ``p`` (every name of
    :data:`PARAMETER_NAMES`; SI; choices as keys): the one place from numbers to physics, for
    the FMU, the calibration and the sweeps. A bad value or an inconsistent set raises
    ValueError naming the parameters and values (:func:`parameter_problems`).

    Returns
    -------
    BearingPair

    >>> pair = pair_from_parameters(default_parameters())
    >>> pair.bearing.n_balls, pair.mounting.arrangement, round(pair.lubricant.c, 3)
    (15, 'face_to_face', 0.932)
    """
    p = _checked(p)
    problems = parameter_problems(p)
    if problems:
        raise ValueError("; ".join(problems))
    bearing = bearing_from_parameters(p)
    housing = _material("housing material", p, "housing")
    shaft = _material("shaft material", p, "shaft")
    fit = RadialFit(
        housing_material=housing,
        housing_outer_diameter=p["housing_outer_diameter"],
        outer_interference=p["outer_interference"],
        shaft_material=shaft,
        shaft_bore=p["shaft_bore"],
        inner_interference=p["inner_interference"],
    )
    loop = _loop(p, bearing, housing, shaft)
    method = p["preload_method"]
    preload = {"shim": None, "force": p["assembly_preload"]}.get(method)
    if method == "spring":  # a spring compressed by c at assembly pushes k·c on the pair
        preload = p["spring_stiffness"] * p["spring_compression"]
    mounting = Mounting(
        key="parameters",
        name="mounting given by parameters",
        bearing_key=bearing.key,
        assembly_temperature=p["assembly_temperature"],
        fit=fit,
        loop=loop,
        assembly_preload=preload,
        arrangement=p["arrangement"],
    )
    lubricant = _viscosity(p) if p["lubrication"] == "grease" else None
    return BearingPair(
        bearing=bearing,
        mounting=mounting,
        lubrication=p["lubrication"],
        lubricant=lubricant,
        coefficients=FrictionCoefficients(
            hysteresis_loss=p["hysteresis_loss"],
            sliding_friction=p["sliding_friction"],
            static_friction_ratio=p["static_friction_ratio"],
            palmgren_s0=p["palmgren_s0"],
        ),
        regularisation_speed=p["regularisation_speed"],
        stribeck_speed=p["stribeck_speed"],
        pressure_limit=p["pressure_limit"],
        friction=friction_from_parameters(p),
    )

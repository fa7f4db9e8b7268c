r"""The friction model of a bearing pair, one of those of :mod:`.friction.registry`
(BearingFriction's ``friction_model``; each model's equations are in its own module), and a
grease term that any of them can carry. This module composes equations written elsewhere; it
writes none itself.

The grease term (:mod:`.friction.grease`, 0 = off) adds, per bearing, Palmgren's
:math:`M_0` with a factor :math:`f_0` calibrated on a grease datasheet's low-temperature
torque, at the base oil's viscosity ν(T) and the bearing's mean diameter (d + D)/2, to the
running torque; and the datasheet's starting ratio :math:`k_s` times :math:`M_0` at the
test's speed to the breakaway torque (never below the running torque at rest). Its limits are
those of :mod:`.friction.grease`.

Everything here is elementwise on Python floats (the per-step path) or numpy arrays (the
exact vectorised path), so both paths compose the same functions.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._checks import check_choice, check_nonnegative, check_range
from ..kernels.friction import palmgren_torque
from . import registry
from .grease import GreaseTorqueTerm


def model_numbers(hook: str, *args) -> dict:
    """The friction models' numbers of one kind, merged in the registry's order: each model
    module's ``hook`` (:mod:`.friction.registry`), a dict or a function of ``args`` giving one.

    Returns
    -------
    dict
        {field of :class:`FrictionModel`: value, or (value, source)}.

    Examples
    --------
    >>> sorted(model_numbers("NUMBERS"))
    ['skf_boundary_friction', 'skf_replenishment']
    """
    numbers = {}
    for entry in registry.entries():
        found = getattr(entry.implementation(), hook, None)
        if found is not None:
            numbers |= found(*args) if callable(found) else found
    return numbers


#: The built-in friction models (:mod:`.friction.registry`; the first is the default).
FRICTION_MODELS = registry.names()
#: Density assumed for a lubricant without a recorded one [kg/m³] (a hydrocarbon oil).
ASSUMED_DENSITY = 870.0
#: The models' numbers that depend on neither bearing nor lubricant, and those of an unknown
#: lubricant: {field: (default, source)} (the modules' ``NUMBERS`` and ``lubricant_numbers``).
DEFAULT_NUMBERS = model_numbers("NUMBERS") | model_numbers("lubricant_numbers", None)
#: Provenance of the SKF coefficients that do not depend on bearing or lubricant.
SKF_SOURCES = {field: source for field, (_, source) in model_numbers("NUMBERS").items()}


@dataclass(frozen=True)
class FrictionModel:
    """Which friction model a pair uses and the numbers only that model needs.

    Attributes
    ----------
    model : one of :data:`FRICTION_MODELS`
    skf : the SKF series constants (the SKF model's ``SkfConstants``, its ``bearing_numbers``);
        needed by the SKF model
    skf_replenishment : Krs of φrs [-] (6e-8 grease or oil-air, 3e-8 oil bath or jet)
    skf_boundary_friction : μbl [-] (SKF: ≈ 0.15)
    skf_film_friction : μEHL [-] (SKF: mineral oil 0.05, synthetic 0.04)
    lubricant_density : ρ [kg/m³] of the (base) oil, η = ν·ρ (the per-contact EHL model)
    grease : the calibrated grease term, or None (off)
    provenance : ((field, source), ...)
    """

    model: str = FRICTION_MODELS[0]
    skf: object | None = None
    skf_replenishment: float = DEFAULT_NUMBERS["skf_replenishment"][0]
    skf_boundary_friction: float = DEFAULT_NUMBERS["skf_boundary_friction"][0]
    skf_film_friction: float = DEFAULT_NUMBERS["skf_film_friction"][0]
    lubricant_density: float = ASSUMED_DENSITY
    grease: GreaseTorqueTerm | None = None
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_choice("friction_model", self.model, registry.names())
        check = getattr(registry.get(self.model).implementation(), "check_numbers", None)
        if check is not None:
            check(self)
        if self.skf is not None and self.skf.bearing_type != "angular_contact":
            raise ValueError(
                f"SKF series {self.skf.key!r} is {self.skf.bearing_type}: the pair takes "
                "angular-contact constants"
            )
        check_nonnegative("skf_replenishment", self.skf_replenishment)
        check_range("skf_boundary_friction", self.skf_boundary_friction, 0.0, 1.0)
        check_range("skf_film_friction", self.skf_film_friction, 0.0, 1.0)
        check_range("lubricant_density", self.lubricant_density, 100.0, 5000.0, unit="kg/m³")

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")


DEFAULT_FRICTION = FrictionModel()


def mean_diameter(bearing) -> float:
    """(d + D)/2 [m] of a :class:`~.contact.geometry.BallBearing`: the dm of the SKF model and of
    the grease term (nominal, as the catalogue and the datasheet test use it).

    Parameters
    ----------
    bearing : BallBearing
        The bearing (d, D [m]).

    Returns
    -------
    float
        dm [m].

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> round(mean_diameter(catalog.bearing("71803")) * 1e3, 3)  # mm: (17 + 26)/2
    21.5
    """
    return 0.5 * (float(bearing.bore) + float(bearing.outer_diameter))


def grease_running(pair, kinematic_viscosity, speed):
    """Running torque of the grease term of both bearings [N·m]: 2·M0(f0, ν, |ω|, (d + D)/2)
    (Palmgren, :mod:`.friction.grease`); 0 without a grease term.

    Parameters
    ----------
    pair : BearingPair
        The pair (its grease term).
    kinematic_viscosity : float or ndarray
        The base oil's ν [m²/s].
    speed : float or ndarray
        ω [rad/s].

    Returns
    -------
    float or ndarray
        [N·m].

    Examples
    --------
    >>> from servofmu.physics.bearing import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> grease_running(pair, 100e-6, 1.0)  # N·m: no grease term in this pair
    0.0
    """
    g = pair.friction.grease
    if g is None:
        return 0.0
    return 2.0 * palmgren_torque(kinematic_viscosity, speed, mean_diameter(pair.bearing), g.f0)


def grease_rest_and_start(pair, kinematic_viscosity):
    """(running torque at rest, starting torque) of the grease term of both bearings [N·m]:
    2·M0(ω = 0) and 2·max(ks·M0(ω_test), M0(ω = 0)) (a starting torque is never below the
    running torque at rest); (0, 0) without a grease term.

    Parameters
    ----------
    pair : BearingPair
        The pair.
    kinematic_viscosity : float or ndarray
        The base oil's ν [m²/s].

    Returns
    -------
    tuple
        (running torque at rest, starting torque) [N·m].

    Examples
    --------
    >>> from servofmu.physics.bearing import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> grease_rest_and_start(pair, 100e-6)  # N·m: no grease term
    (0.0, 0.0)
    """
    g = pair.friction.grease
    if g is None:
        return 0.0, 0.0
    dm = mean_diameter(pair.bearing)
    rest = palmgren_torque(kinematic_viscosity, 0.0, dm, g.f0)
    start = g.starting_ratio * palmgren_torque(kinematic_viscosity, g.reference_speed, dm, g.f0)
    maximum = max if type(start) is float and type(rest) is float else np.maximum
    return 2.0 * rest, 2.0 * maximum(start, rest)


def preset(bearing, lubricant=None, model: str = FRICTION_MODELS[0], grease=None) -> FrictionModel:
    """The :class:`FrictionModel` of catalogue data, each number with its provenance: the
    models' numbers of the bearing and of the lubricant (their modules' ``bearing_numbers``
    and ``lubricant_numbers``: the SKF constants of the bearing's series or their labelled
    fallback, Krs for grease, the catalogue's μbl, μEHL of the base oil's class), and the
    lubricant's recorded density (else assumed).

    Parameters
    ----------
    bearing : :class:`~.contact.geometry.BallBearing` (its ``key`` is the designation)
    lubricant : :class:`~.lubrication.lubricant.LubricantRecord` or None (a dry film, or unknown)
    model : one of :data:`FRICTION_MODELS`
    grease : a :class:`~.friction.grease.GreaseTorqueTerm` or None (off)

    Returns
    -------
    FrictionModel

    >>> from servofmu.parameters import catalog
    >>> fm = preset(catalog.bearing("71803"), catalog.lubricant_record("krytox_143aa"))
    >>> fm.skf.r1, fm.skf_film_friction, fm.lubricant_density
    (5.03e-07, 0.04, 1900.0)
    """
    numbers = (
        model_numbers("NUMBERS")
        | model_numbers("bearing_numbers", bearing)
        | model_numbers("lubricant_numbers", lubricant)
    )
    density, density_src = lubricant_density(lubricant)
    return FrictionModel(
        model=model,
        lubricant_density=float(density),
        grease=grease,
        provenance=(
            *((f, src) for f, (_, src) in numbers.items() if src),
            ("lubricant_density", density_src),
        ),
        **{f: value for f, (value, _) in numbers.items()},
    )


def lubricant_density(lubricant) -> tuple[float, str]:
    """(density [kg/m³], source) of a lubricant record (or None): its recorded density, else
    :data:`ASSUMED_DENSITY`, labelled assumed.

    Returns
    -------
    tuple
        (density [kg/m³], source).

    >>> from servofmu.parameters import catalog
    >>> rho, src = lubricant_density(catalog.lubricant_record("xc_5606j"))
    >>> rho, src[:7]
    (870.1, 'derived')
    """
    density = getattr(lubricant, "density", None)
    if density is None:
        return ASSUMED_DENSITY, "assumed: a hydrocarbon oil (no density recorded)"
    return float(density), f"{lubricant.source('density')} ({lubricant.key})"


def lubricant_numbers(lubricant) -> tuple[tuple[float, str], tuple[float, str]]:
    """((μEHL, source), (density [kg/m³], source)) of a lubricant record (or None): SKF's μEHL
    of its base oil's ``oil_class`` (mineral when unknown, labelled assumed; the models'
    ``lubricant_numbers``) and :func:`lubricant_density`.

    Returns
    -------
    tuple
        ((μEHL [-], source), (density [kg/m³], source)).

    >>> from servofmu.parameters import catalog
    >>> (mu, _), (rho, src) = lubricant_numbers(catalog.lubricant_record("xc_5606j"))
    >>> mu, rho, src[:7]
    (0.05, 870.1, 'derived')
    """
    film = model_numbers("lubricant_numbers", lubricant)["skf_film_friction"]
    return film, lubricant_density(lubricant)


def __getattr__(name: str):
    """A name the module offered before its friction models had modules of their own (e.g.
    ``skf_loads``): from the model's module that lists it in ``FORMER_NAMES``, found through
    :mod:`.registry`; AttributeError for any other name."""
    for entry in registry.entries():
        module = entry.implementation()
        if name in getattr(module, "FORMER_NAMES", ()):
            return getattr(module, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

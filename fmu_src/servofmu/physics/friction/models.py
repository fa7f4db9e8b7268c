r"""The friction model of a bearing pair, one of three (BearingFriction's ``friction_model``),
and a grease term that any of them can carry. This module composes equations written
elsewhere; it writes none itself.

- ``yu2017`` (the default; Yu 2017 eq 1–9): per contact the elastic hysteresis, the spin and,
  for a dry film, the differential sliding (:mod:`.friction.terms`), and Palmgren's viscous torque
  :math:`M_0 \propto s_0\,(\nu n)^{2/3} d_m^3` per bearing.
- ``skf2004`` (SKF 2004, :mod:`.friction.skf2004`): each bearing of the pair with its own
  axial load from the equilibrium (preload included) and its share :math:`F_r/2` of the
  radial load,

  .. math::

     M = \phi_\mathrm{ish}\,\phi_\mathrm{rs}\,M_\mathrm{rr} + M_\mathrm{sl}

  (:math:`M_\mathrm{seal} = 0`: open bearings; :math:`M_\mathrm{drag} = 0`: no oil bath),
  starting torque :math:`M_\mathrm{sl}(n \to 0)`. The series constants are numbers (the
  catalogue's series, or the labelled fallback of :func:`.friction.skf2004.series_constants`).
  The per-contact terms of Yu are not part of it (hysteresis and spin are 0 in its outputs).
- ``ehl_per_contact`` (:mod:`.friction.ehl_per_contact`): the hydrodynamic rolling torque of every
  ball–race contact (Biboulet & Houpert 2010) from that contact's load, contact angle and Hertz
  ellipse and the lubricant's dynamic viscosity :math:`\eta = \nu(T)\,\rho` at the part
  temperatures, in place of Palmgren's term, plus Yu's hysteresis and spin (and Ning's sliding
  for a dry film) per contact.

No thermal (inlet shear) or starvation reduction is applied to the EHL model: Biboulet &
Houpert's fit is for a fully flooded, isothermal contact, and SKF's factors
:math:`\phi_\mathrm{ish}` and :math:`\phi_\mathrm{rs}` are empirical for a bearing's total
rolling moment, not for one contact. For scale, on the gimbal's 71803 at 10 °/s and −40 °C
(Krytox 143AA, ν = 4.1e4 mm²/s) :math:`\phi_\mathrm{ish}` is 1 − 1.6e-4 (inlet heating is
negligible at servo speeds), while SKF's replenishment factor for grease is 0.92 there and
0.0019 at −60 °C (ν extrapolated to 2.9e6 mm²/s): a starved, slowly turning grease-packed
contact would have less rolling torque than this model gives, by an amount no cited
per-contact law gives.

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
from .ehl_per_contact import ehl_torque as ehl_torque
from .grease import GreaseTorqueTerm
from .skf2004 import MU_BOUNDARY, MU_EHL, REPLENISHMENT_KRS, SkfConstants
from .skf2004 import skf_loads as skf_loads
from .skf2004 import skf_starting as skf_starting
from .skf2004 import skf_torques as skf_torques

#: The built-in friction models (:mod:`.friction.registry`; the first is the default).
FRICTION_MODELS = registry.names()
#: Density assumed for a lubricant without a recorded one [kg/m³] (a hydrocarbon oil).
ASSUMED_DENSITY = 870.0
#: Provenance of the SKF coefficients that do not depend on bearing or lubricant.
SKF_SOURCES = {
    "skf_replenishment": "catalogue: SKF 10000 EN, Krs = 6e-8 for grease and oil-air",
    "skf_boundary_friction": "catalogue: SKF 10000 EN p. 103, μbl 'generally ≈ 0,15'",
}


@dataclass(frozen=True)
class FrictionModel:
    """Which friction model a pair uses and the numbers only that model needs.

    Attributes
    ----------
    model : one of :data:`FRICTION_MODELS`
    skf : the SKF series constants (:func:`.friction.skf2004.series_constants`); needed by
        ``skf2004``
    skf_replenishment : Krs of φrs [-] (6e-8 grease or oil-air, 3e-8 oil bath or jet)
    skf_boundary_friction : μbl [-] (SKF: ≈ 0.15)
    skf_film_friction : μEHL [-] (SKF: mineral oil 0.05, synthetic 0.04)
    lubricant_density : ρ [kg/m³] of the (base) oil, η = ν·ρ (``ehl_per_contact``)
    grease : the calibrated grease term, or None (off)
    provenance : ((field, source), ...)
    """

    model: str = FRICTION_MODELS[0]
    skf: SkfConstants | None = None
    skf_replenishment: float = REPLENISHMENT_KRS["grease"]
    skf_boundary_friction: float = MU_BOUNDARY
    skf_film_friction: float = MU_EHL["mineral"]
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
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa", friction_model="skf2004")
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
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa", friction_model="skf2004")
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
    """The :class:`FrictionModel` of catalogue data, each number with its provenance: the SKF
    constants of the bearing's series (or the labelled fallback,
    :func:`.friction.skf2004.series_constants`), Krs for grease, the catalogue's μbl, μEHL of
    the base oil's class, and the lubricant's recorded density (else assumed).

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
    from .skf2004 import series_constants

    skf = series_constants(bearing.key, float(bearing.nominal_contact_angle))
    (film, film_src), (density, density_src) = lubricant_numbers(lubricant)
    return FrictionModel(
        model=model,
        skf=skf,
        skf_replenishment=REPLENISHMENT_KRS["grease"],
        skf_boundary_friction=MU_BOUNDARY,
        skf_film_friction=film,
        lubricant_density=float(density),
        grease=grease,
        provenance=(
            *SKF_SOURCES.items(),
            ("skf_film_friction", film_src),
            ("lubricant_density", density_src),
        ),
    )


def lubricant_numbers(lubricant) -> tuple[tuple[float, str], tuple[float, str]]:
    """((μEHL, source), (density [kg/m³], source)) of a lubricant record (or None): SKF's μEHL
    of its base oil's ``oil_class`` (mineral when unknown, labelled assumed) and its recorded
    density (else :data:`ASSUMED_DENSITY`, labelled assumed).

    Returns
    -------
    tuple
        ((μEHL [-], source), (density [kg/m³], source)).

    >>> from servofmu.parameters import catalog
    >>> (mu, _), (rho, src) = lubricant_numbers(catalog.lubricant_record("xc_5606j"))
    >>> mu, rho, src[:7]
    (0.05, 870.1, 'derived')
    """
    oil_class = getattr(lubricant, "oil_class", "") or ""
    if oil_class:
        film = (
            MU_EHL[oil_class],
            f"catalogue: SKF 10000 EN p. 103, μEHL of {oil_class} oils (lubricant "
            f"{lubricant.key}: {oil_class} base oil)",
        )
    else:
        film = (
            MU_EHL["mineral"],
            "catalogue: SKF 10000 EN p. 103, μEHL of mineral oils (assumed: oil class unknown)",
        )
    density = getattr(lubricant, "density", None)
    if density is None:
        return film, (ASSUMED_DENSITY, "assumed: a hydrocarbon oil (no density recorded)")
    return film, (float(density), f"{lubricant.source('density')} ({lubricant.key})")

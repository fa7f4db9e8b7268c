"""A preloaded pair of angular-contact ball bearings in a frame: the :class:`BearingPair`
configuration (bearing, mounting, lubrication, friction coefficients), its mounting changes
(:func:`with_mounting`) and the loop quantities fixed at assembly (Yu 2017 eq 14–15)."""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass

import numpy as np

from ...parameters import catalog
from .._checks import check_choice, check_positive, check_temperature
from ..contact.geometry import BallBearing, RaceGeometry
from ..friction.grease import lubricant_term
from ..friction.models import DEFAULT_FRICTION, FRICTION_MODELS, FrictionModel, preset
from ..friction.terms import FrictionCoefficients
from ..lubrication.viscosity import ViscosityRange
from ..thermal.fits import mounted_geometry
from ..thermal.temperatures import part_temperatures
from .mounting import Mounting
from .preload import ROLES, TANDEM, shim_for_preload, tandem_offsets
from .rows import PairRows, loop_closure_at

LUBRICATIONS = ("grease", "solid")
DEFAULT_COEFFICIENTS = FrictionCoefficients()
#: Static load limit: 4200 MPa maximum Hertz pressure for ball bearings (ISO 76:2006, the basis
#: of the basic static load rating): above it the contacts deform permanently (dents of about
#: 1e-4 of the ball diameter), and the pair is reported as ``overloaded``. It is not seizure.
PRESSURE_LIMIT = 4.2e9


@dataclass(frozen=True)
class BearingPair:
    """Configuration of a preloaded pair of angular-contact ball bearings in a frame.

    Attributes
    ----------
    bearing : :class:`geometry.BallBearing`
    mounting : :class:`Mounting`
    lubrication : "grease" (Yu 2017 eq 9) or "solid" (Ning)
    lubricant : viscosity model with the range of its data (:mod:`.lubrication.viscosity`; grease);
    None
        for a dry film
    coefficients : :class:`friction.FrictionCoefficients`
    regularisation_speed : width ω_r of the smooth sign through zero speed [rad/s]
    stribeck_speed : decay speed ω_s of the breakaway excess [rad/s]
    pressure_limit : maximum Hertz pressure above which the pair is overloaded [Pa]
    differential_sliding : include Heathcote sliding; None: True for solid, False for grease
    thermal_coupling : False ignores the fit pressures (Yu Fig 3 "without coupling")
    friction : :class:`~.friction.models.FrictionModel`: which friction model (Yu 2017 by
        default), its numbers, and the grease term (off by default)
    """

    bearing: BallBearing
    mounting: Mounting
    lubrication: str = "grease"
    lubricant: ViscosityRange | None = None
    coefficients: FrictionCoefficients = DEFAULT_COEFFICIENTS
    regularisation_speed: float = 1e-3
    stribeck_speed: float = 1e-2
    pressure_limit: float = PRESSURE_LIMIT
    differential_sliding: bool | None = None
    thermal_coupling: bool = True
    friction: FrictionModel = DEFAULT_FRICTION

    def __post_init__(self):
        check_choice("lubrication", self.lubrication, LUBRICATIONS)
        if self.lubrication == "grease" and self.lubricant is None:
            raise ValueError("lubrication = 'grease' needs a lubricant viscosity model")
        if self.friction.grease is not None and self.lubrication != "grease":
            raise ValueError(
                "a grease term (grease_f0 > 0 or grease_starting_ratio > 0) needs lubrication = "
                f"'grease' (the base oil's viscosity), not {self.lubrication!r}"
            )
        check_positive("regularisation_speed", self.regularisation_speed, "rad/s")
        check_positive("stribeck_speed", self.stribeck_speed, "rad/s")
        check_positive("pressure_limit", self.pressure_limit, "Pa")

    @property
    def breakaway_lower_bound(self) -> bool:
        """True when the pair's breakaway is only a lower bound: a fluid lubricant without
        published starting data (no cold start, ks, in its grease term: :mod:`.friction.grease`).
        Its breakaway then holds the zero-speed limit of the viscous term alone, not what a
        cold-soaked lubricant adds at rest (a grease's yield). A dry film has no such term.

        >>> BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa").breakaway_lower_bound
        True
        >>> BearingPair.from_catalog("yu2017_gimbal", "molykote_g1074").breakaway_lower_bound
        False
        """
        g = self.friction.grease
        return self.lubricant is not None and (g is None or not g.has_start)

    @property
    def sliding(self) -> bool:
        if self.differential_sliding is None:
            return self.lubrication == "solid"
        return self.differential_sliding

    @classmethod
    def from_catalog(
        cls,
        mounting: str,
        lubricant: str | None = None,
        friction_model: str = FRICTION_MODELS[0],
        **overrides,
    ):
        """Pair built from catalogue keys: ``mounting`` (``data/mountings.toml``; it names its
        bearing and its friction coefficients, ``data/coefficients.toml``, calibrated where a
        paper allows) and ``lubricant`` (``data/lubricants.toml``; a dry film gives solid
        lubrication), with ``friction_model`` (:data:`~.friction.models.FRICTION_MODELS`, its
        numbers from the catalogue: :func:`~.friction.models.preset`) and the lubricant's grease
        term calibrated on its published low-temperature torques where it has any (its cold
        start: :func:`~.friction.grease.lubricant_term`). Other fields as keyword overrides.

        >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
        >>> round(pair.coefficients.sliding_friction, 4)  # calibrated on Yu 2017 (§3, Fig 8)
        0.0817
        """
        mnt = catalog.mounting(mounting)
        kwargs = {"bearing": catalog.bearing(mnt.bearing_key), "mounting": mnt}
        coefficients = catalog.mounting_coefficients(mounting)
        if coefficients is not None:
            kwargs["coefficients"] = coefficients
        record, grease = None, None
        if lubricant is not None:
            visc = catalog.lubricant(lubricant)
            kwargs["lubricant"] = visc
            kwargs["lubrication"] = "solid" if visc is None else "grease"
            record = catalog.lubricant_record(lubricant)
            grease = lubricant_term(lubricant)  # its published torques: the cold start
        kwargs["friction"] = preset(kwargs["bearing"], record, friction_model, grease)
        kwargs.update(overrides)
        return cls(**kwargs)


MOUNTING_CHANGES = (
    "outer_interference",
    "inner_interference",
    "shim",
    "loop_stiffness",
    "assembly_preload",
    "assembly_temperature",
)


def with_mounting(pair: BearingPair, **changes) -> BearingPair:
    """A copy of ``pair`` with mounting values changed: ``outer_interference``,
    ``inner_interference`` (diametral, m), ``shim`` (m; clears ``assembly_preload``),
    ``loop_stiffness`` (N/m, None = from the members), ``assembly_preload`` (N),
    ``assembly_temperature`` (K).

    Returns
    -------
    BearingPair
        The copy (``pair`` is unchanged).

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> tight = with_mounting(pair, assembly_preload=80.0)
    >>> tight.mounting.assembly_preload, pair.mounting.assembly_preload == 80.0  # N
    (80.0, False)
    """
    unknown = set(changes) - set(MOUNTING_CHANGES)
    if unknown:
        raise ValueError(f"mounting change {sorted(unknown)} is not one of {MOUNTING_CHANGES}")
    m = pair.mounting
    fit = dataclasses.replace(
        m.fit,
        **{k: changes[k] for k in ("outer_interference", "inner_interference") if k in changes},
    )
    loop = m.loop
    if "shim" in changes:
        loop = dataclasses.replace(loop, shim=changes["shim"])
    if "loop_stiffness" in changes:
        loop = dataclasses.replace(loop, stiffness=changes["loop_stiffness"])
    preload = m.assembly_preload
    if "shim" in changes:
        preload = None
    preload = changes.get("assembly_preload", preload)
    mounting = dataclasses.replace(
        m,
        fit=fit,
        loop=loop,
        assembly_preload=preload,
        assembly_temperature=changes.get("assembly_temperature", m.assembly_temperature),
    )
    return dataclasses.replace(pair, mounting=mounting)


@functools.lru_cache(maxsize=64)
def assembly_geometry(pair: BearingPair) -> RaceGeometry:
    """Mounted geometry at the assembly temperature.

    Parameters
    ----------
    pair : BearingPair
        The pair.

    Returns
    -------
    RaceGeometry
        The mounted operating geometry at T0 (fields in m).

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> round(float(assembly_geometry(pair).clearance) * 1e6, 3)  # µm: mounted at 20 °C
    9.658
    """
    m = pair.mounting
    return mounted_geometry(
        pair.bearing, m.fit, m.assembly_temperature, m.assembly_temperature, pair.thermal_coupling
    ).race


def is_tandem(pair: BearingPair) -> bool:
    """Whether the pair's bearings face the same way (:data:`~.pair.preload.TANDEM`): they share a
    thrust set by a spring or a force instead of preloading each other.

    Returns
    -------
    bool

    >>> is_tandem(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    False
    """
    return pair.mounting.arrangement == TANDEM


@functools.lru_cache(maxsize=64)
def effective_shim(pair: BearingPair) -> float:
    """The shim [m]: the loop's, or the one that gives ``assembly_preload`` at T0; 0 for a
    tandem pair (a matched set: equal stand-outs and spacers, so A and B share the thrust
    equally at T0; its preload is a force, the loop's shim is not used).

    Parameters
    ----------
    pair : BearingPair
        The pair.

    Returns
    -------
    float
        s [m].

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> round(effective_shim(pair) * 1e6, 3)  # µm
    30.0
    """
    m = pair.mounting
    if is_tandem(pair):
        return 0.0
    if m.assembly_preload is None:
        return m.loop.shim
    return shim_for_preload(assembly_geometry(pair), m.assembly_preload, loop_stiffness(pair))


def loop_stiffness(pair: BearingPair) -> float:
    """Structural axial stiffness of the preload loop [N/m] (inf: rigid).

    Parameters
    ----------
    pair : BearingPair
        The pair.

    Returns
    -------
    float
        k_loop [N/m].

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> round(loop_stiffness(pair) / 1e6, 3)  # N/µm: the yoke arms and the shaft
    0.37
    """
    return pair.mounting.loop.structural_stiffness


def loop_closure(pair: BearingPair, temperature):
    """C(T) = 2·h(T0) + s − Σ σ·L·α·(T_j − T0) [m] at a uniform temperature [K] or the parts'
    temperatures (each member j at its part's T_j; see :mod:`preload`). For a tandem pair the
    mismatch d(T) = −Σ σ·L·α·(T_j − T0) [m] of bearing B along the thrust relative to A (a
    matched set: 0 at T0; :func:`~.pair.preload.tandem_offsets`). The members are summed by part
    (:func:`closure_coefficients`, :func:`~.pair.continuation.loop_closure_at`).

    Parameters
    ----------
    pair : BearingPair
        The pair.
    temperature : float, array_like or PartTemperatures
        T [K].

    Returns
    -------
    float or ndarray
        C [m] (a tandem pair: d [m]).

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> c = loop_closure(pair, [293.15, 253.15])
    >>> round(float(c[1] - c[0]) * 1e6, 3)  # µm: the loop closes on cooling
    47.2
    """
    temps = part_temperatures(temperature)
    t0 = check_temperature("assembly_temperature", pair.mounting.assembly_temperature)
    return loop_closure_at(
        *closure_coefficients(pair),
        t0,
        np.asarray(temps.housing),
        np.asarray(temps.shaft),
        np.asarray(temps.of("rings")),
    )


@functools.lru_cache(maxsize=64)
def closure_coefficients(pair: BearingPair) -> tuple[float, float, float, float]:
    """(C0 [m], c_housing, c_shaft, c_rings [m/K]) of the loop closure
    C(T) = C0 − Σ_parts c_part·(T_part − T0): C0 = 2·h(T0) + s (a tandem pair: 0, the
    mismatch vanishing at T0), c_part = Σ σ·L·α of the loop members that take the part's
    temperature (Yu 2017 eq 14–15; :func:`~.pair.preload.loop_interference`).

    Parameters
    ----------
    pair : BearingPair
        The pair.

    Returns
    -------
    tuple of float
        (C0 [m], housing, shaft, rings [m/K]).

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> c0, housing, shaft, rings = closure_coefficients(pair)
    >>> housing > 0.0 > shaft  # m/K: a face-to-face pair's frame opens it, its shaft closes it
    True
    """
    m = pair.mounting
    sums = {"housing": 0.0, "shaft": 0.0, "rings": 0.0}
    for member in m.loop.members:
        sums[member.part] += ROLES[member.role] * member.length * member.material.expansion
    c0 = 0.0 if is_tandem(pair) else 2.0 * float(assembly_geometry(pair).first_contact_offset)
    if not is_tandem(pair):
        c0 += effective_shim(pair)
    return c0, sums["housing"], sums["shaft"], sums["rings"]


@functools.lru_cache(maxsize=64)
def pair_rows(pair: BearingPair) -> PairRows:
    """The equilibrium rows of the pair in its arrangement (:class:`~.pair.continuation.PairRows`):
    a face-to-face or back-to-back pair in its loop of stiffness :func:`loop_stiffness`, or a
    tandem pair under its preload spring and thrust (:func:`tandem_preload`).

    Parameters
    ----------
    pair : BearingPair
        The pair.

    Returns
    -------
    PairRows

    Examples
    --------
    >>> rows = pair_rows(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> rows.is_tandem, round(rows.stiffness / 1e6, 3)  # N/µm: the yoke arms and the shaft
    (False, 0.37)
    """
    if is_tandem(pair):
        return PairRows(True, *tandem_preload(pair))
    return PairRows(False, loop_stiffness(pair), 0.0)


@functools.lru_cache(maxsize=64)
def tandem_preload(pair: BearingPair) -> tuple[float, float]:
    """(k_s [N/m], T [N]) of a tandem pair's preload (:func:`~.pair.preload.tandem_offsets`): a
    spring of stiffness k_s compressed by c at assembly pushes P = k_s·(c − (a_A − a_A0)), so
    T = k_s·(c + a_A0) with a_A0 the offset at assembly under P0 = k_s·c; a constant force
    (``assembly_preload``) is k_s = 0, T = P0. The thermal growth of the spring's own seats is
    left out (for a soft spring it moves P by k_s·α·L·ΔT: 0.01 N for 10 mm of steel, 10 K and
    1e5 N/m).

    Returns
    -------
    tuple of float
        (k_s [N/m], T [N]).

    Examples
    --------
    >>> from servofmu.parameters.bearing import default_parameters, pair_from_parameters
    >>> p = default_parameters() | {"arrangement": "tandem", "preload_method": "force",
    ...                             "assembly_preload": 40.0}
    >>> tandem_preload(pair_from_parameters(p))
    (0.0, 40.0)
    """
    m = pair.mounting
    ks = m.loop.spring_stiffness or 0.0
    if not ks:
        return 0.0, float(m.assembly_preload)
    p0 = ks * m.loop.spring_compression
    a0 = float(tandem_offsets(assembly_geometry(pair), effective_shim(pair), 0.0, p0).offset_a[()])
    return ks, ks * (m.loop.spring_compression + a0)

"""The bearing-pair friction model: thermal coupling (fits, preload) + equilibrium + friction.

Composition (Yu 2017 §1–3; Ning §1–2):

1. :func:`thermal_state` — everything that depends on temperature only: the mounted geometry
   (Yu eq 10–13), the clearance and free contact angle, the loop closure (eq 14–15), the
   preload at zero external load, the lubricant viscosity (eq 18).
2. :func:`load_state` — the pair under external axial and radial loads: per-ball loads and
   contact angles (Jones), the speed-independent torques (eq 1–7, Ning), preload, axial
   stiffness, maximum contact pressure and the flags ``overloaded``, ``locked`` and
   ``unloaded`` (:func:`state_flags`).
3. :func:`bearing_outputs` — the speed-dependent part: Palmgren's viscous torque (eq 8), the
   total (eq 9), breakaway versus running torque, the regularised signed friction torque and
   the power loss.

:class:`BearingModel` caches 1 and 2, so that a change of speed costs only step 3 and a change
of load does not re-solve the thermal state.
"""

from __future__ import annotations

import bisect
import dataclasses
import functools
import math
from collections import OrderedDict
from dataclasses import dataclass, fields

import numpy as np
from scipy.optimize.elementwise import find_root

from ._checks import check_choice, check_finite, check_positive, check_temperature
from .equilibrium import _axial_state, _ring_stiffness
from .fits import RadialFit, mounted_geometry
from .friction import (
    BallSetTorques,
    FrictionCoefficients,
    _palmgren,
    _regularised,
    ball_set_torques,
)
from .geometry import BallBearing, RaceGeometry
from .preload import (
    PreloadLoop,
    loop_interference,
    mean_offset,
    pair_axial_stiffness,
    pair_equilibrium,
    pair_offsets,
    shim_for_preload,
)
from .viscosity import WaltherViscosity

LUBRICATIONS = ("grease", "solid")
DEFAULT_COEFFICIENTS = FrictionCoefficients()
#: Static load limit: 4200 MPa maximum Hertz pressure for ball bearings (ISO 76:2006, the basis
#: of the basic static load rating): above it the contacts deform permanently (dents of about
#: 1e-4 of the ball diameter), and the pair is reported as ``overloaded``. It is not seizure.
PRESSURE_LIMIT = 4.2e9


@dataclass(frozen=True)
class Mounting:
    """Seats and preload loop of a bearing pair (catalogue: ``data/mountings.toml``).

    Attributes
    ----------
    key, name : catalogue key and description
    bearing_key : designation of the bearing it was made for
    assembly_temperature : T0 [K] at which fits, shim and preload are set
    fit : :class:`fits.RadialFit`
    loop : :class:`preload.PreloadLoop`
    assembly_preload : preload at T0 [N]; when given, the shim is derived from it
    provenance : ((field, source), ...)
    """

    key: str
    name: str
    bearing_key: str
    assembly_temperature: float
    fit: RadialFit
    loop: PreloadLoop
    assembly_preload: float | None = None
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_temperature("assembly_temperature", self.assembly_temperature)
        if self.assembly_preload is not None:
            check_positive("assembly_preload", self.assembly_preload, "N")

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")


@dataclass(frozen=True)
class BearingPair:
    """Configuration of a preloaded pair of angular-contact ball bearings in a frame.

    Attributes
    ----------
    bearing : :class:`geometry.BallBearing`
    mounting : :class:`Mounting`
    lubrication : "grease" (Yu 2017 eq 9) or "solid" (Ning)
    lubricant : viscosity model (grease); None for a dry film
    coefficients : :class:`friction.FrictionCoefficients`
    regularisation_speed : width ω_r of the smooth sign through zero speed [rad/s]
    stribeck_speed : decay speed ω_s of the breakaway excess [rad/s]
    pressure_limit : maximum Hertz pressure above which the pair is overloaded [Pa]
    differential_sliding : include Heathcote sliding; None: True for solid, False for grease
    thermal_coupling : False ignores the fit pressures (Yu Fig 3 "without coupling")
    """

    bearing: BallBearing
    mounting: Mounting
    lubrication: str = "grease"
    lubricant: WaltherViscosity | None = None
    coefficients: FrictionCoefficients = DEFAULT_COEFFICIENTS
    regularisation_speed: float = 1e-3
    stribeck_speed: float = 1e-2
    pressure_limit: float = PRESSURE_LIMIT
    differential_sliding: bool | None = None
    thermal_coupling: bool = True

    def __post_init__(self):
        check_choice("lubrication", self.lubrication, LUBRICATIONS)
        if self.lubrication == "grease" and self.lubricant is None:
            raise ValueError("lubrication = 'grease' needs a lubricant viscosity model")
        check_positive("regularisation_speed", self.regularisation_speed, "rad/s")
        check_positive("stribeck_speed", self.stribeck_speed, "rad/s")
        check_positive("pressure_limit", self.pressure_limit, "Pa")

    @property
    def sliding(self) -> bool:
        if self.differential_sliding is None:
            return self.lubrication == "solid"
        return self.differential_sliding

    @classmethod
    def from_catalog(cls, mounting: str, lubricant: str | None = None, **overrides):
        """Pair built from catalogue keys: ``mounting`` (``data/mountings.toml``; it names its
        bearing) and ``lubricant`` (``data/lubricants.toml``; a dry film gives solid
        lubrication). Other fields as keyword overrides."""
        from . import catalog

        mnt = catalog.mounting(mounting)
        kwargs = {"bearing": catalog.bearing(mnt.bearing_key), "mounting": mnt}
        if lubricant is not None:
            visc = catalog.lubricant(lubricant)
            kwargs["lubricant"] = visc
            kwargs["lubrication"] = "solid" if visc is None else "grease"
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
    ``assembly_temperature`` (K)."""
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
    """Mounted geometry at the assembly temperature."""
    m = pair.mounting
    return mounted_geometry(
        pair.bearing, m.fit, m.assembly_temperature, m.assembly_temperature, pair.thermal_coupling
    ).race


@functools.lru_cache(maxsize=64)
def effective_shim(pair: BearingPair) -> float:
    """The shim [m]: the loop's, or the one that gives ``assembly_preload`` at T0."""
    m = pair.mounting
    if m.assembly_preload is None:
        return m.loop.shim
    return shim_for_preload(assembly_geometry(pair), m.assembly_preload, loop_stiffness(pair))


def loop_stiffness(pair: BearingPair) -> float:
    """Structural axial stiffness of the preload loop [N/m] (inf: rigid)."""
    return pair.mounting.loop.structural_stiffness


def loop_closure(pair: BearingPair, temperature):
    """C(T) = 2·h(T0) + s − Σ σ·L·α·(T − T0) [m] (see :mod:`preload`)."""
    m = pair.mounting
    loop = m.loop
    if effective_shim(pair) != loop.shim:
        loop = PreloadLoop(loop.members, effective_shim(pair), loop.stiffness)
    h0 = float(assembly_geometry(pair).first_contact_offset)
    return 2.0 * h0 + loop_interference(loop, temperature, m.assembly_temperature)


@dataclass(frozen=True)
class ThermalState:
    """Temperature-only state of the pair (arrays over temperature, or scalars).

    Attributes
    ----------
    temperature : T [K]
    geometry : mounted :class:`RaceGeometry`
    outer_fit_pressure, inner_fit_pressure : Lamé pressures [Pa]
    outer_interference, inner_interference : diametral fit interferences at T [m]
    closure : loop closure C [m]
    loop_stiffness : k_loop [N/m]
    kinematic_viscosity : ν [m²/s] (0 for a dry film)
    preload_offset : offset of each bearing at zero external load [m]
    """

    temperature: np.ndarray
    geometry: RaceGeometry
    outer_fit_pressure: np.ndarray
    inner_fit_pressure: np.ndarray
    outer_interference: np.ndarray
    inner_interference: np.ndarray
    closure: np.ndarray
    loop_stiffness: float
    kinematic_viscosity: np.ndarray
    preload_offset: np.ndarray

    @property
    def clearance(self):
        """Operating diametral clearance Pd [m]."""
        return self.geometry.clearance

    @property
    def free_contact_angle(self):
        """Free contact angle at the operating clearance [rad]."""
        return self.geometry.free_contact_angle


def thermal_state(pair: BearingPair, temperature) -> ThermalState:
    """Temperature-only state at ``temperature`` [K] (scalar or array); Yu 2017 eq 10–18."""
    t = np.asarray(check_temperature("temperature", temperature), dtype=float)
    m = pair.mounting
    mounted = mounted_geometry(
        pair.bearing, m.fit, t, m.assembly_temperature, pair.thermal_coupling
    )
    closure = loop_closure(pair, t)
    k = loop_stiffness(pair)
    offsets = pair_offsets(mounted.race, closure, k, 0.0)
    visc = np.zeros_like(t) if pair.lubricant is None else pair.lubricant.kinematic_viscosity(t)
    return ThermalState(
        temperature=t,
        geometry=mounted.race,
        outer_fit_pressure=mounted.outer_fit_pressure,
        inner_fit_pressure=mounted.inner_fit_pressure,
        outer_interference=np.asarray(mounted.outer_interference),
        inner_interference=np.asarray(mounted.inner_interference),
        closure=closure,
        loop_stiffness=k,
        kinematic_viscosity=np.asarray(visc),
        preload_offset=offsets.offset_a,
    )


@dataclass(slots=True)
class LoadState:
    """Speed-independent state of the pair under load (arrays or scalars).

    Attributes
    ----------
    force_a, force_b : axial forces of bearings A and B [N]
    preload : loop force (F_A + F_B)/2 [N]
    contact_angle : load-weighted operating contact angle of bearing A [rad] (the free
        contact angle when A carries no load)
    axial_stiffness : stiffness of the shaft in the pair [N/m]
    max_contact_pressure : largest Hertz pressure over all contacts [Pa]
    overloaded, locked, unloaded : the flags of :func:`state_flags`
    torques : speed-independent torques of both bearings (:class:`friction.BallSetTorques`)
    axial_displacement : axial displacement of the shaft from its unloaded position,
        z = (a_A − a_B)/2 [m] (positive towards bearing A)
    converged : the load equilibrium was solved
    """

    force_a: np.ndarray
    force_b: np.ndarray
    preload: np.ndarray
    contact_angle: np.ndarray
    axial_stiffness: np.ndarray
    max_contact_pressure: np.ndarray
    overloaded: np.ndarray
    locked: np.ndarray
    unloaded: np.ndarray
    torques: BallSetTorques
    axial_displacement: np.ndarray = 0.0
    converged: bool = True


def state_flags(
    pair: BearingPair, clearance, max_contact_pressure, force_a, force_b, converged=True
) -> dict:
    """What the model knows about the state of the pair, as three flags (arrays or bools).

    - ``overloaded``: the largest Hertz pressure ``max_contact_pressure`` [Pa] reaches the
      pair's ``pressure_limit`` (ISO 76: 4200 MPa, permanent deformation of the races);
    - ``locked``: no operating clearance is left (diametral ``clearance`` [m] ≤ 0: the balls
      are pinched between the rings already without axial offset, the contact angle has
      collapsed and the pair can no longer set its own contact angle), or the load
      equilibrium has no solution (``converged`` False);
    - ``unloaded``: the preload is lost: one bearing's axial force ``force_a``/``force_b`` [N]
      is zero, so the shaft has axial play (with no external load: both are zero).
    """
    p = np.asarray(max_contact_pressure)
    locked = np.asarray(clearance) <= 0.0
    if not converged:
        locked = np.ones_like(locked)
    unloaded = np.minimum(np.asarray(force_a), np.asarray(force_b)) <= 0.0
    return {
        "overloaded": p >= pair.pressure_limit,
        "locked": locked,
        "unloaded": unloaded,
    }


def _torques(pair: BearingPair, geom: RaceGeometry, load, alpha, inner, outer, count=1):
    t = ball_set_torques(
        load,
        alpha,
        inner,
        outer,
        geom.pitch_diameter,
        geom.ball_diameter,
        geom.inner_groove_radius,
        geom.outer_groove_radius,
        pair.coefficients,
        pair.lubrication,
        pair.sliding,
    )
    if count == 1:
        return t
    return BallSetTorques(*(count * getattr(t, f.name) for f in fields(BallSetTorques)))


def _add(t1: BallSetTorques, t2: BallSetTorques) -> BallSetTorques:
    return BallSetTorques(*(getattr(t1, f.name) + getattr(t2, f.name) for f in fields(t1)))


def _max_pressure(load, inner, outer):
    return np.maximum(inner.max_pressure(load), outer.max_pressure(load)).max(axis=-1)


def load_state(pair: BearingPair, thermal: ThermalState, axial_load=0.0, radial_load=0.0):
    """State of the pair at ``thermal`` under ``axial_load`` [N] (pressing bearing A) and
    ``radial_load`` [N]. Vectorised over temperature when the radial load is zero (every ball
    of a bearing alike, Yu eq 4); a radial load is solved per ball (Jones) with the pair
    equilibrium of :func:`preload.pair_equilibrium` (scalar temperature)."""
    f_ext = check_finite("axial_load", axial_load, "N")
    f_r = check_finite("radial_load", radial_load, "N")
    if np.any(np.asarray(f_r) != 0):
        return _combined_load_state(pair, thermal, float(f_ext), float(f_r))
    if np.all(np.asarray(f_ext) == 0):
        a_a = a_b = thermal.preload_offset
    else:
        off = pair_offsets(thermal.geometry, thermal.closure, thermal.loop_stiffness, f_ext)
        a_a, a_b = off.offset_a, off.offset_b
    return axial_load_state(pair, thermal, a_a, a_b)


def axial_load_state(pair: BearingPair, thermal: ThermalState, offset_a, offset_b) -> LoadState:
    """:class:`LoadState` of the pair with bearings A and B at axial offsets ``offset_a``,
    ``offset_b`` [m] and no radial load: every ball of a bearing alike (Yu eq 4), so the
    torques are Z times one ball's (elementwise over arrays)."""
    geom, k = thermal.geometry, thermal.loop_stiffness
    sa, sb = _axial_state(geom, offset_a), _axial_state(geom, offset_b)
    z = geom.n_balls

    def ball(s):
        """One ball of the state with a trailing ball axis of length 1."""
        contacts = [
            type(c)(*(np.asarray(getattr(c, f.name))[..., None] for f in fields(c)))
            for c in (s.inner, s.outer)
        ]
        return np.asarray(s.ball_load)[..., None], np.asarray(s.contact_angle)[..., None], contacts

    (qa, ala, ea), (qb, alb, eb) = ball(sa), ball(sb)
    t = _add(
        _torques(pair, geom, qa, ala, *ea, count=z), _torques(pair, geom, qb, alb, *eb, count=z)
    )
    p_max = np.maximum(_max_pressure(qa, *ea), _max_pressure(qb, *eb))
    angle = np.where(sa.ball_load > 0, sa.contact_angle, geom.free_contact_angle)
    return LoadState(
        force_a=sa.axial_force,
        force_b=sb.axial_force,
        preload=0.5 * (sa.axial_force + sb.axial_force),
        contact_angle=angle,
        axial_stiffness=pair_axial_stiffness(sa.axial_stiffness, sb.axial_stiffness, k),
        max_contact_pressure=p_max,
        **state_flags(pair, geom.clearance, p_max, sa.axial_force, sb.axial_force),
        torques=t,
        axial_displacement=0.5 * (np.asarray(offset_a) - np.asarray(offset_b)),
    )


def _combined_load_state(pair, thermal, f_ext, f_r) -> LoadState:
    if np.ndim(thermal.temperature):
        raise ValueError("a radial load needs a scalar temperature (one thermal state)")
    geom, k = thermal.geometry, thermal.loop_stiffness
    st = pair_equilibrium(geom, float(thermal.closure), k, f_ext, f_r)
    la, lb = st.balls_a, st.balls_b
    t = _add(
        _torques(pair, geom, la.load, la.contact_angle, la.inner, la.outer),
        _torques(pair, geom, lb.load, lb.contact_angle, lb.inner, lb.outer),
    )
    t = BallSetTorques(*(np.asarray(getattr(t, f.name))[0] for f in fields(t)))
    qa = la.load[0]
    angle = (
        float(np.sum(qa * la.contact_angle[0]) / np.sum(qa))
        if qa.sum() > 0
        else geom.free_contact_angle
    )
    ka = _ring_stiffness(geom, la)[0, 0, 0]
    kb = _ring_stiffness(geom, lb)[0, 0, 0]
    p_max = max(
        float(_max_pressure(la.load, la.inner, la.outer)[0]),
        float(_max_pressure(lb.load, lb.inner, lb.outer)[0]),
    )
    fa, fb = float(la.axial_force[0]), float(lb.axial_force[0])
    return LoadState(
        force_a=fa,
        force_b=fb,
        preload=0.5 * (fa + fb),
        contact_angle=angle,
        axial_stiffness=float(pair_axial_stiffness(ka, kb, k)),
        max_contact_pressure=p_max,
        **state_flags(pair, geom.clearance, p_max, fa, fb, st.converged),
        torques=t,
        axial_displacement=0.5 * (st.offset_a - st.offset_b),
        converged=st.converged,
    )


@dataclass(slots=True)
class BearingOutputs:
    """Everything the BearingFriction FMU reports (DESIGN §3), SI; arrays or floats.

    friction_torque [N·m] signed like speed (opposes rotation), running_torque and
    breakaway_torque [N·m], hysteresis/spin/sliding/viscous_torque [N·m], preload [N],
    contact_angle [rad], radial_clearance [m], kinematic_viscosity [m²/s], axial_stiffness
    [N/m], power_loss [W], overloaded, locked, unloaded (see :func:`state_flags`); plus
    inner_ring_torque/outer_ring_torque [N·m], max_contact_pressure [Pa],
    outer/inner_fit_pressure [Pa], outer/inner_interference [m], force_a/force_b [N],
    axial_displacement [m].
    """

    friction_torque: float
    running_torque: float
    breakaway_torque: float
    hysteresis_torque: float
    spin_torque: float
    sliding_torque: float
    viscous_torque: float
    preload: float
    contact_angle: float
    radial_clearance: float
    kinematic_viscosity: float
    axial_stiffness: float
    power_loss: float
    overloaded: bool
    locked: bool
    unloaded: bool
    inner_ring_torque: float
    outer_ring_torque: float
    max_contact_pressure: float
    outer_fit_pressure: float
    inner_fit_pressure: float
    outer_interference: float
    inner_interference: float
    force_a: float
    force_b: float
    axial_displacement: float

    def as_dict(self) -> dict:
        return {f.name: getattr(self, f.name) for f in fields(self)}


def _speed_terms(pair: BearingPair, thermal: ThermalState, load: LoadState, w):
    """(signed friction, running, viscous, Coulomb part, breakaway excess) at speed w [rad/s]
    (Yu 2017 eq 8–9 and the regularised sign); floats in, floats out on the per-step path."""
    t = load.torques
    s0 = pair.coefficients.palmgren_s0 if pair.lubricant is not None else 0.0
    viscous = 2.0 * _palmgren(thermal.kinematic_viscosity, w, thermal.geometry.pitch_diameter, s0)
    coulomb = t.hysteresis + t.spin + t.sliding
    excess = (pair.coefficients.static_friction_ratio - 1.0) * (t.spin + t.sliding)
    running = coulomb + viscous
    signed = _regularised(w, running, excess, pair.regularisation_speed, pair.stribeck_speed)
    return signed, running, viscous, coulomb, excess


def bearing_outputs(
    pair: BearingPair, thermal: ThermalState, load: LoadState, speed
) -> BearingOutputs:
    """Speed-dependent outputs at ``speed`` [rad/s] (Yu 2017 eq 8–9; regularised sign)."""
    w = speed if type(speed) is float else check_finite("speed", speed, "rad/s")
    t = load.torques
    signed, running, viscous, coulomb, excess = _speed_terms(pair, thermal, load, w)
    s0 = pair.coefficients.palmgren_s0 if pair.lubricant is not None else 0.0
    dm = thermal.geometry.pitch_diameter
    viscous_rest = 2.0 * _palmgren(thermal.kinematic_viscosity, 0.0, dm, s0)
    return BearingOutputs(
        friction_torque=signed,
        running_torque=running,
        breakaway_torque=coulomb + excess + viscous_rest,
        hysteresis_torque=t.hysteresis,
        spin_torque=t.spin,
        sliding_torque=t.sliding,
        viscous_torque=viscous,
        preload=load.preload,
        contact_angle=load.contact_angle,
        radial_clearance=thermal.clearance,
        kinematic_viscosity=thermal.kinematic_viscosity,
        axial_stiffness=load.axial_stiffness,
        power_loss=signed * w,
        overloaded=load.overloaded,
        locked=load.locked,
        unloaded=load.unloaded,
        inner_ring_torque=t.inner_ring,
        outer_ring_torque=t.outer_ring,
        max_contact_pressure=load.max_contact_pressure,
        outer_fit_pressure=thermal.outer_fit_pressure,
        inner_fit_pressure=thermal.inner_fit_pressure,
        outer_interference=thermal.outer_interference,
        inner_interference=thermal.inner_interference,
        force_a=load.force_a,
        force_b=load.force_b,
        axial_displacement=load.axial_displacement,
    )


def operating_outputs(
    pair: BearingPair, temperature, speed, axial_load=0.0, radial_load=0.0
) -> BearingOutputs:
    """Exact outputs at temperature [K], speed [rad/s], axial load [N] (arrays broadcast
    together; vectorised when the radial load is zero) and radial load [N] (then scalars):
    :func:`thermal_state`, :func:`load_state` and :func:`bearing_outputs` in one call."""
    th = thermal_state(pair, temperature)
    return bearing_outputs(pair, th, load_state(pair, th, axial_load, radial_load), speed)


def to_floats(obj):
    """The dataclass ``obj`` with every 0-d array field (recursively) made a Python float or
    bool, for the per-step scalar path."""
    changes = {}
    for f in fields(obj):
        v = getattr(obj, f.name)
        if dataclasses.is_dataclass(v):
            changes[f.name] = to_floats(v)
        elif isinstance(v, (np.ndarray, np.generic)) and np.ndim(v) == 0:
            changes[f.name] = bool(v) if v.dtype == bool else float(v)
    return dataclasses.replace(obj, **changes)


class AxialLoadTable:
    """The pair's speed-independent state versus external axial load at one temperature.

    Tabulated once on ``size`` shaft displacements z ≥ 0 (every node solved exactly with
    :func:`preload.mean_offset` and :func:`axial_load_state`, in one vectorised call) up to
    1.5 times the pressure limit, mirrored for z < 0 (bearings A and B swap), and interpolated
    linearly in the load; loads beyond the table return None (the caller solves exactly).
    """

    def __init__(self, pair: BearingPair, thermal: ThermalState, size: int = 513):
        geom, k, c = thermal.geometry, thermal.loop_stiffness, thermal.closure
        p0 = float(thermal.preload_offset)
        a_lim = _offset_at_pressure(geom, 1.5 * pair.pressure_limit)
        z = np.linspace(0.0, max(a_lim - min(p0, 0.0), 1e-9) * 1.05, size)
        p = mean_offset(z, np.full_like(z, c), k, geom)
        ls = axial_load_state(pair, thermal, p + z, p - z)
        sb = _axial_state(geom, p - z)
        angle_b = np.where(sb.ball_load > 0, sb.contact_angle, float(geom.free_contact_angle))
        t = ls.torques
        columns = [
            np.asarray(ls.force_a) - np.asarray(ls.force_b),  # the external load: the key
            ls.force_a,
            ls.force_b,
            ls.contact_angle,
            angle_b,
            ls.preload,
            ls.axial_stiffness,
            ls.max_contact_pressure,
            z,
            *(getattr(t, f.name) for f in fields(BallSetTorques)),
        ]
        self.rows = [
            tuple(map(float, r)) for r in np.column_stack([np.asarray(x, float) for x in columns])
        ]
        self.load = [r[0] for r in self.rows]
        self.pressure_limit = pair.pressure_limit
        self.locked = bool(float(geom.clearance) <= 0.0)

    def lookup(self, axial_load: float) -> LoadState | None:
        """Interpolated :class:`LoadState` (floats) at ``axial_load`` [N], or None."""
        f = abs(axial_load)
        loads = self.load
        if f > loads[-1]:
            return None
        i = min(max(bisect.bisect_right(loads, f) - 1, 0), len(loads) - 2)
        lo, hi = self.rows[i], self.rows[i + 1]
        w = (f - lo[0]) / (hi[0] - lo[0])
        _, fa, fb, ang_a, ang_b, preload, stiffness, p_max, disp, *torques = (
            a + w * (b - a) for a, b in zip(lo, hi, strict=True)
        )
        if axial_load < 0:  # mirror: bearing B carries the load
            fa, fb, ang_a, disp = fb, fa, ang_b, -disp
        return LoadState(
            fa,
            fb,
            preload,
            ang_a,
            stiffness,
            p_max,
            bool(p_max >= self.pressure_limit),
            self.locked,
            min(fa, fb) <= 0.0,
            BallSetTorques(*torques),
            disp,
        )


def _offset_at_pressure(geom: RaceGeometry, pressure: float) -> float:
    """Axial offset [m] of one bearing at which its largest contact pressure reaches
    ``pressure`` [Pa] under pure axial load."""

    def excess(a):
        s = _axial_state(geom, a)
        q = s.ball_load
        return np.maximum(s.inner.max_pressure(q), s.outer.max_pressure(q)) - pressure

    lo = float(geom.first_contact_offset)
    hi = lo + float(geom.curvature_distance)
    while float(excess(hi)) < 0:
        hi += float(geom.curvature_distance)
    return float(find_root(excess, (lo, hi), tolerances={"xrtol": 1e-6}).x)


class BearingModel:
    """Cached evaluation of a :class:`BearingPair` at (temperature, speed, axial, radial load).

    Caches, each a small LRU: the thermal state per temperature; the axial-load table per
    temperature (:class:`AxialLoadTable`, built the first time an axial load is asked for at
    that temperature); the state under a radial load per (temperature, axial, radial load),
    solved exactly. A change of speed alone costs only the Palmgren and regularisation terms,
    evaluated in Python floats.
    """

    def __init__(self, pair: BearingPair, cache_size: int = 8):
        self.pair = pair
        self._cache_size = cache_size
        self._thermal: OrderedDict[float, ThermalState] = OrderedDict()
        self._tables: OrderedDict[float, AxialLoadTable] = OrderedDict()
        self._load: OrderedDict[tuple[float, float, float], LoadState] = OrderedDict()
        # the operating point of the previous call (the per-step fast path)
        self._last_t = None
        self._last_loads = None
        self._th: ThermalState | None = None
        self._table: AxialLoadTable | None = None
        self._state: LoadState | None = None

    def _remember(self, cache: OrderedDict, key, make):
        try:
            cache.move_to_end(key)
            return cache[key]
        except KeyError:
            value = make()
            cache[key] = value
            if len(cache) > self._cache_size:
                cache.popitem(last=False)
            return value

    def thermal(self, temperature: float) -> ThermalState:
        """Cached :func:`thermal_state` at one temperature [K], fields as floats."""
        t = float(check_temperature("temperature", temperature))
        return self._remember(self._thermal, t, lambda: to_floats(thermal_state(self.pair, t)))

    def load(self, temperature: float, axial_load: float = 0.0, radial_load: float = 0.0):
        """Exact :func:`load_state` at one temperature [K] and loads [N] (fields as floats)."""
        th = self.thermal(temperature)
        return to_floats(load_state(self.pair, th, axial_load, radial_load))

    def _load_fast(self, th: ThermalState, axial_load: float, radial_load: float) -> LoadState:
        t = th.temperature
        if radial_load == 0.0:
            if axial_load == 0.0:
                return self._remember(
                    self._load,
                    (t, 0.0, 0.0),
                    lambda: to_floats(
                        axial_load_state(self.pair, th, th.preload_offset, th.preload_offset)
                    ),
                )
            if self._table is None:
                self._table = self._remember(self._tables, t, lambda: AxialLoadTable(self.pair, th))
            hit = self._table.lookup(axial_load)
            if hit is not None:
                return hit
        key = (t, axial_load, radial_load)
        return self._remember(
            self._load, key, lambda: to_floats(load_state(self.pair, th, axial_load, radial_load))
        )

    def evaluate(
        self, temperature: float, speed: float, axial_load: float = 0.0, radial_load: float = 0.0
    ) -> BearingOutputs:
        """All outputs at one operating point, as floats (the per-step path of the FMU).

        Axial loads are read from the per-temperature :class:`AxialLoadTable` (linear
        interpolation between exactly solved nodes; :meth:`load` gives the exact value)."""
        if (axial_load, radial_load) != self._last_loads or temperature != self._last_t:
            for name, v in (("axial_load", axial_load), ("radial_load", radial_load)):
                if not math.isfinite(v):
                    raise ValueError(f"{name} = {v!r} N is outside the valid range (-inf, inf)")
            if temperature != self._last_t:
                self._th = self.thermal(temperature)
                self._table = None
                self._last_t = temperature
            self._state = self._load_fast(self._th, float(axial_load), float(radial_load))
            self._last_loads = (axial_load, radial_load)
        if not math.isfinite(speed):
            raise ValueError(f"speed = {speed!r} rad/s is outside the valid range (-inf, inf)")
        return bearing_outputs(self.pair, self._th, self._state, float(speed))

    def speed_outputs(self, speed: float) -> tuple[float, float, float, float]:
        """(friction_torque, running_torque, viscous_torque, power_loss) at ``speed`` [rad/s]
        for the operating point of the last :meth:`evaluate` call: the per-step path when
        only the speed changed (the same equations, so the same numbers as evaluate)."""
        if not math.isfinite(speed):
            raise ValueError(f"speed = {speed!r} rad/s is outside the valid range (-inf, inf)")
        w = float(speed)
        signed, running, viscous, _, _ = _speed_terms(self.pair, self._th, self._state, w)
        return signed, running, viscous, signed * w

    def curves(self, temperatures, speed: float, axial_load: float = 0.0) -> BearingOutputs:
        """Outputs over an array of temperatures [K] at one speed and axial load, vectorised
        and exact (zero radial load)."""
        return operating_outputs(self.pair, temperatures, speed, axial_load)

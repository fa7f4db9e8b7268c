"""The exact state of a bearing pair, vectorised over operating points (Yu 2017 §1–3;
Ning §1–2):

1. :func:`thermal_state` — everything that depends on temperature only: the mounted geometry
   (Yu eq 10–13), the clearance and free contact angle, the loop closure (eq 14–15), the
   preload at zero external load, the lubricant viscosity (eq 18);
2. :func:`load_state` — the pair under external axial and radial loads: per-ball loads and
   contact angles (Jones), the speed-independent torques (eq 1–7, Ning), preload, axial
   stiffness, maximum contact pressure and the flags ``overloaded``, ``locked`` and
   ``unloaded`` (:func:`state_flags`);
3. :func:`bearing_outputs` — the speed-dependent part: the rolling/viscous torque of the
   pair's friction model (:mod:`.friction.registry`, e.g. Palmgren's eq 8), the total
   (eq 9), breakaway versus running torque, the regularised signed friction torque and the
   power loss.

Every root is found with bracketing solvers (scipy), so this path cannot fail to converge: it
is the reference of the per-step continuation (:mod:`.compiled`) and its fallback.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, fields

import numpy as np

from .. import compiled
from .._checks import check_finite
from ..contact.equilibrium import _axial_state, _ring_stiffness
from ..contact.geometry import RaceGeometry
from ..friction import registry
from ..friction.models import grease_rest_and_start, grease_running
from ..friction.terms import BallSetTorques, ball_set_torques
from ..kernels.friction import coulomb_and_excess, palmgren_torque, regularised_torque
from ..thermal.fits import mounted_geometry_at
from ..thermal.temperatures import PARTS, PartTemperatures, part_temperatures
from .configuration import BearingPair, closure_coefficients, is_tandem, pair_rows
from .preload import axial_offsets, pair_equilibrium
from .rows import axial_play, loop_closure_at, pair_flags, preload_force

#: The output record of one operating point (:mod:`.point`): the one class of the process,
#: compiled when the compiled modules run, whichever path fills it.
PointState = compiled.module("pair.point").PointState


@dataclass(frozen=True)
class ThermalState:
    """Temperature-only state of the pair (arrays over temperature, or scalars).

    Attributes
    ----------
    temperatures : the parts' temperatures [K] (:class:`~.thermal.temperatures.PartTemperatures`;
        all equal for a uniform temperature)
    geometry : mounted :class:`RaceGeometry`
    outer_fit_pressure, inner_fit_pressure : Lamé pressures [Pa]
    outer_interference, inner_interference : diametral fit interferences at T [m]
    closure : loop closure C [m] (a tandem pair: the mismatch d of B relative to A)
    loop_stiffness : k_loop [N/m] (a tandem pair: its preload spring's k_s, 0 for a force)
    kinematic_viscosity : ν [m²/s] the bearing uses (0 for a dry film): the lubricant's law,
        held at its value at the lower end of its data below it (:mod:`.lubrication.viscosity`)
    preload_offset : offset of bearing A at zero external load [m] (B's too, but in a tandem
        pair: the closure more)
    outside_lubricant_range : the lubricant's temperature lies outside the range of its data
        (:meth:`.lubrication.viscosity.ViscosityRange.outside`; False for a dry film)
    """

    temperatures: PartTemperatures
    geometry: RaceGeometry
    outer_fit_pressure: np.ndarray
    inner_fit_pressure: np.ndarray
    outer_interference: np.ndarray
    inner_interference: np.ndarray
    closure: np.ndarray
    loop_stiffness: float
    kinematic_viscosity: np.ndarray
    preload_offset: np.ndarray
    outside_lubricant_range: np.ndarray = False

    @property
    def temperature(self):
        """Temperature of balls and lubricant [K] (the uniform temperature when uniform)."""
        return np.asarray(self.temperatures.lubricant)

    @property
    def clearance(self):
        """Operating diametral clearance Pd [m]."""
        return self.geometry.clearance

    @property
    def pitch_diameter(self):
        """Operating pitch diameter dm [m]."""
        return self.geometry.pitch_diameter

    @property
    def free_contact_angle(self):
        """Free contact angle at the operating clearance [rad]."""
        return self.geometry.free_contact_angle


def thermal_state(pair: BearingPair, temperature) -> ThermalState:
    """Temperature-only state of the pair; Yu 2017 eq 10–18.

    Parameters
    ----------
    pair : the :class:`BearingPair`
    temperature : uniform temperature [K] (float or array), or the parts' temperatures
        (:class:`~.thermal.temperatures.PartTemperatures`, fields broadcasting together)

    Returns
    -------
    ThermalState
        Mounted geometry [m], fit pressures [Pa] and interferences [m], loop closure [m],
        loop stiffness [N/m], viscosity [m²/s] and the unloaded pair's offset [m].

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = thermal_state(pair, np.array([233.15, 293.15]))
    >>> [round(float(v) * 1e6, 1) for v in th.kinematic_viscosity]  # cSt at −40 and 20 °C
    [40947.4, 86.9]
    """
    temps = part_temperatures(temperature)
    return thermal_state_at(pair, *(getattr(temps, f) for f in PARTS))


def thermal_state_at(pair: BearingPair, t_h, t_s, t_o, t_i) -> ThermalState:
    """:func:`thermal_state` at part temperatures already checked
    (:func:`~.thermal.temperatures.part_temperatures`, or the per-step model's check): housing
    ``t_h``, shaft ``t_s``, outer ring ``t_o``, inner ring ``t_i`` [K], floats or arrays that
    broadcast together, made arrays once here.

    Returns
    -------
    ThermalState
        As :func:`thermal_state`.

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = thermal_state_at(pair, 253.15, 253.15, 253.15, 253.15)
    >>> float(th.closure) == float(thermal_state(pair, 253.15).closure)
    True
    """
    temps = PartTemperatures(
        *np.broadcast_arrays(*(np.asarray(t, float) for t in (t_h, t_s, t_o, t_i)))
    )
    m = pair.mounting
    t0 = float(m.assembly_temperature)  # checked by the Mounting
    mounted = mounted_geometry_at(
        pair.bearing,
        m.fit,
        temps.housing,
        temps.shaft,
        temps.outer_ring,
        temps.inner_ring,
        t0,
        pair.thermal_coupling,
    )
    closure = loop_closure_at(
        *closure_coefficients(pair), t0, temps.housing, temps.shaft, temps.balls
    )
    rows = pair_rows(pair)
    k = rows.stiffness
    offsets = axial_offsets(mounted.race, rows, closure, 0.0)
    t_lub = np.asarray(temps.lubricant)
    lub = pair.lubricant
    visc = np.zeros_like(t_lub) if lub is None else lub.operating_viscosity(t_lub)
    outside = np.zeros(t_lub.shape, bool) if lub is None else np.asarray(lub.outside(t_lub))
    return ThermalState(
        temperatures=temps,
        geometry=mounted.race,
        outer_fit_pressure=mounted.outer_fit_pressure,
        inner_fit_pressure=mounted.inner_fit_pressure,
        outer_interference=np.asarray(mounted.outer_interference),
        inner_interference=np.asarray(mounted.inner_interference),
        closure=closure,
        loop_stiffness=k,
        kinematic_viscosity=np.asarray(visc),
        preload_offset=offsets.offset_a,
        outside_lubricant_range=outside,
    )


@dataclass(slots=True)
class LoadState:
    """Speed-independent state of the pair under load (arrays or scalars).

    Attributes
    ----------
    force_a, force_b : axial forces of bearings A and B [N] (negative: :func:`state_flags`'s
        ``reverse_loaded``)
    preload : :func:`preload_force` [N]
    axial_play : :func:`axial_play` [m]
    contact_angle : load-weighted operating contact angle of bearing A [rad] (the free
        contact angle when A carries no load)
    axial_stiffness : stiffness of the shaft in the pair [N/m]
    max_contact_pressure : largest Hertz pressure over all contacts [Pa]
    overloaded, locked, unloaded, reverse_loaded : the flags of :func:`state_flags`
    torques : speed-independent torques of both bearings (:class:`friction.BallSetTorques`)
    axial_displacement : axial displacement of the shaft from its unloaded position,
        z = (a_A − a_B)/2 [m] (positive towards bearing A; a tandem pair: a_A less its
        offset at zero external load, positive along the thrust)
    converged : the load equilibrium was solved
    offset_a, offset_b : axial offsets of the groove curvature centres of A and B [m]
    radial_a, radial_b : radial displacements of the shaft in A and B [m]
    ball_cosines : per-ball cos α of A and B over half the ring (ψ = 2πj/Z, j ≤ Z/2) under
        a radial load, else None (the continuation's start after an exact solve)
    rolling : what the friction model's speed terms need besides the viscosity
        (:func:`rolling_data`): None, the bearings' loads or the contacts' terms, as its
        registry entry asks (:attr:`~.friction.registry.Entry.data`)
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
    reverse_loaded: np.ndarray
    torques: BallSetTorques
    axial_play: np.ndarray = 0.0
    axial_displacement: np.ndarray = 0.0
    converged: bool = True
    offset_a: np.ndarray = 0.0
    offset_b: np.ndarray = 0.0
    radial_a: float = 0.0
    radial_b: float = 0.0
    ball_cosines: tuple | None = None
    rolling: tuple | None = None


def state_flags(
    pair: BearingPair, clearance, max_contact_pressure, force_a, force_b, converged=True
) -> dict:
    """What the model knows about the state of the pair, as four flags (arrays or bools).

    - ``overloaded``: the largest Hertz pressure ``max_contact_pressure`` [Pa] reaches the
      pair's ``pressure_limit`` (ISO 76: 4200 MPa, permanent deformation of the races);
    - ``locked``: no operating clearance is left (diametral ``clearance`` [m] ≤ 0: the balls
      are pinched between the rings already without axial offset, the contact angle has
      collapsed and the pair can no longer set its own contact angle), or the load
      equilibrium has no solution (``converged`` False);
    - ``unloaded``: the preload is lost: one bearing's axial force ``force_a``/``force_b`` [N]
      is zero or negative, so the shaft has axial play (with no external load: both are zero);
    - ``reverse_loaded``: a bearing's axial force is negative: its balls are pushed past the
      axial play onto the other flanks of its grooves (the loop pulled apart, or a tandem set
      under a load against its thrust larger than the thrust). The model takes the grooves as
      symmetric there (a deep-groove bearing); an angular-contact bearing has a low shoulder
      on that side and may not carry the load: its numbers are the symmetric groove's.

    Returns
    -------
    dict
        ``{"overloaded", "locked", "unloaded", "reverse_loaded"}``: bools for floats, boolean
        arrays for arrays.

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> state_flags(pair, 2e-6, 1.5e9, 40.0, 0.0)  # m, Pa, N, N: B lost its load
    {'overloaded': False, 'locked': False, 'unloaded': True, 'reverse_loaded': False}
    """
    overloaded, locked, unloaded, reverse = pair_flags(
        pair.pressure_limit, clearance, max_contact_pressure, force_a, force_b
    )
    return {
        "overloaded": overloaded,
        "locked": locked | (not converged),
        "unloaded": unloaded,
        "reverse_loaded": reverse,
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


def _contacts_terms(pair: BearingPair, thermal: ThermalState, balls, terms) -> tuple:
    """The contacts' terms of the friction model's ``contact_rolling_terms`` ``terms``
    (:mod:`.friction.registry`; arrays, a trailing contact axis: every ball's inner contact, then
    its outer one, bearing after bearing) from ``balls`` = [(Q, α, inner, outer, weight)] with a
    trailing ball axis; a contact without load gets a zero scale (and m0 = 1, so that nothing
    divides 0 by 0)."""
    geom = thermal.geometry

    def g(x):
        return np.asarray(x, dtype=float)[..., None]

    dw, dm = g(geom.ball_diameter), g(geom.pitch_diameter)
    eta = g(thermal.kinematic_viscosity) * pair.friction.lubricant_density
    parts = []
    for q, alpha, inner, outer, weight in balls:
        loaded = q > 0.0
        q_safe = np.where(loaded, q, 1.0)
        gamma = dw * np.cos(alpha) / dm
        for c, r, is_inner in (
            (inner, geom.inner_groove_radius, True),
            (outer, geom.outer_groove_radius, False),
        ):
            a = c.a_coef * np.cbrt(q_safe)
            t = terms(
                q_safe, a, c.ellipticity, c.e_integral, gamma, dw, dm, dw / g(r),
                geom.compliance, eta, is_inner,
            )  # fmt: skip
            scale = np.where(loaded, weight * t[0], 0.0)
            m0 = np.where(loaded, t[3], 1.0)
            shape = np.broadcast_shapes(*(np.shape(x) for x in t))
            parts.append(tuple(np.broadcast_to(x, shape) for x in (scale, t[1], t[2], m0, t[4])))
    return tuple(np.concatenate([p[i] for p in parts], axis=-1) for i in range(5))


def rolling_data(pair: BearingPair, thermal: ThermalState, force_a, force_b, radial_load, balls):
    """What the speed terms of the pair's friction model need besides viscosity and pitch
    diameter (its :attr:`~.friction.registry.Entry.data`): None; the bearings' loads
    (Fa,A, Fa,B, Fr) [N] (the model's ``rolling_loads``); or the contacts' terms
    (:func:`_contacts_terms` of ``balls``, the model's ``contact_rolling_terms``).

    Returns
    -------
    None or tuple
        None, (Fa,A, Fa,B, Fr) [N] or the contacts' terms.

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = thermal_state(pair, 293.15)
    >>> rolling_data(pair, th, 40.0, 40.0, 0.0, []) is None  # the default model needs nothing
    True
    """
    entry = registry.get(pair.friction.model)
    if entry.data == "loads":
        return entry.implementation().rolling_loads(force_a, force_b, radial_load)
    if entry.data == "contacts":
        return _contacts_terms(pair, thermal, balls, entry.implementation().contact_rolling_terms)
    return None


def _max_pressure(load, inner, outer):
    return np.maximum(inner.max_pressure(load), outer.max_pressure(load)).max(axis=-1)


def load_state(pair: BearingPair, thermal: ThermalState, axial_load=0.0, radial_load=0.0):
    """State of the pair at ``thermal`` under ``axial_load`` [N] (pressing bearing A) and
    ``radial_load`` [N]. Vectorised over temperature when the radial load is zero (every ball
    of a bearing alike, Yu eq 4); a radial load is solved per ball (Jones) with the pair
    equilibrium of :func:`preload.pair_equilibrium` (scalar temperature).

    Returns
    -------
    LoadState
        Forces [N], contact angle [rad], stiffness [N/m], pressure [Pa], flags and the
        speed-independent torques [N·m].

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = thermal_state(pair, 233.15)
    >>> ls = load_state(pair, th, axial_load=5.0)
    >>> round(float(ls.force_a - ls.force_b), 9), round(float(ls.preload), 2)  # N
    (5.0, 43.2)
    """
    f_ext = check_finite("axial_load", axial_load, "N")
    f_r = check_finite("radial_load", radial_load, "N")
    if np.any(np.asarray(f_r) != 0):
        return _combined_load_state(pair, thermal, float(f_ext), float(f_r))
    if np.all(np.asarray(f_ext) == 0):  # the thermal state holds the unloaded offsets
        a_a = thermal.preload_offset
        a_b = a_a + thermal.closure if is_tandem(pair) else a_a
    else:
        off = axial_offsets(thermal.geometry, pair_rows(pair), thermal.closure, f_ext)
        a_a, a_b = off.offset_a, off.offset_b
    return axial_load_state(pair, thermal, a_a, a_b)


def axial_load_state(pair: BearingPair, thermal: ThermalState, offset_a, offset_b) -> LoadState:
    """:class:`LoadState` of the pair with bearings A and B at axial offsets ``offset_a``,
    ``offset_b`` [m] and no radial load: every ball of a bearing alike (Yu eq 4), so the
    torques are Z times one ball's (elementwise over arrays).

    Returns
    -------
    LoadState

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = thermal_state(pair, 233.15)
    >>> ls = axial_load_state(pair, th, th.preload_offset, th.preload_offset)
    >>> round(float(ls.force_a), 3) == round(float(ls.force_b), 3), bool(ls.unloaded)
    (True, False)
    """
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
    rolling = rolling_data(
        pair, thermal, sa.axial_force, sb.axial_force, 0.0,
        [(qa, ala, *ea, float(z)), (qb, alb, *eb, float(z))],
    )  # fmt: skip
    return LoadState(
        force_a=sa.axial_force,
        force_b=sb.axial_force,
        preload=preload_force(sa.axial_force, sb.axial_force),
        contact_angle=angle,
        axial_stiffness=_pair_stiffness(pair, sa.axial_stiffness, sb.axial_stiffness, k),
        max_contact_pressure=p_max,
        **state_flags(pair, geom.clearance, p_max, sa.axial_force, sb.axial_force),
        torques=t,
        axial_play=axial_play(
            geom.first_contact_offset, offset_a, offset_b, sa.axial_force, sb.axial_force
        ),
        axial_displacement=_displacement(pair, thermal, offset_a, offset_b),
        offset_a=np.asarray(offset_a),
        offset_b=np.asarray(offset_b),
        rolling=rolling,
    )


def _pair_stiffness(pair: BearingPair, ka, kb, k):
    """Axial stiffness of the shaft [N/m] from the bearings' ``ka``, ``kb`` and the loop's
    (a tandem pair: the spring's) ``k`` [N/m]."""
    return pair_rows(pair).axial_stiffness(ka, kb)


def _displacement(pair: BearingPair, thermal: ThermalState, offset_a, offset_b):
    """Axial displacement of the shaft from its unloaded position [m], positive towards A:
    (a_A − a_B)/2; a tandem pair: a_A less its offset at zero external load, positive along
    the thrust."""
    if is_tandem(pair):
        return np.asarray(offset_a) - np.asarray(thermal.preload_offset)
    return 0.5 * (np.asarray(offset_a) - np.asarray(offset_b))


def _combined_load_state(pair, thermal, f_ext, f_r) -> LoadState:
    if np.ndim(thermal.temperature):
        raise ValueError("a radial load needs a scalar temperature (one thermal state)")
    geom, k = thermal.geometry, thermal.loop_stiffness
    st = pair_equilibrium(geom, float(thermal.closure), pair_rows(pair), f_ext, f_r)
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
    rolling = rolling_data(
        pair, thermal, fa, fb, f_r,
        [(b.load[0], b.contact_angle[0], _first(b.inner), _first(b.outer), 1.0) for b in (la, lb)],
    )  # fmt: skip
    return LoadState(
        force_a=fa,
        force_b=fb,
        preload=preload_force(fa, fb),
        contact_angle=angle,
        axial_stiffness=float(_pair_stiffness(pair, ka, kb, k)),
        max_contact_pressure=p_max,
        **state_flags(pair, geom.clearance, p_max, fa, fb, st.converged),
        torques=t,
        axial_play=axial_play(
            float(geom.first_contact_offset), float(st.offset_a), float(st.offset_b), fa, fb
        ),
        axial_displacement=float(_displacement(pair, thermal, st.offset_a, st.offset_b)),
        converged=st.converged,
        offset_a=st.offset_a,
        offset_b=st.offset_b,
        radial_a=st.radial_a,
        radial_b=st.radial_b,
        ball_cosines=tuple(np.cos(b.contact_angle[0, : geom.n_balls // 2 + 1]) for b in (la, lb)),
        rolling=rolling,
    )


def _first(c):
    """The contact constants of the first (only) operating point of an equilibrium state."""
    return type(c)(*(np.asarray(getattr(c, f.name))[0] for f in fields(c)))


@dataclass(slots=True)
class BearingOutputs:
    """Everything the BearingFriction FMU reports, SI; arrays or floats.

    friction_torque [N·m] signed like speed (opposes rotation), running_torque and
    breakaway_torque [N·m], hysteresis/spin/sliding/viscous_torque [N·m] (viscous: the
    rolling/viscous part of the friction model, its ``running_terms``), grease_torque [N·m] (the
    grease term's running torque), preload [N], contact_angle [rad], radial_clearance [m],
    kinematic_viscosity [m²/s], axial_stiffness [N/m], power_loss [W], overloaded, locked, unloaded
    (see :func:`state_flags`); plus inner_ring_torque/outer_ring_torque [N·m], max_contact_pressure
    [Pa],
    outer/inner_fit_pressure [Pa], outer/inner_interference [m], force_a/force_b [N],
    axial_displacement [m]; axial_play [m] (:func:`axial_play`), reverse_loaded
    (:func:`state_flags`), outside_lubricant_range (the lubricant's temperature outside the
    range of its data, :mod:`.lubrication.viscosity`) and breakaway_lower_bound (a fluid lubricant
    without published starting data: :attr:`.pair.configuration.BearingPair.breakaway_lower_bound`).
    """

    friction_torque: float
    running_torque: float
    breakaway_torque: float
    hysteresis_torque: float
    spin_torque: float
    sliding_torque: float
    viscous_torque: float
    grease_torque: float
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
    axial_play: float
    reverse_loaded: bool
    outside_lubricant_range: bool
    breakaway_lower_bound: bool = False

    def as_dict(self) -> dict:
        return {f.name: getattr(self, f.name) for f in fields(self)}


def _speed_terms(pair: BearingPair, viscosity, pitch_diameter, coulomb, excess, sliding, rolling,
                 w):  # fmt: skip
    """(signed friction, running, sliding, viscous, grease torque) [N·m] at speed w [rad/s]
    (Yu 2017 eq 8–9 and the regularised sign; the friction model of
    :mod:`.friction.models`) from the kinematic viscosity [m²/s], the pitch diameter [m], the
    Coulomb torque (hysteresis + spin + sliding of the contacts), the breakaway excess, the
    contacts' sliding torque [N·m] and the model's ``rolling`` data (:func:`rolling_data`);
    floats in, floats out on the per-step path."""
    fm = pair.friction
    viscous, skf_sliding = _model_terms(pair, viscosity, pitch_diameter, rolling, w)
    if skf_sliding is not None:
        sliding = skf_sliding
        running = coulomb + sliding + viscous
    else:
        running = coulomb + viscous
    if fm.grease is None:
        grease = 0.0
    else:
        grease = grease_running(pair, viscosity, w)
        running = running + grease
    signed = regularised_torque(w, running, excess, pair.regularisation_speed, pair.stribeck_speed)
    return signed, running, sliding, viscous, grease


def _model_terms(pair: BearingPair, viscosity, pitch_diameter, rolling, w):
    """(viscous torque, the model's own sliding torque or None) [N·m] of the pair's friction
    model at speed w [rad/s] (its ``running_terms``, :mod:`.friction.registry`)."""
    model = registry.get(pair.friction.model).implementation()
    return model.running_terms(pair, viscosity, pitch_diameter, rolling, w)


def _coulomb_excess(pair: BearingPair, hysteresis, spin, sliding):
    """(Coulomb torque hysteresis + spin + sliding, breakaway excess (μ_s/μ − 1)·(spin +
    sliding)) [N·m] (Yu 2017 eq 9; the static friction of spin and sliding)."""
    return coulomb_and_excess(pair.coefficients.static_friction_ratio, hysteresis, spin, sliding)


def contact_terms(pair: BearingPair, hysteresis, spin, sliding, inner, outer):
    """The per-contact torques (hysteresis, spin, sliding, inner ring, outer ring) [N·m] as the
    friction model counts them: Yu's and Ning's terms, or zeros under a model whose own
    moments replace them (:attr:`~.friction.registry.Entry.contact_terms` False).

    Parameters
    ----------
    pair : BearingPair
        The pair (its friction model).
    hysteresis, spin, sliding, inner, outer : float or ndarray
        The contacts' torques [N·m].

    Returns
    -------
    tuple
        (hysteresis, spin, sliding, inner ring, outer ring) [N·m].

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> contact_terms(pair, 1e-4, 2e-4, 0.0, 1e-4, 2e-4)  # the default model: as they are
    (0.0001, 0.0002, 0.0, 0.0001, 0.0002)
    """
    if not registry.get(pair.friction.model).contact_terms:
        zero = 0.0 * hysteresis
        return zero, zero, zero, zero, zero
    return hysteresis, spin, sliding, inner, outer


def state_torques(pair: BearingPair, hysteresis, spin, sliding, viscosity, pitch_diameter,
                  rolling, rest=None):  # fmt: skip
    """(Coulomb torque, breakaway excess, breakaway torque) [N·m] of the state: the running
    torque at rest plus the excess of the starting torque over it. A friction model that
    counts the contacts' terms (:attr:`~.friction.registry.Entry.contact_terms`): hysteresis +
    spin + sliding, (μ_s/μ − 1)·(spin + sliding), and its viscous torque at rest (``rest``,
    :func:`rest_torque` when not given: Palmgren's, 0 for a model without it); a model with
    its own: its ``starting_torque`` (no excess); plus
    the lubricant's cold start (:mod:`.friction.grease`): with a grease term (f0 > 0) its
    starting torque ks·M0 at the test speed (:func:`.friction.models.grease_rest_and_start`),
    without one (ks alone) ks times the friction model's viscous torque at the test speed,
    never below that torque at rest.

    Parameters
    ----------
    pair : BearingPair
        The pair.
    hysteresis, spin, sliding : float or ndarray
        Torques [N·m].
    viscosity : float or ndarray
        ν [m²/s].
    pitch_diameter : float or ndarray
        dm [m].
    rolling : None or tuple
        :func:`rolling_data`.
    rest : float or None
        Viscous torque at rest [N·m] (None: :func:`rest_torque`).

    Returns
    -------
    tuple
        (Coulomb torque, breakaway excess, breakaway torque) [N·m].

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> c, excess, brk = state_torques(pair, 1e-4, 2e-4, 0.0, 0.0, 21.5e-3, None)
    >>> round(c * 1e3, 6), round(brk * 1e3, 6)  # N·mm: + excess + Palmgren's floor at rest
    (0.3, 0.559316)
    """
    entry = registry.get(pair.friction.model)
    own = not entry.contact_terms  # the model's own starting torque and sliding torque
    if own:
        coulomb = excess = 0.0
        rest = entry.implementation().starting_torque(pair, rolling)
    else:
        coulomb, excess = _coulomb_excess(pair, hysteresis, spin, sliding)
        if rest is None:
            rest = rest_torque(pair, viscosity, pitch_diameter)
    g = pair.friction.grease
    if g is not None and g.f0 > 0.0:  # the grease term and its start (ks·M0 at the test speed)
        g_rest, g_start = grease_rest_and_start(pair, viscosity)
        excess = excess + (g_start - g_rest)
        rest = rest + g_rest
    elif g is not None and g.has_start:  # ks on the friction model's own viscous torque
        v_rest = 0.0 * rest if own else rest  # a model's own starting torque is not viscous
        v_ref = _model_terms(pair, viscosity, pitch_diameter, rolling, g.reference_speed)[0]
        start = g.starting_ratio * v_ref
        maximum = max if type(start) is float and type(v_rest) is float else np.maximum
        excess = excess + (maximum(start, v_rest) - v_rest)
    return coulomb, excess, coulomb + excess + rest


def rest_torque(pair: BearingPair, viscosity, pitch_diameter):
    """Viscous torque of the pair at rest (Palmgren's eq 8 below its threshold) [N·m] under a
    friction model whose viscous torque is Palmgren's
    (:attr:`~.friction.registry.Entry.palmgren`), 0 under the others.

    Parameters
    ----------
    pair : BearingPair
        The pair.
    viscosity : float or ndarray
        ν [m²/s].
    pitch_diameter : float or ndarray
        dm [m].

    Returns
    -------
    float or ndarray
        [N·m].

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> round(float(rest_torque(pair, 100e-6, 21.5e-3)) * 1e3, 6)  # N·mm, two bearings
    0.219316
    """
    palmgren = pair.lubricant is not None and registry.get(pair.friction.model).palmgren
    s0 = pair.coefficients.palmgren_s0 if palmgren else 0.0
    return 2.0 * palmgren_torque(viscosity, 0.0, pitch_diameter, s0)


def bearing_outputs(
    pair: BearingPair, thermal: ThermalState, load: LoadState, speed
) -> BearingOutputs:
    """Speed-dependent outputs at ``speed`` [rad/s] (Yu 2017 eq 8–9, or the pair's friction
    model; regularised sign).

    Parameters
    ----------
    pair : BearingPair
        The pair.
    thermal : ThermalState
        :func:`thermal_state`.
    load : LoadState
        :func:`load_state`.
    speed : float or array_like
        ω [rad/s], signed.

    Returns
    -------
    BearingOutputs
        Torques [N·m], forces [N], angles [rad], lengths [m], viscosity [m²/s],
        stiffness [N/m], power [W], pressures [Pa], flags.

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = thermal_state(pair, 233.15)
    >>> out = bearing_outputs(pair, th, load_state(pair, th), 0.17)
    >>> round(float(out.running_torque) * 1e3, 3)  # N·mm at −40 °C
    3.13
    """
    w = speed if type(speed) is float else check_finite("speed", speed, "rad/s")
    t = load.torques
    nu, dm = thermal.kinematic_viscosity, thermal.pitch_diameter
    hyst, spin, slide, inner, outer = contact_terms(
        pair, t.hysteresis, t.spin, t.sliding, t.inner_ring, t.outer_ring
    )
    coulomb, excess, breakaway = state_torques(pair, hyst, spin, slide, nu, dm, load.rolling)
    signed, running, sliding, viscous, grease = _speed_terms(
        pair, nu, dm, coulomb, excess, slide, load.rolling, w
    )
    return BearingOutputs(
        friction_torque=signed,
        running_torque=running,
        breakaway_torque=breakaway,
        hysteresis_torque=hyst,
        spin_torque=spin,
        sliding_torque=sliding,
        viscous_torque=viscous,
        grease_torque=grease,
        preload=load.preload,
        contact_angle=load.contact_angle,
        radial_clearance=thermal.clearance,
        kinematic_viscosity=nu,
        axial_stiffness=load.axial_stiffness,
        power_loss=signed * w,
        overloaded=load.overloaded,
        locked=load.locked,
        unloaded=load.unloaded,
        inner_ring_torque=inner,
        outer_ring_torque=outer,
        max_contact_pressure=load.max_contact_pressure,
        outer_fit_pressure=thermal.outer_fit_pressure,
        inner_fit_pressure=thermal.inner_fit_pressure,
        outer_interference=thermal.outer_interference,
        inner_interference=thermal.inner_interference,
        force_a=load.force_a,
        force_b=load.force_b,
        axial_displacement=load.axial_displacement,
        axial_play=load.axial_play,
        reverse_loaded=load.reverse_loaded,
        outside_lubricant_range=thermal.outside_lubricant_range,
        breakaway_lower_bound=_broadcast(pair.breakaway_lower_bound, running),
    )


def _broadcast(flag: bool, like):
    """``flag`` shaped like ``like`` (a bool for a float)."""
    return flag if np.ndim(like) == 0 else np.full(np.shape(like), flag)


def point_state(cls, pair: BearingPair, thermal, torques, load, flags, rest=None,
                rolling=None):  # fmt: skip
    """A :class:`~.pair.continuation.PointState` (of class ``cls``: the compiled or the Python one)
    from the thermal state ``thermal`` (clearance, viscosity, pitch diameter, fits, the
    lubricant's range flag), ``torques`` = (hysteresis, spin, sliding, inner ring, outer ring)
    [N·m], ``load`` = (preload [N], contact angle [rad], axial stiffness [N/m], largest
    pressure [Pa], force_a, force_b [N], axial displacement [m], axial play [m]), ``flags`` =
    (overloaded, locked, unloaded, reverse_loaded) (:func:`state_flags`), the viscous torque at
    rest [N·m] (:func:`rest_torque`, evaluated when not given) and the friction model's
    ``rolling`` data (:func:`rolling_data`, floats).

    Returns
    -------
    PointState

    Examples
    --------
    >>> from servofmu.physics.pair.state import PointState
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = to_floats(thermal_state(pair, 293.15))
    >>> pt = point_state(PointState, pair, th, (1e-4, 2e-4, 0.0, 1e-4, 2e-4),
    ...                  (40.0, 0.26, 3e7, 1e9, 40.0, 40.0, 0.0, 0.0), (False,) * 4)
    >>> round(pt.coulomb_torque * 1e3, 6)  # N·mm: hysteresis + spin + sliding
    0.3
    """
    nu, dm = thermal.kinematic_viscosity, thermal.pitch_diameter
    hyst, spin, slide, inner, outer = contact_terms(pair, *torques)
    coulomb, excess, breakaway = state_torques(pair, hyst, spin, slide, nu, dm, rolling, rest)
    return cls(
        hyst, spin, slide, inner, outer, coulomb, excess, breakaway, load[0], load[1],
        thermal.clearance, nu, dm, load[2], load[3], thermal.outer_fit_pressure,
        thermal.inner_fit_pressure, thermal.outer_interference, thermal.inner_interference,
        load[4], load[5], load[6], *flags, thermal.outside_lubricant_range, load[7], rolling,
    )  # fmt: skip


def exact_point(cls, pair: BearingPair, thermal: ThermalState, load: LoadState):
    """:func:`point_state` from the exact path's thermal and load state (fields as floats,
    :func:`to_floats`).

    Returns
    -------
    PointState

    Examples
    --------
    >>> from servofmu.physics.pair.state import PointState
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = to_floats(thermal_state(pair, 293.15))
    >>> ls = to_floats(load_state(pair, th))
    >>> exact_point(PointState, pair, th, ls).preload == ls.preload  # N
    True
    """
    t = load.torques
    return point_state(
        cls,
        pair,
        thermal,
        (t.hysteresis, t.spin, t.sliding, t.inner_ring, t.outer_ring),
        (
            load.preload,
            load.contact_angle,
            load.axial_stiffness,
            load.max_contact_pressure,
            load.force_a,
            load.force_b,
            load.axial_displacement,
            load.axial_play,
        ),
        (load.overloaded, load.locked, load.unloaded, load.reverse_loaded),
        rolling=_rolling_floats(load.rolling),
    )


def point_outputs(point, speed_outputs, breakaway_lower_bound: bool = False) -> BearingOutputs:
    """:class:`BearingOutputs` of the state ``point`` (:class:`~.pair.continuation.PointState`) with
    the speed outputs ``speed_outputs`` = (friction, running, sliding, viscous, grease torque
    [N·m], power loss [W]) (:meth:`~.pair.continuation.PairSolver.speed_outputs`) and the pair's
    ``breakaway_lower_bound``: the same numbers as :func:`bearing_outputs` on the exact path's
    state.

    Returns
    -------
    BearingOutputs

    Examples
    --------
    >>> from servofmu.physics.pair.state import PointState
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = to_floats(thermal_state(pair, 293.15))
    >>> pt = exact_point(PointState, pair, th, to_floats(load_state(pair, th)))
    >>> point_outputs(pt, (1e-3, 1e-3, 0.0, 5e-4, 0.0, 1e-4)).power_loss  # W
    0.0001
    """
    signed, running, sliding, viscous, grease, power = speed_outputs
    return BearingOutputs(
        signed,
        running,
        point.breakaway_torque,
        point.hysteresis_torque,
        point.spin_torque,
        sliding,
        viscous,
        grease,
        point.preload,
        point.contact_angle,
        point.radial_clearance,
        point.kinematic_viscosity,
        point.axial_stiffness,
        power,
        point.overloaded,
        point.locked,
        point.unloaded,
        point.inner_ring_torque,
        point.outer_ring_torque,
        point.max_contact_pressure,
        point.outer_fit_pressure,
        point.inner_fit_pressure,
        point.outer_interference,
        point.inner_interference,
        point.force_a,
        point.force_b,
        point.axial_displacement,
        point.axial_play,
        point.reverse_loaded,
        point.outside_lubricant_range,
        breakaway_lower_bound,
    )


def _rolling_floats(rolling):
    """The exact path's :func:`rolling_data` of one operating point as floats: the bearings'
    loads as floats, the contacts' terms as tuples of floats of the loaded contacts only."""
    if rolling is None:
        return None
    if isinstance(rolling[0], np.ndarray) and np.ndim(rolling[0]) == 1:
        keep = rolling[0] > 0.0
        return tuple(tuple(float(x) for x in np.asarray(r)[keep]) for r in rolling)
    return tuple(float(x) for x in rolling)


def operating_outputs(
    pair: BearingPair, temperature, speed, axial_load=0.0, radial_load=0.0
) -> BearingOutputs:
    """Exact outputs at temperature [K], speed [rad/s], axial load [N] (arrays broadcast
    together; vectorised when the radial load is zero) and radial load [N] (then scalars):
    :func:`thermal_state`, :func:`load_state` and :func:`bearing_outputs` in one call.

    Returns
    -------
    BearingOutputs

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> out = operating_outputs(pair, np.array([233.15, 293.15]), 0.17)
    >>> [round(float(m) * 1e3, 3) for m in out.running_torque]  # N·mm at −40 and 20 °C
    [3.13, 0.299]
    """
    th = thermal_state(pair, temperature)
    return bearing_outputs(pair, th, load_state(pair, th, axial_load, radial_load), speed)


def to_floats(obj):
    """The dataclass ``obj`` with every 0-d array field (recursively) made a Python float or
    bool, for the per-step scalar path.

    Parameters
    ----------
    obj : dataclass instance

    Returns
    -------
    dataclass instance
        A copy with floats and bools.

    Examples
    --------
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> th = to_floats(thermal_state(pair, 293.15))
    >>> type(th.closure).__name__
    'float'
    """
    changes = {}
    for f in fields(obj):
        v = getattr(obj, f.name)
        if dataclasses.is_dataclass(v):
            changes[f.name] = to_floats(v)
        elif isinstance(v, (np.ndarray, np.generic)) and np.ndim(v) == 0:
            changes[f.name] = bool(v) if v.dtype == bool else float(v)
    return dataclasses.replace(obj, **changes)

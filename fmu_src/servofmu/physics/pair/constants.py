# cython: language_level=3, auto_pickle=False, embedsignature=False
"""A bearing pair's data as floats (:class:`PairConstants`) and its thermal state at the
parts' temperatures (:class:`Thermal`, :func:`thermal_at`): the mounted raceways of
:func:`~servofmu.physics.kernels.lame.mounted_races` (Yu 2017 eq 10–13), the race geometry,
the loop closure (eq 14–15) and the lubricant's viscosity (eq 18 or Vogel's law) on floats,
and the friction terms' coefficients per state. The per-step path's start
(:mod:`.continuation`); the exact path's is :func:`.state.thermal_state`.

Examples
--------
>>> from servofmu.physics.pair.configuration import BearingPair
>>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
>>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
>>> round(th.clearance * 1e6, 4)  # µm: the mounted clearance at assembly
9.6583
"""

import math

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import cbrt, exp, log10
    from cython.cimports.servofmu.physics.kernels._contact import (
        curvature_distance,
        diametral_clearance,
        first_contact_offset,
        free_contact_angle,
        pitch_diameter,
    )
    from cython.cimports.servofmu.physics.kernels._friction import (
        contact_spin_moment,
        heathcote_force,
        hysteresis_force,
    )
    from cython.cimports.servofmu.physics.kernels._lame import mounted_races
    from cython.cimports.servofmu.physics.kernels._viscosity import (
        operating_temperature,
        vogel_log_viscosity,
        walther_viscosity,
    )
    from cython.cimports.servofmu.physics.pair._rows import PairRows, loop_closure_at
else:
    from math import cbrt, exp, log10

    from ..kernels.contact import (
        curvature_distance,
        diametral_clearance,
        first_contact_offset,
        free_contact_angle,
        pitch_diameter,
    )
    from ..kernels.friction import contact_spin_moment, heathcote_force, hysteresis_force
    from ..kernels.lame import mounted_races
    from ..kernels.viscosity import operating_temperature, vogel_log_viscosity, walther_viscosity
    from .rows import PairRows, loop_closure_at

from ..kernels.units import CST

_INF: cython.double = math.inf
_CST: cython.double = CST
#: Viscosity laws (:mod:`servofmu.physics.lubrication.viscosity`) by number.
_NO_LAW: cython.int = 0
_WALTHER: cython.int = 1
_VOGEL: cython.int = 2
_OTHER_LAW: cython.int = 3


@cython.final
@cython.cclass
class PairConstants:
    """The pair's data as floats, for the per-step equations (built once per configuration).

    Parameters
    ----------
    pair : :class:`~.bearing.BearingPair`
    """

    pair: object
    t0: cython.double
    outer_diameter: cython.double
    bore: cython.double
    outer_groove: cython.double
    inner_groove: cython.double
    ball_diameter: cython.double
    inner_curvature: cython.double
    outer_curvature: cython.double
    n_balls: cython.int
    compliance: cython.double
    alpha_ring: cython.double
    e_ring: cython.double
    nu_ring: cython.double
    alpha_ball: cython.double
    alpha_housing: cython.double
    e_housing: cython.double
    nu_housing: cython.double
    alpha_shaft: cython.double
    e_shaft: cython.double
    nu_shaft: cython.double
    outer_interference: cython.double
    inner_interference: cython.double
    housing_outer_diameter: cython.double
    shaft_bore: cython.double
    coupled: cython.bint
    seat_outer: cython.double
    seat_inner: cython.double
    closure_housing: cython.double
    closure_shaft: cython.double
    closure_rings: cython.double
    closure0: cython.double
    tandem: cython.bint
    rows: PairRows
    spring_stiffness: cython.double
    viscosity: object
    law: cython.int
    law_a: cython.double
    law_b: cython.double
    law_c: cython.double
    hold_temperature: cython.double
    lubricated: cython.bint
    lower_limit: cython.double
    upper_limit: cython.double
    solid: cython.bint
    sliding: cython.bint
    pressure_limit: cython.double
    fast: cython.bint
    needs_loads: cython.bint
    needs_contacts: cython.bint
    density: cython.double
    hysteresis_loss: cython.double
    mu: cython.double
    static_ratio: cython.double
    s0: cython.double
    rest_s0: cython.double
    w_reg: cython.double
    w_stribeck: cython.double
    python: object
    model: object
    __slots__ = (
        "alpha_ball",
        "alpha_housing",
        "alpha_ring",
        "alpha_shaft",
        "ball_diameter",
        "bore",
        "closure0",
        "closure_housing",
        "closure_rings",
        "closure_shaft",
        "compliance",
        "coupled",
        "density",
        "e_housing",
        "e_ring",
        "e_shaft",
        "fast",
        "hold_temperature",
        "housing_outer_diameter",
        "hysteresis_loss",
        "inner_curvature",
        "inner_groove",
        "inner_interference",
        "law",
        "law_a",
        "law_b",
        "law_c",
        "lower_limit",
        "lubricated",
        "model",
        "mu",
        "n_balls",
        "needs_contacts",
        "needs_loads",
        "nu_housing",
        "nu_ring",
        "nu_shaft",
        "outer_curvature",
        "outer_diameter",
        "outer_groove",
        "outer_interference",
        "pair",
        "pressure_limit",
        "python",
        "rest_s0",
        "rows",
        "s0",
        "seat_inner",
        "seat_outer",
        "shaft_bore",
        "sliding",
        "solid",
        "spring_stiffness",
        "static_ratio",
        "t0",
        "tandem",
        "upper_limit",
        "viscosity",
        "w_reg",
        "w_stribeck",
    )

    def __init__(self, pair):
        from ..friction import registry
        from ..materials import reduced_compliance
        from . import state as pair_state  # the pair-level functions (imported when first used)
        from .configuration import closure_coefficients, pair_rows

        b, m = pair.bearing, pair.mounting
        fit = m.fit
        ring, ball = b.ring_material, b.ball_material
        hm, sm = fit.housing_material, fit.shaft_material
        self.pair = pair
        self.python = pair_state
        self.t0 = float(m.assembly_temperature)
        self.outer_diameter, self.bore = float(b.outer_diameter), float(b.bore)
        self.outer_groove = float(b.outer_groove_diameter)
        self.inner_groove = float(b.inner_groove_diameter)
        self.ball_diameter = float(b.ball_diameter)
        self.inner_curvature = float(b.inner_curvature)
        self.outer_curvature = float(b.outer_curvature)
        self.n_balls = int(b.n_balls)
        eta = float(reduced_compliance(ring, ball))
        self.compliance = eta
        self.alpha_ring = ring.expansion
        self.e_ring, self.nu_ring = ring.youngs_modulus, ring.poisson_ratio
        self.alpha_ball = ball.expansion
        self.alpha_housing, self.e_housing = hm.expansion, hm.youngs_modulus
        self.nu_housing = hm.poisson_ratio
        self.alpha_shaft, self.e_shaft = sm.expansion, sm.youngs_modulus
        self.nu_shaft = sm.poisson_ratio
        self.outer_interference = float(fit.outer_interference)
        self.inner_interference = float(fit.inner_interference)
        self.housing_outer_diameter = float(fit.housing_outer_diameter)
        self.shaft_bore = float(fit.shaft_bore)
        self.coupled = bool(pair.thermal_coupling)
        self.seat_outer = self.outer_diameter - self.outer_interference  # housing bore at T0
        self.seat_inner = self.bore + self.inner_interference  # shaft seat at T0
        # loop closure C = C0 − Σ σ·L·α·(T_part − T0), summed by part (a tandem pair: B's
        # mismatch d(T), 0 at T0; pair.loop_closure)
        closure = closure_coefficients(pair)
        self.closure0, self.closure_housing, self.closure_shaft, self.closure_rings = closure
        rows = pair_rows(pair)
        self.tandem = rows.is_tandem
        self.rows = PairRows(rows.is_tandem, rows.stiffness, rows.thrust)
        self.spring_stiffness = self.rows.spring
        visc = pair.lubricant
        # the lubricant's law on floats, held below its flow limit when the user chose so, and
        # the range of its data (:mod:`.lubrication.viscosity`)
        self.viscosity = None if visc is None else visc.operating_viscosity_at
        self.law, self.law_a, self.law_b, self.law_c = _law(visc)
        self.hold_temperature = 0.0 if visc is None else visc.hold_temperature
        self.lubricated = visc is not None
        self.lower_limit = 0.0 if visc is None else visc.lower_limit
        self.upper_limit = _INF if visc is None else visc.upper_limit
        self.solid = pair.lubrication == "solid"
        self.sliding = bool(pair.sliding)
        self.pressure_limit = float(pair.pressure_limit)
        fm = pair.friction
        model = registry.get(fm.model)
        self.model = model.implementation()  # its module: the data its speed terms need
        yu = model.palmgren  # the speed terms computed here (Palmgren's), else in Python
        self.fast = yu and fm.grease is None
        self.needs_loads = model.data == "loads"
        self.needs_contacts = model.data == "contacts"
        self.density = float(fm.lubricant_density)
        co = pair.coefficients
        self.hysteresis_loss, self.mu = co.hysteresis_loss, co.sliding_friction
        self.static_ratio = co.static_friction_ratio
        # Palmgren's s0 running (a lubricant) and at rest (a Palmgren model only)
        self.s0 = co.palmgren_s0 if visc is not None else 0.0
        self.rest_s0 = self.s0 if yu else 0.0
        self.w_reg = float(pair.regularisation_speed)
        self.w_stribeck = float(pair.stribeck_speed)

    @property
    def loop_stiffness(self) -> float:
        """The loop's stiffness [N/m] (a tandem pair: its spring's)."""
        return self.rows.stiffness


def _law(visc) -> tuple:
    """(law, a, b, c) of a viscosity model: Walther's (1, a, b, c), Vogel's (2, a, b, T∞),
    none (0: a dry film), or another model (3: its own method)."""
    from ..lubrication.viscosity import VogelViscosity, WaltherViscosity

    if visc is None:
        return _NO_LAW, 0.0, 0.0, 0.0
    if isinstance(visc, WaltherViscosity):
        return _WALTHER, visc.a, visc.b, visc.c
    if isinstance(visc, VogelViscosity):
        return _VOGEL, visc.a, visc.b, visc.t_inf
    return _OTHER_LAW, 0.0, 0.0, 0.0


@cython.cfunc
def _viscosity(c: PairConstants, t: cython.double) -> cython.double:
    """The viscosity [m²/s] the bearing uses at the lubricant's temperature ``t`` [K] (Yu 2017
    eq 18 or Vogel's law, held below the flow limit when chosen; :mod:`.lubrication.viscosity`)."""
    if c.law == _NO_LAW:
        return 0.0
    nu: cython.double = _INF
    at: cython.double = operating_temperature(t, c.hold_temperature)
    if c.law == _WALTHER:
        nu = walther_viscosity(log10(at), c.law_a, c.law_b, c.law_c) * _CST
    elif c.law == _VOGEL:
        nu = exp(vogel_log_viscosity(at, c.law_a, c.law_b, c.law_c))
    if nu < _INF:
        return nu
    return c.viscosity(t)  # another law, or none at this temperature: the model's own error


# ------------------------------------------------------------------ the thermal state
@cython.final
@cython.cclass
class Thermal:
    """Thermal state of one step, as floats: the fields of :class:`~.pair.state.ThermalState`
    that the outputs read, and the race geometry of :class:`~.contact.geometry.RaceGeometry` that
    the contacts need (γ scale Dw/dm, 1/f = Dw/r of each groove); some evaluated when first
    needed (the viscous torque at rest, the torque coefficients, a tandem pair's offset at
    zero external load)."""

    t_housing: cython.double
    t_shaft: cython.double
    t_outer: cython.double
    t_inner: cython.double
    ball_diameter: cython.double
    clearance: cython.double
    closure: cython.double
    curvature_distance: cython.double
    dw_third: cython.double
    first_contact_offset: cython.double
    gamma_scale: cython.double
    inner_fit_pressure: cython.double
    inner_groove_radius: cython.double
    inner_interference: cython.double
    inv_f_inner: cython.double
    inv_f_outer: cython.double
    kinematic_viscosity: cython.double
    outer_fit_pressure: cython.double
    outer_groove_radius: cython.double
    outer_interference: cython.double
    outside_lubricant_range: cython.bint
    pitch_diameter: cython.double
    radial_centre_distance: cython.double
    has_rest: cython.bint
    rest_torque: cython.double
    has_rest_offset: cython.bint
    rest_offset: cython.double
    has_coefficients: cython.bint
    c_hysteresis: cython.double
    c_sliding_inner: cython.double
    c_sliding_outer: cython.double
    c_spin: cython.double
    __slots__ = (
        "ball_diameter",
        "c_hysteresis",
        "c_sliding_inner",
        "c_sliding_outer",
        "c_spin",
        "clearance",
        "closure",
        "curvature_distance",
        "dw_third",
        "first_contact_offset",
        "gamma_scale",
        "has_coefficients",
        "has_rest",
        "has_rest_offset",
        "inner_fit_pressure",
        "inner_groove_radius",
        "inner_interference",
        "inv_f_inner",
        "inv_f_outer",
        "kinematic_viscosity",
        "outer_fit_pressure",
        "outer_groove_radius",
        "outer_interference",
        "outside_lubricant_range",
        "pitch_diameter",
        "radial_centre_distance",
        "rest_offset",
        "rest_torque",
        "t_housing",
        "t_inner",
        "t_outer",
        "t_shaft",
    )

    @property
    def temperatures(self) -> tuple:
        """(housing, shaft, outer ring, inner ring) [K]."""
        return (self.t_housing, self.t_shaft, self.t_outer, self.t_inner)

    @property
    def free_contact_angle(self) -> float:
        """Free contact angle at the operating clearance [rad] (:class:`RaceGeometry`)."""
        return free_angle(self)

    @property
    def torque_coefficients(self) -> tuple:
        """:func:`torque_coefficients` at this state (evaluated when first needed)."""
        return torque_coefficients(self)


@cython.cfunc
def free_angle(th: Thermal) -> cython.double:
    """Free contact angle [rad] at the thermal state ``th``
    (:func:`~servofmu.physics.kernels.contact.free_contact_angle` of its clearance).

    Returns
    -------
    float
        α0 [rad].

    Examples
    --------
    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> free_angle(th) == th.free_contact_angle
    True
    """
    return free_contact_angle(th.clearance, th.curvature_distance)


@cython.ccall
def thermal_at(
    c: PairConstants,
    t_h: cython.double,
    t_s: cython.double,
    t_o: cython.double,
    t_i: cython.double,
) -> Thermal:
    """Thermal state at the parts' temperatures (housing ``t_h``, shaft ``t_s``, outer ring
    ``t_o``, inner ring ``t_i``) [K]: the equations of :func:`fits.mounted_geometry` (Yu 2017
    eq 10–13; the Lamé ratio :func:`lame_ratio`), the loop closure (:func:`loop_closure_at`,
    eq 14–15) and the lubricant's viscosity (eq 18, or Vogel's law; :mod:`.lubrication.viscosity`)
    on floats, with the lubricant's range flag.

    Parameters
    ----------
    c : PairConstants
        The pair's data.
    t_h, t_s, t_o, t_i : float
        Temperatures [K].

    Returns
    -------
    Thermal
        Lengths [m], pressures [Pa], viscosity [m²/s].

    Examples
    --------
    At the assembly temperature the grooves keep their curvature, 1/f_i = 1/0.56 (by hand),
    and the clearance is that of :func:`fits.mounted_geometry` (9.6583 µm, 4.4114 MPa):

    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> round(th.inv_f_inner, 12) == round(1 / 0.56, 12)
    True
    >>> round(th.clearance * 1e6, 4), round(th.outer_fit_pressure / 1e6, 4)  # µm, MPa
    (9.6583, 4.4114)
    """
    t0: cython.double = c.t0
    t_b: cython.double = 0.5 * (t_o + t_i)
    d_i: cython.double
    d_o: cython.double
    dw: cython.double
    r_i: cython.double
    r_o: cython.double
    p_o: cython.double
    p_i: cython.double
    delta_o: cython.double
    delta_i: cython.double
    d_i, d_o, dw, r_i, r_o, p_o, p_i, delta_o, delta_i = mounted_races(
        t_h, t_s, t_o, t_i, t0,
        (c.alpha_ring, c.e_ring, c.nu_ring), c.alpha_ball,
        (c.alpha_housing, c.e_housing, c.nu_housing), (c.alpha_shaft, c.e_shaft, c.nu_shaft),
        (c.outer_diameter, c.bore, c.outer_groove, c.inner_groove, c.ball_diameter,
         c.inner_curvature, c.outer_curvature),
        (c.seat_outer, c.seat_inner, c.housing_outer_diameter, c.shaft_bore),
        c.coupled,
    )  # fmt: skip
    pd: cython.double = diametral_clearance(d_i, d_o, dw)
    a: cython.double = curvature_distance(r_i, r_o, dw)
    dm: cython.double = pitch_diameter(d_i, d_o)
    th: Thermal = Thermal.__new__(Thermal)
    th.t_housing, th.t_shaft, th.t_outer, th.t_inner = t_h, t_s, t_o, t_i
    th.ball_diameter, th.dw_third = dw, cbrt(dw)
    th.has_rest = th.has_coefficients = th.has_rest_offset = False  # when first needed
    th.rest_torque = th.rest_offset = 0.0
    th.c_hysteresis = th.c_sliding_inner = th.c_sliding_outer = th.c_spin = 0.0
    th.pitch_diameter = dm
    th.inner_groove_radius, th.outer_groove_radius = r_i, r_o
    th.inv_f_inner, th.inv_f_outer = dw / r_i, dw / r_o
    th.gamma_scale = dw / dm
    th.clearance = pd
    th.curvature_distance = a
    th.radial_centre_distance = a - 0.5 * pd
    th.closure = loop_closure_at(
        c.closure0, c.closure_housing, c.closure_shaft, c.closure_rings, t0, t_h, t_s, t_b
    )
    th.kinematic_viscosity = _viscosity(c, t_b)
    th.outside_lubricant_range = not c.lower_limit <= t_b <= c.upper_limit
    th.first_contact_offset = first_contact_offset(pd, a)
    th.outer_fit_pressure, th.inner_fit_pressure = p_o, p_i
    th.outer_interference, th.inner_interference = delta_o, delta_i
    return th


def thermal_floats(c: PairConstants, temps) -> Thermal:
    """:func:`thermal_at` at ``temps`` = (housing, shaft, outer ring, inner ring) [K].

    Parameters
    ----------
    c : PairConstants
        The pair's data.
    temps : tuple of 4 floats
        Temperatures [K].

    Returns
    -------
    Thermal
        Lengths [m], pressures [Pa], viscosity [m²/s].

    Examples
    --------
    The lubricant's law at −20 °C (within its data):

    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> nu = thermal_floats(PairConstants(pair), (253.15,) * 4).kinematic_viscosity
    >>> nu == float(pair.lubricant.kinematic_viscosity(253.15))
    True
    """
    t_h, t_s, t_o, t_i = temps
    return thermal_at(c, t_h, t_s, t_o, t_i)


# ------------------------------------------------------------------ torque coefficients
@cython.ccall
def torque_coefficients(th: Thermal) -> tuple:
    """Coefficients of one ball's torque terms at the thermal state ``th`` (evaluated once per
    state): (hysteresis 3·α_r/(8·Dw) [1/m] per Q·b·r, Heathcote sliding of the inner and outer
    race [1/m²] per Q·a²·r (0 without differential sliding), spin 3μ/8 [-] per Q·a·E(e)): the
    kernels of :mod:`.friction.terms` at unit load, semi-axes and E(e).

    Parameters
    ----------
    th : Thermal
        Thermal state of the step (Dw [m], groove radii [m]); its pair's coefficients are
        those of the :class:`PairConstants` it was made with (:func:`set_coefficients`).

    Returns
    -------
    tuple
        (hysteresis [1/m], inner sliding [1/m²], outer sliding [1/m²], spin [-]).

    Examples
    --------
    Yu's pair (α_r = 0.007, μ = 0.0817, no differential sliding): by hand
    3 · 0.007 / (8 · 2.381 mm) = 1.1025 /m and 3 · 0.0817 / 8 = 0.0307:

    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> h, sl_i, sl_o, sp = set_coefficients(th, c)
    >>> round(h, 4), sl_i, sl_o, round(sp, 4)  # 1/m, 1/m², 1/m², -
    (1.1025, 0.0, 0.0, 0.0307)
    """
    return th.c_hysteresis, th.c_sliding_inner, th.c_sliding_outer, th.c_spin


@cython.ccall
def set_coefficients(th: Thermal, c: PairConstants) -> tuple:
    """Evaluate :func:`torque_coefficients` of ``th`` for the pair ``c`` (once per state).

    Returns
    -------
    tuple
        (hysteresis [1/m], inner sliding [1/m²], outer sliding [1/m²], spin [-]).

    Examples
    --------
    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> c = PairConstants(BearingPair.from_catalog("ning_space_shaft", "mos2_film"))
    >>> th = thermal_at(c, c.t0, c.t0, c.t0, c.t0)
    >>> set_coefficients(th, c)[1] > 0.0  # solid film: differential sliding on
    True
    """
    if not th.has_coefficients:
        dw: cython.double = th.ball_diameter
        th.c_hysteresis = hysteresis_force(1.0, 1.0, dw, c.hysteresis_loss)
        if c.sliding:
            th.c_sliding_inner = heathcote_force(1.0, 1.0, dw, th.inner_groove_radius, c.mu)
            th.c_sliding_outer = heathcote_force(1.0, 1.0, dw, th.outer_groove_radius, c.mu)
        else:
            th.c_sliding_inner = th.c_sliding_outer = 0.0
        th.c_spin = contact_spin_moment(1.0, 1.0, 1.0, c.mu)
        th.has_coefficients = True
    return th.c_hysteresis, th.c_sliding_inner, th.c_sliding_outer, th.c_spin

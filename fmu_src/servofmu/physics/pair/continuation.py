# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The per-step update of a bearing pair (its continuation), written in Cython's pure-Python
mode.

This file runs as it is (plain Python on floats), and the build compiles it with the other
modules of :mod:`servofmu.physics.compiled` when a C compiler is there (``setup.py``; the
annotations are C types then, and a call of :meth:`PairSolver.update` is one compiled call:
thermal state, predictor, Newton iterations, ring sums, torques and the output record).
:mod:`servofmu.physics.compiled` chooses the implementation at import. The equations are the
kernels' (:mod:`servofmu.physics.kernels`) and the arrangement's rows
(:class:`~.rows.PairRows`), shared with the exact path; the pair's data and thermal state are
:mod:`.constants`, its balls :mod:`.balls`, the output record :mod:`.point`.

**The continuation.** The exact path (:func:`pair_state.thermal_state`,
:func:`pair_state.load_state`) solves every operating point from scratch with bracketing root
finders over numpy arrays: robust, and the reference, but about a millisecond per point. Inside
an FMU the temperature and the loads change a little from one communication step to the next,
so :class:`PairSolver` solves the same equations from the previous step's solution:

- the thermal state (ring growth, Lamé fits, clearance, loop closure, viscosity) is closed
  form: the equations of :func:`fits.mounted_geometry` and :func:`preload.loop_interference`
  on floats, and the lubricant's own law on floats
  (:meth:`viscosity.ViscosityRange.operating_viscosity_at`) (:func:`thermal_floats`);
- the pair's offsets and radial displacements x = (p, z, δr_A, δr_B) [m] (a_A = p + z,
  a_B = p − z) solve the arrangement's rows (:class:`PairRows`) by Newton's method with the
  analytic Jacobian, the contact angle's effect on the Hertz constants included, started from
  a predictor: the previous solution moved by the tangent of the load change (the last
  Jacobian) and by the secant of the last temperature change when the temperatures move on in
  the same direction. The radial rows are eliminated by hand (they involve one bearing each),
  which leaves a 2×2 system in the bearings' axial offsets (:meth:`PairRows.newton_step`). A
  bearing with no ball in contact under a radial load (its radial row is empty) is first moved
  radially until its ball nearest the load's direction touches (:meth:`PairSolver._touch`);
- under pure axial load every ball of a bearing is alike (Yu 2017 eq 4): a bearing is one ball
  of weight Z (one unknown less when the load is zero, none for a rigid loop at zero load);
  under a radial load every ball differs (Jones 1960): the balls of half the ring (the load is
  symmetric about the radial load's direction) with weights 1 or 2, one ball at a time;
- the Hertz constants of each contact need the ellipticity k, the root of the Hertz relation
  F(k) = F(ρ) (:func:`hertz.ellipticity`). Each contact keeps an *anchor*: k0 with the exact
  K(m0), E(m0), F(k0) and its derivatives (scipy.special). k, K and E are taken to second order
  from the anchor, whose error is below C·(Δk/k)³ with C ≈ 2 (measured on the catalogue
  bearings); the anchor is renewed for the next step at the current k when |Δk| exceeds
  :data:`ANCHOR_DRIFT`·k, and the step is solved again when it exceeds :data:`ANCHOR_REDO`·k,
  which keeps every Hertz constant within about 2e-11 of the exact one;
- the Hertz constants depend on the contact angle only through γ = Dw·cos α/dm, on the
  thermal state through γ, the grooves' 1/f = Dw/r and Dw^(∓1/3), and weakly on γ (relative
  first derivatives of 0.1–0.8, second of 0.1–0.2 on the catalogue bearings). Each ball
  keeps a *base*: the Hertz constants with their first and second derivatives in γ and first
  in 1/f at one (γ0, 1/f0) (:func:`contact_terms`); within :data:`GAMMA_SPAN` and
  :data:`INV_F_SPAN` of it they follow to second order in γ and first order in 1/f (relative
  error below 2e-12, tests/physics/test_continuation.py), at any temperature: on a ramp a ball
  evaluates the Hertz relation again every ten to twenty steps, not every step (1/f is
  constant while balls and rings share their temperature and expansion).

Newton stops at the first point whose next correction is below 1e-12 of the curvature distance
A (about 1e-16 m, the absolute tolerance of the exact path's root finders) and below 2e-10 of
the smallest deflection of a loaded ball (a ball load Q ∝ δ^1.5 and its stiffness ∝ δ^0.5 then
move by less than 3e-10 of their value; a ball that barely touches needs the finer step), or
at rounding (1e-15·A): with the analytic Jacobian and the predictor that is about two
evaluations per step on a temperature ramp. A step that does not converge in
:data:`MAX_ITERATIONS`, a singular Jacobian (no ball in contact while the external load is not
zero), or a non-finite value returns None, and the caller starts again from the unloaded pair
(:meth:`PairSolver.start`) and then falls back to the exact path. The outputs equal the exact
path's to a relative 1e-9 (tests check this on random trajectories of temperature and load,
compiled and not).

The continuation state (:meth:`PairSolver.state`) is a JSON-serialisable dict of floats (the
solution and its inputs, the anchors' k, the bases' γ0 and 1/f0, the last Jacobian and
temperature secant of the predictor, the operating point and its output record): a restored
solver continues bit for bit (the same build: the compiled and the Python path round
differently, by about 1e-16 relative).

The thermal state takes the four parts' temperatures (housing, shaft, outer ring, inner ring);
a uniform temperature is four equal ones.
"""

import math

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import hypot
    from cython.cimports.servofmu.physics.kernels._friction import (
        coulomb_and_excess,
        palmgren_torque,
        regularised_torque,
    )
    from cython.cimports.servofmu.physics.pair._balls import (
        Anchor,
        Ball,
        Ring,
        Sums,
        ball_base,
        contact_terms,
        ring_point,
        ring_sums,
    )
    from cython.cimports.servofmu.physics.pair._constants import (
        PairConstants,
        Thermal,
        free_angle,
        thermal_at,
    )
    from cython.cimports.servofmu.physics.pair._point import PointState
    from cython.cimports.servofmu.physics.pair._rows import (
        PairRows,
        Step,
        axial_play,
        pair_flags,
        preload_force,
    )
else:
    from math import hypot

    from .. import compiled
    from ..kernels.friction import coulomb_and_excess, palmgren_torque, regularised_torque
    from .balls import Anchor, Ball, Ring, Sums, ball_base, contact_terms, ring_point, ring_sums
    from .constants import PairConstants, Thermal, free_angle, thermal_at
    from .rows import PairRows, Step, axial_play, pair_flags, preload_force

    # the one class of the process: the compiled record when the compiled modules run
    PointState = compiled.module("pair.point").PointState

from .balls import exact_contact_k

#: Newton iterations of one step before the step starts again from the unloaded pair.
MAX_ITERATIONS = 12
#: Newton iterations of each stage of a cold start (:meth:`PairSolver.start`): from the loop
#: closure's half to a barely loaded contact the convergence is linear (ratio 1/3, Hertz's
#: Q ∝ δ^1.5) until the quadratic phase.
START_ITERATIONS = 60
#: The smallest share of the external load a cold start adds in one stage (it halves a stage
#: whose Newton's method fails, down to this).
START_SMALLEST_STAGE = 1.0 / 256.0
#: Rounds of anchor renewal within one step before the step starts again.
MAX_ANCHOR_ROUNDS = 6

# the same numbers as C values for the compiled path (cython.declare: an annotated module
# global would stay a Python object)
_ROUNDS = cython.declare(cython.int, MAX_ANCHOR_ROUNDS)
_ITERATIONS = cython.declare(cython.int, MAX_ITERATIONS)
_START_ITERATIONS = cython.declare(cython.int, START_ITERATIONS)
#: Newton stops at the first point whose next correction is below this fraction of the
#: curvature distance A (≈ 1e-16 m for the catalogue bearings, the exact path's tolerance) ...
_TOLERANCE = cython.declare(cython.double, 1e-12)
#: ... and below this fraction of the smallest deflection of a loaded ball (a ball load
#: Q ∝ δ^1.5 and its stiffness ∝ δ^0.5 then move by less than 3e-10 of their value), unless it
#: is below rounding (this fraction of A).
_DEFLECTION_TOLERANCE = cython.declare(cython.double, 2e-10)
_ROUNDING = cython.declare(cython.double, 1e-15)
_INF = cython.declare(cython.double, math.inf)

# The speed terms: a C struct compiled, a tuple uncompiled.
Speed = cython.typedef(
    tuple[cython.double, cython.double, cython.double, cython.double, cython.double]
)


# ------------------------------------------------------------------ the speed terms


@cython.cfunc
def _speed(c: PairConstants, pt: PointState, w: cython.double) -> Speed:
    """(signed friction, running, sliding, viscous, grease torque) [N·m] of the state ``pt``
    at speed ``w`` [rad/s] (Yu 2017 eq 8–9 and the regularised sign; another friction model or
    a grease term through ``pair_state._speed_terms``)."""
    if not c.fast:
        return c.python._speed_terms(
            c.pair, pt.kinematic_viscosity, pt.pitch_diameter, pt.coulomb_torque,
            pt.breakaway_excess, pt.sliding_torque, pt.rolling, w,
        )  # fmt: skip
    viscous: cython.double = 2.0 * palmgren_torque(
        pt.kinematic_viscosity, w, pt.pitch_diameter, c.s0
    )
    running: cython.double = pt.coulomb_torque + viscous
    signed: cython.double = regularised_torque(
        w, running, pt.breakaway_excess, c.w_reg, c.w_stribeck
    )
    return signed, running, pt.sliding_torque, viscous, 0.0


def speed_terms(c: PairConstants, point: PointState, w: float) -> tuple:
    """(signed friction, running, sliding, viscous, grease torque) [N·m] of the state
    ``point`` at speed ``w`` [rad/s] (Yu 2017 eq 8–9, or the pair's friction model;
    regularised sign).

    Returns
    -------
    tuple
        Five torques [N·m].

    Examples
    --------
    At rest the regularised sign gives no torque, and the running torque is the Coulomb
    torque plus Palmgren's at rest:

    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> solver = PairSolver(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
    >>> point = solver.update(253.15, 253.15, 253.15, 253.15, 5.0, 0.0)
    >>> signed, running, sliding, viscous, grease = speed_terms(solver.constants, point, 0.0)
    >>> signed, running == point.coulomb_torque + viscous, sliding, grease
    (0.0, True, 0.0, 0.0)
    """
    return _speed(c, point, w)


# ------------------------------------------------------------------ the continuation
@cython.cfunc
def _parallel(
    a0: cython.double,
    a1: cython.double,
    a2: cython.double,
    a3: cython.double,
    b0: cython.double,
    b1: cython.double,
    b2: cython.double,
    b3: cython.double,
) -> cython.double:
    """θ with a ≈ θ·b for the 4-vectors a and b when they are parallel (cosine above
    1 − 1e-6) and point the same way; else 0."""
    dot = a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3
    n0 = b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3
    if dot <= 0.0 or dot * dot < (1.0 - 1e-6) * n0 * (a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3):
        return 0.0
    return dot / n0


_AXIAL = cython.declare(cython.int, 1)
_RADIAL = cython.declare(cython.int, 2)
_MODE_NAMES = {0: None, 1: "axial", 2: "radial"}


@cython.final
@cython.cclass
class PairSolver:
    """Continuation solve of one :class:`~.pair.configuration.BearingPair` (see module docstring),
    and the per-step update of its state (:meth:`update`).

    :meth:`solve` takes the thermal state of a step (:func:`thermal_at`) and the external
    loads, and returns the step's :class:`PointState`, or None when the warm start fails;
    :meth:`start` solves from the unloaded pair; the caller solves exactly when that fails
    too and :meth:`seed` s the solver with that solution (:meth:`accept` makes it the state).

    Parameters
    ----------
    pair : BearingPair
    """

    c: PairConstants
    half_ring: list
    mode: cython.int
    has_x: cython.bint
    x0: cython.double
    x1: cython.double
    x2: cython.double
    x3: cython.double
    rings: list
    u0: cython.double
    u1: cython.double
    u2: cython.double
    u3: cython.double
    u4: cython.double
    u5: cython.double
    has_jac: cython.bint
    jac_a: Ring
    jac_b: Ring
    new_a: Ring
    new_b: Ring
    has_secant: cython.bint
    sx0: cython.double
    sx1: cython.double
    sx2: cython.double
    sx3: cython.double
    st0: cython.double
    st1: cython.double
    st2: cython.double
    st3: cython.double
    th: Thermal
    point: PointState
    p0: cython.double
    p1: cython.double
    p2: cython.double
    p3: cython.double
    p4: cython.double
    p5: cython.double
    n_steps: cython.int
    n_cold: cython.int
    __slots__ = (
        "c",
        "half_ring",
        "has_jac",
        "has_secant",
        "has_x",
        "jac_a",
        "jac_b",
        "mode",
        "n_cold",
        "n_steps",
        "new_a",
        "new_b",
        "p0",
        "p1",
        "p2",
        "p3",
        "p4",
        "p5",
        "point",
        "rings",
        "st0",
        "st1",
        "st2",
        "st3",
        "sx0",
        "sx1",
        "sx2",
        "sx3",
        "th",
        "u0",
        "u1",
        "u2",
        "u3",
        "u4",
        "u5",
        "x0",
        "x1",
        "x2",
        "x3",
    )  # fmt: skip

    def __init__(self, pair):
        self.c = PairConstants(pair)
        z = self.c.n_balls
        self.half_ring = [
            (math.cos(2.0 * math.pi * j / z), 1.0 if j == 0 or 2 * j == z else 2.0)
            for j in range(z // 2 + 1)
        ]
        self.th = None
        self.point = None
        self.n_steps = self.n_cold = 0
        self.reset()

    @property
    def pair(self):
        """The :class:`~.pair.configuration.BearingPair`."""
        return self.c.pair

    @property
    def constants(self):
        """The pair's :class:`PairConstants`."""
        return self.c

    @property
    def steps(self) -> int:
        """Calls of :meth:`update` that solved a new state (the exact path's included)."""
        return self.n_steps

    @property
    def cold_starts(self) -> int:
        """Of those, the ones solved from the unloaded pair (:meth:`start`)."""
        return self.n_cold

    @property
    def x(self):
        """(p, z, δr_A, δr_B) [m] of the last step, or None."""
        return (self.x0, self.x1, self.x2, self.x3) if self.has_x else None

    @property
    def thermal(self):
        """The thermal state of the current operating point (:func:`thermal_at`), or None."""
        return self.th

    @property
    def current(self):
        """The :class:`PointState` of the current operating point, or None."""
        return self.point

    @cython.ccall
    def reset(self):
        """Forget the last solution: the next step starts from the unloaded pair."""
        self.mode = 0  # _AXIAL (all balls alike) or _RADIAL (per ball)
        self.has_x = self.has_jac = self.has_secant = False
        self.x0 = self.x1 = self.x2 = self.x3 = 0.0
        self.rings = None  # the balls of bearings A and B

    def _layout(self, mode):
        """(cos ψ, weight) of the balls of one bearing in ``mode``."""
        return [(0.0, float(self.c.n_balls))] if mode == _AXIAL else self.half_ring

    # ---------------------------------------------------------------- state
    def state(self) -> dict:
        """JSON-serialisable state (floats): the continuation, the operating point and the
        state there. With :meth:`restore`, a solver continues bit for bit.

        Returns
        -------
        dict
        """
        solver = None
        if self.has_x:
            solver = {
                "mode": _MODE_NAMES[self.mode],
                "x": [self.x0, self.x1, self.x2, self.x3],
                "k": [_anchors_of(ring) for ring in self.rings],
                "base": [_bases_of(ring) for ring in self.rings],
                "inputs": [self.u0, self.u1, self.u2, self.u3, self.u4, self.u5],
                "jacobian": [list(self.jac_a), list(self.jac_b)] if self.has_jac else None,
                "secant": [[self.sx0, self.sx1, self.sx2, self.sx3],
                           [self.st0, self.st1, self.st2, self.st3]]
                if self.has_secant else None,
            }  # fmt: skip
        if self.point is None:
            return {"solver": solver, "point": None, "values": None}
        return {
            "solver": solver,
            "point": [self.p0, self.p1, self.p2, self.p3, self.p4, self.p5],
            "values": self.point.as_dict(),
        }

    def restore(self, state) -> None:
        """Inverse of :meth:`state` (the balls' bases are evaluated again from their γ and
        1/f): a restored solver continues bit for bit."""
        state = state or {"solver": None, "point": None, "values": None}
        self.reset()
        self.th = None
        self.point = None
        solver = state["solver"]
        if solver is not None:
            self.mode = _AXIAL if solver["mode"] == "axial" else _RADIAL
            self.x0, self.x1, self.x2, self.x3 = (float(v) for v in solver["x"])
            self.has_x = True
            layout = self._layout(self.mode)
            self.rings = [
                [
                    Ball(cp, w, Anchor(float(ki)), Anchor(float(ko)))
                    for (cp, w), (ki, ko) in zip(layout, ks, strict=True)
                ]
                for ks in solver["k"]
            ]
            for ring, bases in zip(self.rings, solver["base"], strict=True):
                _set_bases(self.c, ring, bases)
            self.u0, self.u1, self.u2, self.u3, self.u4, self.u5 = (
                float(v) for v in solver["inputs"]
            )
            jac, sec = solver.get("jacobian"), solver.get("secant")
            self.has_jac = jac is not None
            if self.has_jac:
                self.jac_a = tuple(float(v) for v in jac[0])
                self.jac_b = tuple(float(v) for v in jac[1])
            self.has_secant = sec is not None
            if self.has_secant:
                self.sx0, self.sx1, self.sx2, self.sx3 = (float(v) for v in sec[0])
                self.st0, self.st1, self.st2, self.st3 = (float(v) for v in sec[1])
        point = state["point"]
        if point is not None:
            self.p0, self.p1, self.p2, self.p3, self.p4, self.p5 = (float(v) for v in point)
            self.th = thermal_at(self.c, self.p0, self.p1, self.p2, self.p3)
            self.point = PointState(**state["values"])

    def seed(self, th: Thermal, inputs: tuple, x: tuple, ball_cosines=None):
        """Start from an exactly solved state: ``x`` = (p, z) (axial) or (p, z, δr_A, δr_B)
        (radial) [m] at the thermal state ``th`` and ``inputs`` (4 temperatures [K], axial and
        radial load [N]), the anchors at the exact ellipticities of the contacts
        (``ball_cosines``: the per-ball (cos α_A, cos α_B) arrays over half the ring under a
        radial load)."""
        self.reset()
        a2 = th.radial_centre_distance
        if len(x) == 2:
            self.mode = _AXIAL
            p, z = x
            cosines = [[a2 / hypot(p + z, a2)], [a2 / hypot(p - z, a2)]]
            x = (p, z, 0.0, 0.0)
        else:
            self.mode = _RADIAL
            cosines = [[float(v) for v in cs] for cs in ball_cosines]
        layout = self._layout(self.mode)
        self.rings = [
            [
                Ball(
                    cp,
                    w,
                    Anchor(exact_contact_k(th, cos_a, True)),
                    Anchor(exact_contact_k(th, cos_a, False)),
                )
                for (cp, w), cos_a in zip(layout, cs, strict=True)
            ]
            for cs in cosines
        ]
        self.x0, self.x1, self.x2, self.x3 = (float(v) for v in x)
        self.has_x = True
        self.u0, self.u1, self.u2, self.u3, self.u4, self.u5 = (float(v) for v in inputs)

    @cython.cfunc
    def _switch(self, mode: cython.int):
        """Carry the anchors over between the axial and the radial form (the radial balls
        start from the axial ball's anchors; the axial ball from the ball at ψ = 0)."""
        layout = self._layout(mode)
        first: Ball
        rings = []
        for ring in self.rings:
            first = ring[0]
            rings.append([Ball(cp, w, first.anc_i.copy(), first.anc_o.copy()) for cp, w in layout])
        self.rings = rings
        if mode == _AXIAL:
            self.x2 = self.x3 = 0.0
        self.mode, self.has_jac, self.has_secant = mode, False, False

    # ---------------------------------------------------------------- per step
    @cython.ccall
    def update(
        self,
        t_h: cython.double,
        t_s: cython.double,
        t_o: cython.double,
        t_i: cython.double,
        axial_load: cython.double,
        radial_load: cython.double,
    ) -> PointState:
        """The state at the parts' temperatures [K] and loads [N]: the last one when nothing
        changed, else solved by continuation (the thermal state kept when the temperatures
        did not change), from the unloaded pair when that fails (a cold start: the first call,
        or a failed warm start); None when that fails too (the caller solves exactly and
        calls :meth:`seed` and :meth:`accept`). ValueError names a temperature outside
        (0, inf) K or a load outside (−inf, inf) N.

        Returns
        -------
        PointState or None

        Examples
        --------
        The first call starts cold, and gives the exact path's preload:

        >>> from servofmu.physics.pair import state as pair_state
        >>> from servofmu.physics.pair.configuration import BearingPair
        >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
        >>> solver = PairSolver(pair)
        >>> point = solver.update(233.15, 233.15, 233.15, 233.15, 5.0, 0.0)
        >>> th = pair_state.thermal_state(pair, 233.15)
        >>> exact = float(pair_state.load_state(pair, th, 5.0).preload)
        >>> abs(point.preload - exact) < 1e-9 * exact, solver.cold_starts  # N
        (True, 1)
        """
        if (
            self.point is not None
            and t_h == self.p0
            and t_s == self.p1
            and t_o == self.p2
            and t_i == self.p3
            and axial_load == self.p4
            and radial_load == self.p5
        ):
            return self.point
        if not (0.0 < t_h < _INF and 0.0 < t_s < _INF and 0.0 < t_o < _INF and 0.0 < t_i < _INF):
            _bad_temperature(t_h, t_s, t_o, t_i)
        if not -_INF < axial_load < _INF:
            raise ValueError(
                f"axial_load = {axial_load!r} N is outside the valid range (-inf, inf)"
            )
        if not -_INF < radial_load < _INF:
            raise ValueError(
                f"radial_load = {radial_load!r} N is outside the valid range (-inf, inf)"
            )
        th: Thermal = self.th
        if th is None or not (
            t_h == th.t_housing and t_s == th.t_shaft and t_o == th.t_outer and t_i == th.t_inner
        ):
            th = thermal_at(self.c, t_h, t_s, t_o, t_i)
        point: PointState = self.solve(th, axial_load, radial_load, _ITERATIONS)
        if point is None:  # no last solution, or the warm start failed: a cold start
            self.n_cold += 1
            point = self.start(th, axial_load, radial_load)
        if point is None:
            self.th = th  # the exact path seeds the solver at it
            return None
        self.accept(th, point, axial_load, radial_load)
        return point

    @cython.ccall
    def accept(self, th: Thermal, point: PointState, axial_load: cython.double,
               radial_load: cython.double):  # fmt: skip
        """Make ``point`` at the thermal state ``th`` and the loads [N] the current state."""
        self.th, self.point = th, point
        self.p0, self.p1, self.p2, self.p3 = th.t_housing, th.t_shaft, th.t_outer, th.t_inner
        self.p4, self.p5 = axial_load, radial_load
        self.n_steps += 1

    @cython.ccall
    def speed_outputs(self, w: cython.double) -> tuple:
        """(friction_torque, running_torque, sliding_torque, viscous_torque, grease_torque
        [N·m], power_loss [W]) at speed ``w`` [rad/s] for the current state (ValueError for a
        speed outside (−inf, inf)).

        Returns
        -------
        tuple
            Five torques [N·m] and the power [W].
        """
        if not -_INF < w < _INF:
            raise ValueError(f"speed = {w!r} rad/s is outside the valid range (-inf, inf)")
        signed: cython.double
        running: cython.double
        sliding: cython.double
        viscous: cython.double
        grease: cython.double
        signed, running, sliding, viscous, grease = _speed(self.c, self.point, w)
        return signed, running, sliding, viscous, grease, signed * w

    # ---------------------------------------------------------------- solve
    @cython.ccall
    def start(self, th: Thermal, axial_load: cython.double, radial_load: cython.double
              ) -> PointState:  # fmt: skip
        """A first solution without the exact path: the pair at zero external load (Newton's
        method on the symmetric offset p of 2p + F(p)/k = C from p = C/2, F one bearing's
        axial force: it converges monotonically, F being odd and convex beyond first
        contact), then the external loads added in stages, each solved by :meth:`solve` (its
        predictor and Newton's method) and halved when that fails. The step's
        :class:`PointState`, or None (the solver reset: the caller solves exactly)."""
        half = 0.5 * th.closure  # a tandem pair: a_A = 0, a_B = d
        self.seed(th, (th.t_housing, th.t_shaft, th.t_outer, th.t_inner, 0.0, 0.0),
                  (half, -half if self.c.tandem else 0.0))  # fmt: skip
        point: PointState = self.solve(th, 0.0, 0.0, _START_ITERATIONS)
        done: cython.double = 0.0
        stage: cython.double = 1.0
        while point is not None and done < 1.0:
            share = min(1.0, done + stage)
            nxt = self.solve(th, share * axial_load, share * radial_load, _START_ITERATIONS)
            if nxt is None:
                stage *= 0.5
                if stage < START_SMALLEST_STAGE:
                    point = None
                continue
            point, done, stage = nxt, share, 2.0 * stage
        if point is None:
            self.reset()
        return point

    @cython.ccall
    def solve(
        self,
        th: Thermal,
        axial_load: cython.double,
        radial_load: cython.double,
        iterations: cython.int = MAX_ITERATIONS,
    ) -> PointState:
        """The pair at the thermal state ``th`` under ``axial_load`` (pressing A) and
        ``radial_load`` [N] from the last solution, in at most ``iterations`` Newton
        iterations per anchor round: the step's :class:`PointState`, or None."""
        if not self.has_x:
            return None
        mode: cython.int = _AXIAL if radial_load == 0.0 else _RADIAL
        if mode != self.mode:
            self._switch(mode)
        p: cython.double
        z: cython.double
        da: cython.double
        db: cython.double
        moved: cython.bint
        p, z, da, db, moved = self._predict(th, axial_load, radial_load)
        ok: cython.bint
        ka: cython.double
        kb: cython.double
        symmetric: cython.bint = axial_load == 0.0 and mode == _AXIAL and not self.c.tandem
        at_last: cython.bint = not moved  # the start is the last solution
        point: PointState
        redo: cython.bint
        for _ in range(_ROUNDS):
            ok, p, z, da, db, ka, kb = self._newton(th, axial_load, radial_load, p, z, da, db,
                                                    iterations)  # fmt: skip
            if not ok and not at_last:  # the predictor overshot: from the last step
                ok, p, z, da, db, ka, kb = self._newton(
                    th, axial_load, radial_load, self.x0, self.x1, self.x2, self.x3, iterations
                )
            if not ok:
                return None
            point, redo = self._point(th, p, z, ka, kb, symmetric, radial_load)
            if not redo:
                self._advance(th, axial_load, radial_load, p, z, da, db)
                return point
            at_last = False  # the next round starts from this round's solution
        return None

    @cython.cfunc
    def _load_step(self, d_ext: cython.double, d_r: cython.double) -> Step:
        """First-order change of x [m] for a change of the loads by ``d_ext``, ``d_r`` [N]
        (the Newton step of the load change alone, from the last Jacobian)."""
        if d_ext == 0.0 and d_r == 0.0:
            return True, 0.0, 0.0, 0.0, 0.0
        half = -0.5 * d_r
        a11, a12, a21, a22 = self.jac_a[2], self.jac_a[3], self.jac_a[4], self.jac_a[5]
        b11, b12, b21, b22 = self.jac_b[2], self.jac_b[3], self.jac_b[4], self.jac_b[5]
        return self.c.rows.newton_step(a11, a12, a21, a22, b11, b12, b21, b22, -d_ext, half,
                                       half, 0.0, self.mode == _RADIAL)  # fmt: skip

    @cython.cfunc
    def _predict(
        self, th: Thermal, axial_load: cython.double, radial_load: cython.double
    ) -> tuple[cython.double, cython.double, cython.double, cython.double, cython.bint]:
        """Start of a step: the last solution moved by the tangent of the load change (the
        last Jacobian) and by the secant of the temperature change (the last step's change of
        x less its load part, when the temperatures move on in the same direction)."""
        p: cython.double = self.x0
        z: cython.double = self.x1
        da: cython.double = self.x2
        db: cython.double = self.x3
        moved: cython.bint = False
        ok: cython.bint
        d0: cython.double
        d1: cython.double
        d2: cython.double
        d3: cython.double
        if self.has_jac and (axial_load != self.u4 or radial_load != self.u5):
            ok, d0, d1, d2, d3 = self._load_step(axial_load - self.u4, radial_load - self.u5)
            if ok:
                p, z, da, db = p + d0, z + d1, da + d2, db + d3
                moved = True
        dt0: cython.double = th.t_housing - self.u0
        dt1: cython.double = th.t_shaft - self.u1
        dt2: cython.double = th.t_outer - self.u2
        dt3: cython.double = th.t_inner - self.u3
        if self.has_secant and (dt0 != 0.0 or dt1 != 0.0 or dt2 != 0.0 or dt3 != 0.0):
            theta = _parallel(dt0, dt1, dt2, dt3, self.st0, self.st1, self.st2, self.st3)
            if theta != 0.0:
                p, z = p + theta * self.sx0, z + theta * self.sx1
                da, db = da + theta * self.sx2, db + theta * self.sx3
                moved = True
        return p, z, da, db, moved

    @cython.cfunc
    def _advance(
        self,
        th: Thermal,
        axial_load: cython.double,
        radial_load: cython.double,
        p: cython.double,
        z: cython.double,
        da: cython.double,
        db: cython.double,
    ):
        """Make x at the inputs (Jacobian in ``new_a``, ``new_b``) the last solution, and keep
        the secant of the temperature change from the solution before."""
        dt0: cython.double = th.t_housing - self.u0
        dt1: cython.double = th.t_shaft - self.u1
        dt2: cython.double = th.t_outer - self.u2
        dt3: cython.double = th.t_inner - self.u3
        self.has_secant = False
        ok: cython.bint
        d0: cython.double
        d1: cython.double
        d2: cython.double
        d3: cython.double
        if dt0 != 0.0 or dt1 != 0.0 or dt2 != 0.0 or dt3 != 0.0:
            self.jac_a, self.jac_b = self.new_a, self.new_b
            ok, d0, d1, d2, d3 = self._load_step(axial_load - self.u4, radial_load - self.u5)
            if ok:
                self.sx0, self.sx1 = p - self.x0 - d0, z - self.x1 - d1
                self.sx2, self.sx3 = da - self.x2 - d2, db - self.x3 - d3
                self.st0, self.st1, self.st2, self.st3 = dt0, dt1, dt2, dt3
                self.has_secant = True
        self.x0, self.x1, self.x2, self.x3 = p, z, da, db
        self.u0, self.u1, self.u2, self.u3 = th.t_housing, th.t_shaft, th.t_outer, th.t_inner
        self.u4, self.u5 = axial_load, radial_load
        self.jac_a, self.jac_b, self.has_jac = self.new_a, self.new_b, True

    @cython.cfunc
    def _newton(
        self,
        th: Thermal,
        f_ext: cython.double,
        f_r: cython.double,
        p: cython.double,
        z: cython.double,
        da: cython.double,
        db: cython.double,
        iterations: cython.int,
    ) -> tuple[
        cython.bint,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
        cython.double,
    ]:
        """Newton's method from (p, z, δr_A, δr_B) [m] in at most ``iterations`` iterations:
        (ok, the solution, the bearings' output stiffnesses [N/m]); their Jacobians there go
        to ``new_a``, ``new_b`` and the balls hold the loads. A pair in a loop without
        external load keeps z = 0 and B mirrors A (the exact path's symmetric solution); a
        rigid loop holds p = C/2, a tandem pair z = −d/2 (:class:`PairRows`)."""
        c: PairConstants = self.c
        rows: PairRows = c.rows
        closure: cython.double = th.closure
        tol: cython.double = _TOLERANCE * th.curvature_distance
        floor: cython.double = _ROUNDING * th.curvature_distance
        radial: cython.bint = f_r != 0.0
        rigid: cython.bint = rows.rigid
        tandem: cython.bint = rows.tandem
        if rigid:
            p = 0.5 * closure
        elif tandem:
            z = -0.5 * closure
        symmetric: cython.bint = not tandem and f_ext == 0.0 and not radial
        if symmetric:
            z = 0.0
        ring_a: list = self.rings[0]
        ring_b: list = self.rings[1]
        half: cython.double = 0.5 * f_r
        ra: Ring
        rb: Ring
        r1: cython.double
        r2: cython.double
        r3: cython.double
        r4: cython.double
        ok: cython.bint
        dp: cython.double
        dz: cython.double
        dda: cython.double
        ddb: cython.double
        step: cython.double
        engage: object
        for _ in range(iterations):
            ra = ring_point(th, c, p + z, da, ring_a)
            rb = ra if symmetric else ring_point(th, c, p - z, db, ring_b)
            if radial and (ra[5] == 0.0 or rb[5] == 0.0):
                # a bearing with no ball in contact has no radial stiffness: move it radially
                # until its ball nearest the load's direction carries about F_r/2, and go on
                if ra[5] == 0.0:
                    engage = self._touch(th, p + z, half, ring_a)
                    if engage is None:
                        return False, p, z, da, db, 0.0, 0.0
                    da = engage
                if rb[5] == 0.0:
                    engage = self._touch(th, p - z, half, ring_b)
                    if engage is None:
                        return False, p, z, da, db, 0.0, 0.0
                    db = engage
                continue
            r1, r2, r3, r4 = rows.residuals(ra[0], rb[0], ra[1], rb[1], p, z, closure, f_ext,
                                            f_r)  # fmt: skip
            if symmetric:
                dp = 0.0 if rigid else -r4 / (2.0 + ra[2] / rows.k_loop)
                dz = dda = ddb = 0.0
            elif not radial and ra[2] == 0.0 and rb[2] == 0.0 and rows.spring == 0.0:
                # no ball of either bearing touches (axial play): move the shaft along the
                # load until its first contact carries about the load, and go on
                if tandem:
                    engage = self._engage_tandem(th, z, r1)
                    if engage is None:
                        return False, p, z, da, db, 0.0, 0.0
                    p = engage
                else:
                    engage = self._engage(th, p, f_ext)
                    if engage is None:
                        return False, p, z, da, db, 0.0, 0.0
                    z = engage
                continue
            else:
                ok, dp, dz, dda, ddb = rows.newton_step(
                    ra[2], ra[3], ra[4], ra[5], rb[2], rb[3], rb[4], rb[5], r1, r2, r3, r4, radial
                )
                if not ok:
                    return False, p, z, da, db, 0.0, 0.0
            step = max(abs(dp), abs(dz), abs(dda), abs(ddb))
            if step <= tol and (step <= _DEFLECTION_TOLERANCE * min(ra[7], rb[7]) or step <= floor):
                self.new_a, self.new_b = ra, rb
                return True, p, z, da, db, ra[6], rb[6]
            if not step < _INF:
                return False, p, z, da, db, 0.0, 0.0
            p, z, da, db = p + dp, z + dz, da + dda, db + ddb
        return False, p, z, da, db, 0.0, 0.0

    def _engage_tandem(self, th: Thermal, z: float, r1: float):
        """Mean offset p [m] at which a tandem pair (a_A = p + z, a_B = p − z) with no ball in
        contact and a constant force carries its residual thrust −``r1`` [N] on its first
        contact along that thrust (:meth:`_engage` for a tandem pair)."""
        h = th.first_contact_offset
        s = 1.0 if r1 < 0.0 else -1.0  # the set moves along the thrust it lacks
        # the offsets at which A and B first touch going that way: a_A = ±h, a_B = ±h
        p_touch = min(s * h - z, s * h + z) if s > 0.0 else max(s * h - z, s * h + z)
        trial = s * 1e-3 * th.curvature_distance
        ring_a, ring_b = self.rings
        got = abs(
            ring_point(th, self.c, p_touch + trial + z, 0.0, ring_a)[0]
            + ring_point(th, self.c, p_touch + trial - z, 0.0, ring_b)[0]
        )
        if not got > 0.0:
            return None
        return p_touch + trial * (abs(r1) / got) ** (2.0 / 3.0)

    def _engage(self, th: Thermal, p: float, f: float):
        """Shaft displacement z [m] at which the pair with mean offset ``p`` [m] and axial play
        carries about the axial load ``f`` [N] on its first contact: the balls of A meet
        their grooves at a_A = p + z = ±h, those of B at a_B = p − z = ±h (h the first-contact
        offset; the sign of the load picks the side), the nearer of them at
        |z| = h − |p|; beyond it the load rises as δ^1.5 (Hertz), so one trial deflection
        scales to the load's. None without play or load."""
        if f == 0.0:
            return None
        gap = th.first_contact_offset - abs(p)
        if not gap >= 0.0:
            return None
        s = 1.0 if f > 0.0 else -1.0
        trial = 1e-3 * th.curvature_distance
        z = s * (gap + trial)
        ring_a, ring_b = self.rings
        got = abs(
            ring_point(th, self.c, p + z, 0.0, ring_a)[0]
            - ring_point(th, self.c, p - z, 0.0, ring_b)[0]
        )
        if not got > 0.0:
            return None
        return s * (gap + trial * (abs(f) / got) ** (2.0 / 3.0))

    def _touch(self, th: Thermal, a: float, f: float, balls: list):
        """Radial displacement [m] of a bearing at axial offset ``a`` [m] at which its ball
        nearest the direction of the radial force ``f`` [N] carries |f| with the other balls
        free (Hertz: δ = (|f|/(K_n·cos α))^(2/3)): a start for Newton's method where no ball
        touches. None when no radial displacement brings that ball into contact."""
        dist, a2_0 = th.curvature_distance, th.radial_centre_distance
        b: Ball = balls[0]
        ball: Ball
        for ball in balls:  # the ball nearest the force's direction (the first of equals)
            if ball.cos_psi * f > b.cos_psi * f:
                b = ball
        cp = b.cos_psi
        if abs(a) >= dist or cp * f <= 0.0:
            return None
        a2 = math.sqrt(dist * dist - a * a)
        cos_a = a2 / dist
        gamma = th.gamma_scale * cos_a
        ci = contact_terms(self.c, gamma, th.inv_f_inner, True, b.anc_i)[0] / th.dw_third
        co = contact_terms(self.c, gamma, th.inv_f_outer, False, b.anc_o)[0] / th.dw_third
        delta = (abs(f) * (ci + co) ** 1.5 / cos_a) ** (2.0 / 3.0)
        s = dist + delta
        return (math.sqrt(s * s - a * a) - a2_0) / cp

    def _rest_displacement(self, th: Thermal, a_a: float):
        """A tandem pair's axial displacement [m]: a_A less its offset at zero external load
        at the thermal state ``th`` (:func:`pair_state._displacement`), that offset solved once
        per thermal state by :meth:`_newton` on one axial ball per bearing (their anchors A's
        and B's first ball's), from a_A."""
        if not th.has_rest_offset:
            rings = self.rings
            new_a, new_b = self.new_a, self.new_b
            first_a: Ball = rings[0][0]
            first_b: Ball = rings[1][0]
            self.rings = [
                [Ball(0.0, float(self.c.n_balls), first_a.anc_i.copy(), first_a.anc_o.copy())],
                [Ball(0.0, float(self.c.n_balls), first_b.anc_i.copy(), first_b.anc_o.copy())],
            ]
            z = -0.5 * th.closure
            sol = self._newton(th, 0.0, 0.0, a_a - z, z, 0.0, 0.0, START_ITERATIONS)
            self.rings = rings
            self.new_a, self.new_b = new_a, new_b
            th.rest_offset = sol[1] + z if sol[0] else math.nan
            th.has_rest_offset = True
        return a_a - th.rest_offset

    @cython.cfunc
    def _point(
        self,
        th: Thermal,
        p: cython.double,
        z: cython.double,
        ka: cython.double,
        kb: cython.double,
        symmetric: cython.bint,
        radial_load: cython.double,
    ) -> tuple[PointState, cython.bint]:
        """The step's :class:`PointState` from the balls' last evaluation (:func:`ring_sums`):
        torques [N·m], forces [N], the pair's stiffness [N/m], the load-weighted contact angle
        of A [rad], the largest pressure [Pa], flags; and whether an anchor moved so far that
        the step must be solved again. B mirrors A when ``symmetric`` (its anchors follow A's).
        The friction model's data (:func:`~.pair.state.rolling_data`): the bearings' loads
        (``radial_load`` [N] the external one) or the contacts' terms, as its registry entry
        asks (:attr:`~.friction.registry.Entry.data`)."""
        c: PairConstants = self.c
        ring_a: list = self.rings[0]
        ring_b: list = self.rings[1]
        ehl = [[], [], [], [], []] if c.needs_contacts else None
        sa: Sums = ring_sums(th, c, ring_a, ehl)
        sb: Sums
        a: Ball
        b: Ball
        if symmetric:
            sb = sa
            for a, b in zip(ring_a, ring_b, strict=True):
                if b.anc_i.k != a.anc_i.k or b.anc_o.k != a.anc_o.k:
                    b.anc_i, b.anc_o, b.base = a.anc_i.copy(), a.anc_o.copy(), None
            if ehl is not None:  # B's contacts are A's
                ehl = [v + v for v in ehl]
        else:
            sb = ring_sums(th, c, ring_b, ehl)
        fa: cython.double = sa[8]
        fb: cython.double = sb[8]
        rolling = None
        if c.needs_contacts:
            rolling = tuple(tuple(v) for v in ehl)
        elif c.needs_loads:
            rolling = c.model.rolling_loads(fa, fb, radial_load)
        p_max: cython.double = max(sa[5], sb[5])
        overloaded: cython.bint
        locked: cython.bint
        unloaded: cython.bint
        reverse: cython.bint
        overloaded, locked, unloaded, reverse = pair_flags(
            c.pressure_limit, th.clearance, p_max, fa, fb
        )
        a_a: cython.double = p + z
        a_b: cython.double = p - z
        if not th.has_rest:
            th.rest_torque = 2.0 * palmgren_torque(th.kinematic_viscosity, 0.0, th.pitch_diameter,
                                             c.rest_s0)  # fmt: skip
            th.has_rest = True
        hyst: cython.double = sa[0] + sb[0]
        spin: cython.double = sa[1] + sb[1]
        slide: cython.double = sa[2] + sb[2]
        inner: cython.double = sa[3] + sb[3]
        outer: cython.double = sa[4] + sb[4]
        coulomb: cython.double
        excess: cython.double
        breakaway: cython.double
        if c.fast:  # the default: the per-step hot path
            coulomb, excess = coulomb_and_excess(c.static_ratio, hyst, spin, slide)
            breakaway = coulomb + excess + th.rest_torque
        else:
            hyst, spin, slide, inner, outer = c.python.contact_terms(c.pair, hyst, spin, slide,
                                                                     inner, outer)  # fmt: skip
            coulomb, excess, breakaway = c.python.state_torques(
                c.pair, hyst, spin, slide, th.kinematic_viscosity, th.pitch_diameter, rolling,
                th.rest_torque,
            )  # fmt: skip
        displacement: cython.double = self._rest_displacement(th, a_a) if c.tandem else z
        pt: PointState = PointState.__new__(PointState)
        pt.hysteresis_torque, pt.spin_torque, pt.sliding_torque = hyst, spin, slide
        pt.inner_ring_torque, pt.outer_ring_torque = inner, outer
        pt.coulomb_torque, pt.breakaway_excess, pt.breakaway_torque = coulomb, excess, breakaway
        pt.preload = preload_force(fa, fb)
        pt.contact_angle = sa[7] / sa[6] if sa[6] > 0.0 else free_angle(th)
        pt.radial_clearance = th.clearance
        pt.kinematic_viscosity, pt.pitch_diameter = th.kinematic_viscosity, th.pitch_diameter
        pt.axial_stiffness = c.rows.axial_stiffness(ka, kb)
        pt.max_contact_pressure = p_max
        pt.outer_fit_pressure, pt.inner_fit_pressure = th.outer_fit_pressure, th.inner_fit_pressure
        pt.outer_interference, pt.inner_interference = th.outer_interference, th.inner_interference
        pt.force_a, pt.force_b, pt.axial_displacement = fa, fb, displacement
        pt.overloaded, pt.locked, pt.unloaded, pt.reverse_loaded = (
            overloaded,
            locked,
            unloaded,
            reverse,
        )
        pt.outside_lubricant_range = th.outside_lubricant_range
        pt.axial_play = axial_play(th.first_contact_offset, a_a, a_b, fa, fb)
        pt.rolling = rolling
        return pt, sa[9] or sb[9]


def _anchors_of(ring: list) -> list:
    """[[k_inner, k_outer] of each ball's anchors]."""
    out = []
    b: Ball
    for b in ring:
        out.append([b.anc_i.k, b.anc_o.k])
    return out


def _bases_of(ring: list) -> list:
    """[(γ0, 1/f_i0, 1/f_o0) of each ball's base, or None]."""
    out = []
    b: Ball
    for b in ring:
        out.append(None if b.base is None else list(b.base[:3]))
    return out


def _set_bases(c: PairConstants, ring: list, bases: list):
    """The balls' bases evaluated again at their (γ0, 1/f_i0, 1/f_o0) (None: no base)."""
    b: Ball
    for b, at in zip(ring, bases, strict=True):
        if at is not None:
            b.base = ball_base(c, float(at[0]), float(at[1]), float(at[2]), b)


def _bad_temperature(t_h, t_s, t_o, t_i):
    """Raise the ValueError naming the first temperature outside (0, inf) K (``temperature``
    when all four are equal)."""
    temps = (t_h, t_s, t_o, t_i)
    for name, t in zip(("housing", "shaft", "outer_ring", "inner_ring"), temps, strict=True):
        if not (0.0 < t < math.inf):
            label = "temperature" if temps.count(t) == 4 else f"{name}_temperature"
            raise ValueError(f"{label} = {t!r} K is outside the valid range (0, inf) K")

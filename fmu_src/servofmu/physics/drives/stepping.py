# cython: language_level=3, auto_pickle=False, embedsignature=False
r"""The equations of the actuator's crank-slider and its series stiffness (Liu Yuan et al.
2014, "A stiffness calculation method of servo mechanism", eq 1–20; :mod:`.actuator` states
them in full), written in Cython's pure-Python mode: :class:`Linkage` on floats or arrays
(the exact vectorised path of :mod:`.actuator` passes numpy arrays), and :class:`ActuatorStepper`,
the ActuatorStiffness FMU's per-step update in one call. The build compiles this module
(:mod:`servofmu.physics.compiled`); compiled, every function takes C doubles.

Both implementations give the same bits on floats: the same operations in the same order,
the elementary functions from C's ``libm`` (as :mod:`math` calls them; ``hypot`` through
numpy, which calls C's), and the constants that Python's ``**`` makes computed by Python when
the objects are built. On arrays numpy's functions run, whose arccos and arctan2 may round
differently in the last place.

Examples
--------
>>> import math
>>> crank = Linkage(0.05, 0.1, 0.0, 2e11, 1e-4, 1e-4, 0.05, 8e10, 1e-8, 1e-8)
>>> theta = math.pi / 2  # crank upright, Y1 = 0: sin γ = L1/L2 = 0.5, dx/dθ = −L1
>>> gamma = math.asin(crank.sin_rod_angle(theta))
>>> round(crank.nut_position(theta, gamma) * 1e3, 6), round(crank.lever(theta, gamma) * 1e3, 6)
(86.60254, -50.0)
"""

import math

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import INFINITY, copysign, fabs, isfinite
    from cython.cimports.servofmu.physics._shared_step import SharedStep
    from cython.cimports.servofmu.physics.kernels._elementary import (
        arccos,
        arcsin,
        arctan,
        arctan2,
        cos,
        hypot,
        maximum,
        sign,
        sin,
        sqrt,
        tan,
    )
else:
    from math import copysign, isfinite
    from math import inf as INFINITY

    from ..kernels.elementary import (
        arccos,
        arcsin,
        arctan,
        arctan2,
        cos,
        hypot,
        maximum,
        sign,
        sin,
        sqrt,
        tan,
    )
    from ..shared_step import SharedStep

    fabs = abs  # floats or arrays

#: Smallest hinge moment [N·m] whose linkage rotation eq 14–16 resolve: below it the closure
#: of the two circles loses its digits (at 1e-12 N·m K_rod came out 14× too small, found by the
#: FMU fuzzing), and the secant at this moment is used; K_rod is linear in M to 1e-5.
SMALLEST_MOMENT = 1.0e-3
#: Screw force [N] below which the support pair's secant F3/Δz is replaced by its tangent
#: stiffness (the limit): Δz is solved to 1e-16 m, so a few-pN force has no digits left, and
#: 5e-324 N·m of hinge moment divided by zero (found by the FMU fuzzing). At 1 N the secant
#: and the tangent of a 200 N-preloaded pair agree to 1e-3.
SMALLEST_SCREW_FORCE = 1.0
# the same numbers as C doubles for the compiled path (module globals are Python objects)
_SMALLEST_MOMENT: cython.double = SMALLEST_MOMENT
_SMALLEST_SCREW_FORCE: cython.double = SMALLEST_SCREW_FORCE
_INF: cython.double = math.inf


def reach_error(delta: float, crank_length: float, rod_length: float) -> ValueError:
    """The error of an output angle δ [rad] where the linkage of crank L1 and rod L2 [m]
    cannot close (Liu 2014 eq 9: |sin γ| ≥ 1).

    Returns
    -------
    ValueError
        Naming the angle, the reason and the two lengths.

    Examples
    --------
    >>> str(reach_error(1.5, 0.05, 0.03)).split(":")[0]
    "output_angle = 1.5 rad is outside the linkage's reach"
    """
    return ValueError(
        f"output_angle = {delta!r} rad is outside the linkage's reach: sin γ = "
        f"(L1·sin θ − Y1)/L2 reaches ±1 (crank {crank_length!r} m, rod "
        f"{rod_length!r} m)"
    )


def dead_centre_error(delta: float) -> ValueError:
    """The error of an output angle δ [rad] at a dead centre (dx/dθ = 0, Liu 2014 eq 2–3).

    Returns
    -------
    ValueError
        Naming the angle and the reason.

    Examples
    --------
    >>> str(dead_centre_error(-1.2)).split(" (")[0]
    'output_angle = -1.2 rad puts the linkage at a dead centre'
    """
    return ValueError(
        f"output_angle = {delta!r} rad puts the linkage at a dead centre (crank and rod in "
        "line): no moment can be carried"
    )


def motor_reach_error(motor_angle: float, reach: str) -> ValueError:
    """The error of a motor angle φ [rad] beyond the dead centres, with the valid ``reach``.

    Returns
    -------
    ValueError
        Naming the motor angle, the reason and the valid range.

    Examples
    --------
    >>> str(motor_reach_error(300.0, "(-1, 1) rad")).split(":")[0]
    "motor_angle = 300.0 rad is outside the linkage's reach"
    """
    return ValueError(
        f"motor_angle = {motor_angle!r} rad is outside the linkage's reach: the crank-slider "
        f"would pass a dead centre (crank and rod in line); valid {reach}"
    )


@cython.final
@cython.cclass
class Linkage:
    """The crank-slider of Liu 2014 (Fig 5; eq 2–3, 9–19) at crank angles θ [rad], floats or
    arrays (compiled: C doubles).

    Parameters
    ----------
    crank_length, rod_length : L1, L2 [m]
    slide_offset : Y1, height of the slide above the output shaft [m]
    youngs_modulus : E of the crank and rod [Pa]
    crank_area, rod_area : A1, A2 [m²] (eq 12–13)
    arm_length : l, output arm [m] (eq 17–19)
    shear_modulus : G of the output shaft [Pa]
    shaft_polar_moment : I1 [m⁴] (eq 17)
    arm_second_moment : I [m⁴] (eq 18–19)
    """

    def __init__(
        self,
        crank_length,
        rod_length,
        slide_offset,
        youngs_modulus,
        crank_area,
        rod_area,
        arm_length,
        shear_modulus,
        shaft_polar_moment,
        arm_second_moment,
    ):
        self.l1 = crank_length
        self.l2 = rod_length
        self.y1 = slide_offset
        self.e = youngs_modulus
        self.crank_area = crank_area
        self.rod_area = rod_area
        self.arm_length = arm_length
        self.torsional = shear_modulus * shaft_polar_moment  # G·I1 [N·m²]
        self.arm_squared = arm_length**2  # [m²]
        self.l1_squared = crank_length**2  # [m²]
        self.l2_squared = rod_length**2  # [m²]
        self.bending = 3.0 * youngs_modulus * arm_second_moment * crank_length  # 3·E·I·L1

    @cython.ccall
    def sin_rod_angle(self, theta: cython.double) -> cython.double:
        """sin γ = (L1·sin θ − Y1)/L2 (Liu 2014 eq 9, corrected) [-] at crank angle θ [rad]."""
        return (self.l1 * sin(theta) - self.y1) / self.l2

    @cython.ccall
    def nut_position(self, theta: cython.double, gamma: cython.double) -> cython.double:
        """x_A = L1·cos θ + L2·cos γ [m] (Liu 2014 eq 2–3, exact) at crank angle θ and rod
        angle γ [rad]."""
        return self.l1 * cos(theta) + self.l2 * cos(gamma)

    @cython.ccall
    def lever(self, theta: cython.double, gamma: cython.double) -> cython.double:
        """dx_A/dθ = −L1·(sin θ + cos θ·tan γ) [m/rad] at crank angle θ and rod angle γ [rad]:
        the lever that reflects the screw line's axial stiffness to the output."""
        return -self.l1 * (sin(theta) + cos(theta) * tan(gamma))

    @cython.ccall
    def transmission_angle(self, theta: cython.double, gamma: cython.double) -> cython.double:
        """β [rad], between B→C = −(cos θ, sin θ) and B→A = (cos γ, −sin γ) at the crank pin B,
        at crank angle θ and rod angle γ [rad] (Liu 2014 eq 10)."""
        return arccos(sin(theta) * sin(gamma) - cos(theta) * cos(gamma))

    @cython.ccall
    def reach_cosine(self, x_nut: cython.double) -> cython.double:
        """cos(θ − ψ) = (L1² + R² − L2²)/(2·L1·R) [-] with the nut at x_A [m], R = |CA| and
        ψ = atan2(Y1, x_A): the crank pin on both circles |CB| = L1 and |AB| = L2 (the
        inverse of eq 2–3); |cos| < 1 between the dead centres."""
        r = hypot(x_nut, self.y1)
        return (self.l1_squared + r * r - self.l2_squared) / (2.0 * self.l1 * r)

    @cython.ccall
    def crank_angle(self, x_nut: cython.double, branch: cython.double) -> cython.double:
        """θ = ψ ± arccos(:meth:`reach_cosine`) [rad] with the nut at x_A [m], on the branch
        ``branch`` (±1: the side of the line CA the crank pin lies on)."""
        return arctan2(self.y1, x_nut) + branch * arccos(self.reach_cosine(x_nut))

    @cython.ccall
    def rod_cosine(self, x_nut: cython.double, theta: cython.double) -> cython.double:
        """cos γ = (x_A − L1·cos θ)/L2 [-] with the nut at x_A [m] and crank angle θ [rad]
        (> 0: the rod runs from the crank pin towards +x)."""
        return (x_nut - self.l1 * cos(theta)) / self.l2

    @cython.ccall
    def rotation(
        self,
        theta: cython.double,
        beta: cython.double,
        x_nut: cython.double,
        m: cython.double,
    ) -> cython.double:
        """Elastic rotation Δθ [rad] of the output shaft under hinge moment M [N·m] with the nut
        held (Liu 2014 eq 10–19, eq 18–19 with the second moment of area I), at crank angle θ,
        transmission angle β [rad] and nut position x_A [m]."""
        l1 = self.l1
        l2 = self.l2
        e = self.e
        sin_b = sin(beta)
        cos_b = cos(beta)
        f2 = m / (l1 * sin_b)  # eq 10: rod force (compression for M > 0)
        # eq 12–13: crank carries F2·cos β along its length, the rod F2 (compression shortens)
        l1_new = l1 + f2 * cos_b * l1 / (e * self.crank_area)
        l2_new = l2 - f2 * l2 / (e * self.rod_area)
        # eq 14–16: close the mechanism again with the nut A fixed: B' is the intersection of
        # the circles |CB'| = L1', |AB'| = L2' on the side of the undeformed B
        ax = x_nut
        ay = self.y1
        d2 = ax * ax + ay * ay
        d = sqrt(d2)
        along = (l1_new * l1_new - l2_new * l2_new + d2) / (2.0 * d)
        across = sqrt(maximum(l1_new * l1_new - along * along, 0.0))
        ux = ax / d
        uy = ay / d
        bx0 = l1 * cos(theta)
        by0 = l1 * sin(theta)
        side = sign(ux * by0 - uy * bx0)  # which of the two intersections is B
        bx = along * ux - side * across * uy
        by = along * uy + side * across * ux
        d_theta = arctan2(by, bx) - theta
        d_theta1 = arctan2(sin(d_theta), cos(d_theta))  # wrapped to (−π, π]
        torsion = m * self.arm_length / self.torsional  # eq 17
        bending = arctan(m * self.arm_squared / self.bending)  # eq 18–19, with I
        return fabs(d_theta1) * sign(m) + torsion + bending


@cython.final
@cython.cclass
class ActuatorStepper:
    """The ActuatorStiffness FMU's per-step update in one call: the exact kinematics, the
    linkage's secant stiffness, the screw line's elements reflected to the output and their
    series sum (Liu 2014 eq 1–20), on floats, with the support-bearing pair by continuation.

    Parameters
    ----------
    linkage : Linkage
    neutral_crank_angle : θ0 [rad]
    gear_ratio : i_g [-]
    screw_lead : p [m/rev]
    gear_stiffness : K_gear, torsional at the screw shaft [N·m/rad]
    screw_stiffness, housing_stiffness : k_screw, k_body, axial [N/m]
    seat_stiffness : in series with the support bearings [N/m] (inf: rigid)
    support : ``support(temperature, screw_force)`` → the support pair's state
        (:meth:`~servofmu.physics.pair.model.BearingModel.update`, its ``axial_displacement``
        [m] and ``axial_stiffness`` [N/m]), or None: a rigid support
    neutral_nut_position : x_A(θ0) [m] (the motor side, :meth:`output_angle`)
    motor_per_metre : signed motor angle per nut travel ±i_g·2π/p [rad/m]
    branch : ±1, the side of the line from the output shaft to the nut the crank pin lies on
    motor_reach : the valid motor angles, as text for the error

    Examples
    --------
    >>> crank = Linkage(0.05, 0.1, 0.0, 2e11, 1e-4, 1e-4, 0.05, 8e10, 1e-8, 1e-8)
    >>> s = ActuatorStepper(crank, 1.5707963267948966, 3.0, 5e-3, 1e3, 1e8, 1e9, 1e9, None)
    >>> out = s.evaluate(0.0, 100.0, 293.15)  # δ [rad], M [N·m], T [K]
    >>> out[5] == 1.0 / sum(1.0 / k for k in out[:5])  # N·m/rad: total, the series sum (eq 6)
    True
    """

    def __init__(
        self,
        linkage: Linkage,
        neutral_crank_angle,
        gear_ratio,
        screw_lead,
        gear_stiffness,
        screw_stiffness,
        housing_stiffness,
        seat_stiffness,
        support,
        neutral_nut_position=0.0,
        motor_per_metre=1.0,
        branch=1.0,
        motor_reach="",
    ):
        self.linkage = linkage
        self.theta0 = neutral_crank_angle
        self.gear_ratio = gear_ratio
        self.gear_factor = (2.0 * math.pi / screw_lead) ** 2  # (2π/p)² [1/m²]
        self.screw_ratio = 2.0 * math.pi * linkage.l1 / screw_lead  # i_s (eq 1)
        self.gear_stiffness = gear_stiffness
        self.screw_stiffness = screw_stiffness
        self.housing_stiffness = housing_stiffness
        self.seat_stiffness = seat_stiffness
        self.support = support
        self.x0 = neutral_nut_position
        self.motor_per_metre = motor_per_metre
        self.branch = branch
        self.motor_reach = motor_reach

    @cython.ccall
    def output_angle(self, motor_angle: cython.double) -> cython.double:
        """The output angle δ [rad] of the rigid mechanism at motor angle φ [rad] from the
        neutral position (the closed-form inverse of the motor side: nut at
        x_A = x_A(θ0) + φ/(±i_g·2π/p), Liu 2014 eq 1, 4; crank angle on the circles about C
        and A). ValueError naming φ beyond the dead centres (``motor_reach``).

        Returns
        -------
        float
            δ [rad], wrapped to (−π, π].
        """
        k: Linkage = self.linkage
        x: cython.double = self.x0 + motor_angle / self.motor_per_metre
        c: cython.double = k.reach_cosine(x)
        theta: cython.double = k.crank_angle(x, self.branch)
        if not (fabs(c) < 1.0 and k.rod_cosine(x, theta) > 0.0):
            raise motor_reach_error(motor_angle, self.motor_reach)
        d: cython.double = theta - self.theta0
        return arctan2(sin(d), cos(d))

    @cython.ccall
    def evaluate(self, delta: cython.double, m: cython.double, temperature) -> tuple:
        """The stiffness at output angle δ [rad] under hinge moment M [N·m] (both finite), the
        support pair at ``temperature`` [K] (uniform, or a (housing, shaft, outer ring, inner
        ring) tuple in the pair's range). ValueError where the linkage cannot close or stands
        at a dead centre, or an element holds nothing.

        Returns
        -------
        tuple of float
            (gear, screw, linkage, housing, support bearing, total [N·m/rad], deflection
            [rad], reduction ratio i [-], screw force F3 [N]): the fields of
            :class:`~.actuator.StiffnessBreakdown` in order.
        """
        k: Linkage = self.linkage
        l1: cython.double = k.l1
        theta: cython.double = self.theta0 + delta
        s: cython.double = k.sin_rod_angle(theta)
        if not fabs(s) < 1.0:
            raise reach_error(delta, l1, k.l2)
        gamma: cython.double = arcsin(s)
        beta: cython.double = k.transmission_angle(theta, gamma)
        x: cython.double = k.nut_position(theta, gamma)
        lever: cython.double = k.lever(theta, gamma)
        if fabs(lever) < 1e-6 * l1:
            raise dead_centre_error(delta)
        lever2: cython.double = lever * lever
        gear: cython.double = self.gear_factor * lever2 * self.gear_stiffness
        screw: cython.double = lever2 * self.screw_stiffness
        housing: cython.double = lever2 * self.housing_stiffness
        probe: cython.double = m
        if not fabs(m) >= _SMALLEST_MOMENT:
            probe = copysign(_SMALLEST_MOMENT, m)
        linkage: cython.double = probe / k.rotation(theta, beta, x, probe)
        f3: cython.double = fabs(m) / fabs(lever)
        support: cython.double = lever2 * self._support(f3, temperature)
        total: cython.double = 1.0 / (
            _compliance(gear, 0)
            + _compliance(screw, 1)
            + _compliance(linkage, 2)
            + _compliance(housing, 3)
            + _compliance(support, 4)
        )
        ratio: cython.double = self.gear_ratio * self.screw_ratio * (fabs(lever) / l1)
        return (gear, screw, linkage, housing, support, total, m / total, ratio, f3)

    @cython.cfunc
    def _support(self, f3: cython.double, temperature) -> cython.double:
        """The support pair's secant axial stiffness F3/Δz (its tangent below
        :data:`SMALLEST_SCREW_FORCE`) in series with the seat [N/m]; inf when rigid."""
        if self.support is None:
            return _INF
        out = self.support(temperature, f3)
        dz: cython.double = out.axial_displacement
        bearing: cython.double
        if f3 >= _SMALLEST_SCREW_FORCE and dz > 0:
            bearing = f3 / dz
        else:
            bearing = out.axial_stiffness
        if not bearing > 0.0:  # an unloaded pair with axial play holds nothing at this force
            raise ValueError(
                f"support_bearing_stiffness = {bearing!r} N/m: the support pair has axial play "
                f"at screw_force = {f3!r} N (preload lost); the actuator has no stiffness there"
            )
        return 1.0 / (_compliance(bearing, 0) + _compliance(self.seat_stiffness, 1))


@cython.cfunc
def _compliance(k: cython.double, i: cython.int) -> cython.double:
    """1/K of the series element ``i`` of stiffness K (Liu 2014 eq 6: 1/K = Σ 1/K_i, summed
    left to right) [1/unit of K]; ValueError naming the element unless K > 0 (inf: a rigid
    element adds 0)."""
    if not k > 0.0:
        raise ValueError(f"stiffness[{i}] = {k!r} must be > 0")
    return 1.0 / k


@cython.final
@cython.cclass
class ActuatorSharedStep(SharedStep):
    """The ActuatorStiffness FMU's step on the values it shares with servofmu's export
    (:class:`~servofmu.physics.shared_step.SharedStep`): when the inputs changed, the output
    angle (the angle input, or the motor angle through :meth:`ActuatorStepper.output_angle`),
    :meth:`ActuatorStepper.evaluate` and the outputs from it, as the slave computes them, read
    from and written to the block. An output that is not finite is declined (the slave's
    message); an exception (a linkage that cannot close) is the slave's failure mid-step."""

    def bind(
        self,
        stepper: ActuatorStepper,
        motor_side: cython.bint,
        inputs: tuple,
        temperatures: tuple,
        breakdown: tuple,
        infinite: tuple,
        ratio: cython.Py_ssize_t,
        outputs: tuple,
    ):
        """The slave's ``stepper``; whether the position is the motor's (``motor_side``); the
        slots of the inputs (angle, motor angle, speed, motor speed, load torque; -1: none)
        and of the ``temperatures`` (as :meth:`~.SharedStep.temperatures` reads them); the
        slots of evaluate's values in its order (``breakdown``), whether each may be +inf
        (``infinite``: the output allows it), the position of the reduction ratio among them,
        and the slots of the motor load torque, output angle and output speed."""
        self.stepper = stepper
        self.motor_side = motor_side
        self.inputs = inputs
        self.temperature_slots = temperatures
        self.breakdown = breakdown
        self.infinite = infinite
        self.ratio_index = ratio
        self.outputs = outputs

    @cython.cfunc
    def advance(self, t: cython.double, h: cython.double) -> cython.bint:
        if not self.inputs_changed():
            return True
        values = self.values
        k: cython.Py_ssize_t
        slot: cython.Py_ssize_t = self.inputs[1 if self.motor_side else 0]
        angle: cython.double = values[slot]
        if self.motor_side:
            angle = self.stepper.output_angle(angle)
        slot = self.inputs[4]
        m: cython.double = values[slot]
        result: tuple = self.stepper.evaluate(angle, m, self.temperatures(self.temperature_slots))
        ratio: cython.double = result[self.ratio_index]
        if ratio == 0.0:  # the slave's division fails, with Python's message
            return False
        slot = self.inputs[3 if self.motor_side else 2]
        speed: cython.double = values[slot]
        last: tuple = (m / ratio, angle, speed / ratio if self.motor_side else speed)
        x: cython.double
        for k in range(len(result)):
            x = result[k]
            if not (isfinite(x) or (x == INFINITY and self.infinite[k])):
                return False
        for k in range(3):
            if not isfinite(last[k]):
                return False
        for k in range(len(result)):
            slot = self.breakdown[k]
            values[slot] = result[k]
        for k in range(3):
            slot = self.outputs[k]
            values[slot] = last[k]
        return True

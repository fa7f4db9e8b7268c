"""The DC motor (physics.drives.motor and the DCMotor FMU) against the ODE as written, integrated by
scipy.integrate.solve_ivp, never against the module's own matrices:

    L·di/dt = V − R·i − k_e·ω,   J·dω/dt = k_t·i − b·ω − T,   dφ/dt = ω.
"""

import math
import re

import numpy as np
import pytest
from fmu_helpers import Fmu
from kernels import implementations
from scipy.integrate import solve_ivp

from servofmu.physics import compiled
from servofmu.physics.drives import motor

#: Not the defaults, and k_t ≠ k_e, so that a swapped or scaled constant shows.
P = motor.DCMotorParameters(
    resistance=1.5,
    inductance=2.0e-3,
    torque_constant=0.06,
    back_emf_constant=0.04,
    inertia=3.0e-4,
    viscous_damping=2.0e-5,
)


def ode(p, voltage, torque):
    """Right-hand side of the motor's equations, written out (x = i, ω, φ)."""

    def rhs(t, x):
        i, w, _ = x
        return [
            (voltage - p.resistance * i - p.back_emf_constant * w) / p.inductance,
            (p.torque_constant * i - p.viscous_damping * w - torque) / p.inertia,
            w,
        ]

    return rhs


def reference(p, x0, voltage, torque, t_end):
    sol = solve_ivp(
        ode(p, voltage, torque), (0.0, t_end), x0, method="Radau", rtol=1e-12, atol=1e-14
    )
    return sol.y[:, -1]


@pytest.mark.parametrize("h", [1e-4, 1e-3, 1e-2])
def test_step_follows_the_written_ode(h):
    # 0.1 s from a moving start: the back-EMF, the inductance and the damping all matter
    x0, voltage, torque, t_end = (0.5, 20.0, 1.0), 6.0, 2e-3, 0.1
    x = x0
    for _ in range(round(t_end / h)):
        x = motor.step(P, x, voltage, torque, h)
    np.testing.assert_allclose(x, reference(P, x0, voltage, torque, t_end), rtol=1e-8, atol=1e-11)


def test_sliding_friction_is_a_constant_opposing_torque():
    # the rotor turns forward throughout, so the Coulomb friction is the running torque held
    # against it: the ODE with T + T_f
    x0, voltage, torque, t_run, t_end = (1.0, 40.0, 0.0), 3.0, 1e-3, 4e-3, 0.05
    x, mean = x0, []
    for _ in range(50):
        x, f = motor.step_with_friction(P, x, voltage, torque, 1e-3, t_run, 2 * t_run, 1e-4)
        mean.append(f)
    assert x[1] > 0
    np.testing.assert_allclose(
        x, reference(P, x0, voltage, torque + t_run, t_end), rtol=1e-8, atol=1e-11
    )
    assert mean == pytest.approx([t_run] * 50, rel=1e-12)


def test_stuck_rotor_current_is_the_rl_circuit():
    # k_t·i stays below the breakaway torque: ω = 0, φ fixed, and the armature is an R–L
    # circuit, i(t) = V/R·(1 − e^(−R·t/L)) (by hand: 0.5 V / 1.5 Ω = 0.333 A, τ = 1.33 ms)
    # (the friction is held constant over each 0.1 ms sub-step so that the speed ends at 0:
    # while the current still rises, the rotor moves a few 1e-8 rad within the sub-steps and
    # its back-EMF shifts the current by about 2e-6 of itself)
    x, v = (0.0, 0.0, 0.25), 0.5
    for n in range(1, 11):
        x, friction = motor.step_with_friction(P, x, v, 0.0, 1e-3, 0.02, 0.03, 1e-4)
        assert x[1] == 0.0 and x[2] == pytest.approx(0.25, abs=1e-7)
        i_rl = v / 1.5 * (1 - math.exp(-1.5 * n * 1e-3 / 2e-3))
        assert x[0] == pytest.approx(i_rl, rel=1e-5)
        assert 0 < friction < 0.06 * v / 1.5  # holds at most the steady k_t·V/R


def test_steady_speed_by_hand():
    # dω/dt = di/dt = 0: ω = (k_t·V/R − T)/(b + k_t·k_e/R) = (0.24 − 0.001)/0.00162 rad/s
    x = (0.0, 0.0, 0.0)
    for _ in range(600):  # 6 s, 32 time constants J/(b + k_t·k_e/R) = 0.185 s
        x = motor.step(P, x, 6.0, 1e-3, 1e-2)
    assert x[1] == pytest.approx((0.06 * 6.0 / 1.5 - 1e-3) / (2e-5 + 0.06 * 0.04 / 1.5), 1e-9)
    assert x[0] == pytest.approx((6.0 - 0.04 * x[1]) / 1.5, rel=1e-9)


def test_motor_torque():
    assert motor.motor_torque(P, 2.0) == pytest.approx(0.12)


def test_bad_parameters_and_inputs_name_the_value():
    with pytest.raises(ValueError, match=re.escape("inductance = 0.0")):
        motor.DCMotorParameters(inductance=0.0)
    with pytest.raises(ValueError, match=re.escape("viscous_damping = -1.0")):
        motor.DCMotorParameters(viscous_damping=-1.0)
    with pytest.raises(ValueError, match=re.escape("voltage = nan")):
        motor.step(P, (0.0, 0.0, 0.0), float("nan"), 0.0, 1e-3)
    with pytest.raises(ValueError, match=re.escape("running_friction = -0.1")):
        motor.step_with_friction(P, (0.0, 0.0, 0.0), 1.0, 0.0, 1e-3, -0.1, 0.0)


@pytest.mark.parametrize("h", [1e-4, 1e-3, 1e-2])
def test_fmu_follows_the_written_ode(fmus, h):
    params = dict(
        resistance=P.resistance,
        inductance=P.inductance,
        torque_constant=P.torque_constant,
        back_emf_constant=P.back_emf_constant,
        inertia=P.inertia,
        viscous_damping=P.viscous_damping,
    )
    fmu = Fmu(fmus["DCMotor"], f"ode{h}").init(
        initial_current=0.5, initial_speed=20.0, initial_angle=1.0, **params
    )
    t = 0.0
    for _ in range(round(0.1 / h)):
        fmu.set(voltage=6.0, load_torque=2e-3)
        fmu.slave.doStep(t, h)
        t += h
    got = fmu.get("current", "speed", "angle")
    ref = reference(P, (0.5, 20.0, 1.0), 6.0, 2e-3, 0.1)
    np.testing.assert_allclose(got, ref, rtol=1e-8, atol=1e-11)
    assert fmu.get("motor_torque") == pytest.approx(P.torque_constant * ref[0], rel=1e-8)
    fmu.close()


def _substeps_as_written(phi, gamma, state, voltage, load, n, running, breakaway):
    """The sub-steps with friction as the equations read, in Python (the reference of the
    compiled kernel: free step, hold or slide, friction added through Γ's torque column)."""
    i, w, a = state
    total = 0.0
    for _ in range(n):
        free = [
            phi[r][0] * i + phi[r][1] * w + phi[r][2] * a + gamma[r][0] * voltage
            + gamma[r][1] * load
            for r in range(3)
        ]  # fmt: skip
        drop = -gamma[1][1]
        held = abs(free[1]) <= drop * (breakaway if w == 0.0 else running)
        friction = free[1] / drop if held else math.copysign(running, free[1])
        i, w, a = (free[r] + gamma[r][1] * friction for r in range(3))
        w = 0.0 if held else w
        total += friction
    return (i, w, a), total / n


def test_friction_substeps_agree_bit_for_bit_on_both_paths():
    # the DCMotor FMU's sub-steps with friction, compiled and Python, against the loop as
    # written: through sticking, breakaway, reversals and both signs of the load
    rng = np.random.default_rng(3)
    kernels = {i: compiled.module("drives.motor_stepping", i) for i in implementations()}
    for _ in range(1500):
        n = int(rng.integers(1, 12))
        phi, gamma = motor.discretise(P, float(rng.choice([1e-5, 1e-4, 1e-3])))
        state = tuple(float(v) for v in rng.normal(0.0, [0.5, 2.0, 1.0]))
        if rng.random() < 0.3:
            state = (state[0], 0.0, state[2])  # at rest: the breakaway applies
        u = (float(rng.normal(0.0, 3.0)), float(rng.normal(0.0, 0.02)))
        running, breakaway = sorted(float(v) for v in rng.uniform(0.0, 0.05, 2))
        want = _substeps_as_written(phi, gamma, state, *u, n, running, breakaway)
        for impl, k in kernels.items():
            got = k.friction_substeps(phi, gamma, *state, *u, n, running, breakaway)
            assert got == want, impl

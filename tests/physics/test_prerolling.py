"""Pre-rolling friction (Dahl's model in BearingFriction): the closed-form step against an
independent integration, the rest stiffness from the contacts against a hand calculation, and
through fmpy on the built FMUs: Dahl's loop from rest and after a reversal, the Dahl resonance
of an inertia with DCMotor, the state round trip, bad parameters, and nothing changed with
prerolling_model = 0."""

from __future__ import annotations

import math

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException
from fmu_helpers import Fmu
from hypothesis import example, given, settings
from hypothesis import strategies as st
from kernels import implementations
from scipy.integrate import solve_ivp

from servofmu.physics import compiled
from servofmu.physics.friction import prerolling
from servofmu.physics.pair import BearingPair

SIGMA0 = 2.0  # N·m/rad, a given rest slope
SPEED = 0.05  # rad/s: tanh(SPEED/regularisation_speed) is 1 to the last bit
STEP = 1e-3  # s


# ------------------------------------------------------------------ the closed-form step
def _integrated(t0, tc, sigma0, i, dtheta):
    """Dahl's ODE dT/dθ = σ₀·|1 − sT/T_c|^i·sgn(1 − sT/T_c) by an adaptive Runge–Kutta (the
    independent check of the closed form)."""
    s = math.copysign(1.0, dtheta)

    def rhs(_, t):
        y = 1.0 - s * t[0] / tc
        return [s * sigma0 * abs(y) ** i * math.copysign(1.0, y)]

    sol = solve_ivp(rhs, (0.0, abs(dtheta)), [t0], rtol=1e-11, atol=1e-16 * tc, method="DOP853")
    return sol.y[0, -1]


@settings(max_examples=25, deadline=None)
@given(
    t0=st.floats(-1.0, 1.0),
    i=st.sampled_from([0.5, 1.0, 1.5, 2.0, 3.0]),
    x=st.floats(-3.0, 3.0).filter(lambda v: abs(v) > 1e-3),
)
@pytest.mark.slow
@example(t0=0.0, i=1.0, x=1.0)
@example(t0=-1.0, i=0.5, x=3.0)  # y0 = 2 down to 0 in a finite angle (i < 1)
def test_the_closed_form_step_is_dahls_ode_for_every_exponent(t0, i, x):
    tc, sigma0 = 1e-3, 2.0
    dtheta = x * tc / sigma0  # x rest-slope angles
    exact = prerolling.dahl_torque_step(t0 * tc, tc, sigma0, i, dtheta)
    assert exact == pytest.approx(_integrated(t0 * tc, tc, sigma0, i, dtheta), abs=1e-8 * tc)
    assert abs(exact) <= tc


def test_steps_compose_exactly_and_rest_holds_the_torque():
    tc = 3e-4
    one = prerolling.dahl_torque_step(0.0, tc, 2.0, 1.0, 4e-4)
    two = prerolling.dahl_torque_step(prerolling.dahl_torque_step(0.0, tc, 2.0, 1.0, 1e-4), tc,
                                      2.0, 1.0, 3e-4)  # fmt: skip
    assert two == pytest.approx(one, rel=1e-14)
    assert prerolling.dahl_torque_step(one, tc, 2.0, 1.0, 0.0) == one  # ω = 0: held
    assert prerolling.dahl_torque_step(one, 0.0, 2.0, 1.0, 1e-4) == 0.0  # T_c = 0: no torque
    # T_c falls below |T| (the grease thins): the contacts slip to ±T_c at once
    assert prerolling.dahl_torque_step(one, 0.5 * one, 2.0, 1.0, 0.0) == 0.5 * one
    assert prerolling.dahl_torque_step(-one, 0.5 * one, 2.0, 1.0, 1e-6) < 0.0


def test_the_fmus_per_step_kernels_agree_bit_for_bit_on_both_paths():
    # BearingFriction's per-step Dahl step and T_c, compiled and Python, against the library's
    # (the Python kernels), over exponents either side of 1, reversals, T_c below |T|, rest
    kernels = {impl: compiled.module("kernels.friction", impl) for impl in implementations()}
    rng = np.random.default_rng(7)
    for _ in range(2000):
        tc = float(rng.uniform(0.0, 2e-3)) * (rng.random() > 0.05)
        t0 = float(rng.uniform(-1.2, 1.2)) * 1e-3
        i = float(rng.choice([0.0, 0.5, 1.0, 1.5, 3.0]))
        dtheta = float(rng.normal(0.0, 1e-3)) * (rng.random() > 0.05)
        run, excess, speed = (float(v) for v in rng.uniform([0, 0, -1], [1e-3, 1e-3, 1]))
        want = prerolling.dahl_torque_step(t0, tc, SIGMA0, i, dtheta)
        want_tc = prerolling.stribeck_torque(run, excess, speed, 1e-2)
        for impl, k in kernels.items():
            assert k.dahl_torque_step(t0, tc, SIGMA0, i, dtheta) == want, impl
            assert k.stribeck_torque(run, excess, speed, 1e-2) == want_tc, impl
        assert abs(want) <= tc


# ------------------------------------------------------------------ the rest stiffness
def test_rest_stiffness_of_the_gimbal_pair_by_hand():
    """Yu's 71803 pair at 20 °C, zero external load. The inputs of the hand calculation are the
    equilibrium's (asserted below); the arithmetic was done by hand:

    G = 206 GPa/(2·1.33) = 77.444 GPa; 1/G* = 2·(2 − 0.33)/G → G* = 23.187 GPa;
    inner √(ab) = √(77.757 µm · 16.793 µm) = 36.135 µm → k_i = 8·G*·√(ab) = 6.7029 N/µm;
    outer √(89.220 µm · 17.516 µm) = 39.532 µm → k_o = 7.3329 N/µm;
    in series 3.5019 N/µm; r_i = (21.4967 − 2.38099·cos 0.21692)/2 mm = 9.5858 mm;
    per ball 3.5019e6 · (9.5858e-3)² = 321.78 N·m/rad; 15 balls × 2 bearings: 9653 N·m/rad."""
    from servofmu.physics.pair import pair_rows
    from servofmu.physics.pair_state import thermal_state
    from servofmu.physics.preload import pair_equilibrium
    from servofmu.physics.temperatures import PartTemperatures

    pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    th = thermal_state(pair, PartTemperatures(293.15, 293.15, 293.15, 293.15))
    g = th.geometry
    balls = pair_equilibrium(g, float(th.closure), pair_rows(pair), 0.0, 0.0).balls_a
    a_i, b_i = (float(v[0, 0]) for v in balls.inner.semi_axes(balls.load))
    a_o, b_o = (float(v[0, 0]) for v in balls.outer.semi_axes(balls.load))
    typed = (a_i, b_i, a_o, b_o, float(balls.contact_angle[0, 0]), float(g.pitch_diameter))
    assert typed == pytest.approx((77.757e-6, 16.793e-6, 89.220e-6, 17.516e-6, 0.21692,
                                   21.4967e-3), rel=1e-4)  # fmt: skip
    assert (pair.bearing.ring_material.youngs_modulus, pair.bearing.ring_material.poisson_ratio) \
        == (206e9, 0.33)  # fmt: skip
    sigma0 = prerolling.contact_rest_stiffness(pair, (293.15,) * 4)
    assert sigma0 == pytest.approx(9653.0, rel=2e-4)


def test_rest_stiffness_follows_temperature_and_preload():
    pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    cold, warm = (prerolling.contact_rest_stiffness(pair, (t,) * 4) for t in (233.15, 293.15))
    assert cold > 1.5 * warm > 0.0  # the yoke shrinks onto the pair: more preload
    assert prerolling.contact_rest_stiffness(pair, (333.15,) * 4) == 0.0  # preload lost
    loaded = prerolling.contact_rest_stiffness(pair, (293.15,) * 4, axial_load=20.0)
    assert loaded != warm


# ------------------------------------------------------------------ through fmpy
def _bearing(fmus, model=1, name="bearing", speed=SPEED, **values):
    values = {"prerolling_model": model, "prerolling_stiffness": SIGMA0, **values}
    return Fmu(fmus["BearingFriction"], name).init(temperature=293.15, speed=speed, **values)


def _run(fmu, speed, steps, t0=0.0):
    """(θ, T) after each of ``steps`` steps at ``speed``."""
    fmu.set(speed=speed)
    out = []
    for k in range(steps):
        fmu.slave.doStep(t0 + k * STEP, STEP)
        out.append(fmu.get("prerolling_angle", "friction_torque"))
    return np.array(out)


def test_the_fmu_follows_dahls_loop_from_rest_and_after_a_reversal(fmus):
    off = _bearing(fmus, model=0, name="off")
    tc = off.get("friction_torque")  # T_c: the FMU's torque without pre-rolling at this speed
    off.close()
    on = _bearing(fmus)
    assert on.get("friction_torque", "prerolling_torque", "prerolling_angle") == [0.0, 0.0, 0.0]
    up = _run(on, SPEED, 40)
    theta, torque = up[:, 0], up[:, 1]
    assert theta == pytest.approx(SPEED * STEP * np.arange(1, 41), rel=1e-12)
    loop = tc * (1.0 - np.exp(-SIGMA0 * theta / tc))
    assert np.max(np.abs(torque - loop)) <= 1e-9 * tc
    assert torque[-1] > 0.99 * tc  # closed onto today's running torque
    down = _run(on, -SPEED, 40, t0=40 * STEP)
    theta_r, torque_r = up[-1]
    back = -tc + (torque_r + tc) * np.exp(-SIGMA0 * (theta_r - down[:, 0]) / tc)
    assert np.max(np.abs(down[:, 1] - back)) <= 1e-9 * tc
    assert on.get("prerolling_torque") == down[-1, 1]
    on.close()


def test_the_dahl_resonance_of_an_inertia_with_dcmotor(fmus):
    """A gimbal inertia on the bearing's rest slope, no motor torque (R large), a small
    initial speed so that |T| ≪ T_c: it rings at √(σ₀/J)/2π."""
    inertia, sigma0, h = 2e-4, 1.0, 1e-4  # kg·m², N·m/rad, s
    f_dahl = math.sqrt(sigma0 / inertia) / (2.0 * math.pi)
    w0 = 2.0 * math.pi * f_dahl * 3e-6  # rad/s: an amplitude of 3 µrad, σ₀θ ≈ 1 % of T_c
    motor = Fmu(fmus["DCMotor"], "motor").init(
        resistance=1e6, inertia=inertia, viscous_damping=0.0, initial_speed=w0
    )
    bearing = _bearing(fmus, prerolling_stiffness=sigma0, speed=w0)
    speeds = []
    for k in range(int(6.0 / f_dahl / h)):
        w = motor.get("speed")
        bearing.set(speed=w)
        motor.set(load_torque=bearing.get("friction_torque"))
        motor.slave.doStep(k * h, h)
        bearing.slave.doStep(k * h, h)
        speeds.append(w)
    assert abs(bearing.get("friction_torque")) < 0.03 * bearing.get("running_torque")
    motor.close()
    bearing.close()
    w = np.array(speeds)
    k = np.flatnonzero(np.sign(w[:-1]) != np.sign(w[1:]))
    crossings = (k + w[k] / (w[k] - w[k + 1])) * h  # s, linear between the samples
    f = (len(crossings) - 1) / (2.0 * (crossings[-1] - crossings[0]))
    assert len(crossings) >= 10
    assert f == pytest.approx(prerolling.dahl_resonance_frequency(sigma0, inertia), rel=0.01)
    assert f == pytest.approx(f_dahl, rel=0.01)


def test_the_prerolling_state_round_trips(fmus):
    fmu = _bearing(fmus)
    _run(fmu, SPEED, 3)
    saved = fmu.slave.getFMUstate()
    blob = bytes(fmu.slave.serializeFMUstate(saved))
    first = _run(fmu, -SPEED, 5, t0=3 * STEP)
    fmu.slave.setFMUstate(saved)
    fmu.set(speed=SPEED)  # the input as saved; the next step sets -SPEED again
    assert np.array_equal(_run(fmu, -SPEED, 5, t0=3 * STEP), first)
    again = _bearing(fmus, name="again")
    state = again.slave.deSerializeFMUstate(blob)
    again.slave.setFMUstate(state)
    assert np.array_equal(_run(again, -SPEED, 5, t0=3 * STEP), first)
    for f in (fmu, again):
        f.slave.freeFMUstate(saved if f is fmu else state)
        f.close()


@pytest.mark.parametrize(
    "name, value",
    [("prerolling_model", 2), ("prerolling_stiffness", -1.0), ("prerolling_exponent", math.nan)],
)
def test_a_bad_prerolling_parameter_is_refused_naming_it(fmus, name, value):
    fmu = Fmu(fmus["BearingFriction"], "bad")
    fmu.slave.setupExperiment(startTime=0.0)
    fmu.slave.enterInitializationMode()
    fmu.set(**{name: value})
    with pytest.raises(FMICallException) as exc:
        fmu.slave.exitInitializationMode()
    assert exc.value.status == 3  # fmi2Error
    said = " ".join(m for _, m in fmu.log)
    assert name in said and "valid range" in said, said
    fmu.close()


def test_prerolling_model_0_changes_nothing(fmus):
    runs = []
    for values in ({}, {"prerolling_model": 0, "prerolling_stiffness": 5.0}):
        fmu = Fmu(fmus["BearingFriction"], "zero").init(temperature=253.15, speed=0.0, **values)
        out = []
        for k, w in enumerate((1e-4, -3e-4, 0.2, 0.0, -2.0)):
            fmu.set(speed=w)
            fmu.slave.doStep(k * STEP, STEP)
            out.append(fmu.real_outputs())
        fmu.close()
        runs.append(np.array(out))
    assert np.array_equal(runs[0], runs[1])
    names = [n for n in fmu.outputs() if fmu.type[n] == "Real"]
    both = runs[0][:, [names.index("prerolling_angle"), names.index("prerolling_torque")]]
    assert np.all(both == 0.0)

import dataclasses
import math
import re

import numpy as np
import pytest

from servofmu.physics.bearing import BearingModel, BearingPair, with_mounting
from servofmu.physics.pair import model as bm


@pytest.fixture(scope="module")
def printed():
    return BearingPair.from_catalog("yu2017_gimbal_printed", "krytox_143aa")


def test_scalar_path_equals_vectorised_curves(yu_pair):
    m = BearingModel(yu_pair)
    t = np.array([240.0, 280.0, 300.0])
    curves = m.curves(t, 0.2)
    for i, ti in enumerate(t):
        one = m.evaluate(float(ti), 0.2)
        for name in (
            "running_torque",
            "preload",
            "contact_angle",
            "axial_stiffness",
            "radial_clearance",
        ):
            assert getattr(one, name) == pytest.approx(float(getattr(curves, name)[i]), rel=1e-10)


@pytest.mark.parametrize("axial", [-350.0, -40.0, -1.0, 0.5, 25.0, 180.0, 400.0])
def test_per_step_load_equals_the_exact_solution(printed, axial):
    m = BearingModel(printed)
    m.evaluate(293.15, 0.3)  # the continuation starts from the unloaded state
    fast = m.evaluate(293.15, 0.3, axial)
    exact = m.load(293.15, axial)
    assert fast.force_a - fast.force_b == pytest.approx(axial, rel=1e-9, abs=1e-9)
    assert fast.hysteresis_torque + fast.spin_torque == pytest.approx(exact.torques.total, rel=1e-9)
    assert fast.preload == pytest.approx(exact.preload, rel=1e-9)
    assert fast.axial_stiffness == pytest.approx(exact.axial_stiffness, rel=1e-9)
    assert fast.contact_angle == pytest.approx(exact.contact_angle, rel=1e-9)
    assert m.exact_steps == 0  # the first call a cold start, the second a warm one


def test_large_load_is_solved_and_overloads(printed):
    m = BearingModel(printed)
    out = m.evaluate(293.15, 0.3, 5000.0)
    assert out.overloaded and out.max_contact_pressure > printed.pressure_limit
    # 5000 N against a preload of a few hundred N lifts bearing B off: the preload is lost
    assert out.unloaded and out.force_b == 0.0 and not out.locked
    assert out.force_a - out.force_b == pytest.approx(5000.0, rel=1e-9)


def test_speed_change_does_not_resolve_state(yu_pair, monkeypatch):
    m = BearingModel(yu_pair)
    m.evaluate(293.15, 0.1, 10.0)
    calls = []
    for name in ("thermal_state_at", "load_state"):
        monkeypatch.setattr(bm, name, lambda *a, _n=name, **k: calls.append(_n))
    solved = m.steps
    for w in np.linspace(-1, 1, 11):
        m.evaluate(293.15, float(w), 10.0)
    assert calls == [] and m.steps == solved  # no new state: only the speed terms


def test_no_step_of_a_ramp_is_solved_exactly(yu_pair, monkeypatch):
    m = BearingModel(yu_pair)
    real = bm.thermal_state_at
    calls = []

    def counting(pair, *t):
        calls.append(t)
        return real(pair, *t)

    monkeypatch.setattr(bm, "thermal_state_at", counting)
    for t in np.linspace(253.15, 263.15, 50):
        m.evaluate(float(t), 0.1, 5.0)
    assert not calls and m.steps == 50 and m.exact_steps == 0 and m.cold_starts == 1


def test_overload_is_a_reported_state(yu_pair):
    out = BearingModel(yu_pair).evaluate(233.15, 0.1)  # stated reading, rigid loop, −40 °C
    assert out.overloaded is True and out.locked is False and out.unloaded is False
    assert math.isfinite(out.running_torque) and out.max_contact_pressure > 4.2e9


def test_lost_preload_is_reported_as_unloaded(yu_pair):
    m = BearingModel(yu_pair)  # stated reading: the loop opens on heating
    warm, room = m.evaluate(333.15, 0.1), m.evaluate(293.15, 0.1)
    assert warm.preload == 0.0 and warm.unloaded is True and not warm.overloaded
    assert room.preload > 0.0 and room.unloaded is False


def test_negative_clearance_stays_finite(yu_pair):
    tight = with_mounting(yu_pair, outer_interference=16e-6, loop_stiffness=1e6)
    out = BearingModel(tight).evaluate(233.15, 0.1)
    assert out.radial_clearance < 0 and out.locked is True
    assert all(math.isfinite(v) for v in dataclasses.astuple(out))


def test_friction_opposes_rotation_and_dissipates(printed):
    m = BearingModel(printed)
    for w in (-2.0, -1e-4, 0.0, 1e-4, 2.0):
        out = m.evaluate(293.15, w)
        assert np.sign(out.friction_torque) == np.sign(w)
        assert out.power_loss >= 0.0
    assert abs(m.evaluate(293.15, 5.0).friction_torque) == pytest.approx(
        m.evaluate(293.15, 5.0).running_torque, rel=1e-9
    )


def test_breakaway_exceeds_running_at_rest(printed):
    out = BearingModel(printed).evaluate(293.15, 0.0)
    rest = out.hysteresis_torque + out.spin_torque + out.sliding_torque + out.viscous_torque
    ratio = printed.coefficients.static_friction_ratio
    assert out.breakaway_torque == pytest.approx(
        rest + (ratio - 1) * (out.spin_torque + out.sliding_torque)
    )
    assert out.breakaway_torque > rest


def test_solid_lubrication_has_no_viscous_term(ning_pair):
    out = BearingModel(ning_pair).evaluate(293.15, 3.0)
    assert out.viscous_torque == 0.0 and out.kinematic_viscosity == 0.0
    assert out.sliding_torque > 0.0


def test_radial_load_path(printed):
    m = BearingModel(printed)
    out = m.evaluate(293.15, 0.1, 10.0, 30.0)
    assert out.force_a - out.force_b == pytest.approx(10.0, abs=1e-6)
    base = m.evaluate(293.15, 0.1, 10.0, 0.0)
    assert out.running_torque > base.running_torque  # more ball load on the loaded side


@pytest.mark.parametrize(
    "args, match",
    [
        ((0.0, 0.1), "temperature = 0.0 K"),
        ((float("nan"), 0.1), "temperature = nan"),
        ((293.15, float("inf")), "speed = inf rad/s"),
        ((293.15, 0.1, float("nan")), "axial_load = nan N"),
        ((293.15, 0.1, 0.0, float("-inf")), "radial_load = -inf N"),
    ],
)
def test_bad_input_names_the_variable(printed, args, match):
    with pytest.raises(ValueError, match=re.escape(match)):
        BearingModel(printed).evaluate(*args)


def test_bad_configuration(printed):
    with pytest.raises(ValueError, match=re.escape("lubrication = 'oil'")):
        dataclasses.replace(printed, lubrication="oil")
    with pytest.raises(ValueError, match="needs a lubricant"):
        dataclasses.replace(printed, lubricant=None)
    with pytest.raises(ValueError, match=re.escape("mounting change ['colour']")):
        with_mounting(printed, colour="red")


def test_vectorised_curve_has_no_nan_over_a_wide_range(yu_pair):
    out = BearingModel(yu_pair).curves(np.linspace(173.15, 423.15, 251), 0.1)
    for name in ("running_torque", "preload", "axial_stiffness", "contact_angle"):
        assert np.all(np.isfinite(getattr(out, name))), name

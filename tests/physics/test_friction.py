import math
import re

import numpy as np
import pytest
from scipy.integrate import quad

from servofmu.physics.contact.hertz import contact_constants
from servofmu.physics.friction import terms as fr


def test_heathcote_constant_matches_johnson():
    # rolling lines at u0 ≈ 0.347 and F ≈ 0.08·μ·Q·(a/R)² for a close groove (Johnson 1985)
    u0 = 0.3472963553
    integral = quad(lambda u: (1 - u * u) * abs(u0 * u0 - u * u), -1, 1, points=[-u0, u0])[0]
    assert fr.HEATHCOTE == pytest.approx(0.75 * integral, rel=1e-9)
    # close conformity: R_c → Dw/2 gives F = C_H·μ·Q·a²/(Dw²/2) = (C_H/2)·μ·Q·(a/R)²
    assert fr.HEATHCOTE / 2 == pytest.approx(0.08, rel=0.01)


def test_heathcote_force_limit():
    dw, a, q, mu = 2e-3, 0.1e-3, 10.0, 0.1
    f = fr.heathcote_sliding_force(q, a, dw, 0.5 * dw, mu)  # groove radius = ball radius
    assert f == pytest.approx(fr.HEATHCOTE / 2 * mu * q * (a / (dw / 2)) ** 2)


def test_yu_eq1_hysteresis_force():
    # F = 3·b·α_r·Q/(16·R) with R = Dw/2
    assert fr.hysteresis_rolling_force(10.0, 20e-6, 2.4e-3, 0.007) == pytest.approx(
        3 * 20e-6 * 0.007 * 10.0 / (16 * 1.2e-3)
    )


def test_yu_eq6_spin_circular_contact():
    c = contact_constants(1e3, 0.0, 1e-11)  # circular: E(0) = π/2
    a = c.semi_axes(50.0)[0]
    assert fr.spin_moment(50.0, a, c.e_integral, 0.1) == pytest.approx(
        3 / 8 * 0.1 * 50 * a * math.pi / 2
    )


def test_palmgren_eq8_branches():
    dm, s0 = 21.5e-3, 1.0
    nu = 40947e-6  # m²/s (Krytox at −40 °C)
    w = 1.0 * 2 * math.pi / 60  # 1 rpm
    # ν·n = 40947 ≥ 2000: 1e-7·s0·(ν n)^(2/3)·dm³ N·mm
    assert fr.palmgren_viscous_torque(nu, w, dm, s0) == pytest.approx(
        1e-7 * 40947 ** (2 / 3) * 21.5**3 * 1e-3
    )
    # below 2000 the torque is the speed-independent floor, continuous at the threshold
    floor = fr.palmgren_viscous_torque(nu, 0.0, dm, s0)
    assert floor == pytest.approx(1e-7 * 2000 ** (2 / 3) * 21.5**3 * 1e-3)
    assert floor == pytest.approx(160e-7 * 21.5**3 * 1e-3, rel=0.01)  # printed 160
    w_threshold = 2000 / (nu / 1e-6) * 2 * math.pi / 60
    assert fr.palmgren_viscous_torque(nu, w_threshold * (1 + 1e-9), dm, s0) == pytest.approx(floor)
    assert fr.palmgren_viscous_torque(nu, -w, dm, s0) == fr.palmgren_viscous_torque(nu, w, dm, s0)


def test_regularised_torque_is_odd_smooth_and_bounded():
    w = np.linspace(-1, 1, 200001)  # steps of 1e-5 rad/s, 1 % of the regularisation width
    m = fr.regularised_friction_torque(w, 2e-3, 1e-3, 1e-3, 1e-2)
    np.testing.assert_allclose(m, -m[::-1], atol=1e-18)
    assert m[100000] == 0.0
    # no jump through zero: the steepest step is the slope (3e-3 N·m)/(1e-3 rad/s) × 1e-5
    assert np.max(np.abs(np.diff(m))) < 3.1e-5
    assert m[-1] == pytest.approx(2e-3, rel=1e-6)  # running torque far from zero speed
    assert np.max(np.abs(m)) > 2e-3  # breakaway peak near zero speed


def _ball_set(lubrication, sliding, mu=0.05, alpha_r=0.007):
    from servofmu.parameters import catalog
    from servofmu.physics.contact.equilibrium import axial_state, offset_for_axial_force

    g = catalog.bearing("71803").race_geometry()
    s = axial_state(g, offset_for_axial_force(g, 30.0))

    def e(c):
        return type(c)(*(np.asarray(getattr(c, f))[..., None] for f in c.__dataclass_fields__))

    return fr.ball_set_torques(
        np.asarray(s.ball_load)[..., None],
        np.asarray(s.contact_angle)[..., None],
        e(s.inner),
        e(s.outer),
        g.pitch_diameter,
        g.ball_diameter,
        g.inner_groove_radius,
        g.outer_groove_radius,
        fr.FrictionCoefficients(hysteresis_loss=alpha_r, sliding_friction=mu),
        lubrication,
        sliding,
    )


def test_ball_set_terms():
    grease = _ball_set("grease", False)
    solid = _ball_set("solid", True)
    assert float(grease.sliding) == 0.0 and float(solid.sliding) > 0
    # grease (Yu eq 7) takes the larger spin moment; solid spins at the inner race only
    assert float(grease.spin) >= float(solid.spin) > 0
    assert float(solid.inner_ring + solid.outer_ring) == pytest.approx(float(solid.total))
    # spin and sliding are linear in μ, hysteresis in α_r
    double = _ball_set("solid", True, mu=0.1, alpha_r=0.014)
    assert float(double.total) == pytest.approx(2 * float(solid.total))


def test_coefficient_ranges():
    with pytest.raises(ValueError, match=re.escape("static_friction_ratio = 0.5")):
        fr.FrictionCoefficients(static_friction_ratio=0.5)
    with pytest.raises(ValueError, match=re.escape("sliding_friction = -0.1")):
        fr.FrictionCoefficients(sliding_friction=-0.1)


def test_spin_sits_at_the_controlling_race():
    # Three balls, each Q = 10 N at α = 15°, μ = 0.1, no hysteresis, no sliding. Circular
    # contacts (F(ρ) = 0, E = π/2) with Σρ = 4000 1/m at the inner and 1000 1/m at the outer
    # race, steel on steel (η = 2·(1 − 0.3²)/206.9 GPa = 8.7965e-12 1/Pa). By hand (Hertz
    # sphere, a = (3·Q·η/(2·Σρ))^(1/3); spin M = (3/8)·μ·Q·a·E·sin α per ball, Yu eq 6–7):
    #   inner: a = 3.2071e-5 m, M = 4.8895e-6 N·m, three balls 1.4668e-5 N·m
    #   outer: a = 5.0910e-5 m, M = 7.7615e-6 N·m, three balls 2.3285e-5 N·m
    # Solid lubrication (Ning; outer-race control, Jones 1960): the balls roll on the outer
    # race and spin on the inner one. Grease (Yu eq 7): the larger spin moment, here the outer.
    eta = 2 * (1 - 0.3**2) / 206.9e9
    inner, outer = contact_constants(4000.0, 0.0, eta), contact_constants(1000.0, 0.0, eta)
    load = np.full(3, 10.0)
    alpha = np.full(3, math.radians(15.0))
    coeff = fr.FrictionCoefficients(hysteresis_loss=0.0, sliding_friction=0.1)

    def torques(lubrication):
        return fr.ball_set_torques(
            load, alpha, inner, outer, 20e-3, 3e-3, 1.6e-3, 1.6e-3, coeff, lubrication, False
        )

    solid, grease = torques("solid"), torques("grease")
    assert float(solid.spin) == pytest.approx(1.4668e-5, rel=1e-4)
    assert float(solid.inner_ring) == pytest.approx(1.4668e-5, rel=1e-4)
    assert float(solid.outer_ring) == 0.0
    assert float(grease.spin) == pytest.approx(2.3285e-5, rel=1e-4)
    assert float(grease.outer_ring) == pytest.approx(2.3285e-5, rel=1e-4)
    assert float(grease.inner_ring) == 0.0

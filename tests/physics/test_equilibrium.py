import doctest
import math
import re

import numpy as np
import pytest
from scipy.optimize import brentq

from servofmu.parameters import catalog
from servofmu.physics.contact import equilibrium as eq
from servofmu.physics.contact.geometry import RaceGeometry


def with_clearance(g: RaceGeometry, pd):
    """The same bearing with diametral clearance ``pd`` (outer groove moved)."""
    return RaceGeometry(
        g.ball_diameter,
        g.inner_race_diameter,
        g.inner_race_diameter + 2 * g.ball_diameter + pd,
        g.inner_groove_radius,
        g.outer_groove_radius,
        g.n_balls,
        g.compliance,
    )


@pytest.fixture(scope="module")
def geom(b71803):
    return b71803.race_geometry()


def test_yu_eq4_ball_load_under_pure_axial_load(geom):
    a = eq.offset_for_axial_force(geom, 50.0)
    s = eq.axial_state(geom, a)
    assert s.axial_force == pytest.approx(50.0, rel=1e-9)
    assert s.ball_load == pytest.approx(50.0 / (geom.n_balls * math.sin(s.contact_angle)))


def test_yu_eq16_eq17_hold_for_positive_clearance(geom):
    # eq 16: Fa = Z·K·(B·Dw)^1.5·sin α·(cos α0/cos α − 1)^1.5 with K at the operating angle;
    # eq 17: axial displacement from first contact = B·Dw·sin(α − α0)/cos α
    a_len, a0 = geom.curvature_distance, geom.free_contact_angle
    for force in (1.0, 20.0, 300.0):
        s = eq.axial_state(geom, eq.offset_for_axial_force(geom, force))
        al = float(s.contact_angle)
        k_n = float(s.ball_load) / float(s.deflection) ** 1.5
        eq16 = (
            geom.n_balls
            * k_n
            * a_len**1.5
            * math.sin(al)
            * (math.cos(a0) / math.cos(al) - 1) ** 1.5
        )
        assert eq16 == pytest.approx(force, rel=1e-9)
        eq17 = a_len * math.sin(al - a0) / math.cos(al)
        assert float(s.offset) - geom.first_contact_offset == pytest.approx(eq17, rel=1e-9)


@pytest.mark.parametrize("pd", [5e-6, 0.0, -3e-6])
def test_general_geometry_holds_at_zero_and_negative_clearance(geom, pd):
    g = with_clearance(geom, pd)
    a = np.linspace(-20e-6, 60e-6, 81)
    f = eq.axial_force(a, g)
    assert np.all(np.isfinite(f))
    assert np.all(np.diff(f) >= 0)  # non-decreasing
    np.testing.assert_allclose(eq.axial_force(-a, g), -f, atol=1e-12)  # odd
    s0 = eq.axial_state(g, 0.0)
    if pd < 0:  # compressed at α = 0 by −Pd/2, no axial force
        assert float(s0.deflection) == pytest.approx(-pd / 2)
        assert float(s0.axial_force) == 0.0 and float(s0.ball_load) > 0
    else:
        assert float(s0.ball_load) < 1e-12


def test_axial_force_is_continuous_through_zero_clearance(geom):
    # 1 nm of clearance moves the 1.9 µm ball deflection by 0.5 nm·cos α: a 4e-4 change
    for step in (1e-9, 1e-10):
        f = [float(eq.axial_force(30e-6, with_clearance(geom, pd))) for pd in (step, 0.0, -step)]
        assert abs(f[0] - f[1]) < 5e-4 * f[1] * step / 1e-9
        assert abs(f[2] - f[1]) < 5e-4 * f[1] * step / 1e-9


def test_axial_stiffness_is_the_derivative(geom):
    a = eq.offset_for_axial_force(geom, 40.0)
    h = 1e-10
    num = (eq.axial_force(a + h, geom) - eq.axial_force(a - h, geom)) / (2 * h)
    assert float(eq.axial_state(geom, a).axial_stiffness) == pytest.approx(float(num), rel=2e-3)


@pytest.mark.parametrize(
    "loads", [(50.0, 0.0, 0.0), (50.0, 20.0, 0.0), (80.0, 30.0, 0.15), (5.0, 40.0, 0.0)]
)
def test_bearing_displacements_balance_the_loads(geom, loads):
    d = eq.bearing_displacements(geom, *loads)
    assert d.converged
    b = d.balls
    np.testing.assert_allclose(
        [float(b.axial_force), float(b.radial_force), float(b.moment)],
        loads,
        atol=1e-8 * max(abs(x) for x in loads),
    )
    assert d.axial_displacement == pytest.approx(d.axial_offset - geom.first_contact_offset)


def test_radial_load_reverses_with_its_sign(geom):
    p = eq.bearing_displacements(geom, 60.0, 25.0)
    n = eq.bearing_displacements(geom, 60.0, -25.0)
    assert n.radial_displacement == pytest.approx(-p.radial_displacement, rel=1e-8)
    assert n.axial_offset == pytest.approx(p.axial_offset, rel=1e-8)


def test_ring_stiffness_matches_finite_differences(geom):
    # independent small-deflection check of the analytic Jacobian used by the solvers
    x = np.array([7.0e-5, 2e-6, 1e-4])
    base = eq._ball_loads(geom, np.array([[x[0]]]), np.array([[x[1]]]), np.array([[x[2]]]))
    jac = eq._ring_stiffness(geom, base)[0]
    for j, h in enumerate((1e-11, 1e-11, 1e-9)):
        xp, xm = x.copy(), x.copy()
        xp[j] += h
        xm[j] -= h
        fp = eq._ball_loads(geom, np.array([[xp[0]]]), np.array([[xp[1]]]), np.array([[xp[2]]]))
        fm = eq._ball_loads(geom, np.array([[xm[0]]]), np.array([[xm[1]]]), np.array([[xm[2]]]))
        num = [
            (float(getattr(fp, n)[0]) - float(getattr(fm, n)[0])) / (2 * h)
            for n in ("axial_force", "radial_force", "moment")
        ]
        np.testing.assert_allclose(jac[:, j], num, rtol=5e-3, atol=1e-3 * np.abs(jac).max())


def test_unloaded_bearing_is_centred(geom):
    d = eq.bearing_displacements(geom, 0.0, 0.0)
    assert d.converged and d.axial_offset == 0.0 and float(d.balls.load.max()) == 0.0


def test_bad_input(geom):
    with pytest.raises(ValueError, match=re.escape("axial_load = nan")):
        eq.bearing_displacements(geom, float("nan"))
    with pytest.raises(ValueError, match=re.escape("offset = inf")):
        eq.axial_state(geom, float("inf"))


# --- moment loads ----------------------------------------------------------------------


def arm_by_hand(g: RaceGeometry, tilt_arm: str) -> float:
    """The two tilt arms from the geometry fields: inner-groove curvature centres d_i/2 + r_i
    (Harris & Kotzalas 2007, Advanced Concepts ch. 1) or pitch radius (d_i + d_o)/4."""
    if tilt_arm == "groove":
        return g.inner_race_diameter / 2 + g.inner_groove_radius
    return (g.inner_race_diameter + g.outer_race_diameter) / 4


def ring_loads_by_hand(d: eq.Displacements, g: RaceGeometry, tilt_arm: str):
    """(Fa, Fr, M) summed here from the solution's per-ball Q_j and α_j."""
    psi = 2 * np.pi * np.arange(g.n_balls) / g.n_balls
    q, al = d.balls.load, d.balls.contact_angle
    r = arm_by_hand(g, tilt_arm)
    return (
        float(np.sum(q * np.sin(al))),
        float(np.sum(q * np.cos(al) * np.cos(psi))),
        float(np.sum(q * np.sin(al) * r * np.cos(psi))),
    )


@pytest.mark.parametrize("key", ["71803", "7204C", "6204"])
@pytest.mark.parametrize("pd", [None, 0.0, -3e-6])
@pytest.mark.parametrize("moment", [1e-5, 0.02, -0.3])
@pytest.mark.parametrize("tilt_arm", ["groove", "pitch"])
def test_pure_moment_converges(key, pd, moment, tilt_arm):
    # at zero displacement the stiffness is zero (positive or zero clearance): the solve
    # starts from a finite tilt estimated from the moment
    g = catalog.bearing(key).race_geometry()
    g = g if pd is None else with_clearance(g, pd)
    d = eq.bearing_displacements(g, 0.0, 0.0, moment, tilt_arm=tilt_arm)
    assert d.converged
    assert np.sign(d.tilt) == np.sign(moment)
    fa, fr, m = ring_loads_by_hand(d, g, tilt_arm)
    force_tol = 1e-8 * abs(moment) / arm_by_hand(g, tilt_arm)  # N
    assert abs(fa) < force_tol and abs(fr) < force_tol
    assert m == pytest.approx(moment, rel=1e-8)


@pytest.mark.parametrize(
    "loads",
    [(0.0, 5.0, 0.05), (2.0, 0.0, 0.3), (-20.0, 0.0, 0.05), (50.0, 20.0, -0.3), (0.0, -40.0, 1.0)],
)
@pytest.mark.parametrize("tilt_arm", ["groove", "pitch"])
def test_moment_with_axial_and_radial_load_converges(geom, loads, tilt_arm):
    d = eq.bearing_displacements(geom, *loads, tilt_arm=tilt_arm)
    assert d.converged
    np.testing.assert_allclose(
        ring_loads_by_hand(d, geom, tilt_arm), loads, atol=1e-8 * max(map(abs, loads))
    )


def preload_state_by_hand(g: RaceGeometry, fa: float):
    """One bearing under the pure axial load ``fa`` [N], derived here: every ball at
    s = √(a² + A2²), α = atan2(a, A2), δ = s − A, Q = K_n(α)·δ^1.5, Fa = Z·Q·sin α
    (Harris & Kotzalas 2007, Advanced Concepts ch. 1), a found by brentq. Returns the
    per-bearing axial force function and (a, α, δ, Q, s)."""
    big_a = g.inner_groove_radius + g.outer_groove_radius - g.ball_diameter
    a2 = big_a - (g.outer_race_diameter - g.inner_race_diameter - 2 * g.ball_diameter) / 2

    def ball(a):
        s = math.hypot(a, a2)
        al = math.atan2(a, a2)
        k_n = float(eq.contact_constants_at(g, al)[2])  # the Hertz constant (test_hertz)
        delta = s - big_a
        return al, delta, k_n * max(delta, 0.0) ** 1.5, s

    def axial(a):
        al, _, q, _ = ball(a)
        return g.n_balls * q * math.sin(al)

    a = brentq(lambda x: axial(x) - fa, 0.0, big_a, xtol=1e-18, rtol=1e-15)
    return axial, (a, *ball(a))


@pytest.fixture(scope="module")
def preloaded(geom):
    return preload_state_by_hand(geom, 50.0)


def test_tilt_stiffness_radially_held_is_k_ax_r2_over_2(geom, preloaded):
    # rigid rings, radial displacement held: each ball moves axially by θ·R·cos ψ, so
    # dM/dθ = Σ k_ax,ball·R²·cos²ψ = K_ax·R²/2 (Σ cos²ψ = Z/2), K_ax the axial stiffness at the
    # preload, here by central difference of the hand-derived Fa(a). The neglected terms are
    # O((θR/δ)²) = 1.4e-4 at θ = 1e-5 (Σ cos³ψ = 0 for Z = 15 removes the first-order one)
    axial, (a, _, delta, _, _) = preloaded
    h = 1e-11
    k_ax = (axial(a + h) - axial(a - h)) / (2 * h)
    r = arm_by_hand(geom, "pitch")
    theta = 1e-5
    b = eq.ball_loads(geom, a, 0.0, theta, tilt_arm="pitch")
    eps = theta * r / delta
    assert float(b.moment) / theta == pytest.approx(k_ax * r**2 / 2, rel=eps**2)
    assert float(b.axial_force) == pytest.approx(50.0, rel=eps**2)


def test_tilt_of_pitch_arm_matches_hand_check(geom, preloaded):
    # bearing_displacements leaves the radial displacement free (Fr = 0): a single
    # angular-contact row then tilts about its pressure centre (δr ≈ −θ·R·tan α), the balls'
    # normal approach k_n = dQ/ds is nearly not engaged and the tangential term k_t = Q/s of the
    # preloaded contacts resists. Eliminating δr from the per-ball stiffness
    # k = k_n·n·nᵀ + k_t·(I − n·nᵀ), n = (sin α, cos α), gives
    #     M/θ = (Z·R²/2)·k_n·k_t / (k_n·cos²α + k_t·sin²α).
    # Neglected: the angle dependence of K_n (measured 1.6e-6 as M → 0) and O((θR/δ)²)
    # (θR/δ = 0.011 at 0.1 N·mm); tolerance 1e-5.
    _, (_, al, delta, q, s) = preloaded
    k_n = 1.5 * q / delta
    k_t = q / s
    r = arm_by_hand(geom, "pitch")
    k_theta = (
        geom.n_balls * r**2 / 2 * k_n * k_t / (k_n * math.cos(al) ** 2 + k_t * math.sin(al) ** 2)
    )
    moment = 1e-4
    d = eq.bearing_displacements(geom, 50.0, 0.0, moment, tilt_arm="pitch")
    assert d.converged
    assert moment / d.tilt == pytest.approx(k_theta, rel=1e-5)
    assert d.radial_displacement == pytest.approx(-d.tilt * r * math.tan(al), rel=1e-2)
    # the radially held stiffness K_ax·R²/2 is 14 times larger: the free row is far softer
    axial, (a, *_) = preloaded
    k_ax = (axial(a + 1e-11) - axial(a - 1e-11)) / 2e-11
    assert k_ax * r**2 / 2 > 10 * k_theta


@pytest.mark.parametrize("loads", [(50.0, 0.0, 0.01), (0.0, 0.0, 0.05), (20.0, 10.0, -0.2)])
def test_groove_and_pitch_tilts_differ_by_the_ratio_of_the_arms(geom, loads):
    # kinematics and moment both scale with R: the pitch arm under M·R_p/R_g gives the very
    # ball loads of the groove arm under M, at the tilt θ_g·R_g/R_p
    fa, fr, m = loads
    r_g, r_p = arm_by_hand(geom, "groove"), arm_by_hand(geom, "pitch")
    g_ = eq.bearing_displacements(geom, fa, fr, m, tilt_arm="groove")
    p_ = eq.bearing_displacements(geom, fa, fr, m * r_p / r_g, tilt_arm="pitch")
    assert g_.converged and p_.converged
    assert p_.tilt == pytest.approx(g_.tilt * r_g / r_p, rel=1e-8)
    assert p_.axial_offset == pytest.approx(g_.axial_offset, rel=1e-8)
    np.testing.assert_allclose(p_.balls.load, g_.balls.load, rtol=1e-7, atol=1e-9 * max(loads))


def test_same_small_moment_tilts_by_the_arm_ratio_squared(geom):
    # preloaded and linear: the tilting stiffness grows as R², so under one moment the tilts
    # differ by (R_g/R_p)² (2.6 % for the 71803; the arms by 1.29 %)
    r_g, r_p = arm_by_hand(geom, "groove"), arm_by_hand(geom, "pitch")
    assert r_g / r_p - 1 == pytest.approx(0.0129, abs=5e-5)
    g_ = eq.bearing_displacements(geom, 50.0, 0.0, 1e-4, tilt_arm="groove")
    p_ = eq.bearing_displacements(geom, 50.0, 0.0, 1e-4, tilt_arm="pitch")
    assert p_.tilt / g_.tilt == pytest.approx((r_g / r_p) ** 2, rel=1e-5)


def test_tilt_arm_radius_is_the_documented_arm(geom):
    for arm in eq.TILT_ARMS:
        assert float(eq.tilt_arm_radius(geom, arm)) == pytest.approx(arm_by_hand(geom, arm))


def test_bad_tilt_arm_and_moment_are_named(geom):
    msg = re.escape("tilt_arm = 'ball' is not one of ['groove', 'pitch']")
    with pytest.raises(ValueError, match=msg):
        eq.bearing_displacements(geom, 0.0, 0.0, 0.01, tilt_arm="ball")
    with pytest.raises(ValueError, match=msg):
        eq.ball_loads(geom, 7e-5, tilt=1e-4, tilt_arm="ball")
    with pytest.raises(ValueError, match=msg):
        eq.tilt_arm_radius(geom, "ball")
    with pytest.raises(ValueError, match=re.escape("moment = nan")):
        eq.bearing_displacements(geom, 0.0, 0.0, float("nan"))
    with pytest.raises(ValueError, match=re.escape("tilt = inf")):
        eq.ball_loads(geom, 7e-5, tilt=float("inf"))


def test_doctests_pass():
    result = doctest.testmod(eq)
    assert result.attempted > 0 and result.failed == 0

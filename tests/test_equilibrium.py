import math
import re

import numpy as np
import pytest

from servofmu.physics import equilibrium as eq
from servofmu.physics.geometry import RaceGeometry


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

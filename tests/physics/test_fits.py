import re

import numpy as np
import pytest

from servofmu.parameters import catalog
from servofmu.physics.thermal.fits import (
    bore_change_under_external_pressure,
    fit_pressure,
    mounted_geometry,
    outside_change_under_internal_pressure,
)


def lame_u(r, r_a, r_b, p_a, p_b, mat):
    """Radial displacement of an annulus r_a..r_b under internal p_a and external p_b
    (plane stress Lamé solution, written independently of the module)."""
    e, nu = mat.youngs_modulus, mat.poisson_ratio
    return (
        (p_a * r_a**2 - p_b * r_b**2) * r * (1 - nu) + (p_a - p_b) * r_a**2 * r_b**2 * (1 + nu) / r
    ) / (e * (r_b**2 - r_a**2))


@pytest.fixture(scope="module")
def steel():
    return catalog.material("bearing_steel_yu")


@pytest.fixture(scope="module")
def alu():
    return catalog.material("cast_aluminium")


def test_fit_pressure_closes_the_interference(steel, alu):
    d, groove, boss, delta = 26e-3, 23.89e-3, 36e-3, 12e-6
    p = fit_pressure(delta, d, groove, boss, steel, alu)
    u_ring = lame_u(d / 2, groove / 2, d / 2, 0.0, p, steel)  # ring squeezed (external p)
    u_bore = lame_u(d / 2, d / 2, boss / 2, p, 0.0, alu)  # bore pushed out (internal p)
    assert u_bore - u_ring == pytest.approx(delta / 2, rel=1e-12)
    dg = bore_change_under_external_pressure(p, d, groove, steel)
    assert dg == pytest.approx(2 * lame_u(groove / 2, groove / 2, d / 2, 0.0, p, steel), rel=1e-12)


def test_inner_ring_raceway_expands(steel):
    p, bore, groove = 20e6, 17e-3, 19.1e-3
    grow = outside_change_under_internal_pressure(p, bore, groove, steel)
    assert grow == pytest.approx(2 * lame_u(groove / 2, bore / 2, groove / 2, p, 0.0, steel))
    assert grow > 0


def test_solid_shaft_in_large_plate_limit(steel, alu):
    # D → ∞ and solid shaft: p = δ / (d·((1 + ν_o)/E_o + (1 − ν_i)/E_i))
    d, delta = 20e-3, 10e-6
    p = fit_pressure(delta, d, 0.0, 1e3 * d, steel, alu)
    ref = delta / (
        d
        * (
            (1 + alu.poisson_ratio) / alu.youngs_modulus
            + (1 - steel.poisson_ratio) / steel.youngs_modulus
        )
    )
    assert p == pytest.approx(ref, rel=1e-5)


def test_lost_fit_gives_zero_pressure(steel, alu):
    assert fit_pressure(-3e-6, 26e-3, 23.9e-3, 36e-3, steel, alu) == 0.0


def test_yu_clearance_with_and_without_coupling(yu_pair):
    m = yu_pair.mounting
    t = np.array([233.15, 293.15, 333.15])
    free = mounted_geometry(yu_pair.bearing, m.fit, t, m.assembly_temperature, coupled=False)
    cpl = mounted_geometry(yu_pair.bearing, m.fit, t, m.assembly_temperature)
    # without coupling every steel part grows alike: Pd(T) = Pd0·(1 + α·ΔT)
    expected = yu_pair.bearing.clearance * (1 + 11.7e-6 * (t - 293.15))
    np.testing.assert_allclose(free.race.clearance, expected, rtol=1e-9)
    # with coupling the aluminium bore squeezes the ring harder as it cools
    assert np.all(np.diff(cpl.race.clearance) > 0)
    assert np.all(cpl.race.clearance < free.race.clearance)
    # interference: ring OD and bore (26 mm − 12 µm) each grow with their own α
    dt = t - 293.15
    np.testing.assert_allclose(
        cpl.outer_interference, 26e-3 * (1 + 11.7e-6 * dt) - (26e-3 - 12e-6) * (1 + 21.7e-6 * dt)
    )


def test_ning_fit_rates_follow_from_the_materials(ning_pair):
    # Ning §3.1: −0.05 and +0.07 µm/°C; (α_TC4 − α_9Cr18)·d with handbook α
    m = ning_pair.mounting
    t = np.array([213.15, 353.15])
    g = mounted_geometry(ning_pair.bearing, m.fit, t, m.assembly_temperature)
    inner = np.diff(g.inner_interference)[0] / 140 / 1e-6
    outer = np.diff(g.outer_interference)[0] / 140 / 1e-6
    assert inner == pytest.approx(-0.05, abs=0.005)
    assert outer == pytest.approx(0.07, abs=0.005)


def test_bad_input(steel, alu):
    with pytest.raises(ValueError, match=re.escape("inner_bore < interface_diameter")):
        fit_pressure(1e-6, 20e-3, 25e-3, 40e-3, steel, alu)
    with pytest.raises(ValueError, match=re.escape("interference = nan")):
        fit_pressure(float("nan"), 20e-3, 15e-3, 40e-3, steel, alu)

import math
import re

import numpy as np
import pytest
from scipy.optimize import brentq

from servofmu.physics import hertz

STEEL_ETA = 2 * (1 - 0.3**2) / 206.9e9  # Harris's steel–steel compliance [1/Pa]


@pytest.mark.parametrize("f_rho", [1e-3, 0.2, 0.6, 0.9, 0.93, 0.97, 0.995])
def test_ellipticity_solves_the_hertz_relation(f_rho):
    exact = brentq(
        lambda k: hertz.curvature_difference_of_ellipticity(k) - f_rho, 1 + 1e-12, 1e4, xtol=1e-14
    )
    assert hertz.ellipticity(f_rho) == pytest.approx(exact, rel=1e-8)


def test_circular_contact_is_hertz_sphere():
    # sphere of radius R on a flat: Σρ = 2/R, F(ρ) = 0 → a = (3QR/(4E*))^(1/3), δ = a²/R
    r, q = 5e-3, 100.0
    c = hertz.contact_constants(2 / r, 0.0, STEEL_ETA)
    a, b = c.semi_axes(q)
    a_hertz = (3 * q * r * STEEL_ETA / 4) ** (1 / 3)
    assert a == pytest.approx(a_hertz, rel=1e-9) and b == pytest.approx(a_hertz, rel=1e-9)
    assert c.deflection(q) == pytest.approx(a_hertz**2 / r, rel=1e-9)
    assert c.max_pressure(q) == pytest.approx(3 * q / (2 * math.pi * a_hertz**2), rel=1e-9)


@pytest.mark.parametrize("f_rho", [0.5, 0.8, 0.9, 0.95])
def test_harris_steel_constants(f_rho):
    # Harris & Kotzalas: a = 0.0236·a*·(Q/Σρ)^(1/3), δ = 2.79e-4·δ*·Q^(2/3)·Σρ^(1/3) [mm, N]
    rho_mm, q = 0.3, 250.0
    c = hertz.contact_constants(rho_mm * 1e3, f_rho, STEEL_ETA)
    k = c.ellipticity
    a_star = (2 * k**2 * c.e_integral / math.pi) ** (1 / 3)
    d_star = (2 * c.k_integral / math.pi) * (math.pi / (2 * k**2 * c.e_integral)) ** (1 / 3)
    a_mm = c.semi_axes(q)[0] * 1e3
    assert a_mm == pytest.approx(0.0236 * a_star * (q / rho_mm) ** (1 / 3), rel=2e-3)
    d_mm = c.deflection(q) * 1e3
    assert d_mm == pytest.approx(2.79e-4 * d_star * q ** (2 / 3) * rho_mm ** (1 / 3), rel=3e-3)


@pytest.mark.parametrize("ratio", [2.0, 5.0, 10.0, 20.0])
def test_hamrock_brewe_approximations(ratio):
    # Ry/Rx = ratio: F(ρ) = (ratio − 1)/(ratio + 1); Hamrock & Brewe (1983) k ≈ 1.0339·ratio^0.636,
    # E ≈ 1.0003 + 0.5968/ratio (within 3 % for these ratios; 3.7 % off at 60)
    f_rho = (ratio - 1) / (ratio + 1)
    c = hertz.contact_constants(1e3, f_rho, STEEL_ETA)
    assert c.ellipticity == pytest.approx(1.0339 * ratio**0.636, rel=0.03)
    assert c.e_integral == pytest.approx(1.0003 + 0.5968 / ratio, rel=0.01)


def test_curvature_from_radii_independently():
    dw, dm, f, alpha = 12.7e-3, 65e-3, 0.52, math.radians(10)
    r_roll_i = (dm / math.cos(alpha) - dw) / 2  # inner race radius in the rolling plane
    r_roll_o = (dm / math.cos(alpha) + dw) / 2
    inner = 4 / dw + 1 / r_roll_i - 1 / (f * dw)
    outer = 4 / dw - 1 / r_roll_o - 1 / (f * dw)
    s_i, f_i = hertz.curvature_sum_difference(dw, dm, f, alpha, "inner")
    s_o, f_o = hertz.curvature_sum_difference(dw, dm, f, alpha, "outer")
    assert s_i == pytest.approx(inner) and s_o == pytest.approx(outer)
    assert f_i == pytest.approx((1 / r_roll_i + 1 / (f * dw)) / inner)
    assert f_o == pytest.approx((-1 / r_roll_o + 1 / (f * dw)) / outer)


def test_series_stiffness_of_equal_contacts():
    assert hertz.combined_stiffness(8e9, 8e9) == pytest.approx(8e9 / 2**1.5)


def test_vectorised_and_scalar_agree():
    f = np.array([0.3, 0.9])
    np.testing.assert_allclose(hertz.ellipticity(f), [hertz.ellipticity(x) for x in f])


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: hertz.ellipticity(1.0), "curvature_difference = 1.0"),
        (lambda: hertz.ellipticity(-0.1), "curvature_difference = -0.1"),
        (lambda: hertz.curvature_sum_difference(1e-3, 2e-2, 0.5, 0.2, "inner"), "groove_curvature"),
        (
            lambda: hertz.curvature_sum_difference(1e-3, 2e-2, 0.52, 0.2, "middle"),
            "race = 'middle'",
        ),
        (lambda: hertz.contact_constants(-1.0, 0.5, 1e-11), "curvature_sum = -1.0"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=re.escape(match)):
        call()

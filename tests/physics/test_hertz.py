import math
import re

import numpy as np
import pytest
from scipy.optimize import brentq

from servofmu.physics.contact import hertz

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


def _johnson_ellipse(curvature_sum, curvature_difference, compliance, load):
    """Semi-axes a ≥ b [m] and approach δ [m] of a Hertz contact from Johnson's relations
    (Contact Mechanics, 1985, §3.5), solved numerically, without the closed forms under test:
    with the gap h = A·x² + B·y², p0 = 3Q/(2πab), e² = 1 − b²/a², 1/E* = η:
      A = (p0/E*)·(b/a²)·(K(e) − E(e))/e²,  B = (p0/E*)·(b/a²)·((a/b)²·E(e) − K(e))/e²,
      δ = (p0·b/E*)·K(e),
    and A + B = Σρ/2, B − A = F(ρ)·(A + B)."""
    from scipy.optimize import root
    from scipy.special import ellipe, ellipk

    big_a = 0.25 * curvature_sum * (1 - curvature_difference)
    big_b = 0.25 * curvature_sum * (1 + curvature_difference)

    def gaps(x):
        a, b = np.exp(x)
        m = 1 - (b / a) ** 2
        p0 = 3 * load / (2 * math.pi * a * b)
        c = p0 * compliance * b / a**2 / m
        return [
            c * (ellipk(m) - ellipe(m)) / big_a - 1,
            c * ((a / b) ** 2 * ellipe(m) - ellipk(m)) / big_b - 1,
        ]

    r0 = (3 * load * compliance / (2 * curvature_sum)) ** (1 / 3)  # circular contact
    sol = root(gaps, [math.log(2 * r0), math.log(0.5 * r0)], tol=1e-13)
    assert np.max(np.abs(gaps(sol.x))) < 1e-10, sol.message
    a, b = np.exp(sol.x)
    p0 = 3 * load / (2 * math.pi * a * b)
    return a, b, p0 * b * compliance * ellipk(1 - (b / a) ** 2)


@pytest.mark.parametrize("f_rho", [0.3, 0.7, 0.9, 0.95])
def test_semi_axes_and_approach_solve_johnsons_relations(f_rho):
    # an elongated ellipse (k from 1.6 to 11), where b = a/k: the semi-minor axis is checked
    # for k ≠ 1 against the Hertz relations themselves
    rho, q = 400.0, 80.0
    c = hertz.contact_constants(rho, f_rho, STEEL_ETA)
    a_ref, b_ref, delta_ref = _johnson_ellipse(rho, f_rho, STEEL_ETA, q)
    a, b = c.semi_axes(q)
    assert a == pytest.approx(a_ref, rel=1e-7)
    assert b == pytest.approx(b_ref, rel=1e-7)
    assert c.deflection(q) == pytest.approx(delta_ref, rel=1e-7)
    assert c.max_pressure(q) == pytest.approx(3 * q / (2 * math.pi * a_ref * b_ref), rel=1e-6)


@pytest.mark.parametrize("ratio", [2.0, 5.0, 10.0, 20.0])
def test_semi_minor_axis_matches_hamrock_brewe(ratio):
    # Hamrock & Brewe (1983), J. Lubr. Technol. 105:171–177: with α = Ry/Rx, 1/R = Σρ,
    # E' = 2/η: b = (6·Ē·Q·R/(π·k̄·E'))^(1/3), k̄ = 1.0339·α^0.636, Ē = 1.0003 + 0.5968/α
    # (their fits are within 3 % in k and 1 % in E for these ratios: 2 % in b, 1.5 % in a)
    f_rho = (ratio - 1) / (ratio + 1)
    rho, q = 1e3, 50.0
    k_hb, e_hb = 1.0339 * ratio**0.636, 1.0003 + 0.5968 / ratio
    e_prime = 2 / STEEL_ETA
    b_hb = (6 * e_hb * q / (rho * math.pi * k_hb * e_prime)) ** (1 / 3)
    a_hb = (6 * k_hb**2 * e_hb * q / (rho * math.pi * e_prime)) ** (1 / 3)
    a, b = hertz.contact_constants(rho, f_rho, STEEL_ETA).semi_axes(q)
    assert b == pytest.approx(b_hb, rel=0.02)
    assert a == pytest.approx(a_hb, rel=0.025)


def test_the_scalar_ellipticity_equals_the_interpolated_one():
    """One float takes Newton's method from Hamrock & Brewe's approximation (the per-step
    path), an array the interpolant and its polish: the same k to rounding over the range of
    ball–groove contacts."""
    import numpy as np

    from servofmu.physics.contact.hertz import ellipticity

    f = np.linspace(0.002, 0.9998, 4001)
    scalar = np.array([ellipticity(float(x)) for x in f])
    assert np.allclose(scalar, ellipticity(f), rtol=1e-12, atol=0.0)
    assert ellipticity(0.0) == 1.0 and isinstance(ellipticity(0.9), float)

"""Per-contact hydrodynamic rolling force (Biboulet & Houpert 2010 eq 32) against its own
asymptotes, against the independent simplified parameterisation Bălan et al. (2015, eq 1–4)
print, and the bearing torque against the rig equation of Bălan et al. (eq 14)."""

import doctest
import math

import numpy as np
import pytest

from servofmu.physics.contact.hertz import contact_constants
from servofmu.physics.friction import ehl_per_contact as er

E = 2.3e11  # E' of steel on steel, Bălan et al. 2015 §1


def test_doctests_pass():
    assert doctest.testmod(er).failed == 0


def test_rolling_radii_give_balan_k_ratio():
    # Bălan et al. 2015 §4.5: 7.938 mm balls on 4.16 mm grooves, conformity 0.524, k = 21.78
    rx, rz = er.rolling_radii(0.036, 0.007938, math.pi / 2, 0.00416, "inner")
    assert rx == pytest.approx(0.007938 / 2)
    assert rz / rx == pytest.approx(21.78, abs=0.005)
    # angular contact: Rx = Dw(1 ∓ γ)/2 with γ = Dw cos α/dm (Harris & Kotzalas ch. 2)
    dw, dm, a = 2.381e-3, 21.5e-3, math.radians(15)
    g = dw * math.cos(a) / dm
    assert er.rolling_radii(dm, dw, a, 0.56 * dw, "inner")[0] == pytest.approx(dw * (1 - g) / 2)
    assert er.rolling_radii(dm, dw, a, 0.54 * dw, "outer")[0] == pytest.approx(dw * (1 + g) / 2)


def _hertz(q, rx, rz):
    rho = 1 / rx + 1 / rz
    c = contact_constants(rho, (1 / rx - 1 / rz) / rho, 2 / E)
    a = c.semi_axes(q)[0]
    kappa = 1 / c.ellipticity
    beta = 4 / math.pi * c.e_integral / (1 + rx / rz)
    return a, kappa, beta


@pytest.mark.parametrize("d", [3e-3, 6.35e-3])
def test_force_reaches_its_ivr_and_ehl_asymptotes(d):
    rx, rz = d / 2, d / 2 * 4.16e-3 / (4.16e-3 - d / 2)
    q = 0.4
    a, kappa, beta = _hertz(q, rx, rz)
    w = q / (E * rx**2)
    # M = β^(1/4)·κ·W/U^(3/4) ≫ 6.6: EHL asymptote 1.8·β^(−1/4)·(2a/Rx)·U^(3/4)
    u_slow = 1e-7
    big_u = 2 * 0.05 * u_slow / (E * rx)
    m = beta**0.25 * kappa * w / big_u**0.75
    assert m > 1e4
    ehl = 1.8 * beta**-0.25 * (2 * a / rx) * big_u**0.75 * E * rx**2
    got = er.hydrodynamic_rolling_force(q, u_slow, 0.05, rx, rz, E)
    assert got == pytest.approx(ehl, rel=0.02)  # the IVR remainder is /(1 + M/6.6)
    # M ≪ 6.6: IVR asymptote 0.77·β^(−1/3)·κ^0.12·(2a/Rx)·U^(2/3)
    u_fast = 1e6  # unphysical on purpose: the asymptote, not a bearing
    big_u = 2 * 0.05 * u_fast / (E * rx)
    assert beta**0.25 * kappa * w / big_u**0.75 < 1e-2
    ivr = 0.77 * beta ** (-1 / 3) * kappa**0.12 * (2 * a / rx) * big_u ** (2 / 3) * E * rx**2
    got = er.hydrodynamic_rolling_force(q, u_fast, 0.05, rx, rz, E)
    assert got == pytest.approx(ivr, rel=0.01)


def _balan_simplified(q, u, eta, rx, rz):
    """Bălan et al. 2015 eq 1–4 with their U = η·v/(E*·Rx), v the mean speed."""
    k = rz / rx
    big_u = eta * u / (E * rx)
    big_w = q / (E * rx**2)
    ivr = 2.9766 * E * rx**2 * k**0.3316 * big_w ** (1 / 3) * big_u ** (2 / 3)
    ehl = 7.5826 * E * rx**2 * k**0.4055 * big_w ** (1 / 3) * big_u**0.75
    m = 0.5549 * k**-0.6029 * big_w * big_u**-0.75
    return (ivr - ehl) / (1 + m / 6.6) + ehl


@pytest.mark.parametrize("d, q", [(3e-3, 0.633), (3.97e-3, 0.4), (6.35e-3, 0.125), (7.938e-3, 0.4)])
@pytest.mark.parametrize("u", [0.02, 0.06, 0.2])
def test_agrees_with_balan_simplified_fit(d, q, u):
    rx, rz = d / 2, d / 2 * 4.16e-3 / (4.16e-3 - d / 2)
    got = er.hydrodynamic_rolling_force(q, u, 0.05, rx, rz, E)
    assert got == pytest.approx(_balan_simplified(q, u, 0.05, rx, rz), rel=0.12)


def test_rig_torque_is_balan_eq14_and_power_balance_holds():
    r, d, q, w = 0.018, 3e-3, 0.633, 2 * math.pi
    rx, rz = er.rolling_radii(2 * r, d, math.pi / 2, 4.16e-3, "inner")
    fr = er.hydrodynamic_rolling_force(q, w * r / 2, 0.05, rx, rz, E)
    loads = np.full(3, q)
    m = er.ehl_rolling_torque(
        loads, loads, np.full(3, math.pi / 2), 2 * r, d, 4.16e-3, 4.16e-3, 0.05, w, E
    )
    assert m == pytest.approx(6 * r * fr, rel=1e-12)
    # angular contact: torque × ω = Σ 2·F_R·u_m over both contacts of every ball
    dm, dw, a = 21.5e-3, 2.381e-3, np.full(10, math.radians(20))
    qi, qo = np.linspace(5, 15, 10), np.linspace(6, 16, 10)
    w = 10.0
    m = er.ehl_rolling_torque(qi, qo, a, dm, dw, 0.56 * dw, 0.54 * dw, 0.3, w, E)
    u = er.entrainment_speed(dm, dw, a, w)
    power = 0.0
    for q_, f, race in ((qi, 0.56, "inner"), (qo, 0.54, "outer")):
        rx, rz = er.rolling_radii(dm, dw, a, f * dw, race)
        power += np.sum(2 * er.hydrodynamic_rolling_force(q_, u, 0.3, rx, rz, E) * u)
    assert m * w == pytest.approx(power, rel=1e-12)
    # batched over temperatures: shape S + (Z,)
    mb = er.ehl_rolling_torque(
        np.stack([qi, qi]), np.stack([qo, qo]), np.stack([a, a]), dm, dw, 0.56 * dw, 0.54 * dw,
        np.array([[0.3], [0.3]]), w, E,
    )  # fmt: skip
    assert mb.shape == (2,)
    assert mb[0] == pytest.approx(
        er.ehl_rolling_torque(qi, qo, a, dm, dw, 0.56 * dw, 0.54 * dw, 0.3, w, E)
    )


def test_no_load_or_no_speed_no_force():
    assert er.hydrodynamic_rolling_force(0.0, 0.1, 0.05, 1e-3, 5e-3, E) == 0.0
    assert er.hydrodynamic_rolling_force(1.0, 0.0, 0.05, 1e-3, 5e-3, E) == 0.0
    q = np.full(3, 1.0)
    a = np.full(3, 1.0)
    assert er.ehl_rolling_torque(q, q, a, 0.03, 3e-3, 1.6e-3, 1.6e-3, 0.05, 0.0, E) == 0.0


def test_bad_input_names_the_variable():
    with pytest.raises(ValueError, match="transverse_radius"):
        er.hydrodynamic_rolling_force(1.0, 0.1, 0.05, 5e-3, 1e-3, E)
    with pytest.raises(ValueError, match="groove_radius"):
        er.rolling_radii(0.03, 3e-3, 0.3, 1.4e-3, "inner")
    with pytest.raises(ValueError, match="race"):
        er.rolling_radii(0.03, 3e-3, 0.3, 1.6e-3, "middle")
    with pytest.raises(ValueError, match="dynamic_viscosity"):
        er.hydrodynamic_rolling_force(1.0, 0.1, -0.05, 1e-3, 5e-3, E)
    with pytest.raises(ValueError, match="density"):
        er.dynamic_viscosity(1e-4, 1e5)

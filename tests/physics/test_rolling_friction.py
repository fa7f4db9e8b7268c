"""The SKF (2004) friction model against hand computations in the catalogue's own units
(mm, N, r/min, mm²/s, N·mm), written here independently of the module's SI code path."""

import doctest
import math

import numpy as np
import pytest

from servofmu.parameters import catalog
from servofmu.physics.friction import skf2004 as rf
from servofmu.physics.kernels.units import RPM

# 6204 (d = 20, D = 47 mm) with the series-62 constants; 7205 (25 × 52) with 72 B's.
D62 = dict(r1=3.9e-7, r2=1.7, s1=3.23e-3, s2=36.5, kz=3.1)
C62 = rf.SkfConstants("62", "deep_groove", **D62)
C72 = rf.SkfConstants(
    "72B", "angular_contact", r1=5.03e-7, r2=1.97, r3=1.90e-12, s1=1.30e-2, s2=0.68,
    s3=1.91e-12, kz=4.4,
)  # fmt: skip


def rpm(n):
    return n * RPM


def test_doctests_pass():
    assert doctest.testmod(rf).failed == 0


@pytest.mark.parametrize("n, nu", [(10.0, 20.0), (3000.0, 20.0), (1000.0, 300.0)])
def test_reduction_and_weighting_factors_by_hand(n, nu):
    d, big_d = 20.0, 47.0
    dm = 0.5 * (d + big_d)
    phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = 1.0 / math.e ** (6e-8 * nu * n * (d + big_d) * math.sqrt(3.1 / (2 * (big_d - d))))
    phi_bl = 1.0 / math.e ** (2.6e-8 * (n * nu) ** 1.4 * dm)
    w, nu_si = rpm(n), nu * 1e-6
    assert rf.inlet_shear_factor(nu_si, w, dm * 1e-3) == pytest.approx(phi_ish, rel=1e-12)
    assert rf.replenishment_factor(nu_si, w, 0.020, 0.047, 3.1, 6e-8) == pytest.approx(
        phi_rs, rel=1e-12
    )
    assert rf.boundary_weighting(nu_si, w, dm * 1e-3) == pytest.approx(phi_bl, rel=1e-12)
    mu = rf.sliding_friction_coefficient(phi_bl, 0.15, 0.05)
    assert mu == pytest.approx(phi_bl * 0.15 + (1 - phi_bl) * 0.05)


def test_factors_at_rest_and_sign():
    assert rf.inlet_shear_factor(20e-6, 0.0, 0.0335) == 1.0
    assert rf.replenishment_factor(20e-6, 0.0, 0.020, 0.047, 3.1, 6e-8) == 1.0
    assert rf.boundary_weighting(20e-6, 0.0, 0.0335) == 1.0
    w = rpm(500.0)
    assert rf.inlet_shear_factor(20e-6, -w, 0.0335) == rf.inlet_shear_factor(20e-6, w, 0.0335)


def test_deep_groove_radial_moments_by_hand():
    n, nu, fr = 1000.0, 20.0, 1000.0
    dm = 33.5
    grr = 3.9e-7 * dm**1.96 * fr**0.54
    gsl = 3.23e-3 * dm**-0.26 * fr ** (5 / 3)
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mrr = grr * (nu * n) ** 0.6
    msl = gsl * (phi_bl * 0.15 + (1 - phi_bl) * 0.05)
    args = (C62, 0.020, 0.047, fr, 0.0, nu * 1e-6, rpm(n))
    assert rf.rolling_torque(*args) == pytest.approx(mrr * 1e-3, rel=1e-12)
    assert rf.sliding_torque(*args) == pytest.approx(msl * 1e-3, rel=1e-12)


def test_deep_groove_axial_load_uses_alpha_f():
    n, nu, fr, fa, c0 = 1500.0, 30.0, 200.0, 300.0, 6550.0
    dm = 33.5
    alpha_f = math.radians(24.6 * (fa / c0) ** 0.24)
    grr = 3.9e-7 * dm**1.96 * (fr + 1.7 / math.sin(alpha_f) * fa) ** 0.54
    gsl = 3.23e-3 * dm**-0.145 * (fr**5 + 36.5 * dm**1.5 / math.sin(alpha_f) * fa**4) ** (1 / 3)
    args = (C62, 0.020, 0.047, fr, fa, nu * 1e-6, rpm(n))
    assert rf.rolling_torque(*args, static_load_rating=c0) == pytest.approx(
        grr * (nu * n) ** 0.6 * 1e-3, rel=1e-12
    )
    assert rf.sliding_torque(*args, 0.15, 0.05, static_load_rating=c0) / 1e-3 / gsl == (
        pytest.approx(
            rf.sliding_friction_coefficient(rf.boundary_weighting(nu * 1e-6, rpm(n), 0.0335))
        )
    )
    with pytest.raises(ValueError, match="static_load_rating"):
        rf.rolling_torque(*args)


def test_angular_contact_moments_with_centrifugal_term_by_hand():
    n, nu, fr, fa = 6000.0, 10.0, 100.0, 500.0
    dm = 0.5 * (25.0 + 52.0)
    fg_r = 1.90e-12 * dm**4 * n**2
    fg_s = 1.91e-12 * dm**4 * n**2
    grr = 5.03e-7 * dm**1.97 * (fr + fg_r + 1.97 * fa) ** 0.54
    gsl = 1.30e-2 * dm**0.26 * ((fr + fg_s) ** (4 / 3) + 0.68 * fa ** (4 / 3))
    args = (C72, 0.025, 0.052, fr, fa, nu * 1e-6, rpm(n))
    assert rf.rolling_torque(*args) == pytest.approx(grr * (nu * n) ** 0.6 * 1e-3, rel=1e-12)
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu = phi_bl * 0.15 + (1 - phi_bl) * 0.04
    assert rf.sliding_torque(*args, 0.15, 0.04) == pytest.approx(gsl * mu * 1e-3, rel=1e-12)


def test_total_and_starting_torque_compose_as_the_catalogue_says():
    n, nu = 2000.0, 15.0
    args = (C72, 0.025, 0.052, 50.0, 300.0, nu * 1e-6, rpm(n))
    t = rf.skf_friction(*args, lubrication="oil_bath", seal=1e-3, drag=2e-4)
    dm = 38.5
    phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = math.exp(-3e-8 * nu * n * 77.0 * math.sqrt(4.4 / (2 * 27.0)))
    assert t.phi_ish == pytest.approx(phi_ish, rel=1e-12)
    assert t.phi_rs == pytest.approx(phi_rs, rel=1e-12)
    assert t.total == pytest.approx(
        phi_ish * phi_rs * rf.rolling_torque(*args) + rf.sliding_torque(*args) + 1e-3 + 2e-4
    )
    # starting: Msl with φbl = 1 (μsl = μbl) and no centrifugal term, plus the seals
    dm_ = 38.5
    gsl0 = 1.30e-2 * dm_**0.26 * (50.0 ** (4 / 3) + 0.68 * 300.0 ** (4 / 3))
    assert t.starting == pytest.approx(gsl0 * 0.15 * 1e-3 + 1e-3, rel=1e-12)
    # at rest the running moment is the starting moment without the seal's share
    rest = rf.skf_friction(*args[:-1], 0.0, lubrication="grease")
    assert rest.total == pytest.approx(rest.starting)


def test_seal_and_drag_by_hand():
    assert rf.seal_torque(0.025, 0.028, 2.0, 2.25) == pytest.approx(
        (0.028 * 25.0**2.25 + 2.0) * 1e-3, rel=1e-12
    )
    n, nu, h, vm = 3000.0, 20.0, 5.0, 3e-4
    d, big_d = 20.0, 47.0
    dm = 33.5
    k_ball = 3.1 * (d + big_d) / (big_d - d) * 1e-12
    f_a = 0.05 * 3.1 * (big_d + d) / (big_d - d)
    t = 2 * math.acos((0.6 * dm - h) / (0.6 * dm))
    f_t = math.sin(0.5 * t)
    r_s = 0.36 * dm**2 * (t - math.sin(t)) * f_a
    m = (
        0.4 * vm * k_ball * dm**5 * n**2
        + 1.093e-7 * n**2 * dm**3 * (n * dm**2 * f_t / nu) ** -1.379 * r_s
    )
    got = rf.oil_bath_drag_torque(vm, h * 1e-3, 0.020, 0.047, nu * 1e-6, rpm(n), 3.1)
    assert got == pytest.approx(m * 1e-3, rel=1e-12)
    # submerged beyond 1.2·dm: t = 2π, ft = 1
    deep = rf.oil_bath_drag_torque(vm, 0.05, 0.020, 0.047, nu * 1e-6, rpm(n), 3.1)
    r_s2 = 0.36 * dm**2 * 2 * math.pi * f_a
    m2 = (
        0.4 * vm * k_ball * dm**5 * n**2
        + 1.093e-7 * n**2 * dm**3 * (n * dm**2 / nu) ** -1.379 * r_s2
    )
    assert deep == pytest.approx(m2 * 1e-3, rel=1e-12)
    assert rf.oil_bath_drag_torque(vm, h * 1e-3, 0.020, 0.047, nu * 1e-6, 0.0, 3.1) == 0.0


def test_vectorised_over_temperature_like_inputs():
    nu = np.array([10e-6, 100e-6, 1000e-6])
    t = rf.skf_friction(C72, 0.025, 0.052, 0.0, 100.0, nu, rpm(100.0))
    assert t.total.shape == (3,)
    one = rf.skf_friction(C72, 0.025, 0.052, 0.0, 100.0, 100e-6, rpm(100.0))
    assert t.total[1] == pytest.approx(one.total)


def test_bearing_loads_from_balls():
    z = 12
    alpha = np.deg2rad(25.0)
    q = np.full(z, 10.0)
    fa, fr = rf.bearing_loads(q, np.full(z, alpha))
    assert fa == pytest.approx(z * 10.0 * math.sin(alpha))
    assert fr == pytest.approx(0.0, abs=1e-12)
    # a single loaded ball at ψ = 0 carries Fr = Q cos α
    q1 = np.zeros(z)
    q1[0] = 7.0
    fr1 = rf.bearing_loads(q1, np.full(z, alpha))[1]
    assert fr1 == pytest.approx(7.0 * math.cos(alpha))
    # batched: shape S + (Z,)
    fa2, _ = rf.bearing_loads(np.stack([q, q1]), np.full((2, z), alpha))
    assert fa2.shape == (2,)


def test_bad_input_names_the_variable():
    with pytest.raises(ValueError, match=r"radial_load = -1\.0"):
        rf.rolling_torque(C62, 0.020, 0.047, -1.0, 0.0, 20e-6, 1.0)
    with pytest.raises(ValueError, match="outer_diameter"):
        rf.mean_diameter(0.047, 0.020)
    with pytest.raises(ValueError, match="lubrication"):
        rf.skf_friction(C62, 0.020, 0.047, 10.0, 0.0, 20e-6, 1.0, lubrication="oil_mist")
    with pytest.raises(ValueError, match="kinematic_viscosity"):
        rf.inlet_shear_factor(float("nan"), 1.0, 0.03)
    with pytest.raises(ValueError, match="bearing_type"):
        rf.SkfConstants("x", "tapered", r1=1, r2=1, s1=1, s2=1, kz=1)
    with pytest.raises(ValueError, match="'99' is not one of"):
        rf.skf_constants("99")


def test_catalogue_constants_load_with_provenance():
    for key in catalog.keys("skf_friction"):
        c = rf.skf_constants(key)
        for _, source in c.provenance:
            assert source.split(":")[0] in catalog.PROVENANCE_KINDS
        assert c.source("r1")
    c62 = rf.skf_constants("62")
    assert (c62.r1, c62.r2, c62.s1, c62.s2, c62.kz) == (3.9e-7, 1.7, 3.23e-3, 36.5, 3.1)
    assert rf.skf_constants("72B").bearing_type == "angular_contact"

"""The cold-grease torque term: calibration on one datasheet point, the Palmgren scaling it
carries, and the test-standard records."""

import doctest
import math

import pytest

from servofmu.parameters import catalog
from servofmu.physics.friction import grease as gt
from servofmu.physics.kernels.units import RPM

W1 = 1.0 * RPM  # 1 r/min


def test_doctests_pass():
    assert doctest.testmod(gt).failed == 0


def test_grease_factor_inverts_palmgren_by_hand():
    # M0 = 1e-7·f0·(ν·n)^(2/3)·dm³ N·mm, ν mm²/s, n r/min, dm mm (Palmgren; Yu 2017 eq 8)
    nu, dm, m_run = 8000.0, 33.5, 0.050
    f0 = m_run / (1e-7 * (nu * 1.0) ** (2 / 3) * dm**3 * 1e-3)
    assert gt.grease_factor(m_run, nu * 1e-6, W1, dm * 1e-3) == pytest.approx(f0, rel=1e-12)


def test_term_scales_as_palmgren_and_keeps_the_starting_ratio():
    nu, dm = 8000e-6, 0.0335
    t = gt.calibrate_grease_term(0.099, 0.050, nu, W1, dm)
    assert t.running(nu, W1, dm) == pytest.approx(0.050, rel=1e-12)
    assert t.starting(nu, dm) == pytest.approx(0.099, rel=1e-12)
    # dm³ and (ν·n)^(2/3) while ν·n ≥ 2000 mm²/s·r/min
    assert t.running(nu, W1, 2 * dm) == pytest.approx(8 * 0.050, rel=1e-12)
    assert t.running(4 * nu, W1, dm) == pytest.approx(4 ** (2 / 3) * 0.050, rel=1e-12)
    assert t.running(nu, 8 * W1, dm) == pytest.approx(4 * 0.050, rel=1e-12)
    # the starting torque follows the running torque at the test's speed, not the user's
    assert t.starting(4 * nu, 2 * dm) / t.running(4 * nu, W1, 2 * dm) == pytest.approx(1.98)
    # below ν·n = 2000 Palmgren's torque is speed-independent
    low = 1000e-6
    assert t.running(low, W1, dm) == pytest.approx(t.running(low, 0.5 * W1, dm))


def test_astm_d1478_record():
    t = gt.torque_test("astm_d1478")
    assert (t.bore, t.outer_diameter) == (pytest.approx(0.020), pytest.approx(0.047))
    assert t.speed_rpm == pytest.approx(1.0)
    assert t.radial_load == pytest.approx(0.454 * 9.80665)
    assert t.source("speed").startswith("handbook: ASTM D1478 §4.1")
    jis = gt.torque_test("jis_k2220")
    assert (jis.bore, jis.outer_diameter, jis.speed_rpm) == (
        pytest.approx(0.020),
        pytest.approx(0.047),
        pytest.approx(1.0),
    )
    # bearing and speed as described by JALOS; the housing load is still ASTM's, assumed
    assert jis.source("bore").startswith("handbook: JALOS Q&A ID-207")
    assert jis.source("speed").startswith("handbook: JALOS")
    assert jis.source("housing_mass").startswith("assumed")
    # the two tests read the running torque after different times
    assert "10 min" in catalog._table("grease_torques")["tests"]["jis_k2220"]["torques"]
    with pytest.raises(ValueError, match="'astm_d9999' is not one of"):
        gt.torque_test("astm_d9999")


def test_datasheet_point_and_base_oil():
    (p,) = gt.grease_torque_points("molykote_g1074")
    assert p.temperature == pytest.approx(233.15)
    assert (p.starting_torque, p.running_torque) == (pytest.approx(0.099), pytest.approx(0.050))
    assert "80-8136B-01" in p.source("running_torque") or "same TDS" in p.source("running_torque")
    nu = gt.base_oil_viscosity("molykote_g1074")  # its lubricants.toml entry
    assert float(nu.kinematic_viscosity(373.15)) == pytest.approx(8.5e-6, rel=1e-9)
    assert gt.grease_torque_points("no_such_grease") == []
    with pytest.raises(ValueError, match="base-oil"):
        gt.base_oil_viscosity("no_such_grease")
    with pytest.raises(ValueError, match="dry film"):
        gt.base_oil_viscosity("mos2_film")


def test_every_grease_with_torque_points_is_a_catalogue_lubricant():
    # its base oil's viscosity (the term's ν(T)) has one place: data/lubricants.toml
    greases = catalog._table("grease_torques")["greases"]
    assert set(greases) <= set(catalog.keys("lubricants"))


def test_the_lubricant_term_is_the_fit_on_its_points_by_hand():
    """One JIS K 2220 point of G-1074 at −40 °C: f0 = M_run/M0(f0 = 1) with Palmgren's M0 at
    the base oil's ν(−40 °C) (ASTM D341 through 53 and 8.5 cSt), 1 r/min and dm = 33.5 mm;
    ks = 99/50. Both calibrated: the term reproduces the point exactly."""
    assert len(gt.grease_torque_points("molykote_g1074")) == 1
    nu = float(gt.base_oil_viscosity("molykote_g1074").kinematic_viscosity(233.15)) / 1e-6
    m0 = 1e-7 * (nu * 1.0) ** (2 / 3) * 33.5**3 * 1e-3  # N·m at f0 = 1
    t = gt.lubricant_term("molykote_g1074")
    assert t.f0 == pytest.approx(0.050 / m0, rel=1e-12)
    assert t.starting_ratio == pytest.approx(99 / 50, rel=1e-12)
    assert t.reference_speed == pytest.approx(W1)
    assert dict(t.provenance)["starting_ratio"].startswith("calibrated:")
    assert gt.lubricant_term("krytox_143aa") is None


def test_every_data_value_has_provenance():
    def walk(node):
        if isinstance(node, dict):
            if "value" in node:
                yield node
            else:
                for v in node.values():
                    yield from walk(v)
        elif isinstance(node, list):
            for v in node:
                yield from walk(v)

    from servofmu.papers.validation import _measurements

    tables = {"grease_torques": catalog._table("grease_torques"),
              "friction_measurements": _measurements(),
              "skf_friction": catalog._table("skf_friction")}  # fmt: skip
    for table, data in tables.items():
        entries = list(walk(data))
        assert entries, table
        for e in entries:
            value, _ = catalog.quantity(e, table)
            assert math.isfinite(value)


def test_bad_input_names_the_variable():
    with pytest.raises(ValueError, match="running_torque"):
        gt.grease_factor(-1.0, 1e-3, W1, 0.03)
    with pytest.raises(ValueError, match="starting_ratio"):
        gt.GreaseTorqueTerm(f0=1.0, starting_ratio=-1.0, reference_speed=W1)
    with pytest.raises(ValueError, match="f0 > 0 or starting_ratio > 0"):
        gt.GreaseTorqueTerm(f0=0.0, starting_ratio=0.0, reference_speed=W1)

"""The selectable friction models of a bearing pair (physics/friction/models.py) and the
grease term, against independent references: the SKF catalogue's formulas by hand (catalogue
units) and the public single-bearing SKF function per bearing of the pair; Biboulet &
Houpert's force of each contact recomputed from its own Hertz ellipse (hertz through
ehl_rolling.hydrodynamic_rolling_force); the grease datasheet's own numbers on its test
bearing; the FMU round trip. (Both solver paths agree per model:
tests/physics/test_continuation.py.)"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from servofmu.calibration.datasheet import calibrate_datasheet
from servofmu.cli import main
from servofmu.parameters import catalog
from servofmu.parameters.bearing import (
    default_parameters,
    default_sources,
    pair_from_parameters,
    parameter_problems,
)
from servofmu.physics.bearing import BearingModel, BearingPair, load_state, thermal_state
from servofmu.physics.contact.equilibrium import axial_state
from servofmu.physics.friction import skf2004 as rf
from servofmu.physics.friction.ehl_per_contact import (
    entrainment_speed,
    hydrodynamic_rolling_force,
    rolling_radii,
)
from servofmu.physics.friction.grease import GreaseTorqueTerm
from servofmu.physics.friction.skf2004 import skf_loads
from servofmu.physics.kernels.units import RPM

T_COLD, W = 233.15, math.radians(10.0)  # −40 °C, Yu's assumed 10 °/s


def _pair(model, mounting="yu2017_gimbal", lubricant="krytox_143aa"):
    return BearingPair.from_catalog(mounting, lubricant, friction_model=model)


# ---------------------------------------------------------------------------- SKF 2004
def test_skf_pair_by_hand_in_catalogue_units():
    # 71803 (d = 17, D = 26 mm) with the 72 B constants of the fallback, Fa = 30 and 10 N,
    # Fr = 5 N each, n = 100 r/min, ν = 500 mm²/s; every number typed from SKF 10000 EN
    d, big_d, fa_a, fa_b, fr, n, nu = 17.0, 26.0, 30.0, 10.0, 5.0, 100.0, 500.0
    dm = 21.5
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = math.exp(-6e-8 * nu * n * (d + big_d) * math.sqrt(4.4 / (2 * (big_d - d))))
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * 0.15 + (1 - phi_bl) * 0.04
    fg = dm**4 * n**2

    def grr(fa):
        return 5.03e-7 * dm**1.97 * (fr + 1.90e-12 * fg + 1.97 * fa) ** 0.54

    def gsl(fa, centrifugal=True):
        radial = fr + (1.91e-12 * fg if centrifugal else 0.0)
        return 1.30e-2 * dm**0.26 * (radial ** (4 / 3) + 0.68 * fa ** (4 / 3))

    rolling = phi_ish * phi_rs * (grr(fa_a) + grr(fa_b)) * (nu * n) ** 0.6  # N·mm
    sliding = mu_sl * (gsl(fa_a) + gsl(fa_b))
    starting = 0.15 * (gsl(fa_a, False) + gsl(fa_b, False))
    got = rf.pair_moments(
        rf.skf_constants("72B"), 0.017, 0.026, (fa_a, fa_b), fr, nu * 1e-6, n * RPM,
        mu_ehl=0.04,
    )  # fmt: skip
    assert got == pytest.approx((rolling * 1e-3, sliding * 1e-3, starting * 1e-3), rel=1e-12)


@pytest.mark.parametrize("radial", [0.0, 8.0])
def test_skf_model_is_each_bearing_under_its_own_loads(radial):
    # the pair's outputs are the single-bearing SKF model (public, checked) evaluated for A and
    # B with the axial forces of the equilibrium and F_r/2 each, then added
    pair = _pair("skf2004")
    out = BearingModel(pair).evaluate(T_COLD, W, 3.0, radial)
    c = pair.friction.skf
    terms = [
        rf.skf_friction(
            c,
            0.017,
            0.026,
            radial / 2,
            fa,
            out.kinematic_viscosity,
            W,
            lubrication="grease",
            mu_ehl=0.04,
        )
        for fa in (out.force_a, out.force_b)
    ]
    assert out.viscous_torque == pytest.approx(sum(t.rolling_reduced for t in terms), rel=1e-12)
    assert out.sliding_torque == pytest.approx(sum(t.sliding for t in terms), rel=1e-12)
    assert out.breakaway_torque == pytest.approx(sum(t.starting for t in terms), rel=1e-12)
    assert out.running_torque == pytest.approx(sum(t.total for t in terms), rel=1e-12)
    assert out.hysteresis_torque == out.spin_torque == 0.0


def test_skf_loads_count_a_pulling_bearing_as_unloaded():
    assert skf_loads(5.0, -0.1, -6.0) == (5.0, 0.0, 3.0)
    fa, fb, fr = skf_loads(np.array([1.0, -2.0]), np.array([0.5, 0.0]), 4.0)
    assert fa.tolist() == [1.0, 0.0] and fb.tolist() == [0.5, 0.0] and fr == 2.0


def test_skf_constants_of_the_series_or_a_labelled_fallback():
    src = default_sources()
    for name in ("skf_r1", "skf_s2", "skf_kz"):  # the 71803: series 718 not in the table
        assert src[name].startswith("fallback (assumed)") and "71803" in src[name]
    c = rf.series_constants("7205B", math.radians(40.0))  # a 72 B bearing: the catalogue's
    assert c.key == "72B" and c.source("r1").startswith("catalogue:")
    # a 15° bearing of series 72 is not the 40° series: fallback
    assert rf.series_constants("7204C", math.radians(15.0)).source("r1").startswith("fallback")


# ------------------------------------------------------------------ EHL per contact
def _ehl_by_hand(pair, temperature, speed, axial):
    """Σ over both bearings' balls of Biboulet & Houpert's force of each contact (its own
    Hertz ellipse from Rx, Rz and E') times dm·(1 − γ²)/2, from the exact equilibrium."""
    th = thermal_state(pair, temperature)
    ls = load_state(pair, th, axial)
    g = th.geometry
    dw, dm = float(g.ball_diameter), float(g.pitch_diameter)
    eta = float(th.kinematic_viscosity) * pair.friction.lubricant_density
    total = 0.0
    for offset in (ls.offset_a, ls.offset_b):
        s = axial_state(g, float(offset))
        q, alpha = float(s.ball_load), float(s.contact_angle)
        if q <= 0.0:
            continue
        u = entrainment_speed(dm, dw, alpha, speed)
        for race, r in (("inner", g.inner_groove_radius), ("outer", g.outer_groove_radius)):
            rx, rz = rolling_radii(dm, dw, alpha, float(r), race)
            f = hydrodynamic_rolling_force(q, u, eta, rx, rz, 2.0 / g.compliance)
            gamma = dw * math.cos(alpha) / dm
            total += g.n_balls * f * 0.5 * dm * (1.0 - gamma**2)
    return total


@pytest.mark.parametrize("temperature, axial", [(T_COLD, 0.0), (293.15, 12.0), (333.15, -5.0)])
def test_ehl_model_sums_each_contacts_force(temperature, axial):
    pair = _pair("ehl_per_contact")
    out = BearingModel(pair).evaluate(temperature, W, axial)
    assert out.viscous_torque == pytest.approx(_ehl_by_hand(pair, temperature, W, axial), rel=1e-9)
    yu = BearingModel(_pair("yu2017")).evaluate(temperature, W, axial)
    for name in ("hysteresis_torque", "spin_torque", "sliding_torque", "preload"):
        assert getattr(out, name) == getattr(yu, name)  # the per-contact terms are Yu's


def test_ehl_carries_the_thermal_state():
    # colder: the base oil thickens and the preload rises, the rolling torque grows; once the
    # preload is lost (+60 °C in the yoke) no ball is loaded and the model has no rolling
    # torque; a dry film has none
    pair = _pair("ehl_per_contact")
    cold, warm, hot = (BearingModel(pair).evaluate(t, W) for t in (233.15, 293.15, 333.15))
    assert cold.viscous_torque > 10 * warm.viscous_torque > 0.0
    assert hot.unloaded and hot.viscous_torque == 0.0
    dry = BearingModel(_pair("ehl_per_contact", "ning_space_shaft", "mos2_film"))
    assert dry.evaluate(T_COLD, W).viscous_torque == 0.0


def test_density_enters_as_the_speed_does():
    # the fit depends on η0 and u_m only through U = 2·η0·u_m/(E'·Rx), η0 = ν·ρ: twice the
    # density is twice the speed
    pair = _pair("ehl_per_contact")
    heavy = dataclasses.replace(
        pair, friction=dataclasses.replace(pair.friction, lubricant_density=3800.0)
    )
    m_heavy = BearingModel(heavy).evaluate(T_COLD, W).viscous_torque
    m_fast = BearingModel(pair).evaluate(T_COLD, 2 * W).viscous_torque
    assert m_heavy == pytest.approx(m_fast, rel=1e-12)


# ---------------------------------------------------------------------------- grease
def _g1074_on(bearing_values):
    cal = calibrate_datasheet("molykote_g1074")
    return default_parameters() | bearing_values | cal.parameters, cal


def test_grease_term_on_the_test_bearing_gives_the_datasheet_numbers():
    # the calibrated set on a pair of 6204s (the JIS K 2220 bearing) at the test's −40 °C and
    # 1 r/min: each bearing runs at the datasheet's 50 mN·m and starts at its 99 mN·m
    from servofmu.parameters.presets import bearing_values

    params, _ = _g1074_on(bearing_values(catalog.bearing("6204"))[0])
    params |= {"housing_outer_diameter": 0.07, "shaft_bore": 0.0}
    pair = pair_from_parameters(params)
    base = pair_from_parameters(params | {"grease_f0": 0.0, "grease_starting_ratio": 0.0})
    out = BearingModel(pair).evaluate(233.15, RPM)
    ref = BearingModel(base).evaluate(233.15, RPM)
    assert out.grease_torque == pytest.approx(2 * 0.050, rel=1e-9)
    assert out.running_torque - ref.running_torque == pytest.approx(2 * 0.050, rel=1e-9)
    assert out.breakaway_torque - ref.breakaway_torque == pytest.approx(2 * 0.099, rel=1e-9)


def test_grease_term_carries_over_by_palmgren():
    # on the 71803 at −40 °C and 10 °/s: 2·M0 with f0 at the base oil's ν, dm = (d + D)/2
    params, cal = _g1074_on({})
    out = BearingModel(pair_from_parameters(params)).evaluate(T_COLD, W)
    term = GreaseTorqueTerm(cal.f0, cal.ks, RPM)
    assert out.grease_torque == pytest.approx(
        2 * term.running(out.kinematic_viscosity, W, 0.0215), rel=1e-12
    )


def test_a_grease_term_needs_grease():
    p = default_parameters("ning_space_shaft") | {"grease_f0": 5.0}
    assert any("grease_f0" in msg for msg in parameter_problems(p))
    with pytest.raises(ValueError, match="grease_f0"):
        pair_from_parameters(p)


def test_datasheet_calibration_poor_fit_with_inconsistent_points(monkeypatch):
    # two points of one grease that follow the law give it back; a third 50 % off is a
    # POOR FIT (rms relative residual above 10 %)
    from servofmu.calibration import datasheet as ds
    from servofmu.physics.friction.grease import (
        GreaseTorquePoint,
        base_oil_viscosity,
        torque_test,
    )

    rig, visc = torque_test("jis_k2220"), base_oil_viscosity("molykote_g1074")
    term = GreaseTorqueTerm(12.0, 2.5, rig.speed)

    def point(t, factor=1.0):
        run = term.running(float(visc.kinematic_viscosity(t)), rig.speed, rig.mean_diameter)
        return GreaseTorquePoint("molykote_g1074", "jis_k2220", t, 2.5 * run, factor * run)

    good = [point(233.15), point(253.15)]
    monkeypatch.setattr(ds, "grease_torque_points", lambda key: good)
    cal = ds.calibrate_datasheet("molykote_g1074")
    assert (cal.f0, cal.ks) == (pytest.approx(12.0, rel=1e-12), pytest.approx(2.5, rel=1e-12))
    assert not cal.poor
    monkeypatch.setattr(ds, "grease_torque_points", lambda key: [*good, point(263.15, 1.5)])
    cal = ds.calibrate_datasheet("molykote_g1074")
    assert cal.poor and "rms relative residual" in cal.problems[0]


def test_calibrate_datasheet_command(tmp_path, capsys):
    out = tmp_path / "g"
    assert main(["calibrate", "--datasheet", "molykote_g1074", "--out", str(out)]) == 0
    text = (out / "calibrated.ssv").read_text()
    assert 'name="grease_f0"' in text and 'name="lubricant_viscosity_40"' in text
    assert "one datasheet point" in (out / "report.txt").read_text()
    for bad in (["--datasheet", "no_such"], ["--datasheet", "molykote_g1074", "--speed", "1 rpm"],
                ["--test", "jis_k2220", "x.csv"], []):  # fmt: skip
        assert main(["calibrate", *bad, "--out", str(tmp_path / "x")]) == 2
        assert not (tmp_path / "x" / "calibrated.ssv").exists()


# ------------------------------------------------------------------------ the FMU
@pytest.mark.parametrize("model", ["skf2004", "ehl_per_contact"])
def test_fmu_friction_model_through_parameters_gives_the_library_numbers(fmus, model):
    from fmu_helpers import Fmu

    params, _ = _g1074_on({})
    params |= {"friction_model": model}
    pair = pair_from_parameters(params)
    # the calibrated grease set and the model choice (by item name) on the default FMU
    sets = {k: v for k, v in params.items() if k.startswith(("friction_model", "grease_",
                                                              "lubric", "skf_film"))}  # fmt: skip
    fmu = Fmu(fmus["BearingFriction"]).init(**sets, temperature=T_COLD, speed=W, axial_load=4.0,
                                            radial_load=2.0)  # fmt: skip
    try:
        lib = BearingModel(pair).evaluate(T_COLD, W, 4.0, 2.0)
        for name in ("running_torque", "breakaway_torque", "viscous_torque", "sliding_torque",
                     "grease_torque", "friction_torque"):  # fmt: skip
            assert fmu.get(name) == pytest.approx(getattr(lib, name), rel=1e-12, abs=0.0), name
        fmu.set(speed=-2 * W)  # the speed-only path
        assert fmu.get("friction_torque") == pytest.approx(
            BearingModel(pair).evaluate(T_COLD, -2 * W, 4.0, 2.0).friction_torque, rel=1e-12
        )
    finally:
        fmu.close()


def test_the_grease_variant_is_what_the_calibration_writes():
    # ssp/seeker_gimbal/variants/grease_g1074.ssv is servofmu calibrate --datasheet's output
    from servofmu.build.ssp import SSP_DIR
    from servofmu.build.xmlsafe import parse
    from servofmu.calibration.datasheet import GREASE_PARAMETERS
    from servofmu.parameters.bearing import parameter

    path = SSP_DIR / "seeker_gimbal" / "variants" / "grease_g1074.ssv"
    bound = {}
    for prm in parse(path.read_bytes(), path.name).iter("{*}Parameter"):
        (value,) = list(prm)
        bound[prm.get("name").removeprefix("bearing.")] = value.get("value")
    cal = calibrate_datasheet("molykote_g1074")
    assert set(bound) == set(GREASE_PARAMETERS)
    for name, value in cal.parameters.items():
        spec = parameter(name)
        expected = spec.item(value) if spec.choices else value
        # written from the library's fit; another numpy/scipy build may round its last digit
        assert float(bound[name]) == pytest.approx(expected, rel=1e-12), name


def test_the_reduction_factors_the_ehl_model_leaves_out():
    # the numbers friction_models' docstring states for the 71803 at 10 °/s (Krytox 143AA)
    n = 10.0 / 6.0  # r/min
    law = catalog.lubricant("krytox_143aa")  # Yu's eq 18, extrapolated below -40 °C
    for celsius, ish, rs in ((-40.0, 1.6e-4, 0.92), (-60.0, None, 0.0019)):
        out = BearingModel(_pair("ehl_per_contact")).evaluate(celsius + 273.15, W)
        nu = float(law.kinematic_viscosity(celsius + 273.15)) / 1e-6  # mm²/s
        # below -40 °C, the end of Krytox 143AA's data, the law extrapolated (no flow limit)
        assert out.kinematic_viscosity == pytest.approx(nu * 1e-6, rel=1e-12)
        assert out.outside_lubricant_range == (celsius < -40.0)
        if ish is not None:
            assert 1.0 - rf._phi_ish(nu, n, 21.5) == pytest.approx(ish, rel=0.05)
            assert nu == pytest.approx(4.1e4, rel=0.01)
        assert rf._phi_rs(nu, n, 17.0, 26.0, 4.4, 6e-8) == pytest.approx(rs, rel=0.05)

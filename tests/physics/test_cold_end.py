"""The cold end: BearingFriction outside the range of its lubricant's data sets
``outside_lubricant_range``, logs one warning naming the temperature and the limit, and
extrapolates the viscosity law down to the lubricant's flow limit (its pour point or lower
operating temperature); below that no law holds and ``lubricant_below_flow_limit`` holds the
viscosity at the limit or extrapolates on, said once in a warning. Its optional third
viscosity point makes the viscosity Vogel's law through the three points
(physics/lubrication/viscosity.py)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException
from fmu_helpers import Fmu
from pythonfmu.enums import Fmi2Status

from servofmu.parameters import catalog
from servofmu.parameters.bearing import default_parameters, pair_from_parameters
from servofmu.physics.bearing import BearingModel
from servofmu.physics.kernels.units import CST
from servofmu.physics.lubrication.viscosity import (
    VogelViscosity,
    viscosity_model,
    vogel_from_points,
    walther_from_reference,
)

KRYTOX_LOWER = 233.15  # K: -40 °C, the lower end of Yu's use of his fit (lubricants.toml)
FLOW = 213.15  # K: a flow limit given as a parameter (Krytox 143AA has none published)


def _warnings(fmu):
    return [text for status, text in fmu.log if status == Fmi2Status.warning.value]


def _run(fmu, temperature, steps=5, speed=0.17):
    """``steps`` steps at ``temperature`` [K] and ``speed`` [rad/s] (fmpy raises on a status
    worse than warning)."""
    fmu.set(temperature=temperature, speed=speed)
    for k in range(steps):
        fmu.slave.doStep(k * 1e-3, 1e-3)
    return fmu


def test_krytox_at_173_k_steps_with_the_flag_and_one_warning(fmus):
    """No pour point or operating limit of Krytox 143AA is published: below Yu's -40 °C its
    law is extrapolated (not held), flagged, and said once."""
    fmu = Fmu(fmus["BearingFriction"], "gimbal_bearing").init(temperature=173.15, speed=0.17)
    try:
        _run(fmu, 173.15, steps=20)
        assert fmu.get("outside_lubricant_range") is True
        (warning,) = _warnings(fmu)  # one, however many steps
        assert "gimbal_bearing" in warning and "173.15 K" in warning
        assert "lubricant_data_minimum_temperature = 233.15 K" in warning
        assert "-40.0 °C" in warning and "no flow limit is published" in warning
        nu, torque = fmu.get("kinematic_viscosity", "running_torque")
        law = catalog.lubricant("krytox_143aa").kinematic_viscosity(173.15)
        assert nu == pytest.approx(float(law), rel=1e-12)  # the law, extrapolated
        assert math.isfinite(torque) and torque > 1.0  # N·m: Yu's law there, kN·m
        _run(fmu, 173.15, steps=2, speed=1.0e4)  # the fastest input: finite still
        assert math.isfinite(fmu.get("power_loss"))
        assert len(_warnings(fmu)) == 1
    finally:
        fmu.close()


def test_yu_gimbal_at_minus_60_degc_is_not_held():
    """The viscous torque of Yu's default pair at -60 °C (10 °/s) is more than twice that at
    -40 °C, where his data end, and flagged (the hold at -40 °C gave it equal)."""
    pair = pair_from_parameters(default_parameters())
    w = math.radians(10.0)
    at = {t: BearingModel(pair).evaluate(t + 273.15, w) for t in (-40.0, -60.0)}
    assert at[-60.0].viscous_torque > 2.0 * at[-40.0].viscous_torque
    assert at[-60.0].outside_lubricant_range and not at[-40.0].outside_lubricant_range


@pytest.mark.parametrize("choice", ["hold", "extrapolate"])
def test_below_a_flow_limit_the_choice_is_applied_and_said_once(fmus, choice):
    item = {"hold": 1, "extrapolate": 2}[choice]
    fmu = Fmu(fmus["BearingFriction"], "b").init(
        temperature=223.15, lubricant_minimum_temperature=FLOW, lubricant_below_flow_limit=item
    )
    try:
        _run(fmu, 223.15, steps=2)  # below the data (-40 °C), above the flow limit
        law = catalog.lubricant("krytox_143aa").kinematic_viscosity
        assert fmu.get("kinematic_viscosity") == pytest.approx(float(law(223.15)), rel=1e-12)
        assert fmu.get("outside_lubricant_range") is True and len(_warnings(fmu)) == 1
        for t in (193.15, 183.15, 203.15, 193.15):  # below the flow limit, four times
            _run(fmu, t, steps=2)
            expected = law(FLOW if choice == "hold" else t)
            assert fmu.get("kinematic_viscosity") == pytest.approx(float(expected), rel=1e-12)
            assert fmu.get("outside_lubricant_range") is True
        first, below = _warnings(fmu)  # leaving the data; below the flow limit, once
        assert "extrapolated down to the flow limit" in first
        assert "flow limit, lubricant_minimum_temperature = 213.15 K" in below
        assert f"lubricant_below_flow_limit = {choice}" in below and "193.15 K" in below
    finally:
        fmu.close()


def test_krytox_at_253_k_has_the_flag_clear_and_no_warning(fmus):
    fmu = Fmu(fmus["BearingFriction"], "b").init(temperature=253.15, speed=0.17)
    try:
        _run(fmu, 253.15)
        assert fmu.get("outside_lubricant_range") is False
        assert _warnings(fmu) == []
    finally:
        fmu.close()


def test_leaving_the_range_again_warns_again_and_the_return_clears_the_flag(fmus):
    fmu = Fmu(fmus["BearingFriction"], "b").init(temperature=293.15)
    try:
        for t, flag, count in ((293.15, False, 0), (350.0, True, 1), (340.0, True, 1),
                               (300.0, False, 1), (200.0, True, 2)):  # fmt: skip
            _run(fmu, t, steps=2)
            assert (fmu.get("outside_lubricant_range"), len(_warnings(fmu))) == (flag, count), t
        assert "above the upper end" in _warnings(fmu)[0]
        assert "lubricant_maximum_temperature = 333.15 K" in _warnings(fmu)[0]
    finally:
        fmu.close()


def test_the_cold_point_parameters_give_the_published_cold_viscosity(fmus):
    """Pennzane SHF X-2000 by its numbers: ν40 = 107, ν100 = 14.3 and 80 500 cSt at -40 °C
    (Bessette 1997): the FMU's viscosity at -40 °C is the published one, where the ASTM D341
    line through ν40/ν100 alone (lubricant_viscosity_cold = 0) gives +57 %."""
    numbers = {
        "lubricant_viscosity_40": 107 * CST,
        "lubricant_viscosity_100": 14.3 * CST,
        "lubricant_walther_c": 0.7 * CST,
        "lubricant_minimum_temperature": 218.15,
        "lubricant_maximum_temperature": 373.15,
    }
    cold = {"lubricant_viscosity_cold": 80500 * CST, "lubricant_cold_temperature": 233.15}
    got = {}
    for label, extra in (("three points", cold), ("two points", {})):
        fmu = Fmu(fmus["BearingFriction"], "b").init(temperature=233.15, **numbers, **extra)
        try:
            _run(fmu, 233.15, steps=1)
            got[label] = fmu.get("kinematic_viscosity") / CST
            assert fmu.get("outside_lubricant_range") is False
        finally:
            fmu.close()
    assert got["three points"] == pytest.approx(80500, rel=1e-9)
    assert got["two points"] / 80500 - 1 == pytest.approx(0.569, abs=0.002)


@pytest.mark.parametrize(
    "extra, text",
    [
        ({"lubricant_viscosity_cold": 1e-3, "lubricant_cold_temperature": 313.15},
         "at least 1 K from 313.15"),
        ({"lubricant_viscosity_cold": 1e-6, "lubricant_cold_temperature": 233.15},
         "must fall as the temperature rises"),
        ({"lubricant_viscosity_cold": 1e-2, "lubricant_cold_temperature": 273.15,
          "lubricant_minimum_temperature": 233.15}, "T∞"),  # T∞ = 246 K
        ({"lubricant_minimum_temperature": 400.0}, "must lie above lubricant_minimum"),
        ({"lubricant_minimum_temperature": 1.0},
         "lubricant_below_flow_limit = hold: the viscosity at flow_limit = 1.0 K"),
    ],
)  # fmt: skip
def test_an_impossible_lubricant_is_refused_naming_the_values(fmus, extra, text):
    fmu = Fmu(fmus["BearingFriction"], "b")
    try:
        with pytest.raises(FMICallException, match="status 3"):
            fmu.init(**extra)  # refused when the parameters are fixed, before any step
        errors = " ".join(t for s, t in fmu.log if s >= Fmi2Status.error.value)
        assert text in errors and "lubricant_" in errors, fmu.log
    finally:
        fmu.close()


# ------------------------------------------------------------------------------ library
def test_the_range_extrapolates_to_the_flow_limit_holds_below_and_extrapolates_above():
    v = walther_from_reference(32e-6, 5.4e-6, lower_limit=253.15, upper_limit=373.15,
                               flow_limit=213.15)  # fmt: skip
    t = np.array([173.15, 213.15, 233.15, 253.15, 300.0, 373.15, 450.0])
    assert list(v.outside(t)) == [True, True, True, False, False, False, True]
    assert list(v.below_flow(t)) == [True, False, False, False, False, False, False]
    got = v.operating_viscosity(t)
    law = v.kinematic_viscosity(t)
    assert got[0] == law[1] and list(got[1:]) == list(law[1:])  # held below the flow limit
    assert [v.operating_viscosity_at(float(x)) for x in t] == pytest.approx(list(got), rel=1e-13)
    on = dataclasses.replace(v, below_flow_limit="extrapolate")
    assert list(on.operating_viscosity(t)) == list(law)  # the user's choice: the law


def test_the_pair_extrapolates_krytox_and_holds_at_a_flow_limit_on_both_paths():
    law = catalog.lubricant("krytox_143aa").kinematic_viscosity
    for extra, at in (({}, 173.15), ({"lubricant_minimum_temperature": FLOW}, FLOW)):
        pair = pair_from_parameters(default_parameters() | extra)
        out = BearingModel(pair).evaluate(173.15, 0.17)
        exact = BearingModel(pair).curves(np.array([173.15, KRYTOX_LOWER]), 0.17)
        expected = float(law(at))
        assert out.kinematic_viscosity == pytest.approx(expected, rel=1e-12)
        assert exact.kinematic_viscosity[0] == pytest.approx(expected, rel=1e-12)
        assert out.outside_lubricant_range and list(exact.outside_lubricant_range) == [True, False]


def _d341_cst(t, nu40_cst, nu100_cst, c=0.7):
    """ASTM D341's line through ν40 and ν100 at t [K], written out here [cSt]."""
    y40, y100 = (math.log10(math.log10(n + c)) for n in (nu40_cst, nu100_cst))
    b = (y40 - y100) / (math.log10(373.15) - math.log10(313.15))
    a = y40 + b * math.log10(313.15)
    return 10.0 ** (10.0 ** (a - b * math.log10(t))) - c


def test_a_lubricant_without_a_flow_limit_extrapolates_its_d341_line_below_40_c():
    """ISO VG 32 is known at 40 and 100 °C only (no pour point): below 40 °C it is outside its
    data and flagged, and its viscosity is the ASTM D341 line's, not the 40 °C value; the
    preset says so (lubricant_minimum_temperature 0) and the parameter path agrees."""
    rec = catalog.lubricant_record("iso_vg32")
    v = rec.viscosity
    nu40, nu100 = rec.viscosity_40 * 1e6, rec.viscosity_100 * 1e6
    assert v.flow_limit == v.hold_temperature == 0.0 and v.lower_limit == pytest.approx(313.15)
    for t in (293.15, 253.15, 233.15):
        assert v.outside(t)
        expected = _d341_cst(t, nu40, nu100) * 1e-6
        assert float(v.operating_viscosity(t)) == pytest.approx(expected, rel=1e-9)
        assert v.operating_viscosity_at(t) == pytest.approx(expected, rel=1e-9)
    # what holding the 40 °C value would miss: about 70 times the viscosity at −40 °C
    assert _d341_cst(233.15, nu40, nu100) > 50 * nu40
    params = default_parameters(lubricant="iso_vg32")
    assert params["lubricant_minimum_temperature"] == 0.0
    pair = pair_from_parameters(params)
    assert pair.lubricant.hold_temperature == 0.0
    assert pair.lubricant.lower_limit == pytest.approx(313.15)
    assert float(pair.lubricant.operating_viscosity(233.15)) == pytest.approx(
        _d341_cst(233.15, nu40, nu100) * 1e-6, rel=1e-9
    )


def test_a_flow_limit_given_as_a_parameter_holds_the_viscosity_below_it():
    params = default_parameters(lubricant="iso_vg32") | {"lubricant_minimum_temperature": 263.15}
    visc = pair_from_parameters(params).lubricant
    assert visc.hold_temperature == 263.15 and visc.lower_limit == pytest.approx(313.15)
    assert float(visc.operating_viscosity(233.15)) == float(visc.kinematic_viscosity(263.15))
    assert visc.outside(273.15)  # below its data, above the flow limit: the law, flagged
    assert float(visc.operating_viscosity(273.15)) == float(visc.kinematic_viscosity(273.15))


def test_vogel_through_three_points_by_hand():
    """ln ν = a + b/(T − T∞) through (250, e^2), (300, e^1), (400, e^0) [K, m²/s]: the
    differences 1 = b·(1/(250 − T∞) − 1/(300 − T∞)) and 1 = b·(1/(300 − T∞) − 1/(400 − T∞))
    give 100·(250 − T∞) = 50·(400 − T∞), T∞ = 100 K, b = 1/(1/150 − 1/200) = 600 K,
    a = 2 − 600/150 = −2."""
    v = vogel_from_points([(300.0, math.e), (250.0, math.e**2), (400.0, 1.0)])
    assert (v.a, v.b, v.t_inf) == pytest.approx((-2.0, 600.0, 100.0), rel=1e-12)
    assert isinstance(viscosity_model(107e-6, 14.3e-6, cold_point=(233.15, 0.08)), VogelViscosity)


@pytest.mark.parametrize(
    "points, text",
    [
        ([(250.0, 1.0), (300.0, 0.5)], "three or more points"),
        ([(250.0, 1.0), (250.0, 0.9), (300.0, 0.5)], "different temperatures"),
        ([(250.0, 1.0), (300.0, 2.0), (350.0, 0.5)], "must fall"),
        ([(-1.0, 1.0), (300.0, 0.5), (350.0, 0.4)], "points temperature = -1.0"),
    ],
)
def test_vogel_refuses_points_it_cannot_pass_through(points, text):
    with pytest.raises(ValueError, match=text):
        vogel_from_points(points)


def test_a_law_without_a_finite_value_where_it_is_used_is_refused():
    with pytest.raises(ValueError, match=r"flow_limit = 1\.0 K is inf"):
        walther_from_reference(32e-6, 5.4e-6, lower_limit=313.15, flow_limit=1.0)
    with pytest.raises(ValueError, match="must lie below the lowest temperature"):
        vogel_from_points([(250.0, 1.0), (300.0, 0.01), (350.0, 0.005)], lower_limit=150.0)


# ------------------------------------------------------------------------------ cold start
def test_yu_gimbal_at_minus_40_degc_says_its_breakaway_is_a_lower_bound(fmus):
    """At -40 °C and 10 °/s Yu's default BearingFriction starts below its running torque:
    Krytox 143AA has no published starting torque, so breakaway_lower_bound is set; with
    G-1074 (its datasheet's start on by default) it starts harder than it runs, unflagged."""
    w = math.radians(10.0)
    g1074 = default_parameters(lubricant="molykote_g1074")
    names = ("lubricant_viscosity_40", "lubricant_viscosity_100", "lubricant_walther_c",
             "lubricant_density", "skf_film_friction", "lubricant_minimum_temperature",
             "lubricant_data_minimum_temperature", "lubricant_maximum_temperature",
             "grease_f0", "grease_starting_ratio", "grease_reference_speed")  # fmt: skip
    for extra, flagged in (({}, True), ({n: g1074[n] for n in names}, False)):
        fmu = Fmu(fmus["BearingFriction"], "b").init(temperature=KRYTOX_LOWER, speed=w, **extra)
        try:
            _run(fmu, KRYTOX_LOWER, steps=2, speed=w)
            brk, run, bound = fmu.get("breakaway_torque", "running_torque", "breakaway_lower_bound")
            assert bound is flagged
            assert (brk >= run) is not flagged  # a lower bound below; the datasheet's start above
        finally:
            fmu.close()

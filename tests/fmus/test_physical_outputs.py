"""Outputs beyond the physics: each FMU says the range its physics holds for, and an output
that leaves it is flagged and logged once; a step beyond a hard limit (0 K) is discarded."""

from __future__ import annotations

import pytest
from fmu_helpers import Fmu

WARNING = 1


def _warnings(fmu, word):
    return [text for status, text in fmu.log if status == WARNING and word in text]


def test_a_part_beyond_the_networks_range_is_flagged_and_logged_once(fmus):
    fmu = Fmu(fmus["ThermalNetwork"]).init(power_loss=1.0e4)  # its declared maximum power
    try:
        hot = fmu.get("inner_ring_temperature")
        assert hot > 1000.0  # thousands of kelvin: no material or lubricant survives that
        assert fmu.get("outside_valid_range") is True
        for k in range(3):
            fmu.slave.doStep(k * 10.0, 10.0)
        logged = _warnings(fmu, "maximum_part_temperature = 473.15 K")
        assert len(logged) == 1 and "inner_ring_temperature" in logged[0], fmu.log
    finally:
        fmu.close()


def test_the_range_is_the_users_to_set_and_a_return_clears_the_flag(fmus):
    fmu = Fmu(fmus["ThermalNetwork"]).init(power_loss=0.0, maximum_part_temperature=1.0e4)
    try:
        assert fmu.get("outside_valid_range") is False
        fmu.set(ambient_temperature=400.0, power_loss=100.0)
        fmu.slave.doStep(0.0, 1.0e5)
        assert 473.15 < fmu.get("inner_ring_temperature") < 1.0e4
        assert fmu.get("outside_valid_range") is False  # within the user's 10,000 K
    finally:
        fmu.close()
    fmu = Fmu(fmus["ThermalNetwork"]).init(maximum_part_temperature=300.0)
    try:
        assert fmu.get("outside_valid_range") is False  # soaked at 20 °C
        fmu.set(ambient_temperature=350.0)
        fmu.slave.doStep(0.0, 1.0e5)
        assert fmu.get("outside_valid_range") is True
        fmu.set(ambient_temperature=290.0)
        fmu.slave.doStep(1.0e5, 1.0e5)
        assert fmu.get("outside_valid_range") is False
        assert len(_warnings(fmu, "maximum_part_temperature = 300 K")) == 1
    finally:
        fmu.close()


def test_a_range_upside_down_is_refused(fmus):
    from fmpy.fmi1 import FMICallException

    fmu = Fmu(fmus["ThermalNetwork"])
    try:
        with pytest.raises(FMICallException):
            fmu.init(minimum_part_temperature=400.0, maximum_part_temperature=300.0)
        assert any("must be below maximum_part_temperature" in t for _, t in fmu.log), fmu.log
    finally:
        fmu.close()


def test_a_negative_contact_angle_is_flagged_and_logged_once(fmus):
    fmu = Fmu(fmus["BearingFriction"]).init(
        temperature_mode="parts",
        housing_temperature=473.15,
        outer_ring_temperature=473.15,
        shaft_temperature=173.15,
        inner_ring_temperature=173.15,
    )
    try:
        angle, reversed_ = fmu.get("contact_angle", "reverse_loaded")
        assert angle == pytest.approx(-0.64, abs=0.01) and reversed_ is True
        for k in range(3):
            fmu.slave.doStep(k * 1e-3, 1e-3)
        logged = _warnings(fmu, "other flanks of its grooves")
        assert len(logged) == 1 and "-0.64" in logged[0] and "not verified" in logged[0]
    finally:
        fmu.close()

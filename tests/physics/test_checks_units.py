import math
import re

import numpy as np
import pytest

from servofmu.physics._checks import check_positive, check_range, check_temperature
from servofmu.physics.kernels import units


def test_conversions_round_trip():
    assert units.kelvin_to_celsius(units.celsius_to_kelvin(-40.0)) == pytest.approx(-40.0)
    assert units.rpm_to_rad_per_s(60.0) == pytest.approx(2 * math.pi)
    assert units.rad_per_s_to_rpm(units.rpm_to_rad_per_s(1.5)) == pytest.approx(1.5)
    assert units.to_si(26, "mm") == pytest.approx(0.026)
    assert units.to_si(20, "degC") == pytest.approx(293.15)
    assert units.to_si(72, "GPa") == pytest.approx(72e9)


def test_to_si_rejects_unknown_unit():
    with pytest.raises(ValueError, match=re.escape("unit = 'furlong'")):
        units.to_si(1.0, "furlong")


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -1.0, 0.0])
def test_check_positive_names_argument_value_and_range(bad):
    with pytest.raises(ValueError) as exc:
        check_positive("ball_diameter", bad, "m")
    msg = str(exc.value)
    assert "ball_diameter" in msg and repr(bad) in msg and "(0, inf)" in msg


def test_check_range_arrays_report_first_bad_value():
    with pytest.raises(ValueError, match=r"x = 7\.0 .* \[0, 5\]"):
        check_range("x", np.array([1.0, 7.0, 9.0]), 0.0, 5.0)
    np.testing.assert_array_equal(check_range("x", np.array([1.0, 2.0]), 0.0, 5.0), [1.0, 2.0])


def test_temperatures_must_be_positive_kelvin():
    with pytest.raises(ValueError, match=re.escape("temperature = -5.0 K")):
        check_temperature("temperature", -5.0)
    assert check_temperature("temperature", 233.15) == 233.15

import math
import re

import numpy as np
import pytest

from servofmu.parameters import catalog
from servofmu.physics.lubrication.viscosity import (
    walther_from_two_points,
    walther_kinematic_viscosity,
)


def yu_eq18_cst(t_k):
    """Yu 2017 eq 18 solved by hand: ν = 10^(10^(9.597 − 3.773·lg T)) − 0.932."""
    return 10 ** (10 ** (9.597 - 3.773 * math.log10(t_k))) - 0.932


@pytest.mark.parametrize("t_c", [-40, -20, 0, 20, 40, 60])
def test_krytox_fit_is_yu_eq18(t_c):
    visc = catalog.lubricant("krytox_143aa")
    t = t_c + 273.15
    assert visc.kinematic_viscosity(t) / 1e-6 == pytest.approx(yu_eq18_cst(t), rel=1e-12)


def test_krytox_values_at_the_chamber_temperatures():
    visc = catalog.lubricant("krytox_143aa")
    nu = visc.kinematic_viscosity(np.array([233.15, 293.15])) / 1e-6
    # ~41 000 cSt at −40 °C and ~87 cSt at 20 °C: the three orders of magnitude behind Fig 8
    assert nu[0] == pytest.approx(40947, rel=1e-3)
    assert nu[1] == pytest.approx(86.95, rel=1e-3)


def test_two_point_fit_recovers_yu_coefficients():
    t1, t2 = 253.15, 333.15
    fit = walther_from_two_points(t1, yu_eq18_cst(t1) * 1e-6, t2, yu_eq18_cst(t2) * 1e-6, c=0.932)
    assert fit.a == pytest.approx(9.597, rel=1e-9)
    assert fit.b == pytest.approx(3.773, rel=1e-9)


def test_astm_example_passes_through_its_points():
    vg32 = catalog.lubricant("iso_vg32")
    assert vg32.kinematic_viscosity(313.15) == pytest.approx(32e-6, rel=1e-9)
    assert vg32.kinematic_viscosity(373.15) == pytest.approx(5.4e-6, rel=1e-9)


def test_viscosity_falls_with_temperature():
    nu = walther_kinematic_viscosity(np.linspace(220, 400, 50), 9.597, 3.773, 0.932)
    assert np.all(np.diff(nu) < 0)


def test_bad_input():
    with pytest.raises(ValueError, match=re.escape("temperature = 0.0 K")):
        walther_kinematic_viscosity(0.0, 9.597, 3.773)
    with pytest.raises(ValueError, match=re.escape("t2 = 300.0 K must differ")):
        walther_from_two_points(300.0, 1e-5, 300.0, 2e-5)
    with pytest.raises(ValueError, match=re.escape("nu1 = -1e-05")):
        walther_from_two_points(300.0, -1e-5, 350.0, 2e-6)
    with pytest.raises(ValueError, match=re.escape("must fall with temperature")):
        walther_from_two_points(300.0, 1e-6, 350.0, 2e-5)

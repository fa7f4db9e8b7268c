import dataclasses
import math
import re

import numpy as np
import pytest

from servofmu.parameters import catalog
from servofmu.physics.contact.geometry import (
    ball_diameter_from_grooves,
    first_contact_offset,
    free_contact_angle,
)

INCH = 25.4e-3


def test_71803_ball_is_a_3_32_inch_ball(b71803):
    # DESIGN §4: the groove diameters and 15° give Dw ≈ 2.381 mm, a standard 3/32" ball
    assert b71803.ball_diameter == pytest.approx(3 / 32 * INCH, rel=2e-4)
    assert b71803.pitch_diameter == pytest.approx(21.5e-3)
    assert b71803.clearance == pytest.approx(16.23e-6, rel=1e-3)


def test_free_contact_angle_round_trip(b71803):
    assert b71803.contact_angle == pytest.approx(math.radians(15), abs=1e-12)


def test_harris_clearance_relation_limits():
    a = 0.24e-3
    assert free_contact_angle(0.0, a) == 0.0
    assert free_contact_angle(-2e-6, a) == 0.0  # negative clearance: no free angle
    assert free_contact_angle(2 * a, a) == pytest.approx(math.pi / 2)
    assert first_contact_offset(2 * a, a) == pytest.approx(a)
    assert first_contact_offset(-1e-6, a) == 0.0
    # h = A·sin α0 (independent form)
    pd = 10e-6
    assert first_contact_offset(pd, a) == pytest.approx(a * math.sin(free_contact_angle(pd, a)))


def test_ball_diameter_formula_inverts_clearance():
    dw = ball_diameter_from_grooves(19e-3, 24e-3, 0.52, 0.53, math.radians(25))
    pd = 24e-3 - 19e-3 - 2 * dw
    assert math.acos(1 - pd / (2 * 0.05 * dw)) == pytest.approx(math.radians(25))


def test_71807c_geometry_is_consistent():
    b = catalog.bearing("71807C")
    assert b.pitch_diameter == pytest.approx(41e-3)
    assert b.contact_angle == pytest.approx(math.radians(15))
    assert b.bore < b.inner_groove_diameter < b.outer_groove_diameter < b.outer_diameter


@pytest.mark.parametrize(
    "change, match",
    [
        ({"inner_curvature": 0.5}, "inner_curvature = 0.5"),
        ({"outer_curvature": 0.49}, "outer_curvature = 0.49"),
        ({"ball_diameter": -1e-3}, "ball_diameter = -0.001"),
        ({"bore": float("nan")}, "bore = nan"),
        ({"n_balls": 40}, "n_balls × ball_diameter = 40 × 0.00238"),
        ({"n_balls": 40}, "(the balls must fit on the pitch circle)"),
        ({"n_balls": 2}, "n_balls = 2"),
        ({"n_balls": 15.0}, "n_balls = 15.0 must be an integer"),
        ({"ball_diameter": 4.6e-3}, "ball_diameter = 0.0046 m must be below (outer_diameter"),
        ({"nominal_contact_angle": 0.8}, "nominal_contact_angle = 0.8 rad (45.8366°) is outside"),
        ({"nominal_contact_angle": -0.01}, "nominal_contact_angle = -0.01 rad"),
        ({"pitch_diameter": 16e-3}, "pitch_diameter = 0.016 m must lie between bore = 0.017"),
        ({"pitch_diameter": 26.5e-3}, "pitch_diameter = 0.0265 m must lie between"),
        ({"pitch_diameter": 19.3e-3}, "the inner groove (diameter pitch_diameter − ball_diam"),
        ({"outer_diameter": 16e-3}, "outer_diameter = 0.016 m must exceed bore = 0.017 m"),
    ],
)
def test_bad_geometry_is_rejected(b71803, change, match):
    """The consistency checks of the FMU parameters, each naming its values."""
    with pytest.raises(ValueError, match=re.escape(match)):
        dataclasses.replace(b71803, **change)


def test_race_geometry_properties(b71803):
    g = b71803.race_geometry()
    assert g.curvature_distance == pytest.approx(0.1 * b71803.ball_diameter)
    assert g.radial_centre_distance == pytest.approx(g.curvature_distance - g.clearance / 2)
    assert np.isclose(g.free_contact_angle, math.radians(15))


@pytest.mark.parametrize(
    "args, message",
    [
        ((0.0, 0.56, 0.54, 0.26), "ball_diameter = 0.0 m"),
        ((2.381e-3, 0.45, 0.54, 0.26), "inner_curvature = 0.45 is outside the valid range"),
        ((2.381e-3, 0.56, 0.5, 0.26), "outer_curvature = 0.5 is outside the valid range"),
        ((2.381e-3, 0.56, 0.54, -0.1), "contact_angle = -0.1 rad is outside the valid range"),
    ],
)
def test_clearance_from_contact_angle_refuses_what_cannot_be_a_groove(args, message):
    """f_i + f_o < 1 would give a negative clearance silently (found while documenting it)."""
    from servofmu.physics.contact.geometry import clearance_from_contact_angle

    with pytest.raises(ValueError, match=re.escape(message)):
        clearance_from_contact_angle(*args)

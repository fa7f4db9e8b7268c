"""Every public physics function rejects bad input with a ValueError that names the argument,
its value and the valid range."""

import math
import re

import pytest

from servofmu.parameters import catalog
from servofmu.physics.contact import equilibrium, geometry, hertz
from servofmu.physics.contact.geometry import RaceGeometry
from servofmu.physics.friction import terms as friction
from servofmu.physics.pair import preload
from servofmu.physics.thermal import fits

NAN = float("nan")


@pytest.fixture(scope="module")
def g():
    return catalog.bearing("71803").race_geometry()


def cases(g):
    steel = catalog.material("steel_45")
    return [
        (lambda: geometry.diametral_clearance(19e-3, 24e-3, -2e-3), "ball_diameter = -0.002"),
        (lambda: geometry.first_contact_offset(NAN, 2e-4), "clearance = nan"),
        (lambda: geometry.free_contact_angle(1e-5, 0.0), "curvature_distance = 0.0"),
        (lambda: hertz.hertz_load(1e9, NAN), "deflection = nan"),
        (lambda: hertz.contact_constants(1e3, 0.5, 1e-11).semi_axes(-1.0), "load = -1.0"),
        (lambda: equilibrium.axial_force(NAN, g), "offset = nan"),
        (lambda: equilibrium.contact_constants_at(g, math.inf), "alpha = inf"),
        (lambda: equilibrium.offset_for_axial_force(g, NAN), "force = nan"),
        (
            lambda: fits.bore_change_under_external_pressure(1e6, 20e-3, 25e-3, steel),
            "bore = 0.025",
        ),
        (
            lambda: fits.outside_change_under_internal_pressure(-1.0, 20e-3, 25e-3, steel),
            "pressure = -1.0",
        ),
        (lambda: preload.mean_offset(0.0, NAN, 1e8, g), "closure = nan"),
        (lambda: preload.pair_offsets(g, 1e-4, 0.0), "loop_stiffness = 0.0"),
        (lambda: preload.pair_axial_stiffness(-1.0, 1e7, 1e8), "stiffness_a = -1.0"),
        (lambda: preload.pair_equilibrium(g, NAN, 1e8, 0.0, 1.0), "closure = nan"),
        (lambda: preload.shim_for_preload(g, 0.0, 1e8), "preload = 0.0"),
        (lambda: friction.race_contact_radius(-1.0, 2e-3, 0.2, "inner"), "pitch_diameter = -1.0"),
        (lambda: friction.hysteresis_rolling_force(1.0, 1e-5, 2e-3, 1.5), "loss_factor = 1.5"),
        (lambda: friction.spin_moment(NAN, 1e-4, 1.2, 0.1), "load = nan"),
        (
            lambda: friction.heathcote_sliding_force(1.0, 1e-4, 2e-3, 0.0, 0.1),
            "groove_radius = 0.0",
        ),
        (lambda: friction.palmgren_viscous_torque(1e-5, math.inf, 0.02, 1.0), "speed = inf"),
        (
            lambda: friction.regularised_friction_torque(0.1, 1e-3, 0.0, 0.0, 1.0),
            "regularisation_speed = 0.0",
        ),
        (
            lambda: RaceGeometry(2e-3, 19e-3, 24e-3, 0.9e-3, 1.1e-3, 15, 1e-11),
            "inner_groove_radius = 0.0009",
        ),
        (lambda: RaceGeometry(2e-3, 19e-3, 24e-3, 1.1e-3, 1.1e-3, 2, 1e-11), "n_balls = 2"),
    ]


def test_bad_input_is_named(g):
    for call, match in cases(g):
        with pytest.raises(ValueError, match=re.escape(match)):
            call()


def test_a_temperature_is_checked_once_on_its_way_to_the_solver(monkeypatch):
    # thermal_state checks each part once (not again in the fits and the loop closure); the
    # per-step model checks its floats itself, so its exact path checks none again
    from servofmu.physics import bearing
    from servofmu.physics.thermal import temperatures

    pair = bearing.BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    bearing.thermal_state(pair, 293.15)  # the pair's own data at assembly, once per pair
    calls = []
    check = temperatures.check_operating_temperature

    def counted(name, value):
        calls.append(name)
        return check(name, value)

    monkeypatch.setattr(temperatures, "check_operating_temperature", counted)
    bearing.thermal_state(pair, bearing.PartTemperatures(250.0, 260.0, 270.0, 280.0))
    assert sorted(calls) == sorted(f"{p}_temperature" for p in temperatures.PARTS)
    calls.clear()
    model = bearing.BearingModel(pair)
    model.thermal((250.0, 260.0, 270.0, 280.0))
    assert calls == []
    with pytest.raises(ValueError, match=r"shaft_temperature = -10.0 K .* looks like °C"):
        model.thermal((250.0, -10.0, 270.0, 280.0))

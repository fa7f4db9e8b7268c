"""BearingFriction's part-temperature inputs (temperature_mode) against the library (a fresh
library model solves exactly, the FMU by continuation from its initial state: equal to 1e-9)."""

import pytest
from fmu_helpers import Fmu

from servofmu.physics.bearing import BearingModel, PartTemperatures

OUTPUTS = (
    "friction_torque",
    "running_torque",
    "breakaway_torque",
    "preload",
    "contact_angle",
    "radial_clearance",
    "kinematic_viscosity",
    "axial_stiffness",
    "max_contact_pressure",
    "outer_fit_interference",
    "inner_fit_interference",
)


@pytest.fixture(scope="module")
def library():
    # the FMU's defaults: the Yu gimbal with its calibrated coefficients
    from servofmu.parameters.bearing import default_parameters, pair_from_parameters

    return BearingModel(pair_from_parameters(default_parameters("yu2017_gimbal")))


def _fmu(fmus, name, **values):
    fmu = Fmu(fmus["BearingFriction"], name).init(**values)
    fmu.slave.doStep(0.0, 1e-3)
    return fmu


@pytest.mark.parametrize("t", [233.15, 293.15, 333.15])
def test_equal_part_temperatures_give_the_uniform_outputs_exactly(fmus, t):
    uniform = _fmu(fmus, "u", temperature=t, speed=0.17, axial_load=3.0)
    parts = _fmu(
        fmus,
        "p",
        temperature_mode="parts",
        temperature=400.0,  # ignored in this mode
        **dict.fromkeys(("housing_temperature", "shaft_temperature", "outer_ring_temperature"), t),
        inner_ring_temperature=t,
        speed=0.17,
        axial_load=3.0,
    )
    assert parts.get(*OUTPUTS) == uniform.get(*OUTPUTS)
    for flag in ("overloaded", "locked", "unloaded"):
        assert parts.get(flag) == uniform.get(flag)
    uniform.close()
    parts.close()


def test_parts_mode_equals_the_library_at_the_parts_temperatures(fmus, library):
    temps = PartTemperatures(255.0, 268.0, 257.0, 266.0)
    fmu = _fmu(
        fmus,
        "p",
        temperature_mode="parts",
        housing_temperature=temps.housing,
        shaft_temperature=temps.shaft,
        outer_ring_temperature=temps.outer_ring,
        inner_ring_temperature=temps.inner_ring,
        speed=0.17,
    )
    lib = library.evaluate(temps, 0.17)
    for name in OUTPUTS:
        field = {
            "outer_fit_interference": "outer_interference",
            "inner_fit_interference": "inner_interference",
        }.get(name, name)
        assert fmu.get(name) == pytest.approx(getattr(lib, field), rel=1e-9), name
    fmu.close()


def test_housing_shaft_mode_puts_the_rings_at_their_seats(fmus, library):
    fmu = _fmu(
        fmus,
        "hs",
        temperature_mode="housing_shaft",
        housing_temperature=250.0,
        shaft_temperature=270.0,
        outer_ring_temperature=400.0,  # ignored in this mode
        speed=0.17,
    )
    lib = library.evaluate(PartTemperatures(250.0, 270.0, 250.0, 270.0), 0.17)
    assert fmu.get("preload") == pytest.approx(lib.preload, rel=1e-9)
    assert fmu.get("running_torque") == pytest.approx(lib.running_torque, rel=1e-9)
    fmu.close()


def test_a_colder_frame_than_shaft_raises_the_preload(fmus):
    # the aluminium frame shrinks onto the steel shaft's bearings: the loop closes (Yu eq 14)
    even = _fmu(fmus, "even", temperature_mode="parts", **_all(260.0))
    cold_frame = _fmu(
        fmus, "cold", temperature_mode="parts", **{**_all(260.0), "housing_temperature": 250.0}
    )
    assert cold_frame.get("preload") > even.get("preload")
    even.close()
    cold_frame.close()


def _all(t):
    return {f"{p}_temperature": t for p in ("housing", "shaft", "outer_ring", "inner_ring")}


# ---------------------------------------------------------------------------- ActuatorStiffness
ACTUATOR_OUTPUTS = (
    "stiffness",
    "support_bearing_stiffness",
    "deflection",
    "gear_stiffness",
    "linkage_stiffness",
    "screw_force",
)


def _actuator(fmus, name, **values):
    fmu = Fmu(fmus["ActuatorStiffness"], name).init(angle=0.17, load_torque=100.0, **values)
    fmu.slave.doStep(0.0, 1e-2)
    return fmu


@pytest.mark.parametrize("t", [233.15, 333.15])
def test_actuator_equal_part_temperatures_give_the_uniform_outputs_exactly(fmus, t):
    uniform = _actuator(fmus, "u", temperature=t)
    parts = _actuator(fmus, "p", temperature_mode="parts", temperature=400.0, **_all(t))
    assert parts.get(*ACTUATOR_OUTPUTS) == uniform.get(*ACTUATOR_OUTPUTS)
    uniform.close()
    parts.close()


def test_actuator_support_pair_follows_its_part_temperatures(fmus):
    # a cold housing around warm rings and screw (a chamber cooling the actuator): the support
    # pair's thermal preload, hence its stiffness, is the library's at those part temperatures
    from servofmu.physics.drives.actuator import Actuator, ActuatorModel

    temps = {**_all(293.15), "housing_temperature": 253.15, "outer_ring_temperature": 263.15}
    fmu = _actuator(fmus, "p", temperature_mode="parts", **temps)
    even = _actuator(fmus, "e", temperature=293.15)
    model = ActuatorModel(Actuator.from_catalog("liu2014_ema"))
    parts = tuple(
        temps[f"{p}_temperature"] for p in ("housing", "shaft", "outer_ring", "inner_ring")
    )
    lib = model.evaluate(0.17, 100.0, parts)
    assert fmu.get("support_bearing_stiffness") == pytest.approx(lib.support_bearing, rel=1e-9)
    assert fmu.get("stiffness") == pytest.approx(lib.total, rel=1e-9)
    # and it is not the uniform value: the part temperatures reach the support pair
    assert abs(lib.support_bearing / even.get("support_bearing_stiffness") - 1.0) > 1e-3
    shaft_mode = _actuator(
        fmus, "hs", temperature_mode="housing_shaft", **{**temps, "outer_ring_temperature": 400.0}
    )
    hs = model.evaluate(0.17, 100.0, (253.15, 293.15, 253.15, 293.15))
    assert shaft_mode.get("stiffness") == pytest.approx(hs.total, rel=1e-9)
    for f in (fmu, even, shaft_mode):
        f.close()


def test_actuator_library_names_a_bad_part_temperature():
    from servofmu.physics.drives.actuator import Actuator, ActuatorModel

    model = ActuatorModel(Actuator.from_catalog("liu2014_ema"))
    with pytest.raises(ValueError, match="shaft_temperature = nan"):
        model.evaluate(0.17, 100.0, (293.15, float("nan"), 293.15, 293.15))

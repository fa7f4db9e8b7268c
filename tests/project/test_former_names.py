"""The modules' former names keep their public names (physics.MOVED): what user code imported
from ``servofmu.physics.<former>`` before the package was laid out by subject still imports.
The lists are the public names of the former flat modules, written out here."""

import importlib

import pytest

#: Former module → public names it had (functions, classes, constants).
FORMER = {
    "friction_models": (
        *("FrictionModel", "mean_diameter", "skf_loads", "skf_torques", "skf_starting"),
        "ehl_torque",
    ),
    "continuation": (
        *("describe", "kernels", "PairSolver", "PairConstants", "PointState", "Thermal"),
        *("thermal_at", "thermal_floats"),
    ),
}


@pytest.mark.parametrize("former", FORMER)
def test_a_former_module_still_offers_its_public_names(former):
    module = importlib.import_module(f"servofmu.physics.{former}")
    missing = [name for name in FORMER[former] if not hasattr(module, name)]
    assert not missing, f"servofmu.physics.{former} lost {missing}"


def test_former_names_are_the_objects_where_they_live_now():
    from servofmu.physics import compiled
    from servofmu.physics.continuation import PairSolver, PointState
    from servofmu.physics.friction import ehl_per_contact, skf2004
    from servofmu.physics.friction_models import ehl_torque, skf_loads

    assert skf_loads is skf2004.skf_loads and ehl_torque is ehl_per_contact.ehl_torque
    assert PairSolver is compiled.module("pair.continuation").PairSolver
    assert PointState is compiled.module("pair.point").PointState
    with pytest.raises(AttributeError, match="no attribute 'nothing'"):
        _ = importlib.import_module("servofmu.physics.friction_models").nothing

"""The friction-model registry (``servofmu.physics.friction.registry``): a new friction model
is one module and one registry line (``docs/development.md``, "A new friction model"). A toy
model, a constant viscous torque, added through it runs on the exact path and on every
per-step path, and joins the parameter table's enumeration (that the built-in models' names
live in their own modules and the registry only: ``tests/project/test_friction_model_names.py``)."""

from __future__ import annotations

import sys
import types

import numpy as np
import pytest
from kernels import implementations

from servofmu.parameters import table
from servofmu.physics.bearing import BearingModel, BearingPair
from servofmu.physics.friction import registry
from servofmu.physics.pair.state import operating_outputs

#: The toy model's viscous torque of the pair [N·m], whatever the speed and temperature.
TOY = 1.234e-3
TEMPERATURES = (253.15, 253.4, 254.0)  # K
SPEED, AXIAL = 0.2, 5.0  # rad/s, N


@pytest.fixture
def toy(monkeypatch):
    module = types.ModuleType("toy_friction")
    module.running_terms = lambda pair, nu, dm, rolling, speed: (TOY + 0.0 * nu, None)
    monkeypatch.setitem(sys.modules, "toy_friction", module)
    registry.register(registry.Entry("toy", "toy_friction", "a constant viscous torque"))
    yield "toy"
    registry.unregister("toy")


def test_a_toy_model_runs_on_the_exact_path_and_every_per_step_path(toy):
    pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa", friction_model=toy)
    yu = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    exact = operating_outputs(pair, np.array(TEMPERATURES), SPEED, AXIAL)
    reference = operating_outputs(yu, np.array(TEMPERATURES), SPEED, AXIAL)
    np.testing.assert_array_equal(exact.viscous_torque, TOY)
    # the contacts' terms are Yu's (the toy keeps them): the running torque differs by the
    # viscous torques only
    np.testing.assert_allclose(
        exact.running_torque - reference.running_torque,
        TOY - reference.viscous_torque,
        rtol=1e-12,
        atol=1e-15,
    )
    for impl in implementations():
        model = BearingModel(pair, impl)
        for i, t in enumerate(TEMPERATURES):
            out = model.evaluate(t, SPEED, AXIAL)
            assert out.viscous_torque == TOY, impl
            assert out.running_torque == pytest.approx(exact.running_torque[i], rel=1e-9)


def test_a_toy_model_joins_the_enumeration(toy):
    (spec,) = (s for s in table._friction_model_specs() if s.name == "friction_model")
    assert [c.name for c in spec.choices][-1] == toy
    assert spec.description.endswith("skf2004, ehl_per_contact or toy")


def test_an_unknown_model_is_named_with_the_choices():
    with pytest.raises(ValueError, match=r"friction_model = 'yu2018'.*'yu2017'"):
        BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa", friction_model="yu2018")


def test_a_name_is_registered_once():
    with pytest.raises(ValueError, match="registered already"):
        registry.register(registry.Entry("skf2004", ".skf2004", "again"))

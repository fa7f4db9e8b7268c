"""A tandem pair (the thermal loop differs between back-to-back, face-to-face and tandem;
these tests say how): both bearings face the same way and share the thrust of
a force or spring preload and the axial load. The members between them do not change that
thrust, they shift it between A and B (physics/pair/preload.py ARRANGEMENTS, tandem_offsets).

The checks are the model's own equations evaluated by hand from the parameters: the shared
thrust, the mismatch a_B − a_A = L_shaft·α_shaft·ΔT_shaft − L_housing·α_housing·ΔT_housing,
the spring's force k_s·(c − Δa_A), the stiffness k_A + k_B + k_s, the radial shares."""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest
from fmu_helpers import Fmu

from servofmu.parameters.bearing import default_parameters, pair_from_parameters
from servofmu.physics.bearing import BearingModel, load_state, thermal_state
from servofmu.physics.contact.equilibrium import axial_force, axial_state, offset_for_axial_force
from servofmu.physics.drives.actuator import check_support_pair
from servofmu.physics.pair.mounting import Mounting
from servofmu.physics.pair.preload import LoopMember, tandem_equilibrium
from servofmu.physics.thermal.temperatures import PartTemperatures

P0 = 40.0  # N, the set's preload
# the rigid-tube gimbal without fits: only the axial terms act
BASE = default_parameters("yu2017_gimbal_rigid") | {"outer_interference": 0.0}
T0 = BASE["assembly_temperature"]
TANDEM = BASE | {"arrangement": "tandem", "preload_method": "force", "assembly_preload": P0}


def _state(p, temps, axial_load=0.0, radial_load=0.0):
    pair = pair_from_parameters(p)
    th = thermal_state(pair, PartTemperatures(*temps))
    return th, load_state(pair, th, axial_load, radial_load)


def _mismatch(p, shaft_rise=0.0, housing_rise=0.0):
    """a_B − a_A [m] from the parameters: the shaft's growth between the bearings less the
    housing's."""
    return (p["shaft_length"] * p["shaft_expansion"] * shaft_rise
            - p["housing_length"] * p["housing_expansion"] * housing_rise)  # fmt: skip


def test_at_assembly_the_two_bearings_share_the_preload_equally():
    th, ls = _state(TANDEM, (T0,) * 4)
    assert float(ls.force_a) == pytest.approx(P0 / 2, rel=1e-12)
    assert float(ls.force_b) == pytest.approx(P0 / 2, rel=1e-12)
    assert float(ls.preload) == pytest.approx(P0 / 2, rel=1e-12)  # half the thrust
    # each bearing sits where it carries P0/2 alone (the single bearing's own relation)
    a = float(offset_for_axial_force(th.geometry, P0 / 2))
    assert float(ls.offset_a) == pytest.approx(a, abs=1e-15)
    assert float(ls.offset_b) == pytest.approx(a, abs=1e-15)
    k_bearing = float(axial_state(th.geometry, a).axial_stiffness)
    assert float(ls.axial_stiffness) == pytest.approx(2 * k_bearing, rel=1e-12)  # side by side
    assert not ls.unloaded


@pytest.mark.parametrize("shaft_rise, housing_rise", [(2.0, 0.0), (0.0, 2.0), (3.0, 1.0)])
def test_a_part_growing_between_the_bearings_shifts_the_thrust_and_keeps_it(
    shaft_rise, housing_rise
):
    """Face-to-face the same growth changes the preload (tests/parameters/test_parameters.py);
    in tandem F_A + F_B stays the set's force, and a shaft longer than the housing loads B."""
    temps = (T0 + housing_rise, T0 + shaft_rise, T0, T0)
    th, ls = _state(TANDEM, temps)
    fa, fb = float(ls.force_a), float(ls.force_b)
    assert fa + fb == pytest.approx(P0, rel=1e-9)  # the root finders: 1e-16 m
    d = _mismatch(TANDEM, shaft_rise, housing_rise)
    assert float(ls.offset_b - ls.offset_a) == pytest.approx(d, rel=1e-12)
    assert (fb > fa) == (d > 0) and abs(fb - fa) > 1.0  # N: a 2 K mismatch moves newtons
    assert float(axial_force(ls.offset_a, th.geometry)) == pytest.approx(fa, rel=1e-12)
    # the same parts face-to-face: the preload itself moves
    _, df = _state(BASE | {"preload_method": "force", "assembly_preload": P0}, temps)
    assert abs(float(df.preload) - P0) > 1.0


def test_a_large_mismatch_unloads_bearing_a():
    _, ls = _state(TANDEM, (T0, T0 + 10.0, T0, T0))  # 12.6 µm of shaft growth
    assert float(ls.force_a) == 0.0 and float(ls.force_b) == pytest.approx(P0, rel=1e-9)
    assert ls.unloaded  # one bearing has lost its load: the flag's meaning for every pair


def test_a_spring_preload_follows_the_sets_displacement():
    k_s, c = 1e5, P0 / 1e5  # N/m, m
    spring = TANDEM | {"preload_method": "spring", "spring_stiffness": k_s,
                       "spring_compression": c}  # fmt: skip
    _, cold = _state(spring, (T0,) * 4)
    assert float(cold.force_a + cold.force_b) == pytest.approx(P0, rel=1e-12)
    _, warm = _state(spring, (T0, T0 + 10.0, T0, T0))
    moved = float(warm.offset_a - cold.offset_a)  # the set moves back as B takes the thrust
    assert moved < 0
    assert float(warm.force_a + warm.force_b) == pytest.approx(k_s * (c - moved), rel=1e-12)
    # stiffness k_A + k_B + k_s: the displacement under a small added load
    th, base = _state(spring, (T0,) * 4)
    _, pushed = _state(spring, (T0,) * 4, axial_load=0.01)
    step = float(pushed.axial_displacement - base.axial_displacement)
    assert 0.01 / step == pytest.approx(float(base.axial_stiffness), rel=1e-4)
    ka = float(axial_state(th.geometry, base.offset_a).axial_stiffness)
    assert float(base.axial_stiffness) == pytest.approx(2 * ka + k_s, rel=1e-12)


def test_an_axial_load_along_the_thrust_adds_to_it():
    _, ls = _state(TANDEM, (T0,) * 4, axial_load=10.0)
    assert float(ls.force_a) == pytest.approx(25.0, rel=1e-12)
    assert float(ls.force_b) == pytest.approx(25.0, rel=1e-12)
    assert float(ls.axial_displacement) > 0


def test_a_radial_load_is_shared_and_the_thrust_kept():
    th, ls = _state(TANDEM, (T0, T0 + 2.0, T0, T0), axial_load=5.0, radial_load=30.0)
    assert ls.converged
    assert ls.force_a + ls.force_b == pytest.approx(P0 + 5.0, rel=1e-9)
    st = tandem_equilibrium(th.geometry, float(th.closure), 0.0, P0, 5.0, 30.0)
    assert float(st.balls_a.radial_force[0]) == pytest.approx(15.0, rel=1e-9)
    assert float(st.balls_b.radial_force[0]) == pytest.approx(15.0, rel=1e-9)
    assert st.offset_b - st.offset_a == pytest.approx(_mismatch(TANDEM, 2.0), rel=1e-12)
    # a vanishing radial load gives the axial solution
    _, axial = _state(TANDEM, (T0, T0 + 2.0, T0, T0), axial_load=5.0)
    _, tiny = _state(TANDEM, (T0, T0 + 2.0, T0, T0), axial_load=5.0, radial_load=1e-6)
    assert tiny.force_a == pytest.approx(float(axial.force_a), rel=1e-6)


def test_what_a_tandem_pair_cannot_have_is_refused():
    with pytest.raises(ValueError, match="arrangement = tandem needs preload_method = spring"):
        pair_from_parameters(TANDEM | {"preload_method": "shim"})
    m = pair_from_parameters(TANDEM).mounting
    rings = LoopMember("bearings", "closing", 0.014, m.loop.members[0].material)
    loop = dataclasses.replace(m.loop, members=(*m.loop.members, rings))
    with pytest.raises(ValueError, match="'bearings' cannot be in a tandem pair"):
        Mounting(**{**{f.name: getattr(m, f.name) for f in dataclasses.fields(m)}, "loop": loop})
    with pytest.raises(ValueError, match="not valid for the screw's support pair"):
        check_support_pair(pair_from_parameters(TANDEM))


def test_the_per_step_model_is_the_exact_path():
    model = BearingModel(pair_from_parameters(TANDEM))
    for temps, fa, fr in (((T0,) * 4, 0.0, 0.0), ((T0, T0 + 2.0, T0, T0), 5.0, 0.0),
                          ((T0 - 30.0,) * 4, 2.0, 10.0)):  # fmt: skip
        got = model.evaluate(temps, 0.2, fa, fr)
        _, ls = _state(TANDEM, temps, fa, fr)
        assert got.force_a == pytest.approx(float(ls.force_a), rel=1e-9)
        assert got.force_b == pytest.approx(float(ls.force_b), rel=1e-9)
    assert model.steps == 3 and model.exact_steps == 0  # the continuation, from its start


def test_the_fmu_runs_a_tandem_pair_as_the_library_does(fmus):
    values = {"arrangement": "tandem", "preload_method": "force", "assembly_preload": P0}
    fmu = Fmu(fmus["BearingFriction"], "tandem").init(**values)
    assert not [m for s, m in fmu.log if s >= 2], fmu.log
    model = BearingModel(pair_from_parameters(default_parameters() | values))
    for t, w, fa, fr in ((293.15, 0.17, 0.0, 0.0), (253.15, -0.2, 5.0, 0.0),
                         (313.15, 0.5, 2.0, 3.0)):  # fmt: skip
        fmu.set(temperature=t, speed=w, axial_load=fa, radial_load=fr)
        fmu.slave.doStep(0.0, 1e-3)
        out = model.evaluate(t, w, fa, fr)
        got = fmu.get("running_torque", "preload", "axial_stiffness")
        want = (out.running_torque, out.preload, out.axial_stiffness)
        np.testing.assert_allclose(got, want, rtol=1e-12)
    fmu.close()


def test_the_tandem_examples_run():
    import doctest

    from servofmu.physics.drives import actuator
    from servofmu.physics.pair import configuration as pair
    from servofmu.physics.pair import preload

    names = {"tandem_offsets", "tandem_axial_stiffness", "tandem_equilibrium", "is_tandem",
             "tandem_preload", "check_support_pair"}  # fmt: skip
    runner = doctest.DocTestRunner()
    found = set()
    for module in (preload, pair, actuator):
        for t in doctest.DocTestFinder().find(module):
            if t.name.rsplit(".", 1)[-1] in names and t.examples:
                found.add(t.name.rsplit(".", 1)[-1])
                runner.run(t)
    assert found == names and runner.summarize(verbose=False).failed == 0


_Q = '{ value = %s, unit = "%s", kind = "assumed", ref = "test" }'
# a user's tandem set on Yu's rigid tube: its own loop (no rings member), a 40 N force
_USER_TANDEM = f"""
[mountings.my_tandem]
base = "yu2017_gimbal_rigid"
name = "a tandem set on Yu's tube"
arrangement = "tandem"
assembly_preload = {_Q % (40, "N")}

[[mountings.my_tandem.loop]]
name = "frame"
role = "opening"
material = "cast_aluminium"
length = {_Q % (12, "mm")}

[[mountings.my_tandem.loop]]
name = "shaft"
role = "closing"
material = "steel_45"
length = {_Q % (12, "mm")}
"""


def test_a_user_catalogue_tandem_set_is_the_same_model_as_its_numbers(tmp_path, capsys):
    from servofmu.build import catalogs
    from servofmu.cli import main
    from servofmu.physics.bearing import BearingPair

    path = tmp_path / "tandem.toml"
    path.write_text(_USER_TANDEM)
    assert main(["catalog", "--catalog", str(path), "--preset", "my_tandem"]) == 0
    out = capsys.readouterr().out
    assert re.search(r"arrangement +tandem", out) and re.search(r"preload_method +force", out)
    catalogs.load([path])
    try:
        library = BearingModel(BearingPair.from_catalog("my_tandem", "krytox_143aa"))
        numbers = BearingModel(pair_from_parameters(default_parameters("my_tandem")))
    finally:
        catalogs.unload()
    for temps in ((T0,) * 4, (T0, T0 + 3.0, T0, T0), (T0 - 40.0,) * 4):
        a, b = library.evaluate(temps, 0.2, 2.0), numbers.evaluate(temps, 0.2, 2.0)
        assert (a.force_a, a.force_b, a.running_torque) == (b.force_a, b.force_b, b.running_torque)
    # the aluminium frame shrinks more than the steel shaft between the bearings: B loads up
    cold = numbers.evaluate((T0 - 40.0,) * 4, 0.2, 0.0)
    assert cold.force_b > cold.force_a and cold.force_a + cold.force_b == pytest.approx(P0)


def test_a_user_tandem_set_with_a_rings_member_is_refused_naming_it(tmp_path, capsys):
    from servofmu.cli import main

    path = tmp_path / "tandem.toml"
    text = _USER_TANDEM.split("[[mountings.my_tandem.loop]]")[0]  # the base's loop, rings in it
    path.write_text(text)
    assert main(["build", "--catalog", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert str(path) in err and "mountings.my_tandem" in err, err
    assert "loop member 'bearings' cannot be in a tandem pair" in err, err

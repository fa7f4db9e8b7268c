"""Forces a user can read: ``preload`` is never negative, the play of an unloaded pair is its
own output (``axial_play``), and a bearing loaded on the other flanks of its grooves says so
(``reverse_loaded``): on random trajectories of every arrangement (hypothesis) and at the
states where the mean axial force (F_A + F_B)/2 is negative (found by fuzzing the FMU).

The expected values are the model's own definitions evaluated by hand from its forces and
offsets (preload = max((F_A + F_B)/2, 0), play = Σ over unloaded bearings of h − a)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from servofmu.parameters.bearing import default_parameters, pair_from_parameters
from servofmu.physics.bearing import BearingModel, thermal_state
from servofmu.physics.contact.geometry import first_contact_offset
from servofmu.physics.pair.state import axial_play, operating_outputs, preload_force
from servofmu.physics.thermal.temperatures import PartTemperatures

RIGID = default_parameters("yu2017_gimbal_rigid") | {"outer_interference": 0.0}
ARRANGEMENTS = {
    "face_to_face": default_parameters(),  # Yu's gimbal (yoke)
    "back_to_back": default_parameters("ning_space_shaft"),
    "tandem": RIGID | {"arrangement": "tandem", "preload_method": "force", "assembly_preload": 40},
    "tandem_spring": RIGID
    | {
        "arrangement": "tandem",
        "preload_method": "spring",
        "spring_stiffness": 2.0e5,
        "spring_compression": 2.0e-4,
    },
}
PAIRS = {k: pair_from_parameters(p) for k, p in ARRANGEMENTS.items()}

temperature = st.floats(173.15, 473.15)
step = st.tuples(
    temperature,  # housing [K]
    temperature,  # shaft [K]
    st.floats(-1.0e4, 1.0e4) | st.sampled_from([0.0, -40.0, 40.0, -1.0e4]),  # axial load [N]
    st.sampled_from([0.0, 0.0, 0.0, 5.0, 50.0]),  # radial load [N]
)


def _check(out):
    """The definitions, by hand from the outputs' forces (and the flags they imply)."""
    fa, fb = out.force_a, out.force_b
    assert out.preload >= 0.0
    assert out.preload == pytest.approx(max(0.5 * (fa + fb), 0.0), rel=1e-12, abs=1e-12)
    assert out.axial_play >= 0.0
    assert out.reverse_loaded == (fa < 0.0 or fb < 0.0)
    if out.axial_play > 0.0:
        assert out.unloaded
    if out.reverse_loaded:
        assert out.unloaded


@pytest.mark.parametrize("arrangement", sorted(ARRANGEMENTS))
@settings(max_examples=15, deadline=None, derandomize=True)
@given(trajectory=st.lists(step, min_size=1, max_size=8))
def test_preload_is_never_negative_on_random_trajectories(arrangement, trajectory):
    model = BearingModel(PAIRS[arrangement])
    for housing, shaft, axial, radial in trajectory:
        temps = (housing, shaft, housing, shaft)  # the rings at their seats' temperatures
        _check(model.evaluate(temps, 0.17, axial, radial))


@pytest.mark.parametrize(
    "arrangement, temps, axial, mean",
    [
        # found by fuzzing BearingFriction: the mean of the two forces was negative there
        ("face_to_face", (473.15,) * 4, -40.0, -20.0),  # the loop opened by the frame's growth
        ("face_to_face", (473.15, 173.15, 473.15, 173.15), 0.0, -72.9),  # housing_shaft mode
        ("tandem", (293.15,) * 4, -1.0e4, -4980.0),  # a reverse load 250 × the thrust
    ],
)
def test_the_negative_mean_states_report_no_preload(arrangement, temps, axial, mean):
    pair = PAIRS[arrangement]
    for out in (
        BearingModel(pair).evaluate(temps, 0.17, axial),
        operating_outputs(pair, PartTemperatures(*temps), 0.17, axial),
    ):
        fa, fb = float(out.force_a), float(out.force_b)
        assert 0.5 * (fa + fb) == pytest.approx(mean, abs=0.05 * abs(mean))  # still there
        assert float(out.preload) == 0.0
        assert bool(out.unloaded) and bool(out.reverse_loaded)
        if fa < 0.0:  # A's balls on the other flanks: its contact angle changes sign
            assert float(out.contact_angle) < 0.0


def test_axial_play_of_an_open_loop_is_2h_minus_c():
    """Yu's gimbal at 473 K: the aluminium frame has grown the loop open; with no load and
    N = 0 both bearings sit at a = C/2 and the play is 2h − C (h from the operating clearance
    and curvature distance, by :func:`first_contact_offset`; C the loop closure)."""
    pair = PAIRS["face_to_face"]
    th = thermal_state(pair, 400.0)
    h = first_contact_offset(float(th.clearance), float(th.geometry.curvature_distance))
    closure = float(th.closure)
    assert abs(closure) < 2 * h  # between the reverse and the forward contacts: N = 0
    out = BearingModel(pair).evaluate(400.0, 0.17)
    assert out.force_a == out.force_b == 0.0 and out.preload == 0.0
    assert out.axial_play == pytest.approx(2 * h - closure, rel=1e-9)
    assert out.axial_play > 100e-6  # m: over 0.1 mm of play at 127 °C


def test_a_preloaded_pair_has_no_play_and_the_unloaded_bearing_under_load_has():
    pair = PAIRS["face_to_face"]
    model = BearingModel(pair)
    assert model.evaluate(293.15, 0.17).axial_play == 0.0  # 8.4 N of preload
    out = model.evaluate(293.15, 0.17, -30.0)  # 30 N towards B: B carries it, A lifts off
    assert out.unloaded and not out.reverse_loaded
    th = model.thermal(293.15)
    h = float(th.geometry.first_contact_offset)
    a_a = float(model.load(293.15, -30.0).offset_a)
    assert out.axial_play == pytest.approx(h - a_a, rel=1e-6)  # A's gap (B carries 30 N)


def test_the_definitions_on_floats_and_arrays_agree():
    import numpy as np

    fa, fb = np.array([10.0, -5.0, 0.0]), np.array([30.0, -7.0, 4.0])
    assert list(preload_force(fa, fb)) == [20.0, 0.0, 2.0]
    assert [preload_force(float(a), float(b)) for a, b in zip(fa, fb, strict=True)] == [
        20.0,
        0.0,
        2.0,
    ]
    h, a, b = 60e-6, np.array([70e-6, 20e-6, -80e-6]), np.array([65e-6, 30e-6, 65e-6])
    arr = axial_play(h, a, b, np.array([5.0, 0.0, -3.0]), np.array([4.0, 0.0, 6.0]))
    floats = [
        axial_play(h, float(x), float(y), f, g)
        for x, y, f, g in zip(a, b, [5.0, 0.0, -3.0], [4.0, 0.0, 6.0], strict=True)
    ]
    assert list(arr) == pytest.approx(floats, abs=1e-20)
    assert floats == pytest.approx([0.0, 70e-6, 140e-6], abs=1e-18)
    assert math.isclose(floats[2], h - (-80e-6))

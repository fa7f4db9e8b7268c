import math

import numpy as np
import pytest

from servofmu.parameters import catalog
from servofmu.physics.bearing import effective_shim, loop_closure, thermal_state
from servofmu.physics.contact.equilibrium import axial_force, axial_state, offset_for_axial_force
from servofmu.physics.pair.preload import (
    loop_interference,
    pair_axial_stiffness,
    pair_equilibrium,
    pair_offsets,
    shim_for_preload,
)


@pytest.fixture(scope="module")
def geom(b71803):
    return b71803.race_geometry()


def test_loop_interference_signs():
    stated = catalog.mounting("yu2017_gimbal").loop
    printed = catalog.mounting("yu2017_gimbal_printed").loop
    t0 = 293.15
    # stated: the aluminium frame (118 mm) shrinks more than steel shaft and bearings on
    # cooling: +(118·21.7 − 108·11.7 − 10·11.7)e-6 mm = +1.1800 µm per kelvin of cooling
    assert loop_interference(stated, t0 - 1, t0) - stated.shim == pytest.approx(1.1800e-6, rel=1e-9)
    # printed (steel frame, aluminium shaft): 118·11.7 − 108·21.7 → −0.9630 µm per kelvin
    assert loop_interference(printed, t0 - 1, t0) - printed.shim == pytest.approx(
        -0.9630e-6, rel=1e-4
    )


def test_rigid_pair_unloads_at_2_83_times_the_preload(geom):
    # Harris: a rigidly preloaded pair of identical bearings with Q ∝ δ^1.5 at a constant
    # contact angle unloads its second bearing at F_ext = 2^1.5·P. The contact angle grows
    # with load here, so the ratio tends to 2^1.5 as P → 0 and rises above it with P.
    ratios = []
    for p in (0.01, 1.0, 40.0):
        closure = 2 * float(offset_for_axial_force(geom, p))
        f_ext = np.linspace(2.5 * p, 4.0 * p, 1501)
        off = pair_offsets(geom, np.full_like(f_ext, closure), math.inf, f_ext)
        np.testing.assert_allclose(off.force_a - off.force_b, f_ext, rtol=1e-9, atol=1e-12)
        ratios.append(f_ext[np.flatnonzero(off.force_b <= 1e-12 * p)[0]] / p)
    assert ratios[0] == pytest.approx(2**1.5, rel=2e-3)
    assert ratios[0] < ratios[1] < ratios[2]


def test_compliant_loop_compatibility(geom):
    k, closure = 2e7, 2 * 70e-6
    for f_ext in (0.0, 15.0, -30.0):
        off = pair_offsets(geom, closure, k, f_ext)
        assert float(off.force_a - off.force_b) == pytest.approx(f_ext, abs=1e-9)
        lhs = off.offset_a + off.offset_b + off.loop_force / k
        assert float(lhs) == pytest.approx(closure, rel=1e-12)


def test_pair_stiffness_is_the_derivative_of_the_load(geom):
    k, closure, h = 5e7, 2 * 70e-6, 1e-3
    off = pair_offsets(geom, closure, k, np.array([20.0 - h, 20.0, 20.0 + h]))
    dz = np.diff((off.offset_a - off.offset_b) / 2)
    num = 2 * h / (dz[0] + dz[1])
    ka = float(axial_state(geom, off.offset_a[1]).axial_stiffness)
    kb = float(axial_state(geom, off.offset_b[1]).axial_stiffness)
    assert float(pair_axial_stiffness(ka, kb, k)) == pytest.approx(num, rel=1e-4)
    assert float(pair_axial_stiffness(ka, ka, math.inf)) == pytest.approx(2 * ka)


def test_shim_for_preload_round_trip(geom):
    for k in (math.inf, 3e7):
        shim = shim_for_preload(geom, 100.0, k)
        closure = 2 * geom.first_contact_offset + shim
        assert float(pair_offsets(geom, closure, k).loop_force) == pytest.approx(100.0, rel=1e-9)


def test_assembly_preload_sets_the_shim(ning_pair):
    th = thermal_state(ning_pair, ning_pair.mounting.assembly_temperature)
    assert float(axial_force(th.preload_offset, th.geometry)) == pytest.approx(100.0, rel=1e-9)
    assert effective_shim(ning_pair) > 0
    assert float(loop_closure(ning_pair, ning_pair.mounting.assembly_temperature)) == pytest.approx(
        2 * float(th.preload_offset) + 100.0 / th.loop_stiffness, rel=1e-9
    )


def test_pair_equilibrium_with_radial_load(geom):
    closure, k = 2 * 72e-6, 1e8
    st = pair_equilibrium(geom, closure, k, 12.0, 30.0)
    assert st.converged
    fa, fb = float(st.balls_a.axial_force[0]), float(st.balls_b.axial_force[0])
    assert fa - fb == pytest.approx(12.0, abs=1e-7)
    assert float(st.balls_a.radial_force[0]) == pytest.approx(15.0, abs=1e-7)
    assert float(st.balls_b.radial_force[0]) == pytest.approx(15.0, abs=1e-7)
    # tends to the axial solution as the radial load vanishes
    tiny = pair_equilibrium(geom, closure, k, 12.0, 1e-9)
    ax = pair_offsets(geom, closure, k, 12.0)
    assert tiny.offset_a == pytest.approx(float(ax.offset_a), rel=1e-9)


def test_never_nan_at_extreme_closures(geom):
    off = pair_offsets(geom, np.array([-1e-3, 0.0, 1e-3]), 1e8, np.array([0.0, 50.0, -50.0]))
    assert np.all(np.isfinite(off.force_a)) and np.all(np.isfinite(off.force_b))


def test_scalar_and_vectorised_mean_offset_agree(yu_pair):
    # the per-step path solves one state with scipy's brentq, curves use the elementwise
    # Chandrupatla solver: the same root of the loop compatibility
    from servofmu.physics.bearing import thermal_state
    from servofmu.physics.pair.preload import mean_offset

    for t in (233.15, 273.15, 300.0):
        th = thermal_state(yu_pair, t)
        k = float(th.loop_stiffness)
        scalar = float(mean_offset(0.0, float(th.closure), k, th.geometry))
        vector = mean_offset(np.zeros(1), np.array([float(th.closure)]), k, th.geometry)
        assert scalar == pytest.approx(float(vector[0]), rel=1e-9, abs=1e-15)

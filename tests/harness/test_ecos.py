"""ecos (ecospy), a third co-simulation engine: every FMU alone, and every built system's
``.ssp`` run unchanged against the harness's Jacobi run.

Stated tolerance: 1e-9 of the signal's range, as for libcosim (``test_crosscheck.py``). ecos
steps every component from the outputs at the start of the step (Jacobi), applies the same
component-level .ssv values (all carry the one ParameterSet name it applies) and the same
LinearTransformations, so it computes the same numbers: the measured gap is 0. One difference
of *reading*, not of computing: ecos reads outputs after it has already passed the new
outputs along the connections, so an algebraic (feedthrough) component's output in ecos's row
k is the harness's row k + 1 — the value computed from the inputs at t_k, which the harness
only evaluates in the next step. Those outputs are compared one row shifted, and they agree
exactly too; unshifted they would differ by one step of their change.

ecospy needs Intel TBB (Debian's libtbb12, installed by ``make test`` when it runs as root);
without it the tests are skipped and the reason is printed in the summary.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_crosscheck import CASES as SYSTEMS
from test_third_party_hosts import CASES, STEP, STEPS, fmpy_reference

from servofmu.harness import load_system, run
from servofmu.harness.ecos import PARAMETER_SET, ecos_unavailable, run_ecos

REASON = ecos_unavailable()
pytestmark = pytest.mark.skipif(bool(REASON), reason=f"ecos cannot run here: {REASON}")
SYSTEM_STEPS = 300  # communication steps compared (start-up transient)


@pytest.mark.parametrize("name", sorted(CASES))
def test_ecos_runs_every_fmu_alone(fmus, name):
    from ecospy import EcosSimulation, EcosSimulationStructure

    inputs, outputs = CASES[name]
    structure = EcosSimulationStructure()
    structure.add_model(name, fmus[name])
    structure.add_parameter_set(
        PARAMETER_SET, {f"{name}::{k}": float(v) for k, v in inputs.items()}
    )
    sim = EcosSimulation(structure=structure, step_size=STEP)
    try:
        assert sim.init(parameter_set=PARAMETER_SET)
        sim.step(STEPS)
        assert sim.get_real(f"{name}::{next(iter(inputs))}") == next(iter(inputs.values()))
        got = [sim.get_real(f"{name}::{n}") for n in outputs]
        sim.terminate()
    finally:
        sim.free()
        structure.free()
    np.testing.assert_allclose(got, fmpy_reference(fmus[name], inputs, outputs), rtol=1e-12)


@pytest.mark.slow
@pytest.mark.parametrize("name", SYSTEMS)
def test_ecos_runs_every_system_like_the_harness_jacobi(fmus, name):
    archive = fmus["BearingFriction"].parent / f"{name}.ssp"
    record = SYSTEMS[name]
    system = load_system(archive)
    try:
        h = system.step_size
        jacobi = run(
            system, stop=SYSTEM_STEPS * h, record=record, algorithm="jacobi", progress=False
        )
        feedthrough = {c for c, comp in system.components.items() if comp.feedthrough}
    finally:
        system.close()
    ecos = run_ecos(archive, record, SYSTEM_STEPS * h, h)
    assert len(ecos["time"]) == len(jacobi["time"]) == SYSTEM_STEPS + 1
    np.testing.assert_allclose(ecos["time"], jacobi["time"], rtol=0, atol=1e-12)
    moved = False
    for v in record:
        scale = max(np.ptp(jacobi[v]), np.max(np.abs(jacobi[v])))
        moved |= np.ptp(jacobi[v]) > 0
        if v.partition(".")[0] in feedthrough:  # read one communication point later
            gap = np.max(np.abs(ecos[v][:-1] - jacobi[v][1:]))
        else:
            gap = np.max(np.abs(ecos[v] - jacobi[v]))
        assert gap <= 1e-9 * scale, f"{name}: {v} differs by {gap:g} (scale {scale:g})"
    assert moved, f"{name}: nothing moved, the comparison would be empty"
    if name == "space_bearing":  # ecos applied the .ssv's numbers: Ning's pair, 100 N at 20 °C
        assert ecos["bearing.preload"][0] == pytest.approx(100.0, rel=1e-6)


def test_ecos_applies_only_the_named_parameter_sets(fmus):
    """Why every .ssv carries one name: ecos applies the sets named at init, and none without
    a name (the controller then runs with the FMU's own default gain)."""
    archive = fmus["BearingFriction"].parent / "seeker_gimbal.ssp"
    system = load_system(archive)
    try:
        comp = system.components["controller"]
        bound = comp.parameters["kp"][1]
        default = comp.variables["kp"].start
    finally:
        system.close()
    assert float(bound) != float(default)
    h = 1e-3
    named = run_ecos(archive, ["controller.kp"], h, h)
    unnamed = run_ecos(archive, ["controller.kp"], h, h, parameter_set=None)
    assert named["controller.kp"][-1] == float(bound)
    assert unnamed["controller.kp"][-1] == float(default)

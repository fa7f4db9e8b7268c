import dataclasses
import itertools
import json
import math
import re

import numpy as np
import pytest

from servofmu.physics.drives import actuator as A
from servofmu.physics.kernels.units import DEG


@pytest.fixture(scope="module")
def act():
    return A.Actuator.from_catalog("liu2014_ema")


@pytest.fixture(scope="module")
def bare(act):
    """Liu's four elements only (no support bearings)."""
    return dataclasses.replace(act, support_mounting="")


def test_series_formula():
    assert A.series_stiffness(2.0, 2.0) == pytest.approx(1.0)
    assert A.series_stiffness(3.0, np.inf) == pytest.approx(3.0)  # rigid element drops out
    k = A.series_stiffness(np.array([1.0, 4.0]), 4.0)
    np.testing.assert_allclose(k, [0.8, 2.0])
    with pytest.raises(ValueError, match=re.escape("stiffness[1] = -1.0")):
        A.series_stiffness(1.0, -1.0)


def test_lever_is_the_derivative_of_the_exact_position(act):
    d = np.linspace(-30, 30, 13) * DEG
    h = 1e-7
    num = (A.kinematics(act, d + h).nut_position - A.kinematics(act, d - h).nut_position) / (2 * h)
    np.testing.assert_allclose(A.kinematics(act, d).lever, num, rtol=1e-7)


def test_eq10_11_agree_with_virtual_work(act):
    # F3 = M·cos γ/(L1·sin β) (eq 10–11) must equal M/|dx/dθ| (virtual work)
    d = np.linspace(-30, 30, 13) * DEG
    kin = A.kinematics(act, d)
    eq11 = 100.0 * np.cos(kin.rod_angle) / (act.crank_length * np.sin(kin.transmission_angle))
    np.testing.assert_allclose(A.screw_force(act, d, 100.0), eq11, rtol=1e-12)


def test_ratio_limits_and_symmetry(act):
    r0 = A.reduction_ratio(act, 0.0)
    assert float(r0.linkage) == pytest.approx(1.0, abs=1e-12)  # rod square to crank at 0°
    assert float(r0.total) == pytest.approx(
        act.gear_ratio * 2 * math.pi * act.crank_length / act.screw_lead
    )
    d = np.linspace(0, 30, 31) * DEG
    up, down = A.reduction_ratio(act, d).total, A.reduction_ratio(act, -d).total
    # finite rod: γ is even in δ (sin γ = L1·(cos δ − 1)/L2), and with θ = 90° + δ
    # |dx/dθ| = L1·(cos δ − sin δ·tan γ), so the curve's odd part is exactly
    # −2·L1·sin δ·tan γ (scaled by i/|dx/dθ|) and its even part 2·L1·cos δ
    gamma = A.kinematics(act, d).rod_angle
    np.testing.assert_allclose(gamma, A.kinematics(act, -d).rod_angle, atol=1e-15)
    scale = float(r0.total) / act.crank_length
    np.testing.assert_allclose(
        up - down, -2 * scale * act.crank_length * np.sin(d) * np.tan(gamma), atol=1e-9
    )
    np.testing.assert_allclose(up + down, 2 * scale * act.crank_length * np.cos(d), rtol=1e-12)
    assert np.all(np.diff(up + down) < 0)  # the even part is largest at the neutral position
    # infinite rod (Scotch yoke): |dx/dθ| = L1·cos δ exactly, hence exactly symmetric
    yoke = dataclasses.replace(act, rod_length=1e6)
    np.testing.assert_allclose(A.reduction_ratio(yoke, d).linkage, np.cos(d), rtol=1e-6)


def test_linkage_axial_part_matches_castigliano(act):
    # independent small-deflection calculation: δθ = (N1²·L1/(E·A1) + N2²·L2/(E·A2))/M with
    # N2 = M/(L1·sin β), N1 = N2·cos β (energy of the two two-force members)
    axial_only = dataclasses.replace(act, shaft_polar_moment=1e6, arm_second_moment=1e6)
    for deg in (-25.0, 0.0, 10.0, 30.0):
        m = 50.0
        kin = A.kinematics(act, deg * DEG)
        n2 = m / (act.crank_length * math.sin(kin.transmission_angle))
        n1 = n2 * math.cos(kin.transmission_angle)
        e = act.youngs_modulus
        ref = (
            n1**2 * act.crank_length / (e * act.crank_area)
            + n2**2 * act.rod_length / (e * act.rod_area)
        ) / m
        assert float(A.linkage_rotation(axial_only, deg * DEG, m)) == pytest.approx(ref, rel=1e-4)


def test_torsion_and_bending_terms(act):
    # eq 17 and eq 18–19 (with I): rigid members leave M·l/(G·I1) + arctan(M·l²/(3·E·I·L1))
    rigid = dataclasses.replace(act, crank_area=1e6, rod_area=1e6)
    m = 200.0
    ref = m * act.arm_length / (act.shear_modulus * act.shaft_polar_moment) + math.atan(
        m * act.arm_length**2 / (3 * act.youngs_modulus * act.arm_second_moment * act.crank_length)
    )
    assert float(A.linkage_rotation(rigid, 0.1, m)) == pytest.approx(ref, rel=1e-6)


def test_eq9_to_20_are_linear_in_load(bare):
    k = A.linkage_stiffness(bare, 10 * DEG, np.array([1.0, 100.0, 300.0]))
    np.testing.assert_allclose(k, k[0], rtol=1e-4)


def test_liu_reflected_values_hold_at_the_reference_angle(bare):
    b = A.stiffness_breakdown(bare, 10 * DEG, 100.0)
    assert float(A.per_degree(b.gear)) == pytest.approx(1096623.0, rel=1e-9)
    assert float(A.per_degree(b.screw)) == pytest.approx(8256825.0, rel=1e-9)
    assert float(A.per_degree(b.housing)) == pytest.approx(1696.8, rel=1e-9)
    assert np.isinf(b.support_bearing)
    assert float(b.deflection) == pytest.approx(100.0 / float(b.total))


def test_support_bearing_stiffens_with_load_and_moves_with_temperature(act):
    k = A.support_axial_stiffness(act, np.array([500.0, 2000.0, 6000.0]), 293.15)
    assert np.all(np.diff(k) > 0)
    kt = A.support_axial_stiffness(act, 2000.0, np.array([233.15, 293.15, 333.15]))
    assert np.ptp(kt) > 0  # preload follows the thermal coupling
    assert A.support_axial_stiffness(act, 0.0, 293.15) > 0  # tangent at zero load


def test_vectorised_broadcasting(act):
    b = A.stiffness_breakdown(
        act, np.linspace(-0.3, 0.3, 7)[:, None], 150.0, np.array([250.0, 300.0])
    )
    assert b.total.shape == (7, 2)
    shares = sum(b.share(e) for e in A.StiffnessBreakdown.ELEMENTS)
    np.testing.assert_allclose(shares, 1.0)


def _in_line_at(act, theta0):
    """Geometry with the slide through the shaft axis (Y1 = 0): crank and rod in line at θ = 0."""
    gamma0 = math.asin(act.crank_length * math.sin(theta0) / act.rod_length)
    return dataclasses.replace(act, neutral_crank_angle=theta0, neutral_rod_angle=gamma0)


@pytest.mark.parametrize(
    "call, match",
    [
        (
            lambda a: A.kinematics(dataclasses.replace(a, rod_length=0.06), 2.5),
            "outside the linkage's reach",
        ),
        (lambda a: A.kinematics(a, float("nan")), "output_angle = nan"),
        (lambda a: dataclasses.replace(a, rod_length=-0.1), "rod_length = -0.1"),
        (lambda a: dataclasses.replace(a, housing_stiffness=0.0), "housing_stiffness = 0.0"),
        (lambda a: dataclasses.replace(a, neutral_rod_angle=2.0), "neutral_rod_angle = 2.0"),
        (lambda a: A.kinematics(_in_line_at(a, 0.5), -0.5), "dead centre"),
        (lambda a: A.stiffness_breakdown(a, 0.1, 100.0, -3.0), "temperature = -3.0 K"),
        (lambda a: A.screw_force(a, 0.1, float("inf")), "load_torque = inf"),
    ],
)
def test_bad_input(act, call, match):
    with pytest.raises(ValueError, match=re.escape(match)):
        call(act)


def test_data_file_holds_the_code_calibration(act):
    from servofmu.papers import liu2014

    _, fit = liu2014.calibrated_actuator()
    for name, value in fit.items():
        assert getattr(act, name) == pytest.approx(value, rel=1e-6), name


# ----------------------------------------------------------------------------- motor side
def test_motor_angle_is_the_integral_of_the_reduction_ratio(act):
    """dφ/dδ = i (Liu eq 4): the motor angle of the exact nut travel against the ratio
    integrated numerically (Simpson, 2001 points), and φ(0) = 0."""
    from scipy.integrate import simpson

    delta = np.linspace(0.0, math.radians(40.0), 2001)
    integral = simpson(A.reduction_ratio(act, delta).total, x=delta)
    assert A.motor_angle(act, 0.0) == 0.0
    assert float(A.motor_angle(act, delta[-1])) == pytest.approx(integral, rel=1e-10)
    assert np.all(np.diff(A.motor_angle(act, np.linspace(-1.2, 1.5, 500))) > 0)


def test_output_angle_inverts_motor_angle_in_closed_form(act):
    delta = np.linspace(-1.2, 1.5, 1001)
    back = A.output_angle(act, A.motor_angle(act, delta))
    np.testing.assert_allclose(back, delta, rtol=0, atol=1e-13)
    # the linearisation the SSP used before (φ/i0, the ratio at neutral) is not exact: the
    # ratio falls from i0 to i(10°), so the error lies between 0 and (1 − i(10°)/i0)·10°
    i0, i10 = (float(A.reduction_ratio(act, d).total) for d in (0.0, 10 * DEG))
    linear = float(A.motor_angle(act, 10 * DEG)) / i0
    assert 0.01 * DEG < 10 * DEG - linear < (1 - i10 / i0) * 10 * DEG


def test_output_angle_refuses_motor_angles_beyond_the_dead_centres(act):
    with pytest.raises(ValueError, match=r"motor_angle = 300\.0 rad is outside .*dead centre"):
        A.output_angle(act, 300.0)
    with pytest.raises(ValueError, match=r"motor_angle = nan"):
        A.output_angle(act, float("nan"))
    # the reach in the message is where the crank and rod are in line (lever dx/dθ = 0)
    message = ""
    try:
        A.output_angle(act, [0.0, -1e3])
    except ValueError as exc:
        message = str(exc)
    lo, hi = (float(x) for x in re.search(r"\(([-\d.e+]+), ([-\d.e+]+)\) rad", message).groups())
    for phi in (lo, hi):
        inside = phi * (1 - 1e-7)
        lever = A.kinematics(act, A.output_angle(act, inside)).lever
        assert abs(lever) < 2e-3 * act.crank_length  # close to the dead centre


def test_new_examples_run():
    import doctest

    from servofmu.fmus import interpreter_exit

    for module in (A, interpreter_exit):
        finder = doctest.DocTestFinder()
        names = {"motor_angle", "output_angle", "fmu_binary", "register_interpreter_finaliser"}
        tests = [t for t in finder.find(module) if t.name.rsplit(".", 1)[-1] in names]
        runner = doctest.DocTestRunner()
        for t in tests:
            runner.run(t)
        assert tests and runner.summarize(verbose=False).failed == 0


def _breakdown_fields():
    return [f.name for f in dataclasses.fields(A.StiffnessBreakdown)]


@pytest.mark.slow
@pytest.mark.parametrize("support", [True, False])
def test_per_step_model_equals_the_vectorised_path_along_a_trajectory(act, bare, support):
    # ActuatorModel (floats, the support pair by continuation) against stiffness_breakdown
    # (numpy, the support pair solved exactly): angle, moment (through zero, where the
    # linkage takes its secant at SMALLEST_MOMENT and the support pair its tangent) and
    # temperature change every step
    a = act if support else bare
    model = A.ActuatorModel(a)
    rng = np.random.default_rng(5)
    n = 40
    angles = 0.3 * np.sin(np.linspace(0.0, 3.0, n))
    moments = np.linspace(-120.0, 250.0, n) + rng.normal(0.0, 2.0, n)
    moments[n // 3] = 0.0
    temps = np.linspace(233.15, 343.15, n)
    for i in range(n):
        fast = model.evaluate(float(angles[i]), float(moments[i]), float(temps[i]))
        exact = A.stiffness_breakdown(a, angles[i], moments[i], temps[i])
        for name in _breakdown_fields():
            want = float(getattr(exact, name))
            assert getattr(fast, name) == pytest.approx(want, rel=1e-9, abs=0.0), (i, name)
    if support:
        assert model._bearings.exact_steps <= 2


def test_per_step_model_restores_bit_for_bit(act):
    steps = [(0.17 + 0.01 * k, 150.0 + 5.0 * k, 263.15 + 0.5 * k) for k in range(30)]
    a = A.ActuatorModel(act)
    for args in steps[:15]:
        a.evaluate(*args)
    saved = json.loads(json.dumps(a.state()))
    rest_a = [a.evaluate(*args) for args in steps[15:]]
    b = A.ActuatorModel(act)
    b.restore(saved)
    assert [b.evaluate(*args) for args in steps[15:]] == rest_a


@pytest.mark.parametrize(
    "args, match",
    [
        ((float("nan"), 100.0, 293.15), "output_angle = nan rad"),
        ((0.1, float("inf"), 293.15), "load_torque = inf N·m"),
        ((0.1, 100.0, -3.0), "temperature = -3.0 K"),
    ],
)
def test_per_step_model_names_bad_input(act, args, match):
    with pytest.raises(ValueError, match=re.escape(match)):
        A.ActuatorModel(act).evaluate(*args)


def test_per_step_model_refuses_angles_beyond_the_reach_like_the_vectorised_path(bare):
    short = dataclasses.replace(bare, rod_length=0.03)  # sin γ reaches −1 near δ = 1.3 rad
    with pytest.raises(ValueError, match="outside the linkage's reach") as vectorised:
        A.stiffness_breakdown(short, 1.5, 100.0)
    with pytest.raises(ValueError) as per_step:
        A.ActuatorModel(short).evaluate(1.5, 100.0, 293.15)
    assert str(per_step.value) == str(vectorised.value)


def test_a_support_pair_with_play_is_named_where_it_holds_nothing():
    """Without preload (a shim of 0) the support pair has axial play: under a hinge moment its
    balls are loaded and the actuator has a stiffness, at zero moment it has none, and the
    per-step model says so naming the element instead of dividing by zero."""
    from servofmu.parameters.bearing import default_parameters, pair_from_parameters

    p = default_parameters("liu2014_screw_support", lubricant="mos2_film")
    p.update(preload_method="shim", shim=0.0)
    model = A.ActuatorModel(A.Actuator.from_catalog("liu2014_ema"), pair_from_parameters(p))
    assert model.evaluate(0.17, 100.0, 293.15).total > 0.0
    with pytest.raises(ValueError, match=r"support_bearing_stiffness = 0\.0 N/m.*axial play"):
        model.evaluate(0.17, 0.0, 293.15)


def _support_law(temperature, screw_force):
    """A stand-in for the support pair's state (axial_displacement [m], axial_stiffness
    [N/m]): Hertzian-like Δz ∝ F^(2/3), softer when warm, and no stiffness at all below 1 N
    above 400 K (a pair that lost its preload). The same function for both implementations,
    so that their arithmetic is compared alone."""
    from types import SimpleNamespace

    soft = 1.0 + 1e-3 * (temperature - 293.15)
    return SimpleNamespace(
        axial_displacement=2e-8 * soft * screw_force ** (2.0 / 3.0),
        axial_stiffness=0.0 if temperature > 400.0 else 3e7 / soft,
    )


def _steppers(act, support, gear_stiffness=None):
    """{implementation: ActuatorStepper of ``act``} (``gear_stiffness``: one the actuator
    record would refuse)."""
    from kernels import implementations

    from servofmu.physics import compiled

    out = {}
    for impl in implementations():
        mod = compiled.module("drives.stepping", impl)
        out[impl] = mod.ActuatorStepper(
            A.crank_slider(act, mod),
            act.neutral_crank_angle,
            act.gear_ratio,
            act.screw_lead,
            act.gear_stiffness if gear_stiffness is None else gear_stiffness,
            act.screw_stiffness,
            act.housing_stiffness,
            act.seat_stiffness,
            support,
        )
    return out


def _outcome(stepper, *args):
    try:
        return stepper.evaluate(*args)
    except (ValueError, ZeroDivisionError) as exc:
        return f"{type(exc).__name__}: {exc}"


@pytest.mark.parametrize("support", [None, _support_law])
def test_per_step_update_is_the_same_on_both_kernel_paths_and_the_vectorised_one(bare, support):
    # the FMU's one call per step, compiled and Python side by side over angles up to the
    # reach, moments through zero (the secant at SMALLEST_MOMENT, the support's tangent below
    # SMALLEST_SCREW_FORCE) and temperatures: the same bits (the same operations in the same
    # order, libm's functions on both paths), and the same errors. Against the vectorised
    # path (numpy's elementary functions, which may differ from libm's in the last bit):
    # 1e-12 relative on the lever's elements; the linkage's rotation Δθ = M/K_rod is the
    # difference of two crank angles of about 1 rad (eq 14-16), so it agrees to a few of
    # their last bits, 2e-15 rad (at 1e-3 N·m, Δθ ≈ 2e-8 rad: 1e-7 relative)
    a = dataclasses.replace(bare, seat_stiffness=4e8) if support else bare
    steppers = _steppers(a, support)
    angles = [*np.linspace(-1.4, 1.4, 29), 1.5]  # 1.5 rad: a short rod cannot reach it
    moments = [-900.0, -50.0, -1e-4, -0.0, 0.0, 5e-324, 2e-4, 0.5, 75.0, 1800.0]
    errors = set()
    for delta, m, t in itertools.product(angles, moments, (233.15, 353.15, 420.0)):
        results = {impl: _outcome(s, float(delta), m, t) for impl, s in steppers.items()}
        assert len(set(results.values())) == 1, (delta, m, t, results)
        got = results["python"]
        if isinstance(got, str):
            errors.add((t, abs(m) < 0.01, got.split(" = ")[0]))
            continue
        want = A.stiffness_breakdown(a, delta, m, t, support=lambda f3, t: np.inf)
        for name, value in zip(_breakdown_fields(), got, strict=True):
            if name in ("gear", "screw", "housing", "reduction_ratio", "screw_force"):
                assert value == pytest.approx(float(getattr(want, name)), rel=1e-12, abs=0)
        probe = m if abs(m) >= A.SMALLEST_MOMENT else math.copysign(A.SMALLEST_MOMENT, m)
        assert probe / got[2] == pytest.approx(probe / float(want.linkage), rel=0, abs=2e-15)
    # only where the stand-in pair has no preload (warm) and carries (almost) no force
    assert errors == (
        {(420.0, True, "ValueError: support_bearing_stiffness")} if support else set()
    )


def test_per_step_update_refuses_the_same_points_with_the_same_messages_on_both_paths(bare):
    half_pi = 1.5707963267948966
    flat = dataclasses.replace(
        bare,
        neutral_crank_angle=half_pi,
        neutral_rod_angle=math.asin(bare.crank_length / bare.rod_length),
    )  # Y1 = 0: crank and rod in line at θ = 0
    cases = [
        (dataclasses.replace(bare, rod_length=0.03), (1.5, 100.0, 293.15), "outside the linkage"),
        (flat, (-half_pi, 100.0, 293.15), "at a dead centre"),
        (bare, (0.1, 10.0, 293.15), "stiffness[0] = 0.0 must be > 0"),
    ]
    for act, args, text in cases:
        zero = 0.0 if "stiffness" in text else None
        got = {impl: _outcome(s, *args) for impl, s in _steppers(act, None, zero).items()}
        assert len(set(got.values())) == 1 and text in got["python"], got


def test_per_step_motor_side_inverse_on_both_paths_and_against_the_vectorised_one(act):
    # the FMU's motor-side angle, compiled and Python side by side: the same bits (libm's
    # functions on both); against output_angle (numpy's arccos and arctan2, which round
    # differently from libm's in the last place): 1e-15 rad, a few units in the last place
    # of angles up to π; the same message beyond the dead centres
    from kernels import implementations

    models = {impl: A.ActuatorModel(act, implementation=impl) for impl in implementations()}
    phis = [*np.linspace(-95.0, 95.0, 381).tolist(), -1e-9, -0.0, 0.0, 3e-300]  # floats
    want = A.output_angle(act, phis)
    for phi, w in zip(phis, want, strict=True):
        got = {impl: m.stepper.output_angle(phi) for impl, m in models.items()}
        assert len(set(got.values())) == 1, (phi, got)
        assert got["python"] == pytest.approx(float(w), rel=0, abs=1e-15)
    with pytest.raises(ValueError) as vectorised:
        A.output_angle(act, 300.0)
    for m in models.values():
        with pytest.raises(ValueError) as per_step:
            m.stepper.output_angle(300.0)
        assert str(per_step.value) == str(vectorised.value)

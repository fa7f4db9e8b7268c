"""The five FMUs through fmpy: validation, outputs after initialization, state, reset,
several instances, bad input, agreement with the library."""

import functools
import json
import math
import zipfile

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.fmi1 import FMICallException
from fmpy.validation import validate_fmu
from fmu_helpers import Fmu

from servofmu.build.validate import validate
from servofmu.parameters import catalog
from servofmu.physics.bearing import BearingModel, BearingPair
from servofmu.physics.drives.actuator import Actuator, ActuatorModel
from servofmu.physics.drives.control import PIDParameters

NAMES = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController", "ThermalNetwork")


def drive(name, t):
    """A deterministic input history for each FMU."""
    if name == "BearingFriction":
        return dict(
            temperature=273.15 + 30 * math.sin(2 * t),
            speed=0.5 * math.sin(5 * t),
            axial_load=20 * math.sin(3 * t),
        )
    if name == "ActuatorStiffness":
        return dict(angle=0.3 * math.sin(4 * t), load_torque=150 + 100 * math.sin(7 * t))
    if name == "DCMotor":
        return dict(voltage=5 * math.sin(10 * t), load_torque=1e-3)
    if name == "ThermalNetwork":
        return dict(
            ambient_temperature=273.15 + 30 * math.sin(2 * t),
            sink_temperature=263.15 + 20 * math.sin(3 * t),
            power_loss=0.5 + 0.5 * math.sin(5 * t),
        )
    return dict(reference=math.sin(3 * t), measurement=0.8 * math.sin(3 * t - 0.1))


def run(fmu, name, t0, steps, h=1e-3):
    out, t = [], t0
    for _ in range(steps):
        fmu.set(**drive(name, t))
        fmu.slave.doStep(t, h)
        t += h
        out.append(fmu.real_outputs())
    return np.array(out), t


@pytest.mark.parametrize("name", NAMES)
def test_zero_validation_problems(fmus, name):
    assert validate_fmu(str(fmus[name])) == []
    assert validate(fmus[name]) == []


@pytest.mark.parametrize("name", NAMES)
def test_default_experiment_runs_in_fmpy(fmus, name):
    res = simulate_fmu(str(fmus[name]))
    for field in res.dtype.names:
        assert np.all(np.isfinite(res[field].astype(float))), field


def test_bearing_outputs_right_after_initialization(fmus):
    fmu = Fmu(fmus["BearingFriction"]).init(temperature=253.15, speed=0.2, axial_load=5.0)
    ref = BearingModel(
        BearingPair.from_catalog(
            "yu2017_gimbal", "krytox_143aa", coefficients=catalog.coefficients("yu2017_gimbal")
        )
    )
    lib = ref.evaluate(253.15, 0.2, 5.0)
    # before any doStep the outputs already reflect the inputs set in initialization mode
    for name in (
        "friction_torque",
        "preload",
        "contact_angle",
        "radial_clearance",
        "viscous_torque",
    ):
        assert fmu.get(name) == pytest.approx(getattr(lib, name), rel=1e-12), name
    for flag in ("overloaded", "locked", "unloaded"):
        assert fmu.get(flag) == getattr(lib, flag), flag
    # direct feedthrough: a new input shows at once, without a step
    fmu.set(speed=-0.2)
    assert fmu.get("friction_torque") == pytest.approx(-lib.friction_torque, rel=1e-12)
    fmu.close()


def test_actuator_outputs_right_after_initialization(fmus):
    fmu = Fmu(fmus["ActuatorStiffness"]).init(angle=0.1745, load_torque=200.0, temperature=253.15)
    lib = ActuatorModel(Actuator.from_catalog("liu2014_ema")).evaluate(0.1745, 200.0, 253.15)
    assert fmu.get("stiffness") == pytest.approx(lib.total, rel=1e-12)
    assert fmu.get("screw_force") == pytest.approx(lib.screw_force, rel=1e-12)
    assert fmu.get("deflection") == pytest.approx(200.0 / lib.total, rel=1e-12)
    fmu.close()


def test_motor_and_controller_outputs_right_after_initialization(fmus):
    motor = Fmu(fmus["DCMotor"]).init(initial_speed=3.0, initial_current=0.5)
    assert motor.get("speed", "current", "motor_torque") == pytest.approx([3.0, 0.5, 0.025])
    motor.close()
    ctl = Fmu(fmus["ServoController"]).init(reference=2.0, measurement=0.5, kp=3.0)
    assert ctl.get("command") == pytest.approx(3.0 * 1.5)  # first sample: P only, no integral yet
    ctl.close()


def test_stepped_fmus_give_their_initial_outputs_in_initialization_mode(fmus):
    # a master propagating connections before fmi2ExitInitializationMode must see the motor's
    # initial angle (not 0), and the controller's command from the inputs set so far
    motor = Fmu(fmus["DCMotor"])
    ctl = Fmu(fmus["ServoController"])
    for f in (motor, ctl):
        f.slave.setupExperiment(startTime=0.0)
        f.slave.enterInitializationMode()
    motor.set(initial_angle=34.0, initial_speed=1.0)
    ctl.set(mode="position", kp=2.0, reference=34.5)
    assert motor.get("angle") == 34.0
    ctl.set(measurement=motor.get("angle"))
    assert ctl.get("command") == pytest.approx(2.0 * 0.5)
    ctl.set(measurement=34.5)  # a later value is taken up
    assert ctl.get("command") == pytest.approx(0.0)
    for f in (motor, ctl):
        f.slave.exitInitializationMode()
    assert motor.get("angle") == 34.0 and ctl.get("command") == pytest.approx(0.0)
    motor.set(voltage=0.0)  # an input change after initialization must not re-initialise
    motor.slave.doStep(0.0, 1e-3)
    motor.set(voltage=0.0)
    moved = motor.get("angle")
    assert 34.0 < moved < 34.0011 and motor.get("angle") == moved
    motor.close()
    ctl.close()


@pytest.mark.parametrize("name", NAMES)
def test_state_round_trip_is_bit_identical(fmus, name):
    fmu = Fmu(fmus[name], "a").init()
    _, t = run(fmu, name, 0.0, 10)
    state = fmu.slave.getFMUstate()
    blob = fmu.slave.serializeFMUstate(state)
    first, _ = run(fmu, name, t, 25)
    fmu.slave.setFMUstate(state)
    again, _ = run(fmu, name, t, 25)
    np.testing.assert_array_equal(first, again)
    fresh = Fmu(fmus[name], "b").init()
    fresh.slave.setFMUstate(fresh.slave.deSerializeFMUstate(blob))
    restored, _ = run(fresh, name, t, 25)
    np.testing.assert_array_equal(first, restored)
    json.loads(bytes(blob).decode())  # the state is plain JSON
    fmu.close()
    fresh.close()


@pytest.mark.parametrize("name", NAMES)
def test_reset_gives_a_fresh_instance(fmus, name):
    fmu = Fmu(fmus[name], "r").init()
    run(fmu, name, 0.0, 15)
    fmu.slave.reset()
    fmu.init()
    after_reset, _ = run(fmu, name, 0.0, 10)
    fresh = Fmu(fmus[name], "f").init()
    reference, _ = run(fresh, name, 0.0, 10)
    np.testing.assert_array_equal(after_reset, reference)
    fmu.close()
    fresh.close()


def test_instances_are_independent_and_all_five_share_a_process(fmus):
    hot = Fmu(fmus["BearingFriction"], "hot").init(temperature=323.15, shim=0.0)
    cold = Fmu(fmus["BearingFriction"], "cold").init(temperature=253.15, shim=0.05e-3)
    others = [Fmu(fmus[n], n).init() for n in NAMES[1:]]
    assert hot.get("preload") == 0.0  # play open when hot with no shim
    assert cold.get("preload") > 30.0  # the 0.05 mm shim squeezed by the cold yoke
    for f in others:
        f.slave.doStep(0.0, 1e-3)
    hot.set(temperature=253.15)
    assert hot.get("preload") != cold.get("preload")  # shim stays per instance
    for f in (hot, cold, *others):
        f.close()


@pytest.mark.parametrize(
    "name, variable, value",
    [
        ("BearingFriction", "temperature", float("nan")),
        ("BearingFriction", "speed", float("inf")),
        ("BearingFriction", "temperature", -5.0),
        ("ActuatorStiffness", "angle", 3.0),
        ("ActuatorStiffness", "load_torque", float("nan")),
        ("DCMotor", "voltage", float("nan")),
        ("ServoController", "measurement", float("-inf")),
        ("ThermalNetwork", "sink_temperature", float("nan")),
    ],
)
def test_bad_input_is_refused_with_a_message_and_the_instance_recovers(fmus, name, variable, value):
    # fmi2Error (the step is not carried out at all, FMI 2.0), logged as an error; the
    # instance is then in the error state and goes on from a state saved before (FMI's way)
    fmu = Fmu(fmus[name], "bad").init()
    saved = fmu.slave.getFMUstate()
    fmu.set(**{variable: value})
    with pytest.raises(FMICallException, match="status 3"):
        fmu.slave.doStep(0.0, 1e-3)
    messages = [m for s, m in fmu.log if variable in m and s == 3]
    assert messages and repr(value) in messages[-1], fmu.log
    with pytest.raises(FMICallException, match="status 3"):  # not before the state is restored
        fmu.slave.doStep(0.0, 1e-3)
    assert "in state 'error'" in fmu.log[-1][1] and repr(value) in fmu.log[-1][1], fmu.log[-1]
    fmu.slave.setFMUstate(saved)
    fmu.set(**drive(name, 0.0))
    fmu.slave.doStep(0.0, 1e-3)  # usable again
    assert all(np.isfinite(fmu.real_outputs()))
    fmu.close()


def test_bearing_step_without_a_state_is_discarded_naming_the_point(fmus, monkeypatch):
    # the warm start fails and the exact solve fails too: the step is discarded with a message
    # naming temperatures and loads, and the instance carries on once a state exists again.
    # The instance runs the Python kernels with a continuation that always fails (the FMU's
    # handling does not depend on the kernels; the compiled kernels failing by themselves:
    # tests/physics/test_continuation.py)
    from servofmu.physics import compiled
    from servofmu.physics.pair import continuation
    from servofmu.physics.pair import model as bm

    python = functools.partial(compiled.module, implementation="python")
    monkeypatch.setattr(compiled, "module", lambda name, implementation=None: python(name))
    monkeypatch.setattr(continuation.PairSolver, "solve", lambda *args: None)
    fmu = Fmu(fmus["BearingFriction"], "nostate").init(temperature=293.15, axial_load=5.0)

    def no_equilibrium(*args, **kwargs):
        raise ArithmeticError("no equilibrium")

    saved = fmu.slave.getFMUstate()
    monkeypatch.setattr(bm, "load_state", no_equilibrium)
    fmu.set(temperature=300.0, axial_load=6.0)
    with pytest.raises(FMICallException, match="status 2"):
        fmu.slave.doStep(0.0, 1e-3)
    text = "(300.0, 300.0, 300.0, 300.0) K, axial_load = 6.0 N, radial_load = 0.0 N"
    assert any(text in m and "no equilibrium" in m for _, m in fmu.log), fmu.log
    monkeypatch.undo()
    fmu.slave.setFMUstate(saved)  # FMI 2.0: a discarded step is redone from a saved state
    fmu.set(temperature=300.0, axial_load=6.0)
    fmu.slave.doStep(0.0, 1e-3)
    assert math.isfinite(fmu.get("friction_torque"))
    fmu.close()


#: BearingFriction's declared ranges (the model's −100…+200 °C, README) and, for each, a value
#: just outside that the physics itself accepts: only the FMU's own check can refuse it. The
#: temperatures are the exception: the library's range is the FMU's (TEMPERATURES_OUTSIDE).
BEARING_INPUT_RANGES = [
    ("temperature", 173.15, 473.15, 480.0),
    ("temperature", 173.15, 473.15, 170.0),
    ("speed", -1.0e4, 1.0e4, 2.0e4),
    ("axial_load", -1.0e5, 1.0e5, 1.5e5),
    ("radial_load", -1.0e5, 1.0e5, 1.5e5),
]
BEARING_PARAMETER_RANGES = [
    ("assembly_temperature", 173.15, 473.15, 480.0),
    ("outer_interference", -1.0e-3, 1.0e-3, 1.5e-3),
    ("shim", -1.0e-3, 1.0e-3, 1.5e-3),
    ("assembly_preload", 0.0, 1.0e5, 1.5e5),
    ("loop_stiffness", 0.0, 1.0e13, 2.0e13),
    ("palmgren_s0", 0.0, 100.0, 150.0),
    ("regularisation_speed", 1.0e-9, 1.0e3, 2.0e3),
    ("stribeck_speed", 1.0e-9, 1.0e3, 2.0e3),
    ("pressure_limit", 1.0e8, 1.0e11, 2.0e11),
]


#: Temperatures (inputs and parameters) the library refuses as the FMU does.
TEMPERATURES_OUTSIDE = {("temperature", 480.0), ("temperature", 170.0),
                        ("assembly_temperature", 480.0)}  # fmt: skip


def _library_checks(name, value, parameters=None, **inputs) -> bool:
    """The library takes ``value`` of ``name`` (True), or refuses it as the FMU does: a
    temperature outside the FMU's 173.15…473.15 K, named with that range."""
    if (name, value) not in TEMPERATURES_OUTSIDE:
        return _library_accepts(parameters, **inputs)
    with pytest.raises(ValueError, match=rf"{name} = {value!r} K is outside the valid range "
                       r"\[173\.15, 473\.15\] K"):  # fmt: skip
        _library_accepts(parameters, **inputs)
    return True


def _library_accepts(parameters=None, **inputs):
    """The bearing physics evaluated at the default parameter set (changed by
    ``parameters``) and inputs: finite outputs, no exception."""
    from servofmu.parameters.bearing import default_parameters, pair_from_parameters

    p = default_parameters("yu2017_gimbal") | (parameters or {})
    point = dict(temperature=293.15, speed=0.0, axial_load=0.0, radial_load=0.0) | inputs
    out = BearingModel(pair_from_parameters(p)).evaluate(**point)
    return math.isfinite(out.running_torque) and math.isfinite(out.preload)


def _declared(fmu, name):
    (v,) = [v for v in fmu.md.modelVariables if v.name == name]
    return float(v.min), float(v.max)


@pytest.mark.parametrize("name, lo, hi, value", BEARING_INPUT_RANGES)
def test_bearing_input_range_is_the_fmus_own_check(fmus, name, lo, hi, value):
    assert _library_checks(name, value, **{name: value})
    fmu = Fmu(fmus["BearingFriction"], "range").init()
    assert _declared(fmu, name) == (lo, hi)
    fmu.set(**{name: value})
    with pytest.raises(FMICallException, match="status 3"):
        fmu.slave.doStep(0.0, 1e-3)
    text = f"{name} = {value!r} is outside the valid range [{lo:g}, {hi:g}]"
    assert any(text in m for _, m in fmu.log), fmu.log
    fmu.close()


@pytest.mark.parametrize("name, lo, hi, value", BEARING_PARAMETER_RANGES)
def test_bearing_parameter_range_is_the_fmus_own_check(fmus, name, lo, hi, value):
    assert _library_checks(name, value, {name: value})
    fmu = Fmu(fmus["BearingFriction"], "prange")
    with pytest.raises(FMICallException, match="fmi2ExitInitializationMode failed with status 3"):
        fmu.init(**{name: value})
    assert _declared(fmu, name) == (lo, hi)
    text = f"{name} = {value!r} is outside the valid range [{lo:g}, {hi:g}]"
    assert any(text in m and s == 3 for s, m in fmu.log), fmu.log
    with pytest.raises(FMICallException, match="status 3"):
        fmu.slave.doStep(0.0, 1e-3)
    fmu.slave.freeInstance()


def test_bad_tunable_parameter_after_initialization_then_fixed(fmus):
    fmu = Fmu(fmus["BearingFriction"], "p").init()
    saved = fmu.slave.getFMUstate()
    fmu.set(sliding_friction=-1.0)  # tunable: accepted now, checked at the next step
    with pytest.raises(FMICallException, match="status 3"):
        fmu.slave.doStep(0.0, 1e-3)
    assert any("sliding_friction = -1.0" in m and s == 3 for s, m in fmu.log), fmu.log
    fmu.slave.setFMUstate(saved)
    fmu.set(sliding_friction=0.05)
    fmu.slave.doStep(0.0, 1e-3)
    assert math.isfinite(fmu.get("running_torque"))
    fmu.close()


@pytest.mark.parametrize(
    "name, params, text",
    [
        ("BearingFriction", {"arrangement": 9}, "arrangement = 9 is not one of the items (1 = fa"),
        ("BearingFriction", {"preload_method": 0}, "preload_method = 0 is not one of the items"),
        ("ServoController", {"mode": 3}, "mode = 3 is not one of the items (1 = position, 2 = s"),
        ("ActuatorStiffness", {"support_loop_model": -1}, "support_loop_model = -1 is not one"),
        # the parameters' consistency checks, logged at fmi2ExitInitializationMode
        ("BearingFriction", {"ball_diameter": 5e-3}, "ball_diameter = 0.005 m must be below (ou"),
        ("BearingFriction", {"n_balls": 40}, "(the balls must fit on the pitch circle)"),
        ("BearingFriction", {"inner_curvature": 0.5}, "inner_curvature = 0.5 must exceed 0.5"),
        ("BearingFriction", {"nominal_contact_angle": 0.8}, "nominal_contact_angle = 0.8 is out"),
        ("BearingFriction", {"pitch_diameter": 0.016}, "pitch_diameter = 0.016 m must lie betw"),
        (
            "BearingFriction",
            {"lubricant_viscosity_100": 1e-3},
            "lubricant_viscosity_100 = 0.001 m2/s must be below lubricant_viscosity_40",
        ),
        (
            "BearingFriction",
            {"preload_method": "spring"},
            "preload_method = spring needs spring_stiffness > 0 N/m (got 0.0)",
        ),
        (  # a tandem pair is preloaded by a force or a spring (physics/pair/preload.py)
            "BearingFriction",
            {"arrangement": "tandem"},
            "arrangement = tandem needs preload_method = spring or force (got shim)",
        ),
        (  # the screw pushes both ways: its support pair is opposed
            "ActuatorStiffness",
            {"support_arrangement": "tandem"},
            "support pair: support_arrangement = 'tandem' is not valid for the screw's support",
        ),
        (
            "ActuatorStiffness",
            {"support_ball_diameter": 7e-3},
            # the support pair's names as the actuator's own parameters
            "support_ball_diameter = 0.007 m must be below "
            "(support_outer_diameter − support_bore)/2 = 0.006 m",
        ),
        (
            "ServoController",
            {"output_min": 5.0, "output_max": 1.0},
            "output_min = 5.0 V must be below",
        ),
        ("DCMotor", {"inductance": float("nan")}, "inductance = nan"),
        ("ThermalNetwork", {"shaft_capacity": 0.0}, "shaft_capacity = 0.0"),
    ],
)
def test_bad_parameters_are_reported(fmus, name, params, text):
    fmu = Fmu(fmus[name], "bp")
    with pytest.raises(FMICallException, match="fmi2ExitInitializationMode failed with status 3"):
        fmu.init(**params)
    assert any(text in m and s == 3 for s, m in fmu.log), fmu.log
    with pytest.raises(FMICallException, match="status 3"):
        fmu.slave.doStep(0.0, 1e-3)
    fmu.slave.freeInstance()


def test_extreme_load_is_an_overloaded_state_not_a_crash(fmus):
    fmu = Fmu(fmus["BearingFriction"], "x").init(axial_load=9.0e4, temperature=233.15)
    fmu.slave.doStep(0.0, 1e-3)
    assert fmu.get("overloaded") is True and math.isfinite(fmu.get("running_torque"))
    assert fmu.get("unloaded") is True  # bearing B lifted off
    fmu.close()


def test_mismatched_servofmu_is_refused_with_a_clear_message(fmus, tmp_path):
    tampered = tmp_path / "BearingFriction.fmu"
    with zipfile.ZipFile(fmus["BearingFriction"]) as src, zipfile.ZipFile(tampered, "w") as dst:
        for item in src.infolist():
            data = src.read(item.filename)
            if item.filename == "resources/servofmu_build.json":
                info = json.loads(data)
                info["package_hash"] = "0" * 64
                info["version"] = "9.9.9"
                data = json.dumps(info).encode()
            dst.writestr(item, data)
    log = []
    with pytest.raises(Exception, match="instantiate"):
        Fmu(tampered, "old", log=log)
    # the message names both versions and what to do
    text = " ".join(m for _, m in log)
    assert "built with servofmu 9.9.9" in text and "rebuild" in text


def test_documentation_is_inside(fmus):
    with zipfile.ZipFile(fmus["BearingFriction"]) as zf:
        page = zf.read("documentation/index.html").decode()
    assert "Yu eq 8" in page and "sliding_friction" in page and "calibrated" in page


def test_motor_is_exact_for_steps_from_0_1_to_10_ms(fmus):
    from scipy.integrate import solve_ivp

    from servofmu.physics.drives.motor import DCMotorParameters, state_matrices

    p = DCMotorParameters()
    a, b = state_matrices(p)
    ref = solve_ivp(
        lambda t, x: a @ x + b @ [6.0, 2e-3], (0, 0.05), [0.0, 0.0, 0.0], rtol=1e-11, atol=1e-13
    ).y[:, -1]
    for h in (1e-4, 1e-3, 1e-2):
        fmu = Fmu(fmus["DCMotor"], f"m{h}").init()
        t = 0.0
        for _ in range(round(0.05 / h)):
            fmu.set(voltage=6.0, load_torque=2e-3)
            fmu.slave.doStep(t, h)
            t += h
        got = fmu.get("current", "speed", "angle")
        np.testing.assert_allclose(got, ref, rtol=1e-8, atol=1e-12)
        fmu.close()


def test_controller_limits_anti_windup_and_sampling(fmus):
    defaults = PIDParameters()
    fmu = Fmu(fmus["ServoController"], "c").init(sample_period=5e-3)
    fmu.set(reference=100.0, measurement=0.0)  # saturates at output_max
    commands, t = [], 0.0
    for _ in range(1000):
        fmu.slave.doStep(t, 1e-3)
        t += 1e-3
        commands.append(fmu.get("command"))
    assert max(commands) == defaults.output_max
    assert len({round(c, 12) for c in commands[:20]}) <= 5  # changes only every 5 ms sample
    fmu.set(measurement=200.0)  # error reverses: a wound-up integral would hold the limit
    for _ in range(5):
        fmu.slave.doStep(t, 1e-3)
        t += 1e-3
    assert fmu.get("command") < defaults.output_max
    fmu.close()


def test_example_runs_with_plain_fmpy(fmus, tmp_path):
    import subprocess
    import sys
    from pathlib import Path

    script = Path(__file__).parents[2] / "examples" / "bearing_friction_temperature.py"
    png = tmp_path / "plot.png"
    proc = subprocess.run(
        [sys.executable, str(script), str(fmus["BearingFriction"]), str(png)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert proc.returncode == 0, proc.stderr
    assert png.is_file() and "running [N·mm]" in proc.stdout
    assert "Warning" not in proc.stdout + proc.stderr  # fmpy's "missing input for variable"
    assert "servofmu" not in script.read_text().split('"""')[2]  # plain fmpy, no servofmu import


def test_validate_cli_exit_codes(fmus, tmp_path, capsys):
    from servofmu import cli

    assert cli.main(["validate", str(fmus["DCMotor"])]) == 0
    broken = tmp_path / "DCMotor.fmu"
    with zipfile.ZipFile(fmus["DCMotor"]) as src, zipfile.ZipFile(broken, "w") as dst:
        for item in src.infolist():
            if item.filename != "documentation/index.html":
                data = src.read(item.filename)
                if item.filename == "modelDescription.xml":  # drop the InitialUnknowns
                    text = data.decode()
                    start = text.index("<InitialUnknowns>")
                    end = text.index("</InitialUnknowns>") + len("</InitialUnknowns>")
                    data = (text[:start] + text[end:]).encode()
                dst.writestr(item, data)
    assert cli.main(["validate", str(broken)]) == 1
    out = capsys.readouterr().out
    assert "InitialUnknowns" in out and "documentation/index.html is missing" in out


def test_motor_friction_sticks_and_does_not_depend_on_the_step(fmus):
    # held: k_t·i = 0.0125 N·m stays below the 0.03 N·m breakaway, so the rotor never moves
    held = Fmu(fmus["DCMotor"], "held").init()
    t = 0.0
    for _ in range(100):
        held.set(voltage=0.5, friction_running_torque=0.02, friction_breakaway_torque=0.03)
        held.slave.doStep(t, 1e-3)
        t += 1e-3
    assert held.get("speed") == 0.0
    assert held.get("friction_torque") == pytest.approx(held.get("motor_torque"), rel=1e-9)
    held.close()
    # moving: the same sub-steps whatever the communication step
    finals = []
    for h in (1e-4, 1e-3, 1e-2):
        fmu = Fmu(fmus["DCMotor"], f"s{h}").init()
        t = 0.0
        for _ in range(round(0.2 / h)):
            fmu.set(voltage=3.0, friction_running_torque=0.02, friction_breakaway_torque=0.03)
            fmu.slave.doStep(t, h)
            t += h
        finals.append(fmu.get("current", "speed", "angle"))
        fmu.close()
    np.testing.assert_allclose(finals[1], finals[0], rtol=1e-12)
    np.testing.assert_allclose(finals[2], finals[0], rtol=1e-12)
    # after 2 s (12 mechanical time constants) at 3 V against 0.02 N·m:
    # ω = (k_t·V/R − T_f)/(b + k_t·k_e/R)
    fmu = Fmu(fmus["DCMotor"], "ss").init()
    t = 0.0
    for _ in range(200):
        fmu.set(voltage=3.0, friction_running_torque=0.02, friction_breakaway_torque=0.03)
        fmu.slave.doStep(t, 1e-2)
        t += 1e-2
    ss = (0.05 * 3.0 / 2.0 - 0.02) / (1e-5 + 0.05 * 0.05 / 2.0)
    assert fmu.get("speed") == pytest.approx(ss, rel=1e-4)
    fmu.close()


def test_the_package_hash_covers_the_compiled_kernels(tmp_path):
    # an FMU's version check (servofmu_build.json's package_hash against the imported package)
    # changes with a compiled module of the package, as it does with a source file
    from servofmu.build.fmu import stage_package
    from servofmu.fmus.package_hash import package_hash

    package = stage_package(tmp_path / "staged")
    for f in (package / "physics").rglob("_*.so"):
        f.unlink()
    plain = package_hash(package)
    module = package / "physics" / "pair" / "_continuation.cpython-311-x86_64-linux-gnu.so"
    module.write_bytes(b"one build")
    one = package_hash(package)
    module.write_bytes(b"another build")
    assert len({plain, one, package_hash(package)}) == 3

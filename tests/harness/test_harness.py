"""The co-simulation harness: signals, system checks before instantiation, stepping
(Gauss-Seidel/Jacobi, LinearTransformation, SSV bindings, variants), results and failures."""

from __future__ import annotations

import math
import re
import shutil
import zipfile

import numpy as np
import pytest

from servofmu.build.ssp import SSP_DIR
from servofmu.harness import (
    Cycle,
    HarnessError,
    PiecewiseLinear,
    Ramp,
    Steps,
    SystemError_,
    from_csv,
    load_system,
    run,
)
from servofmu.harness import master as master_module
from servofmu.harness.master import order_components
from servofmu.harness.units import read_results
from servofmu.physics.drives.actuator import Actuator, output_angle, reduction_ratio


@pytest.fixture(scope="module")
def out(fmus):
    """Folder with the built FMUs and .ssp systems of this session."""
    return fmus["BearingFriction"].parent


@pytest.fixture
def no_instantiation(monkeypatch):
    """Fail the test if the harness instantiates any FMU."""

    def refuse(*args, **kwargs):
        raise AssertionError("an FMU was instantiated")

    monkeypatch.setattr(master_module, "_Unit", refuse)


def _copy_system(tmp_path, name="seeker_gimbal"):
    target = tmp_path / name
    shutil.copytree(SSP_DIR / name, target)
    return target


def _edit(path, old, new):
    text = path.read_text()
    assert text.count(old) == 1, f"{old!r} not exactly once in {path}"
    path.write_text(text.replace(old, new))


# ----------------------------------------------------------------------------- signals
def test_steps_hold_each_value_from_its_time():
    s = Steps((1.0, 2.0), (10.0, 20.0))
    assert [s(0.0), s(1.0), s(1.5), s(2.0), s(9.0)] == [10.0, 10.0, 10.0, 20.0, 20.0]


def test_ramp_and_piecewise_linear_interpolate_and_hold():
    r = Ramp(1.0, 3.0, 0.0, 4.0)
    assert [r(0.0), r(2.0), r(3.0), r(5.0)] == [0.0, 2.0, 4.0, 4.0]
    p = PiecewiseLinear((0.0, 1.0, 2.0), (0.0, 10.0, 0.0))
    assert p(0.25) == pytest.approx(2.5) and p(1.5) == pytest.approx(5.0)


def test_cycle_triangle_and_sine():
    tri = Cycle(-60.0, 80.0, 10.0, "triangle", start=1.0)
    assert [tri(0.0), tri(1.0), tri(6.0), tri(11.0), tri(3.5)] == pytest.approx(
        [-60.0, -60.0, 80.0, -60.0, 10.0]
    )
    sine = Cycle(-1.0, 1.0, 4.0, "sine")
    assert [sine(0.0), sine(1.0), sine(3.0)] == pytest.approx([0.0, 1.0, -1.0])


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: Steps((2.0, 1.0), (0.0, 1.0)), "must increase"),
        (lambda: Steps((1.0,), (0.0, 1.0)), "as many times as values"),
        (lambda: PiecewiseLinear((0.0,), (1.0,)), "at least two"),
        (lambda: Cycle(0.0, 1.0, 0.0), "period = 0.0"),
        (lambda: Cycle(0.0, 1.0, 1.0, "square"), "'square'"),
    ],
)
def test_bad_signals_name_the_problem(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_signal_from_csv(tmp_path):
    f = tmp_path / "profile.csv"
    f.write_text("time,T\n0,233.15\n10,333.15\n")
    s = from_csv(f, "T")
    assert s(5.0) == pytest.approx(283.15)
    with pytest.raises(ValueError, match="no column 'temp'"):
        from_csv(f, "temp")
    f.write_text("time,T\n0,cold\n")
    with pytest.raises(ValueError, match="non-numeric"):
        from_csv(f, "T")


# ----------------------------------------------------------------------------- loading
def test_every_system_loads_with_its_bindings_and_variants(out):
    for name in ("seeker_gimbal", "seeker_gimbal_position", "ema_actuator", "space_bearing"):
        system = load_system(out / f"{name}.ssp")
        try:
            assert system.step_size > 0 and system.stop_time > system.start_time
            assert all(c.parameters for c in system.components.values())
            assert system.variants
        finally:
            system.close()


def test_gauss_seidel_order_follows_the_connections(out):
    system = load_system(out / "seeker_gimbal.ssp")
    try:
        order = order_components(system)
    finally:
        system.close()
    # every component is in a loop; the loop is broken at the first stateful component in
    # declaration order (the controller), and the algebraic bearing comes after the motor
    # whose speed it reads, so it sees the speed at the end of the step
    assert order == ["controller", "motor", "bearing"]


@pytest.mark.parametrize(
    "file, old, new, message",
    [
        (  # schema: an element SSP 1.0 does not have
            "SystemStructure.ssd",
            "<ssd:Connections>",
            "<ssd:Wires/><ssd:Connections>",
            "Wires",
        ),
        (
            "SystemStructure.ssd",
            'endElement="controller" endConnector="measurement"',
            'endElement="controller" endConnector="measurment"',
            "no variable 'measurment'",
        ),
        (  # unit mismatch between a connector and its FMU variable
            "SystemStructure.ssd",
            '<ssd:Connector name="temperature" kind="input"><ssc:Real unit="K"/>',
            '<ssd:Connector name="temperature" kind="input"><ssc:Real unit="rad/s"/>',
            "unit 'rad/s', the FMU variable 'K'",
        ),
        (
            "SystemStructure.ssd",
            'source="resources/DCMotor.fmu"',
            'source="resources/DCMotr.fmu"',
            "DCMotr.fmu",
        ),
        (
            "bearing.ssv",
            '<ssv:Parameter name="shim">',
            '<ssv:Parameter name="shimm">',
            "bearing.shimm: the FMU has no such variable",
        ),
        (
            "variants/cold.ssv",
            'name="bearing.temperature"',
            'name="bearing.temprature"',
            "'bearing.temprature' names no variable",
        ),
        (  # two components of one name: the second would silently replace the first
            "SystemStructure.ssd",
            '<ssd:Component name="motor"',
            '<ssd:Component name="controller"',
            "SystemStructure.ssd: ssd:Component name='controller' (line 22) is declared more",
        ),
        (
            "SystemStructure.ssd",
            'baseStepSize="0.001"',
            "",
            "osp:FixedStepAlgorithm (line 76) baseStepSize is missing",
        ),
        (
            "SystemStructure.ssd",
            'baseStepSize="0.001"',
            'baseStepSize="1ms"',
            "baseStepSize = '1ms' is not a finite number > 0",
        ),
        (
            "SystemStructure.ssd",
            'baseStepSize="0.001"',
            'baseStepSize="-0.001"',
            "baseStepSize = '-0.001' is not a finite number > 0",
        ),
    ],
)
def test_bad_system_is_refused_before_any_fmu_is_instantiated(
    tmp_path, out, no_instantiation, file, old, new, message
):
    folder = _copy_system(tmp_path)
    _edit(folder / file, old, new)
    with pytest.raises(SystemError_) as info:
        run(folder, fmu_dir=out, stop=0.01)
    assert message in str(info.value)


def test_unit_mismatch_between_connected_variables_is_refused(tmp_path, out, no_instantiation):
    folder = _copy_system(tmp_path)
    ssd = folder / "SystemStructure.ssd"
    # speed (rad/s) into the bearing's temperature (K), connectors without units
    _edit(
        ssd,
        'endElement="bearing" endConnector="speed"',
        'endElement="bearing" endConnector="temperature"',
    )
    _edit(
        ssd,
        '<ssd:Connector name="temperature" kind="input"><ssc:Real unit="K"/>',
        '<ssd:Connector name="temperature" kind="input"><ssc:Real/>',
    )
    with pytest.raises(SystemError_, match="unit 'rad/s' does not match 'K'"):
        load_system(folder, fmu_dir=out)


def test_missing_fmu_says_how_to_build_it(tmp_path, no_instantiation):
    folder = _copy_system(tmp_path)
    with pytest.raises(SystemError_, match="servofmu build") as info:
        load_system(folder)
    assert len(info.value.problems) == 3  # every missing FMU is listed, not just the first


def test_unsafe_archive_is_refused(tmp_path, out):
    bad = tmp_path / "evil.ssp"
    with zipfile.ZipFile(bad, "w") as zf:
        zf.writestr("../escape.txt", "x")
    with pytest.raises(HarnessError, match="leaves the archive"):
        load_system(bad)
    assert not (tmp_path.parent / "escape.txt").exists()


def test_unknown_override_variant_and_signal_targets(out, no_instantiation):
    system = load_system(out / "seeker_gimbal.ssp")
    try:
        with pytest.raises(HarnessError, match="no component 'motorx'"):
            run(system, parameters={"motorx.inertia": 1.0}, stop=0.01)
        with pytest.raises(HarnessError, match="not one of the variants"):
            run(system, parameters="arctic", stop=0.01)
        with pytest.raises(HarnessError, match="only unconnected inputs"):
            run(system, signals={"motor.voltage": Steps((0.0,), (1.0,))}, stop=0.01)
        with pytest.raises(HarnessError, match=r"bearing\.temperature = 'warm' is not a finite"):
            run(system, parameters={"bearing.temperature": "warm"}, stop=0.01)
        with pytest.raises(HarnessError, match=r"motor\.inertia = 'nan' is not a finite Real"):
            run(system, parameters={"motor.inertia": "nan"}, stop=0.01)
    finally:
        system.close()


# ----------------------------------------------------------------------------- running
def test_linear_transformation_maps_motor_angle_to_output_angle(out, tmp_path):
    # ema_actuator with a linearised motor side: the motor angle reaches the actuator's
    # output-angle input through a LinearTransformation (1/i0, the ratio at neutral)
    folder = _copy_system(tmp_path, "ema_actuator")
    factor = 1.0 / float(reduction_ratio(Actuator.from_catalog("liu2014_ema"), 0.0).total)
    _edit(
        folder / "SystemStructure.ssd",
        '<ssd:Connection startElement="motor" startConnector="angle" endElement="actuator" '
        'endConnector="motor_angle"/>',
        '<ssd:Connection startElement="motor" startConnector="angle" endElement="actuator" '
        f'endConnector="angle"><ssc:LinearTransformation factor="{factor!r}"/></ssd:Connection>',
    )
    _edit(
        folder / "SystemStructure.ssd",
        '<ssd:Connector name="motor_angle" kind="input">',
        '<ssd:Connector name="angle" kind="input">',
    )
    old = '<ssv:Parameter name="motor_side_inputs"><ssv:Boolean value="true"/>'
    _edit(folder / "actuator.ssv", old, old.replace("true", "false"))
    system = load_system(folder, fmu_dir=out)
    try:
        assert next(c for c in system.connections if c.end == ("actuator", "angle")).factor == (
            factor
        )
        res = run(
            system,
            stop=0.05,
            record=["motor.angle", "actuator.reduction_ratio"],
            progress=False,
        )
    finally:
        system.close()
    # Gauss-Seidel steps the (algebraic) actuator after the motor: each row's ratio is at
    # the output angle factor·motor angle of the same row
    output_angle = factor * res["motor.angle"]
    expected = reduction_ratio(Actuator.from_catalog("liu2014_ema"), output_angle).total
    assert res["actuator.reduction_ratio"] == pytest.approx(expected, rel=1e-12)
    assert np.ptp(output_angle) > 0  # the loaded motor moves: the check is not at one point


def test_ema_actuator_applies_the_exact_reduction_to_the_motor_angle(out):
    act = Actuator.from_catalog("liu2014_ema")
    system = load_system(out / "ema_actuator.ssp")
    try:
        assert not [c for c in system.connections if c.factor != 1.0 or c.offset != 0.0]
        res = run(
            system,
            stop=0.05,
            record=[
                "motor.angle",
                "motor.speed",
                "actuator.output_angle",
                "actuator.output_speed",
                "actuator.reduction_ratio",
            ],
            progress=False,
        )
    finally:
        system.close()
    # Gauss-Seidel: each row's actuator outputs are at the motor angle of the same row
    delta = output_angle(act, res["motor.angle"])
    assert res["actuator.output_angle"] == pytest.approx(delta, rel=1e-12, abs=1e-15)
    assert res["actuator.reduction_ratio"] == pytest.approx(
        reduction_ratio(act, delta).total, rel=1e-12
    )
    speed = res["motor.speed"] / res["actuator.reduction_ratio"]
    assert res["actuator.output_speed"] == pytest.approx(speed, rel=1e-12, abs=1e-15)
    assert np.ptp(res["motor.angle"]) > 0  # the loaded motor moves
    assert math.degrees(res["actuator.output_angle"][0]) == pytest.approx(10.0, rel=1e-12)


def test_variant_and_override_reach_the_fmu(out):
    system = load_system(out / "seeker_gimbal.ssp")
    try:
        base = run(system, stop=0.01, record=["bearing.running_torque"], progress=False)
        cold = run(
            system, parameters="cold", stop=0.01, record=["bearing.running_torque"], progress=False
        )
        colder = run(
            system,
            parameters=["cold", {"bearing.temperature": 213.15}],
            stop=0.01,
            record=["bearing.running_torque"],
            progress=False,
        )
    finally:
        system.close()
    warm, c1, c2 = (r["bearing.running_torque"][-1] for r in (base, cold, colder))
    assert warm < c1 < c2  # grease and preload: colder is stiffer


def test_gauss_seidel_and_jacobi_converge_to_the_same_steady_state(out):
    system = load_system(out / "seeker_gimbal.ssp")
    try:
        kw = dict(stop=1.0, record=["motor.speed", "motor.current"], progress=False)
        gs = run(system, **kw)
        jac = run(system, algorithm="jacobi", **kw)
    finally:
        system.close()
    target = 10.0 * math.pi / 180.0  # the speed loop's reference in controller.ssv
    assert gs["motor.speed"][-1] == pytest.approx(target, rel=1e-4)
    assert jac["motor.speed"][-1] == pytest.approx(target, rel=1e-4)
    # ... through different transients (Jacobi: one more step of delay in the loop)
    assert np.max(np.abs(gs["motor.speed"] - jac["motor.speed"])) > 0.01 * target


def test_results_csv_and_plot(tmp_path, out):
    res = run(
        out / "seeker_gimbal.ssp",
        stop=0.02,
        record=["motor.speed", "bearing.overloaded"],
        out_dir=tmp_path,
        progress=False,
    )
    assert res.data.dtype.names == ("time", "motor.speed", "bearing.overloaded")
    assert len(res.data) == 21 and res["time"][-1] == pytest.approx(0.02)
    # headers name each column with its unit (the FMUs' SI units)
    header = res.csv.read_text().splitlines()[0]
    assert header == "time [s],motor.speed [rad/s],bearing.overloaded [0/1]"
    table, units = read_results(res.csv)
    assert units == {"time": "s", "motor.speed": "rad/s", "bearing.overloaded": "0/1"}
    assert np.allclose(table["motor.speed"], res["motor.speed"])
    png = res.plot(tmp_path / "r.png", ["motor.speed"])
    assert png.stat().st_size > 1000


def test_failing_fmu_stops_the_run_and_keeps_the_results(tmp_path, out):
    # the chamber temperature ramps through the bearing's valid range (173.15…473.15 K)
    ramp = Ramp(0.0, 0.1, 293.15, 493.15)
    with pytest.raises(HarnessError) as info:
        run(
            out / "seeker_gimbal.ssp",
            signals={"bearing.temperature": ramp},
            stop=0.2,
            out_dir=tmp_path,
            progress=False,
        )
    err = info.value
    # the headline names the component, the status and who logged what (quoted)
    assert "component 'bearing' (BearingFriction) returned fmi2Error" in str(err)
    assert 'bearing (BearingFriction) logged Error: "bearing: fmi2DoStep: temperature = 47' in str(
        err
    )
    assert "[173.15, 473.15]" in str(err)
    t_fail = err.result.data["time"][-1]
    assert 0.08 < t_fail < 0.1  # rows up to the step before the failing one
    on_disk, _ = read_results(tmp_path / "results.csv")
    assert on_disk["time"][-1] == pytest.approx(t_fail)
    assert np.all(on_disk["bearing.temperature"] <= 473.15)
    assert "\n" not in str(err)  # one line for the user ...
    log = (tmp_path / "failure.log").read_text()  # ... the detail in a log
    assert str(tmp_path / "failure.log") in str(err) and "[bearing]" in log


def test_a_failure_quotes_the_component_that_logged():
    """explain(): the failing component's own warnings and errors, else the last ones of any
    component (a bad value usually comes from upstream), each named and quoted."""
    from collections import deque
    from types import SimpleNamespace

    from servofmu.harness.master import _Cosimulation

    journal = deque(
        [("motor", 0, "runs"), ("bearing", 3, "temperature = 500.0 is outside"), ("ctl", 1, "w")]
    )
    units = {
        n: SimpleNamespace(journal=journal, comp=SimpleNamespace(model_identifier=m))
        for n, m in (("motor", "DCMotor"), ("bearing", "BearingFriction"), ("ctl", "Servo"))
    }
    cosim = SimpleNamespace(units=units)
    told = _Cosimulation.explain(cosim, "motor")  # the motor logged no problem itself
    assert told == (
        'bearing (BearingFriction) logged Error: "temperature = 500.0 is outside" | '
        'ctl (Servo) logged Warning: "w"'
    )
    assert _Cosimulation.explain(cosim, "bearing").startswith("bearing (BearingFriction)")
    journal.clear()
    assert _Cosimulation.explain(cosim, "motor") == "no component logged a warning or an error"


def test_bad_run_arguments(out):
    with pytest.raises(HarnessError, match="algorithm = 'newton'"):
        run(out / "seeker_gimbal.ssp", algorithm="newton", stop=0.01)
    with pytest.raises(HarnessError, match=r"stop = 0\.0 s must be after"):
        run(out / "seeker_gimbal.ssp", stop=0.0)


# ----------------------------------------------------------------------------- CLI
def test_cli_run_writes_results_and_reports_failures(tmp_path, out, capsys):
    from servofmu.cli import main

    ssp = str(out / "seeker_gimbal.ssp")
    profile = tmp_path / "chamber.csv"
    profile.write_text("time,T\n0,293.15\n0.05,233.15\n")
    rc = main(
        [
            "run",
            ssp,
            "--parameters",
            "warm",
            "--parameters",
            "controller.kp=3",
            "--parameters",
            "bearing.arrangement=face_to_face",  # a choice by its item name
            "--signal",
            f"bearing.temperature={profile}:T",
            "--stop",
            "0.05",
            "--step",
            "0.5e-3",
            "--record",
            "motor.speed",
            "--record",
            "bearing.temperature",
            "--plot",
            "motor.speed",
            "--out",
            str(tmp_path / "ok"),
        ]
    )
    assert rc == 0
    table, units = read_results(tmp_path / "ok" / "results.csv")
    assert len(table) == 101 and table["bearing.temperature"][-1] < 235.0
    assert units["bearing.temperature"] == "K"
    assert (tmp_path / "ok" / "results.png").is_file()
    assert "× real time" in capsys.readouterr().out

    # a value outside the variable's range is bad input, refused before the run (exit 2) ...
    rc = main(["run", ssp, "--parameters", "bearing.temperature=1000", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 2 and "temperature = 1000.0 is outside the valid range [173.15, 473.15] K" in err
    assert not (tmp_path / "results.csv").exists()
    # ... a signal that leaves it during the run makes the FMU refuse a step: the run failed
    profile.write_text("time,T\n0,293.15\n0.05,493.15\n")
    driven = ["--signal", f"bearing.temperature={profile}:T"]
    rc = main(["run", ssp, *driven, "--stop", "0.05", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 1 and "servofmu: run failed: component 'bearing'" in err
    assert "is outside the valid range" in err and (tmp_path / "results.csv").is_file()
    rc = main(["run", str(tmp_path / "nowhere.ssp")])
    assert rc == 2 and "nowhere.ssp" in capsys.readouterr().err


def test_cli_scenario_prints_its_table(tmp_path, out, capsys, monkeypatch):
    from servofmu.build import fmu as build_fmu
    from servofmu.cli import main

    monkeypatch.setattr(build_fmu, "DEFAULT_OUT", out)  # use this session's build
    assert main(["scenario", "stiffness_test", "--coarse", "--out", str(tmp_path)]) == 0
    text = capsys.readouterr().out
    assert "EMA stiffness test" in text and "vs Liu" in text
    assert (tmp_path / "stiffness_test.csv").is_file()


def test_output_interval_keeps_every_kth_row_and_the_last(out):
    system = load_system(out / "seeker_gimbal.ssp")
    try:
        full = run(system, stop=0.0105, step=5e-4, record=["motor.speed"], progress=False)
        thin = run(
            system,
            stop=0.0105,
            step=5e-4,
            record=["motor.speed"],
            progress=False,
            output_interval=2e-3,
        )
        with pytest.raises(HarnessError, match="output_interval = -1"):
            run(system, stop=0.01, output_interval=-1.0)
    finally:
        system.close()
    assert thin["time"] == pytest.approx([0.0, 0.002, 0.004, 0.006, 0.008, 0.010, 0.0105])
    picked = np.searchsorted(full["time"], thin["time"] - 1e-12)
    assert np.array_equal(thin["motor.speed"], full["motor.speed"][picked])


def test_cli_internal_error_is_one_line_with_the_traceback_in_a_log(monkeypatch, capsys):
    import tempfile
    from pathlib import Path

    from servofmu import cli

    def broken(args):
        raise RuntimeError("something unforeseen")

    monkeypatch.setattr(cli, "_host_env", broken)
    assert cli.main(["host-env"]) == cli.INTERNAL_ERROR
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "RuntimeError: something unforeseen" in err
    log = Path(re.search(r"traceback in (\S+);", err).group(1))  # this run's own log
    assert log.parent == Path(tempfile.gettempdir()) and log.name.startswith("servofmu-error-")
    assert "Traceback" in log.read_text() and "broken" in log.read_text()
    log.unlink()
    with pytest.raises(RuntimeError):
        cli.main(["--debug", "host-env"])


@pytest.mark.parametrize("algorithm", ["gauss-seidel", "jacobi"])
def test_a_slow_component_steps_at_its_rate_and_holds_its_outputs(out, algorithm):
    """rates={"thermal": 25}: the network steps once every 25 communication steps over 25·h
    (exact for held inputs, so its value at 0.25 s is one 0.25 s step of the FMU alone from
    the same start and inputs), its outputs appear when that step ends and hold until the
    next one ends; the loop steps every h."""
    from fmu_helpers import Fmu

    system = load_system(out / "seeker_gimbal_chamber.ssp")
    try:
        h = system.step_size
        record = ["thermal.shaft_temperature", "bearing.preload", "motor.speed"]
        res = run(
            system,
            stop=60 * h,
            record=record,
            algorithm=algorithm,
            rates={"thermal": 25},
            progress=False,
        )
        thermal = system.components["thermal"].parameters
        with pytest.raises(HarnessError, match="'nothing' is not a component"):
            run(system, stop=h, rates={"nothing": 2}, progress=False)
        with pytest.raises(HarnessError, match=r"rates\['thermal'\] = 0"):
            run(system, stop=h, rates={"thermal": 0}, progress=False)
    finally:
        system.close()
    shaft = res["thermal.shaft_temperature"]
    # rows 0…24 (t < 0.25 s) hold the start, rows 25…49 the value at 0.25 s, and so on: the
    # others see the network's outputs once its step has ended, never ahead of time
    assert np.all(shaft[:25] == shaft[0]) and np.all(shaft[25:50] == shaft[25])
    assert shaft[25] != shaft[24] and shaft[50] != shaft[49]
    assert np.all(shaft[50:60] == shaft[50]) and shaft[60] != shaft[59]  # the last, 10 h
    assert np.ptp(res["motor.speed"][1:25]) > 0  # the loop steps every h meanwhile
    # the bearing (algebraic) reads the new part temperatures in the row they appear
    preload = res["bearing.preload"]
    assert np.all(preload[25:50] == preload[25]) and preload[25] != preload[24]
    # one 0.25 s step of the network alone: soaked, the chamber and the bearing's power loss
    # at the start (the bearing at rest: its loss is 0) held over the step
    alone = Fmu(next(out.glob("ThermalNetwork.fmu")), "alone").init(
        **{name: value for name, (_, value) in thermal.items()}, power_loss=0.0
    )
    alone.slave.doStep(0.0, 25 * h)
    assert res["time"][25] == pytest.approx(25 * h)
    assert alone.get("shaft_temperature") == pytest.approx(float(shaft[25]), abs=1e-12)
    alone.close()


def _ssv_reals(path) -> dict:
    """{name: value} of the Real parameters of an .ssv file."""
    from servofmu.build.xmlsafe import parse

    root = parse(path.read_bytes(), path.name)
    return {
        prm.get("name"): float(value.get("value"))
        for prm in root.iter("{*}Parameter")
        for value in prm
        if value.tag.endswith("Real")
    }


@pytest.mark.parametrize(
    "celsius, flow_limit",
    [(-40.0, None), (-84.0, 213.15), (-84.0, None)],
    ids=["-40C", "-84C-held-below-a-flow-limit-at-60C", "-84C-extrapolated"],
)
def test_the_gimbal_holds_10_deg_s_exactly_where_its_motor_can(out, celsius, flow_limit):
    """The speed loop holds 10 °/s where the bearing's running torque at 10 °/s is below the
    motor's stall torque k_t·V_max/R (the system's own parameters: 600 N·mm), and not where it
    is above. At -40 °C Yu's 3.2 N·mm; at -84 °C, far below Krytox 143AA's data, 11 N·m with
    its law extrapolated (no pour point is published), or 40 N·mm held below a flow limit at
    -60 °C that a user gives (lubricant_minimum_temperature, lubricant_below_flow_limit hold).
    Below the data the flag is set and each warning of the bearing comes once, naming the
    temperature."""
    from servofmu.harness import HarnessError
    from servofmu.parameters.bearing import default_parameters, pair_from_parameters
    from servofmu.physics.bearing import BearingModel

    motor = _ssv_reals(SSP_DIR / "seeker_gimbal" / "motor.ssv")
    volts = _ssv_reals(SSP_DIR / "seeker_gimbal" / "controller.ssv")["output_max"]
    stall = motor["torque_constant"] * volts / motor["resistance"]  # N·m at zero speed
    kelvin, target = 273.15 + celsius, math.radians(10.0)
    limit = {} if flow_limit is None else {"lubricant_minimum_temperature": flow_limit}
    model = BearingModel(pair_from_parameters(default_parameters() | limit))
    holds = model.evaluate(kelvin, target).running_torque < stall
    signals = {
        "bearing.temperature": Steps((0.0,), (kelvin,)),
        "controller.reference": Steps((0.0,), (target,)),
    }
    system = load_system(out / "seeker_gimbal.ssp")
    try:
        record = ["motor.speed", "bearing.running_torque", "bearing.outside_lubricant_range"]
        parameters = {f"bearing.{k}": v for k, v in limit.items()}
        res = run(system, parameters=parameters, signals=signals, stop=1.0, record=record)
    except HarnessError as exc:  # the bearing's torque beyond what the motor FMU takes
        assert not holds and "friction_running_torque" in str(exc), exc
        return
    finally:
        system.close()
    speed = res["motor.speed"][-1]
    assert speed == pytest.approx(target, rel=1e-3) if holds else speed < 0.1 * target
    below = celsius < -40.0
    assert np.all((res["bearing.outside_lubricant_range"] > 0.5) == below)
    bearing = [w for w in res.warnings if w.startswith("bearing (BearingFriction)")]
    expected = int(below) + int(below and flow_limit is not None)  # the data, the flow limit
    assert len(bearing) == expected and all(f"{kelvin:.2f}" in w for w in bearing), bearing

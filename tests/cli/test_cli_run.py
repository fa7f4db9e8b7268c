"""`servofmu run` from a user's side: every bad argument exits 2 with one line
naming it before any FMU is instantiated, exit 1 only for a run that failed, Ctrl-C stops at a
step boundary and keeps the results (a real SIGINT to a child process), and the results carry
units (CSV headers, plot axes in the FMUs' display units)."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import threading

import numpy as np
import pytest

from servofmu.cli import main
from servofmu.harness import master as master_module
from servofmu.harness.units import read_results


@pytest.fixture(scope="module")
def ssp(fmus):
    return str(fmus["BearingFriction"].parent / "seeker_gimbal.ssp")


@pytest.fixture
def no_instantiation(monkeypatch):
    def refuse(*args, **kwargs):
        raise AssertionError("an FMU was instantiated")

    monkeypatch.setattr(master_module, "_Unit", refuse)


@pytest.mark.parametrize(
    "args, message",
    [
        (["--step", "2", "--stop", "1"], "step = 2.0 s is longer than the run"),
        (["--step", "inf"], "argument --step: 'inf' s is not finite"),
        (["--stop", "-1"], "stop = -1.0 s must be after start = 0.0 s"),
        (["--step", "0"], "argument --step: '0' s must be > 0"),
        (["--stop", "nan"], "argument --stop: 'nan' s is not finite"),
        (["--stop", "soon"], "argument --stop: 'soon' is not a number of seconds"),
        (["--stop", "1", "--step", "0.3"], "1.0 s is not a whole number of steps of 0.3 s"),
        (["--output-interval", "0.0015"], "output_interval = 0.0015 s must be a positive multiple"),
        (["--parameters", "motor.speed=1"], "parameter motor.speed: it is an output"),
        (["--parameters", "bearing.speed=1"], "driven by the connection from motor.speed"),
        (["--parameters", "motor.inertia=-1"], "motor.inertia = -1.0 is outside the valid range"),
        (["--parameters", "bearing.temperature=1000"], "= 1000.0 is outside the valid range"),
        (["--parameters", "arctic"], "parameter set 'arctic' is not one of the variants"),
        (["--plot", "motor.nothing"], "--plot 'motor.nothing': DCMotor.fmu has no variable"),
        (["--plot", "controller.kp"], "--plot 'controller.kp': it is a Real parameter"),
        (["--record", "motor.nothing"], "record 'motor.nothing': DCMotor.fmu has no variable"),
        (["--record", "motor.voltage"], "record 'motor.voltage': it is an input"),
        (["--algorithm", "newton"], "argument --algorithm: invalid choice: 'newton'"),
        (["--stop", "1e9", "--record", "motor.speed"], "rows × 2 columns"),
    ],
)
def test_bad_run_argument_exits_2_with_one_line_before_any_work(
    ssp, tmp_path, capsys, no_instantiation, args, message
):
    out = tmp_path / "out"
    rc = exit_code(["run", ssp, *args, "--out", str(out)])
    err = capsys.readouterr().err
    assert rc == 2, err
    assert message in err, err
    assert len(err.strip().splitlines()) == 1, err
    assert not out.exists()  # nothing written: no work started


def exit_code(argv: list[str]) -> int:
    """The exit code of ``servofmu ARGV`` (argparse's own errors raise SystemExit)."""
    try:
        return main(argv)
    except SystemExit as exc:
        return exc.code


def test_a_failed_run_exits_1_and_keeps_its_results(ssp, tmp_path, capsys):
    profile = tmp_path / "chamber.csv"
    profile.write_text("time,T\n0,293.15\n0.05,493.15\n")  # leaves the range at 0.045 s
    signal_ = f"bearing.temperature={profile}:T"
    record = ["--record", "bearing.temperature", "--out", str(tmp_path)]
    rc = main(["run", ssp, "--signal", signal_, "--stop", "0.05", *record])
    err = capsys.readouterr().err
    assert rc == 1 and "run failed" in err and "outside the valid range" in err
    data, _ = read_results(tmp_path / "results.csv")
    assert 0.04 < data["time"][-1] < 0.05 and (tmp_path / "failure.log").is_file()


def test_a_run_that_left_the_lubricants_data_says_so(ssp, tmp_path, capsys):
    profile = tmp_path / "cold.csv"
    profile.write_text("time,T\n0,203.15\n0.02,203.15\n")  # -70 °C: Krytox's data end at -40
    signal_ = f"bearing.temperature={profile}:T"
    rc = main(["run", ssp, "--signal", signal_, "--stop", "0.02", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 0, err
    assert "warning: bearing (BearingFriction)" in err and "203.15 K" in err, err


def test_results_and_plot_carry_units(ssp, tmp_path, capsys):
    out = tmp_path / "run"
    profile = tmp_path / "chamber.csv"
    profile.write_text("time,T\n0,293.15\n0.05,253.15\n")
    plot = ["--plot", "motor.speed", "bearing.running_torque", "bearing.temperature"]
    signal_ = ["--signal", f"bearing.temperature={profile}:T"]
    rc = main(["run", ssp, "--stop", "0.05", *signal_, "--out", str(out), *plot])
    assert rc == 0, capsys.readouterr().err
    header = (out / "results.csv").read_text().splitlines()[0].split(",")
    assert header[0] == "time [s]"
    # every column names its unit: SI from the modelDescription, 0/1 for the flags
    assert all(re.fullmatch(r"[a-z_]+\.[a-z_]+ \[[^\]]+\]", h) for h in header[1:]), header
    assert "bearing.running_torque [N.m]" in header and "bearing.overloaded [0/1]" in header
    assert "motor.current [A]" in header and "controller.command [V]" in header
    assert not [h for h in header if "not declared" in h], header
    # the plot shows the display units the FMUs declare: N·mm, °C, rpm
    import matplotlib.image

    image = matplotlib.image.imread(out / "results.png")
    assert image.shape[0] > 300
    from servofmu.harness import load_system

    system = load_system(ssp)
    try:
        assert system.scale("bearing.running_torque").shown_unit == "N·mm"
        assert system.scale("bearing.temperature").shown_unit == "°C"
        assert system.scale("motor.speed").shown_unit == "rpm"
        # the controller declares no unit: its measurement takes the motor speed's
        assert system.scale("controller.measurement").unit == "rad/s"
        data, _ = read_results(out / "results.csv")
        t = system.scale("bearing.temperature").shown(data["bearing.temperature"])
        assert t[0] == pytest.approx(data["bearing.temperature"][0] - 273.15)
    finally:
        system.close()


def _read_line(stream, timeout: float) -> str:
    line: list[str] = []
    reader = threading.Thread(target=lambda: line.append(stream.readline()), daemon=True)
    reader.start()
    reader.join(timeout)
    return line[0] if line else ""


@pytest.mark.slow
def test_ctrl_c_stops_at_a_step_boundary_and_keeps_the_results(ssp, tmp_path):
    out = tmp_path / "long"
    record = ["--record", "motor.speed", "--out", str(out)]
    child = subprocess.Popen(
        [sys.executable, "-m", "servofmu.cli", "run", ssp, "--stop", "1000", *record],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "PYTHONUNBUFFERED": "1"},
    )
    try:
        started = _read_line(child.stdout, 120.0)
        assert "1000000 steps" in started and "Ctrl-C" in started, started
        # the child is instantiating or already stepping; let it step a while
        threading.Event().wait(1.5)
        child.send_signal(signal.SIGINT)  # what Ctrl-C in a terminal sends
        _, stderr = child.communicate(timeout=120)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    assert child.returncode == 130, (child.returncode, stderr)  # not -11 (SIGSEGV)
    assert "Fatal" not in stderr and "Traceback" not in stderr, stderr
    m = re.search(r"interrupted at t = ([0-9.e+-]+) s", stderr)
    assert m, stderr
    t_stop = float(m.group(1))
    data, units = read_results(out / "results.csv")
    assert data["time"][-1] == pytest.approx(t_stop)  # every step up to the stop is kept
    assert len(data) == round(t_stop / 1e-3) + 1 and units["motor.speed"] == "rad/s"
    assert np.all(np.isfinite(data["motor.speed"]))
    assert "interrupted at t =" in (out / "failure.log").read_text()


class _Stream:
    """A stderr stand-in that says whether it is a terminal and counts what is written."""

    def __init__(self, tty: bool):
        self.tty, self.text = tty, ""

    def isatty(self):
        return self.tty

    def write(self, text):
        self.text += text

    def flush(self):
        pass


@pytest.mark.parametrize("tty", [True, False])
def test_progress_bar_is_live_on_a_terminal_and_quiet_otherwise(monkeypatch, tty):
    import time

    from servofmu.harness import progress

    stream = _Stream(tty)
    monkeypatch.setattr(sys, "stderr", stream)
    bar = progress.progress_bar(200, desc="run", unit="step", delay=0.0)
    for _ in range(200):
        time.sleep(0.002)  # 0.4 s: several refreshes on a terminal, none in a log
        bar.update()
    bar.close()
    redraws = stream.text.count("\r")
    if tty:
        assert redraws >= 3, stream.text
    else:  # at most its first and last status, each a line of its own at the end
        assert redraws <= 2 and stream.text.endswith("\n"), stream.text
        assert "200/200" in stream.text

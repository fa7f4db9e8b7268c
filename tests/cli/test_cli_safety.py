"""The command line against careless input and signals: catalogue keys that would name files
outside the output folder, TOML nested too deeply, the internal-error log, SIGTERM and Ctrl-C
during runs and scenarios, and a step no FMU takes in bounded time."""

from __future__ import annotations

import os
import re
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from servofmu import cli
from servofmu.harness.units import read_results

CLI = (sys.executable, "-m", "servofmu.cli")


@pytest.fixture(scope="module")
def ssp(fmus):
    return str(fmus["BearingFriction"].parent / "seeker_gimbal.ssp")


def _catalogue(tmp_path, key: str) -> Path:
    path = tmp_path / "mine.toml"
    q = '{{ value = {}, unit = "{}", kind = "handbook", ref = "ASM" }}'.format
    path.write_text(
        f'[materials."{key}"]\nname = "x"\nyoungs_modulus = {q(71.7, "GPa")}\n'
        f"poisson_ratio = {q(0.33, '-')}\nexpansion = {q(23.6e-6, '1/K')}\n"
    )
    return path


@pytest.mark.parametrize("key", ["../../x", "/tmp/evil", "a-b", "a b", "ü", "x\n--><y/>"])
def test_catalogue_keys_are_identifiers(tmp_path, capsys, key):
    path = _catalogue(tmp_path, key.replace("\n", "\\n"))
    out = tmp_path / "out"
    assert cli.main(["build", "--catalog", str(path), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert str(path) in err and "[materials] entry" in err and "letters, digits" in err, err
    assert len(err.strip().splitlines()) == 1, err
    assert not out.exists() and not (tmp_path.parent / "x.ssv").exists()


def test_a_valid_key_is_taken(tmp_path):
    from servofmu.build import catalogs

    tables, _ = catalogs.read(_catalogue(tmp_path, "my_7075_T6"))
    assert list(tables["materials"]) == ["my_7075_T6"]


@pytest.mark.parametrize("key", ["../x", "/abs", "a.b", ""])
def test_preset_files_are_named_only_by_valid_keys(tmp_path, key):
    from servofmu.build.presets import _file

    with pytest.raises(ValueError, match="not a catalogue key"):
        _file(tmp_path, "mountings", key)
    assert _file(tmp_path, "mountings", "yu2017_gimbal") == tmp_path / "mountings/yu2017_gimbal.ssv"


def test_too_deeply_nested_toml_is_bad_input(tmp_path, capsys):
    path = tmp_path / "deep.toml"
    path.write_text("a = " + "[" * 100_000 + "]" * 100_000 + "\n")
    assert cli.main(["build", "--catalog", str(path), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert str(path) in err and "nested too deeply" in err, err


def test_internal_errors_go_to_a_fresh_private_log(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    victim = tmp_path / "victim.txt"
    victim.write_text("keep me")
    (tmp_path / "servofmu-error.log").symlink_to(victim)  # the old fixed name, redirected

    def boom(args):
        raise RuntimeError("boom")

    monkeypatch.setattr(cli, "_host_env", boom)
    logs = []
    for _ in range(2):
        assert cli.main(["host-env"]) == cli.INTERNAL_ERROR
        err = capsys.readouterr().err
        logs.append(Path(re.search(r"traceback in (\S+);", err).group(1)))
    assert victim.read_text() == "keep me"
    assert logs[0] != logs[1] and all(p.parent == tmp_path for p in logs)
    for log in logs:
        assert "RuntimeError: boom" in log.read_text()
        assert stat.S_IMODE(log.stat().st_mode) == 0o600 and not log.is_symlink()


def test_a_step_too_long_fails_at_once_naming_the_limit(ssp, tmp_path):
    proc = subprocess.run(
        [*CLI, "run", ssp, "--stop", "1e5", "--step", "1e5", "--out", str(tmp_path / "run")],
        capture_output=True,
        text=True,
        timeout=300,
    )
    # the controller steps first (Gauss-Seidel order) and refuses 1e8 samples in one step; the
    # headline names it and quotes its own message
    assert proc.returncode == 1, proc.stderr
    assert "'controller' (ServoController) returned fmi2Discard" in proc.stderr
    assert 'controller (ServoController) logged Discard: "controller: communicationStepSize' in (
        proc.stderr
    )
    assert "one step takes at most 100000" in proc.stderr, proc.stderr


def _read_line(stream, timeout: float) -> str:
    line: list[str] = []
    reader = threading.Thread(target=lambda: line.append(stream.readline()), daemon=True)
    reader.start()
    reader.join(timeout)
    return line[0] if line else ""


@pytest.mark.slow
@pytest.mark.parametrize("signum, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_signal_stops_a_run_within_a_step_and_keeps_the_results(ssp, tmp_path, signum, status):
    out = tmp_path / "long"
    child = subprocess.Popen(
        [*CLI, "run", ssp, "--stop", "1000", "--record", "motor.speed", "--out", str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "PYTHONUNBUFFERED": "1"},
    )
    try:
        assert "Ctrl-C" in _read_line(child.stdout, 120.0)
        time.sleep(1.5)
        child.send_signal(signum)
        _, stderr = child.communicate(timeout=120)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    assert child.returncode == status, (child.returncode, stderr)
    m = re.search(r"interrupted (at t = ([0-9.e+-]+) s|before .+?), ([0-9.e+-]+) ms after", stderr)
    assert m and "Traceback" not in stderr, stderr
    assert float(m.group(3)) < 1000.0  # the run stopped within a second of the signal
    if m.group(2):  # stopped while stepping: every row up to there is kept
        data, _ = read_results(out / "results.csv")
        assert data["time"][-1] == pytest.approx(float(m.group(2)))
        assert np.all(np.isfinite(data["motor.speed"]))


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_after_the_last_check_is_raised_when_the_run_ends(signum):
    # a signal while a run writes its results (after its last step's check) must still stop
    # the work: a scenario must not start its next run as if nothing came
    from servofmu.harness.interrupt import Terminated, interruptible, terminate_as_interrupt

    previous = signal.getsignal(signal.SIGTERM), signal.getsignal(signal.SIGINT)
    # Python's own Ctrl-C handler, whatever this process inherited: a shell's background job
    # starts with SIGINT ignored, and Python then installs none
    signal.signal(signal.SIGINT, signal.default_int_handler)
    terminate_as_interrupt()
    try:
        with pytest.raises(KeyboardInterrupt) as caught:
            with interruptible() as request:
                signal.raise_signal(signum)  # only noted here
                assert request.requested
        assert isinstance(caught.value, Terminated) == (signum == signal.SIGTERM)
    finally:
        signal.signal(signal.SIGTERM, previous[0])
        signal.signal(signal.SIGINT, previous[1])


@pytest.mark.slow
def test_sigterm_keeps_a_scenarios_results_as_ctrl_c_does(fmus, tmp_path):
    out = tmp_path / "scenario"
    child = subprocess.Popen(
        [*CLI, "scenario", "low_speed_tracking", "--coarse", "--out", str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        deadline = time.monotonic() + 600
        while not list(out.glob("*/results.csv")) and time.monotonic() < deadline:
            time.sleep(0.2)  # the first run is done; the next one is under way
        first = list(out.glob("*/results.csv"))
        assert first, "no run finished"
        child.send_signal(signal.SIGTERM)
        _, stderr = child.communicate(timeout=120)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    assert child.returncode == 143, (child.returncode, stderr)
    assert "interrupted" in stderr and "Traceback" not in stderr, stderr
    data, _ = read_results(first[0])  # what was done is kept
    assert len(data) > 1

"""Robustness: property-based fuzzing of every FMU and soak runs, each in a child
process so that a crash of the host shows as a failed test with its output, not as a dead
test run. Short sizes by default; ``pytest --long`` (``make test-long``) runs the full ones:
10,000 fuzzed call sequences per FMU and 1,000,000 steps per soak. The archive and XML
attacks are in ``test_archives.py``."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parents[1] / "robustness"
NAMES = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController", "ThermalNetwork")


def _child(args, timeout):
    proc = subprocess.run(
        [sys.executable, *map(str, args)], capture_output=True, text=True, timeout=timeout
    )
    return proc.returncode, proc.stdout, proc.stderr


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_fuzzed_fmi_calls_and_state(fmus, long_mode, name):
    examples = 10_000 if long_mode else 300
    rc, out, err = _child(
        [HERE / "fmi_fuzz.py", fmus[name].parent, "--examples", examples, "--fmu", name],
        timeout=None if long_mode else 600,
    )
    assert rc == 0, f"exit status {rc} (a negative one is a crash)\n{out}\n{err[-4000:]}"
    assert f"{name}: {examples} call sequences and state checks passed" in out


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_fuzzed_fmi_calls_and_state_under_pythonfmus_binary(stock_fmus, long_mode, name):
    """The same properties with pythonfmu's binary (every call through Python), fewer cases."""
    examples = 2_000 if long_mode else 40
    args = [stock_fmus[name].parent, "--examples", examples, "--fmu", name, "--stock"]
    rc, out, err = _child([HERE / "fmi_fuzz.py", *args], timeout=None if long_mode else 600)
    assert rc == 0, f"exit status {rc} (a negative one is a crash)\n{out}\n{err[-4000:]}"
    assert f"{name}: {examples} call sequences and state checks passed" in out


@pytest.mark.slow
def test_soak_memory_and_outputs(fmus, long_mode):
    steps = 1_000_000 if long_mode else 20_000
    growth = 20.0 if long_mode else 5.0
    rc, out, err = _child(
        [
            HERE / "soak.py",
            fmus["BearingFriction"].parent,
            "--steps",
            steps,
            "--max-growth",
            growth,
        ],
        timeout=None if long_mode else 600,
    )
    reports = [json.loads(line) for line in out.splitlines() if line.startswith("{")]
    assert rc == 0, f"exit status {rc}\n{out}\n{err[-4000:]}"
    assert {r["name"] for r in reports} == {*NAMES, "seeker_gimbal system"}
    for r in reports:
        assert r["steps"] == steps and r["growth_mb"] <= growth, r


@pytest.mark.slow
def test_fmpy_processes_exit_cleanly(fmus, long_mode):
    """A plain fmpy process that used an FMU (steps, state, a discarded NaN, free) exits 0
    by a normal interpreter exit. 30 runs per FMU in long mode (the README's measurement
    runs `python tests/robustness/exit_check.py build/out`), 3 by default."""
    runs = 30 if long_mode else 3
    rc, out, err = _child(
        [HERE / "exit_check.py", fmus["BearingFriction"].parent, "--runs", runs],
        timeout=None if long_mode else 600,
    )
    reports = [json.loads(line) for line in out.splitlines() if line.startswith("{")]
    assert rc == 0, f"exit status {rc}\n{out}\n{err[-4000:]}"
    assert {r["name"] for r in reports} == set(NAMES)
    for r in reports:
        assert r["runs"] == runs and r["exit_0"] == runs, r

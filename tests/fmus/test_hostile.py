"""A hostile host: every case of ``tests/robustness/hostile.py`` against every FMU, each in its
own process with a time limit (the FMI calls of a case get 5 s of CPU time and 60 s in all).

Under servofmu's export (the FMUs ``servofmu build`` makes where the export was compiled) a
host's mistake gets fmi2Error with a logged error message, logging off as in a plain fmpy
run; under pythonfmu's own binary (the fallback without a compiler) nothing is fatal and the
refusal shows as a discarded step. Either way the host exits normally."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from servofmu.build.exportlib import compiled_export

HOSTILE = Path(__file__).resolve().parents[1] / "robustness" / "hostile.py"
NAMES = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController", "ThermalNetwork")
CASES = (
    "unknown_references",
    "wrong_types",
    "corrupt_states",
    "foreign_states",
    "state_machine",
    "bad_steps",
    "long_steps",
    "non_finite_inputs",
    "null_pointers",
    "free_at_once",
)
STOCK_CASES = ("unknown_references", "corrupt_states", "free_at_once")  # all with --long


def _run_case(path: Path, case: str, stock: bool):
    args = [sys.executable, str(HOSTILE), str(path), case, *(["--stock"] if stock else [])]
    proc = subprocess.run(args, capture_output=True, text=True, timeout=300)
    reports = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
    where = f"{path.stem} {case}: exit status {proc.returncode} (negative: killed by a signal)"
    assert proc.returncode == 0 and proc.stdout.rstrip().endswith("done"), (
        f"{where}\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
    )
    assert reports and not reports[0]["failures"], reports
    return reports[0]["calls"]


def test_the_export_library_is_compiled(fmus):
    """The test suite's FMUs carry servofmu's export (the other FMU tests expect its
    fmi2Error statuses): without it, reinstall with a C++17 compiler (``make`` does when
    setup.py or build/export/ changed)."""
    import zipfile

    assert compiled_export() is not None, "servofmu's export library was not compiled"
    with zipfile.ZipFile(fmus["DCMotor"]) as zf:
        assert json.loads(zf.read("resources/servofmu_build.json"))["export"] == "servofmu"
        assert zf.read("binaries/linux64/DCMotor.so") == compiled_export().read_bytes()


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("name", NAMES)
def test_hostile_host_under_servofmus_export(fmus, name, case):
    if compiled_export() is None:
        pytest.skip("servofmu's export was not compiled (no C++17 compiler at install time)")
    calls = _run_case(fmus[name], case, stock=False)
    assert all(c.get("status") != 4 for c in calls)


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("name", NAMES)
def test_hostile_host_under_pythonfmus_binary(stock_fmus, long_mode, name, case):
    if case not in STOCK_CASES and not long_mode:
        pytest.skip("pythonfmu's binary: the full set with --long")
    calls = _run_case(stock_fmus[name], case, stock=True)
    assert all(c.get("status") != 4 for c in calls)


def test_the_hostile_checks_can_fail(fmus, tmp_path):
    """The child reports a failure: an FMU whose record names the other export is refused
    before anything runs, and the checker flags a wrong status."""
    sys.path.insert(0, str(HOSTILE.parent))
    try:
        from hostile import Checker
    finally:
        sys.path.pop(0)
    check = Checker(stock=False)
    check.refused("a call that returned OK", (0, None, []))
    check.refused("a fatal call", (4, None, [(4, "boom")]))
    check.refused("fmi2Error without a message", (3, None, [(0, "info")]))
    assert len(check.failures) == 3, check.failures
    proc = subprocess.run(
        [sys.executable, str(HOSTILE), str(fmus["DCMotor"]), "wrong_types", "--stock"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert proc.returncode == (0 if compiled_export() is None else 2), proc.stderr

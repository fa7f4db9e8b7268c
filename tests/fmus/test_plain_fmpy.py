"""The FMUs with plain fmpy, as a new user runs them: a fresh interpreter of a virtual
environment that has only fmpy, numpy and scipy (created once per test session; pip takes the
versions of this environment, from its cache when it has them).

- every ordered pair of the five FMUs in one fresh process: one after another
  (``simulate_fmu`` deletes the first one's extraction folder, where the servofmu package was
  imported from), then side by side (both instantiated, the first one's folder deleted while
  both step);
- a user's mistakes with ``simulate_fmu``'s defaults (logging off, no logger): the FMU's
  message is printed by fmpy and the call raises, instead of rows of zeros."""

from __future__ import annotations

import itertools
import json
import os
import subprocess
import sys
import venv
import zipfile
from importlib.metadata import version
from pathlib import Path

import pytest

from servofmu.build.exportlib import compiled_export
from servofmu.physics import compiled

PLAIN = Path(__file__).resolve().parents[1] / "robustness" / "plain_fmpy.py"
NAMES = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController", "ThermalNetwork")
PACKAGES = ("fmpy", "numpy", "scipy")


@pytest.fixture(scope="session")
def plain_python(tmp_path_factory) -> Path:
    """The interpreter of a new virtual environment with only fmpy, numpy and scipy."""
    root = tmp_path_factory.mktemp("plain_venv")
    venv.create(root, with_pip=True)
    python = root / "bin" / "python"
    pins = [f"{p}=={version(p)}" for p in PACKAGES]
    proc = subprocess.run(
        [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check", *pins],
        capture_output=True,
        text=True,
        timeout=900,
    )
    if proc.returncode != 0:
        pytest.skip(f"pip could not install {pins} into a fresh environment: {proc.stderr[-500:]}")
    code = "import importlib.util as u; print(u.find_spec('servofmu'), u.find_spec('pythonfmu'))"
    check = subprocess.run([str(python), "-c", code], capture_output=True, text=True)
    assert check.stdout.split() == ["None", "None"], "the environment must not hold servofmu"
    return python


def _plain(python: Path, *args, timeout=300) -> subprocess.CompletedProcess:
    # a user's plain interpreter: no choice of this test run's kernels reaches it
    env = {k: v for k, v in os.environ.items() if k != compiled.PURE_PYTHON}
    return subprocess.run(
        [str(python), str(PLAIN), *map(str, args)],
        capture_output=True,
        text=True,
        timeout=timeout,
        cwd=PLAIN.parent,  # not the checkout: nothing of servofmu on the path
        env=env,
    )


@pytest.mark.slow
@pytest.mark.parametrize("first, second", list(itertools.permutations(NAMES, 2)))
def test_every_ordered_pair_runs_in_sequence_and_side_by_side(plain_python, fmus, first, second):
    proc = _plain(plain_python, "both", fmus[first], fmus[second])
    assert proc.returncode == 0 and proc.stdout.rstrip().endswith("done"), (
        f"exit status {proc.returncode}\n{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}"
    )
    runs = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
    assert [r["fmu"] for r in runs] == [first, second] * 2, runs  # in sequence, side by side
    assert all(r["rows"] >= 10 and r["finite"] for r in runs), runs


@pytest.mark.slow
@pytest.mark.parametrize("first, second", list(zip(NAMES, NAMES[1:] + NAMES[:1], strict=True)))
def test_fmus_with_pythonfmus_binary_run_in_sequence_and_side_by_side(
    plain_python, stock_fmus, first, second
):
    """The same with pythonfmu's binary, which serves every FMI call through Python: each FMU
    once first and once second."""
    proc = _plain(plain_python, "both", stock_fmus[first], stock_fmus[second])
    assert proc.returncode == 0 and proc.stdout.rstrip().endswith("done"), (
        f"exit status {proc.returncode}\n{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}"
    )
    runs = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
    assert [r["fmu"] for r in runs] == [first, second] * 2, runs
    assert all(r["rows"] >= 10 and r["finite"] for r in runs), runs


@pytest.mark.parametrize(
    "case, words",
    [
        ("celsius", "temperature = 20.0 is outside the valid range [173.15, 473.15]"),
        ("geometry", "ball_diameter = 0.005 m must be below"),
        ("no_scipy", "scipy"),
    ],
)
@pytest.mark.slow
def test_mistakes_are_visible_with_fmpys_defaults(plain_python, fmus, case, words):
    if compiled_export() is None:
        pytest.skip("pythonfmu's binary logs nothing with fmpy's defaults (README)")
    proc = _plain(plain_python, "visible", case, fmus["BearingFriction"])
    assert proc.returncode == 0, proc.stderr[-2000:]
    printed, raised = proc.stdout.split("raised: ", 1)
    assert words in printed and ("[ERROR]" in printed or "[FATAL]" in printed), proc.stdout
    assert not raised.startswith("nothing"), proc.stdout


def test_another_build_is_refused_by_name(plain_python, fmus, tmp_path):
    if compiled_export() is None:
        pytest.skip("pythonfmu's binary logs nothing with fmpy's defaults (README)")
    other = tmp_path / "BearingFriction.fmu"
    with zipfile.ZipFile(fmus["BearingFriction"]) as src, zipfile.ZipFile(other, "w") as dst:
        for item in src.infolist():
            data = src.read(item.filename)
            if item.filename == "resources/servofmu_build.json":
                info = json.loads(data)
                info.update(package_hash="0" * 64, version="9.9.9")
                data = json.dumps(info).encode()
            dst.writestr(item, data)
    proc = _plain(plain_python, "two_builds", fmus["DCMotor"], other)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "built with servofmu 9.9.9" in proc.stdout and "[FATAL]" in proc.stdout, proc.stdout
    assert "raised: Exception: Failed to instantiate model" in proc.stdout


def test_the_environment_is_plain(plain_python):
    names = subprocess.run(
        [str(plain_python), "-m", "pip", "list", "--format=json"],
        capture_output=True,
        text=True,
    ).stdout
    installed = {p["name"].lower() for p in json.loads(names)}
    assert {"fmpy", "numpy", "scipy"} <= installed
    assert not installed & {"servofmu", "pythonfmu", "dask", "matplotlib"}, sys.version


def _kernels_said(stdout: str) -> list[str]:
    """The FMU's messages that say which per-step kernels run."""
    return [line for line in stdout.splitlines() if "per-step kernels" in line]


def _shipped_kernels(fmu: Path) -> list[str]:
    with zipfile.ZipFile(fmu) as z:
        return [
            n
            for n in z.namelist()
            if n.startswith("resources/servofmu/physics/")
            and n.rpartition("/")[2].startswith("_")
            and n.endswith((".so", ".pyd"))
        ]


def test_the_fmu_ships_its_compiled_kernels_and_says_which_run(plain_python, fmus):
    # the compiled kernels of this platform travel in the FMU's copy of the package, and a
    # fresh interpreter (no Cython, no servofmu installed) runs them and logs it
    proc = _plain(plain_python, "log", fmus["BearingFriction"])
    assert proc.returncode == 0 and proc.stdout.rstrip().endswith("done"), proc.stderr[-2000:]
    said = _kernels_said(proc.stdout)
    shipped = _shipped_kernels(fmus["BearingFriction"])
    if compiled.IMPLEMENTATION == "compiled":
        assert len(shipped) == len(compiled.MODULES), shipped
        assert said and f"per-step kernels {compiled.describe()}" in said[0], said
    elif shipped:  # this run forces Python (SERVOFMU_PURE_PYTHON); the FMU runs its twins
        assert len(shipped) == len(compiled.MODULES), shipped
        assert said and "per-step kernels compiled (" in said[0], said
    else:  # an install without a compiler: nothing to ship, and the FMU says why
        assert said and "per-step kernels Python (" in said[0], said


def test_an_fmu_built_without_compiled_kernels_runs_python_and_says_so(
    plain_python, fmus, tmp_path
):
    # as a build on a machine without a C compiler makes it: the FMU's copy of the package
    # has no compiled module, and servofmu_build.json records the hash of that copy
    from servofmu.fmus.package_hash import package_hash

    built = fmus["BearingFriction"]
    copy = tmp_path / "copy"
    with zipfile.ZipFile(built) as z:
        z.extractall(copy)
    for f in (copy / "resources" / "servofmu" / "physics").rglob("_*.so"):
        f.unlink()
    info_file = copy / "resources" / "servofmu_build.json"
    info = json.loads(info_file.read_text())
    info["package_hash"] = package_hash(copy / "resources" / "servofmu")
    info_file.write_text(json.dumps(info))
    path = tmp_path / "BearingFriction.fmu"
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for f in sorted(copy.rglob("*")):
            if f.is_file():
                z.write(f, f.relative_to(copy).as_posix())
    assert _shipped_kernels(path) == []
    proc = _plain(plain_python, "log", path)
    assert proc.returncode == 0 and proc.stdout.rstrip().endswith("done"), proc.stderr[-2000:]
    said = _kernels_said(proc.stdout)
    assert said and "per-step kernels Python (no compiled module for this platform" in said[0]
    runs = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
    assert runs and runs[0]["rows"] >= 10 and runs[0]["finite"], runs

"""The release, as a user gets it: the sdist and the wheel built by the PyPA frontend, the
wheel installed in a fresh venv, every command run from an empty folder.

The frontend runs outside the checkout (``python -m build`` inside it would import the
project's own ``build`` package). Nothing may be written inside the installed package, nor
left in the source tree outside ignored folders.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tarfile
import venv
import zipfile
from email.parser import Parser
from pathlib import Path

import pytest

import servofmu
from servofmu.build.ssp import SSP_DIR, systems
from servofmu.physics import compiled

ROOT = Path(__file__).resolve().parents[2]
BIN = Path(sys.executable).parent


def _run(cmd, cwd, timeout=600, env=None):
    proc = subprocess.run(
        [str(c) for c in cmd], cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env
    )
    assert proc.returncode == 0, f"{cmd}: exit {proc.returncode}\n{proc.stdout}\n{proc.stderr}"
    return proc


def _untracked() -> str:
    """The source tree's untracked files that are not ignored."""
    return subprocess.run(
        ["git", "status", "--porcelain", "--untracked-files=all"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout


@pytest.fixture(scope="module")
def dist(tmp_path_factory):
    """(sdist, wheel): the sdist from the checkout, the wheel from the sdist."""
    if not (ROOT / ".git").exists():
        pytest.skip("needs the git checkout (the release is built from it)")
    out = tmp_path_factory.mktemp("dist")
    before = _untracked()
    frontend = BIN / "pyproject-build"
    _run([frontend, "--sdist", "--outdir", out, ROOT], cwd=out)
    (sdist,) = out.glob("servofmu-*.tar.gz")
    _run([frontend, "--wheel", "--outdir", out, sdist], cwd=out)
    (wheel,) = out.glob("servofmu-*.whl")
    assert _untracked() == before, "building left files in the source tree"
    return sdist, wheel


@pytest.mark.slow
def test_pip_builds_from_the_checkout_without_leaving_files(tmp_path):
    """``pip install <checkout>`` builds in the tree: only into ignored folders."""
    if not (ROOT / ".git").exists():
        pytest.skip("needs the git checkout")
    before = _untracked()
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "-w", tmp_path, ROOT],
         cwd=tmp_path)  # fmt: skip
    assert list(tmp_path.glob("servofmu-*.whl")) and _untracked() == before


@pytest.mark.slow
def test_the_version_is_written_once_and_read_everywhere(dist):
    sdist, wheel = dist
    assert sdist.name == f"servofmu-{servofmu.__version__}.tar.gz"
    with zipfile.ZipFile(wheel) as zf:
        meta_name = next(n for n in zf.namelist() if n.endswith(".dist-info/METADATA"))
        meta = Parser().parsestr(zf.read(meta_name).decode())
        names = zf.namelist()
    assert meta["Version"] == servofmu.__version__
    assert meta["License-Expression"] == "MIT"
    assert any(n.endswith(".dist-info/licenses/LICENSE") for n in names)
    pyproject = (ROOT / "pyproject.toml").read_text()
    assert servofmu.__version__ not in pyproject  # one place: servofmu/__init__.py


def test_the_wheel_holds_what_every_command_reads(dist):
    sdist, wheel = dist
    with zipfile.ZipFile(wheel) as zf:
        names = set(zf.namelist())
    for system in systems():
        for f in system.rglob("*"):
            if f.suffix in (".ssd", ".ssv"):
                assert f"servofmu/ssp/{f.relative_to(SSP_DIR).as_posix()}" in names, f
    for f in (ROOT / "examples").rglob("*"):
        if f.is_file() and "__pycache__" not in f.parts:
            assert f"servofmu/examples/{f.relative_to(ROOT / 'examples').as_posix()}" in names
    for f in (ROOT / "build" / "model_descriptions").glob("*.xml"):
        assert f"servofmu/build/model_descriptions/{f.name}" in names
    for f in (ROOT / "fmu_src" / "servofmu" / "parameters" / "data").glob("*.toml"):
        assert f"servofmu/parameters/data/{f.name}" in names
    with tarfile.open(sdist) as tf:  # the sdist keeps the project's own build/ package
        assert any(n.endswith("/build/fmu.py") for n in tf.getnames())


@pytest.mark.slow
def test_the_sdist_carries_the_kernels_source_and_the_wheel_their_build(dist, user):
    # the wheel is built from the sdist: the compiled modules compile there (Cython is a build
    # requirement only); an installed wheel without Cython runs the compiled module
    sdist, wheel = dist
    with tarfile.open(sdist) as tf:
        names = tf.getnames()
    for source in ("setup.py", "physics/pair/continuation.py", "physics/kernels/_cython_shadow.py"):
        assert any(n.endswith(f"/{source}") for n in names), source
    assert not any("/.setuptools-build/" in n for n in names)  # generated copies stay out
    with zipfile.ZipFile(wheel) as zf:
        names = zf.namelist()
    twins = [
        n
        for n in names
        if n.startswith("servofmu/physics/") and n.rpartition("/")[2].startswith("_")
        and n.endswith(".so")
    ]  # fmt: skip
    for name in compiled.MODULES:  # the sources the twins' SOURCE_HASH covers, .pxd included
        path = "servofmu/physics/" + name.replace(".", "/")
        assert f"{path}.py" in names, path
        assert not Path(ROOT / "fmu_src" / f"{path}.pxd").is_file() or f"{path}.pxd" in names
    if compiled.IMPLEMENTATION == "compiled":  # this machine compiles the kernels
        assert len(twins) == len(compiled.MODULES), twins
    code = "from servofmu.physics import compiled as c; print(c.describe())"
    said = _run([user[0], "-c", code], cwd="/").stdout
    assert said.startswith("compiled (" if twins else "Python ("), said


@pytest.fixture(scope="module")
def user(dist, tmp_path_factory):
    """A fresh venv with the wheel installed (base dependencies only), and an empty folder."""
    _, wheel = dist
    env_dir = tmp_path_factory.mktemp("venv")
    venv.create(env_dir, with_pip=True)
    python = env_dir / "bin" / "python"
    _run([python, "-m", "pip", "install", "--quiet", wheel], cwd=env_dir)
    work = tmp_path_factory.mktemp("empty")
    return python, env_dir / "bin" / "servofmu", work, wheel


def _package_files(python) -> dict[str, float]:
    """Every file of the installed package with its modification time."""
    code = (
        "import os, servofmu, json; root = os.path.dirname(servofmu.__file__); "
        "print(json.dumps({os.path.join(d, f): os.stat(os.path.join(d, f)).st_mtime "
        "for d, _, fs in os.walk(root) for f in fs}))"
    )
    import json

    return json.loads(_run([python, "-c", code], cwd="/").stdout)


def _table(text: str) -> list[str]:
    """The printed result lines of a scenario (not the file list or progress lines)."""
    return [line for line in text.splitlines() if line.strip() and not line.startswith("file:")]


@pytest.mark.slow
def test_every_command_runs_from_an_empty_folder_and_writes_nothing_inside_the_package(
    user, tmp_path
):
    python, servofmu_cmd, work, wheel = user
    before = _package_files(python)
    env = {**os.environ, "MPLBACKEND": "Agg"}

    # the main job: same table as in the checkout
    installed = _run([servofmu_cmd, "scenario", "friction_vs_temperature", "--coarse"], work,
                     env=env)  # fmt: skip
    assert (work / "build" / "out" / "seeker_gimbal.ssp").is_file()  # built where build puts them
    checkout = _run(
        [BIN / "servofmu", "scenario", "friction_vs_temperature", "--coarse", "--out", tmp_path],
        cwd=ROOT,
        env=env,
    )
    assert _table(installed.stdout) == _table(checkout.stdout)

    run = _run([servofmu_cmd, "run", "seeker_gimbal", "--stop", "1"], work, env=env)
    assert "1000 steps to t = 1 s" in run.stdout and (work / "out" / "seeker_gimbal").is_dir()
    paper = _run([servofmu_cmd, "paper", "yu2017"], work, env=env)
    assert "reproduced" in paper.stdout

    _run([servofmu_cmd, "examples", "examples"], work, env=env)
    cal = _run(
        [servofmu_cmd, "calibrate", "examples/data/gimbal_friction_synthetic.csv",
         "--mounting", "yu2017_gimbal_printed", "--speed", "10 deg/s"],
        work,
        env=env,
    )  # fmt: skip
    assert "calibrated.ssv" in cal.stdout
    # a user's mechanism from the example catalogue: built in build/my_gimbal, run there
    own = _run(
        [servofmu_cmd, "run", "seeker_gimbal", "--catalog", "examples/my_gimbal_catalog.toml",
         "--stop", "0.2"],
        work,
        env=env,
    )  # fmt: skip
    assert "200 steps to t = 0.2 s" in own.stdout
    assert (work / "build" / "my_gimbal" / "seeker_gimbal.ssp").is_file()

    # the sweep extra: named when missing (exit 2, before any work), then installed
    proc = subprocess.run(
        [servofmu_cmd, "sweep", "seeker_gimbal", "--grid", "bearing.temperature=253.15",
         "--record", "bearing.friction_torque", "--stop", "0.05"],
        cwd=work, capture_output=True, text=True, env=env, timeout=120,
    )  # fmt: skip
    assert proc.returncode == 2 and "pip install 'servofmu[sweep]'" in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1
    _run([python, "-m", "pip", "install", "--quiet", f"servofmu[sweep] @ {wheel.as_uri()}"], work)
    sweep = _run(
        [servofmu_cmd, "sweep", "seeker_gimbal", "--grid", "bearing.temperature=253.15,293.15",
         "--record", "bearing.friction_torque", "--stop", "0.05", "--workers", "1"],
        work,
        env=env,
    )  # fmt: skip
    assert "2 runs" in sweep.stdout and "0 failed" in sweep.stdout

    after = _package_files(python)
    assert after == before, sorted(set(after) ^ set(before))[:10] or "a file was rewritten"

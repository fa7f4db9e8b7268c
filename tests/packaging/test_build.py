"""The build: what an FMU ships and hashes (only the parts of the package it runs), when a
build is stale, and the one-way dependency of the build and the harness."""

from __future__ import annotations

import ast
import shutil
import subprocess
import zipfile
from pathlib import Path

import pytest

from servofmu.build import fmu as fmu_module
from servofmu.build.fmu import PACKAGE_DIR, is_current
from servofmu.fmus.package_hash import SHIPPED, package_hash

BUILD_DIR = Path(fmu_module.__file__).parent


def _copy_package(tmp_path) -> Path:
    copy = tmp_path / "servofmu"
    shutil.copytree(PACKAGE_DIR, copy, ignore=shutil.ignore_patterns("__pycache__"))
    return copy


def test_fmu_ships_only_what_it_runs(fmus):
    with zipfile.ZipFile(fmus["BearingFriction"]) as zf:
        shipped = {
            n.removeprefix("resources/servofmu/")
            for n in zf.namelist()
            if n.startswith("resources/servofmu/") and not n.endswith("/")
        }
    tops = {name.split("/")[0] for name in shipped}
    assert tops == set(SHIPPED)  # __init__.py, physics/, parameters/, fmus/: no papers, cli
    assert "parameters/data/bearings.toml" in shipped and "fmus/runtime.py" in shipped
    assert not [n for n in shipped if "__pycache__" in n or n.endswith(".pyc")]
    expected = {
        f.relative_to(PACKAGE_DIR).as_posix()
        for part in SHIPPED
        for f in (
            [PACKAGE_DIR / part]
            if (PACKAGE_DIR / part).is_file()
            else (PACKAGE_DIR / part).rglob("*")
        )
        # sources (with the compiled modules' declarations), data and the compiled modules
        # built for this platform (physics/compiled.py)
        if f.is_file()
        and f.suffix in (".py", ".pxd", ".toml", ".so", ".pyd")
        and "__pycache__" not in f.parts
    }
    assert shipped == expected


def test_hash_covers_the_shipped_parts_only(tmp_path):
    copy = _copy_package(tmp_path)
    assert package_hash(copy) == package_hash(PACKAGE_DIR)
    label = copy / "papers" / "common.py"
    label.write_text(label.read_text() + "\n# a new plot label\n")
    (copy / "cli.py").write_text((copy / "cli.py").read_text() + "\n")
    assert package_hash(copy) == package_hash(PACKAGE_DIR)  # not run by an FMU: not stale
    data = copy / "parameters" / "data" / "bearings.toml"
    data.write_text(data.read_text() + "\n# edited\n")
    assert package_hash(copy) != package_hash(PACKAGE_DIR)


def test_is_current_ignores_edits_outside_the_shipped_parts(fmus, tmp_path, monkeypatch):
    out = fmus["BearingFriction"].parent
    assert is_current(out)
    copy = _copy_package(tmp_path)
    (copy / "papers" / "yu2017.py").write_text("# edited\n")
    monkeypatch.setattr(fmu_module, "PACKAGE_DIR", copy)
    assert is_current(out)
    (copy / "fmus" / "runtime.py").write_text((copy / "fmus" / "runtime.py").read_text() + "\n")
    assert not is_current(out)


def test_build_never_imports_the_harness():
    for source in BUILD_DIR.glob("*.py"):
        tree = ast.parse(source.read_text())
        for node in ast.walk(tree):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module]
            assert not [n for n in names if "harness" in n], f"{source.name} imports {names}"


def test_a_new_source_file_of_the_export_library_is_not_ignored_by_git():
    """build/export/ is tracked whole: a source added there shows in ``git status`` (only
    its compiled library is ignored), while a mechanism's build folder stays ignored."""
    checkout = BUILD_DIR.parent
    if not (checkout / ".git").exists():
        pytest.skip("not a git checkout")

    def ignored(path: str) -> bool:
        proc = subprocess.run(
            ["git", "check-ignore", "-q", path], cwd=checkout, capture_output=True, check=False
        )
        assert proc.returncode in (0, 1), proc.stderr
        return proc.returncode == 0

    assert not ignored("build/export/src/pythonfmu/SharedValues.hpp")
    assert not ignored("build/export/NOTES.md")
    assert ignored("build/export/servofmu_export.abi3.so")
    assert ignored("build/my_gimbal/BearingFriction.fmu")

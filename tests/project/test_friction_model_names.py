"""A friction model's name is written in two modules of the package and of its build: its own
and the registry (``servofmu.physics.friction.registry``). Everything else reaches a model
through the registry, so a new model is one module and one registry line. The validation
reports (``servofmu.papers``) compare named models with published data and may name them."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import servofmu
import servofmu.build
from servofmu.physics.friction import registry

PACKAGE = Path(servofmu.__file__).resolve().parent
BUILD = Path(servofmu.build.__file__).resolve().parent
#: The package's sources (the validation reports aside) and the build's.
SOURCES = sorted(p for p in PACKAGE.rglob("*.py") if p.relative_to(PACKAGE).parts[0] != "papers")
SOURCES += sorted(BUILD.glob("*.py"))


def _modules_naming(name: str) -> set[str]:
    word = re.compile(rf"(?<![\w]){re.escape(name)}(?![\w])")  # as grep -w
    return {p.as_posix() for p in SOURCES if word.search(p.read_text(encoding="utf-8"))}


def test_the_package_and_the_build_are_searched():
    names = {p.relative_to(PACKAGE).as_posix() for p in SOURCES if p.is_relative_to(PACKAGE)}
    assert {"fmus/BearingFriction.py", "physics/pair/state.py", "parameters/bearing.py"} <= names
    assert (BUILD / "documentation.py") in SOURCES
    assert not any(n.startswith("papers/") for n in names)


@pytest.mark.parametrize("name", registry.names())
def test_a_model_name_is_in_its_own_module_and_the_registry_only(name):
    own = Path(registry.get(name).implementation().__file__).resolve()
    allowed = {own.as_posix(), Path(registry.__file__).resolve().as_posix()}
    assert _modules_naming(name) <= allowed, sorted(_modules_naming(name) - allowed)
    assert own.as_posix() in _modules_naming(name)

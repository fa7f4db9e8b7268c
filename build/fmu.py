"""Build the servofmu FMUs with pythonfmu."""

from __future__ import annotations

import json
import tempfile
from pathlib import Path

import servofmu
from servofmu.fmus.slave import BUILD_INFO, package_hash

from .documentation import write_documentation

FMUS = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController")
PACKAGE_DIR = Path(servofmu.__file__).resolve().parent
DEFAULT_OUT = Path(__file__).resolve().parent / "out"


def build_fmu(name: str, out_dir: Path = DEFAULT_OUT) -> Path:
    """Build FMU ``name`` (one of :data:`FMUS`) into ``out_dir``; returns the .fmu path.

    The FMU carries the servofmu package in ``resources/servofmu`` (every FMU the same copy,
    so that several FMUs can share one interpreter), ``resources/servofmu_build.json`` (the
    package hash checked at instantiation) and ``documentation/index.html``. State handling
    and serialisation are declared (``canGetAndSetFMUstate``, ``canSerializeFMUstate``)."""
    from pythonfmu.builder import FmuBuilder

    if name not in FMUS:
        raise ValueError(f"FMU name = {name!r} is not one of {FMUS}")
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    script = PACKAGE_DIR / "fmus" / f"{name}.py"
    with tempfile.TemporaryDirectory(prefix="servofmu_build_") as tmp:
        tmp = Path(tmp)
        info = tmp / BUILD_INFO
        info.write_text(
            json.dumps(
                {
                    "model": name,
                    "version": servofmu.__version__,
                    "package_hash": package_hash(PACKAGE_DIR),
                },
                indent=2,
            )
        )
        doc = tmp / "documentation"
        write_documentation(name, doc)
        path = FmuBuilder.build_FMU(
            script,
            dest=out_dir,
            project_files=[PACKAGE_DIR, info],
            documentation_folder=doc,
            canGetAndSetFMUstate=True,
            canSerializeFMUstate=True,
        )
    return Path(path)


def build_all(out_dir: Path = DEFAULT_OUT, names=FMUS) -> list[Path]:
    """Build every FMU in ``names``; returns their paths."""
    return [build_fmu(n, out_dir) for n in names]

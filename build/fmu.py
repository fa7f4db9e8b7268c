"""Build the servofmu FMUs with pythonfmu."""

from __future__ import annotations

import json
import shutil
import sys
import tempfile
from pathlib import Path

import servofmu
from servofmu.fmus import slave
from servofmu.fmus.slave import BUILD_INFO, SHIPPED, package_hash

from .catalogs import Defaults
from .documentation import write_documentation
from .presets import start_values, write_presets

FMUS = ("BearingFriction", "ActuatorStiffness", "DCMotor", "ServoController", "ThermalNetwork")
PACKAGE_DIR = Path(servofmu.__file__).resolve().parent
#: Where ``servofmu build`` writes, and where every command looks for built FMUs and systems
#: (building them there when they are missing or stale): the working folder's build/out.
#: Relative, so resolved against the folder a command runs in; never inside the package.
DEFAULT_OUT = Path("build") / "out"


def build_fmu(name: str, out_dir: Path = DEFAULT_OUT, defaults: Defaults | None = None) -> Path:
    """Build FMU ``name`` (one of :data:`FMUS`) into ``out_dir``; returns the .fmu path.

    The FMU carries what it runs of the servofmu package in ``resources/servofmu`` (the parts
    :data:`~servofmu.fmus.slave.SHIPPED`: the package ``__init__``, ``physics/`` with its data
    and ``fmus/``; every FMU the same copy, so that several FMUs can share one interpreter),
    ``resources/servofmu_build.json`` (the hash of those parts, checked at instantiation, and
    the build's start values when ``defaults`` name presets), ``resources/presets/`` (the
    catalogue's presets as SSP parameter sets, BearingFriction and ActuatorStiffness) and
    ``documentation/index.html``. State handling and serialisation are declared
    (``canGetAndSetFMUstate``, ``canSerializeFMUstate``).

    ``defaults`` (:func:`catalogs.load`: user catalogues merged, presets chosen) fill the
    start values: the package stays the same (its hash too), the start values travel in
    ``servofmu_build.json``."""
    from pythonfmu.builder import FmuBuilder

    if name not in FMUS:
        raise ValueError(f"FMU name = {name!r} is not one of {FMUS}")
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    script = PACKAGE_DIR / "fmus" / f"{name}.py"
    start = start_values(name, defaults or Defaults())
    slave.BUILD_START.clear()
    if start:
        slave.BUILD_START[name] = start
    try:
        with tempfile.TemporaryDirectory(prefix="servofmu_build_") as tmp:
            tmp = Path(tmp)
            package = stage_package(tmp / "package")
            info = tmp / BUILD_INFO
            record = {
                "model": name,
                "version": servofmu.__version__,
                "package_hash": package_hash(package),
            }
            if start:
                record["start"] = {k: v for k, (v, _) in start.items()}
                record["catalogues"] = list((defaults or Defaults()).files)
            info.write_text(json.dumps(record, indent=2))
            files = [package, info]
            if name in ("BearingFriction", "ActuatorStiffness"):
                files.append(write_presets(tmp / "presets", name))
            doc = tmp / "documentation"
            write_documentation(name, doc)
            path = FmuBuilder.build_FMU(
                script,
                dest=out_dir,
                project_files=files,
                documentation_folder=doc,
                canGetAndSetFMUstate=True,
                canSerializeFMUstate=True,
            )
    finally:
        slave.BUILD_START.clear()
    return Path(path)


def stage_package(dest: Path) -> Path:
    """Copy the parts of the servofmu package that run inside an FMU (:data:`SHIPPED`: .py
    and .toml files and the compiled kernels built for this platform, if any; no caches) to
    ``dest/servofmu``; returns that folder."""
    target = Path(dest) / "servofmu"
    target.mkdir(parents=True)
    keep = shutil.ignore_patterns("__pycache__", "*.pyc")
    for part in SHIPPED:
        src = PACKAGE_DIR / part
        if src.is_dir():
            shutil.copytree(src, target / part, ignore=keep)
        else:
            shutil.copy2(src, target / part)
    return target


def build_all(
    out_dir: Path = DEFAULT_OUT, names=FMUS, systems: bool = True, defaults: Defaults | None = None
) -> list[Path]:
    """Build every FMU in ``names`` (start values from ``defaults``, see :func:`build_fmu`)
    and, with ``systems``, pack every SSP system of ``ssp/`` with them
    (``out_dir/<system>.ssp``); returns the paths written."""
    from .ssp import pack_all

    paths = [build_fmu(n, out_dir, defaults) for n in names]
    if systems and set(names) == set(FMUS):
        paths += pack_all(out_dir, out_dir)
    return paths


def build_info(fmu: Path) -> dict | None:
    """The build record (``resources/servofmu_build.json``) of a built FMU, or None when
    ``fmu`` is missing or not readable as one.

    Parameters
    ----------
    fmu : pathlib.Path
        A built ``.fmu`` archive.

    Returns
    -------
    dict or None
        ``model``, ``version``, ``package_hash`` and, for a user build, the ``start`` values
        and ``catalogues`` it was built with; None without a readable record.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> print(build_info(Path(tempfile.gettempdir()) / "no_such.fmu"))
    None
    """
    import zipfile

    try:
        with zipfile.ZipFile(fmu) as zf:
            return json.loads(zf.read(f"resources/{BUILD_INFO}"))
    except (OSError, KeyError, ValueError, zipfile.BadZipFile):
        return None


def is_current(out_dir: Path = DEFAULT_OUT) -> bool:
    """True when every FMU and system in ``out_dir`` was built from the current sources: the
    FMU build hash against the parts of the package an FMU ships (an edit elsewhere, e.g. in
    papers/ or the CLI, leaves the FMUs current), with the package's own defaults (not a
    user catalogue's), and archives newer than their ssp/ sources and than the FMUs they
    pack."""
    from .ssp import systems

    current = package_hash(PACKAGE_DIR)
    for name in FMUS:
        info = build_info(Path(out_dir) / f"{name}.fmu")
        if info is None or info["package_hash"] != current or "start" in info:
            return False  # missing, stale, or a user build (start values of a catalogue)
    for system in systems():
        archive = Path(out_dir) / f"{system.name}.ssp"
        newest = max(f.stat().st_mtime for f in system.rglob("*") if f.is_file())
        if not archive.is_file() or archive.stat().st_mtime < newest:
            return False
        if archive.stat().st_mtime < (Path(out_dir) / "BearingFriction.fmu").stat().st_mtime:
            return False
    return True


def ensure_built(out_dir: Path = DEFAULT_OUT) -> Path:
    """Build FMUs and systems into ``out_dir`` unless they are current; returns out_dir.

    A user build there (FMUs built with ``--catalog``/``--preset``) is never overwritten:
    ValueError names the folder and what to do."""
    if not is_current(out_dir):
        user = [
            name for name in FMUS if "start" in (build_info(Path(out_dir) / f"{name}.fmu") or {})
        ]
        if user:
            raise ValueError(
                f"{out_dir} holds FMUs built with a user catalogue or preset ({', '.join(user)}); "
                "this command needs the standard build and will not overwrite yours: run it "
                "from another folder, or move that build (servofmu build --out DIR)"
            )
        print(f"building the FMUs and systems into {out_dir}", file=sys.stderr, flush=True)
        build_all(out_dir)
    return Path(out_dir)

"""Build the servofmu FMUs with pythonfmu."""

from __future__ import annotations

import contextlib
import json
import shutil
import sys
from pathlib import Path

import servofmu
from servofmu.files import OutputError, file_mode, output_folder, scratch_folder, written
from servofmu.fmus import declarations
from servofmu.fmus.package_hash import BUILD_INFO, SHIPPED, package_hash

from .catalogs import Defaults
from .documentation import write_documentation
from .exportlib import compiled_export, export_used, put_export
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
    :data:`~servofmu.fmus.package_hash.SHIPPED`: the package ``__init__``, ``physics/`` with
    its data and ``fmus/``; every FMU the same copy, so that several FMUs can share one
    interpreter),
    ``resources/servofmu_build.json`` (the hash of those parts, checked at instantiation, and
    the build's start values when ``defaults`` name presets), ``resources/presets/`` (the
    catalogue's presets as SSP parameter sets, BearingFriction and ActuatorStiffness) and
    ``documentation/index.html``. State handling and serialisation are declared
    (``canGetAndSetFMUstate``, ``canSerializeFMUstate``). Its Linux binary is servofmu's
    export library where it was compiled at install time, else pythonfmu's (:mod:`.exportlib`;
    ``servofmu_build.json`` says which).

    ``defaults`` (:func:`catalogs.load`: user catalogues merged, presets chosen) fill the
    start values: the package stays the same (its hash too), the start values travel in
    ``servofmu_build.json``, with the mechanism they stand for
    (:meth:`.mechanism.Mechanism.record`: the chosen keys and the catalogue files' hashes)."""
    from pythonfmu.builder import FmuBuilder

    from .mechanism import resolve

    if name not in FMUS:
        raise ValueError(f"FMU name = {name!r} is not one of {FMUS}")
    out_dir = output_folder(out_dir)
    script = PACKAGE_DIR / "fmus" / f"{name}.py"
    start = start_values(name, defaults or Defaults())
    problems = start_value_problems(name, start)
    if problems:  # the FMU would refuse its own start values: it is not packed
        raise ValueError(f"{name}: " + "; ".join(problems))
    declarations.BUILD_START.clear()
    if start:
        declarations.BUILD_START[name] = start
    try:
        with scratch_folder("servofmu_build_") as tmp:
            tmp = Path(tmp)
            package = stage_package(tmp / "package")
            info = tmp / BUILD_INFO
            library = compiled_export()
            record = {
                "model": name,
                "version": servofmu.__version__,
                "package_hash": package_hash(package),
                "mechanism": resolve(defaults or Defaults()).record(),
                "export": export_used(),
            }
            if start:
                record["start"] = {k: v for k, (v, _) in start.items()}
                record["catalogues"] = list((defaults or Defaults()).files)
            info.write_text(json.dumps(record, indent=2))
            files = [package, info]
            if name in ("BearingFriction", "ActuatorStiffness"):
                files.append(write_presets(tmp / "presets", name))
            doc = tmp / "documentation"
            write_documentation(name, doc, resolve(defaults or Defaults()))
            built = FmuBuilder.build_FMU(
                script,
                dest=tmp / "fmu",
                project_files=files,
                documentation_folder=doc,
                canGetAndSetFMUstate=True,
                canSerializeFMUstate=True,
            )
            if library is not None:
                put_export(Path(built), name, library)
            path = out_dir / Path(built).name
            with written(path) as part:  # whole under its name, never half-written
                shutil.copyfile(built, part)
    finally:
        declarations.BUILD_START.clear()
    return path


def start_value_problems(name: str, start: dict) -> list[str]:
    """Every start value of FMU ``name`` (its class's, with ``start`` {variable: (value,
    provenance)} over them) that its own checks would refuse: a number not finite or outside
    the variable's [min, max], an item number that names no item.

    Parameters
    ----------
    name : str
        One of :data:`FMUS`.
    start : dict
        The build's start values (:func:`.presets.start_values`).

    Returns
    -------
    list of str
        One line per refused value ("start value NAME = V (provenance) is outside [lo, hi]
        UNIT"); empty when every value is valid.

    Examples
    --------
    >>> start_value_problems("DCMotor", {})
    []
    >>> start_value_problems("DCMotor", {"resistance": (-1.0, "a typo")})
    ['start value resistance = -1.0 (a typo) is outside its range [1e-06, 1000000.0] Ohm']
    """
    import importlib
    import math

    cls = getattr(importlib.import_module(f"servofmu.fmus.{name}"), name)
    problems = []
    for v in declarations.variables_of(cls, start):
        if v.start is None or v.causality == "output" or isinstance(v.start, str):
            continue
        where = f"start value {v.name} = {v.start!r}"
        if v.name in start:
            where += f" ({start[v.name][1]})"
        if v.type == "Enumeration":
            if not 1 <= v.start <= len(v.items):
                problems.append(f"{where} names no item of {[i.name for i in v.items]}")
            continue
        if v.type not in ("Real", "Integer") or isinstance(v.start, bool):
            continue
        lo = -math.inf if v.min is None else v.min
        hi = math.inf if v.max is None else v.max
        if not (math.isfinite(v.start) and lo <= v.start <= hi):
            problems.append(
                f"{where} is outside its range [{lo!r}, {hi!r}] {v.unit or ''}".rstrip()
            )
    return problems


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
    and, with ``systems``, pack the SSP systems with them (``out_dir/<system>.ssp``): every
    system of ``ssp/`` for the standard mechanism, else the mechanism's systems with it bound
    (:mod:`.mechanism`); returns the paths written."""
    from .mechanism import resolve
    from .ssp import pack_all

    with build_lock(out_dir):
        paths = [build_fmu(n, out_dir, defaults) for n in names]
        if systems and set(names) == set(FMUS):
            paths += pack_all(out_dir, out_dir, resolve(defaults or Defaults()))
    return paths


#: The lock file of a build folder (``flock``: released when its process ends, however).
LOCK_NAME = ".servofmu-build.lock"
_HELD: dict[Path, int] = {}  # build folders this process holds the lock of → depth


@contextlib.contextmanager
def build_lock(out_dir):
    """Hold the build lock of ``out_dir`` (its :data:`LOCK_NAME`): one build at a time per
    folder. When another process holds it, say so on stderr and wait for it. Re-entrant
    within a process.

    Parameters
    ----------
    out_dir : str or pathlib.Path
        The build folder (created).

    Returns
    -------
    contextmanager

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     with build_lock(tmp), build_lock(tmp):  # re-entrant
    ...         print(sorted(p.name for p in Path(tmp).iterdir()))
    ['.servofmu-build.lock']
    """
    import fcntl
    import os

    folder = output_folder(out_dir).resolve()
    if folder in _HELD:
        _HELD[folder] += 1
        try:
            yield
        finally:
            _HELD[folder] -= 1
        return
    try:
        fd = os.open(folder / LOCK_NAME, os.O_CREAT | os.O_RDWR, file_mode())
    except OSError as exc:
        raise OutputError(folder / LOCK_NAME, exc) from None
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            other = os.pread(fd, 32, 0).decode("ascii", "replace").strip() or "?"
            print(
                f"servofmu: waiting for another build in {folder} (process {other}) to finish",
                file=sys.stderr,
                flush=True,
            )
            fcntl.flock(fd, fcntl.LOCK_EX)
        os.ftruncate(fd, 0)
        os.pwrite(fd, str(os.getpid()).encode("ascii"), 0)
        _HELD[folder] = 1
        try:
            yield
        finally:
            del _HELD[folder]
    finally:
        os.close(fd)  # releases the lock


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
        ``model``, ``version``, ``package_hash``, the ``mechanism`` it stands for and, for
        a user build, the ``start`` values and ``catalogues`` it was built with; None
        without a readable record.

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


def recorded_mechanism(info: dict) -> dict:
    """The mechanism a build record names (:meth:`.mechanism.Mechanism.record`), comparable
    across builds: its key, chosen presets and the content hashes of its catalogues (not
    their paths). A record without one (an older build) is the standard mechanism unless it
    carries start values.

    Returns
    -------
    dict
        ``{"key", "mounting", "lubricant", "support_mounting", "catalogues"}``.

    Examples
    --------
    >>> recorded_mechanism({"model": "DCMotor"})["key"]
    'standard'
    >>> recorded_mechanism({"start": {"bore": 0.015}})["key"]
    'a user build'
    """
    record = info.get("mechanism")
    if record is None:
        user = "start" in info or info.get("catalogues")
        record = {"key": "a user build" if user else "standard", "catalogues": []}
    return {
        "key": record.get("key"),
        **{k: record.get(k) for k in ("mounting", "lubricant", "support_mounting")},
        "catalogues": sorted(c["sha256"] for c in record.get("catalogues", [])),
    }


def is_current(out_dir: Path = DEFAULT_OUT, mechanism=None) -> bool:
    """True when every FMU and system of ``mechanism`` (default: the standard one) in
    ``out_dir`` was built from the current sources: the FMU build hash against the parts of
    the package an FMU ships (an edit elsewhere, e.g. in papers/ or the CLI, leaves the FMUs
    current), the mechanism recorded (its presets and the content of its catalogue files),
    and archives newer than their ssp/ sources and than the FMUs they pack.

    Returns
    -------
    bool

    Examples
    --------
    >>> is_current(Path("nowhere"))  # nothing built there
    False
    """
    from .mechanism import resolve
    from .ssp import systems

    mechanism = mechanism or resolve(Defaults())
    expected = recorded_mechanism({"mechanism": mechanism.record()})
    current = package_hash(PACKAGE_DIR)
    for name in FMUS:
        info = build_info(Path(out_dir) / f"{name}.fmu")
        if info is None or info["package_hash"] != current:
            return False  # missing or stale
        if recorded_mechanism(info) != expected:
            return False  # another mechanism, or its catalogues changed
        if info.get("export") != export_used():  # servofmu's export compiled since
            return False
    for system in systems(names=mechanism.systems):
        archive = Path(out_dir) / f"{system.name}.ssp"
        newest = max(f.stat().st_mtime for f in system.rglob("*") if f.is_file())
        if not archive.is_file() or archive.stat().st_mtime < newest:
            return False
        if archive.stat().st_mtime < (Path(out_dir) / "BearingFriction.fmu").stat().st_mtime:
            return False
    return True


def other_mechanism(out_dir: Path, mechanism) -> str | None:
    """The key of another mechanism whose build is in ``out_dir`` (None: none, or a build of
    ``mechanism`` itself, current or stale).

    Returns
    -------
    str or None

    Examples
    --------
    >>> from servofmu.build.mechanism import resolve
    >>> other_mechanism(Path("nowhere"), resolve(Defaults())) is None
    True
    """
    for name in FMUS:
        info = build_info(Path(out_dir) / f"{name}.fmu")
        if info is not None and recorded_mechanism(info)["key"] != mechanism.key:
            return recorded_mechanism(info)["key"]
    return None


def ensure_built(out_dir: Path | None = None, mechanism=None) -> Path:
    """Build the FMUs and systems of ``mechanism`` (:class:`.mechanism.Mechanism`, its
    catalogues loaded; default: the standard one) into ``out_dir`` (default: the mechanism's
    build folder, build/out or build/<key>) unless they are current; returns that folder.

    A build of another mechanism there (another catalogue mounting, or a user build in
    build/out) is never overwritten: ValueError names the folder and what to do."""
    from .mechanism import resolve

    mechanism = mechanism or resolve(Defaults())
    out_dir = Path(out_dir) if out_dir is not None else mechanism.build_dir
    if is_current(out_dir, mechanism):
        return out_dir
    with build_lock(out_dir):  # another build there is waited for, then looked at again
        if not is_current(out_dir, mechanism):
            refuse_other_mechanism(out_dir, mechanism)
            print(
                f"building the FMUs and systems of {mechanism.key} into {out_dir}",
                file=sys.stderr,
                flush=True,
            )
            build_all(out_dir, defaults=mechanism.defaults)
    return out_dir


def refuse_other_mechanism(out_dir: Path, mechanism) -> None:
    """ValueError when ``out_dir`` holds the build of a mechanism other than ``mechanism``.

    Returns
    -------
    None

    Examples
    --------
    >>> from servofmu.build.mechanism import resolve
    >>> refuse_other_mechanism(Path("nowhere"), resolve(Defaults()))  # nothing there
    """
    other = other_mechanism(out_dir, mechanism)
    if other is not None:
        raise ValueError(
            f"{out_dir} holds the FMUs of {other}, not of {mechanism.key}: servofmu will not "
            f"overwrite them; build {mechanism.key} in its own folder ({mechanism.build_dir}, "
            "the default), or move that build"
        )

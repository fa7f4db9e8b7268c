"""The FMI export library in each built FMU (``binaries/linux64/<modelIdentifier>.so``).

servofmu's export (pythonfmu 0.7.0's C++ layer with servofmu's changes: ``export/README.md``)
is compiled when servofmu is installed, where a C++17 compiler is found, into ``export/`` as
``servofmu_export.abi3.so``; the build then puts it into every FMU in place of pythonfmu's binary.
Without it the FMUs carry pythonfmu's binary, and a host's mistake shows only as a discarded
step (``servofmu.fmus.binary``). The FMU records which one it carries in
``resources/servofmu_build.json`` (``"export"``); the slave finds out by itself at run time.
"""

from __future__ import annotations

import shutil
import sys
import tempfile
import zipfile
from pathlib import Path

SERVOFMU = "servofmu"
PYTHONFMU = "pythonfmu"


def compiled_export() -> Path | None:
    """The compiled servofmu export library, or None (not compiled: no compiler at install
    time, or not Linux).

    Returns
    -------
    pathlib.Path or None

    Examples
    --------
    >>> lib = compiled_export()
    >>> lib is None or lib.name.startswith("servofmu_export")
    True
    """
    if not sys.platform.startswith("linux"):
        return None
    found = sorted((Path(__file__).resolve().parent / "export").glob("servofmu_export*.so"))
    return found[0] if found else None


def export_used() -> str:
    """Which export a build puts into the FMUs now.

    Returns
    -------
    str
        :data:`SERVOFMU` when servofmu's export was compiled, else :data:`PYTHONFMU`.

    Examples
    --------
    >>> export_used() in (SERVOFMU, PYTHONFMU)
    True
    """
    return PYTHONFMU if compiled_export() is None else SERVOFMU


def put_export(fmu: Path, model_identifier: str, library: Path) -> None:
    """Replace the Linux binary of the built ``fmu`` by ``library`` (every other member kept
    as it is).

    Parameters
    ----------
    fmu : the .fmu archive (rewritten in place)
    model_identifier : its modelIdentifier (the binary is ``binaries/linux64/<it>.so``)
    library : the shared library to put there

    Returns
    -------
    None

    Examples
    --------
    >>> import tempfile, zipfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     fmu, lib = Path(tmp) / "M.fmu", Path(tmp) / "lib.so"
    ...     _ = lib.write_bytes(b"new")
    ...     with zipfile.ZipFile(fmu, "w") as zf:
    ...         zf.writestr("binaries/linux64/M.so", b"old")
    ...         zf.writestr("modelDescription.xml", b"<m/>")
    ...     put_export(fmu, "M", lib)
    ...     with zipfile.ZipFile(fmu) as zf:
    ...         zf.read("binaries/linux64/M.so"), zf.read("modelDescription.xml")
    (b'new', b'<m/>')
    """
    member = f"binaries/linux64/{model_identifier}.so"
    fmu = Path(fmu)
    with tempfile.NamedTemporaryFile(dir=fmu.parent, suffix=".fmu", delete=False) as tmp:
        rewritten = Path(tmp.name)
    try:
        with zipfile.ZipFile(fmu) as src, zipfile.ZipFile(rewritten, "w") as dst:
            for info in src.infolist():
                if info.filename != member:
                    dst.writestr(info, src.read(info))
            info = zipfile.ZipInfo(member, date_time=(2020, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o755 << 16
            dst.writestr(info, Path(library).read_bytes())
        shutil.move(rewritten, fmu)
    finally:
        rewritten.unlink(missing_ok=True)

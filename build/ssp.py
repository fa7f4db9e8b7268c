"""Pack the SSP systems of ``ssp/`` with their FMUs into ``.ssp`` archives."""

from __future__ import annotations

import importlib.resources
import zipfile
from pathlib import Path

from servofmu.files import written

from .xmlsafe import parse

#: The SSP system sources: the package ``servofmu.ssp`` (the checkout's ``ssp/``, shipped in
#: the wheel), read, never written.
SSP_DIR = Path(str(importlib.resources.files("servofmu.ssp")))
NS = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription"}


def systems(ssp_dir: Path = SSP_DIR, names=None) -> list[Path]:
    """The system folders (those with a SystemStructure.ssd), or those of them in ``names``;
    FileNotFoundError, naming the folder, when there is none (an install without its system
    sources)."""
    found = sorted(p.parent for p in Path(ssp_dir).glob("*/SystemStructure.ssd"))
    if not found:
        raise FileNotFoundError(
            f"no SSP system sources (*/SystemStructure.ssd) in {ssp_dir}: the servofmu "
            "installation is incomplete; reinstall it"
        )
    return found if names is None else [p for p in found if p.name in names]


def fmu_sources(system_dir: Path) -> list[str]:
    """The component sources named in the system's SSD (e.g. resources/DCMotor.fmu)."""
    ssd = Path(system_dir) / "SystemStructure.ssd"
    root = parse(ssd.read_bytes(), str(ssd))
    return sorted({c.get("source") for c in root.iterfind(".//ssd:Component", NS)})


def pack_ssp(system_dir: Path, fmu_dir: Path, out_dir: Path, replace=None) -> Path:
    """Zip ``system_dir`` (SSD, .ssv, variants/) and the FMUs it names, taken from
    ``fmu_dir``, into ``out_dir/<name>.ssp`` (whole under its name, or not at all); raises
    FileNotFoundError for a missing FMU.
    ``replace`` ({path in the system: bytes, or None to leave the file out}) changes files on
    the way (a mechanism's bindings)."""
    system_dir, fmu_dir, out_dir = Path(system_dir), Path(fmu_dir), Path(out_dir)
    target = out_dir / f"{system_dir.name}.ssp"
    replace = replace or {}
    with written(target) as part, zipfile.ZipFile(part, "w", zipfile.ZIP_DEFLATED) as zf:
        for f in sorted(system_dir.rglob("*")):
            if f.is_file() and f.suffix in (".ssd", ".ssv"):
                rel = f.relative_to(system_dir).as_posix()
                if rel not in replace:
                    zf.write(f, rel)
                elif replace[rel] is not None:
                    zf.writestr(rel, replace[rel])
        for source in fmu_sources(system_dir):
            fmu = fmu_dir / Path(source).name
            if not fmu.is_file():
                raise FileNotFoundError(f"{system_dir.name}: {source} not built in {fmu_dir}")
            zf.write(fmu, source)
    return target


def pack_all(fmu_dir: Path, out_dir: Path, mechanism=None) -> list[Path]:
    """Pack every system of ``ssp/``; for a mechanism other than the standard one
    (:class:`.mechanism.Mechanism`), its systems with it bound (:func:`.mechanism.bindings`),
    and no archive of another system stays in ``out_dir``."""
    if mechanism is None or mechanism.standard:
        return [pack_ssp(s, fmu_dir, out_dir) for s in systems()]
    from .mechanism import bindings

    for other in systems(names=set(s.name for s in systems()) - set(mechanism.systems)):
        (Path(out_dir) / f"{other.name}.ssp").unlink(missing_ok=True)
    return [
        pack_ssp(s, fmu_dir, out_dir, bindings(mechanism, s))
        for s in systems(names=mechanism.systems)
    ]

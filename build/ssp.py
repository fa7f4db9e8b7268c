"""Pack the SSP systems of ``ssp/`` with their FMUs into ``.ssp`` archives."""

from __future__ import annotations

import importlib.resources
import zipfile
from pathlib import Path

from .xmlsafe import parse

#: The SSP system sources: the package ``servofmu.ssp`` (the checkout's ``ssp/``, shipped in
#: the wheel), read, never written.
SSP_DIR = Path(str(importlib.resources.files("servofmu.ssp")))
NS = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription"}


def systems(ssp_dir: Path = SSP_DIR) -> list[Path]:
    """The system folders (those with a SystemStructure.ssd); FileNotFoundError, naming the
    folder, when there is none (an install without its system sources)."""
    found = sorted(p.parent for p in Path(ssp_dir).glob("*/SystemStructure.ssd"))
    if not found:
        raise FileNotFoundError(
            f"no SSP system sources (*/SystemStructure.ssd) in {ssp_dir}: the servofmu "
            "installation is incomplete; reinstall it"
        )
    return found


def fmu_sources(system_dir: Path) -> list[str]:
    """The component sources named in the system's SSD (e.g. resources/DCMotor.fmu)."""
    ssd = Path(system_dir) / "SystemStructure.ssd"
    root = parse(ssd.read_bytes(), str(ssd))
    return sorted({c.get("source") for c in root.iterfind(".//ssd:Component", NS)})


def pack_ssp(system_dir: Path, fmu_dir: Path, out_dir: Path) -> Path:
    """Zip ``system_dir`` (SSD, .ssv, variants/) and the FMUs it names, taken from
    ``fmu_dir``, into ``out_dir/<name>.ssp``; raises FileNotFoundError for a missing FMU."""
    system_dir, fmu_dir, out_dir = Path(system_dir), Path(fmu_dir), Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    target = out_dir / f"{system_dir.name}.ssp"
    with zipfile.ZipFile(target, "w", zipfile.ZIP_DEFLATED) as zf:
        for f in sorted(system_dir.rglob("*")):
            if f.is_file() and f.suffix in (".ssd", ".ssv"):
                zf.write(f, f.relative_to(system_dir).as_posix())
        for source in fmu_sources(system_dir):
            fmu = fmu_dir / Path(source).name
            if not fmu.is_file():
                raise FileNotFoundError(f"{system_dir.name}: {source} not built in {fmu_dir}")
            zf.write(fmu, source)
    return target


def pack_all(fmu_dir: Path, out_dir: Path) -> list[Path]:
    """Pack every system of ``ssp/``."""
    return [pack_ssp(s, fmu_dir, out_dir) for s in systems()]

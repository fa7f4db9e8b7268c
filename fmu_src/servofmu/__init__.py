"""servofmu: temperature-aware physics of servo mechanisms, shipped as FMI 2.0 FMUs.

``servofmu.physics`` holds the pure models (numpy in, numpy out, SI units);
``servofmu.papers`` reproduces the source papers; ``servofmu.cli`` is the command line.
"""

import json
import sys
from pathlib import Path

__version__ = "0.1.0"

#: This package was imported from an FMU's ``resources/servofmu`` copy (pythonfmu puts each
#: FMU's resources folder first on ``sys.path``), not from an installation.
_FROM_FMU = (Path(__file__).resolve().parent.parent / "slavemodule.txt").is_file()


def different_build(model: str, info: dict, imported: str = "") -> str:
    """The message for an FMU built from another servofmu than the one imported in the process.

    Parameters
    ----------
    model : the FMU (modelIdentifier)
    info : its ``resources/servofmu_build.json`` (``version``, ``package_hash``)
    imported : the package hash of the servofmu imported in the process

    Returns
    -------
    str

    Examples
    --------
    >>> different_build("DCMotor", {"version": "0.0.9", "package_hash": "ab" * 32}, "cd" * 32)[:62]
    'DCMotor: this FMU was built with servofmu 0.0.9 (abababababab)'
    """
    return (
        f"{model}: this FMU was built with servofmu {info['version']} "
        f"({info['package_hash'][:12]}), but the servofmu already imported in this process "
        f"({__version__}, {imported[:12]}, from {Path(__file__).parent}) differs. Python imports "
        "a package once per process: load FMUs built from one servofmu version together, or "
        "rebuild them with `servofmu build`."
    )


def share_copy(resources) -> None:
    """Let the servofmu already imported in this process also import from the servofmu copy
    in the FMU folder ``resources`` (called first by every FMU's entry script, and by every
    instance with the folder pythonfmu gives it).

    pythonfmu puts each FMU's ``resources`` folder on ``sys.path``, but Python imports a
    package once per process: the first FMU's copy serves every FMU, and a host may delete that
    FMU's folder while others run (fmpy's ``simulate_fmu`` does when it returns). So, when this
    package came from an FMU, the live copy of each newly loaded FMU is put first in the search
    path of ``servofmu`` and its loaded subpackages (deleted folders dropped), and the same for
    pythonfmu's runtime: a module that no FMU imported before is found in a folder that
    exists. An FMU built from another servofmu is refused here, with the reason, before it
    could import a mismatched module. Outside FMUs (an installed servofmu) nothing changes.

    Parameters
    ----------
    resources : str or pathlib.Path
        The FMU's ``resources`` folder.

    Returns
    -------
    None

    Raises
    ------
    ImportError
        For an FMU built from another servofmu than the one imported.

    Examples
    --------
    >>> share_copy("/no/such/fmu/resources")  # not an FMU: nothing to do
    """
    resources = Path(resources)
    copy = resources / "servofmu"
    info_file = resources / "servofmu_build.json"
    if not (_FROM_FMU and info_file.is_file() and (copy / "__init__.py").is_file()):
        return
    info = json.loads(info_file.read_text(encoding="utf-8"))
    hashed = sys.modules.get("servofmu.fmus.package_hash")
    imported = getattr(hashed, "_RUNTIME_HASH", None)
    if imported is not None and info.get("package_hash") != imported:
        raise ImportError(different_build(str(info.get("model")), info, imported))
    for name, module in list(sys.modules.items()):
        if name == "servofmu" or name.startswith("servofmu."):
            _prepend(module, copy.joinpath(*name.split(".")[1:]))
    runtime = sys.modules.get("pythonfmu")
    if runtime is not None and any(
        not Path(p).is_dir() or (Path(p).parent / "slavemodule.txt").is_file()
        for p in getattr(runtime, "__path__", [])
    ):
        _prepend(runtime, resources / "pythonfmu")


def _prepend(package, folder: Path) -> None:
    """Put ``folder`` first in a package's search path, dropping folders that are gone."""
    paths = getattr(package, "__path__", None)
    if paths is None or not folder.is_dir():
        return
    kept = [p for p in paths if Path(p).is_dir() and p != str(folder)]
    paths[:] = [str(folder), *kept]

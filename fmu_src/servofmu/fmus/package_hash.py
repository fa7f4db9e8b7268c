"""Which servofmu an FMU runs: the hash of the package parts an FMU ships, and the build's
record of it.

``servofmu build`` ships the parts of the package in :data:`SHIPPED` inside every FMU and
records their hash in ``resources/servofmu_build.json`` (:data:`BUILD_INFO`). Python imports a
package once per process, so an FMU may find another servofmu already imported (by an FMU of
another build): :func:`build_start` refuses it by name, and a saved FMU state names the hash
it was saved by (:mod:`.calls`).
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from .. import different_build

BUILD_INFO = "servofmu_build.json"  # written into resources/ by the build
#: Package parts that run inside an FMU (the build ships and hashes exactly these).
SHIPPED = ("__init__.py", "physics", "parameters", "fmus")
#: The files of the shipped parts that make up its code: sources, data, compiled modules.
_HASHED = (".py", ".toml", ".so", ".pyd")


def package_hash(root: Path | None = None) -> str:
    """SHA-256 over the relative paths and contents of the .py and .toml files and the
    compiled extension modules (.so, .pyd) of the parts of the servofmu package an FMU runs
    (:data:`SHIPPED`).

    Parameters
    ----------
    root : the package folder (default: this servofmu's)

    Returns
    -------
    str
        64 hexadecimal digits: the code an FMU was built with, compiled parts included; the
        same for the development tree and an FMU's staged copy.

    Examples
    --------
    >>> len(package_hash()), package_hash() == runtime_hash()
    (64, True)
    """
    root = Path(__file__).resolve().parents[1] if root is None else Path(root)
    digest = hashlib.sha256()
    for f in sorted(_shipped_files(root)):
        digest.update(f.relative_to(root).as_posix().encode())
        digest.update(f.read_bytes())
    return digest.hexdigest()


def _shipped_files(root: Path) -> list[Path]:
    files = []
    for part in SHIPPED:
        path = root / part
        candidates = [path] if path.is_file() else path.rglob("*")
        files += [
            f
            for f in candidates
            if f.is_file() and f.suffix in _HASHED and "__pycache__" not in f.parts
        ]
    return files


# the code imported in this process, hashed once while its files certainly exist
_RUNTIME_HASH = package_hash()


def runtime_hash() -> str:
    """The package hash of the servofmu imported in this process (hashed at import).

    Returns
    -------
    str
        64 hexadecimal digits.

    Examples
    --------
    >>> runtime_hash() == _RUNTIME_HASH
    True
    """
    return _RUNTIME_HASH


def build_start(resources, model: str) -> dict[str, tuple[object, str]] | None:
    """The start values a built FMU carries, after refusing a servofmu other than the one it
    was built with.

    Parameters
    ----------
    resources : the FMU's ``resources`` folder (None or a folder without :data:`BUILD_INFO`:
        not a built FMU, e.g. the slave imported by a test or by the build)
    model : the FMU's modelIdentifier (for the message)

    Returns
    -------
    dict or None
        {variable: (start value, "")} of the build; None when not running from a built FMU.

    Raises
    ------
    RuntimeError
        When the servofmu imported in this process is not the one the FMU was built with.

    Examples
    --------
    >>> build_start(None, "DCMotor") is None
    True
    """
    info_file = Path(resources or ".") / BUILD_INFO
    if not info_file.is_file():
        return None
    info = json.loads(info_file.read_text())
    if info["package_hash"] != _RUNTIME_HASH:
        raise RuntimeError(different_build(model, info, _RUNTIME_HASH))
    return {name: (value, "") for name, value in info.get("start", {}).items()}

"""The example files shipped inside the package (``servofmu.examples``): where they are, and
a copy of them into a user's folder (``servofmu examples DEST``)."""

from __future__ import annotations

import importlib.resources
import shutil
from pathlib import Path

#: The files a user copies: everything in the examples package but its Python plumbing.
_SKIP = ("__init__.py", "__pycache__")


def examples_dir() -> Path:
    """The installed folder of the example files (read only: copy them before editing).

    Returns
    -------
    pathlib.Path
        The folder of the package ``servofmu.examples``.

    Examples
    --------
    >>> examples_dir().name, (examples_dir() / "my_gimbal_catalog.toml").is_file()
    ('examples', True)
    """
    return Path(str(importlib.resources.files("servofmu.examples")))


def example_files() -> list[Path]:
    """Every shipped example file, sorted.

    Returns
    -------
    list of pathlib.Path
        Absolute paths inside :func:`examples_dir` (its Python plumbing left out).

    Examples
    --------
    >>> for p in example_files():
    ...     print(p.relative_to(examples_dir()).as_posix())
    README.md
    bearing_friction_temperature.py
    data/gimbal_friction_synthetic.csv
    my_gimbal_catalog.toml
    """
    root = examples_dir()
    return sorted(
        p
        for p in root.rglob("*")
        if p.is_file() and not any(part in _SKIP for part in p.relative_to(root).parts)
    )


def copy_examples(dest: Path, overwrite: bool = False) -> list[Path]:
    """Copy the example files into ``dest`` (created), keeping their relative paths.

    Parameters
    ----------
    dest : str or pathlib.Path
        The folder to copy into.
    overwrite : bool, optional
        Replace files that exist already; without it such a file is a FileExistsError naming
        it, and nothing is copied.

    Returns
    -------
    list of pathlib.Path
        The files written.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     written = copy_examples(Path(tmp) / "mine")
    ...     print(len(written) == len(example_files()), written[0].read_bytes()[:9])
    True b'# example'
    """
    root, dest = examples_dir(), Path(dest)
    pairs = [(src, dest / src.relative_to(root)) for src in example_files()]
    if not overwrite:
        existing = [str(target) for _, target in pairs if target.exists()]
        if existing:
            raise FileExistsError(
                f"{existing[0]} exists already (and {len(existing) - 1} more); copy into "
                "another folder, or pass --force to overwrite"
            )
    for src, target in pairs:
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(src, target)
    return [target for _, target in pairs]

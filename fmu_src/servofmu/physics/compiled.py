"""Which implementation of the compiled modules runs. A few modules of :mod:`servofmu.physics`
are written in Cython's pure-Python mode (:data:`MODULES`): each ``X.py`` runs as it is, and
the build compiles it with its declarations ``X.pxd`` into the extension ``_X`` beside it when
a C compiler is there (``setup.py``; compiled modules call each other's functions in C through
their ``.pxd``). The choice is made once, for all of them, at import: the compiled modules when
every one imports and was built from the source next to it (its ``SOURCE_HASH``, appended by
the build, is :func:`source_hash` of ``X.py`` and ``X.pxd``), the Python ones otherwise, or
when the environment variable ``SERVOFMU_PURE_PYTHON`` is set to a non-empty value other than
``0`` (the tests run both).

Examples
--------
>>> from servofmu.physics import compiled
>>> compiled.IMPLEMENTATION in ("compiled", "python")
True
>>> compiled.module("pair.continuation", "python").__name__
'servofmu.physics.pair.continuation'
"""

from __future__ import annotations

import hashlib
import importlib
import os
from pathlib import Path

#: Environment variable that forces the Python implementation (any value but "" and "0").
PURE_PYTHON = "SERVOFMU_PURE_PYTHON"
#: The modules compiled by the build (dotted names under :mod:`servofmu.physics`), each
#: after the modules it calls in C. ``setup.py`` reads this tuple.
MODULES = (
    "kernels.elementary",
    "kernels.viscosity",
    "kernels.lame",
    "kernels.contact",
    "kernels.friction",
    "pair.rows",
    "pair.point",
    "pair.constants",
    "pair.balls",
    "pair.continuation",
    "shared_step",
    "pair.stepping",
    "thermal.stepping",
    "drives.stepping",
    "drives.motor_stepping",
    "drives.control_stepping",
)

_HERE = Path(__file__).resolve().parent


def twin_name(name: str) -> str:
    """The full name of the compiled twin of module ``name`` (:data:`MODULES`).

    Returns
    -------
    str

    Examples
    --------
    >>> twin_name("pair.continuation")
    'servofmu.physics.pair._continuation'
    """
    parent, _, leaf = name.rpartition(".")
    return ".".join(p for p in (__package__, parent, f"_{leaf}") if p)


def source_hash(name: str) -> str:
    """SHA-256 [hex] of the source ``X.py`` of module ``name`` followed by its ``X.pxd`` (when
    there is one): what the build appends to the compiled twin as ``SOURCE_HASH``.

    Returns
    -------
    str

    Examples
    --------
    >>> len(source_hash("pair.continuation"))
    64
    """
    path = _HERE.joinpath(*name.split("."))
    digest = hashlib.sha256(path.with_suffix(".py").read_bytes())
    pxd = path.with_suffix(".pxd")
    if pxd.is_file():
        digest.update(pxd.read_bytes())
    return digest.hexdigest()


def _load():
    """({name: compiled twin} or None, why the Python path runs: "" when compiled)."""
    if os.environ.get(PURE_PYTHON, "") not in ("", "0"):
        return None, f"{PURE_PYTHON} is set"
    twins = {}
    for name in MODULES:
        try:
            twin = importlib.import_module(twin_name(name))
        except ImportError as exc:
            return None, f"no compiled module for this platform ({exc})"
        if getattr(twin, "SOURCE_HASH", None) != source_hash(name):
            return None, f"the compiled module {twin.__file__} was built from another source"
        twins[name] = twin
    return twins, ""


_TWINS, _WHY = _load()
#: "compiled" or "python": the implementation this process runs.
IMPLEMENTATION = "python" if _TWINS is None else "compiled"


def describe() -> str:
    """One line saying which implementation runs, and why the Python one when it does.

    Returns
    -------
    str

    Examples
    --------
    >>> describe().startswith(("compiled", "Python"))
    True
    """
    if _TWINS is not None:
        return f"compiled ({len(_TWINS)} modules: {', '.join(sorted(_TWINS))})"
    return f"Python ({_WHY})"


def module(name: str, implementation: str | None = None):
    """Module ``name`` (:data:`MODULES`) of ``implementation`` ("compiled" or "python"; None:
    the one this process runs).

    Returns
    -------
    module
        ``servofmu.physics.<name>`` or its compiled twin.

    Examples
    --------
    >>> module("pair.continuation", "python").__name__
    'servofmu.physics.pair.continuation'
    """
    if name not in MODULES:
        raise ValueError(f"module = {name!r} is not one of the compiled modules {MODULES}")
    if implementation is None:
        implementation = IMPLEMENTATION
    if implementation == "python":
        return importlib.import_module(f"{__package__}.{name}")
    if implementation == "compiled":
        if _TWINS is None:
            raise ImportError(
                f"the compiled {twin_name(name)} is not available: {_WHY} (build it with "
                "`pip install -e .` and a C compiler)"
            )
        return _TWINS[name]
    raise ValueError(f"implementation = {implementation!r} is not 'compiled' or 'python'")


def is_compiled(mod) -> bool:
    """Whether ``mod`` is a compiled twin.

    Returns
    -------
    bool

    Examples
    --------
    >>> is_compiled(module("pair.continuation", "python"))
    False
    """
    return any(mod is twin for twin in (_TWINS or {}).values())


#: Names of the former module ``servofmu.physics.continuation``, which is this one now
#: (:data:`servofmu.physics.MOVED`): the compiled module each lives in (this process's
#: implementation of it, as that module gave).
FORMER_NAMES = {
    "PairSolver": "pair.continuation",
    "PairConstants": "pair.constants",
    "Thermal": "pair.constants",
    "thermal_at": "pair.constants",
    "PointState": "pair.point",
}


def kernels(implementation: str | None = None):
    """The per-step pair solver's module of ``implementation`` (as :func:`module`), by the
    former module ``servofmu.physics.continuation``'s name.

    Returns
    -------
    module
        ``servofmu.physics.pair.continuation`` or its compiled twin.

    Examples
    --------
    >>> kernels("python").__name__
    'servofmu.physics.pair.continuation'
    """
    return module("pair.continuation", implementation)


def thermal_floats(constants, temperatures):
    """The pair's thermal state at ``temperatures`` = (housing, shaft, outer ring, inner ring)
    [K] (:func:`~servofmu.physics.pair.constants.thermal_at` of this process's
    implementation), by the former module ``servofmu.physics.continuation``'s name.

    Returns
    -------
    Thermal

    Examples
    --------
    >>> from servofmu.physics.pair import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> c = module("pair.constants").PairConstants(pair)
    >>> thermal_floats(c, (293.15,) * 4).t_inner  # K
    293.15
    """
    return module("pair.constants").thermal_at(constants, *temperatures)


def __getattr__(name: str):
    """A name of :data:`FORMER_NAMES`, from its module; AttributeError for any other name."""
    if name in FORMER_NAMES:
        return getattr(module(FORMER_NAMES[name]), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

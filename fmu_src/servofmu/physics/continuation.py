"""Which implementation of the per-step continuation runs: the compiled
``servofmu.physics._pair_kernels`` (the build compiles :mod:`.pair_kernels` with Cython
when a C compiler is there), or :mod:`.pair_kernels` itself (plain Python). The choice is
made once, at import: the compiled module when it imports and matches the source, the Python
one otherwise, or when the environment variable ``SERVOFMU_PURE_PYTHON`` is set to a
non-empty value other than ``0`` (the tests run both).

The equations and the algorithm are described in :mod:`.pair_kernels`; the names below are
those of the chosen implementation.

Examples
--------
>>> from servofmu.physics import continuation
>>> continuation.IMPLEMENTATION in ("compiled", "python")
True
>>> continuation.kernels().__name__ in ("servofmu.physics._pair_kernels",
...                                     "servofmu.physics.pair_kernels")
True
"""

from __future__ import annotations

import importlib
import os

from . import pair_kernels

#: Environment variable that forces the Python implementation (any value but "" and "0").
PURE_PYTHON = "SERVOFMU_PURE_PYTHON"


def _compiled():
    """(the compiled module or None, why the Python path runs: "" when compiled) — not built,
    built for another interpreter, forced off, or built from another version of the source."""
    if os.environ.get(PURE_PYTHON, "") not in ("", "0"):
        return None, f"{PURE_PYTHON} is set"
    try:
        module = importlib.import_module("._pair_kernels", __package__)
    except ImportError as exc:
        return None, f"no compiled module for this platform ({exc})"
    if getattr(module, "SOURCE_HASH", None) != pair_kernels.SOURCE_HASH:
        return None, f"the compiled module {module.__file__} was built from another source"
    return module, ""


_COMPILED, _WHY = _compiled()
#: "compiled" or "python": the implementation this process runs.
IMPLEMENTATION = "python" if _COMPILED is None else "compiled"


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
    if _COMPILED is not None:
        return f"compiled ({os.path.basename(_COMPILED.__file__)})"
    return f"Python ({_WHY})"


def kernels(implementation: str | None = None):
    """The module of ``implementation`` ("compiled" or "python"; None: the chosen one).

    Returns
    -------
    module
        ``servofmu.physics._pair_kernels`` or ``servofmu.physics.pair_kernels``.

    Examples
    --------
    >>> kernels("python").__name__
    'servofmu.physics.pair_kernels'
    """
    if implementation is None:
        return _COMPILED or pair_kernels
    if implementation == "python":
        return pair_kernels
    if implementation == "compiled":
        if _COMPILED is None:
            raise ImportError(
                f"the compiled servofmu.physics._pair_kernels is not available: {_WHY} (build "
                "it with `pip install -e .` and a C compiler)"
            )
        return _COMPILED
    raise ValueError(f"implementation = {implementation!r} is not 'compiled' or 'python'")


_K = kernels()
PairSolver = _K.PairSolver
PairConstants = _K.PairConstants
PointState = _K.PointState
Thermal = _K.Thermal
thermal_at = _K.thermal_at
thermal_floats = _K.thermal_floats

"""The implementations of the per-step kernels the tests drive side by side: the compiled
twins of ``servofmu.physics.compiled.MODULES`` and their Python sources. Both,
unless ``SERVOFMU_PURE_PYTHON`` is set (then the Python one only); a missing compiled
module is then an ImportError that names itself, not a silent skip."""

from __future__ import annotations

import os

from servofmu.physics.bearing import BearingModel
from servofmu.physics.compiled import PURE_PYTHON


def implementations() -> tuple[str, ...]:
    """("compiled", "python"), or ("python",) when the Python path is forced."""
    if os.environ.get(PURE_PYTHON, "") not in ("", "0"):
        return ("python",)
    return ("compiled", "python")


def models(pair) -> dict[str, BearingModel]:
    """{implementation: BearingModel of ``pair``} for every implementation tested."""
    return {impl: BearingModel(pair, impl) for impl in implementations()}

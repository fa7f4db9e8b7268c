"""The bearing-pair friction model, in one place: thermal coupling (fits, preload) +
equilibrium + friction (Yu 2017 §1–3; Ning §1–2). The names below live in :mod:`.pair`:

- :mod:`.pair.configuration`: the configuration, :class:`BearingPair` (bearing, mounting,
  lubrication, coefficients) and :func:`with_mounting`;
- :mod:`.pair.state`: the exact state, vectorised over operating points:
  :func:`thermal_state` (Yu eq 10–18), :func:`load_state` (Jones; eq 1–7, Ning),
  :func:`bearing_outputs` (eq 8–9, breakaway, regularised sign) and
  :func:`operating_outputs` (all three);
- :mod:`.pair.model`: :class:`BearingModel`, the per-step evaluation an FMU calls
  (continuation first, the exact path as its fallback).
"""

from __future__ import annotations

from .pair.configuration import (
    DEFAULT_COEFFICIENTS,
    LUBRICATIONS,
    MOUNTING_CHANGES,
    PRESSURE_LIMIT,
    BearingPair,
    assembly_geometry,
    effective_shim,
    is_tandem,
    loop_closure,
    loop_stiffness,
    with_mounting,
)
from .pair.model import TEMPERATURE_RANGE, BearingModel
from .pair.mounting import Mounting
from .pair.state import (
    BearingOutputs,
    LoadState,
    ThermalState,
    axial_load_state,
    bearing_outputs,
    exact_point,
    load_state,
    operating_outputs,
    point_outputs,
    state_flags,
    thermal_state,
    to_floats,
)
from .thermal.temperatures import PARTS, PartTemperatures

__all__ = [
    "DEFAULT_COEFFICIENTS",
    "LUBRICATIONS",
    "MOUNTING_CHANGES",
    "PARTS",
    "PRESSURE_LIMIT",
    "TEMPERATURE_RANGE",
    "BearingModel",
    "BearingOutputs",
    "BearingPair",
    "LoadState",
    "Mounting",
    "PartTemperatures",
    "ThermalState",
    "assembly_geometry",
    "axial_load_state",
    "bearing_outputs",
    "effective_shim",
    "exact_point",
    "is_tandem",
    "load_state",
    "loop_closure",
    "loop_stiffness",
    "operating_outputs",
    "point_outputs",
    "state_flags",
    "thermal_state",
    "to_floats",
    "with_mounting",
]

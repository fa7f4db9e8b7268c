"""The flat parameter set of a bearing pair, as the BearingFriction FMU and its ``.ssv`` files
name it, and the :class:`~.bearing.BearingPair` it stands for.

One mapping, used by the FMU (``BearingFriction.configure``) and by the calibration
(``servofmu calibrate``), so that a parameter set fitted to measurements gives the same
torques inside the FMU. Values are SI (m, K, N, N/m); strings are catalogue keys, ``""`` for
"the mounting's own".
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

from . import catalog
from .bearing import PRESSURE_LIMIT, BearingPair, with_mounting
from .friction import FrictionCoefficients

#: Parameters of the pair, in the order of the FMU's modelDescription.
PARAMETER_NAMES = (
    "mounting",
    "bearing",
    "lubrication",
    "lubricant",
    "frame_material",
    "shaft_material",
    "outer_interference",
    "inner_interference",
    "shim",
    "assembly_preload",
    "assembly_temperature",
    "loop_stiffness",
    "hysteresis_loss",
    "sliding_friction",
    "static_friction_ratio",
    "palmgren_s0",
    "regularisation_speed",
    "stribeck_speed",
    "pressure_limit",
)
#: Catalogue lubricant for each lubrication when none is named.
DEFAULT_LUBRICANT = {"grease": "krytox_143aa", "solid": "mos2_film"}


def default_parameters(mounting: str, lubrication: str = "grease") -> dict[str, object]:
    """The parameter set of catalogue mounting ``mounting`` (``data/mountings.toml``) with its
    friction coefficients (``data/coefficients.toml``; the library defaults when the mounting
    has none) and ``lubrication`` ("grease" or "solid") with its default lubricant."""
    mnt = catalog.mounting(mounting)
    try:
        coef = catalog.coefficients(mounting)
    except ValueError:
        coef = FrictionCoefficients()
    if lubrication not in DEFAULT_LUBRICANT:
        raise ValueError(f"lubrication = {lubrication!r} is not one of {sorted(DEFAULT_LUBRICANT)}")
    return {
        "mounting": mounting,
        "bearing": "",
        "lubrication": lubrication,
        "lubricant": DEFAULT_LUBRICANT[lubrication],
        "frame_material": "",
        "shaft_material": "",
        "outer_interference": mnt.fit.outer_interference,
        "inner_interference": mnt.fit.inner_interference,
        "shim": mnt.loop.shim,
        "assembly_preload": mnt.assembly_preload or 0.0,
        "assembly_temperature": mnt.assembly_temperature,
        "loop_stiffness": mnt.loop.stiffness or 0.0,
        "hysteresis_loss": coef.hysteresis_loss,
        "sliding_friction": coef.sliding_friction,
        "static_friction_ratio": coef.static_friction_ratio,
        "palmgren_s0": coef.palmgren_s0 if lubrication == "grease" else 0.0,
        "regularisation_speed": 1.0e-3,
        "stribeck_speed": 1.0e-2,
        "pressure_limit": PRESSURE_LIMIT,
    }


def pair_from_parameters(p: Mapping[str, object]) -> BearingPair:
    """The :class:`BearingPair` of parameter set ``p`` (every name of
    :data:`PARAMETER_NAMES`). ``loop_stiffness`` 0 means "from the parts' E·A/L",
    ``assembly_preload`` 0 means "set by the shim", empty material or bearing keys the
    mounting's own. Raises ValueError (naming the parameter) on a bad key or value."""
    missing = [n for n in PARAMETER_NAMES if n not in p]
    if missing:
        raise ValueError(f"parameter set lacks {missing}")
    mnt = catalog.mounting(p["mounting"])
    fit, loop = mnt.fit, mnt.loop
    if p["frame_material"]:
        frame = catalog.material(p["frame_material"])
        fit = dataclasses.replace(fit, housing_material=frame)
        loop = _with_member_material(loop, ("frame", "housing"), frame)
    if p["shaft_material"]:
        shaft = catalog.material(p["shaft_material"])
        fit = dataclasses.replace(fit, shaft_material=shaft)
        loop = _with_member_material(loop, ("shaft",), shaft)
    solid = p["lubrication"] == "solid"
    pair = BearingPair(
        bearing=catalog.bearing(p["bearing"] or mnt.bearing_key),
        mounting=dataclasses.replace(mnt, fit=fit, loop=loop),
        lubrication=p["lubrication"],
        lubricant=None if solid else catalog.lubricant(p["lubricant"]),
        coefficients=FrictionCoefficients(
            hysteresis_loss=p["hysteresis_loss"],
            sliding_friction=p["sliding_friction"],
            static_friction_ratio=p["static_friction_ratio"],
            palmgren_s0=p["palmgren_s0"],
        ),
        regularisation_speed=p["regularisation_speed"],
        stribeck_speed=p["stribeck_speed"],
        pressure_limit=p["pressure_limit"],
    )
    return with_mounting(
        pair,
        outer_interference=p["outer_interference"],
        inner_interference=p["inner_interference"],
        shim=p["shim"],
        assembly_temperature=p["assembly_temperature"],
        loop_stiffness=p["loop_stiffness"] or None,
        assembly_preload=p["assembly_preload"] or None,
    )


def _with_member_material(loop, names, material):
    members = tuple(
        dataclasses.replace(m, material=material) if m.name in names else m for m in loop.members
    )
    return dataclasses.replace(loop, members=members)

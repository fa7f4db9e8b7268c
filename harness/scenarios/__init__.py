"""System-level scenarios: the papers' experiments reproduced with the harness
(``servofmu scenario NAME``).

- ``friction_vs_temperature``: Yu's electrical method on the seeker gimbal (speed loop,
  −40…+60 °C, torque = k_t·i), next to the bearing model;
- ``stiffness_test``: Liu's stiffness test on the EMA at +10° (100/200/300 N·m);
- ``low_speed_tracking``: sine position tracking at 20 °C and −40 °C, friction dead zone,
  step-size dependence;
- ``thermal_cycle``: Ning's space bearing through −60…+80 °C at constant speed;
- ``chamber_transient``: the part temperatures of a ThermalNetwork in the loop: Yu's gimbal
  through chamber steps and ramps −40 ↔ +60 °C, Ning's bearing through thermal-vacuum (and
  chamber-air) cycles, against the quasi-static curve.
"""

from __future__ import annotations

import importlib

SCENARIOS = (
    "friction_vs_temperature",
    "stiffness_test",
    "low_speed_tracking",
    "thermal_cycle",
    "chamber_transient",
)


def run(name: str, out_dir, fmu_dir=None, coarse: bool = False):
    """Run scenario ``name``; returns its :class:`~.common.ScenarioResult`."""
    if name not in SCENARIOS:
        raise ValueError(f"scenario = {name!r} is not one of {list(SCENARIOS)}")
    return importlib.import_module(f"{__name__}.{name}").run(out_dir, fmu_dir, coarse)

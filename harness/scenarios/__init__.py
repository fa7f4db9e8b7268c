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
  chamber-air) cycles, against the quasi-static curve;
- ``pointing_reversal``: the gimbal's position loop through small-angle reversals (±0.02°)
  at −40, 20 and 60 °C, with pre-rolling friction (Dahl) and without: torque–angle loops,
  tracking error at reversals, hunting.
"""

from __future__ import annotations

import importlib

SCENARIOS = (
    "friction_vs_temperature",
    "stiffness_test",
    "low_speed_tracking",
    "thermal_cycle",
    "chamber_transient",
    "pointing_reversal",
)


#: The scenarios whose runs are independent and go to worker processes (``workers``).
PARALLEL_SCENARIOS = ("chamber_transient",)

#: The scenarios that run any mechanism's gimbal rigs (``--catalog``, ``--mounting``); the
#: others reproduce a paper's own rig (Liu's actuator, Ning's space bearing).
MECHANISM_SCENARIOS = ("friction_vs_temperature", "low_speed_tracking", "chamber_transient")


def check_mechanism(name: str, mechanism) -> None:
    """ValueError when scenario ``name`` cannot run ``mechanism`` (a scenario of a paper's own
    rig asked for another mechanism), or is no scenario.

    Returns
    -------
    None

    Examples
    --------
    >>> check_mechanism("friction_vs_temperature", None)
    >>> try:
    ...     check_mechanism("friction_vs_temprature", None)
    ... except ValueError as exc:
    ...     print(str(exc).split("] ")[-1])
    (did you mean 'friction_vs_temperature'?)
    """
    from servofmu.physics._checks import suggest

    if name not in SCENARIOS:
        raise ValueError(
            f"scenario = {name!r} is not one of {list(SCENARIOS)}{suggest(name, SCENARIOS)}"
        )
    if mechanism is not None and not mechanism.standard and name not in MECHANISM_SCENARIOS:
        raise ValueError(
            f"scenario {name} reproduces its paper's own rig and runs the standard mechanism "
            f"only, not {mechanism.key}; the scenarios of any mechanism are "
            f"{list(MECHANISM_SCENARIOS)}"
        )


def run(name: str, out_dir, fmu_dir=None, coarse: bool = False, mechanism=None, workers=None):
    """Run scenario ``name`` on ``mechanism`` (:class:`servofmu.build.mechanism.Mechanism`,
    its catalogues loaded; default: the standard one), its FMUs and systems from ``fmu_dir``
    (default: the mechanism's build folder, built when missing or stale), the independent
    runs of a scenario of :data:`PARALLEL_SCENARIOS` on ``workers`` processes (default: one
    per core); returns its :class:`~.common.ScenarioResult`."""
    check_mechanism(name, mechanism)
    module = importlib.import_module(f"{__name__}.{name}")
    kw = {"workers": workers} if name in PARALLEL_SCENARIOS else {}
    if name in MECHANISM_SCENARIOS:
        return module.run(out_dir, fmu_dir, coarse, mechanism=mechanism, **kw)
    return module.run(out_dir, fmu_dir, coarse, **kw)

"""The motorisation (torque) margin a mechanism engineer signs: ECSS-E-ST-33-01C clause
4.7.5.3 over temperature, chamber transients and tolerances, with the bearing friction from
:mod:`servofmu.physics` (``servofmu margin``).

- :mod:`.standard` — the rule as pure functions and its factors as data;
- :mod:`.inputs` — the input file (TOML) read and checked;
- :mod:`.study` — the margin at every temperature, case, life, draw and transient time;
- :mod:`.report` — table, CSV and plot.
"""

from __future__ import annotations

from .inputs import MarginInputs, example_input, input_problems, load_inputs
from .report import plot, to_text, write_all, write_csv
from .standard import (
    BASES,
    CATEGORIES,
    TERMS,
    Factors,
    ecss_factors,
    factored_torque,
    minimum_actuation_torque,
    torque_margin,
)
from .study import MarginResult, available_torque, run

__all__ = [
    "BASES",
    "CATEGORIES",
    "TERMS",
    "Factors",
    "MarginInputs",
    "MarginResult",
    "available_torque",
    "ecss_factors",
    "example_input",
    "factored_torque",
    "input_problems",
    "load_inputs",
    "minimum_actuation_torque",
    "plot",
    "run",
    "to_text",
    "torque_margin",
    "write_all",
    "write_csv",
]

"""Calibration of a bearing pair's unknown coefficients from measured friction torque
(``servofmu calibrate``): :mod:`servofmu.calibration.measurements` reads the data,
:mod:`servofmu.calibration.fit` fits with ``scipy.optimize.least_squares`` and checks
identifiability, :mod:`servofmu.calibration.report` writes the report, the plot and the
``.ssv`` parameter set."""

from .fit import UNKNOWNS, Calibration, calibrate, running_torque
from .measurements import DataError, FrictionMeasurements, parse_quantity, read_measurements
from .report import plot, to_text, write_coefficients, write_residuals, write_ssv

__all__ = [
    "UNKNOWNS",
    "Calibration",
    "DataError",
    "FrictionMeasurements",
    "calibrate",
    "parse_quantity",
    "plot",
    "read_measurements",
    "running_torque",
    "to_text",
    "write_coefficients",
    "write_residuals",
    "write_ssv",
]

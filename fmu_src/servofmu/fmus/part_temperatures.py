"""The part-temperature inputs shared by the FMUs whose physics takes the temperatures of a
bearing mounting's parts (:class:`servofmu.physics.thermal.temperatures.PartTemperatures`):
BearingFriction (its pair) and ActuatorStiffness (the ball screw's support pair).

Each such FMU keeps its uniform ``temperature`` input and adds ``housing_temperature``,
``shaft_temperature``, ``outer_ring_temperature`` and ``inner_ring_temperature`` [K], read as
the parameter ``temperature_mode`` says (:data:`TEMPERATURE_MODES`); the default ``uniform``
keeps the behaviour of the uniform input. The physics evaluates a uniform temperature as the
record with every part at it, so equal part temperatures give exactly the uniform outputs.
"""

from __future__ import annotations

from servofmu.fmus.declarations import Item, Var, real_input
from servofmu.physics.thermal.temperatures import PARTS

#: How the temperature inputs are read (parameter ``temperature_mode``): every part at
#: ``temperature``; the rings at their seats' temperatures; or each part its own input.
TEMPERATURE_MODES = {
    "uniform": "every part at temperature (Yu's and Ning's soaked chambers)",
    "housing_shaft": "housing and outer ring at housing_temperature, shaft and inner ring at "
    "shaft_temperature",
    "parts": "housing, shaft, outer and inner ring at their own inputs (a thermal network)",
}
#: The part-temperature inputs, in the order of
# :data:`~servofmu.physics.thermal.temperatures.PARTS`.
PART_INPUTS = tuple(f"{p}_temperature" for p in PARTS)
#: Every temperature input: the uniform one, then the parts'.
TEMPERATURE_INPUTS = ("temperature", *PART_INPUTS)


def part_inputs(of: str = "") -> tuple[Var, ...]:
    """The four part-temperature inputs [K] (start 20 °C, valid 173.15…473.15 K); ``of`` names
    whose parts they are in the descriptions (e.g. " of the support bearings")."""
    return tuple(
        real_input(
            name,
            f"Temperature of the {part.replace('_', ' ')}{of} (temperature_mode parts; "
            + ("housing_shaft too" if part in ("housing", "shaft") else "else unused")
            + ")",
            start=293.15,
            unit="K",
            display_unit="degC",
            min=173.15,
            max=473.15,
        )
        for part, name in zip(PARTS, PART_INPUTS, strict=True)
    )


def temperature_mode_parameter() -> Var:
    """The choice ``temperature_mode`` (:data:`TEMPERATURE_MODES`, default ``uniform``)."""
    return Var(
        name="temperature_mode",
        type="Enumeration",
        causality="parameter",
        description="Which temperature inputs the parts follow",
        start=1,
        items=tuple(Item(k, v) for k, v in TEMPERATURE_MODES.items()),
        declared_type="TemperatureMode",
        source="assumed: uniform, as Yu 2017 and Ning measured after soaking",
    )


def temperatures(slave):
    """The temperatures the physics takes from ``slave``'s inputs by its ``temperature_mode``:
    the uniform ``temperature`` [K], or (housing, shaft, outer ring, inner ring) [K]."""
    mode = slave.temperature_mode
    if mode == 1:
        return slave.temperature
    if mode == 2:
        h, s = slave.housing_temperature, slave.shaft_temperature
        return (h, s, h, s)
    return tuple(getattr(slave, name) for name in PART_INPUTS)


def temperature_inputs(mode: int) -> tuple[str, ...]:
    """The inputs :func:`temperatures` reads in ``temperature_mode`` ``mode``: the uniform
    ``temperature``, the housing's and the shaft's, or the four parts' (a compiled step reads
    them from the shared values in this order).

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> temperature_inputs(2)
    ('housing_temperature', 'shaft_temperature')
    """
    return ("temperature",) if mode == 1 else PART_INPUTS[:2] if mode == 2 else PART_INPUTS

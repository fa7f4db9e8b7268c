"""ThermalNetwork FMU: part temperatures of a bearing mechanism (housing, shaft, outer and inner
rings) from the ambient and sink temperatures and the bearing's power loss, integrated exactly
over each communication step (:mod:`servofmu.physics.thermal.network`).

Defaults: a network filled in at build time (the FMU's documentation names it): the standard
build's is the preset ``yu2017_gimbal_chamber``, a build for another mounting that mounting's
parts in chamber air. The preset ``ning_space_vacuum`` and any mounting give their values
through :func:`thermal_network.preset` / :func:`thermal_network.mechanism_parameters` and
``ThermalParameters.as_dict()``.

The choice ``environment`` (air / vacuum) removes convection and the gas gap in vacuum.

The range its physics holds for: every part between ``minimum_part_temperature`` and
``maximum_part_temperature`` (default 173.15…473.15 K, the temperatures BearingFriction, which
these outputs feed, accepts; set them to your materials' and lubricant's limits). The network's
capacities and conductances are constants of the parts' materials near room temperature, and
beyond those limits the parts' materials or lubricant fail (a bearing steel tempers, a grease
decomposes) long before the computed temperature is reached: at its largest ``power_loss`` the
default network reports an inner ring at thousands of kelvin. Outside the range the output
``outside_valid_range`` is set and one warning naming the part, its temperature and the limit
is logged each time a part leaves it. A step that would take a part to 0 K or below (or to a
value that is not finite) is discarded with a logged error: every temperature output is > 0 K.
"""

from __future__ import annotations

from pathlib import Path

import servofmu

servofmu.share_copy(Path(__file__).parent)  # first of all: see its docstring

import math  # noqa: E402

from pythonfmu.enums import Fmi2Status  # noqa: E402

from servofmu.fmus import accessors  # noqa: E402
from servofmu.fmus.declarations import Item, Var  # noqa: E402
from servofmu.fmus.runtime import ServoSlave  # noqa: E402
from servofmu.physics.thermal import network as tn  # noqa: E402

_P = tn.preset("yu2017_gimbal_chamber")
_OUTPUTS = (
    ("housing_temperature", "Temperature of the housing (frame)"),
    ("shaft_temperature", "Temperature of the shaft"),
    ("outer_ring_temperature", "Temperature of the outer rings (and half the balls)"),
    ("inner_ring_temperature", "Temperature of the inner rings (and half the balls)"),
)
# FMU parameter: (description, unit, min, max); min > 0 where the value must be positive
_PARAMETERS = {
    "housing_capacity": ("Heat capacity of the housing (frame)", "J/K", 1e-9, 1e9),
    "shaft_capacity": ("Heat capacity of the shaft", "J/K", 1e-9, 1e9),
    "outer_ring_capacity": ("Heat capacity of the outer rings, half the balls", "J/K", 1e-9, 1e9),
    "inner_ring_capacity": ("Heat capacity of the inner rings, half the balls", "J/K", 1e-9, 1e9),
    "outer_fit_conductance": ("Conductance housing - outer rings (seats)", "W/K", 1e-12, 1e6),
    "ball_conductance": ("Conductance outer - inner rings (ball contacts)", "W/K", 1e-12, 1e6),
    "inner_fit_conductance": ("Conductance inner rings - shaft (seats)", "W/K", 1e-12, 1e6),
    "gas_gap_conductance": (
        "Conductance shaft - housing through the gas between them (not in vacuum)",
        "W/K",
        0.0,
        1e6,
    ),
    "mount_conductance": ("Conductance housing - ambient (mounting plate)", "W/K", 0.0, 1e6),
    "convection_coefficient": (
        "Heat-transfer coefficient to the ambient air (not in vacuum)",
        "W/(m2.K)",
        0.0,
        1e5,
    ),
    "housing_convection_area": ("Housing surface in the ambient air", "m2", 0.0, 1e3),
    "shaft_convection_area": ("Shaft surface in the ambient air", "m2", 0.0, 1e3),
    "housing_emissivity": ("Emissivity of the housing surface", "1", 0.0, 1.0),
    "housing_radiating_area": ("Housing surface that sees the sink", "m2", 0.0, 1e3),
    "shaft_emissivity": ("Emissivity of the shaft surface", "1", 0.0, 1.0),
    "shaft_radiating_area": ("Shaft surface that sees the sink", "m2", 0.0, 1e3),
    "exchange_area": ("Gray-body radiative exchange area shaft - housing", "m2", 0.0, 1e3),
    "inner_ring_heat_fraction": (
        "Share of power_loss entering the inner rings (the rest: the outer rings)",
        "1",
        0.0,
        1.0,
    ),
}
_ENVIRONMENT = {
    "air": "chamber air: convection and the gas gap conduct",
    "vacuum": "thermal vacuum: no convection, no gas in the gap",
}
# the outputs right after initialization: the steady state of the inputs and every network
# parameter, or initial_temperature (start_steady); the radiation tolerance plays no part
_INITIAL = (
    "ambient_temperature",
    "sink_temperature",
    "power_loss",
    *_PARAMETERS,
    "environment",
    "start_steady",
    "initial_temperature",
)
_STEADY = (
    "true: start at the steady state of the inputs at initialization; false: every part at "
    "initial_temperature"
)


#: The range the network's physics holds for (parameters): (name, description, default [K])
_LIMITS = (
    (
        "minimum_part_temperature",
        "Lowest part temperature the network's physics holds for (its materials and lubricant)",
        173.15,
    ),
    (
        "maximum_part_temperature",
        "Highest part temperature the network's physics holds for (its materials and lubricant)",
        473.15,
    ),
)
_LIMITS_SOURCE = (
    "assumed: the range of the temperatures BearingFriction accepts (173.15…473.15 K), which "
    "these outputs feed; set your materials' and lubricant's limits"
)


def _limit(name, description, start):
    return _real(
        name,
        "parameter",
        description,
        start=start,
        unit="K",
        display_unit="degC",
        min=0.0,
        max=1.0e4,
        source=_LIMITS_SOURCE,
    )


def _real(name, causality, description, **kwargs):
    return Var(name=name, type="Real", causality=causality, description=description, **kwargs)


def _temperature_input(name, description, low):
    return _real(
        name, "input", description, start=293.15, unit="K", display_unit="degC", min=low, max=473.15
    )


def _parameter(field):
    description, unit, low, high = _PARAMETERS[field]
    return _real(
        field,
        "parameter",
        description,
        start=getattr(_P, field),
        unit=unit,
        min=low,
        max=high,
        source=_P.source(field),
    )


class ThermalNetwork(ServoSlave):
    """Lumped-capacitance thermal network of a bearing mechanism."""

    description = (
        "Part temperatures of a bearing mechanism (housing, shaft, outer and inner rings): "
        "lumped capacitances, fits, ball contacts, convection and radiation, exact stepping"
    )
    DEFAULT_EXPERIMENT = (0.0, 3600.0, 10.0)
    PHYSICS = ("servofmu.physics.thermal.network",)
    VARIABLES = (
        _temperature_input(
            "ambient_temperature", "Ambient air and mounting-plate temperature", 173.15
        ),
        _temperature_input(
            "sink_temperature", "Radiative sink temperature (chamber walls, shroud, space)", 0.0
        ),
        _real(
            "power_loss",
            "input",
            "Heat generated in the bearings (BearingFriction.power_loss)",
            start=0.0,
            unit="W",
            min=0.0,
            max=1.0e4,
        ),
        *(
            _real(n, "output", d, unit="K", display_unit="degC", min=0.0, initial_depends=_INITIAL)
            for n, d in _OUTPUTS
        ),
        *(_parameter(field) for field in _PARAMETERS),
        Var(
            name="environment",
            type="Enumeration",
            causality="parameter",
            description="Air (convection, gas gap) or vacuum",
            start=tn.ENVIRONMENTS.index(_P.environment) + 1,
            items=tuple(Item(e, _ENVIRONMENT[e]) for e in tn.ENVIRONMENTS),
            declared_type="ThermalEnvironment",
            source="paper: Yu's climatic chamber (air)",
        ),
        Var(
            name="start_steady",
            type="Boolean",
            causality="parameter",
            description=_STEADY,
            start=True,
            source="assumed: soaked at the start",
        ),
        _real(
            "initial_temperature",
            "parameter",
            "Temperature of every part at the start when start_steady is false",
            start=293.15,
            unit="K",
            display_unit="degC",
            min=173.15,
            max=473.15,
            source="assumed: the mechanism soaked at room temperature",
        ),
        _real(
            "linearisation_tolerance",
            "parameter",
            "Radiation is re-linearised once a part has moved this far (0: every step)",
            start=0.1,
            unit="K",
            min=0.0,
            max=10.0,
            source=(
                "assumed: 0.1 K; Ning's bearing after a 140 K jump, 3 h at 1 s steps: 1497 "
                "matrix exponentials instead of 10800, largest error 1.4e-6 K instead of 5.4e-7 K"
            ),
        ),
        # appended last: pythonfmu numbers value references in declaration order
        *(_limit(name, description, start) for name, description, start in _LIMITS),
        Var(
            name="outside_valid_range",
            type="Boolean",
            causality="output",
            description=(
                "A part temperature lies outside minimum_part_temperature … "
                "maximum_part_temperature, the range this network's physics holds for"
            ),
            initial_depends=(*_INITIAL, *(name for name, _, _ in _LIMITS)),
        ),
    )

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        names = tuple(name for name, _ in _OUTPUTS)
        self._temperatures = accessors.getter(names)  # the state: the part temperatures
        self._assign = self.output_setter(names)
        self.reference = None  # temperatures [K] about which radiation is linearised
        self.started = False  # the initial state has been set

    def configure(self):
        if not self.minimum_part_temperature < self.maximum_part_temperature:
            raise ValueError(
                f"minimum_part_temperature = {self.minimum_part_temperature!r} K must be below "
                f"maximum_part_temperature = {self.maximum_part_temperature!r} K"
            )
        values = {f: getattr(self, f) for f in _PARAMETERS}
        self.params = tn.ThermalParameters(**values, environment=self.item("environment"))
        self.network = tn.network(self.params)
        self.stepper = tn.stepper(self.network)  # the per-step update, one call

    def initialise(self):
        if self.start_steady:
            try:
                state = tn.steady_state(
                    self.network, self.ambient_temperature, self.sink_temperature, self.power_loss
                )
            except ValueError as exc:
                raise ValueError(f"start_steady = True: {exc}") from None
        else:
            state = [self.initial_temperature] * len(_OUTPUTS)
        self._set_state(state)
        self.reference = None
        self.started = True

    def advance(self, current_time, step_size):
        if not self.started:  # the start failed (reported then): try again with today's values
            try:
                self.initialise()
            except ValueError as exc:
                self._error = str(exc)
                return False
        new, ref, bad, outside = self.stepper.advance(  # inputs checked by the slave
            self._temperatures(self),
            self.ambient_temperature,
            self.sink_temperature,
            self.power_loss,
            step_size,
            self.reference,
            self.linearisation_tolerance,
            self.minimum_part_temperature,
            self.maximum_part_temperature,
        )
        if bad >= 0:
            self._error = (
                f"{_OUTPUTS[bad][0]} = {new[bad]!r} K would leave the valid range (finite, > 0 K) "
                f"over a step of {step_size!r} s: shorten the step or check the parameters"
            )
            return False
        self.reference = ref
        self._assign(self, new)
        if outside or self.outside_valid_range:
            self._check_range()
        return True

    shared_step = staticmethod(tn.shared_step)

    def _bind_shared_step(self, step):
        # a warning or a retried start is the Python path's
        if not self.started or self.outside_valid_range:
            return False
        inputs = ("ambient_temperature", "sink_temperature", "power_loss")
        slots = self._shared.slots
        step.bind(
            self.stepper,
            self.reference,
            self.linearisation_tolerance,
            self.minimum_part_temperature,
            self.maximum_part_temperature,
            tuple(slots[name] for name in inputs),
            tuple(slots[name] for name, _ in _OUTPUTS),
        )
        return True

    def _read_shared_step(self, step):
        self.reference = step.reference

    def state_problem(self):
        # a restored state holds temperatures a step could give (advance's rule)
        for name, _ in _OUTPUTS:
            t = getattr(self, name)
            if not (math.isfinite(t) and t > 0.0):
                return f"{name} = {t!r} K is not a temperature (finite, > 0 K)"
        return ""

    def _set_state(self, values):
        self._assign(self, [float(v) for v in values])
        self._check_range()

    def _check_range(self):
        """Set ``outside_valid_range``; one warning each time a part leaves the range."""
        lo, hi = self.minimum_part_temperature, self.maximum_part_temperature
        outside = [(n, getattr(self, n)) for n, _ in _OUTPUTS if not lo <= getattr(self, n) <= hi]
        if outside and not self.outside_valid_range:
            name, t = max(outside, key=lambda item: abs(item[1] - 0.5 * (lo + hi)))
            below = t < lo
            limit = lo if below else hi
            self.log(
                f"{self.instance_name}: {name} = {t:.6g} K ({t - 273.15:.6g} °C) is "
                f"{'below' if below else 'above'} "
                f"{'minimum' if below else 'maximum'}_part_temperature = {limit:.6g} K, the "
                "range the network's physics holds for (its parts' materials and lubricant); "
                "outside_valid_range is set until every part returns",
                status=Fmi2Status.warning,
            )
        self.outside_valid_range = bool(outside)

    def hidden_state(self):
        ref = None if self.reference is None else list(self.reference)
        return {"reference": ref, "started": self.started}

    def restore_hidden_state(self, state):
        ref, started = state["reference"], state["started"]
        if ref is not None and not (
            isinstance(ref, list)
            and len(ref) == len(_OUTPUTS)
            and all(type(v) in (int, float) and math.isfinite(v) for v in ref)
        ):
            raise ValueError(f"reference = {ref!r} is not {len(_OUTPUTS)} finite temperatures")
        if type(started) is not bool:
            raise TypeError(f"started = {started!r} is not a Boolean")
        self.reference = None if ref is None else tuple(float(v) for v in ref)
        self.started = started

"""ActuatorStiffness FMU: stiffness of gear train → ball screw → crank-slider linkage → output
shaft, with the screw's support bearings (Liu 2014 and this project's extension), at the
output shaft for the current angle, hinge moment and temperature
(:class:`servofmu.physics.drives.actuator.ActuatorModel`).

The angle comes from the ``angle`` input (output shaft) or, with the parameter
``motor_side_inputs``, from ``motor_angle`` (motor shaft) through the exact inverse of the
crank-slider (:func:`servofmu.physics.drives.actuator.output_angle`): a system can then connect its
motor to the actuator directly, without a LinearTransformation, which can only be linear.

The support-bearing pair is given by numbers, like BearingFriction's pair: the parameters
``support_<name>`` for every ``name`` of the pair's state (bearing geometry, materials, seats,
loop, preload), with the defaults of the support mounting of Liu's actuator record (a preset).
``support_bearings`` false leaves the pair out (a rigid support). The support bearings carry
a thermal preload: with ``temperature_mode`` ``parts`` (or ``housing_shaft``) their housing,
shaft and rings take their own temperatures (``housing_temperature`` …
``inner_ring_temperature``, e.g. from a ThermalNetwork), as in BearingFriction; the default
``uniform`` reads ``temperature``.
"""

from __future__ import annotations

from pathlib import Path

import servofmu

servofmu.share_copy(Path(__file__).parent)  # first of all: see its docstring

import dataclasses  # noqa: E402
import re  # noqa: E402

from servofmu.fmus.declarations import Var, output, real_input, real_parameter, spec_parameter  # noqa: E402
from servofmu.fmus.part_temperatures import (  # noqa: E402
    TEMPERATURE_INPUTS,
    part_inputs,
    temperature_inputs,
    temperature_mode_parameter,
    temperatures,
)
from servofmu.fmus.runtime import ServoSlave  # noqa: E402
from servofmu.parameters.bearing import (  # noqa: E402
    STATE_PARAMETERS,
    default_parameters,
    default_sources,
    pair_from_parameters,
    prefixed_specs,
)
from servofmu.physics.drives.actuator import (  # noqa: E402
    Actuator,
    ActuatorModel,
    StiffnessBreakdown,
    check_support_pair,
)
from servofmu.physics.drives.actuator import shared_step as actuator_shared_step  # noqa: E402

_A = Actuator.from_catalog("liu2014_ema")
# the per-step update's result: StiffnessBreakdown's fields in order
_BREAKDOWN = tuple(f.name for f in dataclasses.fields(StiffnessBreakdown))
_RATIO_INDEX = _BREAKDOWN.index("reduction_ratio")
_ANGLE = ("angle", "motor_angle")  # the position input: output shaft, or motor shaft
_LOAD = (*TEMPERATURE_INPUTS, "load_torque", *_ANGLE)
# with motor_side_inputs, the angle follows from motor_angle through the ratio's parameters
_MOTOR_SIDE = ("motor_side_inputs", "gear_ratio", "screw_lead")
# the support pair: the actuator record's mounting as the preset of its numbers (a dry film:
# the lubricant plays no part in stiffness)
_SUPPORT_BASE = default_parameters(_A.support_mounting, lubricant="mos2_film")
_SUPPORT_SPECS = prefixed_specs(
    "support_",
    "Support pair",
    STATE_PARAMETERS,
    _SUPPORT_BASE,
    default_sources(_A.support_mounting, lubricant="mos2_film"),
)
#: A support-pair parameter's name in a message of the pair's physics (names as a whole word)
_SUPPORT_NAMES = re.compile(
    r"\b("
    + "|".join(sorted((p.name.removeprefix("support_") for p in _SUPPORT_SPECS), key=len)[::-1])
    + r")\b"
)
# parameters by the part of the model they enter (the outputs' initial dependencies)
_KINEMATICS = ("crank_length", "rod_length", "neutral_crank_angle", "neutral_rod_angle")
_LINKAGE = (
    "crank_area",
    "rod_area",
    "arm_length",
    "shaft_polar_moment",
    "arm_second_moment",
    "youngs_modulus",
    "shear_modulus",
)
_SUPPORT = (
    "seat_stiffness",
    "support_bearings",
    *(p.name for p in _SUPPORT_SPECS),
    "temperature_mode",
)
_GEAR = ("screw_lead", "gear_torsional_stiffness")
_RATIO = ("gear_ratio", "screw_lead")
_ELEMENTS = (*_GEAR, "screw_axial_stiffness", "housing_axial_stiffness", *_LINKAGE, *_SUPPORT)


def _p(name, description, *, field=None, **kw):
    """A Real parameter whose default and provenance are the Liu 2014 record's ``field``
    (default: ``name``); keywords as :func:`real_parameter`."""
    field = field or name
    return real_parameter(
        name, description, start=float(getattr(_A, field)), source=_A.source(field), **kw
    )


def _out(name, description, params, unit="N.m/rad", display="N.m/deg", depends=_LOAD, **kw):
    """An output copying the breakdown's ``field`` (default: none), depending directly on the
    inputs ``depends`` and at initialization on those and the parameters ``params``."""
    return output(
        name,
        description,
        unit=unit,
        display_unit=display,
        depends=depends,
        initial_depends=(*depends, *_KINEMATICS, *_MOTOR_SIDE, *params),
        **kw,
    )


class ActuatorStiffness(ServoSlave):
    """Stiffness of an electromechanical actuator at its output shaft."""

    description = (
        "Stiffness of an EMA (gear train, ball screw, crank-slider, housing, support bearings) "
        "at the output shaft versus angle, hinge moment and temperature (Liu 2014)"
    )
    FEEDTHROUGH = True
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-2)
    PHYSICS = ("servofmu.physics.drives.actuator",)
    VARIABLES = (
        real_input(
            "temperature",
            "Temperature of the actuator (support-bearing preload; temperature_mode uniform)",
            start=293.15,
            unit="K",
            display_unit="degC",
            min=173.15,
            max=473.15,
        ),
        real_input(
            "speed",
            "Output-shaft speed (the quasi-static stiffness does not depend on it)",
            start=0.0,
            unit="rad/s",
            display_unit="deg/s",
            min=-1.0e4,
            max=1.0e4,
        ),
        real_input(
            "load_torque",
            "Hinge moment on the output shaft",
            start=0.0,
            unit="N.m",
            min=-1.0e5,
            max=1.0e5,
        ),
        real_input(
            "angle",
            "Output-shaft angle from the neutral position",
            start=0.0,
            unit="rad",
            display_unit="deg",
            min=-1.5,
            max=1.5,
        ),
        _out(
            "stiffness",
            "Stiffness of the whole actuator at the output shaft (secant M/Δθ)",
            _ELEMENTS,
            field="total",
        ),
        _out(
            "gear_stiffness",
            "Gear train, reflected to the output (Liu eq 8)",
            _GEAR,
            depends=(*_ANGLE,),
            field="gear",
        ),
        _out(
            "screw_stiffness",
            "Ball screw, reflected to the output (Liu eq 8)",
            ("screw_axial_stiffness",),
            depends=(*_ANGLE,),
            field="screw",
        ),
        _out(
            "linkage_stiffness",
            "Crank-slider linkage (Liu eq 9-20)",
            _LINKAGE,
            depends=("load_torque", *_ANGLE),
            field="linkage",
        ),
        _out(
            "housing_stiffness",
            "Housing, reflected to the output",
            ("housing_axial_stiffness",),
            depends=(*_ANGLE,),
            field="housing",
        ),
        _out(
            "support_bearing_stiffness",
            "Support bearings and seat, reflected to the output (inf when none)",
            _SUPPORT,
            field="support_bearing",
            allow_inf=True,
        ),
        _out(
            "reduction_ratio",
            "Motor radians per output radian (Liu eq 4)",
            _RATIO,
            "1",
            None,
            _ANGLE,
            field="reduction_ratio",
        ),
        _out(
            "deflection",
            "Elastic deflection of the output under load_torque",
            _ELEMENTS,
            "rad",
            "deg",
            field="deflection",
        ),
        _out(
            "screw_force",
            "Axial force in the ball screw (Liu eq 11)",
            (),
            "N",
            None,
            ("load_torque", *_ANGLE),
            field="screw_force",
        ),
        _out(
            "motor_load_torque",
            "Hinge moment reflected to the motor shaft, load_torque/reduction_ratio",
            _RATIO,
            "N.m",
            "N.mm",
            ("load_torque", *_ANGLE),
        ),
        _p("gear_ratio", "Gear-train ratio i_g", unit="1", min=1e-3, max=1e4),
        _p(
            "screw_lead",
            "Ball-screw lead p (per revolution)",
            unit="m",
            display_unit="mm",
            min=1e-5,
            max=1.0,
        ),
        _p("crank_length", "Crank length L1", unit="m", display_unit="mm", min=1e-4, max=10.0),
        _p(
            "rod_length",
            "Connecting-rod length L2",
            unit="m",
            display_unit="mm",
            min=1e-4,
            max=10.0,
        ),
        _p(
            "neutral_crank_angle",
            "Crank angle at the neutral position θ0",
            unit="rad",
            display_unit="deg",
            min=1e-3,
            max=3.14,
        ),
        _p(
            "neutral_rod_angle",
            "Rod angle at the neutral position γ0",
            unit="rad",
            display_unit="deg",
            min=-1.5,
            max=1.5,
        ),
        _p(
            "crank_area", "Crank cross-section A1", unit="m2", display_unit="mm2", min=1e-9, max=1.0
        ),
        _p("rod_area", "Rod cross-section A2", unit="m2", display_unit="mm2", min=1e-9, max=1.0),
        _p(
            "arm_length",
            "Output-arm length l (torsion and bending)",
            unit="m",
            display_unit="mm",
            min=1e-6,
            max=10.0,
        ),
        _p(
            "shaft_polar_moment",
            "Polar moment of the output shaft I1",
            unit="m4",
            display_unit="mm4",
            min=1e-16,
            max=1.0,
        ),
        _p(
            "arm_second_moment",
            "Second moment of area of the output arm I",
            unit="m4",
            display_unit="mm4",
            min=1e-16,
            max=1.0,
        ),
        _p(
            "youngs_modulus",
            "Young's modulus of the linkage",
            unit="Pa",
            display_unit="GPa",
            min=1e6,
            max=1e13,
        ),
        _p(
            "shear_modulus",
            "Shear modulus of the linkage",
            unit="Pa",
            display_unit="GPa",
            min=1e6,
            max=1e13,
        ),
        _p(
            "gear_torsional_stiffness",
            "Gear-train stiffness, torsional at the screw shaft",
            unit="N.m/rad",
            min=1e-3,
            max=1e15,
            field="gear_stiffness",
        ),
        _p(
            "screw_axial_stiffness",
            "Ball-screw axial stiffness",
            unit="N/m",
            display_unit="N/um",
            min=1e-3,
            max=1e15,
            field="screw_stiffness",
        ),
        _p(
            "housing_axial_stiffness",
            "Housing axial stiffness along the screw",
            unit="N/m",
            display_unit="N/um",
            min=1e-3,
            max=1e15,
            field="housing_stiffness",
        ),
        _p(
            "seat_stiffness",
            "Axial stiffness in series with the support bearings",
            unit="N/m",
            display_unit="N/um",
            min=1e-3,
            max=1e15,
        ),
        Var(
            name="support_bearings",
            type="Boolean",
            causality="parameter",
            description="true: the screw's support-bearing pair (support_*) in series; false: "
            "a rigid support",
            start=bool(_A.support_mounting),
            source="assumed: this project's extension of Liu 2014",
        ),
        *(spec_parameter(p) for p in _SUPPORT_SPECS),
        # the motor side: an SSP connection can only scale linearly, so a system
        # that drives the actuator from its motor gives it the motor's angle and speed, and
        # the exact crank-slider reduction is applied here
        Var(
            name="motor_side_inputs",
            type="Boolean",
            causality="parameter",
            description=(
                "true: the mechanism's position is motor_angle/motor_speed (motor shaft) "
                "through the exact crank-slider reduction; false: angle/speed (output shaft)"
            ),
            start=False,
            source="assumed: false, the output-shaft inputs",
        ),
        real_input(
            "motor_angle",
            "Motor-shaft angle from the neutral position (with motor_side_inputs)",
            start=0.0,
            unit="rad",
            display_unit="deg",
            min=-1.0e4,
            max=1.0e4,
        ),
        real_input(
            "motor_speed",
            "Motor-shaft speed (with motor_side_inputs)",
            start=0.0,
            unit="rad/s",
            display_unit="rpm",
            min=-1.0e5,
            max=1.0e5,
        ),
        _out(
            "output_angle",
            "Output-shaft angle of the rigid mechanism (angle, or from motor_angle)",
            (),
            "rad",
            "deg",
            _ANGLE,
        ),
        _out(
            "output_speed",
            "Output-shaft speed (speed, or motor_speed over the reduction ratio)",
            (),
            "rad/s",
            "deg/s",
            ("speed", "motor_speed", *_ANGLE),
        ),
        # the support bearings' part temperatures, e.g. from a ThermalNetwork
        *part_inputs(" of the support bearings"),
        temperature_mode_parameter(),
    )

    def configure(self):
        act = dataclasses.replace(
            _A,
            **{
                v.name: getattr(self, v.name)
                for v in self._params
                if v.type == "Real" and hasattr(_A, v.name)
            },
            gear_stiffness=self.gear_torsional_stiffness,
            screw_stiffness=self.screw_axial_stiffness,
            housing_stiffness=self.housing_axial_stiffness,
            support_mounting=_A.support_mounting if self.support_bearings else "",
        )
        support = None
        if self.support_bearings:
            values = dict(_SUPPORT_BASE)
            for p in _SUPPORT_SPECS:
                value = getattr(self, p.name)
                values[p.name.removeprefix("support_")] = p.key(value) if p.choices else value
            try:
                support = pair_from_parameters(values)
                check_support_pair(support)
            except ValueError as exc:  # the pair's names are this FMU's support_<name>
                named = _SUPPORT_NAMES.sub(r"support_\1", str(exc))
                raise ValueError(f"support pair: {named}") from None
        self.model = ActuatorModel(act, support)
        self._step = self.model.stepper.evaluate
        by_field = {v.field: v.name for v in self._outputs if v.field}
        self._set_breakdown = self.output_setter(tuple(by_field[f] for f in _BREAKDOWN))

    def compute(self):
        # the inputs are checked by the slave: the per-step update in one call, its result
        # (StiffnessBreakdown's fields in order) into the outputs in one statement
        angle = self._mechanism_angle()
        m = self.load_torque
        values = self._step(angle, m, temperatures(self))
        self._set_breakdown(self, values)
        ratio = values[_RATIO_INDEX]
        self.motor_load_torque = m / ratio
        self.output_angle = angle
        self.output_speed = self.motor_speed / ratio if self.motor_side_inputs else self.speed

    shared_step = staticmethod(actuator_shared_step)

    def _bind_shared_step(self, step):
        slots = self._shared.slots
        by_field = {v.field: v for v in self._outputs if v.field}
        step.bind(
            self.model.stepper,
            self.motor_side_inputs,
            tuple(slots[n] for n in (*_ANGLE, "speed", "motor_speed", "load_torque")),
            tuple(slots[name] for name in temperature_inputs(self.temperature_mode)),
            tuple(slots[by_field[f].name] for f in _BREAKDOWN),
            tuple(by_field[f].allow_inf for f in _BREAKDOWN),
            _RATIO_INDEX,
            tuple(slots[n] for n in ("motor_load_torque", "output_angle", "output_speed")),
        )
        return True

    def _mechanism_angle(self) -> float:
        """The output angle δ [rad]: the angle input, or the motor angle through the exact
        inverse of the crank-slider (ValueError naming motor_angle beyond a dead centre)."""
        if self.motor_side_inputs:
            return self.model.stepper.output_angle(self.motor_angle)
        return self.angle

    def hidden_state(self):
        # the support pair's continuation (physics/pair/continuation.py): restored bit
        # for bit
        return {"continuation": self.model.state() if self._configured else None}

    def restore_hidden_state(self, state):
        if self._configured:
            self.model.restore(state.get("continuation"))

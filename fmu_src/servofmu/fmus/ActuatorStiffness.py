"""ActuatorStiffness FMU: stiffness of gear train → ball screw → crank-slider linkage → output
shaft, with the screw's support bearings (Liu 2014 and this project's extension), at the
output shaft for the current angle, hinge moment and temperature
(:class:`servofmu.physics.actuator.ActuatorModel`).

The angle comes from the ``angle`` input (output shaft) or, with the parameter
``motor_side_inputs``, from ``motor_angle`` (motor shaft) through the exact inverse of the
crank-slider (:func:`servofmu.physics.actuator.output_angle`): a system can then connect its
motor to the actuator directly, without a LinearTransformation, which can only be linear."""

from __future__ import annotations

import dataclasses

from servofmu.fmus.slave import ServoSlave, Var
from servofmu.physics import catalog
from servofmu.physics.actuator import ActuatorModel
from servofmu.physics.actuator import output_angle as mechanism_output_angle
from servofmu.physics.bearing import BearingPair, with_mounting

_A = catalog.actuator("liu2014_ema")
_ANGLE = ("angle", "motor_angle")  # the position input: output shaft, or motor shaft
_LOAD = ("temperature", "load_torque", *_ANGLE)


def _p(name, description, unit, display, lo, hi):
    return Var(
        name,
        "Real",
        "parameter",
        description,
        float(getattr(_A, name)),
        unit,
        display,
        lo,
        hi,
        source=_A.source(name),
    )


def _out(name, description, unit="N.m/rad", display="N.m/deg", depends=_LOAD):
    return Var(
        name, "Real", "output", description, unit=unit, display_unit=display, depends=depends
    )


class ActuatorStiffness(ServoSlave):
    """Stiffness of an electromechanical actuator at its output shaft."""

    description = (
        "Stiffness of an EMA (gear train, ball screw, crank-slider, housing, support bearings) "
        "at the output shaft versus angle, hinge moment and temperature (Liu 2014)"
    )
    FEEDTHROUGH = True
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-2)
    PHYSICS = ("servofmu.physics.actuator",)
    VARIABLES = (
        Var(
            "temperature",
            "Real",
            "input",
            "Temperature of the actuator (support-bearing preload)",
            293.15,
            "K",
            "degC",
            173.15,
            473.15,
        ),
        Var(
            "speed",
            "Real",
            "input",
            "Output-shaft speed (the quasi-static stiffness does not depend on it)",
            0.0,
            "rad/s",
            "deg/s",
            -1.0e4,
            1.0e4,
        ),
        Var(
            "load_torque",
            "Real",
            "input",
            "Hinge moment on the output shaft",
            0.0,
            "N.m",
            None,
            -1.0e5,
            1.0e5,
        ),
        Var(
            "angle",
            "Real",
            "input",
            "Output-shaft angle from the neutral position",
            0.0,
            "rad",
            "deg",
            -1.5,
            1.5,
        ),
        _out("stiffness", "Stiffness of the whole actuator at the output shaft (secant M/Δθ)"),
        _out("gear_stiffness", "Gear train, reflected to the output (Liu eq 8)", depends=_ANGLE),
        _out("screw_stiffness", "Ball screw, reflected to the output (Liu eq 8)", depends=_ANGLE),
        _out("linkage_stiffness", "Crank-slider linkage (Liu eq 9-20)", depends=_ANGLE),
        _out("housing_stiffness", "Housing, reflected to the output", depends=_ANGLE),
        _out(
            "support_bearing_stiffness",
            "Support bearings and seat, reflected to the output (inf when none)",
        ),
        _out("reduction_ratio", "Motor radians per output radian (Liu eq 4)", "1", None, _ANGLE),
        _out("deflection", "Elastic deflection of the output under load_torque", "rad", "deg"),
        _out(
            "screw_force",
            "Axial force in the ball screw (Liu eq 11)",
            "N",
            None,
            ("load_torque", *_ANGLE),
        ),
        _out(
            "motor_load_torque",
            "Hinge moment reflected to the motor shaft, load_torque/reduction_ratio",
            "N.m",
            "N.mm",
            ("load_torque", *_ANGLE),
        ),
        _p("gear_ratio", "Gear-train ratio i_g", "1", None, 1e-3, 1e4),
        _p("screw_lead", "Ball-screw lead p (per revolution)", "m", "mm", 1e-5, 1.0),
        _p("crank_length", "Crank length L1", "m", "mm", 1e-4, 10.0),
        _p("rod_length", "Connecting-rod length L2", "m", "mm", 1e-4, 10.0),
        _p(
            "neutral_crank_angle",
            "Crank angle at the neutral position θ0",
            "rad",
            "deg",
            1e-3,
            3.14,
        ),
        _p("neutral_rod_angle", "Rod angle at the neutral position γ0", "rad", "deg", -1.5, 1.5),
        _p("crank_area", "Crank cross-section A1", "m2", "mm2", 1e-9, 1.0),
        _p("rod_area", "Rod cross-section A2", "m2", "mm2", 1e-9, 1.0),
        _p("arm_length", "Output-arm length l (torsion and bending)", "m", "mm", 1e-6, 10.0),
        _p("shaft_polar_moment", "Polar moment of the output shaft I1", "m4", "mm4", 1e-16, 1.0),
        _p(
            "arm_second_moment",
            "Second moment of area of the output arm I",
            "m4",
            "mm4",
            1e-16,
            1.0,
        ),
        _p("youngs_modulus", "Young's modulus of the linkage", "Pa", "GPa", 1e6, 1e13),
        _p("shear_modulus", "Shear modulus of the linkage", "Pa", "GPa", 1e6, 1e13),
        Var(
            "gear_torsional_stiffness",
            "Real",
            "parameter",
            "Gear-train stiffness, torsional at the screw shaft",
            float(_A.gear_stiffness),
            "N.m/rad",
            None,
            1e-3,
            1e15,
            source=_A.source("gear_stiffness"),
        ),
        Var(
            "screw_axial_stiffness",
            "Real",
            "parameter",
            "Ball-screw axial stiffness",
            float(_A.screw_stiffness),
            "N/m",
            "N/um",
            1e-3,
            1e15,
            source=_A.source("screw_stiffness"),
        ),
        Var(
            "housing_axial_stiffness",
            "Real",
            "parameter",
            "Housing axial stiffness along the screw",
            float(_A.housing_stiffness),
            "N/m",
            "N/um",
            1e-3,
            1e15,
            source=_A.source("housing_stiffness"),
        ),
        Var(
            "seat_stiffness",
            "Real",
            "parameter",
            "Axial stiffness in series with the support bearings",
            float(_A.seat_stiffness),
            "N/m",
            "N/um",
            1e-3,
            1e15,
            source=_A.source("seat_stiffness"),
        ),
        Var(
            "support_mounting",
            "String",
            "parameter",
            "Catalogue mounting of the support-bearing pair; empty: none",
            _A.support_mounting,
            source="assumed: this project's extension",
            choices=("", *catalog.keys("mountings")),
        ),
        Var(
            "support_bearing",
            "String",
            "parameter",
            "Support-bearing designation; empty: the mounting's",
            "",
            source="catalogue: data/bearings.toml",
            choices=("", *catalog.keys("bearings")),
        ),
        Var(
            "support_preload",
            "Real",
            "parameter",
            "Preload of the support pair at assembly",
            200.0,
            "N",
            None,
            1e-3,
            1e6,
            source=catalog.mounting("liu2014_screw_support").source("assembly_preload"),
        ),
        # the motor side (issue 15): an SSP connection can only scale linearly, so a system
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
        Var(
            name="motor_angle",
            type="Real",
            causality="input",
            description="Motor-shaft angle from the neutral position (with motor_side_inputs)",
            start=0.0,
            unit="rad",
            display_unit="deg",
            min=-1.0e4,
            max=1.0e4,
        ),
        Var(
            name="motor_speed",
            type="Real",
            causality="input",
            description="Motor-shaft speed (with motor_side_inputs)",
            start=0.0,
            unit="rad/s",
            display_unit="rpm",
            min=-1.0e5,
            max=1.0e5,
        ),
        Var(
            name="output_angle",
            type="Real",
            causality="output",
            description="Output-shaft angle of the rigid mechanism (angle, or from motor_angle)",
            unit="rad",
            display_unit="deg",
            depends=_ANGLE,
        ),
        Var(
            name="output_speed",
            type="Real",
            causality="output",
            description="Output-shaft speed (speed, or motor_speed over the reduction ratio)",
            unit="rad/s",
            display_unit="deg/s",
            depends=("speed", "motor_speed", *_ANGLE),
        ),
    )

    def configure(self):
        act = dataclasses.replace(
            _A,
            **{v.name: getattr(self, v.name) for v in self._params if hasattr(_A, v.name)},
            gear_stiffness=self.gear_torsional_stiffness,
            screw_stiffness=self.screw_axial_stiffness,
            housing_stiffness=self.housing_axial_stiffness,
        )
        support = None
        if self.support_mounting:
            pair = BearingPair.from_catalog(self.support_mounting, "mos2_film")
            if self.support_bearing:
                pair = dataclasses.replace(pair, bearing=catalog.bearing(self.support_bearing))
            support = with_mounting(pair, assembly_preload=self.support_preload)
        self.model = ActuatorModel(act, support)

    def compute(self):
        angle = self._mechanism_angle()
        b = self.model.evaluate(angle, self.load_torque, self.temperature)
        self.stiffness = b.total
        self.gear_stiffness = b.gear
        self.screw_stiffness = b.screw
        self.linkage_stiffness = b.linkage
        self.housing_stiffness = b.housing
        self.support_bearing_stiffness = b.support_bearing
        self.reduction_ratio = b.reduction_ratio
        self.deflection = b.deflection
        self.screw_force = b.screw_force
        self.motor_load_torque = self.load_torque / b.reduction_ratio
        self.output_angle = angle
        self.output_speed = (
            self.motor_speed / b.reduction_ratio if self.motor_side_inputs else self.speed
        )

    def _mechanism_angle(self) -> float:
        """The output angle δ [rad]: the angle input, or the motor angle through the exact
        inverse of the crank-slider (ValueError naming motor_angle beyond a dead centre)."""
        if self.motor_side_inputs:
            return float(mechanism_output_angle(self.model.act, self.motor_angle))
        return self.angle

"""BearingFriction FMU: friction of a preloaded angular-contact ball-bearing pair in a frame,
with the thermal coupling of frame, shaft and bearings (Yu 2017; Ning).

Inputs → :class:`servofmu.physics.bearing.BearingModel` → outputs. Defaults: Yu 2017's seeker
gimbal (71803 pair, Krytox 143AA grease, cast-aluminium frame, 45-steel shaft) with the
coefficients calibrated in ``servofmu paper yu2017``.
"""

from __future__ import annotations

from servofmu.fmus.slave import ServoSlave, Var
from servofmu.physics import catalog
from servofmu.physics.bearing import PRESSURE_LIMIT, BearingModel
from servofmu.physics.bearing_parameters import PARAMETER_NAMES, pair_from_parameters

_MNT = catalog.mounting("yu2017_gimbal")
_COEF = catalog.coefficients("yu2017_gimbal")
_LOADS = ("temperature", "axial_load", "radial_load")
_ALL = ("temperature", "speed", "axial_load", "radial_load")


def _out(name, description, unit, display=None, depends=_LOADS, kind="Real"):
    return Var(name, kind, "output", description, unit=unit, display_unit=display, depends=depends)


class BearingFriction(ServoSlave):
    """Friction torque of a preloaded angular-contact ball-bearing pair versus temperature."""

    description = (
        "Friction torque of a preloaded pair of angular-contact ball bearings in a frame, with "
        "the thermal coupling of frame, shaft and bearings (Yu 2017; Ning)"
    )
    FEEDTHROUGH = True
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-3)
    PHYSICS = (
        "servofmu.physics.bearing",
        "servofmu.physics.friction",
        "servofmu.physics.fits",
        "servofmu.physics.preload",
        "servofmu.physics.equilibrium",
        "servofmu.physics.hertz",
        "servofmu.physics.viscosity",
    )
    VARIABLES = (
        Var(
            "temperature",
            "Real",
            "input",
            "Temperature of bearings, frame and shaft",
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
            "Speed of the shaft relative to the housing (signed)",
            0.0,
            "rad/s",
            "rpm",
            -1.0e4,
            1.0e4,
        ),
        Var(
            "axial_load",
            "Real",
            "input",
            "External axial load on the shaft, positive towards bearing A",
            0.0,
            "N",
            None,
            -1.0e5,
            1.0e5,
        ),
        Var(
            "radial_load",
            "Real",
            "input",
            "External radial load, shared by the two bearings",
            0.0,
            "N",
            None,
            -1.0e5,
            1.0e5,
        ),
        _out(
            "friction_torque",
            "Friction torque opposing rotation, signed like speed (subtract it when driving)",
            "N.m",
            "N.mm",
            _ALL,
        ),
        _out("running_torque", "Running friction torque at |speed|", "N.m", "N.mm", _ALL),
        _out("breakaway_torque", "Breakaway (starting) torque", "N.m", "N.mm"),
        _out("hysteresis_torque", "Elastic hysteresis torque (Yu eq 1-3)", "N.m", "N.mm"),
        _out("spin_torque", "Ball spin torque (Yu eq 5-7; Ning inner-race spin)", "N.m", "N.mm"),
        _out("sliding_torque", "Differential (Heathcote) sliding torque (Ning)", "N.m", "N.mm"),
        _out(
            "viscous_torque",
            "Palmgren viscous torque (Yu eq 8)",
            "N.m",
            "N.mm",
            ("temperature", "speed"),
        ),
        _out("preload", "Axial force in the preload loop", "N"),
        _out("contact_angle", "Operating contact angle of bearing A", "rad", "deg"),
        _out(
            "radial_clearance",
            "Operating radial (diametral) clearance",
            "m",
            "um",
            ("temperature",),
        ),
        _out(
            "kinematic_viscosity",
            "Kinematic viscosity of the lubricant (0 for a dry film)",
            "m2/s",
            "cSt",
            ("temperature",),
        ),
        _out("axial_stiffness", "Axial stiffness of the shaft in the pair", "N/m", "N/um"),
        _out("power_loss", "Power dissipated by friction", "W", None, _ALL),
        _out("max_contact_pressure", "Largest Hertz contact pressure", "Pa", "MPa"),
        _out(
            "outer_fit_interference",
            "Diametral interference of outer ring and bore at temperature",
            "m",
            "um",
            ("temperature",),
        ),
        _out(
            "inner_fit_interference",
            "Diametral interference of shaft and inner ring at temperature",
            "m",
            "um",
            ("temperature",),
        ),
        _out(
            "overloaded",
            "Contact pressure at or above pressure_limit (permanent deformation, ISO 76)",
            None,
            None,
            _LOADS,
            "Boolean",
        ),
        _out(
            "locked",
            "No operating clearance left (balls pinched radially) or no load equilibrium",
            None,
            None,
            _LOADS,
            "Boolean",
        ),
        _out(
            "unloaded",
            "Preload lost: a bearing of the pair carries no axial load (axial play)",
            None,
            None,
            _LOADS,
            "Boolean",
        ),
        Var(
            "mounting",
            "String",
            "parameter",
            "Catalogue mounting: loop geometry and base of the pair",
            "yu2017_gimbal",
            source="catalogue: data/mountings.toml",
            choices=tuple(catalog.keys("mountings")),
        ),
        Var(
            "bearing",
            "String",
            "parameter",
            "Catalogue bearing designation; empty: the mounting's",
            "",
            source="catalogue: data/bearings.toml",
            choices=("", *catalog.keys("bearings")),
        ),
        Var(
            "lubrication",
            "String",
            "parameter",
            "grease (Yu eq 9) or solid (Ning: no viscous term)",
            "grease",
            source="paper: Yu 2017",
            choices=("grease", "solid"),
        ),
        Var(
            "lubricant",
            "String",
            "parameter",
            "Catalogue lubricant (viscosity model) for grease lubrication",
            "krytox_143aa",
            source="paper: Yu 2017 eq 18",
            choices=tuple(catalog.keys("lubricants")),
        ),
        Var(
            "frame_material",
            "String",
            "parameter",
            "Material of frame/housing; empty: the mounting's",
            "",
            source="paper: Yu 2017 §1 (cast aluminium)",
            choices=("", *catalog.keys("materials")),
        ),
        Var(
            "shaft_material",
            "String",
            "parameter",
            "Material of the shaft; empty: the mounting's",
            "",
            source="paper: Yu 2017 §1 (45 steel)",
            choices=("", *catalog.keys("materials")),
        ),
        Var(
            "outer_interference",
            "Real",
            "parameter",
            "Diametral interference of outer ring and housing bore at assembly",
            _MNT.fit.outer_interference,
            "m",
            "um",
            -1.0e-3,
            1.0e-3,
            source=_MNT.source("outer_interference"),
        ),
        Var(
            "inner_interference",
            "Real",
            "parameter",
            "Diametral interference of shaft and inner ring at assembly",
            _MNT.fit.inner_interference,
            "m",
            "um",
            -1.0e-3,
            1.0e-3,
            source=_MNT.source("inner_interference"),
        ),
        Var(
            "shim",
            "Real",
            "parameter",
            "Axial interference added after the play is taken up at assembly",
            _MNT.loop.shim,
            "m",
            "mm",
            -1.0e-3,
            1.0e-3,
            source=_MNT.source("shim"),
        ),
        Var(
            "assembly_preload",
            "Real",
            "parameter",
            "Preload at assembly; 0: set by the shim",
            0.0,
            "N",
            None,
            0.0,
            1.0e5,
            source="assumed: 0 = use the shim",
        ),
        Var(
            "assembly_temperature",
            "Real",
            "parameter",
            "Temperature at which fits and shim are set",
            _MNT.assembly_temperature,
            "K",
            "degC",
            173.15,
            473.15,
            source=_MNT.source("assembly_temperature"),
        ),
        Var(
            "loop_stiffness",
            "Real",
            "parameter",
            "Structural axial stiffness of the preload loop; 0: from the parts' E·A/L",
            0.0,
            "N/m",
            None,
            0.0,
            1.0e13,
            source="derived: Σ L/(E·A) of the mounting's loop members",
        ),
        Var(
            "hysteresis_loss",
            "Real",
            "parameter",
            "Elastic hysteresis loss factor α_r",
            _COEF.hysteresis_loss,
            "1",
            None,
            0.0,
            1.0,
            "tunable",
            source=_COEF.source("hysteresis_loss"),
        ),
        Var(
            "sliding_friction",
            "Real",
            "parameter",
            "Sliding friction coefficient μ (spin, differential sliding)",
            _COEF.sliding_friction,
            "1",
            None,
            0.0,
            2.0,
            "tunable",
            source=_COEF.source("sliding_friction"),
        ),
        Var(
            "static_friction_ratio",
            "Real",
            "parameter",
            "Static over kinetic friction coefficient (breakaway)",
            _COEF.static_friction_ratio,
            "1",
            None,
            1.0,
            10.0,
            "tunable",
            source=_COEF.source("static_friction_ratio"),
        ),
        Var(
            "palmgren_s0",
            "Real",
            "parameter",
            "Palmgren factor s0 (Yu eq 8)",
            _COEF.palmgren_s0,
            "1",
            None,
            0.0,
            100.0,
            "tunable",
            source=_COEF.source("palmgren_s0"),
        ),
        Var(
            "regularisation_speed",
            "Real",
            "parameter",
            "Width of the smooth sign through zero speed",
            1.0e-3,
            "rad/s",
            None,
            1.0e-9,
            1.0e3,
            "tunable",
            source="assumed",
        ),
        Var(
            "stribeck_speed",
            "Real",
            "parameter",
            "Decay speed of the breakaway excess",
            1.0e-2,
            "rad/s",
            None,
            1.0e-9,
            1.0e3,
            "tunable",
            source="assumed",
        ),
        Var(
            "pressure_limit",
            "Real",
            "parameter",
            "Hertz pressure at which the pair counts as overloaded (permanent deformation)",
            PRESSURE_LIMIT,
            "Pa",
            "MPa",
            1.0e8,
            1.0e11,
            source="handbook: ISO 76, 4200 MPa for ball bearings",
        ),
    )

    def configure(self):
        pair = pair_from_parameters({n: getattr(self, n) for n in PARAMETER_NAMES})
        self._point = None  # (temperature, axial_load, radial_load) of the last evaluate
        self.model = BearingModel(pair)

    def hidden_state(self):
        # the continuation of the thermal and load state (physics/continuation.py): a restored
        # instance continues bit for bit
        return {"continuation": self.model.state() if self._configured else None}

    def restore_hidden_state(self, state):
        # the restored outputs need not belong to the model's last operating point: the next
        # compute evaluates every output (found by the state fuzzing of tests/robustness)
        self._point = None
        if self._configured:
            self.model.restore(state.get("continuation"))

    def compute(self):
        point = (self.temperature, self.axial_load, self.radial_load)
        if point == self._point:  # only the speed changed: the speed terms alone
            f, r, v, p = self.model.speed_outputs(self.speed)
            self.friction_torque, self.running_torque, self.viscous_torque, self.power_loss = (
                f,
                r,
                v,
                p,
            )
            return
        o = self.model.evaluate(self.temperature, self.speed, self.axial_load, self.radial_load)
        self._point = point
        self.friction_torque = o.friction_torque
        self.running_torque = o.running_torque
        self.breakaway_torque = o.breakaway_torque
        self.hysteresis_torque = o.hysteresis_torque
        self.spin_torque = o.spin_torque
        self.sliding_torque = o.sliding_torque
        self.viscous_torque = o.viscous_torque
        self.preload = o.preload
        self.contact_angle = o.contact_angle
        self.radial_clearance = o.radial_clearance
        self.kinematic_viscosity = o.kinematic_viscosity
        self.axial_stiffness = o.axial_stiffness
        self.power_loss = o.power_loss
        self.max_contact_pressure = o.max_contact_pressure
        self.outer_fit_interference = o.outer_interference
        self.inner_fit_interference = o.inner_interference
        self.overloaded = o.overloaded
        self.locked = o.locked
        self.unloaded = o.unloaded

r"""BearingFriction FMU: friction of a preloaded angular-contact ball-bearing pair in a frame,
with the thermal coupling of frame, shaft and bearings (Yu 2017; Ning).

The FMU evaluates :class:`servofmu.physics.bearing.BearingModel` at each step: from the
temperatures, the speed and the external loads to the torques, the preload and the flags.
Every physical input is a numeric parameter, and the model uses exactly these numbers: the
bearing's internal geometry (``bore``, ``outer_diameter``, ``width``, ``ball_diameter``,
``n_balls``, ``pitch_diameter``, ``nominal_contact_angle``, ``inner_curvature``,
``outer_curvature``), the materials of rings, balls, housing, shaft and spacer, the seats, the
loop geometry, the preload and the lubricant's ν40/ν100. The defaults are a catalogue preset
filled in at build time: its mounting, bearing, lubricant and friction coefficients (the FMU's
documentation names them under "Defaults of this build"; the standard build's is Yu 2017's
seeker gimbal, a 71803 pair with Krytox 143AA in a cast-aluminium yoke on a 45-steel shaft,
with the coefficients calibrated in ``servofmu paper``'s reproduction of Yu 2017); the presets the
FMU was built with are in ``resources/presets/`` as SSP parameter sets. An inconsistent set (a
geometry that cannot be a bearing, ν100 ≥ ν40, a spring preload without a stiffness, …) is refused
at fmi2ExitInitializationMode with fmi2Error and a logged error naming the values.

``friction_model`` chooses the torque (:mod:`servofmu.physics.friction.models`), one of the
friction models of :mod:`servofmu.physics.friction.registry` (its enumeration items, numbered
from 1 in this order):

FRICTION_MODEL_ITEMS

The SKF model's series constants and coefficients are the ``skf_*`` parameters, the lubricant's
density of the per-contact EHL torque ``lubricant_density``.

``viscous_torque`` is the chosen model's rolling/viscous part; ``grease_torque`` the grease
term (``grease_f0``, ``grease_starting_ratio``, ``grease_reference_speed``; 0 = off), which
adds to the running and the breakaway torque:

.. math::

   M_\mathrm{running} = M_\mathrm{hysteresis} + M_\mathrm{spin} + M_\mathrm{sliding}
   + M_\mathrm{viscous} + M_\mathrm{grease}.

The lubricant's viscosity is the ASTM D341 line through ``lubricant_viscosity_40``/``_100``, or
Vogel's law through them and ``lubricant_viscosity_cold`` at ``lubricant_cold_temperature``
(:mod:`servofmu.physics.lubrication.viscosity`). Outside the range of the lubricant's data (from its
coldest viscosity point or ``lubricant_data_minimum_temperature`` to
``lubricant_maximum_temperature``) the output ``outside_lubricant_range`` is set and one
warning naming the temperature and the limit is logged each time the lubricant's temperature
leaves the range; the law is extrapolated there. Below the flow limit
``lubricant_minimum_temperature`` (its pour point or lower operating temperature; 0: none
published) no law holds: ``lubricant_below_flow_limit`` holds the viscosity at its value there
(the default) or extrapolates the law on, and the first time the temperature goes below it a
warning says which.

The breakaway after a soak at rest adds the lubricant's cold start: ``grease_starting_ratio``
(ks, from its published starting-torque test) times the lubricant's torque at
``grease_reference_speed`` (:mod:`servofmu.physics.friction.grease`). Without starting data
(ks = 0) the breakaway holds only the zero-speed limit of the viscous term, and the output
``breakaway_lower_bound`` says that it is a lower bound.
``preload`` is never negative, ``axial_play`` is the gap of an
unloaded pair, ``reverse_loaded`` says a bearing is loaded on the other flanks of its grooves
(:func:`servofmu.physics.pair.state.preload_force`, :func:`~servofmu.physics.pair.state.axial_play`,
:func:`~servofmu.physics.pair.state.state_flags`).

``prerolling_model`` = 1 turns on pre-rolling friction
(:mod:`servofmu.physics.friction.prerolling`): over the rings' relative angle θ, integrated
from ``speed`` (``prerolling_angle``), the friction torque T follows Dahl's model (Dahl 1976,
AIAA J. 14:1675, eq. 1)

.. math::

   \frac{dT}{d\theta} = \sigma_0\,\Bigl|1 - \frac{T}{T_c}\,\mathrm{sgn}\,\omega\Bigr|^{i}
   \,\mathrm{sgn}\Bigl(1 - \frac{T}{T_c}\,\mathrm{sgn}\,\omega\Bigr),

from T = 0 at initialization, with T_c the torque without pre-rolling at that speed and
temperature (its regularised sign taken away), σ₀ ``prerolling_stiffness`` and i
``prerolling_exponent``. Each step advances T in closed form with the speed and T_c held, exact
for every i; ``prerolling_torque`` is T at the end of the last step and ``friction_torque``
is T held within ±T_c of the current inputs, signed as without pre-rolling (it opposes the
motion that built it); ``power_loss`` = T·ω. With
``prerolling_stiffness`` = 0 the rest slope is derived from the contacts at each operating
point (Mindlin 1949; Johnson 1985 §7.2 and §4.2):

.. math::

   \sigma_0 = \sum_{\text{bearings}} \sum_{\text{balls}}
   \frac{k_{t,i}\,k_{t,o}}{k_{t,i} + k_{t,o}}\, r_i^2, \qquad k_t = 8\,G^*\sqrt{a\,b},
   \qquad r_i = \tfrac12\,(d_m - D_w\cos\alpha);

a pair without a loaded ball (σ₀ = 0) keeps the regularised sign. With
``prerolling_model`` = 0 (the default) none of this runs and every output is as before.

The range its physics holds for: the balls on the designed flanks of their grooves
(``contact_angle`` ≥ 0 for bearing A). A pair pulled far apart (a 473 K housing around a 173 K
shaft: ``contact_angle`` = −0.64 rad) puts them on the other flanks, where an angular-contact
bearing has its low shoulder and the model takes the grooves as symmetric. The angle is
reported as computed, not clamped; ``reverse_loaded`` is set and one warning naming the angle
is logged each time the balls go there: the torques there are not verified.
"""

from __future__ import annotations

from pathlib import Path

import servofmu

servofmu.share_copy(Path(__file__).parent)  # first of all: see its docstring

import functools  # noqa: E402
import math  # noqa: E402

from pythonfmu.enums import Fmi2Status  # noqa: E402

from servofmu.fmus.declarations import Var, output, real_input, real_parameter, spec_parameter  # noqa: E402
from servofmu.fmus.part_temperatures import (  # noqa: E402
    TEMPERATURE_INPUTS,
    part_inputs,
    temperature_inputs,
    temperature_mode_parameter,
    temperatures,
)
from servofmu.fmus.runtime import ServoSlave  # noqa: E402
from servofmu.parameters.bearing import PARAMETERS, pair_from_parameters, parameters_in  # noqa: E402
from servofmu.parameters.table import LATER_PARAMETERS  # noqa: E402
from servofmu.physics import compiled as continuation  # noqa: E402
from servofmu.physics.bearing import BearingModel  # noqa: E402
from servofmu.physics.friction import prerolling, registry  # noqa: E402
from servofmu.physics.pair import model as pair_model  # noqa: E402
from servofmu.physics.pair import stepping as pair_stepping  # noqa: E402
from servofmu.physics.pair.state import PointState  # noqa: E402

if __doc__:  # the friction models' items, from the registry (absent under python -OO)
    __doc__ = __doc__.replace(
        "FRICTION_MODEL_ITEMS",
        "\n".join(
            f"- ``{e.name}``{' (default)' if i == 0 else ''}: {e.description}"
            for i, e in enumerate(registry.entries())
        ),
    )

_TEMPS = TEMPERATURE_INPUTS
_ALL = (*_TEMPS, "speed", "axial_load", "radial_load")
_LOADS = (*_TEMPS, "axial_load", "radial_load")
_STATE = ("fit", "loop")  # parameter groups that fix the thermal and load state
_MODEL = ("friction_model", "skf", "density")  # the friction model and its numbers
_TORQUE = (*_STATE, "lubrication", "hysteresis", "sliding", "viscous", *_MODEL, "grease")
#: What BearingModel.speed_outputs returns, in its order: the outputs that move with speed.
_SPEED_FIELDS = (
    "friction_torque",
    "running_torque",
    "sliding_torque",
    "viscous_torque",
    "grease_torque",
    "power_loss",
)


def _out(name, description, unit, display=None, *, depends=_LOADS, groups=_STATE, **kw):
    """An output: ``depends`` its direct inputs, ``groups`` the parameter groups (see
    bearing_parameters.GROUPS) its value depends on; it copies the model's field ``name``
    unless ``field`` says otherwise."""
    return output(
        name,
        description,
        unit=unit,
        display_unit=display,
        type=kw.pop("kind", "Real"),
        depends=depends,
        initial_depends=(
            *depends,
            "temperature_mode",
            *parameters_in(*groups),
            *kw.pop("also", ()),  # parameters outside bearing_parameters.GROUPS
        ),
        field=kw.pop("field", name),
        **kw,
    )


def _outputs_of(fields, variables) -> tuple[str, ...]:
    """The names of the outputs that copy ``fields``, in that order."""
    return tuple(next(v.name for v in variables if v.field == f) for f in fields)


def _flag(name, description, groups=_STATE, depends=_LOADS):
    return _out(name, description, None, kind="Boolean", groups=groups, depends=depends)


_PREROLLING = ("prerolling_model", "prerolling_stiffness", "prerolling_exponent")
_PREROLLING_VARIABLES = (
    Var(
        name="prerolling_model",
        type="Integer",
        causality="parameter",
        description="Pre-rolling friction: 0 = none (the regularised sign of friction_torque), "
        "1 = Dahl (friction_torque follows Dahl's state over the rings' relative angle)",
        start=prerolling.NONE,
        min=0,
        max=len(prerolling.MODELS) - 1,
        source="assumed: off by default, so that earlier results stay",
    ),
    real_parameter(
        "prerolling_stiffness",
        "Dahl's rest slope sigma0 (0: derived from the contacts, Mindlin's no-slip stiffness "
        "8 G* sqrt(ab) of each ball's inner and outer contact in series times the inner contact "
        "radius squared, summed over the balls of both bearings)",
        start=0.0,
        unit="N.m/rad",
        min=prerolling.STIFFNESS_RANGE[0],
        max=prerolling.STIFFNESS_RANGE[1],
        source="0: derived (Mindlin 1949; Johnson 1985 §7.2); a value: measured (Dahl 1976)",
    ),
    real_parameter(
        "prerolling_exponent",
        "Dahl's exponent i (1: the exponential loop)",
        start=1.0,
        unit="1",
        min=prerolling.EXPONENT_RANGE[0],
        max=prerolling.EXPONENT_RANGE[1],
        source="assumed: i = 1, the exponential loop of Dahl 1976; not fitted",
    ),
    output(
        "prerolling_angle",
        "Relative angle of the rings integrated from speed over the steps (0 at "
        "initialization; 0 with prerolling_model = 0)",
        unit="rad",
        depends=(),
        initial_depends=(),
        field="prerolling_angle",
    ),
    output(
        "prerolling_torque",
        "Dahl's pre-rolling torque at the end of the last step (0 at initialization; 0 with "
        "prerolling_model = 0), signed like friction_torque, which is it held within the "
        "sliding torque of the current inputs",
        unit="N.m",
        display_unit="N.mm",
        depends=(),  # the state of the last step: no input moves it directly
        initial_depends=(),  # zero stress at initialization, whatever the parameters
        field="prerolling_torque",
    ),
)


class BearingFriction(ServoSlave):
    """Friction torque of a preloaded angular-contact ball-bearing pair versus temperature."""

    description = (
        "Friction torque of a preloaded pair of angular-contact ball bearings in a frame, with "
        "the thermal coupling of frame, shaft and bearings (Yu 2017; Ning); friction model "
        f"{registry.listed()}, and a grease term for the cold"
    )
    FEEDTHROUGH = True
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-3)
    PHYSICS = (
        "servofmu.physics.bearing",
        "servofmu.physics.friction.terms",
        "servofmu.physics.friction.models",
        *(e.module_name for e in registry.entries()),
        "servofmu.physics.friction.grease",
        "servofmu.physics.thermal.fits",
        "servofmu.physics.pair.preload",
        "servofmu.physics.contact.equilibrium",
        "servofmu.physics.contact.hertz",
        "servofmu.physics.lubrication.viscosity",
        "servofmu.physics.friction.prerolling",
    )
    VARIABLES = (
        real_input(
            "temperature",
            "Temperature of bearings, frame and shaft (temperature_mode uniform)",
            start=293.15,
            unit="K",
            display_unit="degC",
            min=173.15,
            max=473.15,
        ),
        *part_inputs(),
        real_input(
            "speed",
            "Speed of the shaft relative to the housing (signed)",
            start=0.0,
            unit="rad/s",
            display_unit="rpm",
            min=-1.0e4,
            max=1.0e4,
        ),
        real_input(
            "axial_load",
            "External axial load on the shaft, positive towards bearing A",
            start=0.0,
            unit="N",
            min=-1.0e5,
            max=1.0e5,
        ),
        real_input(
            "radial_load",
            "External radial load, shared by the two bearings",
            start=0.0,
            unit="N",
            min=-1.0e5,
            max=1.0e5,
        ),
        _out(
            "friction_torque",
            "Friction torque opposing rotation, signed like speed (subtract it when driving)",
            "N.m",
            "N.mm",
            depends=_ALL,
            groups=(*_TORQUE, "lubricant", "breakaway", "grease_start", "regularisation"),
            also=_PREROLLING,
        ),
        _out(
            "running_torque",
            "Running friction torque at |speed|",
            "N.m",
            "N.mm",
            depends=_ALL,
            groups=(*_TORQUE, "lubricant"),
        ),
        _out(
            "breakaway_torque",
            "Breakaway (starting) torque",
            "N.m",
            "N.mm",
            groups=(*_TORQUE, "lubricant", "breakaway", "grease_start"),
        ),
        _out(
            "hysteresis_torque",
            "Elastic hysteresis torque (Yu eq 1-3; 0 under a friction model without contact terms)",
            "N.m",
            "N.mm",
            groups=(*_STATE, "hysteresis", "friction_model"),
        ),
        _out(
            "spin_torque",
            "Ball spin torque (Yu eq 5-7; Ning inner-race spin; 0 under a friction model without "
            "contact terms)",
            "N.m",
            "N.mm",
            groups=(*_STATE, "lubrication", "sliding", "friction_model"),
        ),
        _out(
            "sliding_torque",
            "Sliding torque: differential (Heathcote) sliding (Ning), or the friction model's own "
            "(SKF's Msl)",
            "N.m",
            "N.mm",
            depends=_ALL,
            groups=(*_STATE, "lubrication", "lubricant", "sliding", "friction_model", "skf"),
        ),
        _out(
            "viscous_torque",
            "Rolling/viscous torque of the friction model (friction_model): Palmgren's (Yu eq 8) "
            "under the default",
            "N.m",
            "N.mm",
            depends=_ALL,
            groups=(*_STATE, "lubrication", "lubricant", "viscous", *_MODEL),
        ),
        _out(
            "grease_torque",
            "Running torque of the grease term (grease_f0; 0: off), part of running_torque",
            "N.m",
            "N.mm",
            depends=(*_TEMPS, "speed"),
            groups=("fit", "lubrication", "lubricant", "grease"),
        ),
        _out(
            "preload",
            "Preload: the mean axial force (F_A + F_B)/2 of the two bearings (tandem: half the "
            "thrust the set carries), 0 where it is not a compression",
            "N",
        ),
        _out(
            "contact_angle",
            "Operating contact angle of bearing A (negative: its balls on the other flanks of "
            "its grooves, reverse_loaded: outside the range the model holds for)",
            "rad",
            "deg",
        ),
        _out(
            "radial_clearance",
            "Operating radial (diametral) clearance",
            "m",
            "um",
            depends=_TEMPS,
            groups=("fit",),
        ),
        _out(
            "kinematic_viscosity",
            "Kinematic viscosity of the lubricant (0 for a dry film)",
            "m2/s",
            "cSt",
            depends=_TEMPS,
            groups=("lubrication", "lubricant"),
        ),
        _out("axial_stiffness", "Axial stiffness of the shaft in the pair", "N/m", "N/um"),
        _out(
            "power_loss",
            "Power dissipated by friction",
            "W",
            depends=_ALL,
            groups=(*_TORQUE, "lubricant", "breakaway", "grease_start", "regularisation"),
            also=_PREROLLING,
        ),
        _out("max_contact_pressure", "Largest Hertz contact pressure", "Pa", "MPa"),
        _out(
            "outer_fit_interference",
            "Diametral interference of outer ring and bore at temperature",
            "m",
            "um",
            depends=_TEMPS,
            groups=("fit",),
            field="outer_interference",
        ),
        _out(
            "inner_fit_interference",
            "Diametral interference of shaft and inner ring at temperature",
            "m",
            "um",
            depends=_TEMPS,
            groups=("fit",),
            field="inner_interference",
        ),
        _flag(
            "overloaded",
            "Contact pressure at or above pressure_limit (permanent deformation, ISO 76)",
            (*_STATE, "limit"),
        ),
        _flag(
            "locked", "No operating clearance left (balls pinched radially) or no load equilibrium"
        ),
        _flag("unloaded", "Preload lost: a bearing of the pair carries no axial load (axial play)"),
        temperature_mode_parameter(),
        *(spec_parameter(p) for p in PARAMETERS if p.name not in LATER_PARAMETERS),
        # pythonfmu numbers value references in declaration order: appended variables last
        _flag(
            "outside_lubricant_range",
            "The lubricant's temperature lies outside the range of its data (from its coldest "
            "viscosity point or lubricant_data_minimum_temperature to "
            "lubricant_maximum_temperature): the viscosity law is extrapolated, and below the "
            "flow limit lubricant_minimum_temperature held or extrapolated as "
            "lubricant_below_flow_limit says",
            ("lubrication", "lubricant"),
            _TEMPS,
        ),
        _out(
            "axial_play",
            "Axial play: the gap to first contact of the bearings that carry no axial load "
            "(0 while both do; at zero load 2h - C, how far the loop is short of closing)",
            "m",
            "um",
        ),
        _flag(
            "reverse_loaded",
            "A bearing's balls pushed onto the other flanks of its grooves (axial force < 0: "
            "the loop pulled apart, or a tandem set loaded against its thrust beyond it); "
            "the model takes the grooves as symmetric there, outside the range its physics "
            "holds for (an angular-contact bearing has its low shoulder there)",
        ),
        _flag(
            "breakaway_lower_bound",
            "breakaway_torque is only a lower bound: the lubricant has no published starting "
            "torque (grease_starting_ratio = 0), so the breakaway holds the zero-speed limit of "
            "the viscous term and not what a cold-soaked lubricant adds at rest",
            ("lubrication", "grease", "grease_start"),
            (),
        ),
        *(spec_parameter(p) for p in PARAMETERS if p.name in LATER_PARAMETERS),
        *_PREROLLING_VARIABLES,
    )
    _SPEED_OUTPUTS = _outputs_of(_SPEED_FIELDS, VARIABLES)  # those that move with speed alone
    _set_speed = staticmethod(ServoSlave.output_setter(_SPEED_OUTPUTS))

    def _announce(self):
        # with the export: which per-step path runs here, the compiled kernels shipped for
        # this platform, or the same equations in Python where none matches (and why)
        if not self._announced:
            super()._announce()
            self.log(f"{self.instance_name}: per-step kernels {continuation.describe()}")

    def configure(self):
        values = {p.name: getattr(self, p.name) for p in PARAMETERS}
        for p in PARAMETERS:
            if p.choices:
                values[p.name] = p.key(values[p.name])  # the item's key
        self._point = None  # (temperatures, axial_load, radial_load) of the last evaluate
        self.model = BearingModel(pair_from_parameters(values))
        self.breakaway_lower_bound = self.model.pair.breakaway_lower_bound
        self._below_flow_told = False  # the warning below the flow limit: once
        # the outputs that do not move with speed: copied from the model's PointState
        self._copy_state = self.output_copier(PointState.__dataclass_fields__)
        if self._shared is not None:  # the same outputs, for the compiled step
            by_field = {v.field: v.name for v in self._outputs}
            slots = self._shared.slots
            self._state_slots = tuple(
                slots[by_field[f]] if f in by_field else -1 for f in pair_stepping.STATE_FIELDS
            )
            self._state_flags = tuple(by_field[f] for f in pair_stepping.FLAG_FIELDS)
        # pre-rolling (physics/friction/prerolling.py): Dahl's state (rings' angle [rad],
        # torque [N·m]) from zero stress; with prerolling_model = 0 nothing of it runs (_carry None)
        self._pr_angle = self._pr_torque = 0.0
        self._sigma0 = self.prerolling_stiffness  # 0: derived at each operating point
        self._excess = 0.0  # the breakaway excess of the operating point [N·m]
        self._stribeck = self.model.pair.stribeck_speed  # ω_s [rad/s] of T_c
        # Dahl's step and T_c: the friction kernels of the model's implementation
        kernels = continuation.module("kernels.friction", self.model.implementation)
        self._stribeck_torque, self._dahl_torque_step = (
            kernels.stribeck_torque,
            kernels.dahl_torque_step,
        )
        self._carry = self._advance_prerolling if self.prerolling_model == prerolling.DAHL else None

    def hidden_state(self):
        # the continuation of the thermal and load state (physics/pair/continuation.py): a
        # restored instance continues bit for bit
        return {
            "continuation": self.model.state() if self._configured else None,
            "prerolling": [self._pr_angle, self._pr_torque] if self._configured else [0.0, 0.0],
        }

    def restore_hidden_state(self, state):
        # the restored outputs need not belong to the model's last operating point: the next
        # compute evaluates every output (found by the state fuzzing of tests/robustness)
        self._point = None
        angle, torque = _prerolling_state(state.get("prerolling"), self.prerolling_model)
        if self._configured:
            self.model.restore(state.get("continuation"))
            self._pr_angle, self._pr_torque = angle, torque

    def compute(self):
        temps = temperatures(self)
        point = (temps, self.axial_load, self.radial_load)
        if point != self._point:  # else only the speed changed: the speed terms alone
            was_outside, was_reversed = self.outside_lubricant_range, self.reverse_loaded
            state = self.model.update(temps, self.axial_load, self.radial_load)
            self._copy_state(self, state)
            self._point = point
            if self._carry is not None:
                self._prerolling_point(state, temps)
            if self.outside_lubricant_range and not was_outside:
                self._warn_lubricant_range(temps)
            elif self.outside_lubricant_range and not self._below_flow_told:
                self._check_flow_limit(temps)
            if self.reverse_loaded and not was_reversed:
                self._warn_reverse_loaded()
        self._set_speed(self, self.model.speed_outputs(self.speed))
        if self._carry is not None:
            self._hold_prerolling()

    # ------------------------------------------------------------------ compiled step
    shared_step = staticmethod(pair_model.shared_step)

    def _bind_shared_step(self, step):
        coulomb = getattr(self, "_coulomb", None)  # T_c of the last computed outputs
        if self._carry is not None and coulomb is None:
            return False
        slots = self._shared.slots
        step.bind(
            self.model,
            tuple(slots[name] for name in temperature_inputs(self.temperature_mode)),
            (slots["axial_load"], slots["radial_load"], slots["speed"]),
            self._state_slots,
            tuple(slots[name] for name in self._SPEED_OUTPUTS),
            pair_stepping.flag_bits(tuple(getattr(self, n) for n in self._state_flags)),
            self._point,
            self._below_flow_told,
            self.model.pair.lubricant.below_flow,
        )
        if self._carry is not None:
            step.bind_prerolling(
                (slots["prerolling_angle"], slots["prerolling_torque"]),
                functools.partial(prerolling.contact_rest_stiffness, self.model.pair),
                self.prerolling_stiffness,
                self._sigma0,
                self._excess,
                self._stribeck,
                self.prerolling_exponent,
                self._pr_angle,
                self._pr_torque,
                coulomb,
            )
        return True

    def _read_shared_step(self, step):
        self._point = step.point
        if self._carry is not None:
            self._pr_angle, self._pr_torque = step.prerolling_angle, step.prerolling_torque
            self._sigma0, self._excess, self._coulomb = step.sigma0, step.excess, step.coulomb

    # ------------------------------------------------------------------ pre-rolling
    def _prerolling_point(self, state, temps):
        """At a new operating point: its breakaway excess and, derived, its rest stiffness."""
        self._excess = state.breakaway_excess
        if self.prerolling_stiffness == 0.0:
            t4 = (temps,) * 4 if type(temps) is float else temps
            self._sigma0 = prerolling.contact_rest_stiffness(
                self.model.pair, t4, self.axial_load, self.radial_load
            )

    def _hold_prerolling(self):
        """Dahl's state as it is, within T_c of the current inputs: prerolling_angle,
        prerolling_torque and, from them, friction_torque and power_loss (a rest stiffness of
        0, no ball loaded: the regularised sign)."""
        speed = self.speed
        tc = self._stribeck_torque(self.running_torque, self._excess, speed, self._stribeck)
        self._coulomb = tc
        self.prerolling_angle = self._pr_angle
        self.prerolling_torque = t = self._pr_torque
        if self._sigma0 > 0.0:
            t = tc if t > tc else (-tc if t < -tc else t)
            self.friction_torque = t
            self.power_loss = t * speed

    def _advance_prerolling(self, step_size: float) -> bool:
        """Dahl's state over a step, speed and T_c held (exact for every exponent: the closed
        form of :func:`~servofmu.physics.kernels.friction.dahl_torque_step`), and its outputs;
        T_c is this step's, computed from its inputs before the step."""
        speed = self.speed
        dtheta = speed * step_size
        self.prerolling_angle = self._pr_angle = self._pr_angle + dtheta
        if self._sigma0 > 0.0:  # |T| <= T_c after the step
            t = self._dahl_torque_step(
                self._pr_torque, self._coulomb, self._sigma0, self.prerolling_exponent, dtheta
            )
            self.prerolling_torque = self.friction_torque = self._pr_torque = t
            self.power_loss = t * speed
        else:  # no ball loaded: no stress held
            self.prerolling_torque = self._pr_torque = 0.0
        return True

    def _warn_reverse_loaded(self):
        """One warning each time a bearing's balls go onto the other flanks of its grooves."""
        a = self.contact_angle
        self.log(
            f"{self.instance_name}: a bearing's balls bear on the other flanks of its grooves "
            f"(contact_angle of bearing A = {a:.6g} rad, {math.degrees(a):.4g}°), where an "
            "angular-contact bearing has its low shoulder; the model takes the grooves as "
            "symmetric there, outside the range its physics holds for, so its torques are not "
            "verified; reverse_loaded is set until the balls return",
            status=Fmi2Status.warning,
        )

    def _check_flow_limit(self, temps):
        """Outside the data already: the warning below the flow limit when it is crossed."""
        t = temps if type(temps) is float else 0.5 * (temps[2] + temps[3])
        if self.model.pair.lubricant.below_flow(t):
            self._warn_below_flow_limit(t)

    def _warn_below_flow_limit(self, t):
        """One warning, the first time the lubricant's temperature goes below its flow limit:
        no law holds there, and what the model does instead (the user's choice)."""
        visc = self.model.pair.lubricant
        self._below_flow_told = True
        then = (
            f"the viscosity is held at its value there ({visc.hold_temperature:.2f} K)"
            if visc.hold_temperature
            else "the viscosity law is extrapolated on"
        )
        self.log(
            f"{self.instance_name}: the lubricant's temperature {t:.2f} K ({t - 273.15:.1f} °C) "
            f"is below its flow limit, lubricant_minimum_temperature = {visc.flow_limit:.2f} K "
            f"({visc.flow_limit - 273.15:.1f} °C), where no viscosity law holds; "
            f"lubricant_below_flow_limit = {self.item('lubricant_below_flow_limit')}: {then}; "
            "outside_lubricant_range stays set (said once)",
            status=Fmi2Status.warning,
        )

    def _warn_lubricant_range(self, temps):
        """One warning each time the lubricant's temperature leaves the range of its data."""
        t = temps if type(temps) is float else 0.5 * (temps[2] + temps[3])  # the rings' mean
        visc = self.model.pair.lubricant
        below = t < visc.lower_limit
        limit = visc.lower_limit if below else visc.upper_limit
        if not below:
            name = "lubricant_maximum_temperature"
        elif visc.lower_limit == self.lubricant_data_minimum_temperature:
            name = "lubricant_data_minimum_temperature"
        else:
            name = "the coldest viscosity point"
        if below and visc.flow_limit > 0.0:
            then = (
                "the viscosity law is extrapolated down to the flow limit "
                f"lubricant_minimum_temperature = {visc.flow_limit:.2f} K"
            )
        elif below:
            then = "no flow limit is published, so the viscosity law is extrapolated"
        else:
            then = "the viscosity law is extrapolated"
        self.log(
            f"{self.instance_name}: the lubricant's temperature {t:.2f} K ({t - 273.15:.1f} °C) "
            f"is {'below' if below else 'above'} the {'lower' if below else 'upper'} end of its "
            f"data, {name} = {limit:.2f} K ({limit - 273.15:.1f} °C); {then}, and "
            "outside_lubricant_range is set until it returns",
            status=Fmi2Status.warning,
        )
        if below and not self._below_flow_told and visc.below_flow(t):
            self._warn_below_flow_limit(t)


def _prerolling_state(state, model: int) -> tuple[float, float]:
    """The (angle [rad], torque [N·m]) of a restored hidden state, checked: two finite
    numbers, both 0 with prerolling_model = 0 (nothing else is ever saved); ValueError
    naming what is wrong. A torque beyond T_c is taken to ±T_c when used, as a step does."""
    if not (isinstance(state, list) and len(state) == 2):
        raise ValueError(f"prerolling = {state!r} is not [angle, torque]")
    angle, torque = state
    for name, x in (("prerolling angle", angle), ("prerolling torque", torque)):
        if type(x) is not float or not math.isfinite(x):
            raise ValueError(f"{name} = {x!r} is not a finite number")
    if model != prerolling.DAHL and (angle, torque) != (0.0, 0.0):
        raise ValueError(
            f"prerolling = {state!r} with prerolling_model = {model!r}: without pre-rolling "
            "the state is [0.0, 0.0]"
        )
    return angle, torque


# every output is in the model's PointState, moves with speed (compute copies those) or is a
# property of the configuration (configure sets it)
_UNCOPIED = {v.field for v in BearingFriction.VARIABLES if v.causality == "output"} - {
    *PointState.__dataclass_fields__,
    *_SPEED_FIELDS,
    "breakaway_lower_bound",
    "prerolling_angle",  # with prerolling_model = 1 from Dahl's state (_hold_prerolling)
    "prerolling_torque",
}
if _UNCOPIED:
    raise TypeError(f"BearingFriction outputs without a source in compute(): {sorted(_UNCOPIED)}")

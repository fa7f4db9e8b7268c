"""The per-step evaluation of a bearing pair, :class:`BearingModel`: the path of the
BearingFriction FMU. Continuation first (:mod:`.continuation`, compiled when the build could
compile it: :mod:`servofmu.physics.compiled`), a cold start on the same floats when the warm
start fails, and the exact path (:mod:`.state`) when that fails too.
"""

from __future__ import annotations

from .. import compiled
from .._checks import TEMPERATURE_RANGE as _TEMPERATURE_RANGE
from .._checks import check_operating_temperature
from ..thermal.temperatures import PARTS, PartTemperatures
from .configuration import BearingPair
from .state import (
    BearingOutputs,
    LoadState,
    PointState,
    ThermalState,
    exact_point,
    load_state,
    operating_outputs,
    point_outputs,
    thermal_state_at,
    to_floats,
)

#: Valid range of a part temperature [K]: the FMUs' (:data:`._checks.TEMPERATURE_RANGE`).
TEMPERATURE_RANGE = _TEMPERATURE_RANGE
_LO, _HI = TEMPERATURE_RANGE


def _temperatures(temperature) -> tuple[float, float, float, float]:
    """(housing, shaft, outer ring, inner ring) [K] as floats from a uniform temperature, a
    :class:`PartTemperatures` or a 4-tuple; ValueError naming one outside
    :data:`TEMPERATURE_RANGE` (with a hint when it looks like °C)."""
    if type(temperature) is float and _LO <= temperature <= _HI:  # the per-step cases
        return (temperature, temperature, temperature, temperature)
    if type(temperature) is tuple and len(temperature) == 4:
        h, s, o, i = temperature
        if type(h) is type(s) is type(o) is type(i) is float and (
            _LO <= h <= _HI and _LO <= s <= _HI and _LO <= o <= _HI and _LO <= i <= _HI
        ):
            return temperature
    if isinstance(temperature, PartTemperatures):
        temps = tuple(float(getattr(temperature, p)) for p in PARTS)
    elif isinstance(temperature, tuple):
        temps = tuple(float(t) for t in temperature)
    else:
        t = float(temperature)
        temps = (t, t, t, t)
    for name, t in zip(PARTS, temps, strict=True):
        if not (_LO <= t <= _HI):
            label = "temperature" if temps.count(t) == 4 else f"{name}_temperature"
            check_operating_temperature(label, t)
    return temps


class BearingModel:
    """Per-step evaluation of a :class:`BearingPair` at (temperatures, speed, axial load,
    radial load), as floats: the path of the BearingFriction FMU.

    The thermal and load state is solved by continuation from the previous call
    (:class:`~.pair.continuation.PairSolver`, compiled when the build could compile it:
    :mod:`.compiled`); the first call, and any call whose warm start fails, is solved from
    scratch on the same floats (:meth:`~.pair.continuation.PairSolver.start`), and the exact path
    (:func:`thermal_state`, :func:`load_state`) solves a call that fails too and seeds the
    continuation again. Every arrangement alike (:class:`~.pair.continuation.PairRows`). A call
    whose temperatures and loads equal the previous call's reuses its state
    (:class:`~.pair.continuation.PointState`): a change of speed alone costs only the speed
    terms; a call whose temperatures equal the previous call's reuses the thermal state.

    Parameters
    ----------
    pair : BearingPair
    implementation : "compiled", "python" or None (the one :mod:`.compiled` chose)

    Attributes
    ----------
    steps : calls that solved a new state
    cold_starts : of those, the ones the continuation solved from scratch (the first call,
        or a failed warm start)
    exact_steps : of those, the ones solved by the exact path (a failed cold start)
    """

    def __init__(self, pair: BearingPair, implementation: str | None = None):
        self.pair = pair
        self.kernels = compiled.module("pair.continuation", implementation)
        self.solver = self.kernels.PairSolver(pair)
        self.exact_steps = 0

    @property
    def implementation(self) -> str:
        """ "compiled" or "python"."""
        return "compiled" if compiled.is_compiled(self.kernels) else "python"

    @property
    def steps(self) -> int:
        return self.solver.steps

    @property
    def cold_starts(self) -> int:
        return self.solver.cold_starts

    # ---------------------------------------------------------------- state
    def state(self) -> dict:
        """The per-step state (JSON-serialisable): the continuation, the operating point and
        the state there. With :meth:`restore`, a model continues bit for bit."""
        return self.solver.state()

    def restore(self, state: dict | None) -> None:
        """Continue from a :meth:`state`: the state at its operating point as it was, and the
        continuation from there, so that the next steps repeat bit for bit."""
        self.solver.restore(state)

    # ---------------------------------------------------------------- per step
    def _exact(self, temps, axial_load: float, radial_load: float):
        """The exact path's state, seeding the continuation at the solver's thermal state."""
        try:
            th_exact = to_floats(thermal_state_at(self.pair, *temps))
            ls = to_floats(load_state(self.pair, th_exact, axial_load, radial_load))
        except (ValueError, ArithmeticError) as exc:
            raise ValueError(
                f"no state at temperatures (housing, shaft, outer ring, inner ring) = "
                f"{temps} K, axial_load = {axial_load!r} N, radial_load = "
                f"{radial_load!r} N: {exc}"
            ) from exc
        th = self.solver.thermal
        p = 0.5 * (ls.offset_a + ls.offset_b)
        z = 0.5 * (ls.offset_a - ls.offset_b)
        inputs = (*temps, axial_load, radial_load)
        if radial_load == 0.0:
            self.solver.seed(th, inputs, (p, z))
        else:
            self.solver.seed(th, inputs, (p, z, ls.radial_a, ls.radial_b), ls.ball_cosines)
        point = exact_point(PointState, self.pair, th_exact, ls)
        self.solver.accept(th, point, axial_load, radial_load)
        return point

    def update(self, temperature, axial_load: float = 0.0, radial_load: float = 0.0):
        """The state at (temperature, axial_load, radial_load) (arguments as :meth:`evaluate`):
        solved when it is a new operating point, else the last one.

        Returns
        -------
        PointState
            Every output of :meth:`evaluate` that does not move with speed (torques [N·m],
            forces [N], angle [rad], lengths [m], stiffness [N/m], pressures [Pa], flags).
        """
        if type(temperature) is float and _LO <= temperature <= _HI:  # the per-step case
            t_h = t_s = t_o = t_i = temperature
        else:
            t_h, t_s, t_o, t_i = _temperatures(temperature)
        fa, fr = float(axial_load), float(radial_load)
        point = self.solver.update(t_h, t_s, t_o, t_i, fa, fr)
        return self.solve_exactly(t_h, t_s, t_o, t_i, fa, fr) if point is None else point

    def solve_exactly(self, t_h: float, t_s: float, t_o: float, t_i: float, fa: float, fr: float):
        """The state at the parts' temperatures [K] and loads [N] on the exact path, the
        continuation seeded there (:meth:`update`, when the continuation fails; counted in
        ``exact_steps``).

        Returns
        -------
        PointState
        """
        self.exact_steps += 1
        return self._exact((t_h, t_s, t_o, t_i), fa, fr)

    def evaluate(
        self, temperature, speed: float, axial_load: float = 0.0, radial_load: float = 0.0
    ) -> BearingOutputs:
        """All outputs at one operating point, as floats.

        Parameters
        ----------
        temperature : uniform temperature [K], or the parts' temperatures
            (:class:`PartTemperatures` or a (housing, shaft, outer ring, inner ring) tuple)
        speed : shaft speed relative to the housing [rad/s], signed
        axial_load : external axial load [N], positive towards bearing A
        radial_load : external radial load [N], shared by the two bearings

        Returns
        -------
        BearingOutputs
            Torques [N·m], preload [N], angles [rad], lengths [m], viscosity [m²/s],
            stiffness [N/m], power [W], pressures [Pa], flags.

        >>> model = BearingModel(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
        >>> out = model.evaluate(293.15, 0.17, axial_load=5.0)
        >>> round(out.running_torque * 1e3, 3)  # N·mm (the compliant yoke at 20 °C)
        0.301
        """
        point = self.update(temperature, axial_load, radial_load)
        speed_outputs = self.solver.speed_outputs(float(speed))
        return point_outputs(point, speed_outputs, self.pair.breakaway_lower_bound)

    def speed_outputs(self, speed: float) -> tuple[float, float, float, float, float, float]:
        """(friction_torque, running_torque, sliding_torque, viscous_torque, grease_torque
        [N·m], power_loss [W]) at ``speed`` [rad/s] for the state of the last :meth:`evaluate`
        call: the per-step path when only the speed changed (the same equations, so the same
        numbers as evaluate)."""
        return self.solver.speed_outputs(speed)

    # ---------------------------------------------------------------- exact
    def thermal(self, temperature) -> ThermalState:
        """Exact :func:`thermal_state` at one temperature [K] (fields as floats)."""
        return to_floats(thermal_state_at(self.pair, *_temperatures(temperature)))

    def load(self, temperature, axial_load: float = 0.0, radial_load: float = 0.0) -> LoadState:
        """Exact :func:`load_state` at one temperature [K] and loads [N] (fields as floats)."""
        return to_floats(load_state(self.pair, self.thermal(temperature), axial_load, radial_load))

    def curves(self, temperatures, speed: float, axial_load: float = 0.0) -> BearingOutputs:
        """Outputs over an array of temperatures [K] at one speed [rad/s] and axial load [N],
        vectorised and exact (zero radial load)."""
        return operating_outputs(self.pair, temperatures, speed, axial_load)


def shared_step(*args, implementation: str | None = None):
    """The BearingFriction FMU's step on the values it shares with servofmu's export
    (:class:`.stepping.PairSharedStep`; ``args``: those of
    :class:`~servofmu.physics.shared_step.SharedStep`), of ``implementation`` ("compiled",
    "python"; None: the one :mod:`.compiled` chose, as :class:`BearingModel`'s).

    Returns
    -------
    PairSharedStep

    Examples
    --------
    >>> step = shared_step(bytearray(32), 0, 0, 2, False, None, None)  # a block of no values
    >>> type(step).__name__, step.armed
    ('PairSharedStep', False)
    """
    return compiled.module("pair.stepping", implementation).PairSharedStep(*args)

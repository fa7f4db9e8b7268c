"""The bearing-pair friction model: thermal coupling (fits, preload) + equilibrium + friction.

Where each part lives (Yu 2017 §1–3; Ning §1–2):

- :mod:`.pair` — the configuration: :class:`BearingPair` (bearing, mounting, lubrication,
  coefficients) and :func:`with_mounting`;
- :mod:`.pair_state` — the exact state, vectorised over operating points:
  :func:`thermal_state` (Yu eq 10–18), :func:`load_state` (Jones; eq 1–7, Ning),
  :func:`bearing_outputs` (eq 8–9, breakaway, regularised sign) and
  :func:`operating_outputs` (all three);
- :mod:`.continuation` — the same equations solved per step from the previous step's
  solution, on floats;
- here, :class:`BearingModel`: the per-step evaluation an FMU calls, continuation first and
  the exact path when the warm start fails.

The names of :mod:`.pair` and :mod:`.pair_state` are re-exported here, so that
``from servofmu.physics.bearing import BearingPair, thermal_state`` keeps working.
"""

from __future__ import annotations

import math

from .continuation import (
    AxialSolution,
    PairSolver,
    axial_state_of,
    radial_state_of,
    thermal_floats,
)
from .mounting import Mounting
from .pair import (
    DEFAULT_COEFFICIENTS,
    LUBRICATIONS,
    MOUNTING_CHANGES,
    PRESSURE_LIMIT,
    BearingPair,
    assembly_geometry,
    effective_shim,
    loop_closure,
    loop_stiffness,
    with_mounting,
)
from .pair_state import (
    BearingOutputs,
    LoadState,
    ThermalState,
    _speed_terms,
    axial_load_state,
    bearing_outputs,
    load_state,
    operating_outputs,
    state_flags,
    thermal_state,
    to_floats,
)
from .temperatures import PARTS, PartTemperatures

__all__ = [
    "DEFAULT_COEFFICIENTS",
    "LUBRICATIONS",
    "MOUNTING_CHANGES",
    "PRESSURE_LIMIT",
    "BearingModel",
    "BearingOutputs",
    "BearingPair",
    "LoadState",
    "Mounting",
    "PartTemperatures",
    "ThermalState",
    "assembly_geometry",
    "axial_load_state",
    "bearing_outputs",
    "effective_shim",
    "load_state",
    "loop_closure",
    "loop_stiffness",
    "operating_outputs",
    "state_flags",
    "thermal_state",
    "to_floats",
    "with_mounting",
]

#: Valid range of a part temperature [K] on the per-step path.
TEMPERATURE_RANGE = (0.0, math.inf)


def _temperatures(temperature) -> tuple[float, float, float, float]:
    """(housing, shaft, outer ring, inner ring) [K] as floats from a uniform temperature, a
    :class:`PartTemperatures` or a 4-tuple; ValueError naming a non-finite or non-positive
    one."""
    if isinstance(temperature, PartTemperatures):
        temps = tuple(float(getattr(temperature, p)) for p in PARTS)
    elif isinstance(temperature, tuple):
        temps = tuple(float(t) for t in temperature)
    else:
        t = float(temperature)
        temps = (t, t, t, t)
    for name, t in zip(PARTS, temps, strict=True):
        if not (0.0 < t < math.inf):
            label = "temperature" if temps.count(t) == 4 else f"{name}_temperature"
            raise ValueError(f"{label} = {t!r} K is outside the valid range (0, inf) K")
    return temps


class BearingModel:
    """Per-step evaluation of a :class:`BearingPair` at (temperatures, speed, axial load,
    radial load), as floats: the path of the BearingFriction FMU.

    The thermal and load state is solved by continuation from the previous call
    (:class:`continuation.PairSolver`); the exact path (:func:`thermal_state`,
    :func:`load_state`) solves the first call, and any call whose warm start fails, and seeds
    the continuation again. A call whose temperatures and loads equal the previous call's
    reuses its state: a change of speed alone costs only the speed terms.

    Attributes
    ----------
    steps : calls that solved a new state
    exact_steps : of those, the ones solved by the exact path
    """

    def __init__(self, pair: BearingPair):
        self.pair = pair
        self.solver = PairSolver(pair)
        self._key = None  # (temperatures, axial load, radial load) of the current state
        self._th = None
        self._state: LoadState | None = None
        self._exact_last = False  # the current state came from the exact path
        self.steps = 0
        self.exact_steps = 0

    # ---------------------------------------------------------------- state
    def state(self) -> dict:
        """The per-step state (JSON-serialisable): the continuation and the operating point
        of the current outputs. With :meth:`restore`, a model continues bit for bit."""
        key = None if self._key is None else [*self._key[0], self._key[1], self._key[2]]
        return {"solver": self.solver.state(), "point": key, "exact": self._exact_last}

    def restore(self, state: dict | None) -> None:
        """Continue from a :meth:`state`: the outputs at its operating point are evaluated
        again the way they were first solved (exactly, or at the continuation's solution with
        its anchors), without a new solve, so that the next steps repeat bit for bit."""
        state = state or {"solver": None, "point": None, "exact": False}
        self.solver.restore(state["solver"])
        self._key, self._exact_last = None, bool(state["exact"])
        point = state["point"]
        if point is None:
            return
        temps, axial, radial = tuple(float(t) for t in point[:4]), float(point[4]), float(point[5])
        if self._exact_last:
            self._th, self._state = self._exact(temps, axial, radial, seed=False)
        else:
            th = thermal_floats(self.solver.c, temps)
            self._th, self._state = th, self._state_of(th, self.solver.evaluate(th, axial, radial))
        self._key = (temps, axial, radial)

    # ---------------------------------------------------------------- per step
    def _exact(self, temps, axial_load: float, radial_load: float, seed: bool = True):
        th_exact = thermal_state(self.pair, PartTemperatures(*temps))
        ls = to_floats(load_state(self.pair, th_exact, axial_load, radial_load))
        if seed:
            th = thermal_floats(self.solver.c, temps)
            p = 0.5 * (ls.offset_a + ls.offset_b)
            z = 0.5 * (ls.offset_a - ls.offset_b)
            inputs = (*temps, axial_load, radial_load)
            if radial_load == 0.0:
                self.solver.seed(th, inputs, (p, z))
            else:
                x = (p, z, ls.radial_a, ls.radial_b)
                self.solver.seed(th, inputs, x, ls.ball_cosines)
        return to_floats(th_exact), ls

    def _state_of(self, th, sol) -> LoadState:
        if isinstance(sol, AxialSolution):
            return axial_state_of(self.pair, self.solver.c, th, sol)
        return radial_state_of(self.pair, self.solver, th, sol)

    def _solve(self, temps, axial_load: float, radial_load: float):
        th = thermal_floats(self.solver.c, temps)
        sol = self.solver.solve(th, axial_load, radial_load)
        self._exact_last = sol is None
        if sol is None:
            self.exact_steps += 1
            try:
                return self._exact(temps, axial_load, radial_load)
            except (ValueError, ArithmeticError) as exc:
                raise ValueError(
                    f"no state at temperatures (housing, shaft, outer ring, inner ring) = "
                    f"{temps} K, axial_load = {axial_load!r} N, radial_load = "
                    f"{radial_load!r} N: {exc}"
                ) from exc
        return th, self._state_of(th, sol)

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
        >>> round(out.running_torque * 1e3, 3)  # N·mm
        1.614
        """
        temps = _temperatures(temperature)
        key = (temps, float(axial_load), float(radial_load))
        if key != self._key:
            for name, v in (("axial_load", axial_load), ("radial_load", radial_load)):
                if not math.isfinite(v):
                    raise ValueError(f"{name} = {v!r} N is outside the valid range (-inf, inf)")
            self._th, self._state = self._solve(*key)
            self._key = key
            self.steps += 1
        if not math.isfinite(speed):
            raise ValueError(f"speed = {speed!r} rad/s is outside the valid range (-inf, inf)")
        return bearing_outputs(self.pair, self._th, self._state, float(speed))

    def speed_outputs(self, speed: float) -> tuple[float, float, float, float]:
        """(friction_torque [N·m], running_torque [N·m], viscous_torque [N·m], power_loss [W])
        at ``speed`` [rad/s] for the state of the last :meth:`evaluate` call: the per-step path
        when only the speed changed (the same equations, so the same numbers as evaluate)."""
        if not math.isfinite(speed):
            raise ValueError(f"speed = {speed!r} rad/s is outside the valid range (-inf, inf)")
        w = float(speed)
        signed, running, viscous, _, _ = _speed_terms(self.pair, self._th, self._state, w)
        return signed, running, viscous, signed * w

    # ---------------------------------------------------------------- exact
    def thermal(self, temperature) -> ThermalState:
        """Exact :func:`thermal_state` at one temperature [K] (fields as floats)."""
        return to_floats(thermal_state(self.pair, PartTemperatures(*_temperatures(temperature))))

    def load(self, temperature, axial_load: float = 0.0, radial_load: float = 0.0) -> LoadState:
        """Exact :func:`load_state` at one temperature [K] and loads [N] (fields as floats)."""
        return to_floats(load_state(self.pair, self.thermal(temperature), axial_load, radial_load))

    def curves(self, temperatures, speed: float, axial_load: float = 0.0) -> BearingOutputs:
        """Outputs over an array of temperatures [K] at one speed [rad/s] and axial load [N],
        vectorised and exact (zero radial load)."""
        return operating_outputs(self.pair, temperatures, speed, axial_load)

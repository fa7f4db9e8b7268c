r"""Discrete PID controller with output limit and anti-windup (the ServoController FMU's law).

Parallel form sampled every :math:`T_s`, derivative on the measurement (no kick on reference
steps) with a first-order filter (backward Euler), conditional integration (clamping) as
anti-windup (Åström & Hägglund, *Advanced PID Control*, 2006, ch. 3):

.. math::

   e_k = r_k - y_k

   D_k = \frac{T_f\,D_{k-1} - K_d\,(y_k - y_{k-1})}{T_f + T_s}

   v_k = K_p\,e_k + I_k + D_k, \qquad u_k = \operatorname{clip}(v_k, u_\mathrm{min}, u_\mathrm{max})

   I_{k+1} = I_k + K_i\,T_s\,e_k

the last unless :math:`u_k` is saturated and :math:`e_k` drives it further. The same law
serves a position loop (r, y in rad) and a speed loop (r, y in rad/s).
"""

from __future__ import annotations

from dataclasses import dataclass

from .. import compiled
from .._checks import check_choice, check_finite, check_nonnegative, check_positive

MODES = ("position", "speed")


@dataclass(frozen=True)
class PIDParameters:
    """Gains and limits (SI: command in V; reference in rad or rad/s by ``mode``)."""

    mode: str = "speed"
    kp: float = 1.0
    ki: float = 10.0
    kd: float = 0.0
    derivative_filter: float = 1.0e-3  # T_f [s]
    output_min: float = -24.0  # V
    output_max: float = 24.0  # V
    sample_period: float = 1.0e-3  # T_s [s]

    def __post_init__(self):
        check_choice("mode", self.mode, MODES)
        for name in ("kp", "ki", "kd"):
            check_nonnegative(name, getattr(self, name))
        check_positive("derivative_filter", self.derivative_filter, "s")
        check_positive("sample_period", self.sample_period, "s")
        check_finite("output_min", self.output_min, "V")
        check_finite("output_max", self.output_max, "V")
        if not self.output_min < self.output_max:
            raise ValueError(
                f"output_min = {self.output_min!r} V must be below output_max = "
                f"{self.output_max!r} V"
            )


@dataclass(frozen=True)
class PIDState:
    """Hidden state between samples: integral I, filtered derivative D, last measurement."""

    integral: float = 0.0
    derivative: float = 0.0
    last_measurement: float | None = None


def pid_sample(p: PIDParameters, s: PIDState, reference: float, measurement: float):
    """One sample of the controller: returns (command u_k [V], new state).

    Parameters
    ----------
    p : PIDParameters
        Gains, limits [V] and sample period [s].
    s : PIDState
        The state after the last sample.
    reference, measurement : float
        Setpoint and measured value [rad or rad/s by ``p.mode``].

    Returns
    -------
    tuple
        (command u_k [V], the new :class:`PIDState`).

    Examples
    --------
    >>> u, s = pid_sample(PIDParameters(kp=2.0, ki=0.0), PIDState(), 1.0, 0.25)
    >>> u  # V: kp·e = 2·0.75
    1.5
    """
    e = reference - measurement
    y_prev = measurement if s.last_measurement is None else s.last_measurement
    ts, tf = p.sample_period, p.derivative_filter
    d = (tf * s.derivative - p.kd * (measurement - y_prev)) / (tf + ts)
    v = p.kp * e + s.integral + d
    u = min(max(v, p.output_min), p.output_max)
    winding_up = (v > p.output_max and e > 0) or (v < p.output_min and e < 0)
    integral = s.integral if winding_up else s.integral + p.ki * ts * e
    return u, PIDState(integral, d, measurement)


def shared_step(*args, implementation: str | None = None):
    """The ServoController FMU's step on the values it shares with servofmu's export
    (:class:`.control_stepping.ControllerSharedStep`; ``args``: those of
    :class:`~servofmu.physics.shared_step.SharedStep`), of ``implementation`` ("compiled",
    "python"; None: the one :mod:`servofmu.physics.compiled` chose).

    Returns
    -------
    ControllerSharedStep

    Examples
    --------
    >>> step = shared_step(bytearray(32), 0, 0, 2, True, None, None)  # a block of no values
    >>> type(step).__name__, step.armed
    ('ControllerSharedStep', False)
    """
    return compiled.module("drives.control_stepping", implementation).ControllerSharedStep(*args)

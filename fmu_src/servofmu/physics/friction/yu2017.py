"""Yu's friction model of a bearing pair (Yu, Li, Shang, Cao 2017, eq 1–9; the paper:
:mod:`servofmu.papers.yu2017`), the default: per contact the elastic hysteresis, the spin
and, for a dry film, Ning's differential sliding (:mod:`.friction.terms`, counted by the
pair's solvers), and per bearing Palmgren's viscous torque (eq 8,
:func:`~servofmu.physics.kernels.friction.palmgren_torque`),
M_L = 1e-7·s0·(max(ν·n, 2000))^(2/3)·dm³ [N·mm] (ν [mm²/s], n [r/min], dm [mm]; the
continuous form of eq 8) with the pair's calibrated s0, running and at rest; no viscous
torque without a lubricant.
"""

from __future__ import annotations

from ..kernels.friction import palmgren_torque


def running_terms(pair, kinematic_viscosity, pitch_diameter, rolling, speed):
    """(Palmgren's viscous torque of both bearings, None) [N·m] (Yu 2017 eq 8) at ν [m²/s],
    dm [m] and ω [rad/s]; ``rolling`` is not used (the model needs no data).

    Returns
    -------
    tuple
        (viscous torque [N·m], None: no sliding torque of its own).

    Examples
    --------
    >>> from servofmu.physics.bearing import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> viscous, sliding = running_terms(pair, 100e-6, 21.5e-3, None, 0.0)
    >>> round(viscous * 1e3, 6), sliding  # N·mm of both bearings at rest; no sliding of its own
    (0.219316, None)
    """
    s0 = pair.coefficients.palmgren_s0 if pair.lubricant is not None else 0.0
    return 2.0 * palmgren_torque(kinematic_viscosity, speed, pitch_diameter, s0), None

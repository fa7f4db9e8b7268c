"""Bearing friction: the terms of one contact and of a ball set (:mod:`.terms`), one module per
friction model (listed in :mod:`.registry`) and effect (:mod:`.grease`, :mod:`.prerolling`) and
the pair's friction model (:mod:`.models`).

The public names of :mod:`.terms` are importable from here as well: this package was the
module ``servofmu.physics.friction``.
"""

#: The names of :mod:`.terms` importable from here (imported when first asked for).
TERMS = (
    "HEATHCOTE",
    "PALMGREN_THRESHOLD",
    "BallSetTorques",
    "FrictionCoefficients",
    "ball_set_torques",
    "ball_torque_terms",
    "heathcote_sliding_force",
    "hysteresis_rolling_force",
    "palmgren_viscous_torque",
    "race_contact_radius",
    "regularised_friction_torque",
    "spin_moment",
)


def __getattr__(name):
    if name in TERMS:
        from . import terms

        return getattr(terms, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

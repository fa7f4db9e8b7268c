"""A preloaded pair of angular-contact ball bearings: its configuration
(:mod:`.configuration`), mounting (:mod:`.mounting`), the arrangement's equilibrium rows and the
solves on them (exact: :mod:`.state`; bracketing: :mod:`.preload`; per step: :mod:`.continuation`)
and the per-step model of the FMU (:mod:`.model`).

The public names of :mod:`.configuration` are importable from here as well: this package was
the module ``servofmu.physics.pair``.
"""

#: The names of :mod:`.configuration` importable from here (imported when first asked for).
CONFIGURATION = (
    "LUBRICATIONS",
    "DEFAULT_COEFFICIENTS",
    "PRESSURE_LIMIT",
    "BearingPair",
    "MOUNTING_CHANGES",
    "with_mounting",
    "assembly_geometry",
    "is_tandem",
    "effective_shim",
    "loop_stiffness",
    "loop_closure",
    "closure_coefficients",
    "pair_rows",
    "tandem_preload",
)


def __getattr__(name):
    if name in CONFIGURATION:
        from . import configuration

        return getattr(configuration, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

"""Pure physics models (numpy in, numpy out, SI units), each citing its paper and equation.

Modules: units, materials, viscosity, geometry, hertz, equilibrium, fits (radial thermal
coupling), preload (axial thermal coupling), friction, rolling_friction (the SKF 2004 model),
ehl_rolling (per-contact hydrodynamic rolling resistance), grease_torque (the cold-grease term),
temperatures (part temperatures), pair, pair_state and continuation (the pair's state, exact and
per step), bearing (the composed model), actuator (Liu 2014), motor, control, thermal_network
(part temperatures of a mechanism), catalog (records kept as data in ``data/*.toml``).
"""

#: The main modules (:func:`load_all` imports every module of the package)
MODULES = (
    "units",
    "materials",
    "viscosity",
    "geometry",
    "hertz",
    "equilibrium",
    "fits",
    "preload",
    "friction",
    "bearing",
    "actuator",
    "motor",
    "control",
    "thermal_network",
    "catalog",
)


def load_all() -> None:
    """Import every physics module and read every data table now.

    FMUs built from servofmu share the first imported copy of the package in a process, and a
    host may delete that FMU's extraction folder while others still run (fmpy's simulate_fmu
    does): after this call nothing is read from disk any more.

    Returns
    -------
    None

    Examples
    --------
    >>> load_all()
    >>> from servofmu.physics import catalog
    >>> "71803" in catalog.keys("bearings")  # read already: no file is opened now
    True
    """
    import importlib
    import pkgutil

    for module in pkgutil.iter_modules(__path__):  # every module, not only MODULES
        importlib.import_module(f"{__name__}.{module.name}")
    from .catalog import preload

    preload()

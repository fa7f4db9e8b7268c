"""Pure physics models (numpy in, numpy out, SI units), each citing its paper and equation.

Modules: units, materials, viscosity, geometry, hertz, equilibrium, fits (radial thermal
coupling), preload (axial thermal coupling), friction, bearing (the composed model), catalog
(records kept as data in ``data/*.toml``).
"""

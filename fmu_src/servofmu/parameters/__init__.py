"""The numbers of a mechanism, apart from its physics: the catalogue of records kept as data
(:mod:`~servofmu.parameters.catalog`, ``data/*.toml``, every value with its provenance), the
BearingFriction parameter table (:mod:`~servofmu.parameters.table`), the presets that fill it
from the catalogue (:mod:`~servofmu.parameters.presets`) and the mapping of a parameter set to
a :class:`~servofmu.physics.pair.configuration.BearingPair`
(:mod:`~servofmu.parameters.bearing`). The FMUs read them at run time (their parameter
tables, the actuator and the thermal presets), so an FMU ships this package with
:mod:`servofmu.physics`.
"""

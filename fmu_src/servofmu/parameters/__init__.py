"""The numbers of a mechanism, apart from its physics: the catalogue of records kept as data
(:mod:`.catalog`, ``data/*.toml``, every value with its provenance), the BearingFriction
parameter table (:mod:`.table`), the presets that fill it from the catalogue (:mod:`.presets`)
and the mapping of a parameter set to a :class:`~servofmu.physics.pair.configuration.BearingPair`
(:mod:`.bearing`). The FMUs read them at run time (their parameter tables, the actuator and the
thermal presets), so an FMU ships this package with :mod:`servofmu.physics`.
"""

"""The FMU slaves: module name = class name = modelIdentifier (BearingFriction,
ActuatorStiffness, DCMotor, ServoController, ThermalNetwork), over the machinery of
:mod:`.runtime`, each declaring its variables with :mod:`.declarations`.

Importing this package loads all of :mod:`servofmu.physics` and its data (see
:func:`servofmu.physics.load_all`).
"""

from ..physics import load_all

load_all()

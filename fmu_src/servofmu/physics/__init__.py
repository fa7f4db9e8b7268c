"""Pure physics models (numpy in, numpy out, SI units), each citing its paper and equation,
laid out in layers (``docs/development.md``, "Layers"):

- :mod:`.kernels`: the equations, float-or-array, shared by the exact vectorised path and the
  per-step path; they import nothing else from :mod:`servofmu.physics`;
- by subject above them: :mod:`.contact` (geometry, Hertz, ball loads), :mod:`.lubrication`
  (viscosity, lubricants), :mod:`.friction` (the terms, one module per friction model and
  their registry), :mod:`.thermal` (part temperatures, fits, the thermal network),
  :mod:`.pair` (the bearing pair: configuration, equilibrium rows, exact and bracketing
  solves, the continuation and :class:`~.pair.model.BearingModel`) and :mod:`.drives`
  (actuator, motor, control);
- :mod:`.bearing`: the face of the bearing model (its public names in one place);
- :mod:`.materials` and the argument checks beside everything.

The catalogues, presets and parameter tables are :mod:`servofmu.parameters`. The modules'
former names (:data:`MOVED`) stay importable: ``servofmu.physics.catalog`` is
:mod:`servofmu.parameters.catalog`, the same module.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.util
import sys

from .friction import registry as _friction_models

#: The former modules of the package, by their former name under ``servofmu.physics``, and
#: where each lives now: importing the former name gives that module itself (a friction
#: model's former name is in its registry entry, :mod:`.friction.registry`).
MOVED = {
    "units": "servofmu.physics.kernels.units",
    "_cython_shadow": "servofmu.physics.kernels._cython_shadow",
    "geometry": "servofmu.physics.contact.geometry",
    "hertz": "servofmu.physics.contact.hertz",
    "equilibrium": "servofmu.physics.contact.equilibrium",
    "viscosity": "servofmu.physics.lubrication.viscosity",
    "lubricant": "servofmu.physics.lubrication.lubricant",
    "friction_models": "servofmu.physics.friction.models",
    "grease_torque": "servofmu.physics.friction.grease",
    "temperatures": "servofmu.physics.thermal.temperatures",
    "fits": "servofmu.physics.thermal.fits",
    "thermal_network": "servofmu.physics.thermal.network",
    "mounting": "servofmu.physics.pair.mounting",
    "preload": "servofmu.physics.pair.preload",
    "pair_state": "servofmu.physics.pair.state",
    "continuation": "servofmu.physics.compiled",
    "actuator": "servofmu.physics.drives.actuator",
    "motor": "servofmu.physics.drives.motor",
    "control": "servofmu.physics.drives.control",
    "catalog": "servofmu.parameters.catalog",
    "parameter_table": "servofmu.parameters.table",
    "presets": "servofmu.parameters.presets",
    "bearing_parameters": "servofmu.parameters.bearing",
} | {e.former_name: e.module_name for e in _friction_models.entries() if e.former_name}


class _Moved(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Import finder of the former module names (:data:`MOVED`): the module where it lives."""

    def find_spec(self, fullname, path=None, target=None):
        prefix, _, name = fullname.rpartition(".")
        if prefix == __name__ and name in MOVED:
            return importlib.util.spec_from_loader(fullname, self)
        return None

    def create_module(self, spec):
        return importlib.import_module(MOVED[spec.name.rpartition(".")[2]])

    def exec_module(self, module):
        """The module has run where it lives."""


if not any(isinstance(f, _Moved) for f in sys.meta_path):
    sys.meta_path.append(_Moved())


def load_all() -> None:
    """Import every physics module (and :mod:`servofmu.parameters`) and read every data table
    now.

    FMUs built from servofmu share the first imported copy of the package in a process, and a
    host may delete that FMU's extraction folder while others still run (fmpy's simulate_fmu
    does): after this call nothing is read from disk any more.

    Returns
    -------
    None

    Examples
    --------
    >>> load_all()
    >>> from servofmu.parameters import catalog
    >>> "71803" in catalog.keys("bearings")  # read already: no file is opened now
    True
    """
    import pkgutil

    from .. import parameters

    for package in (sys.modules[__name__], parameters):
        for module in pkgutil.walk_packages(package.__path__, f"{package.__name__}."):
            if not module.name.rpartition(".")[2].startswith("_"):  # compiled twins: compiled
                importlib.import_module(module.name)
    from ..parameters.catalog import preload

    preload()

"""Catalogue presets at build time: the start values a build gives BearingFriction and
ActuatorStiffness (the numbers of the chosen presets, with their provenance), and the presets
an FMU carries as SSP parameter sets in ``resources/presets/``:

- ``mountings/<key>.ssv``: the whole parameter set of a catalogue mounting with its bearing,
  lubricant and coefficients (bind it to the component and the FMU is that mounting);
- ``bearings/<key>.ssv``: the bearing's numbers only (geometry, ring and ball materials);
- ``lubricants/<key>.ssv``: the lubrication and the lubricant's ν40, ν100 and Walther c.

ActuatorStiffness carries the mountings and bearings with the ``support_`` prefix (the state
of its support pair). Every value in them is SI, a choice an ``ssv:Integer`` with its item
name as description (:mod:`servofmu.parameter_sets`).
"""

from __future__ import annotations

from pathlib import Path

from servofmu.parameter_sets import write_ssv
from servofmu.parameters import catalog
from servofmu.parameters.bearing import (
    BEARING_FIELDS,
    DEFAULT_MOUNTING,
    LUBRICANT_FIELDS,
    PARAMETERS,
    STATE_PARAMETERS,
    bearing_values,
    default_parameters,
    default_sources,
    lubricant_values,
    prefixed_specs,
)

from .catalogs import KEY, Defaults

SUPPORT_LUBRICANT = "mos2_film"  # the support pair's lubricant plays no part in stiffness


def _fmu_value(spec, value):
    """A parameter value as the FMU holds it: a choice's item number, a count as int."""
    if spec.choices:
        return spec.item(value)
    return int(value) if spec.type == "Integer" else float(value)


def start_values(name: str, defaults: Defaults) -> dict[str, tuple[object, str]]:
    """{variable: (start value, provenance)} that ``defaults`` give FMU ``name`` (empty: the
    class's own defaults).

    Parameters
    ----------
    name : the FMU (BearingFriction and ActuatorStiffness take presets; ThermalNetwork the
        network of the chosen mounting's parts in chamber air: :mod:`.mechanism`)
    defaults : the chosen presets (:class:`catalogs.Defaults`)

    Returns
    -------
    dict
        Start values as the FMU holds them (SI floats, item numbers, ints) with provenance.
    """
    if name == "BearingFriction" and (defaults.mounting or defaults.lubricant):
        args = (defaults.mounting or DEFAULT_MOUNTING,)
        kw = {"lubricant": defaults.lubricant}
        values, sources = default_parameters(*args, **kw), default_sources(*args, **kw)
        return {p.name: (_fmu_value(p, values[p.name]), sources[p.name]) for p in PARAMETERS}
    if name == "ThermalNetwork" and (defaults.mounting or DEFAULT_MOUNTING) != DEFAULT_MOUNTING:
        from servofmu.physics.thermal.network import ENVIRONMENTS

        from .mechanism import resolve, thermal_parameters

        p = thermal_parameters(resolve(defaults))
        start = {f: (float(v), p.source(f)) for f, v in p.as_dict().items() if f != "environment"}
        start["environment"] = (
            ENVIRONMENTS.index(p.environment) + 1,
            "assumed: the mechanism in the air of a climatic chamber",
        )
        return start
    if name == "ActuatorStiffness" and defaults.support_mounting:
        key = defaults.support_mounting
        specs = prefixed_specs(
            "support_",
            "Support pair",
            STATE_PARAMETERS,
            default_parameters(key, lubricant=SUPPORT_LUBRICANT),
            default_sources(key, lubricant=SUPPORT_LUBRICANT),
        )
        return {p.name: (_fmu_value(p, p.default), p.source) for p in specs}
    return {}


def write_presets(folder: Path, name: str) -> Path:
    """Write the catalogue's presets for FMU ``name`` into ``folder`` (see the module
    docstring); returns ``folder``."""
    folder = Path(folder)
    support = name == "ActuatorStiffness"
    prefix = "support_" if support else ""
    for key in catalog.keys("mountings"):
        lubricant = SUPPORT_LUBRICANT if support else None
        values = default_parameters(key, lubricant=lubricant)
        _write(_file(folder, "mountings", key), values, prefix, f"mounting {key}", support)
    for key in catalog.keys("bearings"):
        values, _ = bearing_values(catalog.bearing(key))
        _write(_file(folder, "bearings", key), values, prefix, f"bearing {key}", support,
               BEARING_FIELDS)  # fmt: skip
    if not support:
        for key in catalog.keys("lubricants"):
            values, _ = lubricant_values(key)
            _write(_file(folder, "lubricants", key), values, "", f"lubricant {key}", False,
                   tuple(f for f in LUBRICANT_FIELDS if f in values))  # fmt: skip
    return folder


def _file(folder: Path, table: str, key: str) -> Path:
    """``folder/table/key.ssv``: a file name only from a valid catalogue key."""
    if not KEY.fullmatch(key):
        raise ValueError(f"{table}.{key!r} is not a catalogue key (letters, digits, underscores)")
    return folder / table / f"{key}.ssv"


def _write(path, values, prefix, what, support, only=None):
    names = STATE_PARAMETERS if support else [p.name for p in PARAMETERS]
    if only is not None:
        names = [n for n in names if n in only]
    specs = prefixed_specs(prefix, "", names, values, dict.fromkeys(names, ""))
    write_ssv(
        {p.name: values[p.name.removeprefix(prefix)] for p in specs},
        path,
        specs=specs,
        comment=f"servofmu preset: {what} ({catalog.origin(*_table_key(what))})",
    )


def _table_key(what: str) -> tuple[str, str]:
    kind, key = what.split(" ", 1)
    return f"{kind}s", key

"""User catalogues: a user's bearings, lubricants, materials and mountings, in the format of the
package's ``physics/data/*.toml`` (every number ``{value, unit, kind, ref}``), merged into the
catalogue for a build (``servofmu build --catalog my.toml``) or a listing (``servofmu
catalog``). The format is documented with an example in ``examples/my_gimbal_catalog.toml``.

A user catalogue file holds tables ``[bearings.KEY]``, ``[lubricants.KEY]``,
``[materials.KEY]``, ``[mountings.KEY]`` (keys new to the catalogue) and optionally
``[defaults]``: ``mounting`` (the preset whose numbers become the FMUs' start values, its
bearing included), ``lubricant`` and ``support_mounting`` (ActuatorStiffness's support pair).
Every entry is loaded, and every mounting turned into the FMU's numbers, before anything is
built: an error names the file, the entry and the field.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from servofmu.physics import catalog

DEFAULT_KEYS = ("mounting", "lubricant", "support_mounting")


@dataclass(frozen=True)
class Defaults:
    """The presets that fill an FMU build's start values (None: the package's own)."""

    mounting: str | None = None
    lubricant: str | None = None
    support_mounting: str | None = None
    files: tuple[str, ...] = field(default=())

    @property
    def is_package(self) -> bool:
        return self.mounting is None and self.lubricant is None and self.support_mounting is None


def read(path) -> tuple[dict, dict]:
    """(tables, defaults) of user catalogue ``path``; ValueError naming the file."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise ValueError(f"{path}: cannot be read ({exc.strerror})") from None
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{path}: not valid TOML ({exc})") from None
    defaults = data.pop("defaults", {})
    extra = sorted(set(defaults) - set(DEFAULT_KEYS)) if isinstance(defaults, dict) else defaults
    if extra:
        raise ValueError(f"{path}: [defaults] may name {list(DEFAULT_KEYS)}, not {extra}")
    return data, defaults


def load(paths, mounting=None, lubricant=None, support_mounting=None) -> Defaults:
    """Merge the user catalogues ``paths`` into the catalogue, check every entry they add
    (loaded, and each mounting turned into the parameter set), and return the build's
    defaults: the arguments given, else the last file's ``[defaults]``. On an error nothing
    stays merged and ValueError names the file, the entry and the field."""
    from servofmu.physics.bearing_parameters import default_parameters

    chosen = {"mounting": mounting, "lubricant": lubricant, "support_mounting": support_mounting}
    where = dict.fromkeys(chosen, "command line")
    files = []
    try:
        for path in paths:
            tables, defaults = read(path)
            catalog.add_entries(tables, str(path))
            for table in catalog.USER_TABLES:
                catalog.check_entries(table, list(tables.get(table, {})))
            for key in tables.get("mountings", {}):
                _check_preset(path, key, default_parameters)
            for k, v in defaults.items():
                if chosen[k] is None or where[k] != "command line":
                    chosen[k], where[k] = v, f"{path}: [defaults]"
            files.append(str(path))
        for kind, key in chosen.items():
            if key is not None:
                table = "lubricants" if kind == "lubricant" else "mountings"
                if key not in catalog.keys(table):
                    raise ValueError(
                        f"{where[kind]}: {kind} = {key!r} is not in the catalogue's {table}: "
                        f"{catalog.keys(table)}"
                    )
        if chosen["mounting"] or chosen["lubricant"]:
            _check_preset(files[-1] if files else "--preset", chosen["mounting"],
                          default_parameters, chosen["lubricant"])  # fmt: skip
    except ValueError:
        catalog.remove_user_entries()
        raise
    return Defaults(**chosen, files=tuple(files))


def _check_preset(path, mounting, default_parameters, lubricant=None) -> None:
    from servofmu.physics.bearing_parameters import DEFAULT_MOUNTING, pair_from_parameters

    try:
        pair_from_parameters(default_parameters(mounting or DEFAULT_MOUNTING, lubricant=lubricant))
    except (KeyError, ValueError) as err:
        raise ValueError(f"{path}: mountings.{mounting}: {err}") from None


def unload() -> None:
    """Forget the user catalogues (the package's catalogue stays)."""
    catalog.remove_user_entries()


def listing() -> str:
    """The catalogue as text, one table per kind, each entry with its origin (the package's
    data file or a user catalogue) and the numbers that identify it (SI at the edges: mm,
    GPa, cSt, µm/m/K)."""
    from servofmu.physics.bearing_parameters import default_parameters

    lines = ["bearings (d × D × B [mm], Z × Dw [mm], dm [mm], α0 [°], f_i/f_o)"]
    for key in catalog.keys("bearings"):
        b = catalog.bearing(key)
        lines.append(
            f"  {key:10s} {b.bore * 1e3:g} × {b.outer_diameter * 1e3:g} × {b.width * 1e3:g}, "
            f"{b.n_balls} × {b.ball_diameter * 1e3:.4g}, {b.pitch_diameter * 1e3:.4g}, "
            f"{math.degrees(b.nominal_contact_angle):.4g}, {b.inner_curvature:g}/"
            f"{b.outer_curvature:g}  [{catalog.origin('bearings', key)}]"
        )
    lines.append(
        "lubricants (type, ν40 / ν100 [cSt] of the base oil and the kind of their source, pour "
        "point [°C])"
    )
    for key in catalog.keys("lubricants"):
        rec = catalog.lubricant_record(key)
        nu = (
            "dry film"
            if rec.viscosity is None
            else f"{rec.viscosity_40 * 1e6:.4g} / {rec.viscosity_100 * 1e6:.4g} "
            f"({rec.source('viscosity_40').split(':')[0]})"
        )
        pour = "" if rec.pour_point is None else f", {rec.pour_point - 273.15:.4g}"
        lines.append(
            f"  {key:16s} {rec.lubricant_type}, {nu}{pour}  [{catalog.origin('lubricants', key)}]"
        )
    lines.append("materials (E [GPa], ν, α [µm/(m·K)])")
    for key in catalog.keys("materials"):
        m = catalog.material(key)
        lines.append(
            f"  {key:16s} {m.youngs_modulus / 1e9:g}, {m.poisson_ratio:g}, "
            f"{m.expansion * 1e6:g}  [{catalog.origin('materials', key)}]"
        )
    lines.append("mountings (bearing, arrangement, preload, loop, lubricant)")
    for key in catalog.keys("mountings"):
        m = catalog.mounting(key)
        p = default_parameters(key)
        lube = "dry film" if p["lubrication"] == "solid" else "grease"
        lines.append(
            f"  {key:22s} {m.bearing_key}, {m.arrangement}, {m.preload_method}, "
            f"{m.loop.model}, {lube}  [{catalog.origin('mountings', key)}]"
        )
    return "\n".join(lines)


def preset_table(values, sources) -> str:
    """A parameter set as text: name, value (SI), unit and provenance, one per line."""
    from servofmu.physics.bearing_parameters import PARAMETERS

    rows = []
    for spec in PARAMETERS:
        value = values[spec.name]
        text = value if isinstance(value, str) else f"{value:.10g}"
        rows.append(f"  {spec.name:24s} {text:>14s} {spec.unit or '':5s} {sources[spec.name]}")
    return "\n".join(rows)

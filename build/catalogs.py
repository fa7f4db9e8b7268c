"""User catalogues: a user's bearings, lubricants, materials and mountings, in the format of the
package's ``parameters/data/*.toml`` (every number ``{value, unit, kind, ref}``), merged into the
catalogue for a build (``servofmu build --catalog my.toml``) or a listing (``servofmu
catalog``). The format is documented with an example in ``examples/my_gimbal_catalog.toml``.

A user catalogue file holds tables ``[bearings.KEY]``, ``[lubricants.KEY]``,
``[materials.KEY]``, ``[mountings.KEY]`` (keys new to the catalogue), tables keyed by a mounting
that take precedence over the package's for it — ``[coefficients.MOUNTING]`` (its friction
coefficients: a calibration, as ``servofmu calibrate`` writes it) and
``[tolerances.MOUNTING]`` (its tolerance bands for ``servofmu montecarlo``) — and optionally
``[defaults]``: ``mounting`` (the preset whose numbers become the FMUs' start values, its
bearing included), ``lubricant`` and ``support_mounting`` (ActuatorStiffness's support pair).
Every entry is loaded, and every mounting turned into the FMU's numbers, before anything is
built: an error names the file, the entry and the field.
"""

from __future__ import annotations

import contextlib
import gc
import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from servofmu.files import read_input
from servofmu.parameters import catalog
from servofmu.physics._checks import suggest

DEFAULT_KEYS = ("mounting", "lubricant", "support_mounting")
KEY = re.compile(r"[A-Za-z0-9_]+")  # a catalogue key: letters, digits, underscores (ASCII)


class CatalogueError(ValueError):
    """A user catalogue that does not fit its schema: ``problems`` lists them (the first
    twenty), each naming the file, the table, the entry and the key; the message is the
    first, with how many more there are."""

    def __init__(self, problems: list[str]):
        more = f" (and {len(problems) - 1} more problems)" if len(problems) > 1 else ""
        super().__init__(problems[0] + more)
        self.problems = list(problems)


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
    """(tables, defaults) of user catalogue ``path``; ValueError naming the file.

    Only reads and checks the ``[defaults]`` keys; :func:`load` checks the entries.

    Parameters
    ----------
    path : str or pathlib.Path
        The user catalogue (TOML).

    Returns
    -------
    tuple of dict
        ``(tables, defaults)``: ``{table: {key: entry}}`` as written (numbers in the file's
        units, ``{value, unit, kind, ref}``), and the ``[defaults]`` table (``{}`` without
        one).

    Raises
    ------
    ValueError
        For an unreadable file (too large, not UTF-8), invalid TOML, a ``[defaults]`` key
        other than ``mounting``, ``lubricant`` and ``support_mounting``, or an entry that does
        not fit its table's schema (:class:`CatalogueError`, :mod:`.schema`: an unknown key, a
        wrong type, a unit of another dimension); the message names the file.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> q = '{{ value = {}, unit = "{}", kind = "handbook", ref = "ASM" }}'.format
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = Path(tmp) / "mine.toml"
    ...     _ = path.write_text(
    ...         '[defaults]\\nlubricant = "krytox_143aa"\\n'
    ...         '[materials.my_7075]\\nname = "Aluminium 7075-T6"\\n'
    ...         f'youngs_modulus = {q(71.7, "GPa")}\\npoisson_ratio = {q(0.33, "-")}\\n'
    ...         f'expansion = {q(23.6e-6, "1/K")}\\n'
    ...     )
    ...     tables, defaults = read(path)
    ...     _ = path.write_text('[defaults]\\ncolour = "red"\\n')
    ...     try:
    ...         read(path)
    ...     except ValueError as exc:
    ...         print(str(exc).replace(str(path), "mine.toml"))
    mine.toml: [defaults] may name ['mounting', 'lubricant', 'support_mounting'], not ['colour']
    >>> defaults
    {'lubricant': 'krytox_143aa'}
    >>> tables["materials"]["my_7075"]["youngs_modulus"]["value"]  # as written, in GPa
    71.7
    """
    from .schema import catalogue_problems

    path = Path(path)
    try:
        with _collector_paused():
            data = tomllib.loads(read_input(path, "catalogue"))
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{path}: not valid TOML ({exc})") from None
    except RecursionError:
        raise ValueError(f"{path}: not a catalogue (tables or arrays nested too deeply)") from None
    defaults = data.get("defaults", {})
    extra = sorted(set(defaults) - set(DEFAULT_KEYS)) if isinstance(defaults, dict) else defaults
    if extra:
        raise ValueError(f"{path}: [defaults] may name {list(DEFAULT_KEYS)}, not {extra}")
    for table, entries in data.items():
        for key in entries if isinstance(entries, dict) and table != "defaults" else ():
            if not KEY.fullmatch(key):
                raise ValueError(
                    f"{path}: [{table}] entry {key!r}: a catalogue key is letters, digits and "
                    "underscores (it names files and appears in XML)"
                )
    with _collector_paused():
        problems = catalogue_problems(data, str(path))
    if problems:
        raise CatalogueError(problems)
    data.pop("defaults", None)
    return data, defaults


@contextlib.contextmanager
def _collector_paused():
    """Python's cyclic garbage collector paused: reading and checking a large catalogue makes
    millions of acyclic objects, and the collector's passes over them took half the time."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def load(paths, mounting=None, lubricant=None, support_mounting=None) -> Defaults:
    """Merge the user catalogues ``paths`` into the catalogue, check every entry they add
    (loaded, and each mounting turned into the parameter set), and return the build's
    defaults: the arguments given, else the last file's ``[defaults]``. On an error nothing
    stays merged and ValueError names the file, the entry and the field.

    Parameters
    ----------
    paths : iterable of str or pathlib.Path
        User catalogues (TOML, see the module docstring), merged in this order.
    mounting : str, optional
        Catalogue mounting whose numbers become BearingFriction's start values (overrides
        the files' ``[defaults]``).
    lubricant : str, optional
        Catalogue lubricant of those start values (overrides the files' ``[defaults]``).
    support_mounting : str, optional
        Catalogue mounting of ActuatorStiffness's support pair (overrides the files'
        ``[defaults]``).

    Returns
    -------
    Defaults
        The chosen presets (None: the package's own) and the files merged. The entries stay
        in the catalogue until :func:`unload`.

    Raises
    ------
    ValueError
        For a bad file, entry or preset; nothing stays merged then.

    Examples
    --------
    A user material merged into the catalogue (71.7 GPa = 7.17e10 Pa), then forgotten:

    >>> import tempfile
    >>> from pathlib import Path
    >>> from servofmu.parameters import catalog
    >>> q = '{{ value = {}, unit = "{}", kind = "handbook", ref = "ASM" }}'.format
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = Path(tmp) / "mine.toml"
    ...     _ = path.write_text(
    ...         '[defaults]\\nlubricant = "krytox_143aa"\\n'
    ...         '[materials.my_7075]\\nname = "Aluminium 7075-T6"\\n'
    ...         f'youngs_modulus = {q(71.7, "GPa")}\\npoisson_ratio = {q(0.33, "-")}\\n'
    ...         f'expansion = {q(23.6e-6, "1/K")}\\n'
    ...     )
    ...     defaults = load([path])
    >>> defaults.lubricant, defaults.mounting
    ('krytox_143aa', None)
    >>> f"{catalog.material('my_7075').youngs_modulus:.4g}"  # Pa
    '7.17e+10'
    >>> unload()
    >>> load([], mounting="yu2017_gimbal_spring").mounting  # a package preset, no file
    'yu2017_gimbal_spring'
    >>> try:
    ...     load([], support_mounting="my_gimbal")
    ... except ValueError as exc:
    ...     print(exc)  # doctest: +ELLIPSIS
    command line: support_mounting = 'my_gimbal' is not in the catalogue's mountings: [...]...
    """
    with _collector_paused():
        return _merge(paths, mounting, lubricant, support_mounting)


def _merge(paths, mounting, lubricant, support_mounting) -> Defaults:
    from servofmu.parameters.bearing import default_parameters

    chosen = {"mounting": mounting, "lubricant": lubricant, "support_mounting": support_mounting}
    where = dict.fromkeys(chosen, "command line")
    files = []
    try:
        per_mounting = []  # coefficients, tolerances: checked once every mounting is in
        for path in paths:
            tables, defaults = read(path)
            catalog.add_entries(tables, str(path))
            for table in catalog.USER_TABLES:
                keys = list(tables.get(table, {}))
                if table in catalog.MOUNTING_TABLES:
                    per_mounting.append((table, keys))
                else:
                    catalog.check_entries(table, keys)
            for key in tables.get("mountings", {}):
                _check_preset(path, key, default_parameters)
            for k, v in defaults.items():
                if chosen[k] is None or where[k] != "command line":
                    chosen[k], where[k] = v, f"{path}: [defaults]"
            files.append(str(path))
        for table, keys in per_mounting:
            catalog.check_entries(table, keys)
            if table == "coefficients":
                for key in keys:
                    _check_preset(catalog.origin(table, key), key, default_parameters)
        for kind, key in chosen.items():
            if key is not None:
                table = "lubricants" if kind == "lubricant" else "mountings"
                if key not in catalog.keys(table):
                    raise ValueError(
                        f"{where[kind]}: {kind} = {key!r} is not in the catalogue's {table}: "
                        f"{catalog.keys(table)}{suggest(key, catalog.keys(table))}"
                    )
        if chosen["mounting"] or chosen["lubricant"]:
            _check_preset(files[-1] if files else "--preset", chosen["mounting"],
                          default_parameters, chosen["lubricant"])  # fmt: skip
    except ValueError:
        catalog.remove_user_entries()
        raise
    return Defaults(**chosen, files=tuple(files))


def _check_preset(path, mounting, default_parameters, lubricant=None) -> None:
    from servofmu.parameters.bearing import DEFAULT_MOUNTING, pair_from_parameters

    try:
        pair_from_parameters(default_parameters(mounting or DEFAULT_MOUNTING, lubricant=lubricant))
    except (KeyError, ValueError) as err:
        raise ValueError(f"{path}: mountings.{mounting}: {err}") from None


def unload() -> None:
    """Forget the user catalogues (the package's catalogue stays).

    Returns
    -------
    None

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> q = {"value": 70, "unit": "GPa", "kind": "assumed", "ref": "demo"}
    >>> entry = {"name": "demo", "youngs_modulus": q}
    >>> catalog.add_entries({"materials": {"demo_alu": entry}}, "demo.toml")
    >>> catalog.origin("materials", "demo_alu")
    'demo.toml'
    >>> unload()
    >>> "demo_alu" in catalog.keys("materials"), "cast_aluminium" in catalog.keys("materials")
    (False, True)
    """
    catalog.remove_user_entries()


def listing() -> str:
    """The catalogue as text, one table per kind, each entry with its origin (the package's
    data file or a user catalogue) and the numbers that identify it (SI at the edges: mm,
    GPa, cSt, µm/m/K).

    Returns
    -------
    str
        One header line per table (bearings, lubricants, materials, mountings) naming the
        columns and their units (mm, °, cSt, °C, GPa, µm/(m·K)), then one line per entry.

    Examples
    --------
    The header of the bearings and the line of the 71803 (d × D × B = 17 × 26 × 5 mm):

    >>> lines = listing().splitlines()
    >>> print(lines[0])
    bearings (d × D × B [mm], Z × Dw [mm], dm [mm], α0 [°], f_i/f_o)
    >>> print(next(line for line in lines if line.split()[0] == "71803"))
      71803      17 × 26 × 5, 15 × 2.381, 21.5, 15, 0.56/0.54  [data/bearings.toml]
    """
    from servofmu.parameters.bearing import default_parameters

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
        "point [°C]; the range of its data [°C], and the law when a third viscosity is known)"
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
        if rec.viscosity is not None:
            v = rec.viscosity
            law = "; Vogel" if len(getattr(v, "points", ())) >= 3 else ""
            pour += f"; {v.lower_limit - 273.15:.4g}…{v.upper_limit - 273.15:.4g}{law}"
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
    """A parameter set as text: name, value (SI), unit and provenance, one per line.

    Parameters
    ----------
    values : dict
        ``{parameter: value}`` in SI units (choices as item names), e.g.
        :func:`~servofmu.parameters.bearing.default_parameters`; every parameter of
        ``PARAMETERS`` must be there.
    sources : dict
        ``{parameter: provenance}``, e.g.
        :func:`~servofmu.parameters.bearing.default_sources`.

    Returns
    -------
    str
        One line per parameter of ``PARAMETERS``: name, value (SI), SI unit, provenance.

    Examples
    --------
    The first lines of the default preset (Yu 2017's gimbal, a 71803: d = 17 mm, D = 26 mm):

    >>> from servofmu.parameters.bearing import default_parameters, default_sources
    >>> text = preset_table(default_parameters(), default_sources())
    >>> print("\\n".join(text.splitlines()[:2]))
      bore                              0.017 m     paper: Yu 2017 §2
      outer_diameter                    0.026 m     paper: Yu 2017 §2
    """
    from servofmu.parameters.bearing import PARAMETERS

    rows = []
    for spec in PARAMETERS:
        value = values[spec.name]
        text = value if isinstance(value, str) else f"{value:.10g}"
        rows.append(f"  {spec.name:24s} {text:>14s} {spec.unit or '':5s} {sources[spec.name]}")
    return "\n".join(rows)

"""The mechanism a command works on, and where its build lives.

A mechanism is a catalogue mounting (with its bearing, lubricant and coefficients), chosen
from the package's catalogue or a user's (``--catalog FILE``, repeatable; ``--mounting KEY``,
else the last file's ``[defaults] mounting``, else the package's default, Yu 2017's gimbal).
Every command that takes ``--catalog``/``--mounting`` resolves them here, once
(:func:`open_mechanism`), and works on the :class:`Mechanism` it gets.

**Where its build lives.** The standard mechanism (no catalogue, no other preset) is built in
``build/out`` (:data:`~servofmu.build.fmu.DEFAULT_OUT`); any other in ``build/<key>``, its key
the mounting's (``build/my_gimbal``), with ``+<lubricant>`` and ``+support_<mounting>`` when
those are chosen too. A build records its mechanism (the chosen keys and the content hash of
every catalogue file) in each FMU's ``resources/servofmu_build.json``: a build whose record,
or the package hash, differs from now is stale and rebuilt; a folder holding another
mechanism's build is never overwritten.

**Its systems.** A build for a mechanism other than the standard one packs the gimbal rigs
(:data:`MECHANISM_SYSTEMS`) with the mechanism bound in full: each ``bearing.ssv`` carries the
mechanism's whole parameter set, each ``thermal.ssv`` the ThermalNetwork of its parts
(:func:`thermal_parameters`), and variants that bind the gimbal's own geometry, fits, loop or
preload (Yu's mountings ``rigid``, ``printed``, ``spring``, his interferences) are left out:
they would put Yu's 71803 back. Variants of inputs (``cold``, ``warm``, ``cooling``) and of the
lubricant (``grease_g1074``) stay. Ning's space-bearing rigs (stepped at 1 s, tuned for a dry
film whose torque does not depend on speed) and Liu's actuator reproduce their papers and
stay in the standard build (the actuator joins a build that chooses its support pair).
"""

from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import math
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from servofmu.parameters import catalog
from servofmu.parameters.bearing import (
    DEFAULT_MOUNTING,
    LUBRICANT_FIELDS,
    PARAMETERS,
    default_parameters,
    default_sources,
)
from servofmu.parameters.presets import CoefficientSet, coefficient_set
from servofmu.physics.materials import THERMAL_FIELDS

from . import catalogs
from .catalogs import Defaults

#: The systems a build for a mechanism packs, its bearing bound: the gimbal's speed loop,
#: position loop and chamber (with a ThermalNetwork of the mechanism's parts).
MECHANISM_SYSTEMS = ("seeker_gimbal", "seeker_gimbal_position", "seeker_gimbal_chamber")
#: The system a build packs besides when it chooses ActuatorStiffness's support pair.
SUPPORT_SYSTEMS = ("ema_actuator",)
#: The default support pair of ActuatorStiffness (Liu 2014's actuator).
DEFAULT_SUPPORT = catalog.actuator_entry("liu2014_ema")[0]["support_mounting"]
#: The ThermalNetwork of a mechanism in a climatic chamber: air crossing the housing [m/s].
CHAMBER_AIR_SPEED = (
    1.0,
    "assumed: forced circulation in the work space of a climatic chamber, 1 m/s (as for "
    "Yu's gimbal, data/thermal.toml)",
)
#: Bearing parameters a variant may bind in a mechanism's build: the lubricant with its grease
#: term (a lubricant's datasheet calibration); anything else of the pair is the mechanism's.
LUBRICANT_PARAMETERS = frozenset(LUBRICANT_FIELDS)


@dataclass(frozen=True)
class Mechanism:
    """A resolved mechanism: the presets a build takes (:class:`~.catalogs.Defaults`), what
    the mounting is, what its friction coefficients are, and where its build lives.

    Attributes
    ----------
    defaults : the presets chosen (None where the package's own), and the catalogue files
    mounting : the catalogue mounting (the package's default when none was chosen)
    lubricant : the lubricant of its preset (catalogue key)
    name : the mounting entry's name
    bearing : the bearing's catalogue key
    coefficients : what its friction coefficients are (:func:`.parameters.presets.coefficient_set`)
    catalogue_hashes : (file, sha256 of its content) of every catalogue file, in order
    yu : whether it is one of Yu 2017's gimbal mountings of the package (his measurements
        are its reference)
    chosen : whether a mounting was named (on the command line or in a catalogue's
        ``[defaults]``), the package's default included
    """

    defaults: Defaults
    mounting: str
    lubricant: str
    name: str
    bearing: str
    coefficients: CoefficientSet
    catalogue_hashes: tuple[tuple[str, str], ...] = ()
    yu: bool = False
    chosen: bool = False

    @property
    def standard(self) -> bool:
        """The package's own mechanism, built in build/out: no catalogue, no other preset."""
        return self.defaults.is_package and not self.catalogue_hashes

    @property
    def key(self) -> str:
        """What identifies the mechanism's build: ``standard``, or the mounting's key with
        ``+<lubricant>`` and ``+support_<mounting>`` when those were chosen."""
        if self.standard:
            return "standard"
        d = self.defaults
        parts = [d.mounting or DEFAULT_MOUNTING]
        parts += [d.lubricant] if d.lubricant else []
        parts += [f"support_{d.support_mounting}"] if d.support_mounting else []
        return "+".join(parts)

    @property
    def build_dir(self) -> Path:
        """Where the mechanism's build lives: build/out (standard) or build/<key>, relative
        to the working folder."""
        from .fmu import DEFAULT_OUT

        return DEFAULT_OUT if self.standard else Path("build") / self.key

    @property
    def systems(self) -> tuple[str, ...] | None:
        """The systems its build packs (None: every system of the package)."""
        if self.standard:
            return None
        return MECHANISM_SYSTEMS + (SUPPORT_SYSTEMS if self.defaults.support_mounting else ())

    def record(self) -> dict:
        """The mechanism as its build records it (``servofmu_build.json``)."""
        d = self.defaults
        return {
            "key": self.key,
            "mounting": d.mounting,
            "lubricant": d.lubricant,
            "support_mounting": d.support_mounting,
            "catalogues": [{"file": f, "sha256": h} for f, h in self.catalogue_hashes],
        }

    def parameters(self) -> dict:
        """The BearingFriction parameter set of the mechanism (SI; needs its catalogues)."""
        return default_parameters(self.mounting, lubricant=self.defaults.lubricant)

    def sources(self) -> dict:
        """The provenance of each value of :meth:`parameters`."""
        return default_sources(self.mounting, lubricant=self.defaults.lubricant)

    def describe(self) -> str:
        """One line: the mounting, its bearing and lubricant, where it comes from."""
        files = ", ".join(f for f, _ in self.catalogue_hashes)
        return (
            f"{self.mounting} ({self.name}; bearing {self.bearing}, lubricant "
            f"{self.lubricant}; {files or catalog.origin('mountings', self.mounting)})"
        )


def _sha256(path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def _normalised(defaults: Defaults) -> Defaults:
    """``defaults`` without choices that name what the package takes anyway (the default
    mounting, a mounting's own lubricant, the actuator's own support pair)."""
    mounting = None if defaults.mounting == DEFAULT_MOUNTING else defaults.mounting
    own = catalog.mounting_entry(defaults.mounting or DEFAULT_MOUNTING).get("lubricant")
    lubricant = None if defaults.lubricant == own else defaults.lubricant
    support = None if defaults.support_mounting == DEFAULT_SUPPORT else defaults.support_mounting
    return dataclasses.replace(
        defaults, mounting=mounting, lubricant=lubricant, support_mounting=support
    )


def resolve(defaults: Defaults) -> Mechanism:
    """The :class:`Mechanism` of presets ``defaults`` (:func:`.catalogs.load`; its
    catalogues must be loaded).

    Parameters
    ----------
    defaults : Defaults
        The chosen presets and catalogue files.

    Returns
    -------
    Mechanism

    Examples
    --------
    >>> m = resolve(Defaults())
    >>> m.standard, m.key, str(m.build_dir), m.coefficients.kind
    (True, 'standard', 'build/out', 'calibrated')
    >>> m = resolve(Defaults(mounting="yu2017_gimbal_spring"))
    >>> m.key, str(m.build_dir), m.yu
    ('yu2017_gimbal_spring', 'build/yu2017_gimbal_spring', True)
    """
    chosen = defaults.mounting is not None
    defaults = _normalised(defaults)
    mounting = defaults.mounting or DEFAULT_MOUNTING
    entry = catalog.mounting_entry(mounting)
    lubricant = defaults.lubricant or entry.get("lubricant", "")
    package = catalog.origin("mountings", mounting).startswith("data/")
    return Mechanism(
        defaults=defaults,
        mounting=mounting,
        lubricant=lubricant,
        name=entry.get("name", mounting),
        bearing=entry["bearing"],
        coefficients=coefficient_set(mounting),
        catalogue_hashes=tuple((f, _sha256(f)) for f in defaults.files),
        yu=package and catalog.coefficient_set_name(mounting) == DEFAULT_MOUNTING,
        chosen=chosen,
    )


@contextlib.contextmanager
def open_mechanism(
    catalogues=(), mounting=None, lubricant=None, support_mounting=None
) -> Iterator[Mechanism]:
    """Merge the user catalogues, choose the presets (the arguments, else the files'
    ``[defaults]``) and yield the :class:`Mechanism`; the catalogues are forgotten on exit.
    The one place the command line turns ``--catalog``/``--mounting``/``--lubricant`` into a
    mechanism; a bad file, entry or key raises ValueError before anything else is done.

    Parameters
    ----------
    catalogues : iterable of path
        User catalogues, merged in order.
    mounting, lubricant, support_mounting : str, optional
        Catalogue keys (override the files' ``[defaults]``).

    Returns
    -------
    contextlib.AbstractContextManager
        Yields the :class:`Mechanism`.

    Examples
    --------
    >>> with open_mechanism(mounting="ning_space_shaft") as m:
    ...     print(m.key, m.lubricant, m.coefficients.kind)
    ning_space_shaft mos2_film assumed
    >>> try:
    ...     with open_mechanism(mounting="yu2017_gimbal_sprung"):
    ...         pass
    ... except ValueError as exc:
    ...     print(str(exc).split("] ")[-1])
    (did you mean 'yu2017_gimbal_spring'?)
    """
    defaults = catalogs.load(catalogues, mounting, lubricant, support_mounting)
    try:
        yield resolve(defaults)
    finally:
        catalogs.unload()


# ------------------------------------------------------------------ the thermal network
def _thermal_complete(material, notes: dict) -> object:
    """``material`` with every thermal property (:data:`THERMAL_FIELDS`, emissivity): those it
    lacks taken from the package material closest to it in E and α, and named in ``notes``
    ({material key: (properties, source)})."""
    fields = (*THERMAL_FIELDS, "emissivity")
    missing = [f for f in fields if getattr(material, f) is None]
    if not missing:
        return material
    candidates = []
    for key in catalog.keys("materials"):
        if not catalog.origin("materials", key).startswith("data/"):
            continue
        other = catalog.material(key)
        if all(getattr(other, f) is not None for f in fields):
            distance = math.hypot(
                (other.youngs_modulus - material.youngs_modulus) / material.youngs_modulus,
                (other.expansion - material.expansion) / max(abs(material.expansion), 1e-7),
            )
            candidates.append((distance, key, other))
    _, key, nearest = min(candidates)
    source = (
        f"assumed: {key}'s (the catalogue material closest in E and α; {material.key} gives none)"
    )
    notes[material.key] = (missing, source)
    provenance = dict(material.provenance) | dict.fromkeys(missing, source)
    return dataclasses.replace(
        material,
        provenance=tuple(provenance.items()),
        **{f: getattr(nearest, f) for f in missing},
    )


def thermal_parameters(mechanism: Mechanism):
    """The ThermalNetwork of the mechanism's parts in the air of a climatic chamber
    (:func:`~servofmu.physics.thermal.network.mechanism_parameters`; needs its catalogues):
    the package's preset for Yu's default gimbal (``yu2017_gimbal_chamber``), else derived
    from the mounting's bearing, seats, loop lengths and materials. A thermal property a
    material does not give is taken from the closest package material and said so in each
    value's provenance; the air speed (1 m/s) and the reference preload for the ball contacts
    (the mounting's assembly preload, else the library's preload at the assembly
    temperature) are stated there too.

    Returns
    -------
    ThermalParameters

    Examples
    --------
    >>> p = thermal_parameters(resolve(Defaults(mounting="yu2017_gimbal_spring")))
    >>> p.environment, round(p.housing_capacity, 1), "30 N" in p.source("ball_conductance")
    ('air', 147.7, True)
    """
    from servofmu.physics.thermal import network as tn

    if mechanism.mounting == DEFAULT_MOUNTING:
        return tn.preset("yu2017_gimbal_chamber")
    bearing, mounting, notes = _thermal_parts(mechanism)
    preload, preload_source = _reference_preload(mechanism)
    p = tn.mechanism_parameters(
        bearing,
        mounting,
        vacuum=False,
        air_speed=CHAMBER_AIR_SPEED[0],
        reference_preload=preload,
        notes={
            "air_speed": CHAMBER_AIR_SPEED[1],
            "reference_preload": preload_source,
            "inner_ring_heat_fraction": "assumed: half of the power loss at the inner-race "
            "contacts, half at the outer (under a pure preload both carry the same ball load)",
        },
    )
    provenance = []
    for field, source in p.provenance:
        for key, (missing, why) in notes.items():
            if key in source and why not in source:
                source += f"; {key}: {', '.join(missing)} {why}"
        provenance.append((field, source))
    return dataclasses.replace(p, provenance=tuple(provenance))


def _thermal_parts(mechanism: Mechanism):
    """(bearing, mounting, notes): the mechanism's catalogue records with every material
    thermally complete (:func:`_thermal_complete`; ``notes`` says what was taken from where)."""
    mounting = catalog.mounting(mechanism.mounting)
    bearing = catalog.bearing(mechanism.bearing)
    notes: dict = {}
    fit = mounting.fit
    fit = dataclasses.replace(
        fit,
        housing_material=_thermal_complete(fit.housing_material, notes),
        shaft_material=_thermal_complete(fit.shaft_material, notes),
    )
    bearing = dataclasses.replace(
        bearing,
        ring_material=_thermal_complete(bearing.ring_material, notes),
        ball_material=_thermal_complete(bearing.ball_material, notes),
    )
    return bearing, dataclasses.replace(mounting, fit=fit), notes


def assumed_fields(p) -> list[str]:
    """The fields of ThermalParameters ``p`` whose provenance rests on an assumed value.

    Returns
    -------
    list of str

    Examples
    --------
    >>> from servofmu.physics.thermal.network import preset
    >>> "inner_ring_heat_fraction" in assumed_fields(preset("yu2017_gimbal_chamber"))
    True
    """
    return [f for f, source in p.provenance if "assumed" in source]


def thermal_notes(mechanism: Mechanism) -> list[str]:
    """What the mechanism's ThermalNetwork (:func:`thermal_parameters`) rests on, in short:
    its source, the materials' thermal properties taken from others, the fields that rest on
    assumed values (each value's provenance: the ThermalNetwork FMU of the build).

    Returns
    -------
    list of str
        One line each.

    Examples
    --------
    >>> thermal_notes(resolve(Defaults()))
    ['ThermalNetwork: the preset yu2017_gimbal_chamber (data/thermal.toml)']
    >>> thermal_notes(resolve(Defaults(mounting="yu2017_gimbal_spring")))[0][:57]
    "ThermalNetwork: derived from the mechanism's parts (beari"
    """
    if mechanism.mounting == DEFAULT_MOUNTING:
        return ["ThermalNetwork: the preset yu2017_gimbal_chamber (data/thermal.toml)"]
    p = thermal_parameters(mechanism)
    _, _, notes = _thermal_parts(mechanism)
    return [
        "ThermalNetwork: derived from the mechanism's parts (bearing, seats, loop lengths, "
        f"materials) in chamber air at {CHAMBER_AIR_SPEED[0]:g} m/s (assumed)",
        *(
            f"ThermalNetwork: {key}'s {', '.join(missing)} {why}"
            for key, (missing, why) in notes.items()
        ),
        f"ThermalNetwork: resting on assumed values: {', '.join(assumed_fields(p))} (each "
        f"value's provenance: the documentation of the ThermalNetwork FMU in "
        f"{mechanism.build_dir})",
    ]


def _reference_preload(mechanism: Mechanism) -> tuple[float, str]:
    """(preload [N], provenance) at which the ball contacts' conductance is evaluated."""
    mounting = catalog.mounting(mechanism.mounting)
    if mounting.assembly_preload:
        return mounting.assembly_preload, (
            mounting.source("assembly_preload") or "the mounting's assembly preload"
        )
    from servofmu.parameters.bearing import pair_from_parameters
    from servofmu.physics.bearing import BearingModel

    t0 = mounting.assembly_temperature
    preload = BearingModel(pair_from_parameters(mechanism.parameters())).evaluate(t0, 0.0).preload
    if preload > 0:
        return preload, f"derived: the library's preload at the assembly temperature {t0:g} K"
    return 1.0, (
        f"assumed: 1 N (the pair has no preload at the assembly temperature {t0:g} K: the "
        "ball contacts' conductance is a lower bound)"
    )


# ------------------------------------------------------------------ its systems' bindings
SSV_NS = "http://ssp-standard.org/SSP1/SystemStructureParameterValues"
SSD_NS = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription"}


def _components(system_dir: Path) -> dict[str, tuple[str, list[str]]]:
    """{component: (model identifier, its component-level .ssv sources)} of a system."""
    from .xmlsafe import parse

    ssd = Path(system_dir) / "SystemStructure.ssd"
    root = parse(ssd.read_bytes(), str(ssd))
    out = {}
    for comp in root.iterfind(".//ssd:Component", SSD_NS):
        sources = [b.get("source") for b in comp.iterfind(".//ssd:ParameterBinding", SSD_NS)]
        out[comp.get("name")] = (Path(comp.get("source")).stem, [s for s in sources if s])
    return out


def _thermal_value(name: str, value) -> tuple[str, str, str | None]:
    from servofmu.physics.thermal.network import ENVIRONMENTS

    if name == "environment":
        return "Integer", str(ENVIRONMENTS.index(value) + 1), value
    return "Real", repr(float(value)), None


def _rebind(root, values: dict, encode, comment: str) -> bytes:
    """The parameter set ``root`` with every parameter named in ``values`` set to its value
    (``encode(name, value)`` → element, text, description) and ``comment`` first."""
    from lxml import etree

    params = root.find(f"{{{SSV_NS}}}Parameters")
    for old in [c for c in params if isinstance(c, etree._Comment)]:
        params.remove(old)
    note = etree.Comment(f" {comment.replace('--', '- -')} ")
    note.tail = "\n    "
    params.insert(0, note)
    for prm in params.iterfind(f"{{{SSV_NS}}}Parameter"):
        name = prm.get("name")
        if name not in values:
            continue
        kind, text, description = encode(name, values[name])
        (old,) = list(prm)
        new = etree.SubElement(prm, f"{{{SSV_NS}}}{kind}", {"value": text})
        new.tail = old.tail
        prm.replace(old, new)
        if description is None:
            prm.attrib.pop("description", None)
        else:
            prm.set("description", description)
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8") + b"\n"


def bindings(mechanism: Mechanism, system_dir: Path) -> dict[str, bytes | None]:
    """The files of system ``system_dir`` that a build of ``mechanism`` changes, for
    :func:`.ssp.pack_ssp`: each BearingFriction binding with the mechanism's whole parameter
    set, each ThermalNetwork binding with :func:`thermal_parameters`, and None (left out)
    for a variant that binds the pair's own geometry, fits, loop or preload (anything but
    :data:`LUBRICANT_PARAMETERS`). Values the systems add (input start values, the
    temperature mode, the soak temperature) stay.

    Returns
    -------
    dict
        ``{path in the system: new bytes or None}``.

    Examples
    --------
    Yu's spring-preloaded gimbal in the speed-loop rig: its whole set bound, the variants of
    Yu's other mountings and interferences left out, those of the chamber temperature kept:

    >>> from servofmu.build.ssp import SSP_DIR
    >>> files = bindings(resolve(Defaults(mounting="yu2017_gimbal_spring")),
    ...                  SSP_DIR / "seeker_gimbal")
    >>> sorted(k for k, v in files.items() if v is None)[:2], "variants/cold.ssv" in files
    (['variants/interference_0006.ssv', 'variants/interference_0008.ssv'], False)
    >>> b'name="preload_method" description="spring"' in files["bearing.ssv"]
    True
    """
    from servofmu.parameter_sets import ssv_value

    from .xmlsafe import parse

    system_dir = Path(system_dir)
    components = _components(system_dir)
    bearings = {c for c, (model, _) in components.items() if model == "BearingFriction"}
    specs = {p.name: p for p in PARAMETERS}
    values = mechanism.parameters()
    files = ", ".join(f for f, _ in mechanism.catalogue_hashes) or "the package's catalogue"
    out: dict[str, bytes | None] = {}
    for model, sources in components.values():
        for source in sources:
            root = parse((system_dir / source).read_bytes(), source)
            if model == "BearingFriction":
                out[source] = _rebind(
                    root,
                    values,
                    lambda n, v: ssv_value(specs[n], v),
                    f"mechanism {mechanism.key}: mounting {mechanism.mounting}, lubricant "
                    f"{mechanism.lubricant} ({files}), its whole parameter set, bound by "
                    f"servofmu build; friction coefficients {mechanism.coefficients.label}",
                )
            elif model == "ThermalNetwork":
                p = thermal_parameters(mechanism)
                out[source] = _rebind(
                    root,
                    p.as_dict(),
                    _thermal_value,
                    f"mechanism {mechanism.key}: " + "; ".join(thermal_notes(mechanism)),
                )
    for variant in sorted(system_dir.glob("variants/*.ssv")):
        rel = variant.relative_to(system_dir).as_posix()
        root = parse(variant.read_bytes(), rel)
        for prm in root.iterfind(f".//{{{SSV_NS}}}Parameter"):
            comp, _, name = prm.get("name").partition(".")
            if comp in bearings and name in specs and name not in LUBRICANT_PARAMETERS:
                out[rel] = None  # it would bind the pair of another mounting
                break
    return out

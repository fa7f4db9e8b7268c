"""The friction models of a bearing pair, one line each: the one list that BearingFriction's
``friction_model`` enumeration, the parameter table, the pair's solvers (the exact path and
both per-step paths), the documentation and the scenarios read.

A model is its module (``servofmu.physics.friction.<name>`` for the built-in ones) and one
:class:`Entry` here. The module defines

- ``running_terms(pair, kinematic_viscosity, pitch_diameter, rolling, speed)`` → (viscous
  torque, sliding torque or None) [N·m], floats or arrays: the model's speed terms at ω
  [rad/s], from ν [m²/s], dm [m] and the data the entry asks the solver to gather
  (``rolling``, :attr:`Entry.data`); a sliding torque replaces the contacts' own;
- and, when :attr:`Entry.contact_terms` is False, ``starting_torque(pair, rolling)`` [N·m]:
  its torque at rest, in place of the contacts' Coulomb torque;
- with :attr:`Entry.data` "loads", ``rolling_loads(force_a, force_b, radial_load)``: its
  ``rolling`` from the bearings' axial forces and the external radial load [N];
- with :attr:`Entry.data` "contacts", ``contact_rolling_terms(load, semi_major_axis,
  ellipticity, e_integral, gamma, ball_diameter, pitch_diameter, inverse_conformity,
  compliance, dynamic_viscosity, inner)``: one loaded contact's five terms (floats or
  arrays), which the solvers gather for every loaded contact (the first times the ball's
  weight) into its ``rolling``;
- optionally ``check_numbers(friction)``: raise ValueError when the pair's
  :class:`~.models.FrictionModel` lacks a number the model needs;
- optionally its numbers in a :class:`~.models.FrictionModel` and their sources: ``NUMBERS``
  ({field: (default, source)}), ``bearing_numbers(bearing)`` and
  ``lubricant_numbers(lubricant)`` ({field: (value, source)} of catalogue records) and
  ``parameter_numbers(p)`` ({field: value} of a parameter set).

``docs/development.md`` ("A new friction model") gives the recipe.

Examples
--------
>>> names()
('yu2017', 'skf2004', 'ehl_per_contact')
>>> get("skf2004").data, get("skf2004").contact_terms
('loads', False)
"""

from __future__ import annotations

import importlib
import importlib.util
from dataclasses import dataclass

#: What the solvers can gather for a model's speed terms besides ν and dm: nothing, the
#: bearings' axial and radial loads (Fa,A, Fa,B, Fr) [N] (the module's ``rolling_loads``), or
#: the terms of every loaded contact (the module's ``contact_rolling_terms``).
DATA = ("", "loads", "contacts")


@dataclass(frozen=True)
class Entry:
    """One friction model.

    Attributes
    ----------
    name : the name users choose it by (``friction_model``; the FMU's enumeration item)
    module : its module, absolute or relative to :mod:`servofmu.physics.friction`
    description : one line: the enumeration item's description and the docs' table
    data : what its speed terms need (:data:`DATA`)
    contact_terms : whether Yu's hysteresis and spin (and Ning's sliding) per contact count
    palmgren : whether its viscous torque is Palmgren's (Yu 2017 eq 8) with the pair's s0,
        running and at rest (the compiled per-step path computes it in C)
    former_name : a name its module was importable by under :mod:`servofmu.physics`, and is
        still (:data:`servofmu.physics.MOVED`), or ""
    """

    name: str
    module: str
    description: str
    data: str = ""
    contact_terms: bool = True
    palmgren: bool = False
    former_name: str = ""

    def __post_init__(self):
        if self.data not in DATA:
            raise ValueError(f"data = {self.data!r} of friction model {self.name!r}: one of {DATA}")

    @property
    def module_name(self) -> str:
        """The absolute name of the model's module."""
        return importlib.util.resolve_name(self.module, __package__)

    def implementation(self):
        """The model's module (imported when first asked for)."""
        return importlib.import_module(self.module_name)


_MODELS: dict[str, Entry] = {}


def register(entry: Entry) -> Entry:
    """Add ``entry`` (its name not taken), after the models already listed (the FMU numbers its
    enumeration items in this order, from 1).

    Returns
    -------
    Entry
        ``entry``.

    Examples
    --------
    >>> register(Entry("skf2004", ".skf2004", "SKF 2004, again"))
    Traceback (most recent call last):
    ...
    ValueError: friction model 'skf2004' is registered already
    """
    if entry.name in _MODELS:
        raise ValueError(f"friction model {entry.name!r} is registered already")
    _MODELS[entry.name] = entry
    return entry


def unregister(name: str) -> None:
    """Remove the model ``name`` (a model a test or a user added).

    Returns
    -------
    None

    Examples
    --------
    >>> _ = register(Entry("constant", "toy_friction", "a constant torque"))
    >>> unregister("constant")
    >>> "constant" in names()
    False
    """
    del _MODELS[name]


def names() -> tuple[str, ...]:
    """The models' names, in order (the first is the default).

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> names()[0]
    'yu2017'
    """
    return tuple(_MODELS)


def listed(models: tuple[str, ...] | None = None, conjunction: str = "or") -> str:
    """``models`` (default: every model's name) as a phrase: "a, b or c" (or ``conjunction``).

    Returns
    -------
    str

    Examples
    --------
    >>> listed(("a", "b", "c")), listed(("a", "b"), "and"), listed(("a",))
    ('a, b or c', 'a and b', 'a')
    """
    models = names() if models is None else tuple(models)
    return f" {conjunction} ".join(filter(None, (", ".join(models[:-1]), *models[-1:])))


def entries() -> tuple[Entry, ...]:
    """The models, in order.

    Returns
    -------
    tuple of Entry

    Examples
    --------
    >>> [e.data for e in entries()]
    ['', 'loads', 'contacts']
    """
    return tuple(_MODELS.values())


def get(name: str) -> Entry:
    """The model called ``name``.

    Returns
    -------
    Entry

    Examples
    --------
    >>> get("ehl_per_contact").implementation().__name__
    'servofmu.physics.friction.ehl_per_contact'
    >>> get("yu2018")
    Traceback (most recent call last):
    ...
    ValueError: friction_model = 'yu2018' is not one of ('yu2017', 'skf2004', 'ehl_per_contact')
    """
    try:
        return _MODELS[name]
    except KeyError:
        raise ValueError(f"friction_model = {name!r} is not one of {names()}") from None


register(
    Entry(
        "yu2017",
        ".yu2017",
        "Yu 2017 eq 1-9: hysteresis, spin (and Ning's sliding) per contact + Palmgren's "
        "viscous torque s0·(ν·n)^(2/3)·dm³",
        palmgren=True,
    )
)
register(
    Entry(
        "skf2004",
        ".skf2004",
        "SKF 2004: φish·φrs·Mrr + Msl per bearing with its own axial and radial load "
        "(open, no oil bath)",
        data="loads",
        contact_terms=False,
        former_name="rolling_friction",
    )
)
register(
    Entry(
        "ehl_per_contact",
        ".ehl_per_contact",
        "Biboulet & Houpert 2010 hydrodynamic rolling torque of every ball-race contact + Yu's "
        "hysteresis and spin per contact",
        data="contacts",
        former_name="ehl_rolling",
    )
)

"""Attribute access compiled once per variable table: the per-step copies and checks of the
FMU runtime (:mod:`.runtime`) cost what the statements written out cost, not a loop of
``getattr``/``setattr``. Each factory checks that the names it compiles are identifiers, and
caches its function per table.
"""

from __future__ import annotations

import functools
import math


def _defined(source: str, names, **constants):
    """The one function ``source`` defines, compiled with ``constants`` as its globals, after
    checking that every name it is built from is an identifier (nothing else reaches exec)."""
    if not all(n.isidentifier() for n in names):
        raise ValueError(f"names must be identifiers: {names}")
    namespace = dict(constants)
    exec(source, namespace)  # the names checked above
    (function,) = (v for k, v in namespace.items() if k not in constants and k != "__builtins__")
    return function


@functools.cache
def copier(pairs: tuple[tuple[str, str], ...]):
    """A function ``copy(slave, record)`` doing ``slave.<name> = record.<field>`` for each
    (name, field) pair, compiled once from the map.

    Per step it costs what the assignments written out cost (0.4 µs for BearingFriction's 19
    outputs, against 4 µs for a setattr/getattr loop).

    Parameters
    ----------
    pairs : tuple of (output name, record field)

    Returns
    -------
    callable
        ``copy(slave, record) -> None``.

    Examples
    --------
    >>> from types import SimpleNamespace as NS
    >>> slave = NS()
    >>> copier((("stiffness", "total"),))(slave, NS(total=2.5))
    >>> slave.stiffness
    2.5
    """
    body = "".join(f"    slave.{n} = record.{f}\n" for n, f in pairs) or "    pass\n"
    return _defined(f"def copy(slave, record):\n{body}", [x for pair in pairs for x in pair])


@functools.cache
def setter(names: tuple[str, ...]):
    """A function ``assign(slave, values)`` doing ``slave.<names[i]> = values[i]`` in one
    statement (the values of one model call).

    Parameters
    ----------
    names : tuple of str, at least one

    Returns
    -------
    callable
        ``assign(slave, values) -> None``; ``values`` has exactly ``len(names)`` items.

    Examples
    --------
    >>> from types import SimpleNamespace as NS
    >>> slave = NS()
    >>> setter(("a", "b"))(slave, (1.0, 2.0))
    >>> slave.a, slave.b
    (1.0, 2.0)
    """
    if not names:
        raise ValueError("no names to assign")
    targets = ", ".join(f"slave.{n}" for n in names)
    return _defined(f"def assign(slave, values):\n    {targets}, = values\n", names)


@functools.cache
def getter(names: tuple[str, ...]):
    """A function ``values(slave)`` returning ``(slave.<names[0]>, …)``.

    Parameters
    ----------
    names : tuple of str

    Returns
    -------
    callable
        ``values(slave) -> tuple``.

    Examples
    --------
    >>> from types import SimpleNamespace as NS
    >>> getter(("b", "a"))(NS(a=1.0, b=2.0))
    (2.0, 1.0)
    """
    values = "".join(f"slave.{n}, " for n in names)
    return _defined(f"def values(slave):\n    return ({values})\n", names)


@functools.cache
def range_checker(checks: tuple[tuple[str, float, float], ...]):
    """A function ``ok(slave)``: True when every ``slave.<name>`` lies in [lo, hi] (NaN does
    not), compiled once (0.3 µs for BearingFriction's 8 inputs, against 1 µs for a loop).

    Parameters
    ----------
    checks : tuple of (name, lo, hi)

    Returns
    -------
    callable
        ``ok(slave) -> bool``.

    Examples
    --------
    >>> from types import SimpleNamespace as NS
    >>> ok = range_checker((("temperature", 173.15, 473.15),))
    >>> ok(NS(temperature=293.15)), ok(NS(temperature=float("nan")))
    (True, False)
    """
    tests = " and ".join(f"lo{i} <= slave.{n} <= hi{i}" for i, (n, _, _) in enumerate(checks))
    bounds = {}
    for i, (_, lo, hi) in enumerate(checks):
        bounds[f"lo{i}"], bounds[f"hi{i}"] = lo, hi
    source = f"def ok(slave):\n    return {tests or 'True'}\n"
    return _defined(source, [n for n, _, _ in checks], **bounds)


@functools.cache
def finite_checker(outputs: tuple[tuple[str, bool], ...]):
    """A function ``ok(slave)``: True when every ``slave.<name>`` is finite (+inf too where
    allowed), compiled once like :func:`range_checker`.

    Parameters
    ----------
    outputs : tuple of (name, allow_inf)

    Returns
    -------
    callable
        ``ok(slave) -> bool``.

    Examples
    --------
    >>> from types import SimpleNamespace as NS
    >>> ok = finite_checker((("stiffness", True), ("deflection", False)))
    >>> ok(NS(stiffness=math.inf, deflection=0.0)), ok(NS(stiffness=1.0, deflection=math.inf))
    (True, False)
    """
    tests = " and ".join(f"-inf < slave.{n} {'<=' if inf else '<'} inf" for n, inf in outputs)
    source = f"def ok(slave):\n    return {tests or 'True'}\n"
    return _defined(source, [n for n, _ in outputs], inf=math.inf)

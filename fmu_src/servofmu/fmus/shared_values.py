"""The Real values of an FMU instance in memory shared with servofmu's export library, so
that fmi2SetReal and fmi2GetReal are served without entering Python.

The slave allocates the block (a ``bytearray``); the export library (``build/export/``,
``SharedValues.hpp``) holds a buffer view of it for the instance's lifetime. It holds:

- a header of 32-bit integers (:data:`HEADER`): a magic number, the number of value
  references and of values, the FMI state the slave is in (an index of
  :data:`~.calls.PHASES`, -1: everything through Python), ``pending`` (the library wrote
  inputs the slave has not read yet) and ``dirty`` (inputs changed since the outputs were
  computed);
- every Real variable's value (doubles, native byte order): the inputs first, then the
  outputs, then the parameters, each group in declaration order;
- the range the library accepts for each value (inputs: their declared min/max; nothing
  else is written by it);
- the slot of each value reference (-1: not a Real);
- per FMI state and value reference, what the library may do without Python (:data:`SET`,
  :data:`GET`), and per state whether a dirty instance must compute before a read.

The tables are the slave's own rules (:mod:`.calls`, :mod:`.runtime`) written out once:

- fmi2SetReal is served when every reference is an input writable in the current state and
  every value is finite and within its input's range; the library then writes the values and
  sets ``pending`` and ``dirty``;
- fmi2GetReal is served when the state allows reading, every reference is a Real, no
  computation is due (an algebraic FMU with inputs changed, or any FMU in initialization
  mode with inputs changed, computes first) and every value is finite;
- anything else (an unknown reference, a parameter, another state, a value out of range or
  not finite, a non-finite output) goes to the slave in Python, which stays the one authority
  on the state machine, the checks and the messages: a call served by the library is one the
  slave would have answered with fmi2OK and the same values.

The slave keeps its values in attributes (the physics reads them there): every FMI call that
enters Python first reads the pending inputs (:meth:`SharedValues.pull`) and, before it
returns, writes back what it may have changed (:meth:`SharedValues.push`): the header always,
and the values of the groups the call can change. fmi2DoStep is then the one crossing per
step of a host that sets inputs and gets outputs.

A model with a compiled step on the block (:mod:`servofmu.physics.shared_step`, the slave's
``shared_step``) takes that crossing in compiled code: its step reads the inputs from the
block and writes the outputs to it, and marks the header ``stale``; the slave's attributes,
its time and its model's state are read back from it (:meth:`SharedValues.pull`) before any
later call enters Python. Whatever the slave does in Python then re-arms it or not
(:meth:`SharedValues.push`).
"""

from __future__ import annotations

import math
import os
import struct

from . import accessors
from .calls import INITIALIZATION, PHASES, READABLE, STEP_COMPLETE

#: Identifies the block's layout (the export library refuses another one).
MAGIC = 0x53465631  # "SFV1"
#: The header's 32-bit integers, in order.
HEADER = ("magic", "n_references", "n_values", "phase", "pending", "dirty", "n_phases", "stale")
#: Access bits of a value reference in a state.
SET, GET = 1, 2
#: Groups of values a call may change (what :meth:`SharedValues.push` writes back).
INPUTS, OUTPUTS, PARAMETERS = 1, 2, 4
ALL = INPUTS | OUTPUTS | PARAMETERS
#: Set to "0" to keep every FMI call in Python (a run without the shared values).
ENVIRONMENT = "SERVOFMU_SHARED_VALUES"

_PHASE = HEADER.index("phase")
_PENDING = HEADER.index("pending")
_DIRTY = HEADER.index("dirty")
_STALE = HEADER.index("stale")


def wanted() -> bool:
    """Whether a slave shares its values with an export library that can (not when the
    environment variable :data:`ENVIRONMENT` is "0").

    Returns
    -------
    bool

    Examples
    --------
    >>> isinstance(wanted(), bool)
    True
    """
    return os.environ.get(ENVIRONMENT, "1") != "0"


def layout(variables) -> tuple[list, list, list]:
    """The Real variables in the order of the value block: inputs, outputs, parameters.

    Parameters
    ----------
    variables : the slave's :class:`~.declarations.Var`, in value-reference order

    Returns
    -------
    tuple of list
        (inputs, outputs, parameters), each a list of (value reference, Var).

    Examples
    --------
    >>> from servofmu.fmus.declarations import output, real_input
    >>> u = real_input("u", "an input", start=0.0)
    >>> y = output("y", "an output", initial_depends=("u",))
    >>> [[vr for vr, _ in group] for group in layout((y, u))]
    [[1], [0], []]
    """
    groups = {"input": [], "output": [], "parameter": []}
    for vr, v in enumerate(variables):
        if v.type == "Real":
            groups[v.causality].append((vr, v))
    return groups["input"], groups["output"], groups["parameter"]


class SharedValues:
    """The block shared with the export library for one slave instance (module docstring).

    Parameters
    ----------
    variables : the slave's variables, in value-reference order
    feedthrough : whether the slave is algebraic (its outputs are computed from the inputs
        before they are read)
    writable : {FMI state: {value reference: name}} of Real variables the slave's fmi2SetReal
        accepts in each state

    Examples
    --------
    >>> from types import SimpleNamespace as NS
    >>> from servofmu.fmus.declarations import output, real_input
    >>> u = real_input("u", "an input", start=1.0, min=0.0, max=2.0)
    >>> y = output("y", "an output", initial_depends=("u",))
    >>> shared = SharedValues((u, y), True, {STEP_COMPLETE: {0: "u"}})
    >>> slave = NS(u=1.0, y=0.5, _phase=STEP_COMPLETE, _dirty=False, _checked=None)
    >>> shared.push(slave, ALL)
    >>> shared.values()
    [1.0, 0.5]
    """

    def __init__(self, variables, feedthrough: bool, writable: dict):
        inputs, outputs, parameters = layout(variables)
        order = [*inputs, *outputs, *parameters]
        n_refs, n = len(variables), len(order)
        slot = {vr: k for k, (vr, _) in enumerate(order)}
        #: {Real variable's name: its position in the value block}
        self.slots = {v.name: k for k, (_, v) in enumerate(order)}
        self._sizes = (n, len(inputs))
        ranges = [(v.min, v.max) if v.causality == "input" else (None, None) for _, v in order]
        access = [
            (SET if v.causality == "input" and vr in writable.get(phase, {}) else 0)
            | (GET if phase in READABLE else 0)
            if v.type == "Real"
            else 0
            for phase in PHASES
            for vr, v in enumerate(variables)
        ]
        fresh = [
            phase == INITIALIZATION or (feedthrough and phase == STEP_COMPLETE) for phase in PHASES
        ]
        blocks = (  # (struct format, contents) in the order of the block
            (f"{len(HEADER)}i", (MAGIC, n_refs, n, -1, 0, 1, len(PHASES), 0)),
            (f"{n}d", [0.0] * n),
            (f"{n}d", [-math.inf if lo is None else lo for lo, _ in ranges]),
            (f"{n}d", [math.inf if hi is None else hi for _, hi in ranges]),
            (f"{n_refs}i", [slot.get(vr, -1) for vr in range(n_refs)]),
            (f"{len(access)}B", access),
            (f"{len(fresh)}B", fresh),
        )
        self.buffer = bytearray(sum(struct.calcsize(f"={f}") for f, _ in blocks))
        offset = 0
        for fmt, contents in blocks:
            struct.pack_into(f"={fmt}", self.buffer, offset, *contents)
            offset += struct.calcsize(f"={fmt}")
        start = struct.calcsize(f"={len(HEADER)}i")
        self._ints = memoryview(self.buffer)[:start].cast("i")
        self._all = (struct.Struct(f"={n}d"), start)
        self._codes = {phase: k for k, phase in enumerate(PHASES)}
        packers, first = {}, 0
        for group, members in ((INPUTS, inputs), (OUTPUTS, outputs), (PARAMETERS, parameters)):
            names = tuple(v.name for _, v in members)
            if names:  # (packer, offset, the slave's values, their assignment)
                packers[group] = (
                    struct.Struct(f"={len(names)}d"),
                    start + 8 * first,
                    accessors.getter(names),
                    accessors.setter(names),
                )
            first += len(names)
        self._inputs = packers.get(INPUTS)
        self._outputs = packers.get(OUTPUTS)
        #: the compiled step on the block (:meth:`attach_step`), or None
        self.step = None
        #: per combination of groups, what push writes: (group, pack_into, offset, values)
        self._pushers = [
            tuple(
                (g, packers[g][0].pack_into, packers[g][1], packers[g][2])
                for g in (INPUTS, OUTPUTS, PARAMETERS)
                if groups & g and g in packers
            )
            for groups in range(ALL + 1)
        ]

    def pull(self, slave) -> None:
        """Read the inputs the export library wrote into the slave's attributes (the slave is
        then dirty), if it wrote any.

        Parameters
        ----------
        slave : the slave instance

        Returns
        -------
        None
        """
        ints = self._ints
        if ints[_STALE]:
            self._read_steps(slave)
        if ints[_PENDING]:
            self._assign(slave, self._inputs)
            slave._dirty = True
            ints[_PENDING] = 0

    def push(self, slave, groups: int) -> None:
        """Write the slave's state, dirty flag and the values of ``groups`` to the block;
        should that fail (a value that is not a number), every later call goes through
        Python (:meth:`stop`).

        Parameters
        ----------
        slave : the slave instance (``_phase``, ``_dirty``, the variables' attributes, and
            ``_checked``: its Real outputs as it checked them during the call, or None)
        groups : :data:`INPUTS`, :data:`OUTPUTS`, :data:`PARAMETERS`, or'ed

        Returns
        -------
        None
        """
        try:
            buffer, checked = self.buffer, slave._checked
            slave._checked = None
            for group, pack_into, offset, values in self._pushers[groups]:
                if group == OUTPUTS and checked is not None:  # the outputs, just checked
                    pack_into(buffer, offset, *checked)
                else:
                    pack_into(buffer, offset, *values(slave))
            ints = self._ints
            ints[_DIRTY] = 1 if slave._dirty else 0
            ints[_PHASE] = self._codes.get(slave._phase, -1)
            if self.step is not None:
                self._arm(slave)
        except Exception:
            self.stop()

    def attach_step(self, make, stepped: bool, fallback, failed) -> None:
        """Take fmi2DoStep in compiled code (:mod:`servofmu.physics.shared_step`): ``make``
        builds the model's :class:`~servofmu.physics.shared_step.SharedStep` from its
        arguments, ``fallback(t, h)`` is the slave's own step and ``failed(exc)`` its answer
        to an exception in the compiled one. Armed by :meth:`push` whenever the slave's
        ``_bind_shared_step`` agrees.

        Returns
        -------
        None
        """
        n, n_inputs = self._sizes
        code = self._codes[STEP_COMPLETE]
        self.step = make(self.buffer, n, n_inputs, code, stepped, fallback, failed)

    def _arm(self, slave) -> None:
        """Arm the compiled step when the slave, as it is now, would take a step in its
        state, configured, from a known time, and its model can (``_bind_shared_step``)."""
        step = self.step
        if (
            slave._phase == STEP_COMPLETE
            and slave._configured
            and slave._time is not None
            and slave._bind_shared_step(step)
        ):
            step.arm(slave._time)
        else:
            step.disarm()

    def _read_steps(self, slave) -> None:
        """Bring the slave up to the steps taken in compiled code: its inputs and outputs
        from the block, its time, its dirty flag and its model's state (``_read_shared_step``)."""
        self._assign(slave, self._inputs)
        self._assign(slave, self._outputs)
        ints = self._ints
        slave._dirty = bool(ints[_DIRTY])
        slave._time = self.step.time
        slave._read_shared_step(self.step)
        ints[_STALE] = 0

    def _assign(self, slave, packer) -> None:
        """Set the slave's attributes of one group of values from the block (``packer``: the
        group's (packer, offset, getter, setter); None: an empty group)."""
        if packer is not None:
            values, offset, _, assign = packer
            assign(slave, values.unpack_from(self.buffer, offset))

    def stop(self) -> None:
        """Send every later call through Python (the state code -1).

        Returns
        -------
        None
        """
        self._ints[_PHASE] = -1

    def values(self) -> list[float]:
        """The value block, in its order (inputs, outputs, parameters).

        Returns
        -------
        list of float
        """
        packer, offset = self._all
        return list(packer.unpack_from(self.buffer, offset))

# cython: language_level=3, auto_pickle=False, embedsignature=False
"""An FMU's fmi2DoStep over the values it shares with servofmu's export library, in one call
of compiled code: the one crossing into Python per step of a host that sets inputs and gets
outputs through the library (the block's layout: :mod:`servofmu.fmus.shared_values`).

:class:`SharedStep` keeps the rules of the slave's step that do not depend on the model (the
FMI state, the communication point and step size, the inputs' ranges) and asks its model's
subclass to :meth:`~SharedStep.advance` on the block: read the inputs, step, and write the
outputs, or decline having changed nothing the slave's own step would not repeat (a model may
have solved its state at the new inputs: a model that keeps its last answer gives the slave's
step the same one; the block's outputs it wrote are the slave's to overwrite).

A step it takes is one the slave's Python path would have taken with fmi2OK and the same
values; any other call (the first step, a step size that is not finite, an input out of
range, a model's warning or failure to come) goes to the slave's own ``do_step``
(``fallback``), the one authority on the state machine, the checks and the messages. The
slave reads what the steps taken here changed before any later call enters Python (the
header's ``stale``, :meth:`.shared_values.SharedValues.pull`).

Written in Cython's pure-Python mode; the build compiles it (:mod:`servofmu.physics.compiled`).

Examples
--------
>>> import struct
>>> block = bytearray(struct.pack("=8i6d", 0, 0, 2, 2, 1, 1, 0, 0, 3.0, 0.0, 0, 0, 10, 0))
>>> class Doubling(SharedStep):  # one input (slot 0), one output (slot 1): y = 2u
...     def advance(self, t, h):
...         self.values[1] = 2.0 * self.values[0]
...         return True
>>> s = Doubling(block, 2, 1, 2, True, lambda t, h: "Python's step", None)
>>> s.arm(0.0)
>>> s.step(0.0, 0.1), s.time, list(s.values)
(True, 0.1, [3.0, 6.0])
>>> s.step(0.0, 0.1)  # does not continue the last step: the slave's Python path answers
"Python's step"
"""

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from .kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import fabs, isfinite
else:
    from math import fabs, isfinite

#: The header's 32-bit integers in the block (:data:`servofmu.fmus.shared_values.HEADER`).
HEADER_SIZE = 8
#: Positions in the header: the slave's FMI state, inputs written and not read, inputs
#: changed since the outputs were computed, steps taken here that the slave has not read.
PHASE, PENDING, DIRTY, STALE = 3, 4, 5, 7


@cython.cclass
class SharedStep:
    """fmi2DoStep of one slave instance over its block of shared values.

    Parameters
    ----------
    block : the block (a writable buffer in the layout of :mod:`servofmu.fmus.shared_values`)
    n_values : number of Real values in the block
    n_inputs : number of inputs (the first values)
    phase : the header's code of the state in which steps are taken (step complete)
    stepped : whether each step must continue the last one (False: an algebraic FMU, whose
        outputs are then current and its inputs no longer dirty)
    fallback : ``fallback(t, h)``, the slave's own fmi2DoStep, for every step not taken here
    failed : ``failed(exc)``, the slave's answer to an exception raised by :meth:`advance`
        (its Python path's, for an exception in the middle of a step)
    """

    def __init__(
        self,
        block,
        n_values: cython.Py_ssize_t,
        n_inputs: cython.Py_ssize_t,
        phase: cython.int,
        stepped: cython.bint,
        fallback,
        failed,
    ):
        view = memoryview(block)
        head: cython.Py_ssize_t = 4 * HEADER_SIZE
        self.header = view[:head].cast("i")
        self.values = view[head : head + 8 * n_values].cast("d")
        self.lo = view[head + 8 * n_values : head + 16 * n_values].cast("d")
        self.hi = view[head + 16 * n_values : head + 24 * n_values].cast("d")
        self.n_inputs = n_inputs
        self.phase = phase
        self.stepped = stepped
        self.fallback = fallback
        self.failed = failed
        self.armed = False
        self.time = 0.0

    @cython.ccall
    def arm(self, time: cython.double):
        """Take steps here from now on, the next one from ``time`` [s]."""
        self.time = time
        self.armed = True

    @cython.ccall
    def disarm(self):
        """Send every step to the slave's Python path until :meth:`arm` is called."""
        self.armed = False

    @cython.ccall
    def step(self, t: cython.double, h: cython.double):
        """fmi2DoStep(``t`` [s], ``h`` [s]): True when taken here, else the fallback's answer."""
        k: cython.Py_ssize_t
        x: cython.double
        if not (self.armed and self.header[PHASE] == self.phase and isfinite(t)):
            return self.fallback(t, h)
        if not (0.0 < h and isfinite(h)):
            return self.fallback(t, h)
        if self.stepped and fabs(t - self.time) > 1e-9 * max(fabs(t), fabs(self.time), h):
            return self.fallback(t, h)
        for k in range(self.n_inputs):
            x = self.values[k]
            if not (self.lo[k] <= x <= self.hi[k]):  # NaN fails too
                return self.fallback(t, h)
        try:
            taken: cython.bint = self.advance(t, h)
        except BaseException as exc:  # the model's failure mid-step: the slave's answer
            self.armed = False
            self.header[STALE] = 1
            return self.failed(exc)
        if not taken:
            return self.fallback(t, h)
        self.header[PENDING] = 0  # the inputs were read here
        if not self.stepped:
            self.header[DIRTY] = 0
        self.header[STALE] = 1
        self.time = t + h
        return True

    @cython.cfunc
    def temperatures(self, slots: tuple):
        """The parts' temperatures [K] as the physics takes them from the inputs at ``slots``
        (servofmu.fmus.part_temperatures: 1 slot, the uniform temperature, a float; 2, the
        housing's and the shaft's, (h, s, h, s); 4, the parts')."""
        values = self.values
        k: cython.Py_ssize_t = slots[0]
        if len(slots) == 1:
            return values[k]
        j: cython.Py_ssize_t = slots[1]
        if len(slots) == 2:
            return (values[k], values[j], values[k], values[j])
        m: cython.Py_ssize_t = slots[2]
        n: cython.Py_ssize_t = slots[3]
        return (values[k], values[j], values[m], values[n])

    @cython.cfunc
    def inputs_changed(self) -> cython.bint:
        """Whether the inputs changed since the outputs were computed (during
        :meth:`advance`: before this step)."""
        return self.header[DIRTY] != 0

    @cython.cfunc
    def advance(self, t: cython.double, h: cython.double) -> cython.bint:
        """The model's step from ``t`` [s] over ``h`` [s] on the block: read the inputs, step,
        write the outputs and return True; or return False having changed nothing that the
        slave's Python path, which then takes the step, would not repeat (module docstring).
        The base class declines every step."""
        return False

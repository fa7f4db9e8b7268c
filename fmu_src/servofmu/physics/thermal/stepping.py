# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The per-step arithmetic of the thermal network (:mod:`.network`), written in Cython's
pure-Python mode: the rates dT/dt of every node and the exponential step
T(t + h) = T(t) + h·φ1(hJ)·f(T(t)) on floats. The exact path of :mod:`.network` and the
ThermalNetwork FMU run these functions; the build compiles them (:mod:`servofmu.physics.compiled`).

Sums are taken left to right from 0.0, as ``sum`` does on floats before Python 3.12, and the
fourth powers by C's ``pow``, as Python's ``**`` does: both implementations give the same bits.

The coefficients ``terms`` are ``network._terms``: (rows of A = −C⁻¹K [1/s], ambient G/C
[1/s], heat split s/C [K/J], sink σεA/C [1/(s·K³)], exchange ((i, j, σ𝓔/C_i, σ𝓔/C_j), ...)).

Examples
--------
>>> terms = (((-0.2,),), (0.2,), (0.1,), (0.0,), ())  # one node: C = 10 J/K, G = 2 W/K
>>> rates(terms, [300.0], 290.0, 0.0, 5.0)  # K/s: (2·(290 − 300) + 5)/10
[-1.5]
"""

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import isfinite, pow
    from cython.cimports.servofmu.physics._shared_step import SharedStep
else:
    from math import isfinite, pow

    from ..shared_step import SharedStep


@cython.ccall
def rates(
    terms: tuple, t, ambient: cython.double, sink: cython.double, power: cython.double
) -> list:
    """dT/dt [K/s] of every node at node temperatures ``t`` [K], ambient and sink
    temperatures [K] and heat input ``power`` [W] (:mod:`.network`'s energy balance).

    Returns
    -------
    list of float
        dT/dt [K/s] per node.

    Examples
    --------
    >>> rates((((-0.2,),), (0.2,), (0.1,), (0.0,), ()), [300.0], 290.0, 0.0, 5.0)
    [-1.5]
    """
    rows: tuple = terms[0]
    amb: tuple = terms[1]
    split: tuple = terms[2]
    sink_k: tuple = terms[3]
    n: cython.Py_ssize_t = len(rows)
    k: cython.Py_ssize_t
    j: cython.Py_ssize_t
    i: cython.Py_ssize_t
    acc: cython.double
    a: cython.double
    x: cython.double
    q: cython.double
    row: tuple
    e: tuple
    out: list = [0.0] * n
    for k in range(n):
        row = rows[k]
        acc = 0.0
        for j in range(n):
            a, x = row[j], t[j]
            acc += a * x
        a, x = amb[k], split[k]
        out[k] = acc + a * ambient + x * power
    s4: cython.double = pow(sink, 4.0)
    for k in range(n):
        a = sink_k[k]
        if a:
            acc, x = out[k], t[k]
            out[k] = acc - a * (pow(x, 4.0) - s4)
    for e in terms[4]:
        i, j = e[0], e[1]
        acc, x = t[i], t[j]
        q = pow(acc, 4.0) - pow(x, 4.0)
        acc, x = out[i], out[j]
        a = e[2]
        out[i] = acc - a * q
        a = e[3]
        out[j] = x + a * q
    return out


@cython.ccall
def exponential_step(m: tuple, t, f: list) -> list:
    """T + M·f: node temperatures [K] after a step from ``t`` [K] with the propagator
    ``m`` = h·φ1(hJ) [s] (rows, :func:`.network.propagator`) and the rates ``f`` [K/s].

    Returns
    -------
    list of float
        [K] per node.

    Examples
    --------
    >>> exponential_step(((2.0,),), [300.0], [-1.5])
    [297.0]
    """
    n: cython.Py_ssize_t = len(m)
    k: cython.Py_ssize_t
    j: cython.Py_ssize_t
    acc: cython.double
    row: tuple
    out: list = [0.0] * n
    a: cython.double
    x: cython.double
    for k in range(n):
        row = m[k]
        acc = 0.0
        for j in range(n):
            a, x = row[j], f[j]
            acc += a * x
        x = t[k]
        out[k] = x + acc
    return out


@cython.final
@cython.cclass
class NetworkStepper:
    """The ThermalNetwork FMU's step in one call: re-linearisation of radiation, the
    propagator of the step (kept while the step size and the reference stay), rates, step, and
    the checks of the new temperatures.

    Parameters
    ----------
    terms : the network's coefficients (``network._terms``)
    radiating : whether the network radiates (radiation is linearised about a reference)
    propagate : ``propagate(h, reference)`` → h·φ1(hJ) (:func:`.network.propagator`)

    Examples
    --------
    >>> s = NetworkStepper((((-0.2,),), (0.2,), (0.1,), (0.0,), ()), False, lambda h, r: ((2.0,),))
    >>> s.advance((300.0,), 290.0, 0.0, 5.0, 1.0, None, 0.1, 200.0, 400.0)
    ([297.0], None, -1, False)
    """

    def __init__(self, terms: tuple, radiating: cython.bint, propagate):
        self.terms = terms
        self.radiating = radiating
        self.propagate = propagate
        self.step = 0.0
        self.reference = None
        self.matrix = None

    @cython.ccall
    def advance(
        self,
        t: tuple,
        ambient: cython.double,
        sink: cython.double,
        power: cython.double,
        h: cython.double,
        reference,
        tolerance: cython.double,
        lo: cython.double,
        hi: cython.double,
    ) -> tuple:
        """One step of ``h`` [s] from the node temperatures ``t`` [K] (inputs as
        :func:`rates`). Radiation is linearised about ``reference`` [K] (a tuple; None: not
        yet), renewed at ``t`` once a node has moved more than ``tolerance`` [K] from it.

        Returns
        -------
        tuple
            (new temperatures [K] (list), the reference used (None without radiation), the
            first node whose new temperature is not finite and > 0 K (−1: none), whether a new
            temperature lies outside [``lo``, ``hi``] [K]).
        """
        n: cython.Py_ssize_t = len(t)
        k: cython.Py_ssize_t
        x: cython.double
        y: cython.double
        if not self.radiating:
            reference = None
        elif reference is None:
            reference = t
        else:
            for k in range(n):
                x, y = t[k], reference[k]
                if abs(x - y) > tolerance:
                    reference = t
                    break
        if self.matrix is None or h != self.step or reference is not self.reference:
            self.matrix = self.propagate(h, reference)
            self.step = h
            self.reference = reference
        new: list = exponential_step(self.matrix, t, rates(self.terms, t, ambient, sink, power))
        bad: cython.Py_ssize_t = -1
        outside: cython.bint = False
        for k in range(n):
            x = new[k]
            if not (isfinite(x) and x > 0.0):
                bad = k
                break
            if not (lo <= x <= hi):
                outside = True
        return new, reference, bad, outside


@cython.final
@cython.cclass
class NetworkSharedStep(SharedStep):
    """The ThermalNetwork FMU's step on its block of shared values
    (:class:`~servofmu.physics.shared_step.SharedStep`): :meth:`NetworkStepper.advance` from
    the part temperatures in the block (its outputs, the network's state), the inputs read
    from it and the new temperatures written to it; a step that leaves a temperature not
    finite and > 0 K, or outside the valid range, is declined (the slave's Python path takes
    it: its message, its warning).

    :meth:`bind` gives it the slave's stepper, parameters and slots before it is armed;
    ``reference`` is the temperatures [K] about which radiation is linearised (the slave's
    own, read back when it next enters Python).
    """

    def bind(
        self,
        stepper: NetworkStepper,
        reference,
        tolerance: cython.double,
        lo: cython.double,
        hi: cython.double,
        inputs: tuple,
        parts: tuple,
    ):
        """The slave's ``stepper``, radiation's ``reference`` (a tuple [K] or None), the
        linearisation ``tolerance`` [K], the valid range [``lo``, ``hi``] [K], the slots of the
        inputs (ambient temperature, sink temperature, power loss) and of the parts."""
        self.stepper = stepper
        self.reference = reference
        self.tolerance, self.lowest, self.highest = tolerance, lo, hi
        self.ambient, self.sink, self.power = inputs[0], inputs[1], inputs[2]
        self.parts = parts

    @cython.cfunc
    def advance(self, t: cython.double, h: cython.double) -> cython.bint:
        values = self.values
        k: cython.Py_ssize_t
        j: cython.Py_ssize_t
        n: cython.Py_ssize_t = len(self.parts)
        state: list = [0.0] * n
        for k in range(n):
            j = self.parts[k]
            state[k] = values[j]
        new: list
        bad: cython.Py_ssize_t
        outside: cython.bint
        new, reference, bad, outside = self.stepper.advance(
            tuple(state),
            values[self.ambient],
            values[self.sink],
            values[self.power],
            h,
            self.reference,
            self.tolerance,
            self.lowest,
            self.highest,
        )
        if bad >= 0 or outside:
            return False
        self.reference = reference
        for k in range(n):
            j = self.parts[k]
            values[j] = new[k]
        return True

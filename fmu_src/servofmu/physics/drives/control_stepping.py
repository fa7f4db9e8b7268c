# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The ServoController FMU's step on the values it shares with servofmu's export
(:class:`~servofmu.physics.shared_step.SharedStep`), written in Cython's pure-Python mode; the
build compiles it (:mod:`servofmu.physics.compiled`).

The samples due within the step, at t0 + k·Ts in [t, t + h) with the inputs held, each one
:func:`.control.pid_sample` (the slave's function); the command of the last one written to
the block. A step holding more samples than the slave allows, or giving a command that is not
finite, is declined (the slave's message).
"""

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc.math import ceil, isfinite
    from cython.cimports.servofmu.physics._shared_step import SharedStep
else:
    from math import ceil, isfinite

    from ..shared_step import SharedStep


@cython.final
@cython.cclass
class ControllerSharedStep(SharedStep):
    """ServoController's step on its block (module docstring); the slave reads back ``pid``
    and ``next_sample``."""

    def bind(
        self,
        params,
        sample,
        pid,
        next_sample: cython.longlong,
        start: cython.double,
        most: cython.longlong,
        inputs: tuple,
        command: cython.Py_ssize_t,
    ):
        """The controller's ``params`` (PIDParameters), ``sample`` (:func:`.control.pid_sample`),
        its state ``pid`` (PIDState) and the index of its next sample; the start time t0 [s];
        the most samples of a step; the slots of the inputs (reference, measurement) and of
        the command."""
        self.params, self.sample, self.pid = params, sample, pid
        self.next_sample = next_sample
        self.start = start
        self.period = params.sample_period
        self.most = most
        self.reference, self.measurement = inputs[0], inputs[1]
        self.command = command

    @cython.cfunc
    def advance(self, t: cython.double, h: cython.double) -> cython.bint:
        values = self.values
        ts: cython.double = self.period
        end: cython.double = t + h
        # the first sample not due (compiled, ceil gives a C double: int() as in Python)
        last: cython.longlong = int(ceil((end - 1e-9 * ts - self.start) / ts))  # noqa: RUF046
        due: cython.longlong = last - self.next_sample
        if due > self.most:
            return False
        reference: cython.double = values[self.reference]
        measurement: cython.double = values[self.measurement]
        pid = self.pid
        command = values[self.command]
        _k: cython.longlong
        for _k in range(max(0, due)):
            command, pid = self.sample(self.params, pid, reference, measurement)
        if not isfinite(command):
            return False
        values[self.command] = command
        self.pid = pid
        self.next_sample = max(self.next_sample, last)
        return True

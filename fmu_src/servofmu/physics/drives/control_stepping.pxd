# Declarations of control_stepping.py for its compilation.
cimport cython

from servofmu.physics._shared_step cimport SharedStep


@cython.final
cdef class ControllerSharedStep(SharedStep):
    cdef object params, sample
    cdef readonly object pid
    cdef readonly long long next_sample
    cdef double start, period
    cdef long long most
    cdef Py_ssize_t reference, measurement, command

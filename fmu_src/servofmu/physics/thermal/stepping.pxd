# Declarations of stepping.py for its compilation.
cimport cython

from servofmu.physics._shared_step cimport SharedStep

cpdef list rates(tuple terms, object t, double ambient, double sink, double power)
cpdef list exponential_step(tuple m, object t, list f)


@cython.final
cdef class NetworkStepper:
    cdef readonly tuple terms
    cdef readonly bint radiating
    cdef readonly object propagate
    cdef double step
    cdef object reference
    cdef tuple matrix
    cpdef tuple advance(
        self, tuple t, double ambient, double sink, double power, double h, object reference,
        double tolerance, double lo, double hi)


@cython.final
cdef class NetworkSharedStep(SharedStep):
    cdef NetworkStepper stepper
    cdef public object reference
    cdef double tolerance, lowest, highest
    cdef Py_ssize_t ambient, sink, power
    cdef tuple parts

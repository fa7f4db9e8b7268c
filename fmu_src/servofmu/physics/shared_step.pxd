# Declarations of shared_step.py for its compilation.
cimport cython

cdef Py_ssize_t HEADER_SIZE, PHASE, PENDING, DIRTY, STALE


cdef class SharedStep:
    cdef int[::1] header
    cdef double[::1] values, lo, hi
    cdef Py_ssize_t n_inputs
    cdef int phase
    cdef bint stepped
    cdef object fallback, failed
    cdef public bint armed
    cdef public double time
    cpdef arm(self, double time)
    cpdef disarm(self)
    cpdef step(self, double t, double h)
    cdef object temperatures(self, tuple slots)
    cdef bint inputs_changed(self)
    cdef bint advance(self, double t, double h)

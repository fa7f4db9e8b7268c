# Declarations of stepping.py for its compilation.
cimport cython

from servofmu.physics._shared_step cimport SharedStep
from servofmu.physics.pair._point cimport PointState


cpdef int flag_bits(tuple flags)


@cython.final
cdef class PairSharedStep(SharedStep):
    cdef object model, solver, rest_stiffness, below_flow
    cdef tuple temperature_slots, state_outputs, speed_slots, prerolling_slots
    cdef int flags
    cdef Py_ssize_t axial, radial, speed
    cdef readonly object point
    cdef bint checked_flow, prerolling
    cdef double stiffness, stribeck, exponent, lowest, highest
    cdef readonly double sigma0, excess, coulomb, prerolling_angle, prerolling_torque
    cdef _update(self, tuple point)
    cdef _write_state(self, PointState s)
    cdef _put(self, Py_ssize_t slot, double x)
    cdef bint _keeps_flags(self, PointState s, object temps)
    cdef bint _roll(self, object state, object point, double speed, double h)

# Declarations of stepping.py for its compilation.
cimport cython

from servofmu.physics._shared_step cimport SharedStep


@cython.final
cdef class PairSharedStep(SharedStep):
    cdef object model, solver, rest_stiffness, below_flow
    cdef tuple temperature_slots, state_outputs, speed_slots, flags, prerolling_slots
    cdef Py_ssize_t axial, radial, speed
    cdef readonly object point
    cdef bint checked_flow, prerolling
    cdef double stiffness, stribeck, exponent
    cdef readonly double sigma0, excess, coulomb, prerolling_angle, prerolling_torque
    cdef bint _keeps_flags(self, object state, object temps)
    cdef bint _roll(self, object state, object point, double speed, double h)

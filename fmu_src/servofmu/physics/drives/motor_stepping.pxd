# Declarations of motor_stepping.py for its compilation.
cimport cython

from servofmu.physics._shared_step cimport SharedStep

cpdef tuple friction_substeps(
    tuple phi, tuple gamma, double current, double speed, double angle, double voltage,
    double load_torque, int substeps, double running_friction, double breakaway_friction)


@cython.final
cdef class MotorSharedStep(SharedStep):
    cdef object params, plain, with_friction
    cdef double torque_constant, substep, most
    cdef tuple ranges, inputs, outputs

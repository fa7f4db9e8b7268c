# Declarations of stepping.py for its compilation.
cimport cython

from servofmu.physics._shared_step cimport SharedStep

# the module's constants, as C values (its _NAME: cython.<type> = ... lines)
cdef double _SMALLEST_MOMENT, _SMALLEST_SCREW_FORCE, _INF

cdef double _compliance(double k, int i)


@cython.final
cdef class Linkage:
    cdef readonly double l1, l2, y1, e, crank_area, rod_area, arm_length
    cdef readonly double torsional, arm_squared, bending, l1_squared, l2_squared
    cpdef double sin_rod_angle(self, double theta)
    cpdef double nut_position(self, double theta, double gamma)
    cpdef double lever(self, double theta, double gamma)
    cpdef double transmission_angle(self, double theta, double gamma)
    cpdef double reach_cosine(self, double x_nut)
    cpdef double crank_angle(self, double x_nut, double branch)
    cpdef double rod_cosine(self, double x_nut, double theta)
    cpdef double rotation(self, double theta, double beta, double x_nut, double m)


@cython.final
cdef class ActuatorStepper:
    cdef readonly Linkage linkage
    cdef readonly double theta0, gear_ratio, gear_factor, screw_ratio
    cdef readonly double gear_stiffness, screw_stiffness, housing_stiffness, seat_stiffness
    cdef readonly object support
    cdef readonly double x0, motor_per_metre, branch
    cdef readonly str motor_reach
    cpdef double output_angle(self, double motor_angle)
    cpdef tuple evaluate(self, double delta, double m, object temperature)
    cdef double _support(self, double f3, object temperature)


@cython.final
cdef class ActuatorSharedStep(SharedStep):
    cdef ActuatorStepper stepper
    cdef bint motor_side
    cdef tuple inputs, temperature_slots, breakdown, infinite, outputs
    cdef Py_ssize_t ratio_index

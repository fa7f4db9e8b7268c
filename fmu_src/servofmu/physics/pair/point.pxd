# Declarations of point.py for the compiled modules that fill it in C.
cimport cython


@cython.final
cdef class PointState:
    cdef public double hysteresis_torque
    cdef public double spin_torque
    cdef public double sliding_torque
    cdef public double inner_ring_torque
    cdef public double outer_ring_torque
    cdef public double coulomb_torque
    cdef public double breakaway_excess
    cdef public double breakaway_torque
    cdef public double preload
    cdef public double contact_angle
    cdef public double radial_clearance
    cdef public double kinematic_viscosity
    cdef public double pitch_diameter
    cdef public double axial_stiffness
    cdef public double max_contact_pressure
    cdef public double outer_fit_pressure
    cdef public double inner_fit_pressure
    cdef public double outer_interference
    cdef public double inner_interference
    cdef public double force_a
    cdef public double force_b
    cdef public double axial_displacement
    cdef public bint overloaded
    cdef public bint locked
    cdef public bint unloaded
    cdef public bint reverse_loaded
    cdef public bint outside_lubricant_range
    cdef public double axial_play
    cdef public object rolling

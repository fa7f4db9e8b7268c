# Declarations of constants.py for the compiled modules that call it in C.
cimport cython

from servofmu.physics.pair._rows cimport PairRows

# the module's constants, as C values (its _NAME: cython.<type> = ... lines)
cdef double _INF, _CST
cdef int _NO_LAW, _WALTHER, _VOGEL, _OTHER_LAW


@cython.final
cdef class PairConstants:
    cdef public object pair
    cdef public double t0
    cdef public double outer_diameter
    cdef public double bore
    cdef public double outer_groove
    cdef public double inner_groove
    cdef public double ball_diameter
    cdef public double inner_curvature
    cdef public double outer_curvature
    cdef public int n_balls
    cdef public double compliance
    cdef public double alpha_ring
    cdef public double e_ring
    cdef public double nu_ring
    cdef public double alpha_ball
    cdef public double alpha_housing
    cdef public double e_housing
    cdef public double nu_housing
    cdef public double alpha_shaft
    cdef public double e_shaft
    cdef public double nu_shaft
    cdef public double outer_interference
    cdef public double inner_interference
    cdef public double housing_outer_diameter
    cdef public double shaft_bore
    cdef public bint coupled
    cdef public double seat_outer
    cdef public double seat_inner
    cdef public double closure_housing
    cdef public double closure_shaft
    cdef public double closure_rings
    cdef public double closure0
    cdef public bint tandem
    cdef public PairRows rows
    cdef public double spring_stiffness
    cdef public object viscosity
    cdef public int law
    cdef public double law_a
    cdef public double law_b
    cdef public double law_c
    cdef public double hold_temperature
    cdef public bint lubricated
    cdef public double lower_limit
    cdef public double upper_limit
    cdef public bint solid
    cdef public bint sliding
    cdef public double pressure_limit
    cdef public bint fast
    cdef public bint needs_loads
    cdef public bint needs_contacts
    cdef public double density
    cdef public double hysteresis_loss
    cdef public double mu
    cdef public double static_ratio
    cdef public double s0
    cdef public double rest_s0
    cdef public double w_reg
    cdef public double w_stribeck
    cdef public object python
    cdef public object model


@cython.final
cdef class Thermal:
    cdef public double t_housing
    cdef public double t_shaft
    cdef public double t_outer
    cdef public double t_inner
    cdef public double ball_diameter
    cdef public double clearance
    cdef public double closure
    cdef public double curvature_distance
    cdef public double dw_third
    cdef public double first_contact_offset
    cdef public double gamma_scale
    cdef public double inner_fit_pressure
    cdef public double inner_groove_radius
    cdef public double inner_interference
    cdef public double inv_f_inner
    cdef public double inv_f_outer
    cdef public double kinematic_viscosity
    cdef public double outer_fit_pressure
    cdef public double outer_groove_radius
    cdef public double outer_interference
    cdef public bint outside_lubricant_range
    cdef public double pitch_diameter
    cdef public double radial_centre_distance
    cdef public bint has_rest
    cdef public double rest_torque
    cdef public bint has_rest_offset
    cdef public double rest_offset
    cdef public bint has_coefficients
    cdef public double c_hysteresis
    cdef public double c_sliding_inner
    cdef public double c_sliding_outer
    cdef public double c_spin


cdef double free_angle(Thermal th)
cpdef Thermal thermal_at(PairConstants c, double t_h, double t_s, double t_o, double t_i)
cpdef tuple set_coefficients(Thermal th, PairConstants c)

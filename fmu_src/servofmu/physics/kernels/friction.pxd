# Declarations of friction.py for the compiled modules that call it in C.

# the module's constants, as C values (its _NAME: cython.<type> = ... lines)
cdef double _HEATHCOTE, _THRESHOLD, _TWO_THIRDS, _CST, _MM, _NMM, _RPM

cpdef double hysteresis_force(double load, double semi_minor_axis, double ball_diameter,
                              double loss_factor)
cpdef double contact_spin_moment(double load, double semi_major_axis, double e_integral,
                                 double friction_coefficient)
cpdef double heathcote_force(double load, double semi_major_axis, double ball_diameter,
                             double groove_radius, double friction)
cpdef double palmgren_torque(double kinematic_viscosity, double speed, double pitch_diameter,
                             double s0)
cpdef double stribeck_torque(double running_torque, double breakaway_excess, double speed,
                             double stribeck_speed)
cpdef double regularised_torque(double speed, double running_torque, double breakaway_excess,
                                double regularisation_speed, double stribeck_speed)
cpdef (double, double) coulomb_and_excess(double static_ratio, double hysteresis, double spin,
                                          double sliding)
cpdef double dahl_torque_step(double torque, double coulomb, double sigma0, double exponent,
                              double dtheta)

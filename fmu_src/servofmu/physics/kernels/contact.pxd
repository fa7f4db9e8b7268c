# Declarations of contact.py for the compiled modules that call it in C.

# the module's constants, as C values (its _NAME: cython.<type> = ... lines)
cdef double _PI

cpdef double diametral_clearance(double inner_groove, double outer_groove, double ball_diameter)
cpdef double curvature_distance(double inner_radius, double outer_radius, double ball_diameter)
cpdef double pitch_diameter(double inner_groove, double outer_groove)
cpdef double first_contact_offset(double clearance, double curvature_distance)
cpdef double free_contact_angle(double clearance, double curvature_distance)
cpdef (double, double, double, double) elliptic_slopes(double m, double k_integral,
                                                      double e_integral)
cpdef (double, double, double) hertz_relation(double k, double k_integral, double e_integral)
cpdef (double, double) race_curvature(double gamma, double inverse_conformity, bint inner)
cpdef (double, double, double) hertz_coefficients(double curvature_sum, double ellipticity,
                                                  double k_integral, double e_integral,
                                                  double compliance)
cpdef double hertz_pressure(double load, double semi_axes)
cpdef double series_stiffness(double c_inner, double c_outer)
cpdef (double, double, double, double) ball_contact(double axial, double radial,
                                                    double curvature_distance)
cpdef double hertz_load(double stiffness, double deflection)
cpdef (double, double, double, double, double) ball_stiffness(
    double load, double distance, double deflection, double stiffness, double stiffness_slope,
    double sin_a, double cos_a)

# Declarations of lame.py for the compiled modules that call it in C.
cpdef double lame_ratio(double d_small, double d_large)
cpdef double shaft_compliance(double bore, double diameter, double youngs_modulus,
                              double poisson_ratio)
cpdef double hub_compliance(double diameter, double outer_diameter, double youngs_modulus,
                            double poisson_ratio)
cpdef double fit_pressure(double interference, double diameter, double shaft, double hub)
cpdef double bore_change(double pressure, double outer_diameter, double bore,
                         double youngs_modulus)
cpdef double outside_change(double pressure, double bore, double outer_diameter,
                            double youngs_modulus)
cpdef (double, double, double, double, double, double, double, double, double) mounted_races(
    double t_housing, double t_shaft, double t_outer, double t_inner, double t0,
    (double, double, double) ring, double ball_expansion, (double, double, double) housing,
    (double, double, double) shaft,
    (double, double, double, double, double, double, double) bearing,
    (double, double, double, double) seats, bint coupled)

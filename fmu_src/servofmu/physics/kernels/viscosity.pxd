# Declarations of viscosity.py for the compiled modules that call it in C.
cpdef double walther_viscosity(double log10_temperature, double a, double b, double c)
cpdef double vogel_log_viscosity(double temperature, double a, double b, double t_inf)
cpdef double operating_temperature(double temperature, double hold)

# Declarations of elementary.py for the compiled modules that call it in C.
cpdef double maximum(double a, double b)
cpdef double minimum(double a, double b)
cpdef double sqrt(double x)
cpdef double cbrt(double x)
cpdef double exp(double x)
cpdef double tanh(double x)
cpdef double log10(double x)
cpdef double arccos(double x)

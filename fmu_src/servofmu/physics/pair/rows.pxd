# Declarations of rows.py for the compiled modules that call it in C.
cimport cython

# the module's constants, as C values (its _NAME: cython.<type> = ... lines)
cdef double _INF
cdef int _LOOP, _RIGID, _TANDEM

ctypedef (bint, double, double, double, double) Step

cpdef double preload_force(double force_a, double force_b)
cpdef double axial_play(double first_contact_offset, double offset_a, double offset_b,
                        double force_a, double force_b)
cpdef (bint, bint, bint, bint) pair_flags(double pressure_limit, double clearance,
                                          double max_contact_pressure, double force_a,
                                          double force_b)
cpdef double loop_closure_at(double assembly, double housing, double shaft, double rings,
                             double t0, double t_housing, double t_shaft, double t_rings)


@cython.final
cdef class PairRows:
    cdef public int kind
    cdef public bint rigid
    cdef public bint tandem
    cdef public double sign_b
    cdef public double spring
    cdef public double thrust
    cdef public double k_loop
    cpdef (double, double, double, double) residuals(
        self, double fa_a, double fa_b, double fr_a, double fr_b, double p, double z,
        double closure, double f_ext, double f_r)
    cpdef Step newton_step(
        self, double a11, double a12, double a21, double a22, double b11, double b12,
        double b21, double b22, double r1, double r2, double r3, double r4, bint radial)
    cpdef double axial_stiffness(self, double ka, double kb)

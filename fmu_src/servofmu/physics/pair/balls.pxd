# Declarations of balls.py for the compiled modules that call it in C.
cimport cython

from servofmu.physics.pair._constants cimport PairConstants, Thermal

# the module's constants, as C doubles (its _NAME: cython.double = ... lines)
cdef double _DRIFT, _REDO, _G_SPAN, _F_SPAN, _THIRD

ctypedef (double, double, double, double, double, double, double, double, double, double, double, double, double, double, double, double) Terms
ctypedef (double, double, double, double, double, double, double, double) Ring
ctypedef (double, double, double, double, double, double, double, double, double, bint) Sums


@cython.final
cdef class Anchor:
    cdef public double k
    cdef public double m
    cdef public double k_int
    cdef public double e_int
    cdef public double f
    cdef public double f1
    cdef public double f2
    cdef public double f2_f1
    cdef public double inv_f1
    cdef public double k1
    cdef public double k2
    cdef public double e1
    cdef public double e2
    cpdef copy(self)
    cpdef set(self, double k)


@cython.final
cdef class Ball:
    cdef public double cos_psi
    cdef public double weight
    cdef public Anchor anc_i
    cdef public Anchor anc_o
    cdef public object base
    cdef public double load
    cdef public double cos_a
    cdef public double sin_a


cpdef Terms contact_terms(
    PairConstants c, double gamma, double inv_f, bint inner, Anchor anc)
cpdef tuple ball_base(PairConstants c, double gamma, double inv_f_i, double inv_f_o, Ball b)
cpdef Ring ring_point(
    Thermal th, PairConstants c, double a, double dr, list balls)
cpdef Sums ring_sums(
    Thermal th, PairConstants c, list balls, object ehl=*)

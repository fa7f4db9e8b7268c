# cython: language_level=3, auto_pickle=False, embedsignature=False
"""Elementary operations of the kernels on a Python float, a numpy array or, compiled, a C
double: the one place where a kernel's arithmetic chooses between :mod:`math`, numpy and C's
``libm``. A kernel written with them takes floats or arrays as they come.

Examples
--------
>>> import numpy as np
>>> maximum(2.0, 3.0), maximum(np.array([1.0, 4.0]), 2.0).tolist()
(3.0, [2.0, 4.0])
"""

import math

import numpy as np

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from . import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.libc import math as libm


def _both_floats(a, b) -> bool:
    return type(a) is float and type(b) is float


@cython.ccall
def maximum(a: cython.double, b: cython.double) -> cython.double:
    """The larger of ``a`` and ``b``, elementwise (floats or arrays, any unit).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> maximum(-1.0, 0.0)
    0.0
    """
    if cython.compiled:
        return a if a >= b else b
    else:
        return max(a, b) if _both_floats(a, b) else np.maximum(a, b)


@cython.ccall
def minimum(a: cython.double, b: cython.double) -> cython.double:
    """The smaller of ``a`` and ``b``, elementwise (floats or arrays, any unit).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> minimum(-1.0, 0.0)
    -1.0
    """
    if cython.compiled:
        return a if a <= b else b
    else:
        return min(a, b) if _both_floats(a, b) else np.minimum(a, b)


@cython.ccall
def sqrt(x: cython.double) -> cython.double:
    """√x, elementwise (x ≥ 0).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> sqrt(4.0)
    2.0
    """
    if cython.compiled:
        return libm.sqrt(x)
    else:
        return math.sqrt(x) if type(x) is float else np.sqrt(x)


@cython.ccall
def cbrt(x: cython.double) -> cython.double:
    """∛x, elementwise (real, any sign).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> cbrt(-8.0)
    -2.0
    """
    if cython.compiled:
        return libm.cbrt(x)
    else:
        return math.cbrt(x) if type(x) is float else np.cbrt(x)


@cython.ccall
def exp(x: cython.double) -> cython.double:
    """eˣ, elementwise.

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> exp(0.0)
    1.0
    """
    if cython.compiled:
        return libm.exp(x)
    else:
        return math.exp(x) if type(x) is float else np.exp(x)


@cython.ccall
def power(x: cython.double, y: cython.double) -> cython.double:
    """xʸ, elementwise (x ≥ 0, or y whole).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> power(4.0, 0.5)
    2.0
    """
    if cython.compiled:
        return libm.pow(x, y)
    else:
        return x**y if _both_floats(x, y) else np.power(x, y)


@cython.ccall
def tanh(x: cython.double) -> cython.double:
    """tanh x, elementwise.

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> tanh(0.0)
    0.0
    """
    if cython.compiled:
        return libm.tanh(x)
    else:
        return math.tanh(x) if type(x) is float else np.tanh(x)


@cython.ccall
def log10(x: cython.double) -> cython.double:
    """lg x, elementwise (x > 0).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> log10(1000.0)
    3.0
    """
    if cython.compiled:
        return libm.log10(x)
    else:
        return math.log10(x) if type(x) is float else np.log10(x)


@cython.ccall
def arccos(x: cython.double) -> cython.double:
    """arccos x [rad], elementwise, x clipped to [−1, 1] first (rounding past ±1 gives 0 or
    π, not NaN).

    Returns
    -------
    float or ndarray
        [rad].

    Examples
    --------
    >>> arccos(1.0 + 1e-16), round(arccos(0.5) * 3, 12)  # rad: π/3·3 = π
    (0.0, 3.14159265359)
    """
    c: cython.double = maximum(minimum(x, 1.0), -1.0)
    if cython.compiled:
        return libm.acos(c)
    else:
        return math.acos(c) if type(c) is float else np.arccos(c)

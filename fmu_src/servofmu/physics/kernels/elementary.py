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


@cython.ccall
def sin(x: cython.double) -> cython.double:
    """sin x, elementwise (x [rad]).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> sin(0.0)
    0.0
    """
    if cython.compiled:
        return libm.sin(x)
    else:
        return math.sin(x) if type(x) is float else np.sin(x)


@cython.ccall
def cos(x: cython.double) -> cython.double:
    """cos x, elementwise (x [rad]).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> cos(0.0)
    1.0
    """
    if cython.compiled:
        return libm.cos(x)
    else:
        return math.cos(x) if type(x) is float else np.cos(x)


@cython.ccall
def tan(x: cython.double) -> cython.double:
    """tan x, elementwise (x [rad]).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> tan(0.0)
    0.0
    """
    if cython.compiled:
        return libm.tan(x)
    else:
        return math.tan(x) if type(x) is float else np.tan(x)


@cython.ccall
def arcsin(x: cython.double) -> cython.double:
    """arcsin x [rad], elementwise (|x| ≤ 1).

    Returns
    -------
    float or ndarray
        [rad].

    Examples
    --------
    >>> arcsin(0.0)
    0.0
    """
    if cython.compiled:
        return libm.asin(x)
    else:
        return math.asin(x) if type(x) is float else np.arcsin(x)


@cython.ccall
def arctan(x: cython.double) -> cython.double:
    """arctan x [rad], elementwise.

    Returns
    -------
    float or ndarray
        [rad].

    Examples
    --------
    >>> arctan(0.0)
    0.0
    """
    if cython.compiled:
        return libm.atan(x)
    else:
        return math.atan(x) if type(x) is float else np.arctan(x)


@cython.ccall
def arctan2(y: cython.double, x: cython.double) -> cython.double:
    """The angle of the point (x, y) [rad], in (−π, π], elementwise.

    Returns
    -------
    float or ndarray
        [rad].

    Examples
    --------
    >>> round(arctan2(1.0, -1.0) * 4 / 3, 12)  # rad: 3π/4·4/3 = π
    3.14159265359
    """
    if cython.compiled:
        return libm.atan2(y, x)
    else:
        return math.atan2(y, x) if _both_floats(y, x) else np.arctan2(y, x)


@cython.ccall
def sign(x: cython.double) -> cython.double:
    """−1, 0 or 1 by the sign of x, elementwise (0 at ±0).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> sign(-2.0), sign(0.0)
    (-1.0, 0.0)
    """
    if cython.compiled:
        return (x > 0.0) - (x < 0.0)
    else:
        return float((x > 0.0) - (x < 0.0)) if type(x) is float else np.sign(x)


@cython.ccall
def hypot(x: cython.double, y: cython.double) -> cython.double:
    """√(x² + y²) without overflow, elementwise (C's ``hypot``: Python's :func:`math.hypot`
    rounds differently, so the Python path calls numpy's, which is C's).

    Returns
    -------
    float or ndarray

    Examples
    --------
    >>> hypot(3.0, 4.0)
    5.0
    """
    if cython.compiled:
        return libm.hypot(x, y)
    else:
        return float(np.hypot(x, y)) if _both_floats(x, y) else np.hypot(x, y)

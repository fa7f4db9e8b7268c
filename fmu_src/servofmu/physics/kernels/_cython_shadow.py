"""The names of Cython's pure-Python mode that the compiled modules use
(:mod:`servofmu.physics.compiled`), for an interpreter without Cython (an FMU's host needs numpy
and scipy only): decorators that return what they
decorate, type names that are only read in annotations, and ``compiled = False``. With
Cython installed its own ``cython`` module (Cython.Shadow) takes this place; compiled, the
names are Cython's.

Examples
--------
>>> from servofmu.physics.kernels import _cython_shadow as cython
>>> cython.compiled, cython.cfunc(len) is len, cython.typedef(float) is float
(False, True, True)
"""

import dataclasses  # noqa: F401  (``cython.dataclasses``: the standard library's, as in Cython.Shadow)

compiled = False

# type names (read in annotations and typedefs only)
double = float
bint = bool
int = int
longlong = int
Py_ssize_t = int


def _pass_through(obj=None, *args, **kwargs):
    """A decorator used bare (``@cython.cfunc``) or with arguments
    (``@cython.exceptval(check=False)``): returns the decorated object."""
    if callable(obj) and not args and not kwargs:
        return obj
    return lambda f: f


cclass = cfunc = ccall = inline = final = _pass_through
locals = exceptval = boundscheck = wraparound = cdivision = _pass_through


def typedef(t):
    """A type alias: the type itself uncompiled.

    Returns
    -------
    type
        ``t``.

    Examples
    --------
    >>> typedef(tuple[float, float])
    tuple[float, float]
    """
    return t


def declare(t=None, value=None, **kwargs):
    """A declared variable: its value (None when not given) uncompiled.

    Returns
    -------
    object
        ``value``.

    Examples
    --------
    >>> declare(float, 2.0)
    2.0
    """
    return value

"""Finalise the embedded Python interpreter first at process exit (pythonfmu 0.7 on Linux).

Why
---
A non-Python host (a C or C++ program that dlopens the FMU with ``LD_PRELOAD=libpython``)
got fmi2OK from every FMI call and then died with SIGSEGV or SIGABRT inside a normal
``exit()``, for all four FMUs, depending on the heap layout (``PYTHONHASHSEED`` 3, 4, 5 show
it). Two defects of pythonfmu 0.7's export library meet scipy:

1. pythonfmu keeps the interpreter in a namespace-scope ``std::shared_ptr<PyState>`` whose
   destructor wakes pythonfmu's worker thread to run ``Py_Finalize``. That destructor was
   registered (``__cxa_atexit``) when the FMU library was loaded, and exit handlers run in
   reverse order of registration: it runs *after* the static destructors of the C++
   extensions imported later. scipy's ``_uarray`` (reached through ``scipy.interpolate`` →
   ``scipy.optimize`` → … → ``scipy.fft``) drops its reference to
   ``BackendNotImplementedError`` in such a destructor, and the interpreter's finalisation
   then drops it again (valgrind: invalid read in ``delete_garbage`` ← ``Py_FinalizeEx``).
2. pythonfmu's ``onLibraryUnload`` (``__attribute__((destructor))``, run by the dynamic
   loader after the exit handlers) assigns ``nullptr`` to that shared_ptr after its
   destructor has run: the control block is released a second time. This hits Python hosts
   too (fmpy: ``corrupted double-linked list`` at exit, a few runs in a hundred).

The fix
-------
After the imports that load the C++ extensions, look up the FMU binary that is already
loaded (``dlopen`` with ``RTLD_NOLOAD``, plus ``RTLD_NODELETE`` so that it stays mapped until
the exit handlers run) and register its exported ``finalizePythonInterpreter`` with libc's
``__cxa_atexit``. Registered last, it runs first: the interpreter is finalised while every
extension is intact, and the shared_ptr is empty by the time the destructors of point 1 and 2
touch it, which makes both no-ops.

- Python hosts (fmpy, libcosimpy, …): the interpreter was not started by pythonfmu, so its
  worker thread has already returned; ``finalizePythonInterpreter`` then only releases the
  empty ``PyState`` after Python's own finalisation. No second finalisation, no Python call.
- Several FMUs in one process: each FMU binary holds its own ``PyState``; each binary is
  registered once (the first, which started the interpreter, is finalised last).
- Windows: pythonfmu finalises from ``DllMain`` instead, and macOS has no pythonfmu binary;
  nothing is done there.
"""

from __future__ import annotations

import ctypes
import os
import sys

from .binary import fmu_binary, loaded

_REGISTERED: set[str] = set()  # real paths of the FMU binaries registered in this process


def register_interpreter_finaliser(
    resources: str | os.PathLike | None, model_identifier: str
) -> bool:
    """Register the loaded FMU binary's ``finalizePythonInterpreter`` as the last-registered
    (hence first-run) exit handler, once per binary and process (see the module docstring).

    Never raises: where it cannot or need not register (not Linux, not running from a loaded
    FMU binary, a binary without the symbol), nothing changes.

    Parameters
    ----------
    resources : the FMU's ``resources`` folder, or None outside an FMU
    model_identifier : the FMU's modelIdentifier (servofmu: the slave class name)

    Returns
    -------
    bool
        True when the binary's finaliser is registered (now or earlier in this process).

    Examples
    --------
    >>> register_interpreter_finaliser("/no/such/fmu/resources", "DCMotor")
    False
    """
    if not sys.platform.startswith("linux") or not resources:
        return False
    binary = os.path.realpath(fmu_binary(resources, model_identifier))
    if binary in _REGISTERED:
        return True
    lib = loaded(resources, model_identifier, keep=True)
    if lib is None:  # not loaded (e.g. imported in a test)
        return False
    try:
        finaliser = ctypes.cast(lib.finalizePythonInterpreter, ctypes.c_void_p)
        cxa_atexit = ctypes.CDLL(None)["__cxa_atexit"]
    except (OSError, AttributeError):  # no such symbol
        return False
    cxa_atexit.argtypes = (ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p)
    cxa_atexit.restype = ctypes.c_int
    if cxa_atexit(finaliser, None, None) != 0:
        return False
    _REGISTERED.add(binary)
    return True

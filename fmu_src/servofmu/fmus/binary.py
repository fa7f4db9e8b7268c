"""Which FMI export library runs a slave: the FMU's binary, looked up in the process.

An FMU built by ``servofmu build`` carries either servofmu's export library (pythonfmu 0.7.0's
C++ layer with servofmu's changes, compiled when servofmu was installed) or, where none was
compiled, pythonfmu's own binary. They answer a Python exception differently:

- servofmu's export answers an exception that carries an FMI status (:class:`.calls.FMIError`)
  with that status and its logged message, and keeps the instance; it forwards fmi2Warning,
  fmi2Error and fmi2Fatal messages to the host whatever ``loggingOn`` says;
- pythonfmu's binary answers every exception with fmi2Fatal and destroys the instance (a later
  call can crash the host), and forwards no message at all without ``loggingOn``.

A slave therefore raises only where :func:`export_of` names servofmu's export.
"""

from __future__ import annotations

import ctypes
import os
import sys
from pathlib import Path

#: What :func:`export_of` answers for pythonfmu's binary (or when no binary is loaded)
PYTHONFMU = "pythonfmu 0.7.0"


def fmu_binary(resources: str | os.PathLike, model_identifier: str) -> Path:
    """Path of an FMU's Linux binary from its resources folder (FMI 2.0 layout).

    Parameters
    ----------
    resources : the FMU's ``resources`` folder (as pythonfmu passes it to the slave)
    model_identifier : the FMU's modelIdentifier (servofmu: the slave class name)

    Returns
    -------
    Path
        ``<resources>/../binaries/linux64/<model_identifier>.so``

    Examples
    --------
    >>> fmu_binary("/tmp/fmu/resources", "DCMotor").as_posix()
    '/tmp/fmu/binaries/linux64/DCMotor.so'
    """
    return Path(resources).parent / "binaries" / "linux64" / f"{model_identifier}.so"


def loaded(resources, model_identifier: str, keep: bool = False):
    """The FMU's binary as a ``ctypes.CDLL`` when the process has loaded it, else None
    (never loads it: ``RTLD_NOLOAD``; Linux only).

    Parameters
    ----------
    resources : the FMU's ``resources`` folder, or None outside an FMU
    model_identifier : the FMU's modelIdentifier
    keep : also keep the library mapped until the process exits (``RTLD_NODELETE``)

    Returns
    -------
    ctypes.CDLL or None

    Examples
    --------
    >>> loaded("/no/such/fmu/resources", "DCMotor") is None
    True
    """
    if not sys.platform.startswith("linux") or not resources:
        return None
    mode = os.RTLD_NOLOAD | (os.RTLD_NODELETE if keep else 0)
    try:
        return ctypes.CDLL(os.path.realpath(fmu_binary(resources, model_identifier)), mode=mode)
    except OSError:  # not loaded (e.g. the package imported in a test or by the build)
        return None


def export_of(resources, model_identifier: str) -> str | None:
    """Which export library runs the slave: its ``servofmuExport()`` text for servofmu's
    export, :data:`PYTHONFMU` for pythonfmu's binary, None when no FMU binary is loaded (the
    slave imported as a library, e.g. by the build).

    Parameters
    ----------
    resources : the FMU's ``resources`` folder, or None outside an FMU
    model_identifier : the FMU's modelIdentifier

    Returns
    -------
    str or None

    Examples
    --------
    >>> export_of(None, "DCMotor") is None
    True
    """
    lib = loaded(resources, model_identifier)
    if lib is None:
        return None
    try:
        marker = lib.servofmuExport
    except AttributeError:  # pythonfmu's binary
        return PYTHONFMU
    marker.restype = ctypes.c_char_p
    marker.argtypes = ()
    return marker().decode()


def shares_values(export: str | None) -> bool:
    """Whether an export library serves fmi2SetReal and fmi2GetReal from the values a slave
    shares with it (:mod:`.shared_values`): servofmu's export from version 2.

    Parameters
    ----------
    export : what :func:`export_of` answered (None: no FMU binary)

    Returns
    -------
    bool

    Examples
    --------
    >>> shares_values("servofmu-export 2 (pythonfmu 0.7.0, patched)")
    True
    >>> shares_values("servofmu-export 1 (pythonfmu 0.7.0, patched)"), shares_values(PYTHONFMU)
    (False, False)
    """
    if export is None or not export.startswith("servofmu-export "):
        return False
    version = export.removeprefix("servofmu-export ").split(" ", 1)[0]
    return version.isdigit() and int(version) >= 2


def reports_statuses(export: str) -> bool:
    """Whether an export library turns :class:`.calls.FMIError` into a status.

    Parameters
    ----------
    export : what :func:`export_of` answered (None: no FMU binary)

    Returns
    -------
    bool
        True for servofmu's export.

    Examples
    --------
    >>> reports_statuses("servofmu-export 2 (pythonfmu 0.7.0, patched)")
    True
    >>> reports_statuses(PYTHONFMU)
    False
    """
    return export is not None and export.startswith("servofmu-export ")

"""What a servofmu slave answers a host: the FMI 2.0 co-simulation states, which call each
allows, the exception that the servofmu export turns into a status, and the checks of an FMU
state handed back by a host.

States and calls (FMI 2.0, section 4.2.4, the state table of co-simulation; the FMI
Reference FMUs implement the same table):

=============================  =======================================================
call                           allowed in
=============================  =======================================================
fmi2SetupExperiment            instantiated
fmi2EnterInitializationMode    instantiated
fmi2ExitInitializationMode     initialization mode
fmi2DoStep                     step complete
fmi2Terminate                  step complete, step failed
fmi2Get{Real,Integer,…}        initialization mode, step complete, step failed,
                               terminated, error
fmi2Set{Real,Integer,…}        instantiated, initialization mode (inputs, parameters);
                               step complete (inputs, tunable parameters); never an output
fmi2Get/Set/…FMUstate          every state
fmi2Reset, fmi2FreeInstance    every state (pythonfmu's C++ layer)
=============================  =======================================================

A call answered with fmi2Error leaves the instance in the *error* state, a step answered with
fmi2Discard in *step failed*: from there only reading, fmi2SetFMUstate (the state recorded in
it, the FMI way to retry), fmi2Terminate (step failed), fmi2Reset and fmi2FreeInstance lead on.

A serialized state is its JSON text with the SHA-256 of those bytes appended as a last field,
``{…, "sha256": "<64 hex digits>"}`` (:func:`sealed`): still one JSON object, and a state whose
bytes were altered, truncated or written by anything else is refused (:func:`unsealed`)
before a value of it is read. The checksum guards against accidents and careless tools, not
against someone who means harm (anyone can compute a SHA-256): the restored values are
checked as well, as values set through the FMI calls are (:mod:`.runtime`).
"""

from __future__ import annotations

import hashlib
import json
import math
import re

INSTANTIATED = "instantiated"
INITIALIZATION = "initialization mode"
STEP_COMPLETE = "step complete"
STEP_FAILED = "step failed"
TERMINATED = "terminated"
ERROR = "error"
PHASES = (INSTANTIATED, INITIALIZATION, STEP_COMPLETE, STEP_FAILED, TERMINATED, ERROR)
#: the states in which the values can be read (fmi2Get*)
READABLE = frozenset({INITIALIZATION, STEP_COMPLETE, STEP_FAILED, TERMINATED, ERROR})
#: the calls that need one state, and the states each allows
ALLOWED = {
    "fmi2SetupExperiment": (INSTANTIATED,),
    "fmi2EnterInitializationMode": (INSTANTIATED,),
    "fmi2ExitInitializationMode": (INITIALIZATION,),
    "fmi2DoStep": (STEP_COMPLETE,),
    "fmi2Terminate": (STEP_COMPLETE, STEP_FAILED),
}
#: the call that leads out of each state (for messages)
NEXT = {
    INSTANTIATED: "fmi2SetupExperiment and fmi2EnterInitializationMode",
    INITIALIZATION: "fmi2ExitInitializationMode",
    STEP_COMPLETE: "fmi2DoStep",
    STEP_FAILED: "fmi2SetFMUstate with a state saved before the failed step, or fmi2Reset",
    TERMINATED: "fmi2Reset or fmi2FreeInstance",
    ERROR: "fmi2SetFMUstate with a state saved before the error, or fmi2Reset",
}
#: FMI 2.0 status values
OK, WARNING, DISCARD, ERROR_STATUS = 0, 1, 2, 3
#: the keys of a saved FMU state
STATE_KEYS = frozenset(
    {"fmu", "package", "phase", "time", "start_time", "values", "hidden", "dirty", "error"}
)


class FMIError(Exception):
    """A host's mistake, answered with fmi2Error: the servofmu export logs ``str(exc)`` and
    returns the status in ``fmi2_status``, and the slave instance stays alive (pythonfmu's own
    binary would answer any exception with fmi2Fatal and destroy the instance: the slaves raise
    it only under the servofmu export)."""

    fmi2_status = ERROR_STATUS


def sequence_problem(call: str, phase: str) -> str:
    """Why ``call`` is not allowed in ``phase`` ("" when it is).

    Parameters
    ----------
    call : an FMI function name of :data:`ALLOWED`
    phase : one of :data:`PHASES`

    Returns
    -------
    str
        The message, naming the state and what leads out of it.

    Examples
    --------
    >>> sequence_problem("fmi2DoStep", INITIALIZATION)
    "illegal call sequence: fmi2DoStep in state 'initialization mode' (allowed in 'step complete'; next: fmi2ExitInitializationMode)"
    >>> sequence_problem("fmi2DoStep", STEP_COMPLETE)
    ''
    """  # noqa: E501
    allowed = ALLOWED[call]
    if phase in allowed:
        return ""
    return (
        f"illegal call sequence: {call} in state '{phase}' (allowed in "
        f"{' or '.join(repr(a) for a in allowed)}; next: {NEXT[phase]})"
    )


def value_problem(kind: str, value) -> str:
    """Why ``value`` cannot be a saved value of a variable of FMI type ``kind`` ("" if it can).

    Parameters
    ----------
    kind : "Real", "Integer", "Enumeration" or "Boolean"
    value : the value read from a saved state

    Returns
    -------
    str
        The problem, or "".

    Examples
    --------
    >>> value_problem("Real", 1.5), value_problem("Integer", True), value_problem("Boolean", 1)
    ('', 'True is not an Integer', '1 is not a Boolean')
    """
    if kind == "Real":
        ok = type(value) is float or type(value) is int
    elif kind == "Boolean":
        ok = type(value) is bool
    else:
        ok = type(value) is int
    return "" if ok else f"{value!r} is not {'an' if kind[0] in 'IE' else 'a'} {kind}"


def state_problem(state, fmu: str, package: str, variables) -> str:
    """Why ``state`` is not a saved state of FMU ``fmu`` built from package hash ``package``
    with ``variables`` (name → FMI type) ("" when it is one). The hidden part is checked by the
    FMU itself when it is restored.

    Parameters
    ----------
    state : what the host handed back (anything)
    fmu : the modelIdentifier the state must name
    package : the package hash the state must name (this build)
    variables : dict of variable name → FMI type

    Returns
    -------
    str
        The first problem found, or "".

    Examples
    --------
    >>> state_problem({"fmu": "DCMotor"}, "ServoController", "abc", {})  # doctest: +ELLIPSIS
    "it is not a servofmu FMU state (keys ['fmu'] instead of [...])"
    """
    if not isinstance(state, dict) or set(state) != STATE_KEYS:
        keys = sorted(state) if isinstance(state, dict) else type(state).__name__
        return f"it is not a servofmu FMU state (keys {keys} instead of {sorted(STATE_KEYS)})"
    if state["fmu"] != fmu:
        return f"it is a state of {state['fmu']!r}, not of {fmu!r}"
    if state["package"] != package:
        return (
            f"it was saved by another servofmu build ({str(state['package'])[:12]!r}, this FMU "
            f"is {package[:12]!r})"
        )
    if state["phase"] not in PHASES:
        return f"phase = {state['phase']!r} is not one of {list(PHASES)}"
    for key in ("time", "start_time"):
        t = state[key]
        if not (t is None or (type(t) in (int, float) and math.isfinite(t))):
            return f"{key} = {t!r} is not a finite number"
    if type(state["dirty"]) is not bool or type(state["error"]) is not str:
        return "dirty must be a Boolean and error a text"
    values = state["values"]
    if not isinstance(values, dict) or set(values) != set(variables):
        return "its values are not this FMU's variables"
    for name, kind in variables.items():
        problem = value_problem(kind, values[name])
        if problem:
            return f"{name}: {problem}"
    if not isinstance(state["hidden"], dict):
        return "its hidden state is not a table"
    return ""


#: The checksum field that ends a serialized state (see the module docstring).
_SEAL = re.compile(rb', "sha256": "([0-9a-f]{64})"\}\Z')


def sealed(state: dict) -> bytes:
    """The bytes of a serialized FMU state: its JSON text, and the SHA-256 of that text as a
    last field.

    Parameters
    ----------
    state : a non-empty JSON-serialisable table (NaN and infinities allowed)

    Returns
    -------
    bytes
        UTF-8 JSON: ``{<the state's fields>, "sha256": "<64 hex digits>"}``.

    Examples
    --------
    >>> data = sealed({"time": 1.5})
    >>> data[:14], len(data)
    (b'{"time": 1.5, ', 91)
    >>> unsealed(data)
    ({'time': 1.5}, '')
    """
    if not (isinstance(state, dict) and state):
        raise TypeError(f"a state is a non-empty table, not {state!r}")
    body = json.dumps(state, allow_nan=True).encode("utf-8")
    digest = hashlib.sha256(body).hexdigest()
    return body[:-1] + f', "sha256": "{digest}"}}'.encode()


def unsealed(data: bytes) -> tuple[object, str]:
    """The state in bytes written by :func:`sealed`, once their checksum matches.

    Parameters
    ----------
    data : the bytes a host hands back (anything)

    Returns
    -------
    tuple
        (the state, "") or (None, why the bytes are refused).

    Examples
    --------
    >>> data = sealed({"time": 1.5})
    >>> unsealed(data.replace(b"1.5", b"2.5"))
    (None, 'its bytes do not match their checksum (altered or damaged)')
    >>> unsealed(b'{"time": 1.5}')
    (None, 'its bytes do not end with the checksum of a state (truncated, or not one)')
    """
    found = _SEAL.search(data)
    if found is None:
        return None, "its bytes do not end with the checksum of a state (truncated, or not one)"
    body = data[: found.start()] + b"}"
    if hashlib.sha256(body).hexdigest() != found.group(1).decode():
        return None, "its bytes do not match their checksum (altered or damaged)"
    return json.loads(body.decode("utf-8")), ""

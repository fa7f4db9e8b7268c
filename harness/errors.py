"""Errors of the harness: one clear line for the user, details attached."""

from __future__ import annotations

from contextlib import contextmanager

from servofmu.build.archive import ArchiveError
from servofmu.build.xmlsafe import XMLError


class HarnessError(Exception):
    """A run failed: the message names what, where and what to do; ``result`` holds what was
    computed up to the failure (also written to disk when the run had an output folder)."""

    def __init__(self, message: str, result=None, details: str = ""):
        super().__init__(message)
        self.result = result
        self.details = details


class SystemError_(HarnessError):
    """The system description is unusable (schema, connections, units, FMUs, parameters);
    raised before any FMU is instantiated. ``problems`` lists every problem found."""

    def __init__(self, problems: list[str]):
        self.problems = list(problems)
        head = self.problems[0] if len(self.problems) == 1 else f"{len(self.problems)} problems"
        super().__init__(f"unusable system description: {head}", details="\n".join(self.problems))

    def __str__(self):
        if len(self.problems) == 1:
            return super().__str__()
        return super().__str__() + ":\n  - " + "\n  - ".join(self.problems)


class MissingExtra(ImportError):
    """A command needs packages of an extra that this install left out; the message names the
    extra to install (bad set-up: the command line exits 2)."""


class ArgumentError(HarnessError, ValueError):
    """An argument of a run (times, overrides, signals, names to record) is unusable; raised
    before any FMU is instantiated (bad input: the command line exits 2)."""


class ParameterError(ArgumentError):
    """A parameter value or variant given to a run does not fit its variable; raised before
    any FMU is instantiated (bad input: the command line exits 2)."""


class Interrupted(HarnessError):
    """A run stopped at a step boundary on request (Ctrl-C or SIGTERM): ``result`` holds the
    rows up to that step (written to disk too when the run had an output folder), ``time`` the
    time [s] it stopped at, ``signum`` the signal. The command line exits 128 + signum (130
    for Ctrl-C, 143 for SIGTERM)."""

    def __init__(
        self, message: str, result=None, details: str = "", time: float = 0.0, signum: int = 2
    ):
        super().__init__(message, result=result, details=details)
        self.time = time
        self.signum = int(signum)


class ArchiveRefused(HarnessError, ArchiveError):
    """A refused archive, as a harness error."""


class XMLRefused(SystemError_, XMLError):
    """A refused XML document (malformed, a DTD, not schema-valid): an unusable description."""


@contextmanager
def refusals():
    """Raise the refusals of :mod:`servofmu.build.archive` and :mod:`servofmu.build.xmlsafe`
    as harness errors (still instances of the build's ArchiveError and XMLError)."""
    try:
        yield
    except XMLRefused:
        raise
    except XMLError as exc:
        raise XMLRefused([str(exc)]) from None
    except ArchiveRefused:
        raise
    except ArchiveError as exc:
        raise ArchiveRefused(str(exc)) from None

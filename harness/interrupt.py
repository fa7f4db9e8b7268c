"""Ctrl-C (or SIGTERM) during a co-simulation: stop at the next step boundary instead of
inside an FMU.

Python raises KeyboardInterrupt wherever the main thread is when SIGINT arrives, which in a
co-simulation is most often inside a pythonfmu slave's Python code called from the FMU's C
layer: the FMU then answers fmi2Fatal and the next call into it can crash the process; and
SIGTERM ends the process at once, keeping nothing. While :func:`interruptible` is active,
either signal only sets a flag; the master checks it between communication steps (each bounded
in time), frees its FMUs and raises :class:`~.errors.Interrupted` with the results so far.
Outside it, :func:`terminate_as_interrupt` makes SIGTERM raise :class:`Terminated`, a
KeyboardInterrupt, so that whatever keeps its results on Ctrl-C keeps them on SIGTERM too.
"""

from __future__ import annotations

import signal
import threading
import time
from contextlib import contextmanager

SIGNALS = (signal.SIGINT, signal.SIGTERM)


class Terminated(KeyboardInterrupt):
    """SIGTERM outside a co-simulation step loop, raised like Ctrl-C's KeyboardInterrupt."""

    signum = signal.SIGTERM


class StopRequest:
    """Set by SIGINT or SIGTERM while :func:`interruptible` is active; ``count`` counts the
    signals, ``signum`` is the first one."""

    def __init__(self):
        self.count = 0
        self.signum = signal.SIGINT
        self.received_at = 0.0  # time.perf_counter() at the first signal

    def delay(self) -> float:
        """Seconds since the first signal."""
        return time.perf_counter() - self.received_at

    @property
    def requested(self) -> bool:
        return self.count > 0

    def _handler(self, signum, frame):
        global _RECEIVED
        if not self.count:
            self.signum = _RECEIVED = signum
            self.received_at = time.perf_counter()
        self.count += 1


_RECEIVED = signal.SIGINT  # the signal that stopped the work (SIGINT unless SIGTERM did)


def received() -> int:
    """The number of the signal that stopped the work (the exit status is 128 + it).

    Returns
    -------
    int
        SIGTERM's number once the handlers of this module received it, else SIGINT's.

    Examples
    --------
    >>> received() in (signal.SIGINT, signal.SIGTERM)
    True
    """
    return int(_RECEIVED)


def _raise_terminated(signum, frame):
    global _RECEIVED
    _RECEIVED = signum
    raise Terminated("terminated (SIGTERM)")


def terminate_as_interrupt() -> None:
    """From now on SIGTERM raises :class:`Terminated` (a KeyboardInterrupt) in the main thread
    (elsewhere nothing changes).

    Returns
    -------
    None

    Examples
    --------
    >>> previous = signal.getsignal(signal.SIGTERM)
    >>> terminate_as_interrupt()
    >>> signal.getsignal(signal.SIGTERM) is _raise_terminated
    True
    >>> _ = signal.signal(signal.SIGTERM, previous)
    """
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGTERM, _raise_terminated)


_ACTIVE: StopRequest | None = None


@contextmanager
def interruptible():
    """Within this block SIGINT and SIGTERM set the yielded :class:`StopRequest` instead of
    raising KeyboardInterrupt or ending the process. Nested blocks share the outer request.
    Signal handlers can only be set in the main thread: elsewhere (a Dask worker's thread) it
    yields None and changes nothing. A signal that the block did not act on (it came after
    the block's last check, while a run wrote its results) is raised again when the block
    ends, for the handler outside it: a stop request is never lost between two runs."""
    global _ACTIVE
    if _ACTIVE is not None:
        yield _ACTIVE
        return
    if threading.current_thread() is not threading.main_thread():
        yield None
        return
    request = StopRequest()
    previous = {s: signal.signal(s, request._handler) for s in SIGNALS}
    _ACTIVE = request
    try:
        yield request
    finally:
        _ACTIVE = None
        for s, handler in previous.items():
            signal.signal(s, handler)
    if request.requested:  # it came after the last check (a run's end): the handler outside acts
        signal.raise_signal(request.signum)


_PROTECTED: list[int] | None = None  # the signals held by the active protected() block


@contextmanager
def protected(reraise: bool = True):
    """Within this block SIGINT and SIGTERM wait: a result being written, or the cleanup after
    a first signal (a cluster shutting down, the rows so far being written), is not cut short
    by a further one. Yields the list of the signals held. When the block ends, the first of
    them is raised again for the handler outside it (one raise, however many came), unless
    ``reraise`` is False: then the caller acts on the list (a run already stopping). Nested
    blocks share the outer one's list; in other threads than the main one nothing changes
    (an empty list).

    Returns
    -------
    contextmanager yielding list of int
        The numbers of the signals held so far.

    Examples
    --------
    >>> with protected(reraise=False) as held:
    ...     signal.raise_signal(signal.SIGINT)  # waits: no KeyboardInterrupt here
    >>> held == [signal.SIGINT]
    True
    """
    global _PROTECTED, _RECEIVED
    if _PROTECTED is not None:
        yield _PROTECTED
        return
    if threading.current_thread() is not threading.main_thread():
        yield []
        return
    held: list[int] = []

    def hold(signum, frame):
        global _RECEIVED
        if not held:
            _RECEIVED = signum
        held.append(signum)

    previous = {s: signal.signal(s, hold) for s in SIGNALS}
    _PROTECTED = held
    try:
        yield held
    finally:
        _PROTECTED = None
        for s, handler in previous.items():
            signal.signal(s, handler)
        if held and reraise:
            signal.raise_signal(held[0])

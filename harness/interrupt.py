"""Ctrl-C during a co-simulation: stop at the next step boundary instead of inside an FMU.

Python raises KeyboardInterrupt wherever the main thread is when SIGINT arrives, which in a
co-simulation is most often inside a pythonfmu slave's Python code called from the FMU's C
layer: the FMU then answers fmi2Fatal and the next call into it can crash the process. While
:func:`interruptible` is active, SIGINT only sets a flag; the master checks it between
communication steps, frees its FMUs and raises :class:`~.errors.Interrupted` with the results
so far.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager


class StopRequest:
    """Set by SIGINT while :func:`interruptible` is active; ``count`` counts the signals."""

    def __init__(self):
        self.count = 0

    @property
    def requested(self) -> bool:
        return self.count > 0

    def _handler(self, signum, frame):
        self.count += 1


_ACTIVE: StopRequest | None = None


@contextmanager
def interruptible():
    """Within this block SIGINT sets the yielded :class:`StopRequest` instead of raising
    KeyboardInterrupt. Nested blocks share the outer request. Signal handlers can only be
    set in the main thread: elsewhere (a Dask worker's thread) it yields None and changes
    nothing."""
    global _ACTIVE
    if _ACTIVE is not None:
        yield _ACTIVE
        return
    if threading.current_thread() is not threading.main_thread():
        yield None
        return
    request = StopRequest()
    previous = signal.signal(signal.SIGINT, request._handler)
    _ACTIVE = request
    try:
        yield request
    finally:
        _ACTIVE = None
        signal.signal(signal.SIGINT, previous)

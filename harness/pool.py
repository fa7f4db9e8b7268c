"""Independent co-simulations on worker processes, behind one progress bar.

A scenario's runs (one chamber profile each) share nothing: :func:`run_parallel` runs them on
a pool of worker processes, the longest first, and advances one progress bar by every run's
communication steps. The workers are started fresh (``spawn``): they inherit no FMU instance,
thread or lock of the caller. Each run is the same call as in the caller, so the results are
those of running them one after another; ``workers=1`` does exactly that, in this process.

Ctrl-C or SIGTERM: each running co-simulation stops at its next step boundary and keeps its
rows (:class:`~.errors.Interrupted`, its files written), the runs not started are dropped, and
the first Interrupted is raised here. A run that fails stops the others the same way, and its
error is raised.
"""

from __future__ import annotations

import os
import signal
import time
from collections.abc import Callable, Sequence

from .errors import HarnessError, Interrupted
from .interrupt import interruptible
from .progress import progress_bar

#: Seconds between two progress messages of a worker.
REPORT_INTERVAL = 0.2


def default_workers(n_runs: int) -> int:
    """One worker per core this process may run on, no more than there are runs (at least
    one).

    Returns
    -------
    int

    Examples
    --------
    >>> default_workers(1)
    1
    """
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return max(1, min(cores or 1, n_runs))


def run_parallel(
    function: Callable,
    calls: Sequence[tuple],
    *,
    steps: Sequence[int],
    workers: int | None = None,
    desc: str = "runs",
    progress: bool = True,
) -> list:
    """``[function(*args, progress=bar) for args in calls]``, each call on a worker process.

    Parameters
    ----------
    function : callable
        A module-level function (the workers import it by name) that runs co-simulations and
        passes its ``progress`` argument on to :func:`~.master.run`; its arguments and result
        must pickle.
    calls : sequence of tuple
        The positional arguments of each call.
    steps : sequence of int
        The communication steps of each call (the bar's total; the longest calls start first).
    workers : int, optional
        Worker processes (default: :func:`default_workers`); 1 runs the calls here, in order.
    desc : str
        The bar's label.
    progress : bool
        Show the bar (after two seconds).

    Returns
    -------
    list
        The results, in the order of ``calls``.

    Examples
    --------
    >>> def square(x, progress):
    ...     progress.update(1)
    ...     return x * x
    >>> run_parallel(square, [(2,), (3,)], steps=[1, 1], workers=1, progress=False)
    [4, 9]
    """
    n = default_workers(len(calls)) if workers is None else workers
    if type(n) is not int or n < 1:
        raise ValueError(f"workers = {workers!r} must be a whole number ≥ 1")
    bar = progress_bar(sum(steps), desc=desc, unit="step", enabled=progress)
    try:
        if n == 1 or len(calls) == 1:
            return [function(*args, progress=bar) for args in calls]
        return _on_workers(function, calls, steps, min(n, len(calls)), bar)
    finally:
        bar.close()


def _on_workers(function, calls, steps, n: int, bar) -> list:
    import multiprocessing
    from concurrent.futures import FIRST_EXCEPTION, ProcessPoolExecutor, wait

    context = multiprocessing.get_context("spawn")
    messages, stop = context.Queue(), context.Event()
    order = sorted(range(len(calls)), key=lambda i: -steps[i])  # the longest first
    pids: set[int] = set()
    with (
        interruptible() as stop_request,
        ProcessPoolExecutor(
            n, mp_context=context, initializer=_start, initargs=(messages, stop)
        ) as pool,
    ):
        futures = {i: pool.submit(_call, function, calls[i]) for i in order}
        pending, stopping = set(futures.values()), False
        while pending:
            _, pending = wait(pending, timeout=REPORT_INTERVAL, return_when=FIRST_EXCEPTION)
            _drain(messages, bar, pids)
            failed = any(f.done() and not f.cancelled() and f.exception() for f in futures.values())
            asked = stop_request is not None and stop_request.requested
            if (failed or asked) and not stopping:
                stopping = True
                stop.set()  # a call not yet started does not start
                for f in futures.values():
                    f.cancel()
                for pid in pids:  # a call running stops (a run at its next step boundary)
                    _signal(pid)
        _drain(messages, bar, pids)
        return _results([futures[i] for i in range(len(calls))], stop_request)


def _results(futures, stop_request) -> list:
    """Every call's result; else the first failure that is not an interruption, then the
    first interruption (a run's, with its rows)."""
    from concurrent.futures.process import BrokenProcessPool

    errors = [f.exception() for f in futures if not f.cancelled() and f.exception()]
    for exc in errors:
        if isinstance(exc, BrokenProcessPool):
            raise HarnessError(
                f"a worker process ended abruptly ({exc}): run with workers=1 to see where"
            ) from exc
    failures = [e for e in errors if not isinstance(e, Interrupted | KeyboardInterrupt)]
    if failures:
        raise failures[0]
    if stopped := [e for e in errors if isinstance(e, Interrupted)]:
        raise stopped[0]
    if errors or any(f.cancelled() for f in futures):
        signum = stop_request.signum if stop_request is not None else signal.SIGINT
        raise Interrupted("interrupted between two runs", signum=signum)
    return [f.result() for f in futures]


def _signal(pid: int) -> None:
    try:
        os.kill(pid, signal.SIGINT)
    except ProcessLookupError:  # pragma: no cover - the worker has just ended
        pass


def _drain(messages, bar, pids: set[int]) -> None:
    """The workers' messages so far: their process ids, steps done."""
    import queue

    while True:
        try:
            kind, value = messages.get_nowait()
        except queue.Empty:
            return
        if kind == "pid":
            pids.add(value)
        else:
            bar.update(value)


# ---------------------------------------------------------------------------- in a worker
_MESSAGES = _STOP = None
_BUSY = False  # a call is running in this worker


def _start(messages, stop) -> None:
    """A worker's set-up: SIGINT (Ctrl-C from the terminal, or the caller stopping the runs)
    stops a call in progress (a co-simulation at its next step boundary, anything else at
    once) and leaves an idle worker alone; once the caller sets ``stop`` no call starts; the
    caller learns the process id to stop it by."""
    global _MESSAGES, _STOP
    signal.signal(signal.SIGINT, _interrupt_call)
    _MESSAGES, _STOP = messages, stop
    messages.put(("pid", os.getpid()))


def _interrupt_call(signum, frame):
    if _BUSY:
        raise KeyboardInterrupt


def _call(function, args):
    global _BUSY
    reporter = _Reporter(_MESSAGES)
    _BUSY = True  # before the check: a stop set after it comes as a signal
    try:
        if _STOP.is_set():
            raise KeyboardInterrupt
        return function(*args, progress=reporter)
    finally:
        _BUSY = False
        reporter.flush()


class _Reporter:
    """A worker's side of the bar: the steps done, sent at most every
    :data:`REPORT_INTERVAL` seconds."""

    def __init__(self, messages):
        self.messages, self.pending, self.sent = messages, 0, time.monotonic()

    def update(self, n: int = 1) -> None:
        self.pending += n
        if time.monotonic() - self.sent >= REPORT_INTERVAL:
            self.flush()

    def flush(self) -> None:
        if self.pending:
            self.messages.put(("steps", self.pending))
        self.pending, self.sent = 0, time.monotonic()

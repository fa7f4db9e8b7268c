"""Progress bars (tqdm) for long runs and sweeps: live on a terminal; when stderr is a file
or a pipe (a log, CI), one status line a minute at most instead of a redraw every 0.1 s."""

from __future__ import annotations

import sys

#: Seconds between two updates written to a stderr that is not a terminal.
QUIET_INTERVAL = 60.0


def progress_bar(total: int, *, desc: str, unit: str, enabled: bool = True, delay: float = 2.0):
    """A tqdm bar over ``total`` items on stderr, shown after ``delay`` seconds; disabled
    when ``enabled`` is false."""
    from tqdm import tqdm

    tty = sys.stderr.isatty()
    return tqdm(
        total=total,
        desc=desc,
        unit=unit,
        disable=not enabled,
        delay=delay,
        leave=not tty,  # a log keeps its last status line; a terminal is tidied up
        mininterval=0.1 if tty else QUIET_INTERVAL,
        maxinterval=10.0 if tty else QUIET_INTERVAL,
        ascii=not tty,
        dynamic_ncols=tty,
        file=sys.stderr,
    )

"""Independent runs on worker processes (servofmu.harness.pool): results in order, a failure
or a stop request stops every run at its next step and is raised, with the rows so far."""

from __future__ import annotations

import os
import signal
import threading
import time
from pathlib import Path

import pytest

from servofmu.harness.errors import HarnessError, Interrupted
from servofmu.harness.pool import run_parallel


# the calls: module-level, so that a spawned worker imports them by name
def _square(x, progress):
    progress.update(x)
    return x * x, os.getpid()


def _until_stopped(marker, progress):
    """A stand-in for a co-simulation: steps until a stop request, then raises Interrupted
    with its steps so far (as a run does with its rows)."""
    from servofmu.harness.interrupt import interruptible

    Path(marker).touch()
    with interruptible() as request:
        for k in range(200_000):  # 20 s at most
            if request.requested:
                raise Interrupted(f"stopped at step {k}", result=k, signum=request.signum)
            progress.update(1)
            time.sleep(1e-4)
    return -1


def _fails(progress):
    progress.update(1)
    raise HarnessError("component 'bearing' returned fmi2Error")


def _dispatch(kind, marker, progress):
    return _until_stopped(marker, progress) if kind == "wait" else _fails(progress)


class _Bar:
    """Counts the steps a progress bar is advanced by."""

    def __init__(self):
        self.n = 0

    def update(self, n=1):
        self.n += n

    def close(self):
        pass


@pytest.mark.slow
def test_calls_run_here_or_on_workers_with_the_same_results_in_order(monkeypatch):
    import servofmu.harness.pool as pool

    bar = _Bar()
    monkeypatch.setattr(pool, "progress_bar", lambda total, **kw: bar)
    here = run_parallel(_square, [(1,), (2,), (3,)], steps=[1, 2, 3], workers=1)
    assert [r[0] for r in here] == [1, 4, 9] and {r[1] for r in here} == {os.getpid()}
    assert bar.n == 6
    there = run_parallel(_square, [(1,), (2,), (3,)], steps=[1, 2, 3], workers=2)
    assert [r[0] for r in there] == [1, 4, 9] and os.getpid() not in {r[1] for r in there}
    assert bar.n == 12  # each worker's steps reached the caller's bar
    with pytest.raises(ValueError, match="workers = 0"):
        run_parallel(_square, [(1,)], steps=[1], workers=0)


@pytest.mark.slow
def test_a_failing_run_stops_the_others_and_its_error_is_raised(tmp_path):
    t0 = time.perf_counter()
    with pytest.raises(HarnessError, match="fmi2Error") as err:
        run_parallel(
            _dispatch,
            [("wait", str(tmp_path / "a")), ("fail", "")],
            steps=[200_000, 1],
            workers=2,
            progress=False,
        )
    assert not isinstance(err.value, Interrupted)
    assert time.perf_counter() - t0 < 15.0  # the waiting run was stopped, not waited for


@pytest.mark.slow
def test_ctrl_c_stops_every_running_run_at_a_step_and_keeps_its_rows(tmp_path):
    markers = [tmp_path / "a", tmp_path / "b"]

    def interrupt_once_both_run():
        deadline = time.monotonic() + 30.0
        while not all(m.exists() for m in markers) and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.3)
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=interrupt_once_both_run, daemon=True).start()
    with pytest.raises(Interrupted) as err:
        run_parallel(
            _until_stopped,
            [(str(m),) for m in markers],
            steps=[200_000, 200_000],
            workers=2,
            progress=False,
        )
    assert isinstance(err.value.result, int) and err.value.result > 0  # the rows so far
    assert err.value.signum == signal.SIGINT


def test_a_run_advances_an_open_bar_by_its_steps(fmus):
    """run(progress=bar): a caller's bar (a scenario's, over its runs) counts the run's steps
    and stays open."""
    from servofmu.harness import run

    bar = _Bar()
    res = run(
        fmus["BearingFriction"].parent / "seeker_gimbal.ssp",
        stop=0.2,
        record=["motor.speed"],
        progress=bar,
    )
    assert bar.n == 200 and len(res.data) == 201

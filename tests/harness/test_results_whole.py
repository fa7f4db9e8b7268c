"""Results whole or marked: a result reaches its name whole (a temporary name in its folder,
then a rename) or not at all; a signal waits until it is in place; a run that ended early says
so in its table; a full disk or a folder that cannot be written exits 74 naming the path; a
killed run's temporary files are cleaned by the next run; a sweep's cleanup after a signal is
protected from a second one, a run lost with its worker runs again, and a failed run makes
the sweep exit non-zero."""

from __future__ import annotations

import errno
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from servofmu import cli, files
from servofmu.harness.interrupt import Terminated, protected, terminate_as_interrupt
from servofmu.harness.sweep import SweepResult

CLI = (sys.executable, "-m", "servofmu.cli")


@pytest.fixture
def sigterm_raises():
    """SIGTERM raises Terminated here, as under the command line (restored afterwards)."""
    previous = signal.getsignal(signal.SIGTERM)
    terminate_as_interrupt()
    yield
    signal.signal(signal.SIGTERM, previous)


def _leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if files.PART_SUFFIX in p.name)


def test_a_signal_while_a_result_is_written_waits_until_it_is_whole(tmp_path, sigterm_raises):
    target = tmp_path / "table.csv"
    with pytest.raises(Terminated):
        with files.written(target) as part, part.open("w") as fh:
            for i in range(1000):
                fh.write(f"{i}\n")
                if i == 10:
                    os.kill(os.getpid(), signal.SIGTERM)  # held until the file is in place
    assert target.read_text().splitlines() == [str(i) for i in range(1000)]
    assert _leftovers(tmp_path) == []


def test_a_failed_write_leaves_nothing_under_either_name(tmp_path):
    target = tmp_path / "table.csv"
    target.write_text("the old table\n")
    with pytest.raises(RuntimeError), files.written(target) as part:
        part.write_text("half")
        raise RuntimeError("the writer failed")
    assert target.read_text() == "the old table\n" and _leftovers(tmp_path) == []


def test_results_get_the_umasks_mode(tmp_path):
    old = os.umask(0o027)
    try:
        path = files.write_text(tmp_path / "r.txt", "x")
    finally:
        os.umask(old)
    assert path.stat().st_mode & 0o777 == 0o640


def test_a_stopped_runs_table_says_where_and_why_it_ended(tmp_path):
    from servofmu.harness.master import RunResult
    from servofmu.harness.units import read_results

    data = np.rec.fromarrays([[0.0, 0.1], [1.0, 2.0]], names="time,m.x").view(np.ndarray)
    res = RunResult("demo", data, failed=True, message="interrupted (SIGTERM)\nat a step")
    path = res.to_csv(tmp_path / "results.csv")
    assert path.read_text().splitlines()[-1] == (
        "# incomplete: the run ended at t = 0.1 s, before its stop time: interrupted "
        "(SIGTERM) at a step"
    )
    back, _ = read_results(path)
    assert list(back["m.x"]) == [1.0, 2.0]
    whole = RunResult("demo", data).to_csv(tmp_path / "whole.csv")
    assert "incomplete" not in whole.read_text()


def _no_space(self, *args, **kwargs):
    raise OSError(errno.ENOSPC, "No space left on device")


def test_a_full_disk_exits_74_naming_the_file_and_leaves_no_partial_file(
    tmp_path, monkeypatch, capsys
):
    target = tmp_path / "preset.ssv"
    real = Path.write_text

    def half_then_full(self, text, *args, **kwargs):
        real(self, text[: len(text) // 2], *args, **kwargs)
        _no_space(self)

    monkeypatch.setattr(Path, "write_text", half_then_full)
    rc = cli.main(["catalog", "--mounting", "yu2017_gimbal", "--ssv", str(target)])
    err = capsys.readouterr().err
    assert rc == files.EXIT_OUTPUT, err
    assert f"cannot write {target}: No space left on device" in err
    assert not target.exists() and _leftovers(tmp_path) == []


def test_a_folder_that_cannot_be_written_exits_74_naming_it(tmp_path, capsys):
    blocker = tmp_path / "a_file"
    blocker.write_text("not a folder")
    rc = cli.main(["catalog", "--mounting", "yu2017_gimbal", "--ssv", str(blocker / "p.ssv")])
    err = capsys.readouterr().err
    assert rc == files.EXIT_OUTPUT and f"cannot write {blocker}" in err, err


def test_a_killed_runs_partial_file_is_removed_by_the_next_write(tmp_path, monkeypatch):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True).stdout.strip()  # fmt: skip
    stale = tmp_path / f".results.csv.{dead}.abcd1234.part.csv"
    stale.write_text("half a table")
    live = tmp_path / f".other.csv.{os.getpid()}.abcd1234.part.csv"  # a live writer's
    live.write_text("being written")
    monkeypatch.setattr(files, "_CLEANED", set())
    files.write_text(tmp_path / "results.csv", "whole\n")
    assert not stale.exists() and live.exists()


def test_a_killed_runs_scratch_folder_is_removed_by_the_next_run(fmus, tmp_path):
    ssp = fmus["BearingFriction"].parent / "seeker_gimbal.ssp"
    env = {**os.environ, "TMPDIR": str(tmp_path), "PYTHONUNBUFFERED": "1"}
    child = subprocess.Popen(
        [*CLI, "run", str(ssp), "--stop", "1000", "--out", str(tmp_path / "out")],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
    )  # fmt: skip
    try:
        assert "Ctrl-C" in child.stdout.readline()
        time.sleep(0.5)
    finally:
        child.kill()
        child.wait()
    root = tmp_path / f"servofmu-{os.getuid()}"
    left = [p.name for p in root.iterdir()]
    assert any(name.startswith(f"servofmu_ssp_{child.pid}-") for name in left), left
    code = "from servofmu.files import scratch_folder; scratch_folder('next_').cleanup()"
    subprocess.run([sys.executable, "-c", code], env=env, check=True)
    assert list(root.iterdir()) == []


# ----------------------------------------------------------------------------- sweeps
def _rows(n):
    return [{"temperature": 200.0 + i, "running_torque": 1e-3 * i} for i in range(n)]


def test_a_sigterm_while_a_sweep_writes_its_table_leaves_it_whole(tmp_path, monkeypatch, capsys):
    from servofmu.harness import sweep

    n = 40_000
    monkeypatch.setattr(sweep, "run_sweep", lambda *a, **k: SweepResult(_rows(n), 1, 0.1))
    real_cell, count = sweep._cell, [0]

    def cell(v):
        count[0] += 1
        if count[0] == 300:  # SIGTERM in the middle of the table
            os.kill(os.getpid(), signal.SIGTERM)
        return real_cell(v)

    monkeypatch.setattr(sweep, "_cell", cell)
    out = tmp_path / "s.csv"
    argv = ["sweep", "model", "--grid", "temperature=250,260", "--out", str(out)]
    previous = signal.getsignal(signal.SIGTERM)
    try:
        rc = cli.main(argv)
    finally:
        signal.signal(signal.SIGTERM, previous)
    assert rc == 143, capsys.readouterr().err
    assert len(out.read_text().splitlines()) == n + 1  # the header and every row
    assert _leftovers(tmp_path) == []


def test_a_second_signal_during_a_sweeps_cleanup_loses_no_row(monkeypatch, sigterm_raises):
    import dask.distributed

    from servofmu.harness.sweep import ModelTask, grid_points, run_sweep
    from servofmu.parameters.bearing import default_parameters

    real = dask.distributed.as_completed

    def interrupted_after_one(futures):
        it = real(futures)
        yield next(it)
        raise Terminated("terminated (SIGTERM)")  # the first signal

    class SlowToClose(dask.distributed.Client):
        signalled = False

        def close(self, *a, **k):
            if not self.signalled:
                self.signalled = True
                os.kill(os.getpid(), signal.SIGTERM)  # the second, while the cluster closes
            return super().close(*a, **k)

    monkeypatch.setattr(dask.distributed, "as_completed", interrupted_after_one)
    with dask.distributed.LocalCluster(n_workers=1, processes=False, dashboard_address=":0") as c:
        client = SlowToClose(c)
        monkeypatch.setattr(dask.distributed, "Client", lambda *a: client)
        points = grid_points({"temperature": [233.15, 253.15, 273.15]})
        task = ModelTask(default_parameters("yu2017_gimbal"), ("running_torque",))
        res = run_sweep(task, points, scheduler="tcp://ignored", chunk_size=1, progress=False)
    assert res.interrupted
    assert sum("error" not in r for r in res.rows) == 1
    assert [r["error"] for r in res.rows if "error" in r] == ["interrupted"] * 2


def test_a_sweep_with_a_failed_run_exits_1(tmp_path, monkeypatch, capsys):
    from servofmu.harness import sweep

    rows = _rows(3)
    rows[1]["error"] = "ValueError: locked"
    monkeypatch.setattr(sweep, "run_sweep", lambda *a, **k: SweepResult(rows, 1, 0.1))
    out = tmp_path / "s.csv"
    assert cli.main(["sweep", "model", "--grid", "temperature=250", "--out", str(out)]) == 1
    assert "1 failed" in capsys.readouterr().out and out.exists()


class _DiesOnce:
    """A task whose worker dies the first time any worker runs a chunk (a marker file remembers)."""

    def __init__(self, marker):
        self.marker = str(marker)

    def check(self, points):
        pass

    def __call__(self, points):
        try:  # created exclusively: of two chunks started together, one worker dies
            fd = os.open(self.marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
        except FileExistsError:
            return [dict(p, y=2 * p["x"]) for p in points]
        os.close(fd)
        os._exit(1)  # the worker process dies with the chunk


@pytest.mark.slow
def test_a_run_lost_with_its_worker_runs_again_while_workers_remain(tmp_path):
    import dask
    from dask.distributed import Client, LocalCluster

    from servofmu.harness.sweep import grid_points, run_sweep

    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as c:
            with Client(c) as client:
                res = run_sweep(
                    _DiesOnce(tmp_path / "marker"), grid_points({"x": [0, 1, 2, 3]}),
                    client=client, chunk_size=2, progress=False,
                )  # fmt: skip
    assert (tmp_path / "marker").exists()  # a worker did die
    assert [r.get("y") for r in res.rows] == [0, 2, 4, 6], res.rows


def test_protected_holds_signals_and_raises_one_afterwards(sigterm_raises):
    with pytest.raises(Terminated):
        with protected() as held:
            os.kill(os.getpid(), signal.SIGTERM)
            os.kill(os.getpid(), signal.SIGTERM)
            assert held == [signal.SIGTERM, signal.SIGTERM]
    with protected(reraise=False) as held:
        os.kill(os.getpid(), signal.SIGTERM)
    assert held == [signal.SIGTERM]

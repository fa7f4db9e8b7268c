"""Safe concurrent use of one build folder: two builds at once both succeed (one waits on the
folder's lock and says so), a run started meanwhile waits for the build instead of reading a
half-written archive, and every FMU and system gets the mode the umask gives files."""

from __future__ import annotations

import os
import subprocess
import sys
import time
import zipfile

import pytest

CLI = (sys.executable, "-m", "servofmu.cli")


@pytest.mark.slow
def test_two_builds_and_a_run_at_once_in_one_folder_all_succeed(tmp_path):
    env = {**os.environ, "PYTHONUNBUFFERED": "1", "TMPDIR": str(tmp_path)}

    def start(*args):
        return subprocess.Popen(
            [*CLI, *args], cwd=tmp_path, env=env, text=True,
            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        )  # fmt: skip

    first = start("build")
    time.sleep(0.5)
    second = start("build")
    run = start("run", "seeker_gimbal", "--stop", "0.01", "--out", "out")
    results = [p.communicate(timeout=600) for p in (first, second, run)]
    codes = [p.returncode for p in (first, second, run)]
    assert codes == [0, 0, 0], results
    waited = [err for _, err in results if "waiting for another build in" in err]
    assert waited, results  # someone waited on the lock, and said so
    build = tmp_path / "build" / "out"
    for path in [*build.glob("*.fmu"), *build.glob("*.ssp")]:
        with zipfile.ZipFile(path) as zf:
            assert zf.testzip() is None, path
        assert path.stat().st_mode & 0o777 == 0o666 & ~_umask(), path
    assert not [p for p in build.iterdir() if ".part" in p.name]
    assert (tmp_path / "out" / "results.csv").is_file()


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask

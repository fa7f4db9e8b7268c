"""Every test file is collected: no folder of tests/ bears a name that pytest skips
(``norecursedirs``: ``build``, ``dist``, ``venv``, dot-folders, …), which would drop its tests
without a word."""

from __future__ import annotations

from fnmatch import fnmatch
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1]


def test_no_test_folder_is_one_pytest_skips(pytestconfig):
    skipped = pytestconfig.getini("norecursedirs")
    folders = {p.parent for p in TESTS.rglob("test_*.py")}
    hidden = [
        f.relative_to(TESTS).as_posix()
        for f in folders
        for part in f.relative_to(TESTS).parts
        if any(fnmatch(part, pattern) for pattern in skipped)
    ]
    assert hidden == [], f"pytest does not collect tests in {hidden} (norecursedirs {skipped})"

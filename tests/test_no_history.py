"""History lives in CHANGELOG.md: no issue number ("issue 17", "#17") and no commit hash in the
files a reader reads as the state of the project. FILES lists them; extend it (code, comments,
README, docs) as they are cleaned."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "fmu_src" / "servofmu" / "physics" / "data"

#: Files checked, relative to the repository root: the catalogue data (but the two tables still
#: being rewritten elsewhere, lubricants.toml and grease_torques.toml, which join once cleaned),
#: the documentation's pages and examples, and the next README.
FILES = sorted(
    p.relative_to(ROOT).as_posix()
    for p in (
        *DATA.glob("*.toml"),
        *(ROOT / "docs").glob("*.md"),
        *(ROOT / "docs").glob("*.rst"),
        *(ROOT / "docs" / "guide").glob("*.md"),
        *(ROOT / "docs" / "gallery").glob("*.py"),
    )
    if p.name not in ("lubricants.toml", "grease_torques.toml")
)

#: What history looks like: an issue of this project by number, or a commit hash (7 to 40 hex
#: digits with at least one digit and one letter, not part of a number such as 6.248662e7).
PATTERNS = {
    "issue number": re.compile(r"\bissues?\s*#?\d+|(?<![\w&#/])#\d+\b", re.IGNORECASE),
    "commit hash": re.compile(
        r"(?<![\w.])(?!\d+e\d+\b)(?=[0-9a-f]*\d)(?=[0-9a-f]*[a-f])[0-9a-f]{7,40}\b"
    ),
}


def history(text: str) -> list[str]:
    """The issue numbers and commit hashes in ``text``, as found."""
    return [m.group(0) for pattern in PATTERNS.values() for m in pattern.finditer(text)]


@pytest.mark.parametrize(
    ("text", "found"),
    [
        ("fixed in issue 17", ["issue 17"]),
        ("see #11 and Issues #3", ["Issues #3", "#11"]),
        ("Before: commit ec2b445", ["ec2b445"]),
        ("d118a3e", ["d118a3e"]),
        ("bearing No. 6204, 71807C, 1e-7, ISO 15:2017, color #ccc", []),
        ("a decade of accessed facades, 1234567, 6.248662e7, 1234567e8", []),
    ],
)
def test_the_patterns_find_history_and_nothing_else(text, found):
    assert sorted(history(text)) == sorted(found)


@pytest.mark.parametrize("name", FILES)
def test_no_history_in(name):
    found = history((ROOT / name).read_text(encoding="utf-8"))
    assert not found, f"{name}: {found} (history belongs in CHANGELOG.md)"

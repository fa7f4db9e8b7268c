"""History lives in CHANGELOG.md: no issue number ("issue 17", "#17") and no commit hash in the
files a reader reads as the state of the project (the README, the documentation, the code and its
comments, the tests, the catalogue data), and no research log in the catalogue data: a
provenance is a citation a reader can follow, not the story of how it was looked for."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "fmu_src" / "servofmu" / "parameters" / "data"
#: Generated or third-party files, and this test (its examples are history on purpose).
SKIP = ("docs/_build/", "docs/_generated/", "docs/auto_examples/", "docs/api/generated/",
        "build/export/src/", "build/out/", "tests/project/test_no_history.py")  # fmt: skip
#: The project's text, relative to the repository root: the README, the documentation's pages
#: and examples, the code (package, build, harness, benchmarks, tests), the SSP notes, the
#: examples, the catalogue data and the project files.
FILES = sorted(
    name
    for pattern in (
        "README.md",
        "Makefile",
        "pyproject.toml",
        "setup.py",
        "setup.cfg",
        "MANIFEST.in",
        "docs/**/*.md",
        "docs/**/*.rst",
        "docs/**/*.py",
        "fmu_src/**/*.py",
        "fmu_src/**/*.toml",
        "build/**/*.py",
        "build/**/*.md",
        "harness/**/*.py",
        "benchmarks/**/*.py",
        "tests/**/*.py",
        "tests/**/*.c",
        "ssp/**/*.md",
        "examples/**/*.py",
        "examples/**/*.toml",
        "examples/**/*.md",
    )
    for p in ROOT.glob(pattern)
    if p.is_file()
    and "__pycache__" not in p.parts
    and not (name := p.relative_to(ROOT).as_posix()).startswith(SKIP)
)
#: The catalogue data, where a provenance must read as a citation.
CATALOGUES = sorted(p.relative_to(ROOT).as_posix() for p in DATA.glob("*.toml"))

#: What history looks like: an issue of this project by number, or a commit hash (7 to 40 hex
#: digits with at least one digit and one letter, not part of a number such as 6.248662e7).
PATTERNS = {
    "issue number": re.compile(r"\bissues?\s*#?\d+|(?<![\w&#/])#\d+\b", re.IGNORECASE),
    "commit hash": re.compile(
        r"(?<![\w.])(?!\d+e\d+\b)(?=[0-9a-f]*\d)(?=[0-9a-f]*[a-f])[0-9a-f]{7,40}\b"
    ),
}


#: What a research log looks like in a provenance: where a copy was stored or how it was read,
#: instead of what it is.
RESEARCH_LOG = re.compile(
    r"\bin this work\b|\bstored (?:copy|copies|code|page|part|address)\b|\bcode id\b|"
    r"\bnot opened\b|\byumpu\b|\bcould not be (?:opened|sourced|found)\b",
    re.IGNORECASE,
)


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


@pytest.mark.parametrize(
    ("text", "found"),
    [
        ("the paper itself not opened in this work", ["not opened", "in this work"]),
        ("as transcribed in a public repository (stored code id 69817465099)", ["stored code"]),
        ("yumpu document 55668573", ["yumpu"]),
        ("Bessette, NASA CP-3350 (1997), Table 6; value as transcribed, original not checked", []),
    ],
)
def test_the_research_log_pattern(text, found):
    assert sorted(m.group(0) for m in RESEARCH_LOG.finditer(text)) == sorted(found)


def test_the_files_include_code_tests_and_every_catalogue():
    assert set(CATALOGUES) <= set(FILES)
    for name in ("README.md", "fmu_src/servofmu/fmus/runtime.py", "tests/project/test_readme.py",
                 "harness/master.py",
                 "fmu_src/servofmu/parameters/data/lubricants.toml"):  # fmt: skip
        assert name in FILES, name


def _refs(node) -> list[str]:
    """Every provenance (``ref``) string in a catalogue's parsed data."""
    if isinstance(node, dict):
        return [v for k, v in node.items() if k == "ref" and isinstance(v, str)] + [
            r for v in node.values() for r in _refs(v)
        ]
    return [r for v in node for r in _refs(v)] if isinstance(node, list) else []


@pytest.mark.parametrize("name", CATALOGUES)
def test_provenance_is_a_citation_in(name):
    # the whole file, comments included; a catalogue that keeps a record of the candidate
    # sources searched for (``[[searched]]``: what of each could be read, printed by the
    # validation report) is checked on its values' provenance
    text = (ROOT / name).read_text(encoding="utf-8")
    data = tomllib.loads(text)
    checked = "\n".join(_refs(data)) if "searched" in data else text
    found = [m.group(0) for m in RESEARCH_LOG.finditer(checked)]
    assert not found, f"{name}: {found} (cite the source a reader can follow)"

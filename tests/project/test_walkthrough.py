"""The "Model your own gimbal" walkthrough works when typed as written from a fresh clone
after ``make run``: the shell blocks of that section of the documentation are run, exactly as
they stand, in a folder laid out as a clone (the examples, and the ``.venv`` that ``make run``
made), and the files the walkthrough promises are there.

Every ``sh`` block of the section is a command sequence to run (Markdown fences ```` ```sh ````,
or reStructuredText ``.. code-block:: sh``): write any listing that must not run in another
language (``text``). :data:`DOCUMENT` and :data:`SECTION` name the page and its section.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: The document that holds the walkthrough, and the title of its section.
DOCUMENT = ROOT / "docs" / "guide" / "own_gimbal.md"
SECTION = "Model your own gimbal"


_UNDERLINE = re.compile(r"([=\-~^\"'`#*+])\1{2,}")


def section_text(text: str, title: str) -> str:
    """The section of a Markdown or reStructuredText document whose heading is ``title``,
    up to the next heading of the same or a higher level (reStructuredText: the levels are
    the underline characters in the order the document first uses them).

    Returns
    -------
    str
        The section's text (heading included); ValueError when there is none.

    Examples
    --------
    >>> md = "# A\\n## Own\\nx\\n```sh\\n# a comment\\n```\\n### sub\\ny\\n## Next\\nz\\n"
    >>> section_text(md, "Own").splitlines()
    ['## Own', 'x', '```sh', '# a comment', '```', '### sub', 'y']
    >>> rst = "Top\\n===\\nOwn\\n---\\nx\\n\\nSub\\n~~~\\ny\\n\\nNext\\n----\\nz\\n"
    >>> section_text(rst, "Own").splitlines()
    ['Own', '---', 'x', '', 'Sub', '~~~', 'y']
    """
    lines = text.splitlines()
    headings = []  # (line, level): Markdown "#" count, or the rank of an rst underline
    order: list[str] = []
    fenced = False  # inside a Markdown code fence: no headings there
    for i, line in enumerate(lines):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        if m := re.match(r"(#+)\s+(.*?)\s*$", line):
            headings.append((i, len(m.group(1)), m.group(2)))
        elif line.strip() and i + 1 < len(lines) and _UNDERLINE.fullmatch(lines[i + 1]):
            char = lines[i + 1][0]
            order += [] if char in order else [char]
            headings.append((i, order.index(char) + 1, line.strip()))
    for k, (i, level, name) in enumerate(headings):
        if name == title:
            end = next((j for j, lv, _ in headings[k + 1 :] if lv <= level), len(lines))
            return "\n".join(lines[i:end])
    raise ValueError(f"no section {title!r}")


def shell_blocks(section: str) -> list[str]:
    """The ``sh`` code blocks of a section, in order (Markdown fences or reStructuredText
    ``code-block:: sh`` directives).

    Returns
    -------
    list of str

    Examples
    --------
    >>> shell_blocks("a\\n```sh\\nls\\n```\\n```text\\nnot run\\n```\\n")
    ['ls\\n']
    >>> shell_blocks(".. code-block:: sh\\n\\n   ls -l\\n   pwd\\n\\nafter\\n")
    ['ls -l\\npwd\\n']
    """
    blocks = re.findall(r"^```(?:sh|bash|shell)\n(.*?)^```", section, flags=re.S | re.M)
    for body in re.findall(
        r"^\.\. code-block:: (?:sh|bash|shell)\n\n((?:[ \t]+.*\n|\n)+)", section, flags=re.M
    ):
        lines = body.rstrip("\n").splitlines()
        indent = min(len(x) - len(x.lstrip()) for x in lines if x.strip())
        blocks.append("\n".join(x[indent:] for x in lines) + "\n")
    return blocks


def test_the_section_has_the_walkthrough():
    blocks = shell_blocks(section_text(DOCUMENT.read_text(encoding="utf-8"), SECTION))
    text = "".join(blocks)
    # it starts by copying the example, and covers the loop of the issue
    assert blocks and "cp examples/my_gimbal_catalog.toml my.toml" in blocks[0]
    for step in ("servofmu build --catalog my.toml", "servofmu scenario", "servofmu run",
                 "servofmu calibrate", "--catalog calibration/calibrated.toml"):  # fmt: skip
        assert step in text, step


@pytest.fixture(scope="module")
def clone(tmp_path_factory):
    """A folder as a fresh clone looks after ``make run``: the examples, and the project's
    virtual environment as ``.venv`` (the one running these tests)."""
    folder = tmp_path_factory.mktemp("clone")
    shutil.copytree(ROOT / "examples", folder / "examples")
    venv = Path(sys.prefix)
    if not (venv / "bin" / "activate").is_file():
        pytest.skip(f"the tests do not run in a virtual environment ({venv}): no .venv to use")
    (folder / ".venv").symlink_to(venv, target_is_directory=True)
    return folder


@pytest.mark.slow
def test_the_walkthrough_runs_as_written(clone):
    blocks = shell_blocks(section_text(DOCUMENT.read_text(encoding="utf-8"), SECTION))
    env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHONPATH")}
    env["PATH"] = os.pathsep.join(  # servofmu is not on the PATH until the block says so
        p for p in env.get("PATH", "").split(os.pathsep) if not p.startswith(sys.prefix)
    )
    env["MPLBACKEND"] = "Agg"
    script = "set -e -o pipefail\n" + "\n".join(blocks)
    done = subprocess.run(
        ["bash", "-c", script], cwd=clone, env=env, capture_output=True, text=True, timeout=1800
    )
    assert done.returncode == 0, (done.stdout[-3000:], done.stderr[-3000:])
    # what it promises: the user's build, its three gimbal rigs, the scenario's table and
    # plot on the user's gimbal, the calibration as a catalogue, and the rebuild with it
    build = clone / "build" / "my_gimbal"
    assert sorted(p.name for p in build.glob("*.ssp")) == [
        "seeker_gimbal.ssp",
        "seeker_gimbal_chamber.ssp",
        "seeker_gimbal_position.ssp",
    ]
    assert not (clone / "build" / "out").exists()  # nothing of the standard mechanism needed
    table = clone / "out" / "friction_vs_temperature" / "friction_vs_temperature.csv"
    assert table.is_file() and "mechanism my_gimbal" in done.stdout
    assert "Yu 2017 [N.mm]" not in (table.parent / "friction_models.csv").read_text()
    calibrated = (clone / "calibration" / "calibrated.toml").read_text()
    assert "[coefficients.my_gimbal]" in calibrated and "standard_error" in calibrated
    assert "calibrated by the user (set my_gimbal" in done.stdout  # the rebuilt scenario says so


def test_the_extraction_follows_its_examples():
    import doctest

    result = doctest.testmod(sys.modules[__name__])
    assert result.attempted >= 4 and result.failed == 0, result

"""Golden modelDescription.xml files: each FMU's public interface (variables, units, items,
dependencies) committed in ``build/model_descriptions/``, so that a change of the API shows in
a diff. ``tests/fmus/test_golden.py`` checks that a fresh build gives the same text.

Regenerate them after a deliberate change with::

    .venv/bin/python -m servofmu.build.golden

The volatile attributes are normalised: ``guid`` (new at every build) and
``generationDateAndTime``.
"""

from __future__ import annotations

import re
import sys
import tempfile
import zipfile
from pathlib import Path

GOLDEN_DIR = Path(__file__).resolve().parent / "model_descriptions"
_VOLATILE = (
    (re.compile(r' guid="[^"]*"'), ' guid="normalised"'),
    (re.compile(r' generationDateAndTime="[^"]*"'), ""),
)


def normalised(xml: str) -> str:
    """``xml`` (a modelDescription) with its volatile attributes normalised.

    >>> normalised('<a guid="{1}" generationDateAndTime="2026-01-01T00:00:00Z" b="c"/>')
    '<a guid="normalised" b="c"/>'
    """
    for pattern, replacement in _VOLATILE:
        xml = pattern.sub(replacement, xml)
    return xml


def model_description(fmu: Path) -> str:
    """The normalised modelDescription.xml of the built FMU at ``fmu``."""
    with zipfile.ZipFile(fmu) as zf:
        return normalised(zf.read("modelDescription.xml").decode("utf-8"))


def golden_path(name: str) -> Path:
    """Where the golden modelDescription of FMU ``name`` lives."""
    return GOLDEN_DIR / f"{name}.xml"


def update(names=None) -> list[Path]:
    """Build the FMUs ``names`` (default: all) into a temporary folder and write their
    normalised modelDescriptions to :data:`GOLDEN_DIR`; returns the files written."""
    from .fmu import FMUS, build_fmu

    written = []
    with tempfile.TemporaryDirectory(prefix="servofmu_golden_") as tmp:
        for name in names or FMUS:
            path = golden_path(name)
            path.write_text(model_description(build_fmu(name, Path(tmp))), encoding="utf-8")
            written.append(path)
    return written


if __name__ == "__main__":  # pragma: no cover - the documented regeneration command
    for p in update(sys.argv[1:] or None):
        print(p)

"""The built FMUs' modelDescription.xml equal the golden copies in build/model_descriptions/
(the FMUs' public API): a change of the interface shows in a diff and must be committed."""

import difflib

import pytest

from servofmu.build.fmu import FMUS
from servofmu.build.golden import GOLDEN_DIR, golden_path, model_description, normalised


def test_every_fmu_has_a_golden_model_description():
    assert sorted(p.stem for p in GOLDEN_DIR.glob("*.xml")) == sorted(FMUS)


@pytest.mark.parametrize("name", FMUS)
def test_model_description_equals_the_golden_one(fmus, name):
    built = model_description(fmus[name])
    golden = golden_path(name).read_text(encoding="utf-8")
    diff = "".join(
        difflib.unified_diff(
            golden.splitlines(keepends=True),
            built.splitlines(keepends=True),
            f"golden/{name}.xml",
            f"built/{name}.xml",
        )
    )
    assert not diff, (
        f"{name}'s modelDescription differs from {golden_path(name)}; if the change is "
        "deliberate, run `.venv/bin/python -m servofmu.build.golden` and commit the diff:\n" + diff
    )


def test_volatile_fields_are_normalised_and_nothing_else():
    xml = '<m guid="{a-b}" generationDateAndTime="2026-11-22T12:00:00+00:00" version="0.1.0"/>'
    assert normalised(xml) == '<m guid="normalised" version="0.1.0"/>'
    assert normalised(normalised(xml)) == normalised(xml)

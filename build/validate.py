"""``servofmu validate``: fmpy's validation of an FMU plus the project's own checks."""

from __future__ import annotations

import zipfile
from pathlib import Path

from servofmu.fmus.package_hash import BUILD_INFO

from . import choices
from .archive import ArchiveError, check_archive, read_member
from .xmlsafe import XMLError, parse


def validate(path) -> list[str]:
    """All problems found in the FMU at ``path`` (empty when it passes).

    fmpy (schema, names, ModelStructure, start values, causality/variability, units), then:
    declared state capabilities, a DefaultExperiment with a step size, a description and an
    explicit output-dependency list for every variable that needs one (Outputs and
    InitialUnknowns), start values within min/max, every choice tied to declared items
    (:func:`.choices.problems`), ``documentation/index.html`` and the build information in
    ``resources/``."""
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    path = Path(path)
    if not path.is_file():
        return [f"{path}: no such FMU"]
    # the archive and its XML are checked safely before fmpy reads them (fmpy's parser would
    # expand entities and read external ones)
    unsafe = check_archive(path)
    if unsafe:
        return unsafe
    try:
        root = parse(read_member(path, "modelDescription.xml"), f"{path.name}/modelDescription.xml")
    except (ArchiveError, XMLError) as exc:
        return [str(exc)]
    problems = [f"fmpy: {p}" for p in validate_fmu(str(path))]
    problems += choices.problems(root)
    try:
        md = read_model_description(str(path))
    except Exception as exc:  # fmpy already reported it
        return problems or [f"modelDescription.xml cannot be read: {exc}"]
    cs = md.coSimulation
    if cs is None:
        problems.append("no CoSimulation interface")
    else:
        for flag in ("canGetAndSetFMUstate", "canSerializeFMUstate"):
            if not getattr(cs, flag):
                problems.append(f"CoSimulation/{flag} is not true")
    de = md.defaultExperiment
    if de is None or de.stepSize is None:
        problems.append("no DefaultExperiment with a stepSize")
    for v in md.modelVariables:
        if not v.description:
            problems.append(f'variable "{v.name}" has no description')
        if v.causality == "parameter" and v.variability not in ("fixed", "tunable"):
            problems.append(f'parameter "{v.name}" has variability {v.variability!r}')
        if v.type == "Real" and v.start is not None and v.causality in ("input", "parameter"):
            start = float(v.start)
            if v.min is not None and start < float(v.min):
                problems.append(f'start of "{v.name}" ({start}) is below its min ({v.min})')
            if v.max is not None and start > float(v.max):
                problems.append(f'start of "{v.name}" ({start}) is above its max ({v.max})')
    for kind, unknowns in (("output", md.outputs), ("initial unknown", md.initialUnknowns)):
        for unknown in unknowns:
            if unknown.dependencies is None:  # read as "depends on everything"
                problems.append(f'{kind} "{unknown.variable.name}" lists no dependencies')
    with zipfile.ZipFile(path) as zf:
        names = set(zf.namelist())
    for required in ("documentation/index.html", f"resources/{BUILD_INFO}"):
        if required not in names:
            problems.append(f"{required} is missing")
    return problems

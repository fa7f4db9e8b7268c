"""Reproductions of the source papers: validation reports, CSV curves and PNG figures.

``servofmu paper yu2017|ning|liu2014|validation [--json] [--out DIR]``; see
:mod:`servofmu.papers.report` for the format.
"""

PAPERS = ("yu2017", "ning", "liu2014", "validation")


def run(paper: str, out_dir):
    """Run the reproduction of ``paper`` (one of :data:`PAPERS`); returns its Report."""
    if paper == "yu2017":
        from . import yu2017 as mod
    elif paper == "ning":
        from . import ning as mod
    elif paper == "liu2014":
        from . import liu2014 as mod
    elif paper == "validation":
        from . import validation as mod
    else:
        raise ValueError(f"paper = {paper!r} is not one of {PAPERS}")
    return mod.reproduce(out_dir)

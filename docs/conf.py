"""Sphinx configuration of the servofmu documentation (``make docs``).

The site builds offline: no intersphinx, no web fonts or scripts from elsewhere, math as
MathML (``_ext/mathml.py``). Pages generated from the project's own data (FMU reference,
validation, performance) are written into ``_generated/`` when the build starts
(``_ext/generated.py``). The examples gallery runs its scripts; ``SERVOFMU_GALLERY=full``
runs them at full resolution, the default (``coarse``) at a few points per curve.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import servofmu

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))

project = "servofmu"
author = "the servofmu authors"
copyright = "the servofmu authors, MIT licence"
version = release = servofmu.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
    "myst_parser",
    "mathml",
    "generated",
]

exclude_patterns = [
    "_build",
    "gallery/GALLERY_HEADER.rst",
    "**.ipynb",
    "_generated/performance.rst",  # included by performance.rst
    "_generated/validation/*/**",
]
templates_path = ["_templates"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
nitpicky = False
suppress_warnings = ["config.cache"]  # sphinx-gallery's callables in the config
myst_heading_anchors = 3  # [text](page.md#a-heading) links to headings down to level 3

# --- math: MathML through docutils' converter, the same as inside the FMUs
html_math_renderer = "mathml"

# --- API reference
autosummary_generate = True
autodoc_default_options = {"members": True, "member-order": "bysource"}
autodoc_typehints = "none"  # the numpydoc sections give the types and units
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_validation_checks = set()
numpydoc_xref_param_type = False

# --- examples gallery: the scripts read SERVOFMU_GALLERY (coarse: a few points per curve)
GALLERY_MODE = os.environ.setdefault("SERVOFMU_GALLERY", "coarse")
if GALLERY_MODE not in ("coarse", "full"):
    raise ValueError(f"SERVOFMU_GALLERY = {GALLERY_MODE!r} is not one of ('coarse', 'full')")
sphinx_gallery_conf = {
    "examples_dirs": ["gallery"],
    "gallery_dirs": ["auto_examples"],
    "filename_pattern": r"/plot_",
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "show_memory": False,
    "abort_on_example_error": True,
    "min_reported_time": 1,
}

# --- HTML: a local theme, nothing loaded from the network
html_theme = "pydata_sphinx_theme"
html_title = f"servofmu {release}"
html_static_path = ["_static"]
html_css_files = ["servofmu.css"]
html_show_sourcelink = False
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "header_links_before_dropdown": 8,
    # the host page's five-column table needs the width of the page contents
    "secondary_sidebar_items": {"**": ["page-toc"], "guide/hosts": []},
    "footer_start": ["copyright"],
    "footer_end": [],
}
html_context = {"default_mode": "light"}
# the validation reports' nine-column row tables take the whole width: no section navigation
# (the breadcrumbs and the Validation page lead back)
html_sidebars = {"_generated/validation/*": []}


def _bars_are_absolute_values(app, what, name, obj, options, lines):
    """In the docstrings ``|x|`` is an absolute value, never a substitution (the FMU pages
    read them the same way: ``servofmu.build.documentation.escape_bars``)."""
    from servofmu.build.documentation import escape_bars

    lines[:] = escape_bars("\n".join(lines)).split("\n")


def setup(app):
    app.connect("autodoc-process-docstring", _bars_are_absolute_values, priority=400)

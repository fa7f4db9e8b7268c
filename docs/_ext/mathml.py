"""Math as MathML in Sphinx's HTML, converted by docutils' own LaTeX → MathML converter: the
same conversion that renders the equations on the FMUs' documentation pages
(``servofmu.build.documentation``). Browsers render MathML natively, so the pages need no
script and no network. A formula the converter cannot read fails the build (a warning, and
``make docs`` turns warnings into errors) instead of showing raw LaTeX.
"""

from __future__ import annotations

from docutils import nodes
from docutils.utils.math import MathError, latex2mathml, unichar2tex
from sphinx.util import logging

logger = logging.getLogger(__name__)


def to_mathml(tex: str, block: bool) -> str:
    """MathML of ``tex`` (LaTeX; Unicode letters such as α allowed, as docutils allows)."""
    return latex2mathml.tex2mathml(tex.translate(unichar2tex.uni2tex_table), as_block=block)


def _convert(self, node, block: bool) -> str:
    try:
        return to_mathml(node.astext(), block)
    except MathError as err:
        logger.warning("math %r: %s", node.astext(), err, location=node)
        return self.encode(node.astext())


def visit_math(self, node) -> None:
    self.body.append(_convert(self, node, block=False))
    raise nodes.SkipNode


def visit_displaymath(self, node) -> None:
    self.body.append(self.starttag(node, "div", CLASS="math-mathml"))
    if node.get("number"):
        self.body.append(f'<span class="eqno">({node["number"]})</span>')
    # blank lines separate equations (Sphinx's convention): one MathML block each
    for part in (p for p in node.astext().split("\n\n") if p.strip()):
        self.body.append(_convert(self, nodes.math_block(part, part), block=True))
    self.body.append("</div>\n")
    raise nodes.SkipNode


def setup(app):
    app.add_html_math_renderer(
        "mathml",
        inline_renderers=(visit_math, None),
        block_renderers=(visit_displaymath, None),
    )
    return {"parallel_read_safe": True, "parallel_write_safe": True}

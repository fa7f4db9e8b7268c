"""XML parsing without entity expansion, DTDs or network access, and validation against the
SSP 1.0 schemas (the XSDs shipped with fmpy), both with lxml: for the build (SSD sources, a
built FMU's modelDescription) and the harness."""

from __future__ import annotations

import functools
from pathlib import Path

from lxml import etree

_PARSER = etree.XMLParser(
    resolve_entities=False, no_network=True, load_dtd=False, dtd_validation=False, huge_tree=False
)
SCHEMAS = {
    "ssd": "SystemStructureDescription.xsd",
    "ssv": "SystemStructureParameterValues.xsd",
}


class XMLError(ValueError):
    """An XML document was refused (malformed, a DTD, or not schema-valid)."""


def parse(data: bytes, what: str) -> etree._Element:
    """Parse ``data`` safely; documents with a DOCTYPE are refused (FMI and SSP use none, and a
    DTD is how entity-expansion and external-entity attacks get in).

    Parameters
    ----------
    data : bytes
        The document.
    what : str
        What it is, e.g. a file name (for messages only).

    Returns
    -------
    lxml.etree._Element
        The document's root element.

    Raises
    ------
    XMLError
        For a document with a DOCTYPE, or one that is not well-formed.

    Examples
    --------
    >>> root = parse(b'<fmiModelDescription fmiVersion="2.0"/>', "demo.xml")
    >>> root.tag, root.get("fmiVersion")
    ('fmiModelDescription', '2.0')
    >>> try:
    ...     parse(b'<!DOCTYPE a [<!ENTITY x "boom">]><a>&x;</a>', "evil.xml")
    ... except XMLError as exc:
    ...     print(exc)
    evil.xml: a DOCTYPE/DTD is not allowed (entity expansion is refused)
    """
    if b"<!DOCTYPE" in data or "<!DOCTYPE".encode("utf-16-le") in data:
        raise XMLError(f"{what}: a DOCTYPE/DTD is not allowed (entity expansion is refused)")
    try:
        tree = etree.fromstring(data, parser=_PARSER).getroottree()
    except etree.XMLSyntaxError as exc:
        raise XMLError(f"{what}: not well-formed XML ({exc})") from None
    if tree.docinfo.doctype or tree.docinfo.internalDTD is not None:
        raise XMLError(f"{what}: a DOCTYPE/DTD is not allowed (entity expansion is refused)")
    return tree.getroot()


@functools.cache
def schema(kind: str) -> etree.XMLSchema:
    """The SSP 1.0 schema ``kind`` ("ssd" or "ssv") from fmpy's copy.

    Parameters
    ----------
    kind : str
        "ssd" (SystemStructureDescription) or "ssv" (SystemStructureParameterValues).

    Returns
    -------
    lxml.etree.XMLSchema
        The schema, loaded once per process (cached).

    Examples
    --------
    >>> type(schema("ssd")).__name__
    'XMLSchema'
    >>> schema("ssv") is schema("ssv")  # cached
    True
    """
    import fmpy.ssp

    path = Path(fmpy.ssp.__file__).parent / "schema" / SCHEMAS[kind]
    return etree.XMLSchema(etree.parse(str(path)))


def validate(root: etree._Element, kind: str, what: str) -> None:
    """Raise XMLError listing the schema violations of ``root``.

    Parameters
    ----------
    root : lxml.etree._Element
        The parsed document (:func:`parse`).
    kind : str
        The schema: "ssd" or "ssv" (:func:`schema`).
    what : str
        What the document is, e.g. a file name (for messages only).

    Returns
    -------
    None
        When ``root`` is valid.

    Raises
    ------
    XMLError
        Listing every violation with its line.

    Examples
    --------
    The smallest SSD the schema accepts, then the same without the System's required name:

    >>> ssd = (
    ...     b'<ssd:SystemStructureDescription version="1.0" name="demo" '
    ...     b'xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription">'
    ...     b'<ssd:System name="root"/></ssd:SystemStructureDescription>'
    ... )
    >>> validate(parse(ssd, "demo.ssd"), "ssd", "demo.ssd")
    >>> try:
    ...     validate(parse(ssd.replace(b' name="root"', b""), "bad.ssd"), "ssd", "bad.ssd")
    ... except XMLError as exc:
    ...     print(exc)  # doctest: +ELLIPSIS
    bad.ssd fails the SSP 1.0 schema: line 1: ...'name' is required but missing.
    """
    s = schema(kind)
    if not s.validate(root):
        errors = "; ".join(f"line {e.line}: {e.message}" for e in s.error_log)
        raise XMLError(f"{what} fails the SSP 1.0 schema: {errors}")

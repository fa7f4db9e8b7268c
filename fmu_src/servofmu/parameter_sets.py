"""Parameter sets as SSP 1.0 ``.ssv`` files: the BearingFriction parameter set (or a preset of
it) written so that every engine applies it (the harness, libcosim, OMSimulator, ecos).

A choice is written as its item number (``ssv:Integer``, which every engine applies; an
``ssv:Enumeration`` is dropped by libcosim and ecos) with the item name as the parameter's
description; a count as ``ssv:Integer``; a number as ``ssv:Real`` (SI). The set's name is the
one every ``.ssv`` of ``ssp/`` carries (ecos applies the sets of one name only). Not part of the
package an FMU ships.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from xml.etree.ElementTree import Comment, Element, SubElement, register_namespace, tostring

from servofmu.files import write_text

from .parameters.bearing import PARAMETERS

SSV_NS = "http://ssp-standard.org/SSP1/SystemStructureParameterValues"
#: The ParameterSet name of every .ssv of servofmu (ecos applies one name only).
SET_NAME = "servofmu"


def write_ssv(
    parameters: Mapping[str, object],
    path,
    component: str | None = None,
    name: str = SET_NAME,
    specs: Sequence = PARAMETERS,
    only: Sequence[str] | None = None,
    comment: str = "",
    extra: Mapping[str, float] | None = None,
) -> Path:
    """Write ``parameters`` (``{name: value}``, SI, choices as keys) as an SSP 1.0 parameter
    set at ``path``: bare names (a component-level binding, or start values for the FMU), or
    ``component.name`` names (a variant of a system, e.g. ``ssp/seeker_gimbal/variants/``).

    Parameters
    ----------
    parameters : the values, keyed by the names of ``specs``
    path : the .ssv file to write (folders are created)
    component : prefix of each name, or None
    name : the ParameterSet name
    specs : the parameter specifications (name, type, choices), in the order to write
    only : write only these names (default: every spec)
    comment : an XML comment at the top of the parameters (e.g. the preset it came from)
    extra : further Real values (e.g. an input's start value), written after the set

    Returns
    -------
    Path
        ``path``.
    """
    path = Path(path)
    root = Element(f"{{{SSV_NS}}}ParameterSet", {"version": "1.0", "name": name})
    params = SubElement(root, f"{{{SSV_NS}}}Parameters")
    if comment:
        params.append(Comment(f" {comment.replace('--', '- -')} "))  # XML forbids "--" there
    for spec in specs:
        if only is not None and spec.name not in only:
            continue
        attrs = {"name": f"{component}.{spec.name}" if component else spec.name}
        kind, text, description = ssv_value(spec, parameters[spec.name])
        if description is not None:
            attrs["description"] = description
        elem = SubElement(params, f"{{{SSV_NS}}}Parameter", attrs)
        SubElement(elem, f"{{{SSV_NS}}}{kind}", {"value": text})
    for key, value in (extra or {}).items():
        elem = SubElement(params, f"{{{SSV_NS}}}Parameter", {"name": key})
        SubElement(elem, f"{{{SSV_NS}}}Real", {"value": repr(float(value))})
    root.text, params.text, params.tail = "\n  ", "\n    ", "\n"
    for child in params:  # one parameter per line
        child.tail = "\n    "
    if len(params):
        params[-1].tail = "\n  "
    register_namespace("ssv", SSV_NS)
    body = tostring(root, encoding="unicode")
    write_text(path, f'<?xml version="1.0" encoding="UTF-8"?>\n{body}\n')
    return path


def ssv_value(spec, value) -> tuple[str, str, str | None]:
    """How parameter ``spec`` with ``value`` (SI; a choice as its key) is written in an .ssv:
    (element, value text, description). A choice is its item number as ``ssv:Integer`` with
    the item name as description (every engine applies an Integer), a count an Integer, a
    number a Real (``repr``: exact).

    Parameters
    ----------
    spec : ParameterSpec
        The parameter (name, type, choices).
    value : float, int or str
        Its value (a choice: the item's key).

    Returns
    -------
    tuple
        ``("Real" | "Integer", text, description or None)``.

    Examples
    --------
    >>> from servofmu.parameters.bearing import parameter
    >>> ssv_value(parameter("lubrication"), "solid"), ssv_value(parameter("bore"), 0.017)
    (('Integer', '2', 'solid'), ('Real', '0.017', None))
    """
    if spec.choices:  # an item number (every engine applies ssv:Integer), its name beside
        item = spec.item(value)
        return "Integer", str(item), spec.choices[item - 1].name
    if spec.type == "Integer":
        return "Integer", str(int(value)), None
    return "Real", repr(float(value)), None

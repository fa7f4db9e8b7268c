"""The choices of an FMU read back from its modelDescription: every variable that names one of
a few items, written as an FMI ``Enumeration`` or (servofmu's default, see
``servofmu.fmus.model_description.CHOICES_AS``) as an ``Integer`` tied to its item type by a
``VendorAnnotations/Tool[@name="servofmu"]/Choices/Choice`` entry. Either way the items are an
``Enumeration`` ``SimpleType`` in ``TypeDefinitions``."""

from __future__ import annotations

from servofmu.fmus.model_description import VENDOR_TOOL


def enumeration_types(root) -> dict[str, dict[str, int]]:
    """``{type name: {item name: value}}`` of the Enumeration SimpleTypes of a parsed
    modelDescription ``root`` (an lxml or ElementTree element).

    Parameters
    ----------
    root : lxml.etree._Element or xml.etree.ElementTree.Element
        The root (``fmiModelDescription``) of a parsed modelDescription.

    Returns
    -------
    dict
        ``{type name: {item name: item value [-]}}``, in the order of the document.

    Examples
    --------
    The golden modelDescription of BearingFriction (``build/model_descriptions/``):

    >>> from servofmu.build.golden import golden_path
    >>> from servofmu.build.xmlsafe import parse
    >>> md = parse(golden_path("BearingFriction").read_bytes(), "BearingFriction.xml")
    >>> from servofmu.physics.friction import registry
    >>> items = enumeration_types(md)["FrictionModel"]
    >>> items == {name: i for i, name in enumerate(registry.names(), 1)}  # numbered from 1
    True
    """
    types = {}
    for simple in root.iterfind("TypeDefinitions/SimpleType"):
        enum = simple.find("Enumeration")
        if enum is not None:
            types[simple.get("name")] = {
                item.get("name"): int(item.get("value")) for item in enum.iterfind("Item")
            }
    return types


def choice_items(root) -> dict[str, dict[str, int]]:
    """``{variable name: {item name: value}}`` for every choice variable of a parsed
    modelDescription ``root``; a reference to a type that is not declared gives no items
    (:func:`problems` reports it).

    Parameters
    ----------
    root : lxml.etree._Element or xml.etree.ElementTree.Element
        The root (``fmiModelDescription``) of a parsed modelDescription.

    Returns
    -------
    dict
        ``{variable name: {item name: item value [-]}}``: FMI Enumeration variables first,
        then the Integer variables that servofmu's VendorAnnotation ties to a type.

    Examples
    --------
    >>> from servofmu.build.golden import golden_path
    >>> from servofmu.build.xmlsafe import parse
    >>> md = parse(golden_path("BearingFriction").read_bytes(), "BearingFriction.xml")
    >>> choice_items(md)["lubrication"]
    {'grease': 1, 'solid': 2}
    """
    types = enumeration_types(root)
    declared = {}
    for sv in root.iterfind("ModelVariables/ScalarVariable"):
        enum = sv.find("Enumeration")
        if enum is not None:
            declared[sv.get("name")] = enum.get("declaredType")
    for choice in root.iterfind(f"VendorAnnotations/Tool[@name='{VENDOR_TOOL}']/Choices/Choice"):
        declared[choice.get("variable")] = choice.get("declaredType")
    return {name: types.get(kind, {}) for name, kind in declared.items()}


def problems(root) -> list[str]:
    """Every inconsistency of the choices of ``root``: a choice whose type is not declared or
    has no items, a servofmu Choice naming a variable that is not an Integer, or an Integer
    choice whose min/max differ from its item values.

    Parameters
    ----------
    root : lxml.etree._Element or xml.etree.ElementTree.Element
        The root (``fmiModelDescription``) of a parsed modelDescription.

    Returns
    -------
    list of str
        One message per inconsistency; empty when the choices are consistent.

    Examples
    --------
    A golden modelDescription has none; a hand-made one has an Integer choice whose max is
    one too high and a choice of an undeclared type:

    >>> from servofmu.build.golden import golden_path
    >>> from servofmu.build.xmlsafe import parse
    >>> problems(parse(golden_path("BearingFriction").read_bytes(), "BearingFriction.xml"))
    []
    >>> md = parse(
    ...     b'<fmiModelDescription><TypeDefinitions><SimpleType name="Lubrication">'
    ...     b'<Enumeration><Item name="grease" value="1"/><Item name="solid" value="2"/>'
    ...     b'</Enumeration></SimpleType></TypeDefinitions><ModelVariables>'
    ...     b'<ScalarVariable name="lubrication"><Integer min="1" max="3"/></ScalarVariable>'
    ...     b'</ModelVariables><VendorAnnotations><Tool name="servofmu"><Choices>'
    ...     b'<Choice variable="lubrication" declaredType="Lubrication"/>'
    ...     b'<Choice variable="mode" declaredType="Mode"/>'
    ...     b"</Choices></Tool></VendorAnnotations></fmiModelDescription>",
    ...     "demo.xml",
    ... )
    >>> for line in problems(md):
    ...     print(line)
    choice "lubrication": min/max 1/3 differ from its item values 1…2
    choice "mode": its enumeration type is not declared or has no items
    """
    found = []
    variables = {sv.get("name"): sv for sv in root.iterfind("ModelVariables/ScalarVariable")}
    for name, items in choice_items(root).items():
        sv = variables.get(name)
        if not items:
            found.append(f'choice "{name}": its enumeration type is not declared or has no items')
            continue
        if sv is None or (sv.find("Integer") is None and sv.find("Enumeration") is None):
            found.append(f'choice "{name}" is not an Integer or Enumeration variable')
            continue
        values = sorted(items.values())
        integer = sv.find("Integer")
        if integer is not None and (
            integer.get("min") != str(values[0]) or integer.get("max") != str(values[-1])
        ):
            found.append(
                f'choice "{name}": min/max {integer.get("min")}/{integer.get("max")} differ '
                f"from its item values {values[0]}…{values[-1]}"
            )
    return found

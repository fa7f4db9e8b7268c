"""The choices of an FMU read back from its modelDescription: every variable that names one of
a few items, written as an FMI ``Enumeration`` or (servofmu's default, see
``servofmu.fmus.slave.CHOICES_AS``) as an ``Integer`` tied to its item type by a
``VendorAnnotations/Tool[@name="servofmu"]/Choices/Choice`` entry. Either way the items are an
``Enumeration`` ``SimpleType`` in ``TypeDefinitions``."""

from __future__ import annotations

from servofmu.fmus.slave import VENDOR_TOOL


def enumeration_types(root) -> dict[str, dict[str, int]]:
    """``{type name: {item name: value}}`` of the Enumeration SimpleTypes of a parsed
    modelDescription ``root`` (an lxml or ElementTree element)."""
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
    (:func:`problems` reports it)."""
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
    choice whose min/max differ from its item values."""
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

"""The complete modelDescription of a servofmu FMU, from its declared variables.

pythonfmu writes ScalarVariables without units, ranges or display units, Outputs without
dependencies and no InitialUnknowns, UnitDefinitions or TypeDefinitions (``fmpy validate``
fails on it). :func:`complete` adds what is missing to the element tree pythonfmu builds at
build time: UnitDefinitions with display units, units and min/max, the items of every choice
in TypeDefinitions (written as :data:`CHOICES_AS` says), a ModelStructure with the outputs'
direct dependencies and the InitialUnknowns with every input and parameter they depend on
(an entry without dependencies would mean "depends on everything").
"""

from __future__ import annotations

from xml.etree.ElementTree import Element, SubElement

from .declarations import UNITS, Var

#: How a choice (``type="Enumeration"``) is written into the modelDescription. Either way its
#: items are declared in ``TypeDefinitions`` (``SimpleType``/``Enumeration``/``Item``, human
#: names and descriptions), and hosts get and set it with fmi2Get/SetInteger.
#:
#: - "Enumeration": ``<Enumeration declaredType=...>``, the FMI type for a choice. libcosim
#:   (libcosimpy 0.0.6) and ecos (0.7.2) drop FMI 2.0 Enumeration variables from the model
#:   (libcosim logs "FMI 2.0 Enumeration variable type not supported, variable ... will be
#:   ignored"), so no ``.ssv`` binding reaches them there.
#: - "Integer": ``<Integer min="1" max="n">``, tied to its item type by a servofmu
#:   ``VendorAnnotation``. Every engine applies an ``ssv:Integer`` binding to it (harness,
#:   libcosim, OMSimulator, ecos). The default, until libcosim and ecos apply enumerations.
CHOICES_AS = "Integer"
VENDOR_TOOL = "servofmu"  # VendorAnnotations/Tool name that ties choices to their types


def complete(root: Element, variables) -> Element:
    """Complete pythonfmu's modelDescription of an FMU with ``variables`` (in place).

    Parameters
    ----------
    root : the ``fmiModelDescription`` element pythonfmu's ``Fmi2Slave.to_xml`` returns
    variables : the FMU's :class:`~.declarations.Var` (as registered, in that order)

    Returns
    -------
    xml.etree.ElementTree.Element
        ``root``, with units, ranges, type and unit definitions, vendor annotations and the
        model structure.

    Examples
    --------
    >>> from servofmu.fmus.declarations import output, real_input
    >>> root = Element("fmiModelDescription")
    >>> _ = SubElement(root, "CoSimulation")
    >>> listed = SubElement(root, "ModelVariables")
    >>> for name in ("u", "y"):
    ...     _ = SubElement(SubElement(listed, "ScalarVariable", name=name), "Real")
    >>> _ = SubElement(root, "ModelStructure")
    >>> u = real_input("u", "an input", start=0.0, unit="K", min=0.0, max=500.0)
    >>> y = output("y", "an output", unit="K", depends=("u",), initial_depends=("u",))
    >>> root = complete(root, (u, y))
    >>> [e.tag for e in root]
    ['CoSimulation', 'UnitDefinitions', 'ModelVariables', 'ModelStructure']
    >>> root.find("ModelVariables")[0][0].attrib
    {'unit': 'K', 'min': '0', 'max': '500'}
    >>> root.find("ModelStructure/Outputs/Unknown").attrib["dependencies"]
    '1'
    """
    by_name = {v.name: v for v in variables}
    listed = root.find("ModelVariables")
    for sv in listed.findall("ScalarVariable"):
        _complete_variable(sv, by_name[sv.get("name")])
    after = root.find("CoSimulation")
    for block in (_unit_definitions(variables), _type_definitions(variables)):
        if block is not None:
            root.insert(list(root).index(after) + 1, block)
            after = block
    annotations = _vendor_annotations(variables)
    if annotations is not None:
        root.insert(list(root).index(listed), annotations)
    root.remove(root.find("ModelStructure"))
    root.append(_model_structure(variables))
    return root


def _complete_variable(sv, v: Var):
    """Add unit, range and (for a choice) the enumeration type to a pythonfmu ScalarVariable."""
    elem = sv[0]
    if v.type == "Enumeration":
        attrs = dict(elem.attrib)
        sv.remove(elem)
        if CHOICES_AS == "Enumeration":
            elem = SubElement(sv, "Enumeration", declaredType=v.declared_type, **attrs)
        else:
            elem = SubElement(sv, "Integer", **attrs, min="1", max=str(len(v.items)))
        return
    if v.unit:
        elem.set("unit", v.unit)
    if v.display_unit:
        elem.set("displayUnit", v.display_unit)
    if v.min is not None:
        elem.set("min", _number(v.min, v.type))
    if v.max is not None:
        elem.set("max", _number(v.max, v.type))


def _number(x, kind: str) -> str:
    return str(int(x)) if kind == "Integer" else f"{x:.16g}"


def _unit_definitions(variables):
    used = dict.fromkeys(v.unit for v in variables if v.unit)
    if not used:
        return None
    units = Element("UnitDefinitions")
    for name in used:
        exps, displays = UNITS[name]
        unit = SubElement(units, "Unit", name=name)
        SubElement(unit, "BaseUnit", {k: str(e) for k, e in exps.items()})
        for d, factor, offset in displays:
            attrs = {"name": d, "factor": f"{factor:.16g}"}
            if offset:
                attrs["offset"] = f"{offset:.16g}"
            SubElement(unit, "DisplayUnit", attrs)
    return units


def _type_definitions(variables):
    """TypeDefinitions with one Enumeration SimpleType per declared item type."""
    types = {}
    for v in variables:
        if v.type == "Enumeration":
            if types.setdefault(v.declared_type, v.items) != v.items:
                raise ValueError(f"declared type {v.declared_type!r} has two item lists")
    if not types:
        return None
    block = Element("TypeDefinitions")
    for name, items in types.items():
        enum = SubElement(SubElement(block, "SimpleType", name=name), "Enumeration")
        for i, item in enumerate(items, start=1):
            attrs = {"name": item.name, "value": str(i)}
            if item.description:
                attrs["description"] = item.description
            SubElement(enum, "Item", attrs)
    return block


def _vendor_annotations(variables):
    """With choices written as Integer: which item type each choice variable uses."""
    choices = [v for v in variables if v.type == "Enumeration"]
    if CHOICES_AS == "Enumeration" or not choices:
        return None
    block = Element("VendorAnnotations")
    tool = SubElement(SubElement(block, "Tool", name=VENDOR_TOOL), "Choices")
    for v in choices:
        SubElement(tool, "Choice", variable=v.name, declaredType=v.declared_type)
    return block


def _model_structure(variables):
    """Outputs with their direct input dependencies, InitialUnknowns with every input and
    parameter their initial value depends on (an entry without dependencies would mean
    "depends on everything")."""
    index = {v.name: i for i, v in enumerate(variables, start=1)}
    structure = Element("ModelStructure")
    outputs = SubElement(structure, "Outputs")
    initial = SubElement(structure, "InitialUnknowns")
    for v in variables:
        if v.causality != "output":
            continue
        deps = sorted(index[d] for d in v.depends)
        SubElement(
            outputs,
            "Unknown",
            index=str(index[v.name]),
            dependencies=" ".join(map(str, deps)),
            dependenciesKind=" ".join("dependent" for _ in deps),
        )
        deps = sorted(index[d] for d in v.initial_depends)
        SubElement(
            initial, "Unknown", index=str(index[v.name]), dependencies=" ".join(map(str, deps))
        )
    return structure

"""Reading an SSP 1.0 system (``.ssp`` archive or folder with ``SystemStructure.ssd``) and
checking it against its FMUs before anything is instantiated.

Supported: one flat system of FMU components; connections between component connectors with
an optional ``ssc:LinearTransformation``; parameter bindings at component level from ``.ssv``
files (names relative to the component); the DefaultExperiment with the OSP
``FixedStepAlgorithm baseStepSize`` annotation; parameter-set variants as ``variants/NAME.ssv``
with system-level names ``component.variable``, applied after the component bindings.

:func:`load_system` raises :class:`~.errors.SystemError_` listing every problem: schema
violations, a missing FMU, a connection or connector naming a variable the FMU lacks, wrong
causality or type, a unit mismatch across a connection, a parameter the FMU does not have.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from servofmu.build.archive import ArchiveError, Budget, read_member, safe_extract
from servofmu.build.choices import choice_items
from servofmu.build.xmlsafe import parse, validate
from servofmu.files import read_input_bytes, scratch_folder
from servofmu.physics._checks import suggest

from .errors import HarnessError, SystemError_, refusals

NS = {
    "ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
    "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
    "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues",
    "osp": "http://opensimulationplatform.com/SSP/OSPAnnotations",
}
TYPES = ("Real", "Integer", "Boolean", "String", "Enumeration")


@dataclass(frozen=True)
class Variable:
    """One FMU variable as the harness needs it; ``items`` maps the item names of a choice
    (an FMI Enumeration, or an Integer that servofmu ties to an item type) to its values."""

    name: str
    value_reference: int
    type: str
    causality: str
    unit: str | None
    start: object
    items: dict[str, int] | None = None
    display_unit: str | None = None  # display = factor·value + offset
    display_factor: float = 1.0
    display_offset: float = 0.0
    min: float | None = None  # valid range (inclusive), where the FMU declares it
    max: float | None = None
    variability: str | None = None


@dataclass
class Component:
    """One FMU in the system: its file, declared connectors and bound parameter values."""

    name: str
    source: str
    fmu: Path | None
    connectors: dict[str, tuple[str, str, str | None]]  # name → (kind, type, unit)
    parameters: dict[str, tuple[str, object]] = field(default_factory=dict)  # name → (type, value)
    variables: dict[str, Variable] = field(default_factory=dict)
    model_identifier: str = ""
    guid: str = ""
    feedthrough: bool = False  # some output depends directly on an input


@dataclass(frozen=True)
class Connection:
    """``start.component.connector`` → ``end`` with y = factor·x + offset."""

    start: tuple[str, str]
    end: tuple[str, str]
    factor: float = 1.0
    offset: float = 0.0


@dataclass
class System:
    """A loaded, checked system; close() removes an unpacked archive."""

    name: str
    root: Path
    components: dict[str, Component]
    connections: list[Connection]
    start_time: float
    stop_time: float
    step_size: float | None
    variants: dict[str, dict[str, tuple[str, object]]]
    _tmp: object = None
    _unpacked: dict = field(default_factory=dict)  # FMU path → its unpacked folder
    _fmu_tmp: object = None
    #: one budget of unpacked bytes and entries for the archive and every FMU of the system
    _budget: Budget = field(default_factory=Budget)

    def unpacked(self, fmu: Path) -> Path:
        """The folder ``fmu`` is unpacked to, once per system (runs share it; removed by
        :meth:`close`)."""
        if fmu not in self._unpacked:
            if self._fmu_tmp is None:
                self._fmu_tmp = scratch_folder("servofmu_fmus_")
            target = Path(self._fmu_tmp.name) / f"{len(self._unpacked)}_{fmu.stem}"
            with refusals():
                self._unpacked[fmu] = safe_extract(fmu, target, budget=self._budget)
        return self._unpacked[fmu]

    def close(self):
        for tmp in (self._tmp, self._fmu_tmp):
            if tmp is not None:
                tmp.cleanup()
        self._tmp = self._fmu_tmp = None
        self._unpacked.clear()

    def scale(self, target: str):
        """How ``component.variable`` is labelled and shown
        (:class:`~.units.Scale`): its FMU's unit and display unit; without a unit in the FMU,
        the unit of the variable connected to it, then that of its SSD connector."""
        from .units import Scale

        comp, var = self.variable(target)
        if var.type == "Boolean":
            return Scale(None, boolean=True)
        if var.unit is not None:
            return Scale(var.unit, var.display_unit, var.display_factor, var.display_offset)
        key = (comp.name, var.name)
        for c in self.connections:
            other = c.start if c.end == key else c.end if c.start == key else None
            if other is not None and c.factor == 1.0 and c.offset == 0.0:
                ov = self.components[other[0]].variables.get(other[1])
                if ov is not None and ov.unit is not None:
                    return Scale(ov.unit, ov.display_unit, ov.display_factor, ov.display_offset)
        connector = comp.connectors.get(var.name)
        return Scale(connector[2] if connector else None)

    def variable(self, target: str) -> tuple[Component, Variable]:
        """(component, variable) of ``"component.variable"``, or HarnessError."""
        comp_name, _, var_name = target.partition(".")
        comp = self.components.get(comp_name)
        if comp is None:
            raise HarnessError(
                f"{target!r}: no component {comp_name!r} in the system "
                f"(components {sorted(self.components)}){suggest(comp_name, self.components)}"
            )
        if var_name not in comp.variables:
            raise HarnessError(
                f"{target!r}: {comp.fmu.name if comp.fmu else comp_name} has no variable "
                f"{var_name!r}{suggest(var_name, comp.variables)}"
            )
        return comp, comp.variables[var_name]


def _float(elem, attr, default):
    value = elem.get(attr)
    return default if value is None else float(value)


def _read_parameter_set(data: bytes, what: str) -> dict[str, tuple[str, object]]:
    root = parse(data, what)
    validate(root, "ssv", what)
    values = {}
    for p in root.findall("ssv:Parameters/ssv:Parameter", NS):
        for t in TYPES:
            elem = p.find(f"ssv:{t}", NS)
            if elem is not None:
                raw = elem.get("value")
                try:
                    value = {
                        "Real": float,
                        "Integer": int,
                        "Boolean": lambda s: s.strip().lower() in ("true", "1"),
                        "String": str,
                        "Enumeration": str,
                    }[t](raw)
                except (TypeError, ValueError):
                    raise SystemError_(
                        [f"{what}: parameter {p.get('name')!r}: {raw!r} is not a {t} value"]
                    ) from None
                if t == "Real" and not math.isfinite(value):
                    raise SystemError_(
                        [f"{what}: parameter {p.get('name')!r}: {raw!r} is not finite"]
                    )
                values[p.get("name")] = (t, value)
                break
    return values


def _bound(text) -> float | None:
    try:
        return None if text is None else float(text)
    except ValueError:
        return None


def _model_variables(fmu: Path) -> tuple[str, str, dict[str, Variable], bool]:
    """(modelIdentifier, guid, variables, feedthrough) read from the FMU (XML checked first)."""
    from fmpy import read_model_description

    with refusals():
        root = parse(read_member(fmu, "modelDescription.xml"), f"{fmu.name}/modelDescription.xml")
    md = read_model_description(str(fmu), validate=False)
    if md.coSimulation is None:
        raise HarnessError(f"{fmu.name} has no co-simulation interface")
    choices = choice_items(root)
    displays = {
        u.name: {d.name: (float(d.factor), float(d.offset)) for d in u.displayUnits}
        for u in md.unitDefinitions
    }
    variables = {}
    for v in md.modelVariables:
        declared = v.declaredType
        unit = v.unit if v.unit is not None else getattr(declared, "unit", None)
        shown = v.displayUnit or getattr(declared, "displayUnit", None)
        factor, offset = displays.get(unit, {}).get(shown, (1.0, 0.0))
        if shown is not None and shown not in displays.get(unit, {}):
            shown = None  # a display unit the UnitDefinitions do not define: show SI
        variables[v.name] = Variable(
            v.name,
            v.valueReference,
            v.type,
            v.causality,
            unit,
            v.start,
            choices.get(v.name),
            shown,
            factor,
            offset,
            _bound(v.min if v.min is not None else getattr(declared, "min", None)),
            _bound(v.max if v.max is not None else getattr(declared, "max", None)),
            v.variability,
        )
    feedthrough = any(u.dependencies for u in md.outputs) or any(
        u.dependencies is None for u in md.outputs
    )
    return md.coSimulation.modelIdentifier, md.guid, variables, feedthrough


def _outside(root: Path, source: str) -> str:
    """Why ``source`` (a component's FMU or parameter set, relative to the system folder
    ``root``) is refused, or "" when it lies inside the folder (the archive): an absolute
    path, a URI, a drive, ``..`` or a link that resolves elsewhere would load a file from
    outside the system."""
    rel = PurePosixPath(source)
    if rel.is_absolute() or "\\" in source or (rel.parts and ":" in rel.parts[0]):
        return "is an absolute path or URI: it must be a path inside the system folder"
    if ".." in rel.parts:
        return "leaves the system folder ('..'): it must be a path inside it"
    if not (root / source).resolve().is_relative_to(root.resolve()):
        return "resolves outside the system folder (a link): it must lie inside it"
    return ""


def load_system(path, fmu_dir=None) -> System:
    """Read and check the system at ``path`` (``.ssp`` archive, folder, or its
    ``SystemStructure.ssd``). Component sources are resolved relative to the system folder;
    a missing one is looked up by file name in ``fmu_dir`` (e.g. ``build/out``)."""
    path = Path(path)
    tmp = None
    budget = Budget()  # the archive and its FMUs together
    if path.is_file() and path.suffix == ".ssp":
        tmp = scratch_folder("servofmu_ssp_")
        try:
            with refusals():
                root = safe_extract(path, tmp.name, budget=budget)
        except BaseException:
            tmp.cleanup()
            raise
    elif path.is_dir():
        root = path
    elif path.is_file() and path.suffix == ".ssd":
        root = path.parent
    else:
        raise HarnessError(f"{path}: no .ssp archive or system folder there")
    try:
        with refusals():
            return _load(root, path, tmp, fmu_dir, budget)
    except Exception:
        if tmp is not None:
            tmp.cleanup()
        raise


def _load(root: Path, path: Path, tmp, fmu_dir, budget: Budget) -> System:
    ssd_file = root / "SystemStructure.ssd"
    if not ssd_file.is_file():
        raise SystemError_([f"{path}: no SystemStructure.ssd"])
    ssd = parse(read_input_bytes(ssd_file, "system description"), str(ssd_file))
    validate(ssd, "ssd", str(ssd_file))
    problems: list[str] = []
    system = ssd.find("ssd:System", NS)
    components: dict[str, Component] = {}
    for elem in system.findall("ssd:Elements/ssd:Component", NS):
        name, source = elem.get("name"), elem.get("source")
        if name in components:  # one name, one component: a second would replace the first
            problems.append(
                f"{ssd_file}: ssd:Component name={name!r} (line {elem.sourceline}) is declared "
                "more than once: component names must be unique"
            )
            continue
        if elem.get("type", "application/x-fmu-sharedlibrary") != "application/x-fmu-sharedlibrary":
            problems.append(f"component {name!r}: only FMU components are supported")
            continue
        connectors = {}
        for c in elem.findall("ssd:Connectors/ssd:Connector", NS):
            kind_elem = next(
                (c.find(f"ssc:{t}", NS) for t in TYPES if c.find(f"ssc:{t}", NS) is not None), None
            )
            ctype = None if kind_elem is None else kind_elem.tag.split("}")[1]
            unit = None if kind_elem is None else kind_elem.get("unit")
            connectors[c.get("name")] = (c.get("kind"), ctype, unit)
        if source and (outside := _outside(root, source)):
            problems.append(f"component {name!r}: FMU source {source!r} {outside}")
            source = None
        fmu = (root / source) if source else None
        if fmu is not None and not fmu.is_file() and fmu_dir is not None:
            fmu = Path(fmu_dir) / Path(source).name
        comp = Component(name, source, fmu if fmu and fmu.is_file() else None, connectors)
        if comp.fmu is None and source is not None:
            hint = " (build it with `servofmu build`)" if fmu_dir is None else f" or in {fmu_dir}"
            problems.append(f"component {name!r}: FMU {source!r} not found in {root}{hint}")
        for binding in elem.findall("ssd:ParameterBindings/ssd:ParameterBinding", NS):
            src = binding.get("source")
            if src is None:
                problems.append(f"component {name!r}: only .ssv parameter bindings are supported")
                continue
            if outside := _outside(root, src):
                problems.append(f"component {name!r}: parameter set {src!r} {outside}")
                continue
            ssv_file = root / src
            if not ssv_file.is_file():
                problems.append(f"component {name!r}: parameter set {src!r} not found")
                continue
            data = read_input_bytes(ssv_file, "parameter set")
            comp.parameters.update(_read_parameter_set(data, str(ssv_file)))
        components[name] = comp
    connections = []
    for c in system.findall("ssd:Connections/ssd:Connection", NS):
        start = (c.get("startElement"), c.get("startConnector"))
        end = (c.get("endElement"), c.get("endConnector"))
        if start[0] is None or end[0] is None:
            problems.append(
                f"connection {start} → {end}: system-level connectors are not supported "
                "(connect components directly; drive unconnected inputs with signals)"
            )
            continue
        lt = c.find("ssc:LinearTransformation", NS)
        factor = 1.0 if lt is None else _float(lt, "factor", 1.0)
        offset = 0.0 if lt is None else _float(lt, "offset", 0.0)
        connections.append(Connection(start, end, factor, offset))
    de = ssd.find("ssd:DefaultExperiment", NS)
    start_time = 0.0 if de is None else _float(de, "startTime", 0.0)
    stop_time = 1.0 if de is None else _float(de, "stopTime", 1.0)
    step = _base_step(ssd.find(".//osp:FixedStepAlgorithm", NS), ssd_file, problems)
    variants = {}
    for f in sorted((root / "variants").glob("*.ssv")) if (root / "variants").is_dir() else []:
        variants[f.stem] = _read_parameter_set(read_input_bytes(f, "parameter set"), str(f))
    over = []  # every FMU charged before any is unpacked or read
    for comp in components.values():
        if comp.fmu is not None:
            try:
                budget.reserve(comp.fmu)
            except ArchiveError as exc:
                over.append(f"component {comp.name!r}: {exc}")
    if over:
        raise SystemError_(over)
    sys_ = System(
        ssd.get("name"), root, components, connections, start_time, stop_time, step, variants, tmp
    )
    sys_._budget = budget
    problems += _check(sys_)
    if problems:
        raise SystemError_(problems)
    return sys_


def _base_step(fixed, ssd_file: Path, problems: list[str]) -> float | None:
    """The communication step [s] of the OSP ``FixedStepAlgorithm`` annotation (None without
    one); a missing, non-numeric, non-finite or non-positive ``baseStepSize`` is a problem
    naming the file and the element."""
    if fixed is None:
        return None
    raw = fixed.get("baseStepSize")
    try:
        step = float(raw)
    except (TypeError, ValueError):
        step = math.nan
    if not (math.isfinite(step) and step > 0.0):
        given = "is missing" if raw is None else f"= {raw!r} is not a finite number > 0"
        problems.append(
            f"{ssd_file}: osp:FixedStepAlgorithm (line {fixed.sourceline}) baseStepSize {given} "
            '(the communication step [s], e.g. baseStepSize="0.001")'
        )
        return None
    return step


def _check(system: System) -> list[str]:
    """Every problem of a parsed system against its FMUs."""
    problems = []
    unreadable = set()  # components whose FMU could not be read: no further checks on them
    for comp in system.components.values():
        if comp.fmu is None:
            continue
        try:
            comp.model_identifier, comp.guid, comp.variables, comp.feedthrough = _model_variables(
                comp.fmu
            )
        except HarnessError as exc:
            details = exc.problems if isinstance(exc, SystemError_) else [str(exc)]
            problems += [f"component {comp.name!r}: {d}" for d in details]
            unreadable.add(comp.name)
            continue
        for name, (kind, ctype, unit) in comp.connectors.items():
            v = comp.variables.get(name)
            if v is None:
                problems.append(f"connector {comp.name}.{name}: the FMU has no variable {name!r}")
                continue
            if kind in ("input", "output", "parameter") and v.causality != kind:
                problems.append(
                    f"connector {comp.name}.{name} is declared {kind}, the FMU says {v.causality}"
                )
            if ctype and ctype != v.type:
                problems.append(
                    f"connector {comp.name}.{name} is {ctype} but the FMU variable is {v.type}"
                )
            if unit and v.unit and unit != v.unit:
                problems.append(
                    f"connector {comp.name}.{name} has unit {unit!r}, the FMU variable {v.unit!r}"
                )
        for pname, (ptype, value) in comp.parameters.items():
            v = comp.variables.get(pname)
            if v is None:
                problems.append(f"parameter {comp.name}.{pname}: the FMU has no such variable")
            elif v.causality not in ("parameter", "input"):
                problems.append(
                    f"parameter {comp.name}.{pname}: the FMU variable is an {v.causality}"
                )
            else:
                try:
                    comp.parameters[pname] = (v.type, bound_value(v, ptype, value))
                except ValueError as exc:
                    problems.append(f"parameter {comp.name}.{pname} {exc}")
    inputs_seen = set()
    for con in system.connections:
        ends = []
        for (cname, vname), role in ((con.start, "start"), (con.end, "end")):
            comp = system.components.get(cname)
            if comp is None:
                problems.append(f"connection {con.start} → {con.end}: no component {cname!r}")
                ends.append(None)
                continue
            v = comp.variables.get(vname) if comp.variables else None
            if comp.fmu is not None and v is None and cname not in unreadable:
                problems.append(
                    f"connection {cname}.{vname} ({role}): the FMU has no variable {vname!r}"
                )
            ends.append(v)
        src, dst = ends
        if src is not None and src.causality != "output":
            problems.append(
                f"connection from {'.'.join(con.start)}: it is an {src.causality}, not an output"
            )
        if dst is not None and dst.causality != "input":
            problems.append(
                f"connection to {'.'.join(con.end)}: it is an {dst.causality}, not an input"
            )
        if src is not None and dst is not None:
            if src.type != dst.type:
                problems.append(
                    f"connection {'.'.join(con.start)} → {'.'.join(con.end)}: "
                    f"{src.type} to {dst.type}"
                )
            if src.unit != dst.unit and src.unit and dst.unit:
                problems.append(
                    f"connection {'.'.join(con.start)} → {'.'.join(con.end)}: unit {src.unit!r} "
                    f"does not match {dst.unit!r}"
                )
        if con.end in inputs_seen:
            problems.append(f"input {'.'.join(con.end)} has more than one incoming connection")
        inputs_seen.add(con.end)
    for vname, values in system.variants.items():
        for target, (ptype, value) in values.items():
            cname, _, var = target.partition(".")
            comp = system.components.get(cname)
            if comp is None or (comp.variables and var not in comp.variables):
                problems.append(f"variant {vname!r}: {target!r} names no variable of the system")
            elif comp.variables:
                v = comp.variables[var]
                try:
                    values[target] = (v.type, bound_value(v, ptype, value))
                except ValueError as exc:
                    problems.append(f"variant {vname!r}: {target} {exc}")
    return problems


def bound_value(var: Variable, kind: str, value):
    """The value an ``.ssv`` binding of type ``kind`` ("Real", "Integer", "Boolean", "String"
    or "Enumeration", an item name) gives FMU variable ``var``; ValueError (worded to follow
    the parameter's name) when the two do not fit. An Integer binding sets a Real, an Integer
    or an Enumeration binding sets a choice."""
    if var.items is not None:
        if kind == "Enumeration" and value in var.items:
            return var.items[value]
        if kind == "Integer" and value in var.items.values():
            return value
        raise ValueError(f"= {value!r} ({kind}) is not one of {describe_items(var.items)}")
    if kind == var.type or (kind == "Integer" and var.type == "Real"):
        if problem := out_of_range(var, value):
            raise ValueError(problem)
        return value
    raise ValueError(f"is given as {kind}, the FMU wants {var.type}")


def out_of_range(var: Variable, value) -> str:
    """ "= value is outside the valid range [min, max] unit" when a number ``value`` lies
    outside the range ``var`` declares (its FMU would refuse it), else ""."""
    if var.type not in ("Real", "Integer") or isinstance(value, bool | str):
        return ""
    lo = -math.inf if var.min is None else var.min
    hi = math.inf if var.max is None else var.max
    if lo <= value <= hi:
        return ""
    unit = f" {var.unit}" if var.unit else ""
    return f"= {value!r} is outside the valid range [{lo:g}, {hi:g}]{unit}"


def describe_items(items: dict[str, int]) -> str:
    """ "the items name (value), …" for a message."""
    return "the items " + ", ".join(f"{name} ({value})" for name, value in items.items())


def parameter_file(system: System, path) -> dict[str, object]:
    """The values of parameter-set file ``path`` (SSP 1.0 .ssv) as ``{"comp.var": value}`` for
    a run of ``system``: a variant's ``comp.var`` names as they are, or one component's bare
    names (``servofmu catalog --ssv``, ``servofmu calibrate``) bound to the one component that
    has every one of them. ParameterError naming the file otherwise.

    Parameters
    ----------
    system : System
        The loaded system.
    path : str or pathlib.Path
        The .ssv file.

    Returns
    -------
    dict
        ``{"component.variable": value}`` (Real, Integer, Boolean, or an item name).

    Examples
    --------
    A component's bare names, bound to the one component that has them all:

    >>> import tempfile
    >>> from types import SimpleNamespace
    >>> from servofmu.parameter_sets import write_ssv
    >>> from servofmu.parameters.bearing import default_parameters, PARAMETERS
    >>> names = {p.name for p in PARAMETERS}
    >>> system = SimpleNamespace(name="demo", components={
    ...     "motor": SimpleNamespace(variables={"voltage"}),
    ...     "bearing": SimpleNamespace(variables=names)})
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     ssv = write_ssv(default_parameters("ning_space_shaft"), Path(tmp) / "ning.ssv")
    ...     values = parameter_file(system, ssv)
    >>> values["bearing.assembly_preload"], values["bearing.lubrication"]
    (100.0, 2)
    """
    from .errors import ParameterError

    path = Path(path)
    if not path.is_file():
        raise ParameterError(f"--parameters {path}: no such parameter-set file")
    with refusals():
        values = {name: value for name, (_, value) in _read_parameter_set(
            read_input_bytes(path, "parameter set"), str(path)).items()}  # fmt: skip
    if not values:
        raise ParameterError(f"--parameters {path}: the parameter set is empty")
    qualified = [n for n in values if n.partition(".")[0] in system.components]
    if len(qualified) == len(values):
        return values
    bare = [n for n in values if n not in qualified]
    owners = [
        name for name, comp in system.components.items() if all(n in comp.variables for n in bare)
    ]
    if len(owners) != 1:
        what = "no component" if not owners else f"the components {owners}"
        raise ParameterError(
            f"--parameters {path}: its names {bare[:3]}{'…' if len(bare) > 3 else ''} are "
            f"bare, and {what} of {system.name} has every one of them; write them as "
            "component.variable (e.g. servofmu catalog --ssv FILE --component bearing)"
        )
    return {n if n in qualified else f"{owners[0]}.{n}": v for n, v in values.items()}

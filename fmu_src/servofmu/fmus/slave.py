"""Common machinery of the servofmu FMU slaves (pythonfmu ``Fmi2Slave``).

Each FMU declares its variables once, as a tuple of :class:`Var`; from that one list this
base class

- answers every FMI entry point pythonfmu calls itself (fmi2Get*/fmi2Set* for any value
  reference, the FMI 2.0 state machine of :mod:`.calls`, fmi2DoStep with any arguments, FMU
  states handed back by a host): it checks the arguments and the state and answers a host's
  mistake with fmi2Error and a message naming what was wrong. Under servofmu's export library
  that is an :class:`~.calls.FMIError` turned into the status; under pythonfmu's own binary,
  which makes any exception fatal and can then crash the host, nothing is ever raised: the
  message is logged, the call returns a harmless value, the instance enters the error state
  and its next fmi2DoStep is discarded with the message (:mod:`.binary`);
- writes the complete modelDescription (``to_xml``): UnitDefinitions with display units, units,
  min/max, descriptions, variability and initial attributes, TypeDefinitions with the items of
  every choice (see :data:`CHOICES_AS`), ModelStructure with the outputs' direct dependencies
  and the InitialUnknowns with every input and parameter they depend on, DefaultExperiment —
  what pythonfmu does not write;
- copies a model's result record to the outputs through one map (each output's ``field``);
- checks inputs and parameters against their declared ranges and items (a choice is an integer
  1…n naming an item, registered with pythonfmu as Integer: FMI 2.0 hosts access
  enumerations through fmi2Get/SetInteger): a bad parameter refuses
  fmi2ExitInitializationMode (or, a tunable one changed later, the next step), a bad input the
  step, each naming the variable and its value; a model that cannot take a step (or a step
  longer than it takes in bounded time) discards it with a logged message; an output that is
  not finite is never returned with fmi2OK;
- saves and restores the whole state, hidden state included, as JSON (``fmi2GetFMUstate``,
  ``fmi2SerializeFMUstate``); a state handed back is checked (this FMU, this build, these
  fields) before anything is restored, and a refused one leaves the instance's values as they
  were;
- refuses to run (at instantiation, with a clear message) when the servofmu package already
  imported in the process is not the one the FMU was built with.

Time: a stepped FMU's first fmi2DoStep starts at fmi2SetupExperiment's startTime (or, without
it, defines the start), each later one where the last ended (or at the time of a restored
state); another currentCommunicationPoint is refused (FMI 2.0: the point and the FMU's state
must agree), never caught up silently. An algebraic FMU's outputs depend on its inputs alone:
it takes a step at any point.

Two kinds of FMU: *algebraic* ones (``FEEDTHROUGH = True``: BearingFriction,
ActuatorStiffness) compute their outputs from the current inputs, lazily, whenever an output
is read after an input changed; *stepped* ones (DCMotor, ServoController) advance a hidden
state in ``do_step`` and their outputs do not depend directly on the inputs.
"""

from __future__ import annotations

import copy
import dataclasses
import functools
import hashlib
import json
import math
from dataclasses import dataclass
from pathlib import Path
from xml.etree.ElementTree import Element, SubElement

from pythonfmu import Boolean, Fmi2Causality, Fmi2Slave, Fmi2Variability, Integer, Real
from pythonfmu.enums import Fmi2Initial, Fmi2Status

from .. import __version__, different_build
from .binary import export_of, reports_statuses
from .calls import (
    ERROR,
    INITIALIZATION,
    INSTANTIATED,
    PHASES,
    READABLE,
    STEP_COMPLETE,
    STEP_FAILED,
    TERMINATED,
    FMIError,
    sequence_problem,
    state_problem,
)
from .interpreter_exit import register_interpreter_finaliser

BUILD_INFO = "servofmu_build.json"  # written into resources/ by the build

# SI base-unit exponents and display units (factor, offset: display = factor·value + offset)
UNITS: dict[str, tuple[dict[str, int], tuple[tuple[str, float, float], ...]]] = {
    "K": ({"K": 1}, (("degC", 1.0, -273.15),)),
    "rad/s": ({"rad": 1, "s": -1}, (("rpm", 30.0 / math.pi, 0.0), ("deg/s", 180.0 / math.pi, 0.0))),
    "rad": ({"rad": 1}, (("deg", 180.0 / math.pi, 0.0),)),
    "N": ({"kg": 1, "m": 1, "s": -2}, ()),
    "N.m": ({"kg": 1, "m": 2, "s": -2}, (("N.mm", 1.0e3, 0.0),)),
    "m": ({"m": 1}, (("mm", 1.0e3, 0.0), ("um", 1.0e6, 0.0))),
    "m2": ({"m": 2}, (("mm2", 1.0e6, 0.0),)),
    "m4": ({"m": 4}, (("mm4", 1.0e12, 0.0),)),
    "m2/s": ({"m": 2, "s": -1}, (("cSt", 1.0e6, 0.0),)),
    "N/m": ({"kg": 1, "s": -2}, (("N/um", 1.0e-6, 0.0),)),
    "N.m/rad": ({"kg": 1, "m": 2, "s": -2, "rad": -1}, (("N.m/deg", math.pi / 180.0, 0.0),)),
    "W": ({"kg": 1, "m": 2, "s": -3}, ()),
    "Pa": ({"kg": 1, "m": -1, "s": -2}, (("MPa", 1.0e-6, 0.0), ("GPa", 1.0e-9, 0.0))),
    "V": ({"kg": 1, "m": 2, "s": -3, "A": -1}, ()),
    "A": ({"A": 1}, ()),
    "Ohm": ({"kg": 1, "m": 2, "s": -3, "A": -2}, ()),
    "H": ({"kg": 1, "m": 2, "s": -2, "A": -2}, (("mH", 1.0e3, 0.0),)),
    "N.m/A": ({"kg": 1, "m": 2, "s": -2, "A": -1}, ()),
    "V.s/rad": ({"kg": 1, "m": 2, "s": -3, "A": -1, "rad": -1}, ()),
    "kg.m2": ({"kg": 1, "m": 2}, ()),
    "N.m.s/rad": ({"kg": 1, "m": 2, "s": -1, "rad": -1}, ()),
    "s": ({"s": 1}, (("ms", 1.0e3, 0.0),)),
    "J/K": ({"kg": 1, "m": 2, "s": -2, "K": -1}, ()),
    "W/K": ({"kg": 1, "m": 2, "s": -3, "K": -1}, ()),
    "W/(m2.K)": ({"kg": 1, "s": -3, "K": -1}, ()),
    "1/K": ({"K": -1}, ()),
    "kg/m3": ({"kg": 1, "m": -3}, (("g/cm3", 1.0e-3, 0.0),)),
    "1": ({}, ()),
}

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

_TYPES = {"Real": Real, "Integer": Integer, "Boolean": Boolean, "Enumeration": Integer}
#: the FMI type through which hosts get and set each kind of variable
_FMI_TYPE = {"Real": "Real", "Integer": "Integer", "Boolean": "Boolean", "Enumeration": "Integer"}
_FMI_TYPES = ("Real", "Integer", "Boolean", "String")
_DEFAULT = {"Real": 0.0, "Integer": 0, "Boolean": False, "String": ""}
_DESCRIBING = "describing"  # the build writes the modelDescription (reads the start values)
#: Package parts that run inside an FMU (the build ships and hashes exactly these).
SHIPPED = ("__init__.py", "physics", "parameters", "fmus")
#: Start values (and their provenance) that a build gives an FMU instead of its class's
#: defaults (``servofmu build --catalog/--preset``): {model name: {variable: (start,
#: source)}}, set by the build process; a built FMU reads its own from
#: ``resources/servofmu_build.json`` ("start"), so the package it ships stays the same.
BUILD_START: dict[str, dict[str, tuple[object, str]]] = {}


@dataclass(frozen=True)
class Item:
    """One item of an enumeration: its name (what users read and type) and meaning."""

    name: str
    description: str = ""


@dataclass(frozen=True, kw_only=True)
class Var:
    """One FMU variable (keyword arguments only).

    Attributes
    ----------
    name : FMI name (public API: tests, SSPs and users depend on it)
    type : "Real", "Integer", "Boolean" or "Enumeration" (a choice: an integer 1…n naming one
        of ``items``)
    causality : "input", "output" or "parameter"
    description : one line, with the unit in words where it helps
    start : start value (inputs, parameters; the item number of an Enumeration); outputs are
        calculated
    unit, display_unit : keys of :data:`UNITS` (Real only)
    min, max : valid range (inclusive), checked at run time as well
    variability : parameters "fixed" (default) or "tunable"; inputs "continuous"/"discrete"
    depends : outputs: the inputs they depend on directly while stepping (() for none)
    initial_depends : outputs: every input and parameter their value right after
        initialization depends on (ModelStructure/InitialUnknowns); required for outputs
    field : outputs: the attribute of the model's result record that the output copies
    source : provenance of the default (paper, catalogue, handbook, assumed, calibrated)
    items : Enumeration: the items, numbered 1, 2, … in this order
    declared_type : Enumeration: the name of its item type (variables may share one)
    allow_inf : Real outputs: +inf is a value (its description says when), not a failure
    """

    name: str
    type: str
    causality: str
    description: str
    start: object = None
    unit: str | None = None
    display_unit: str | None = None
    min: float | None = None
    max: float | None = None
    variability: str | None = None
    depends: tuple[str, ...] = ()
    initial_depends: tuple[str, ...] | None = None
    field: str | None = None
    source: str = ""
    items: tuple[Item, ...] = ()
    declared_type: str | None = None
    allow_inf: bool = False

    def item_name(self, value) -> str:
        """The item name of Enumeration value ``value`` (1-based)."""
        return self.items[value - 1].name


def real_input(name, description, start, unit, display_unit, lo, hi) -> Var:
    """A continuous Real input with its start value, unit and valid range."""
    return _real("input", name, description, start, unit, display_unit, lo, hi)


def real_parameter(name, description, start, unit, display_unit, lo, hi, **kw) -> Var:
    """A Real parameter with its default, unit and valid range (``variability`` "fixed" unless
    given, ``source`` its provenance)."""
    return _real("parameter", name, description, start, unit, display_unit, lo, hi, **kw)


def _real(causality, name, description, start, unit, display_unit, lo, hi, **kw) -> Var:
    return Var(
        name=name,
        type="Real",
        causality=causality,
        description=description,
        start=start,
        unit=unit,
        display_unit=display_unit,
        min=lo,
        max=hi,
        **kw,
    )


def output(name, description, unit=None, display_unit=None, **kw) -> Var:
    """An output (Real unless ``type`` says otherwise); keywords as :class:`Var`."""
    return Var(
        name=name,
        type=kw.pop("type", "Real"),
        causality="output",
        description=description,
        unit=unit,
        display_unit=display_unit,
        **kw,
    )


def items(choices) -> tuple[Item, ...]:
    """Enumeration items of physics choices (objects with ``name`` and ``description``)."""
    return tuple(Item(c.name, c.description) for c in choices)


def spec_parameter(spec) -> Var:
    """The parameter variable of a physics parameter specification (an object with the
    attributes of :class:`servofmu.parameters.bearing.ParameterSpec`)."""
    choice = spec.type == "Enumeration"
    return Var(
        name=spec.name,
        type=spec.type,
        causality="parameter",
        description=spec.description,
        start=spec.item(spec.default) if choice else spec.default,
        unit=spec.unit,
        display_unit=spec.display_unit,
        min=spec.min,
        max=spec.max,
        variability=spec.variability,
        source=spec.source,
        items=items(spec.choices),
        declared_type=spec.declared_type,
    )


def variables_of(cls, start: dict[str, tuple[object, str]] | None = None) -> tuple[Var, ...]:
    """The VARIABLES of slave class ``cls`` with the start values and provenance of ``start``
    (default: :data:`BUILD_START` of the class), as its modelDescription and documentation
    show them."""
    start = BUILD_START.get(cls.__name__, {}) if start is None else start
    by_name = {v.name for v in cls.VARIABLES}
    unknown = sorted(set(start) - by_name)
    if unknown:
        raise ValueError(f"{cls.__name__}: start values for unknown variables {unknown}")
    return tuple(
        dataclasses.replace(v, start=start[v.name][0], source=start[v.name][1])
        if v.name in start
        else v
        for v in cls.VARIABLES
    )


def package_hash(root: Path | None = None) -> str:
    """SHA-256 over the relative paths and contents of the .py and .toml files and the
    compiled extension modules (.so, .pyd) of the parts of the servofmu package an FMU runs
    (:data:`SHIPPED`): identifies the code an FMU was built with, compiled parts included. The
    same for the development tree and an FMU's staged copy."""
    root = Path(__file__).resolve().parents[1] if root is None else Path(root)
    digest = hashlib.sha256()
    for f in sorted(_shipped_files(root)):
        digest.update(f.relative_to(root).as_posix().encode())
        digest.update(f.read_bytes())
    return digest.hexdigest()


#: The files of the shipped parts that make up its code: sources, data, compiled modules.
_HASHED = (".py", ".toml", ".so", ".pyd")


def _shipped_files(root: Path) -> list[Path]:
    files = []
    for part in SHIPPED:
        path = root / part
        candidates = [path] if path.is_file() else path.rglob("*")
        files += [
            f
            for f in candidates
            if f.is_file() and f.suffix in _HASHED and "__pycache__" not in f.parts
        ]
    return files


# the code imported in this process, hashed once while its files certainly exist
_RUNTIME_HASH = package_hash()


def _runtime_hash() -> str:
    return _RUNTIME_HASH


class ServoSlave(Fmi2Slave):
    """Base class of the servofmu FMUs; see the module docstring."""

    VARIABLES: tuple[Var, ...] = ()
    PHYSICS: tuple[str, ...] = ()  # modules whose equations the documentation shows
    FEEDTHROUGH = False
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-3)  # start, stop, step [s]
    author = "servofmu"
    license = "MIT"
    version = __version__
    #: whether every instance of this class so far runs under servofmu's export (the class
    #: methods that (de)serialise states raise only then); None before the first instance
    _class_reports: bool | None = None

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        problems = check_variables(cls.VARIABLES)
        if problems:
            raise TypeError(f"{cls.__name__}.VARIABLES: " + "; ".join(problems))

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        from pythonfmu.default_experiment import DefaultExperiment

        build_start = self._check_build()
        # after every import that loads a C++ extension (servofmu.fmus loads all of them)
        register_interpreter_finaliser(self.resources, type(self).__name__)
        export = export_of(self.resources, type(self).__name__)
        self._export = export or "no FMU binary (imported as a library)"
        self._reports = reports_statuses(export)
        cls = type(self)
        if export is not None:  # (an instance made by the build says nothing)
            cls._class_reports = self._reports and cls._class_reports is not False
        start, stop, step = self.DEFAULT_EXPERIMENT
        self.default_experiment = DefaultExperiment(
            start_time=start, stop_time=stop, step_size=step
        )
        self.variables = variables_of(cls, build_start)
        self._by_name = {v.name: v for v in self.variables}
        if len(self._by_name) != len(self.variables):
            names = [v.name for v in self.variables]
            raise ValueError(f"{cls.__name__}: duplicate variable names {names}")
        self._types = {v.name: v.type for v in self.variables}
        self._inputs = [v for v in self.variables if v.causality == "input"]
        self._params = [v for v in self.variables if v.causality == "parameter"]
        self._outputs = [v for v in self.variables if v.causality == "output"]
        self._input_checks = _ranges(self._inputs)
        self._inputs_in_range = _range_checker(tuple(self._input_checks))
        self._param_checks = _ranges(self._params)
        self._choices = [v for v in self._params + self._inputs if v.type == "Enumeration"]
        self._copy = _copier(tuple((v.name, v.field) for v in self._outputs if v.field))
        reals = [v for v in self._outputs if v.type == "Real"]
        self._outputs_finite = _finite_checker(tuple((v.name, v.allow_inf) for v in reals))
        self._inf_ok = frozenset(v.name for v in reals if v.allow_inf)
        for v in self.variables:
            setattr(self, v.name, v.start if v.causality != "output" else _zero(v.type))
        self._dirty = True  # inputs changed since the outputs were computed
        self._configured = False  # parameters turned into model objects
        self._error = ""  # why the FMU cannot compute, or why it refused a call
        self._phase = INSTANTIATED  # the FMI 2.0 state (calls.py)
        self._start_time: float | None = None  # fmi2SetupExperiment's startTime
        self._time: float | None = None  # where the next fmi2DoStep must start
        for v in self.variables:
            self._register(v)
        self._tables()
        self._announced = False
        if self._reports:  # pythonfmu's binary would free its logger before this message
            self._announce()

    def _announce(self):
        """Say once which export runs the instance (pythonfmu's binary: at the first call
        after the instantiation; freeing an instance with a message still queued crashes it
        when logging is on)."""
        if not self._announced:
            self._announced = True
            how = (
                "a host's mistake gets fmi2Error"
                if self._reports
                else "a host's mistake is logged and the next fmi2DoStep discarded (compile "
                "servofmu's export, then rebuild, for fmi2Error statuses)"
            )
            model = type(self).__name__
            self.log(f"{self.instance_name}: {model} runs under {self._export}: {how}")

    # ------------------------------------------------------------------ registration
    def _register(self, v: Var):
        kwargs = {
            "causality": getattr(Fmi2Causality, v.causality),
            "description": v.description,
        }
        if v.causality == "parameter":
            kwargs["variability"] = getattr(Fmi2Variability, v.variability or "fixed")
            kwargs["initial"] = Fmi2Initial.exact
        elif v.causality == "input":
            kwargs["variability"] = getattr(
                Fmi2Variability, v.variability or ("continuous" if v.type == "Real" else "discrete")
            )
        else:
            kwargs["variability"] = (
                Fmi2Variability.continuous if v.type == "Real" else Fmi2Variability.discrete
            )
            kwargs["initial"] = Fmi2Initial.calculated
        getter = functools.partial(getattr, self, v.name)
        setter = functools.partial(setattr, self, v.name)
        self.register_variable(_TYPES[v.type](v.name, getter=getter, setter=setter, **kwargs))

    def _tables(self):
        """The value references each fmi2Get*/fmi2Set* call accepts, per FMI type and state
        (calls.py): every variable is readable; inputs and parameters are writable until
        initialization ends, then inputs and tunable parameters."""
        self._vr = {v.name: vr for vr, v in enumerate(self.variables)}
        self._readable = {kind: {} for kind in _FMI_TYPES}
        self._writable = {p: {kind: {} for kind in _FMI_TYPES} for p in PHASES}
        for vr, v in enumerate(self.variables):
            kind = _FMI_TYPE[v.type]
            self._readable[kind][vr] = v.name
            if v.causality == "output":
                continue
            self._writable[INSTANTIATED][kind][vr] = v.name
            self._writable[INITIALIZATION][kind][vr] = v.name
            if v.causality == "input" or v.variability == "tunable":
                self._writable[STEP_COMPLETE][kind][vr] = v.name
        self._param_vrs = frozenset(self._vr[v.name] for v in self._params)

    # ------------------------------------------------------------------ refusals
    def _refuse(self, call: str, message: str, result=None):
        """A host's mistake: fmi2Error with the message under servofmu's export; under
        pythonfmu's binary the message is logged, ``result`` is returned (a step: discarded)
        and the next fmi2DoStep is refused with the message. Either way the instance is then
        in the error state (calls.py)."""
        self._announce()
        text = f"{call}: {message}"
        if self._phase != ERROR:
            self._error = text
        self._phase = ERROR
        if self._reports:
            raise FMIError(f"{self.instance_name}: {text}")
        self.log(f"{self.instance_name}: {text}", status=Fmi2Status.error)
        return result

    def _sequence(self, call: str) -> str:
        """Why ``call`` is illegal now ("" if it is not), with the failure that led here."""
        problem = sequence_problem(call, self._phase)
        if problem and self._phase in (ERROR, STEP_FAILED) and self._error:
            problem += f"; it failed with: {self._error}"
        return problem

    def _internal(self, call: str, exc: BaseException, result=None):
        """An exception of servofmu's own code: never passed on to pythonfmu."""
        return self._refuse(call, f"internal error {type(exc).__name__}: {exc}", result)

    def _reference_problem(self, kind: str, vrs, writing: bool) -> str:
        """Why one of ``vrs`` cannot be read or written as ``kind`` now."""
        table = (self._writable[self._phase] if writing else self._readable)[kind]
        for vr in vrs:
            if vr in table:
                continue
            if not (type(vr) is int and 0 <= vr < len(self.variables)):
                return f"valueReference {vr!r} is not a variable of {type(self).__name__}"
            v = self.variables[vr]
            if _FMI_TYPE[v.type] != kind:
                return (
                    f"valueReference {vr} is {v.name!r}, a{'n' if v.type[0] in 'IE' else ''} "
                    f"{_FMI_TYPE[v.type]}, not a{'n' if kind[0] == 'I' else ''} {kind}"
                )
            if v.causality == "output":
                return f"{v.name!r} (valueReference {vr}) is an output: a host cannot set it"
            if self._phase == STEP_COMPLETE:
                return (
                    f"{v.name!r} (valueReference {vr}) is a fixed parameter: it can be set "
                    "only before fmi2ExitInitializationMode"
                )
            return f"{v.name!r} (valueReference {vr}) cannot be set in {self._phase}"
        return "unknown value reference"

    # ------------------------------------------------------------------ fmi2Get*, fmi2Set*
    def get_real(self, vrs):
        return self._get("fmi2GetReal", "Real", vrs)

    def get_integer(self, vrs):
        return self._get("fmi2GetInteger", "Integer", vrs)

    def get_boolean(self, vrs):
        return self._get("fmi2GetBoolean", "Boolean", vrs)

    def get_string(self, vrs):
        return self._get("fmi2GetString", "String", vrs)

    def set_real(self, vrs, values):
        self._set("fmi2SetReal", "Real", vrs, values)

    def set_integer(self, vrs, values):
        self._set("fmi2SetInteger", "Integer", vrs, values)

    def set_boolean(self, vrs, values):
        self._set("fmi2SetBoolean", "Boolean", vrs, values)

    def set_string(self, vrs, values):
        self._set("fmi2SetString", "String", vrs, values)

    def _get(self, call: str, kind: str, vrs):
        try:
            phase = self._phase
            if phase not in READABLE and phase != _DESCRIBING:
                return self._refuse(
                    call,
                    f"values can be read from initialization mode on (now: {phase})",
                    [_DEFAULT[kind]] * len(vrs),
                )
            if self._dirty and (
                phase == INITIALIZATION or (phase == STEP_COMPLETE and self.FEEDTHROUGH)
            ):
                self._update_outputs(call)
            table = self._readable[kind]
            try:
                values = [getattr(self, table[vr]) for vr in vrs]
            except (KeyError, TypeError):
                problem = self._reference_problem(kind, vrs, False)
                return self._refuse(call, problem, [_DEFAULT[kind]] * len(vrs))
            if kind == "Real":
                total = sum(values)
                if total - total != 0.0:  # NaN or an infinity among them (or a huge sum)
                    bad = [
                        f"{table[vr]} = {x!r}"
                        for vr, x in zip(vrs, values, strict=True)
                        if not (math.isfinite(x) or (x == math.inf and table[vr] in self._inf_ok))
                    ]
                    if bad:
                        return self._refuse(call, f"not finite: {', '.join(bad)}", values)
            return values
        except FMIError:
            raise
        except (Exception, KeyboardInterrupt) as exc:
            return self._internal(call, exc, [_DEFAULT[kind]] * len(vrs))

    def _set(self, call: str, kind: str, vrs, values):
        try:
            table = self._writable[self._phase][kind]
            try:
                names = [table[vr] for vr in vrs]
            except (KeyError, TypeError):
                return self._refuse(call, self._reference_problem(kind, vrs, True))
            for name, value in zip(names, values, strict=True):
                setattr(self, name, value)
            self._dirty = True
            if not self._param_vrs.isdisjoint(vrs):
                self._configured = False
        except FMIError:
            raise
        except (Exception, KeyboardInterrupt) as exc:
            return self._internal(call, exc)

    def _update_outputs(self, call: str):
        """The outputs after inputs or parameters changed, before they are read: in
        Initialization Mode from the values set so far (a problem is left for
        fmi2ExitInitializationMode to report); an algebraic FMU's from its inputs (a problem
        refuses the read)."""
        if self._phase == INITIALIZATION:
            if self.FEEDTHROUGH:
                self._refresh()
            else:
                self._initial_outputs()
        elif not self._refresh():
            self._refuse(call, self._error)

    # ------------------------------------------------------------------ checks
    def _bad_input(self) -> str:
        """Message for the first input outside its declared range, else "" (every step: one
        compiled test, the loop only to name a bad input)."""
        if self._inputs_in_range(self):
            return ""
        for name, lo, hi in self._input_checks:
            x = getattr(self, name)
            if not lo <= x <= hi:  # NaN fails too
                return f"{name} = {x!r} is outside the valid range [{lo:g}, {hi:g}]"
        return ""

    def _bad_parameter(self) -> str:
        """Message for the first parameter outside its range or items, else "" (checked
        whenever a parameter changed)."""
        for name, lo, hi in self._param_checks:
            x = getattr(self, name)
            if not lo <= x <= hi:
                return f"{name} = {x!r} is outside the valid range [{lo:g}, {hi:g}]"
        for v in self._choices:
            x = getattr(self, v.name)
            if type(x) is not int or not 1 <= x <= len(v.items):
                items = ", ".join(f"{i} = {item.name}" for i, item in enumerate(v.items, 1))
                return f"{v.name} = {x!r} is not one of the items ({items})"
        return ""

    def _bad_output(self) -> str:
        """Message naming the first Real output that is not finite (+inf where the variable
        allows it), else ""."""
        if self._outputs_finite(self):
            return ""
        for v in self._outputs:
            x = getattr(self, v.name)
            if v.type == "Real" and not (math.isfinite(x) or (x == math.inf and v.allow_inf)):
                return f"{v.name} = {x!r} is not finite: the step is not taken"
        return ""

    def item(self, name: str) -> str:
        """The item name of the current value of Enumeration variable ``name``."""
        return self._by_name[name].item_name(getattr(self, name))

    def copy_outputs(self, record):
        """Set every output that names a ``field`` from ``record``: the one map from the
        model's result to the FMU's outputs (each output's ``field``)."""
        self._copy(self, record)

    def output_copier(self, fields):
        """A function ``copy(slave, record)`` that sets the outputs whose ``field`` is in
        ``fields`` from ``record`` (part of :meth:`copy_outputs`, compiled once)."""
        return _copier(tuple((v.name, v.field) for v in self._outputs if v.field in fields))

    @staticmethod
    def output_setter(names):
        """A function ``set(slave, values)`` doing ``slave.<names[i]> = values[i]`` (compiled
        once: the outputs of one model call in one statement)."""
        return _setter(tuple(names))

    def _ensure_configured(self) -> bool:
        """Build the model from the parameters if needed; False (and ``_error``) on failure."""
        if self._configured:
            return True
        bad = self._bad_parameter()
        if not bad:
            try:
                self.configure()
            except (ValueError, KeyError, TypeError, ArithmeticError) as exc:
                bad = f"parameters rejected: {exc}"
        if bad:
            self._error = bad
            return False
        self._configured = True
        self._error = ""
        return True

    def _refresh(self) -> bool:
        """Recompute the outputs of an algebraic FMU from the current inputs."""
        if not (self._configured or self._ensure_configured()):
            return False
        bad = self._bad_input()
        if bad:
            self._error = bad
            return False
        try:
            self.compute()
        except Exception as exc:  # an output read calls this: no exception may leave it
            self._error = f"{type(exc).__name__}: {exc}"
            return False
        bad = self._bad_output()
        if bad:
            self._error = bad
            return False
        self._error = ""
        self._dirty = False
        return True

    def _initial_outputs(self):
        """Stepped FMUs in Initialization Mode: the outputs at the start time from the
        parameters and inputs set so far, so that a master propagating values before
        fmi2ExitInitializationMode sees e.g. the motor's initial angle and not 0. A problem
        is left for fmi2ExitInitializationMode to report."""
        try:
            if self._ensure_configured() and not self._bad_input() and self._initialise():
                self._dirty = False
        except Exception:  # no exception may leave an FMI call; reported at exit
            pass

    # ------------------------------------------------------------------ FMI calls
    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        call = "fmi2SetupExperiment"
        try:
            self._announce()
            problem = self._sequence(call) or _experiment_problem(start_time, stop_time, tolerance)
            if problem:
                return self._refuse(call, problem)
            self._start_time = self._time = float(start_time)
        except FMIError:
            raise
        except (Exception, KeyboardInterrupt) as exc:
            return self._internal(call, exc)

    def enter_initialization_mode(self):
        call = "fmi2EnterInitializationMode"
        self._announce()
        problem = self._sequence(call)
        if problem:
            return self._refuse(call, problem)
        self._phase = INITIALIZATION
        self._dirty = True

    def exit_initialization_mode(self):
        call = "fmi2ExitInitializationMode"
        try:
            problem = self._sequence(call)
            if problem:
                return self._refuse(call, problem)
            ok = self._ensure_configured() and (
                self._refresh() if self.FEEDTHROUGH else self._initialise()
            )
            if ok and not self.FEEDTHROUGH:
                self._error = self._bad_output()
                ok = not self._error
            if not ok:
                return self._refuse(call, self._error)
            self._phase = STEP_COMPLETE
        except FMIError:
            raise
        except (Exception, KeyboardInterrupt) as exc:
            return self._internal(call, exc)

    def do_step(self, current_time: float, step_size: float) -> bool:
        call = "fmi2DoStep"
        try:
            problem = "" if self._phase == STEP_COMPLETE else self._sequence(call)
            problem = problem or self._step_problem(current_time, step_size)
            if not problem and not (self._configured or self._ensure_configured()):
                problem = self._error
            problem = problem or self._bad_input()
            if problem:  # a host's mistake: the step is not carried out at all
                return self._refuse(call, problem, False)
            if self._time is None:  # no fmi2SetupExperiment: the first step starts the run
                self._start_time = self._time = current_time
            if self.FEEDTHROUGH:
                ok = self._refresh() if self._dirty else True
            else:  # a model failure mid-step (or a step beyond its bound): discarded
                ok = self.advance(current_time, step_size)
                if ok:
                    self._error = self._bad_output()
                    ok = not self._error
            if not ok:
                return self._discard()
            self._time = current_time + step_size
            return True
        except FMIError:
            raise
        except (Exception, KeyboardInterrupt) as exc:
            self._error = f"{type(exc).__name__}: {exc}"
            return self._discard()

    def _step_problem(self, t: float, h: float) -> str:
        """Why fmi2DoStep(t, h) cannot be carried out: a point or step size that is not a
        finite number, h ≤ 0 (FMI 2.0: h > 0), or, for a stepped FMU, a point that does not
        continue the last step (or the start time, or the time of a restored state)."""
        if not (-math.inf < t < math.inf and 0.0 < h < math.inf):
            return (
                f"currentCommunicationPoint = {t!r}, communicationStepSize = {h!r}: the point "
                "must be finite and the step size finite and > 0"
            )
        expected = None if self.FEEDTHROUGH else self._time
        if expected is not None and abs(t - expected) > 1e-9 * max(abs(t), abs(expected), h):
            return (
                f"currentCommunicationPoint = {t!r} s does not continue the last step, which "
                f"ended at {expected!r} s (FMI 2.0: the point and the FMU's state must agree; "
                "restore a state saved at that point with fmi2SetFMUstate, or fmi2Reset)"
            )
        return ""

    def _discard(self) -> bool:
        """A step the model could not take: fmi2Discard with a logged message; the instance is
        then in step failed (calls.py)."""
        self._phase = STEP_FAILED
        self.log(f"{self.instance_name}: {self._error}", status=Fmi2Status.discard)
        return False

    def terminate(self):
        call = "fmi2Terminate"
        problem = self._sequence(call)
        if problem:
            return self._refuse(call, problem)
        self._phase = TERMINATED

    # ------------------------------------------------------------------ state
    def _get_fmu_state(self):
        try:
            return {
                "fmu": type(self).__name__,
                "package": _runtime_hash(),
                "phase": self._phase,
                "time": self._time,
                "start_time": self._start_time,
                "values": {v.name: _CAST[v.type](getattr(self, v.name)) for v in self.variables},
                "hidden": self.hidden_state(),
                "dirty": self._dirty,
                "error": self._error,
            }
        except FMIError:
            raise
        except (Exception, KeyboardInterrupt) as exc:
            return self._internal("fmi2GetFMUstate", exc, {"refused": str(exc)})

    def _set_fmu_state(self, state):
        call = "fmi2SetFMUstate"
        try:
            if isinstance(state, dict) and set(state) == {"refused"}:
                problem = str(state["refused"])
            else:
                problem = state_problem(state, type(self).__name__, _runtime_hash(), self._types)
            if not problem and set(state["hidden"]) != set(self.hidden_state()):
                problem = f"its hidden state has the fields {sorted(state['hidden'])}"
            if problem:
                return self._refuse(call, f"the state is refused ({problem}); nothing restored")
            saved = self._get_fmu_state()
            try:
                self._restore(state)
            except (Exception, KeyboardInterrupt) as exc:
                self._restore(saved)
                return self._refuse(
                    call, f"the state is refused ({type(exc).__name__}: {exc}); nothing restored"
                )
        except FMIError:
            raise
        except (Exception, KeyboardInterrupt) as exc:
            return self._internal(call, exc)

    def _restore(self, state: dict):
        """Every declared field of a checked state (never anything else: the variables by
        name, the hidden state through the FMU's own :meth:`restore_hidden_state`)."""
        values = state["values"]
        params_changed = any(values[v.name] != getattr(self, v.name) for v in self._params)
        for v in self.variables:
            setattr(self, v.name, _CAST[v.type](values[v.name]))
        if params_changed or not self._configured:
            self._configured = False
            self._ensure_configured()
        self.restore_hidden_state(copy.deepcopy(state["hidden"]))
        self._dirty, self._error = state["dirty"], state["error"]
        self._phase, self._time, self._start_time = (
            state["phase"],
            state["time"],
            state["start_time"],
        )

    @classmethod
    def _fmu_state_to_bytes(cls, state) -> bytes:
        try:
            return json.dumps(state, allow_nan=True).encode("utf-8")
        except (Exception, KeyboardInterrupt) as exc:
            message = f"fmi2SerializeFMUstate: the state cannot be serialised ({exc})"
            if cls._class_reports:
                raise FMIError(message) from None
            return json.dumps({"refused": message}).encode("utf-8")

    @classmethod
    def _fmu_state_from_bytes(cls, data) -> dict:
        try:
            state = json.loads(bytes(data).decode("utf-8"))
            types = {v.name: v.type for v in cls.VARIABLES}
            problem = state_problem(state, cls.__name__, _runtime_hash(), types)
        except (Exception, KeyboardInterrupt) as exc:
            problem = f"{type(exc).__name__}: {exc}"
        if not problem:
            return state
        message = f"fmi2DeSerializeFMUstate: not a state of {cls.__name__} ({problem})"
        if cls._class_reports:
            raise FMIError(message)
        return {"refused": message}

    # ------------------------------------------------------------------ version
    def _check_build(self) -> dict[str, tuple[object, str]] | None:
        """Refuse a different servofmu; the build's start values (None: the class's, or those
        of :data:`BUILD_START` while building)."""
        info_file = Path(self.resources or ".") / BUILD_INFO
        if not info_file.is_file():
            return None  # not running from a built FMU (e.g. imported in a test or the build)
        info = json.loads(info_file.read_text())
        here = _runtime_hash()
        if info["package_hash"] != here:
            raise RuntimeError(different_build(type(self).__name__, info, here))
        return {name: (value, "") for name, value in info.get("start", {}).items()}

    # ------------------------------------------------------------------ XML
    def to_xml(self, model_options=None):
        """The complete modelDescription (see module docstring)."""
        phase, self._phase = self._phase, _DESCRIBING  # pythonfmu reads the start values
        try:
            root = super().to_xml(model_options or {})
        finally:
            self._phase = phase
        variables = root.find("ModelVariables")
        for sv in variables.findall("ScalarVariable"):
            _complete_variable(sv, self._by_name[sv.get("name")])
        after = root.find("CoSimulation")
        for block in (_unit_definitions(self.variables), _type_definitions(self.variables)):
            if block is not None:
                root.insert(list(root).index(after) + 1, block)
                after = block
        annotations = _vendor_annotations(self.variables)
        if annotations is not None:
            root.insert(list(root).index(variables), annotations)
        root.remove(root.find("ModelStructure"))
        root.append(_model_structure(self.variables))
        return root

    # ------------------------------------------------------------------ hooks
    def configure(self):
        """Turn the parameters into model objects; raise ValueError on a bad combination."""

    def compute(self):
        """Algebraic FMUs: set the outputs from the current inputs."""
        raise NotImplementedError

    def advance(self, current_time: float, step_size: float) -> bool:
        """Stepped FMUs: advance the hidden state over the step and set the outputs; False
        (with ``_error`` naming why) when the step cannot be taken."""
        raise NotImplementedError

    def _initialise(self) -> bool:
        """Stepped FMUs: set the outputs at the start time (default: ``initialise()``)."""
        try:
            self.initialise()
        except (ValueError, ArithmeticError) as exc:
            self._error = f"{type(exc).__name__}: {exc}"
            return False
        return True

    def initialise(self):
        """Stepped FMUs: outputs right after initialization."""

    def hidden_state(self) -> dict:
        """JSON-serialisable state not held in FMI variables (the same fields every time)."""
        return {}

    def restore_hidden_state(self, state: dict):
        """Inverse of :meth:`hidden_state`; raises (ValueError, TypeError, KeyError) on a
        field it cannot take, and the base class then restores what was there."""


_CAST = {"Real": float, "Integer": int, "Boolean": bool, "Enumeration": int}


@functools.cache
def _copier(pairs: tuple[tuple[str, str], ...]):
    """A function ``copy(slave, record)`` doing ``slave.<name> = record.<field>`` for each
    pair, compiled once from the map: per step it costs what the assignments written out cost
    (0.4 µs for BearingFriction's 19 outputs, against 4 µs for a setattr/getattr loop)."""
    if not all(n.isidentifier() and f.isidentifier() for n, f in pairs):
        raise ValueError(f"output names and fields must be identifiers: {pairs}")
    body = "".join(f"    slave.{n} = record.{f}\n" for n, f in pairs) or "    pass\n"
    namespace = {}
    exec(f"def copy(slave, record):\n{body}", namespace)  # names checked above
    return namespace["copy"]


@functools.cache
def _setter(names: tuple[str, ...]):
    """See :meth:`ServoSlave.output_setter`."""
    if not names or not all(n.isidentifier() for n in names):
        raise ValueError(f"output names must be identifiers: {names}")
    namespace = {}
    targets = ", ".join(f"slave.{n}" for n in names)
    exec(f"def assign(slave, values):\n    {targets}, = values\n", namespace)  # names checked
    return namespace["assign"]


@functools.cache
def _range_checker(checks: tuple[tuple[str, float, float], ...]):
    """A function ``ok(slave)``: True when every ``slave.<name>`` lies in [lo, hi] (NaN does
    not), for the (name, lo, hi) of ``checks``; compiled once (0.3 µs for BearingFriction's 8
    inputs, against 1 µs for the loop of :meth:`ServoSlave._bad_input`)."""
    if not all(name.isidentifier() for name, _, _ in checks):
        raise ValueError(f"input names must be identifiers: {checks}")
    namespace = {}
    tests = [f"lo{i} <= slave.{name} <= hi{i}" for i, (name, _, _) in enumerate(checks)]
    for i, (_, lo, hi) in enumerate(checks):
        namespace[f"lo{i}"], namespace[f"hi{i}"] = lo, hi
    exec(
        f"def ok(slave):\n    return {' and '.join(tests) or 'True'}\n", namespace
    )  # names checked
    return namespace["ok"]


@functools.cache
def _finite_checker(outputs: tuple[tuple[str, bool], ...]):
    """A function ``ok(slave)``: True when every ``slave.<name>`` of ``outputs`` (name,
    allow_inf) is finite (+inf too where allowed); compiled once like :func:`_range_checker`."""
    if not all(name.isidentifier() for name, _ in outputs):
        raise ValueError(f"output names must be identifiers: {outputs}")
    tests = [f"-inf < slave.{n} {'<=' if inf else '<'} inf" for n, inf in outputs]
    namespace = {"inf": math.inf}
    exec(  # names checked above
        f"def ok(slave):\n    return {' and '.join(tests) or 'True'}\n", namespace
    )
    return namespace["ok"]


def _experiment_problem(start, stop, tolerance) -> str:
    """Why fmi2SetupExperiment's arguments are unusable ("" when they are not)."""
    if not math.isfinite(start):
        return f"startTime = {start!r} is not finite"
    if stop is not None and not (math.isfinite(stop) and stop >= start):
        return f"stopTime = {stop!r} is not a finite time at or after startTime = {start!r}"
    if tolerance is not None and not (math.isfinite(tolerance) and tolerance >= 0.0):
        return f"tolerance = {tolerance!r} is not a finite number ≥ 0"
    return ""


def check_variables(variables) -> list[str]:
    """Every problem of a VARIABLES table (empty: fine): types, causalities, enumeration
    items, and outputs' dependencies naming inputs and parameters that exist."""
    problems, names = [], [v.name for v in variables]
    knowns = {v.name: v.causality for v in variables if v.causality in ("input", "parameter")}
    if len(set(names)) != len(names):
        problems.append(f"duplicate variable names in {names}")
    for v in variables:
        if v.type not in _TYPES or v.causality not in ("input", "output", "parameter"):
            problems.append(f"{v.name}: type {v.type!r} / causality {v.causality!r}")
        if (v.type == "Enumeration") != bool(v.items) or (v.items and not v.declared_type):
            problems.append(
                f"{v.name}: an Enumeration needs items and a declared_type, and only it"
            )
        if v.causality != "output":
            continue
        if v.initial_depends is None:
            problems.append(f"output {v.name}: initial_depends not declared")
        wrong = [d for d in v.depends if knowns.get(d) != "input"]
        wrong += [d for d in v.initial_depends or () if d not in knowns]
        wrong += [d for d in v.depends if d not in (v.initial_depends or ())]
        if wrong:
            problems.append(f"output {v.name}: dependencies {wrong} are not inputs/parameters")
    return problems


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


def _ranges(variables) -> list[tuple[str, float, float]]:
    """(name, min, max) of the Real and Integer variables, open ends as ±inf."""
    return [
        (v.name, -math.inf if v.min is None else v.min, math.inf if v.max is None else v.max)
        for v in variables
        if v.type in ("Real", "Integer")
    ]


def _zero(kind: str):
    return {"Real": 0.0, "Integer": 0, "Boolean": False, "Enumeration": 1}[kind]

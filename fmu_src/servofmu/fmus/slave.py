"""Common machinery of the servofmu FMU slaves (pythonfmu ``Fmi2Slave``).

Each FMU declares its variables once, as a tuple of :class:`Var`; from that one list this
base class

- registers the variables with pythonfmu (setters store the value and never raise);
- writes the complete modelDescription (``to_xml``): UnitDefinitions with display units, units,
  min/max, descriptions, variability and initial attributes, ModelStructure with the outputs'
  dependencies and the InitialUnknowns, DefaultExperiment — what pythonfmu does not write;
- checks inputs and parameters against their declared ranges and reports a bad value as a
  logged message naming the variable and its value, with ``fmi2Discard`` from the next
  ``fmi2DoStep`` (pythonfmu maps any escaping Python exception to ``fmi2Fatal``, and the only
  non-fatal status a Python slave can return is the discard of a step: so no exception ever
  leaves an FMI call here);
- saves and restores the whole state, hidden state included, as JSON (``fmi2GetFMUstate``,
  ``fmi2SerializeFMUstate``);
- refuses to run (at instantiation, with a clear message) when the servofmu package already
  imported in the process is not the one the FMU was built with.

Two kinds of FMU: *algebraic* ones (``FEEDTHROUGH = True``: BearingFriction,
ActuatorStiffness) compute their outputs from the current inputs, lazily, whenever an output
is read after an input changed; *stepped* ones (DCMotor, ServoController) advance a hidden
state in ``do_step`` and their outputs do not depend directly on the inputs.
"""

from __future__ import annotations

import hashlib
import json
import math
from dataclasses import dataclass
from pathlib import Path
from xml.etree.ElementTree import Element, SubElement

from pythonfmu import Boolean, Fmi2Causality, Fmi2Slave, Fmi2Variability, Integer, Real, String
from pythonfmu.enums import Fmi2Initial, Fmi2Status

from .. import __version__
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
    "1": ({}, ()),
}

_TYPES = {"Real": Real, "Integer": Integer, "Boolean": Boolean, "String": String}


@dataclass(frozen=True)
class Var:
    """One FMU variable.

    Attributes
    ----------
    name : FMI name (public API: DESIGN §3)
    type : "Real", "Integer", "Boolean" or "String"
    causality : "input", "output" or "parameter"
    description : one line, with the unit in words where it helps
    start : start value (inputs, parameters); outputs are calculated
    unit, display_unit : keys of :data:`UNITS` (Real only)
    min, max : valid range (inclusive), checked at run time as well
    variability : parameters "fixed" (default) or "tunable"; inputs "continuous"/"discrete"
    depends : outputs: names of the inputs they depend on directly (() for none)
    source : provenance of the default (paper, catalogue, handbook, assumed, calibrated)
    choices : String parameters: the allowed values (None: any catalogue key, checked later)
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
    source: str = ""
    choices: tuple[str, ...] | None = None


def package_hash(root: Path | None = None) -> str:
    """SHA-256 over the relative paths and contents of the servofmu package's .py and .toml
    files: identifies the code an FMU was built with."""
    root = Path(__file__).resolve().parents[1] if root is None else Path(root)
    digest = hashlib.sha256()
    for f in sorted(root.rglob("*")):
        if f.suffix in (".py", ".toml") and "__pycache__" not in f.parts:
            digest.update(f.relative_to(root).as_posix().encode())
            digest.update(f.read_bytes())
    return digest.hexdigest()


# the code imported in this process, hashed once while its files certainly exist
_RUNTIME_HASH = package_hash()


def _runtime_hash() -> str:
    return _RUNTIME_HASH


class ServoSlave(Fmi2Slave):
    """Base class of the four servofmu FMUs; see the module docstring."""

    VARIABLES: tuple[Var, ...] = ()
    PHYSICS: tuple[str, ...] = ()  # modules whose equations the documentation shows
    FEEDTHROUGH = False
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-3)  # start, stop, step [s]
    author = "servofmu"
    license = "MIT"
    version = __version__

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        from pythonfmu.default_experiment import DefaultExperiment

        self._check_build()
        # after every import that loads a C++ extension (servofmu.fmus loads all of them)
        register_interpreter_finaliser(self.resources, type(self).__name__)
        start, stop, step = self.DEFAULT_EXPERIMENT
        self.default_experiment = DefaultExperiment(
            start_time=start, stop_time=stop, step_size=step
        )
        self._by_name = {v.name: v for v in self.VARIABLES}
        if len(self._by_name) != len(self.VARIABLES):
            names = [v.name for v in self.VARIABLES]
            raise ValueError(f"{type(self).__name__}: duplicate variable names {names}")
        self._inputs = [v for v in self.VARIABLES if v.causality == "input"]
        self._params = [v for v in self.VARIABLES if v.causality == "parameter"]
        self._outputs = [v for v in self.VARIABLES if v.causality == "output"]
        self._input_checks = _ranges(self._inputs)
        self._param_checks = _ranges(self._params)
        for v in self.VARIABLES:
            setattr(self, v.name, v.start if v.causality != "output" else _zero(v.type))
        self._dirty = True  # inputs changed since the outputs were computed
        self._configured = False  # parameters turned into model objects
        self._error = ""  # why the FMU cannot compute (bad parameter or input)
        self._initializing = False  # between fmi2EnterInitializationMode and its exit
        for v in self.VARIABLES:
            self._register(v)

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
        name = v.name
        if v.causality == "output":
            getter = self._output_getter(name)
        else:

            def getter(_n=name):
                return getattr(self, _n)

        # setters store the value and never raise (it is checked when used)
        if v.causality == "parameter":

            def setter(value, _n=name):
                setattr(self, _n, value)
                self._configured = False
                self._dirty = True

        else:

            def setter(value, _n=name):
                setattr(self, _n, value)
                self._dirty = True

        self.register_variable(_TYPES[v.type](name, getter=getter, setter=setter, **kwargs))

    def _output_getter(self, name: str):
        def getter():
            if self._dirty:
                if self.FEEDTHROUGH:
                    self._refresh()
                elif self._initializing:
                    self._initial_outputs()
            return getattr(self, name)

        return getter

    # ------------------------------------------------------------------ checks
    def _bad_input(self) -> str:
        """Message for the first input outside its declared range, else "" (every step)."""
        for name, lo, hi in self._input_checks:
            x = getattr(self, name)
            if not lo <= x <= hi:  # NaN fails too
                return f"{name} = {x!r} is outside the valid range [{lo:g}, {hi:g}]"
        return ""

    def _bad_parameter(self) -> str:
        """Message for the first parameter outside its range or choices, else "" (checked
        whenever a parameter changed)."""
        for name, lo, hi in self._param_checks:
            x = getattr(self, name)
            if not lo <= x <= hi:
                return f"{name} = {x!r} is outside the valid range [{lo:g}, {hi:g}]"
        for v in self._params:
            if v.choices is not None and getattr(self, v.name) not in v.choices:
                return f"{v.name} = {getattr(self, v.name)!r} is not one of {list(v.choices)}"
        return ""

    def _ensure_configured(self) -> bool:
        """Build the model from the parameters if needed; False (and a log) on failure."""
        if self._configured:
            return True
        bad = self._bad_parameter()
        if not bad:
            try:
                self.configure()
            except (ValueError, KeyError, TypeError) as exc:
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
        except (ValueError, ArithmeticError) as exc:
            self._error = f"{type(exc).__name__}: {exc}"
            return False
        self._error = ""
        self._dirty = False
        return True

    def _report(self, status: Fmi2Status):
        self.log(f"{self.instance_name}: {self._error}", status=status)

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
    def enter_initialization_mode(self):
        self._initializing = True

    def exit_initialization_mode(self):
        self._initializing = False
        try:
            ok = self._ensure_configured() and (
                self._refresh() if self.FEEDTHROUGH else self._initialise()
            )
            if not ok:
                # pythonfmu cannot return fmi2Error here without an exception (fmi2Fatal): the
                # problem is logged now and every fmi2DoStep is discarded until it is fixed
                self._report(Fmi2Status.error)
        except Exception as exc:  # no exception may leave an FMI call
            self._error = f"{type(exc).__name__}: {exc}"
            self._report(Fmi2Status.error)

    def do_step(self, current_time: float, step_size: float) -> bool:
        try:
            if not (math.isfinite(current_time) and math.isfinite(step_size) and step_size >= 0):
                self._error = (
                    f"fmi2DoStep(currentCommunicationPoint = {current_time!r}, "
                    f"communicationStepSize = {step_size!r}): the point must be finite and the "
                    "step size finite and ≥ 0"
                )
                self._report(Fmi2Status.discard)
                return False
            if not (self._configured or self._ensure_configured()):
                self._report(Fmi2Status.discard)
                return False
            if self.FEEDTHROUGH:
                ok = self._refresh() if self._dirty else True
            else:
                bad = self._bad_input()
                if bad:
                    self._error = bad
                    ok = False
                else:  # a zero step advances nothing (the outputs stay those at the point)
                    ok = step_size == 0.0 or self.advance(current_time, step_size)
            if not ok:
                self._report(Fmi2Status.discard)
            return ok
        except Exception as exc:
            self._error = f"{type(exc).__name__}: {exc}"
            self._report(Fmi2Status.discard)
            return False

    # ------------------------------------------------------------------ state
    def _get_fmu_state(self):
        values = {v.name: _CAST[v.type](getattr(self, v.name)) for v in self.VARIABLES}
        return {
            "values": values,
            "hidden": self.hidden_state(),
            "dirty": self._dirty,
            "error": self._error,
        }

    def _set_fmu_state(self, state):
        try:
            params_changed = any(
                state["values"][v.name] != getattr(self, v.name) for v in self._params
            )
            for name, value in state["values"].items():
                setattr(self, name, value)
            if params_changed or not self._configured:
                self._configured = False
                self._ensure_configured()
            self.restore_hidden_state(state["hidden"])
            self._dirty = state["dirty"]
            self._error = state["error"]
        except Exception as exc:
            self._error = f"state not restored: {type(exc).__name__}: {exc}"
            self._report(Fmi2Status.error)

    # ------------------------------------------------------------------ version
    def _check_build(self):
        info_file = Path(self.resources or ".") / BUILD_INFO
        if not info_file.is_file():
            return  # not running from a built FMU (e.g. imported in a test)
        info = json.loads(info_file.read_text())
        here = _runtime_hash()
        if info["package_hash"] != here:
            import servofmu

            raise RuntimeError(
                f"{type(self).__name__}: this FMU was built with servofmu {info['version']} "
                f"({info['package_hash'][:12]}), but the servofmu already imported in this "
                f"process ({servofmu.__version__}, {here[:12]}, from "
                f"{Path(servofmu.__file__).parent}) differs. Python imports a package once per "
                "process: load FMUs built from one servofmu version together, or rebuild them "
                "with `servofmu build`."
            )

    # ------------------------------------------------------------------ XML
    def to_xml(self, model_options=None):
        """The complete modelDescription (see module docstring)."""
        root = super().to_xml(model_options or {})
        variables = root.find("ModelVariables")
        used_units = []
        for sv in variables.findall("ScalarVariable"):
            v = self._by_name[sv.get("name")]
            elem = sv[0]
            if v.unit:
                elem.set("unit", v.unit)
                used_units.append(v.unit)
            if v.display_unit:
                elem.set("displayUnit", v.display_unit)
            if v.min is not None:
                elem.set("min", f"{v.min:.16g}")
            if v.max is not None:
                elem.set("max", f"{v.max:.16g}")
        units = Element("UnitDefinitions")
        for name in dict.fromkeys(used_units):
            exps, displays = UNITS[name]
            unit = SubElement(units, "Unit", name=name)
            SubElement(unit, "BaseUnit", {k: str(e) for k, e in exps.items()})
            for d, factor, offset in displays:
                attrs = {"name": d, "factor": f"{factor:.16g}"}
                if offset:
                    attrs["offset"] = f"{offset:.16g}"
                SubElement(unit, "DisplayUnit", attrs)
        children = list(root)
        root.insert(children.index(root.find("CoSimulation")) + 1, units)
        root.remove(root.find("ModelStructure"))
        index = {v.name: i + 1 for i, v in enumerate(self.VARIABLES)}
        structure = SubElement(root, "ModelStructure")
        outputs = SubElement(structure, "Outputs")
        initial = SubElement(structure, "InitialUnknowns")
        for v in self._outputs:
            deps = " ".join(str(index[d]) for d in v.depends)
            kinds = " ".join("dependent" for _ in v.depends)
            SubElement(
                outputs,
                "Unknown",
                index=str(index[v.name]),
                dependencies=deps,
                dependenciesKind=kinds,
            )
            SubElement(initial, "Unknown", index=str(index[v.name]))
        return root

    # ------------------------------------------------------------------ hooks
    def configure(self):
        """Turn the parameters into model objects; raise ValueError on a bad combination."""

    def compute(self):
        """Algebraic FMUs: set the outputs from the current inputs."""
        raise NotImplementedError

    def advance(self, current_time: float, step_size: float) -> bool:
        """Stepped FMUs: advance the hidden state over the step and set the outputs."""
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
        """JSON-serialisable state not held in FMI variables."""
        return {}

    def restore_hidden_state(self, state: dict):
        """Inverse of :meth:`hidden_state`."""


_CAST = {"Real": float, "Integer": int, "Boolean": bool, "String": str}


def _ranges(variables) -> list[tuple[str, float, float]]:
    """(name, min, max) of the Real variables, open ends as ±inf."""
    return [
        (v.name, -math.inf if v.min is None else v.min, math.inf if v.max is None else v.max)
        for v in variables
        if v.type == "Real"
    ]


def _zero(kind: str):
    return {"Real": 0.0, "Integer": 0, "Boolean": False, "String": ""}[kind]

"""The runtime of the servofmu FMU slaves (pythonfmu ``Fmi2Slave``): every FMI entry point
pythonfmu calls, over the variables each FMU declares (:mod:`.declarations`).

From the one table of variables, :class:`ServoSlave`

- answers every FMI entry point pythonfmu calls itself (fmi2Get*/fmi2Set* for any value
  reference, the FMI 2.0 state machine of :mod:`.calls`, fmi2DoStep with any arguments, FMU
  states handed back by a host): it checks the arguments and the state and answers a host's
  mistake with fmi2Error and a message naming what was wrong. Under servofmu's export library
  that is an :class:`~.calls.FMIError` turned into the status; under pythonfmu's own binary,
  which makes any exception fatal and can then crash the host, nothing is ever raised: the
  message is logged, the call returns a harmless value, the instance enters the error state
  and its next fmi2DoStep is discarded with the message (:mod:`.binary`). One decorator,
  :func:`fmi_call`, keeps every exception of servofmu's own code from reaching pythonfmu;
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
  imported in the process is not the one the FMU was built with (:mod:`.package_hash`);
- writes the complete modelDescription at build time (:mod:`.model_description`).

Time: a stepped FMU's first fmi2DoStep starts at fmi2SetupExperiment's startTime (or, without
it, defines the start), each later one where the last ended (or at the time of a restored
state); another currentCommunicationPoint is refused (FMI 2.0: the point and the FMU's state
must agree), never caught up silently. An algebraic FMU's outputs depend on its inputs alone:
it takes a step at any point.

Two kinds of FMU: *algebraic* ones (``FEEDTHROUGH = True``: BearingFriction,
ActuatorStiffness) compute their outputs from the current inputs, lazily, whenever an output
is read after an input changed; *stepped* ones (DCMotor, ServoController, ThermalNetwork)
advance a hidden state in ``do_step`` and their outputs do not depend directly on the inputs.
"""

from __future__ import annotations

import copy
import functools
import math

from pythonfmu import Boolean, Fmi2Causality, Fmi2Slave, Fmi2Variability, Integer, Real
from pythonfmu.enums import Fmi2Initial, Fmi2Status

from .. import __version__
from . import accessors, model_description, shared_values
from .binary import export_of, reports_statuses, shares_values
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
    sealed,
    sequence_problem,
    state_problem,
    unsealed,
)
from .declarations import FMI_TYPE, Var, check_variables, variables_of
from .interpreter_exit import register_interpreter_finaliser
from .package_hash import build_start, runtime_hash
from .shared_values import ALL, INPUTS, OUTPUTS, PARAMETERS, SharedValues

_TYPES = {"Real": Real, "Integer": Integer, "Boolean": Boolean, "Enumeration": Integer}
_FMI_TYPES = ("Real", "Integer", "Boolean", "String")
_DEFAULT = {"Real": 0.0, "Integer": 0, "Boolean": False, "String": ""}
_CAST = {"Real": float, "Integer": int, "Boolean": bool, "Enumeration": int}
_DESCRIBING = "describing"  # the build writes the modelDescription (reads the start values)


def fmi_call(call: str, result=None, failure: str = "_internal", changes: int = ALL):
    """Decorator of an FMI entry point of :class:`ServoSlave`: no exception of servofmu's own
    code leaves it, and the values shared with the export library (:mod:`.shared_values`)
    are read before it and written back after it.

    The method receives ``call`` (the FMI function's name, for its messages) after ``self``.
    An :class:`~.calls.FMIError` (a refusal under servofmu's export) passes through; any other
    exception goes to the method named ``failure`` as ``(call, exc, result)``: by default
    :meth:`ServoSlave._internal`, a refusal naming the exception, which under pythonfmu's
    binary returns the harmless ``result``.

    Parameters
    ----------
    call : the FMI function, e.g. "fmi2DoStep"
    result : what a refused call returns under pythonfmu's binary: a value, or a function of
        the call's arguments
    failure : the name of the slave's method that answers an exception
    changes : the groups of shared values the call may change (:data:`.shared_values.INPUTS`,
        ``OUTPUTS``, ``PARAMETERS``, or'ed; its state and dirty flag are always written back)

    Returns
    -------
    callable
        The decorator.

    Examples
    --------
    >>> class Demo:
    ...     _shared = None  # no export library shares values with it
    ...     def _internal(self, call, exc, result):
    ...         return f"{call}: {type(exc).__name__}", result
    ...     @fmi_call("fmi2GetReal", result=lambda vrs: [0.0] * len(vrs))
    ...     def get_real(self, call, vrs):
    ...         return [1.0 / v for v in vrs]
    >>> Demo().get_real([2, 0])
    ('fmi2GetReal: ZeroDivisionError', [0.0, 0.0])
    """

    def decorate(method):
        @functools.wraps(method)
        def entry(self, *args):
            shared = self._shared
            try:
                if shared is not None:
                    shared.pull(self)
                return method(self, call, *args)
            except FMIError:
                raise
            except (Exception, KeyboardInterrupt) as exc:
                try:
                    refused = result(*args) if callable(result) else result
                except Exception:  # arguments a host should not have passed
                    refused = None
                return getattr(self, failure)(call, exc, refused)
            finally:
                if shared is not None:
                    shared.push(self, changes)

        return entry

    return decorate


def _defaults(kind: str):
    """The harmless answer of a refused fmi2Get<kind>: one default per value reference."""
    return lambda vrs: [_DEFAULT[kind]] * len(vrs)


class ServoSlave(Fmi2Slave):
    """Base class of the servofmu FMUs; see the module docstring."""

    VARIABLES: tuple[Var, ...] = ()
    PHYSICS: tuple[str, ...] = ()  # modules whose equations the documentation shows
    FEEDTHROUGH = False
    DEFAULT_EXPERIMENT = (0.0, 1.0, 1.0e-3)  # start, stop, step [s]
    #: the model's step in compiled code on the values shared with servofmu's export: a
    #: function of :class:`~servofmu.physics.shared_step.SharedStep`'s arguments that builds
    #: the model's subclass (see :meth:`_bind_shared_step`); None: every step in Python
    shared_step = None
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

        cls = type(self)
        start_values = build_start(self.resources, cls.__name__)
        # after every import that loads a C++ extension (servofmu.fmus loads all of them)
        register_interpreter_finaliser(self.resources, cls.__name__)
        export = export_of(self.resources, cls.__name__)
        self._export = export or "no FMU binary (imported as a library)"
        self._reports = reports_statuses(export)
        if export is not None:  # (an instance made by the build says nothing)
            cls._class_reports = self._reports and cls._class_reports is not False
        start, stop, step = self.DEFAULT_EXPERIMENT
        self.default_experiment = DefaultExperiment(
            start_time=start, stop_time=stop, step_size=step
        )
        self.variables = variables_of(cls, start_values)
        self._by_name = {v.name: v for v in self.variables}
        self._types = {v.name: v.type for v in self.variables}
        self._inputs = [v for v in self.variables if v.causality == "input"]
        self._params = [v for v in self.variables if v.causality == "parameter"]
        self._outputs = [v for v in self.variables if v.causality == "output"]
        self._input_checks = _ranges(self._inputs)
        self._inputs_in_range = accessors.range_checker(tuple(self._input_checks))
        self._param_checks = _ranges(self._params)
        self._output_checks = [c for c in _ranges(self._outputs) if c[1:] != (-math.inf, math.inf)]
        self._choices = [v for v in self._params + self._inputs if v.type == "Enumeration"]
        self._copy = accessors.copier(tuple((v.name, v.field) for v in self._outputs if v.field))
        reals = [v for v in self._outputs if v.type == "Real"]
        self._outputs_finite = accessors.finite_checker(tuple((v.name, v.allow_inf) for v in reals))
        self._real_outputs = accessors.getter(tuple(v.name for v in reals))
        self._inf_ok = frozenset(v.name for v in reals if v.allow_inf)
        #: the Real outputs as last checked finite in this FMI call, while they stay so
        self._checked: tuple | None = None
        for v in self.variables:
            setattr(self, v.name, v.start if v.causality != "output" else _zero(v.type))
        self._dirty = True  # inputs changed since the outputs were computed
        self._inputs_valid = False  # every input known to lie within its range
        self._configured = False  # parameters turned into model objects
        self._error = ""  # why the FMU cannot compute, or why it refused a call
        self._phase = INSTANTIATED  # the FMI 2.0 state (calls.py)
        #: an algebraic FMU with a state that moves over a step (BearingFriction's
        #: pre-rolling): called with the step size after its outputs are current, it advances
        #: that state and sets the outputs at the step's end; None (the rule): nothing to carry
        self._carry = None
        self._start_time: float | None = None  # fmi2SetupExperiment's startTime
        self._time: float | None = None  # where the next fmi2DoStep must start
        for v in self.variables:
            self._register(v)
        self._tables()
        self._shared = None  # the values shared with servofmu's export (shared_values.py)
        if shares_values(export) and shared_values.wanted():
            writable = {phase: self._writable[phase]["Real"] for phase in PHASES}
            self._shared = SharedValues(self.variables, self.FEEDTHROUGH, writable)
            self._shared.push(self, ALL)
        # the block the export library views (None: every call through Python)
        self._shared_buffer = None if self._shared is None else self._shared.buffer
        if self._shared is not None and self.shared_step is not None:
            # the library calls the instance's "do_step": the compiled step, which hands
            # every step it does not take to the class's own
            self._shared.attach_step(
                self.shared_step, not self.FEEDTHROUGH, self.do_step, self._shared_step_failed
            )
            self.do_step = self._shared.step.step
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
            kind = FMI_TYPE[v.type]
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
            if FMI_TYPE[v.type] != kind:
                return (
                    f"valueReference {vr} is {v.name!r}, a{'n' if v.type[0] in 'IE' else ''} "
                    f"{FMI_TYPE[v.type]}, not a{'n' if kind[0] == 'I' else ''} {kind}"
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
    @fmi_call("fmi2GetReal", result=_defaults("Real"), changes=OUTPUTS)
    def get_real(self, call, vrs):
        return self._get(call, "Real", vrs)

    @fmi_call("fmi2GetInteger", result=_defaults("Integer"), changes=OUTPUTS)
    def get_integer(self, call, vrs):
        return self._get(call, "Integer", vrs)

    @fmi_call("fmi2GetBoolean", result=_defaults("Boolean"), changes=OUTPUTS)
    def get_boolean(self, call, vrs):
        return self._get(call, "Boolean", vrs)

    @fmi_call("fmi2GetString", result=_defaults("String"), changes=OUTPUTS)
    def get_string(self, call, vrs):
        return self._get(call, "String", vrs)

    @fmi_call("fmi2SetReal", changes=INPUTS | PARAMETERS)
    def set_real(self, call, vrs, values):
        self._set(call, "Real", vrs, values)

    @fmi_call("fmi2SetInteger", changes=0)
    def set_integer(self, call, vrs, values):
        self._set(call, "Integer", vrs, values)

    @fmi_call("fmi2SetBoolean", changes=0)
    def set_boolean(self, call, vrs, values):
        self._set(call, "Boolean", vrs, values)

    @fmi_call("fmi2SetString", changes=0)
    def set_string(self, call, vrs, values):
        self._set(call, "String", vrs, values)

    def _get(self, call: str, kind: str, vrs):
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

    def _set(self, call: str, kind: str, vrs, values):
        table = self._writable[self._phase][kind]
        try:
            names = [table[vr] for vr in vrs]
        except (KeyError, TypeError):
            return self._refuse(call, self._reference_problem(kind, vrs, True))
        for name, value in zip(names, values, strict=True):
            setattr(self, name, value)
        self._dirty = True
        self._inputs_valid = False
        if not self._param_vrs.isdisjoint(vrs):
            self._configured = False

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
        compiled test, the loop only to name a bad input; none while the inputs are known to
        be in range: checked since the last fmi2Set* through Python, or written by the export
        library, which takes only finite values within the ranges)."""
        if self._inputs_valid:
            return ""
        if self._inputs_in_range(self):
            self._inputs_valid = True
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
        return self._nonfinite_output(": the step is not taken")

    def _nonfinite_output(self, then: str = "") -> str:
        """The first Real output that is not finite (+inf where allowed), named (and
        ``then``), else "". The values checked are kept for the shared block
        (:meth:`.shared_values.SharedValues.push`: the outputs as they are now)."""
        values = self._checked = self._real_outputs(self)
        total = sum(values)
        if total - total == 0.0 or self._outputs_finite(self):  # the first: all finite
            return ""
        for v in self._outputs:
            x = getattr(self, v.name)
            if v.type == "Real" and not (math.isfinite(x) or (x == math.inf and v.allow_inf)):
                return f"{v.name} = {x!r} is not finite{then}"
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
        return accessors.copier(
            tuple((v.name, v.field) for v in self._outputs if v.field in fields)
        )

    @staticmethod
    def output_setter(names):
        """A function ``set(slave, values)`` doing ``slave.<names[i]> = values[i]`` (compiled
        once: the outputs of one model call in one statement)."""
        return accessors.setter(tuple(names))

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

    def _refresh(self, check: bool = True) -> bool:
        """Recompute the outputs of an algebraic FMU from the current inputs (``check``: and
        check them; a caller that changes them further checks them itself)."""
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
        bad = self._bad_output() if check else ""
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
    @fmi_call("fmi2SetupExperiment", changes=0)
    def setup_experiment(self, call, start_time, stop_time=None, tolerance=None):
        self._announce()
        problem = self._sequence(call) or _experiment_problem(start_time, stop_time, tolerance)
        if problem:
            return self._refuse(call, problem)
        self._start_time = self._time = float(start_time)

    @fmi_call("fmi2EnterInitializationMode", changes=0)
    def enter_initialization_mode(self, call):
        self._announce()
        problem = self._sequence(call)
        if problem:
            return self._refuse(call, problem)
        self._phase = INITIALIZATION
        self._dirty = True

    @fmi_call("fmi2ExitInitializationMode", changes=OUTPUTS)
    def exit_initialization_mode(self, call):
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

    @fmi_call("fmi2DoStep", result=False, failure="_step_failed", changes=OUTPUTS)
    def do_step(self, call, current_time: float, step_size: float) -> bool:
        problem = "" if self._phase == STEP_COMPLETE else self._sequence(call)
        problem = problem or self._step_problem(current_time, step_size)
        if not problem and not (self._configured or self._ensure_configured()):
            problem = self._error
        problem = problem or self._bad_input()
        if problem:  # a host's mistake: the step is not carried out at all
            return self._refuse(call, problem, False)
        if self._time is None:  # no fmi2SetupExperiment: the first step starts the run
            self._start_time = self._time = current_time
        if self.FEEDTHROUGH and self._carry is None:
            ok = self._refresh() if self._dirty else True
        elif self.FEEDTHROUGH:  # a state carried over the step (see _carry): the outputs
            # checked once, after it (and the checked ones shared)
            ok = (self._refresh(check=False) if self._dirty else True) and self._carry(step_size)
            if ok:
                self._error = self._bad_output()
                ok = not self._error
                self._dirty = not ok  # a bad output is recomputed (and reported) when read
        else:  # a model failure mid-step (or a step beyond its bound): discarded
            ok = self.advance(current_time, step_size)
            if ok:
                self._error = self._bad_output()
                ok = not self._error
        if not ok:
            return self._discard()
        self._time = current_time + step_size
        return True

    @fmi_call("fmi2DoStep", result=False, failure="_step_failed", changes=OUTPUTS)
    def _shared_step_failed(self, call, exc: BaseException) -> bool:
        """The answer to an exception raised by the compiled step on the shared values
        (:attr:`shared_step`): that of an exception in the middle of :meth:`do_step`."""
        raise exc

    def _step_failed(self, call: str, exc: BaseException, result=False) -> bool:
        """An exception in the middle of a step is the model's failure: discarded."""
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

    @fmi_call("fmi2Terminate", changes=0)
    def terminate(self, call):
        problem = self._sequence(call)
        if problem:
            return self._refuse(call, problem)
        self._phase = TERMINATED

    # ------------------------------------------------------------------ state
    @fmi_call("fmi2GetFMUstate", failure="_state_failed", changes=0)
    def _get_fmu_state(self, call):
        return {
            "fmu": type(self).__name__,
            "package": runtime_hash(),
            "phase": self._phase,
            "time": self._time,
            "start_time": self._start_time,
            "values": {v.name: _CAST[v.type](getattr(self, v.name)) for v in self.variables},
            "hidden": self.hidden_state(),
            "dirty": self._dirty,
            "error": self._error,
        }

    def _state_failed(self, call: str, exc: BaseException, result=None) -> dict:
        """A state that cannot be saved: under pythonfmu's binary a record that any later
        fmi2SetFMUstate refuses with the reason."""
        return self._internal(call, exc, {"refused": str(exc)})

    @fmi_call("fmi2SetFMUstate")
    def _set_fmu_state(self, call, state):
        if isinstance(state, dict) and set(state) == {"refused"}:
            problem = str(state["refused"])
        else:
            problem = state_problem(state, type(self).__name__, runtime_hash(), self._types)
        if not problem and set(state["hidden"]) != set(self.hidden_state()):
            problem = f"its hidden state has the fields {sorted(state['hidden'])}"
        if problem:
            return self._refuse(call, f"the state is refused ({problem}); nothing restored")
        saved = self._get_fmu_state()
        try:
            self._restore(state)
        except (Exception, KeyboardInterrupt) as exc:
            problem = f"{type(exc).__name__}: {exc}"
        else:
            problem = self._restored_problem()
        if problem:
            self._restore(saved)
            return self._refuse(call, f"the state is refused ({problem}); nothing restored")

    def _restored_problem(self) -> str:
        """Why the values just restored are not ones this FMU can hold ("" when they are).

        Inputs and parameters are held to what fmi2Set* leads to: any value is taken, and the
        next fmi2ExitInitializationMode or fmi2DoStep (an algebraic FMU: the next output read
        too) refuses one outside its range, naming it. An algebraic FMU's outputs are
        recomputed from its inputs before they are read again. A stepped FMU's outputs and
        hidden state are its state: from a phase that steps or has stepped, the outputs must
        be finite (as after every step), within their declared ranges, and pass the FMU's
        :meth:`state_problem`; the hidden state is checked by :meth:`restore_hidden_state`."""
        if self.FEEDTHROUGH or self._phase not in (STEP_COMPLETE, TERMINATED):
            return ""
        problem = self._nonfinite_output()
        if problem:
            return problem
        for name, lo, hi in self._output_checks:
            x = getattr(self, name)
            if not lo <= x <= hi:
                return f"{name} = {x!r} is outside its declared range [{lo:g}, {hi:g}]"
        return self.state_problem()

    def _restore(self, state: dict):
        """Every declared field of a checked state (never anything else: the variables by
        name, the hidden state through the FMU's own :meth:`restore_hidden_state`)."""
        values = state["values"]
        params_changed = any(values[v.name] != getattr(self, v.name) for v in self._params)
        for v in self.variables:
            setattr(self, v.name, _CAST[v.type](values[v.name]))
        self._inputs_valid = False
        self._checked = None
        if params_changed or not self._configured:
            self._configured = False
            self._ensure_configured()
        self.restore_hidden_state(copy.deepcopy(state["hidden"]))
        # an algebraic FMU's outputs follow from its inputs: computed again before any read
        self._dirty = True if self.FEEDTHROUGH else state["dirty"]
        self._error = state["error"]
        self._phase, self._time, self._start_time = (
            state["phase"],
            state["time"],
            state["start_time"],
        )

    @classmethod
    def _fmu_state_to_bytes(cls, state) -> bytes:
        """The serialized state: its JSON with a checksum of its bytes (:func:`.calls.sealed`)."""
        try:
            return sealed(state)
        except (Exception, KeyboardInterrupt) as exc:
            message = f"fmi2SerializeFMUstate: the state cannot be serialised ({exc})"
            if cls._class_reports:
                raise FMIError(message) from None
            return sealed({"refused": message})

    @classmethod
    def _fmu_state_from_bytes(cls, data) -> dict:
        """A state from bytes of :meth:`_fmu_state_to_bytes`: refused unless their checksum
        matches and they hold a state of this FMU and build."""
        try:
            state, problem = unsealed(bytes(data))
            if not problem:
                types = {v.name: v.type for v in cls.VARIABLES}
                problem = state_problem(state, cls.__name__, runtime_hash(), types)
        except (Exception, KeyboardInterrupt) as exc:
            problem = f"{type(exc).__name__}: {exc}"
        if not problem:
            return state
        message = f"fmi2DeSerializeFMUstate: not a state of {cls.__name__} ({problem})"
        if cls._class_reports:
            raise FMIError(message)
        return {"refused": message}

    # ------------------------------------------------------------------ XML
    def to_xml(self, model_options=None):
        """The complete modelDescription (:func:`.model_description.complete`)."""
        phase, self._phase = self._phase, _DESCRIBING  # pythonfmu reads the start values
        try:
            root = super().to_xml(model_options or {})
        finally:
            self._phase = phase
        return model_description.complete(root, self.variables)

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
        field it cannot take (of the wrong type, not finite, outside what a step gives), and
        the base class then restores what was there."""

    def state_problem(self) -> str:
        """Stepped FMUs: why the restored outputs and hidden state are not a state this FMU
        can hold between steps, beyond finite outputs ("" when they are): what its steps
        guarantee (ranges, relations between the values)."""
        return ""

    def _bind_shared_step(self, step) -> bool:
        """With :attr:`shared_step`: give ``step`` the model objects, parameters and hidden
        state its next steps start from, and say whether it may take them (False: the next
        step in Python, e.g. while a warning is due). Called after every FMI call that entered
        Python, in step complete, configured, with a known time."""
        return False

    def _read_shared_step(self, step):
        """With :attr:`shared_step`: take back the hidden state its steps changed (the
        inputs, outputs and time are read by the runtime)."""


def _experiment_problem(start, stop, tolerance) -> str:
    """Why fmi2SetupExperiment's arguments are unusable ("" when they are not)."""
    if not math.isfinite(start):
        return f"startTime = {start!r} is not finite"
    if stop is not None and not (math.isfinite(stop) and stop >= start):
        return f"stopTime = {stop!r} is not a finite time at or after startTime = {start!r}"
    if tolerance is not None and not (math.isfinite(tolerance) and tolerance >= 0.0):
        return f"tolerance = {tolerance!r} is not a finite number ≥ 0"
    return ""


def _ranges(variables) -> list[tuple[str, float, float]]:
    """(name, min, max) of the Real and Integer variables, open ends as ±inf."""
    return [
        (v.name, -math.inf if v.min is None else v.min, math.inf if v.max is None else v.max)
        for v in variables
        if v.type in ("Real", "Integer")
    ]


def _zero(kind: str):
    return {"Real": 0.0, "Integer": 0, "Boolean": False, "Enumeration": 1}[kind]

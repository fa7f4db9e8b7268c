"""The co-simulation master: fixed communication step, Gauss-Seidel (default) or Jacobi.

Per communication step t → t + h:

- **Gauss-Seidel**: the components are stepped one after another in an order derived from the
  connection graph (:func:`order_components`); each one's inputs are set from the newest
  outputs of its sources (already at t + h for sources stepped earlier in the sweep, at t for
  the others) and from the external signals at t, then it steps and its outputs are read.
- **Jacobi**: every input is set from the outputs at t, then every component steps (libcosim's
  fixed-step algorithm does the same, so the two agree to the last digits).

A LinearTransformation y = factor·x + offset is applied on each connection. Unconnected inputs
keep their start value (or SSV/variant value) unless a signal drives them. Initialization:
instantiate, apply the parameter bindings, variant and overrides in initialization mode,
propagate the connections, exit initialization mode, propagate again and record t0.

A component that answers fmi2Discard or worse ends the run: :class:`~.errors.HarnessError`
names the component, the time and the FMU's last log messages, and carries the results up
to the failure (written to disk too when the run has an output folder). Ctrl-C stops the run
at the next step boundary (:mod:`.interrupt`) the same way, with :class:`~.errors.Interrupted`.

Every argument (times, overrides against their variables' type and range, signals, names to
record) is checked before any FMU is instantiated: :class:`~.errors.ArgumentError`.
"""

from __future__ import annotations

import ctypes
import math
import time as _time
from collections import deque
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from servofmu.files import write_text, written
from servofmu.physics._checks import suggest

from .errors import ArgumentError, HarnessError, Interrupted, ParameterError
from .interrupt import interruptible
from .progress import progress_bar
from .system import System, describe_items, load_system, out_of_range
from .units import TIME, Scale, header, label

STATUS = ("OK", "Warning", "Discard", "Error", "Fatal", "Pending")
ALGORITHMS = ("gauss-seidel", "jacobi")


@dataclass
class RunResult:
    """Results of one run: ``data`` is a structured array with ``time`` and one field per
    recorded ``component.variable``; ``failed``/``message`` tell how it ended."""

    system: str
    data: np.ndarray
    failed: bool = False
    message: str = ""
    csv: Path | None = None
    wall_time: float = 0.0
    units: dict[str, Scale] = field(default_factory=dict)  # field name → unit and display
    #: the distinct warnings the components logged, "component (FMU): message", in order
    warnings: list[str] = field(default_factory=list)

    @property
    def names(self) -> tuple[str, ...]:
        return self.data.dtype.names

    def __getitem__(self, name: str) -> np.ndarray:
        return self.data[name]

    def scale(self, name: str) -> Scale:
        """Unit and display unit of field ``name`` (``time``: s)."""
        return TIME if name == "time" else self.units.get(name, Scale(None))

    def to_csv(self, path) -> Path:
        """Write the results as CSV in the FMUs' SI units, headers ``name [unit]``
        (:func:`~.units.read_results` reads it back by name), whole or not at all
        (:func:`servofmu.files.written`). A run that ended early (failed or interrupted) ends
        with the line ``# incomplete: …`` saying where and why: the rows after it were not
        computed."""
        path = Path(path)
        footer = ""
        if self.failed:
            end = f"t = {self.data['time'][-1]:.12g} s" if len(self.data) else "no row"
            why = " ".join(self.message.split())
            footer = f"incomplete: the run ended at {end}, before its stop time: {why}"
        with written(path) as part:
            np.savetxt(
                part,
                self.data.view((float, len(self.names)))
                if len(self.data)
                else np.empty((0, len(self.names))),
                delimiter=",",
                header=",".join(header(n, self.scale(n)) for n in self.names),
                comments="",
                fmt="%.12g",
            )
            if footer:
                with part.open("a") as fh:
                    fh.write(f"# {footer}\n")
        return path

    def plot(self, path, names, title: str = "") -> Path:
        """Plot the fields ``names`` against time to a PNG (one axis each), in the display
        units the FMUs declare (N·mm, °C, …), each axis labelled with its unit."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        path = Path(path)
        fig, axes = plt.subplots(
            len(names), 1, sharex=True, figsize=(7, 1.8 + 1.6 * len(names)), squeeze=False
        )
        for ax, name in zip(axes[:, 0], names, strict=True):
            scale = self.scale(name)
            ax.plot(self.data["time"], scale.shown(self.data[name]))
            ax.set_ylabel(label(name, scale).replace(" [", "\n["), fontsize=8)
            if scale.boolean:
                ax.set_ylim(-0.15, 1.15)
                ax.set_yticks([0, 1], ["false", "true"])
            ax.grid(True, alpha=0.3)
        axes[-1, 0].set_xlabel("time [s]")
        fig.suptitle(title or self.system, fontsize=10)
        fig.tight_layout()
        with written(path) as part:
            fig.savefig(part, dpi=100)
        plt.close(fig)
        return path


def order_components(system: System) -> list[str]:
    """Gauss-Seidel order from the connection graph: a component comes after the sources of
    its inputs; a cycle is broken at a component whose outputs do not depend directly on its
    inputs (a state-carrying FMU), in declaration order."""
    names = list(system.components)
    sources = {n: set() for n in names}
    for c in system.connections:
        if c.start[0] != c.end[0]:
            sources[c.end[0]].add(c.start[0])
    order, placed = [], set()
    while len(order) < len(names):
        ready = [n for n in names if n not in placed and sources[n] <= placed]
        if not ready:
            left = [n for n in names if n not in placed]
            stateful = [n for n in left if not system.components[n].feedthrough]
            ready = [(stateful or left)[0]]
        order.append(ready[0])
        placed.add(ready[0])
    return order


class _Journal(deque):
    """The components' log messages of a run, (component, status, message), the last
    :data:`JOURNAL_LENGTH` in the order logged; and every distinct warning (the first
    :data:`WARNINGS_KEPT`), which a successful run reports too."""

    def __init__(self):
        super().__init__(maxlen=JOURNAL_LENGTH)
        self.warnings: dict[tuple[str, str], None] = {}

    def note(self, name: str, status: int, text: str) -> None:
        self.append((name, status, text))
        if status == 1 and len(self.warnings) < WARNINGS_KEPT:
            self.warnings.setdefault((name, text), None)


JOURNAL_LENGTH = 200
WARNINGS_KEPT = 20


class _Unit:
    """One instantiated component with preallocated ctypes buffers for the step loop; its
    log messages go to ``log`` and, tagged with its name, to the run's ``journal``."""

    def __init__(self, comp, unzip_dir: Path, journal: _Journal | None = None):
        from fmpy.fmi1 import calloc, free
        from fmpy.fmi2 import (
            FMU2Slave,
            fmi2CallbackAllocateMemoryTYPE,
            fmi2CallbackFreeMemoryTYPE,
            fmi2CallbackFunctions,
            fmi2CallbackLoggerTYPE,
        )

        self.name = comp.name
        self.comp = comp
        self.log: deque[str] = deque(maxlen=50)
        self.journal = _Journal() if journal is None else journal

        def logger(env, instance, status, category, message):
            text = message.decode(errors="replace") if isinstance(message, bytes) else str(message)
            self.log.append(f"[{STATUS[status] if 0 <= status < 6 else status}] {text}")
            self.journal.note(self.name, status, text)

        # each unit's own logger, called with the message as the FMU passes it: fmpy's
        # printf-formatting proxy (fmpy.logging.addLoggerProxy) keeps one logger for the whole
        # process, the last one added, and sent every FMU's messages to the last component
        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        self._keep = (cb, logger)
        self.slave = FMU2Slave(
            guid=comp.guid,
            unzipDirectory=str(unzip_dir),
            modelIdentifier=comp.model_identifier,
            instanceName=comp.name,
        )
        self.instantiated = False
        try:
            self.slave.instantiate(callbacks=cb, loggingOn=True)  # messages go to self.log
        except Exception as exc:
            raise HarnessError(
                f"component {self.name!r} ({comp.fmu.name}) could not be instantiated: "
                f"{' | '.join(self.log) or exc}"
            ) from None
        self.instantiated = True
        f = self.slave._functions
        self.c = self.slave.component
        self.set_real, self.get_real = f["fmi2SetReal"], f["fmi2GetReal"]
        self.get_boolean, self.do_step = f["fmi2GetBoolean"], f["fmi2DoStep"]

    def bind(self, values, flags, wiring: _UnitWiring) -> None:
        """Point the unit's FMI calls at its slices of the run's buffers (``values``: c_double,
        ``flags``: c_int; :class:`_UnitWiring`): its inputs are set from, its outputs read
        into, those slices, so a step moves no value through a Python list."""
        linked, first = wiring.n_linked, wiring.first_output
        self.n_in, self.in_vr = _block(ctypes.c_uint, wiring.input_vrs)
        self.n_out, self.out_vr = _block(ctypes.c_uint, wiring.output_vrs[:linked])
        self.n_kept, self.kept_vr = _block(ctypes.c_uint, wiring.output_vrs[linked:])
        self.n_bool, self.bool_vr = _block(ctypes.c_uint, wiring.bool_vrs)
        self.in_val = _view(values, ctypes.c_double, wiring.first_input, self.n_in)
        self.out_val = _view(values, ctypes.c_double, first, self.n_out)
        self.kept_val = _view(values, ctypes.c_double, first + linked, self.n_kept)
        self.bool_val = _view(flags, ctypes.c_int, wiring.first_bool, self.n_bool)
        self.recorded_only = bool(self.n_kept or self.n_bool)
        self.values = values
        self.copies = tuple((d, s) for d, s, f, o in wiring.links if f == 1.0 and o == 0.0)
        self.scaled = tuple(link for link in wiring.links if link[2:] != (1.0, 0.0))
        self.signals = tuple(wiring.signals)

    def set_inputs(self, t: float, signals: bool = True) -> int:
        """Inputs from the connections (y = factor·x + offset) and, unless ``signals`` is
        false (they keep the values last set), the signals at ``t``, set with one
        fmi2SetReal; the FMI status."""
        values = self.values
        for dst, src in self.copies:
            values[dst] = values[src]
        for dst, src, factor, offset in self.scaled:
            values[dst] = factor * values[src] + offset
        if signals:
            for dst, signal in self.signals:
                values[dst] = signal(t)
        if self.n_in:
            return self.set_real(self.c, self.in_vr, self.n_in, self.in_val)
        return 0

    def refresh(self) -> int:
        """An algebraic unit's outputs from its connected inputs now, without a step; the
        FMI status."""
        if (status := self.set_inputs(0.0, signals=False)) > 1:
            return status
        return self.get_all()

    def get_outputs(self) -> int:
        """The outputs other units read, into the run's buffer (one fmi2GetReal); the FMI
        status."""
        if self.n_out:
            return self.get_real(self.c, self.out_vr, self.n_out, self.out_val)
        return 0

    def get_recorded(self) -> int:
        """The outputs only recorded, into the run's buffers (one fmi2GetReal, one
        fmi2GetBoolean): they hold what the unit's last step computed until its next step or
        inputs, so they are read when a row is kept; the first status worse than a warning,
        else the last."""
        status = 0
        if self.n_kept:
            status = self.get_real(self.c, self.kept_vr, self.n_kept, self.kept_val)
            if status > 1:
                return status
        if self.n_bool:
            status = self.get_boolean(self.c, self.bool_vr, self.n_bool, self.bool_val)
        return status

    def get_all(self) -> int:
        """Every output read (:meth:`get_outputs`, :meth:`get_recorded`); the FMI status."""
        if (status := self.get_outputs()) > 1:
            return status
        return self.get_recorded()

    def close(self):
        if self.instantiated:
            try:
                self.slave.terminate()
            except Exception:
                pass
            self.slave.freeInstance()
            self.instantiated = False


def _readers(system: System, order: list[str], sources: list[str]) -> list[str]:
    """The algebraic (direct-feedthrough) components that read ``sources``' outputs, directly
    or through other such components, in stepping order."""
    reached, out = set(sources), []
    for name in order:
        comp = system.components[name]
        if comp.feedthrough and name not in reached:
            if any(c.end[0] == name and c.start[0] in reached for c in system.connections):
                reached.add(name)
                out.append(name)
    return out


def _set_value(slave, var, value):
    if var.type == "Real":
        slave.setReal([var.value_reference], [float(value)])
    elif var.type in ("Integer", "Enumeration"):
        slave.setInteger([var.value_reference], [int(value)])
    elif var.type == "Boolean":
        slave.setBoolean([var.value_reference], [bool(value)])
    else:
        slave.setString([var.value_reference], [str(value)])


def run(
    system,
    *,
    parameters=None,
    signals=None,
    start: float | None = None,
    stop: float | None = None,
    step: float | None = None,
    algorithm: str = "gauss-seidel",
    record=None,
    out_dir=None,
    progress=True,
    fmu_dir=None,
    output_interval: float | None = None,
    rates: dict[str, int] | None = None,
) -> RunResult:
    """Co-simulate ``system`` (a :class:`System`, or a path for :func:`load_system`).

    Parameters
    ----------
    parameters : variant name (``variants/NAME.ssv``), or dict ``{"comp.var": value}`` of
        overrides, or a list mixing both (applied in order, after the component bindings)
    signals : ``{"comp.input": callable(t)}`` external signals for unconnected inputs
    start, stop, step : times [s]; default from the DefaultExperiment and the OSP annotation
    algorithm : "gauss-seidel" or "jacobi"
    record : ``component.variable`` names to record (default: every Real and Boolean output
        and every signal target). A signal-driven input is recorded as the value the FMU
        holds: the signal at the start of the step that ended at the row's time, the value
        its outputs at that time were computed from.
    out_dir : folder for ``results.csv`` (also written on failure, with the partial results)
    progress : show a progress bar when the run takes longer than two seconds; or an open bar
        (anything with ``update(n)``, e.g. a scenario's bar over its runs) to advance by the
        steps done
    output_interval : keep a row every this many seconds (a multiple of the step; default
        every step), and always the last one
    rates : ``{"component": N}``: that component steps once every N communication steps,
        over N·h (the last one over what is left), its inputs set at the start of that step;
        its outputs reach the others when that step ends and hold until the next one ends
        (they lag by up to N·h), and the algebraic components that read them are updated
        then (inputs set, outputs read, no step), so that a row's values belong together: a
        slow subsystem such as a thermal network beside a millisecond motor loop; the
        others step every h

    Raises
    ------
    ArgumentError : an unusable argument (:func:`check_run`), before any FMU is instantiated
    HarnessError : a component failed; ``result`` holds the rows up to the failure
    Interrupted : Ctrl-C (SIGINT to the main thread): stopped at the next step boundary, FMUs
        freed, ``result`` holding the rows so far
    """
    own = not isinstance(system, System)
    sys_ = load_system(system, fmu_dir=fmu_dir) if own else system
    try:
        plan = check_run(
            sys_,
            parameters=parameters,
            signals=signals,
            start=start,
            stop=stop,
            step=step,
            algorithm=algorithm,
            record=record,
            output_interval=output_interval,
            rates=rates,
        )
        settings = _Settings(
            algorithm, plan.record, out_dir, progress, output_interval, rates or {}
        )
        with interruptible() as stop_request:
            return _run(sys_, plan, signals or {}, settings, stop_request)
    finally:
        if own:
            sys_.close()


@dataclass(frozen=True)
class RunPlan:
    """The checked arguments of a run (:func:`check_run`): times [s], the number of steps,
    the rows kept (every ``every``-th step and the last), the typed overrides and the names
    recorded."""

    start: float
    stop: float
    step: float
    n_steps: int
    every: int
    overrides: dict
    record: list


def check_run(
    system: System,
    *,
    parameters=None,
    signals=None,
    start=None,
    stop=None,
    step=None,
    algorithm: str = "gauss-seidel",
    record=None,
    output_interval=None,
    rates=None,
) -> RunPlan:
    """Every argument of :func:`run` checked against ``system`` without instantiating
    anything: :class:`~.errors.ArgumentError` naming the argument, its value and what is
    valid (times finite, a positive step no longer than the run and dividing it; overrides
    naming a parameter or an unconnected input, of its type and within its range; signals on
    unconnected inputs; recorded names that are outputs or signal-driven inputs)."""
    if algorithm not in ALGORITHMS:
        raise ArgumentError(f"algorithm = {algorithm!r} is not one of {list(ALGORITHMS)}")
    t0 = _seconds("start", start, system.start_time)
    t1 = _seconds("stop", stop, system.stop_time)
    if step is None and system.step_size is None:
        raise ArgumentError(
            "step: the system declares no communication step (osp:FixedStepAlgorithm "
            "baseStepSize); give one"
        )
    h = _seconds("step", step, system.step_size)
    if not h > 0:
        raise ArgumentError(f"step = {h!r} s must be > 0")
    if not t1 > t0:
        raise ArgumentError(f"stop = {t1!r} s must be after start = {t0!r} s")
    span = t1 - t0
    if h > span * (1.0 + 1e-9):
        raise ArgumentError(
            f"step = {h!r} s is longer than the run (start = {t0!r} s to stop = {t1!r} s)"
        )
    n_steps = round(span / h)
    if abs(n_steps * h - span) > 1e-6 * h:
        raise ArgumentError(
            f"stop − start = {span!r} s is not a whole number of steps of {h!r} s (the run "
            f"would end at t = {t0 + n_steps * h:.9g} s): change stop or step"
        )
    every = 1
    if output_interval is not None:
        oi = _seconds("output_interval", output_interval, None)
        every = round(oi / h)
        if not oi > 0 or every < 1 or abs(every * h - oi) > 1e-6 * h:
            raise ArgumentError(
                f"output_interval = {oi!r} s must be a positive multiple of the step {h!r} s"
            )
    for name, n in (rates or {}).items():
        if name not in system.components:
            raise ArgumentError(f"rates: {name!r} is not a component of {list(system.components)}")
        if type(n) is not int or n < 1:
            raise ArgumentError(f"rates[{name!r}] = {n!r} must be a whole number of steps ≥ 1")
    connected = {c.end: c.start for c in system.connections}
    overrides = _overrides(system, parameters, connected)
    signals = signals or {}
    for target, sig in signals.items():
        comp, var = _variable(system, target, "signal")
        if var.causality != "input" or (comp.name, var.name) in connected:
            raise ArgumentError(f"signal {target!r}: only unconnected inputs can be driven")
        if not callable(sig):
            raise ArgumentError(f"signal {target!r} is not a function of time")
    if record is None:
        record = [
            f"{c.name}.{v.name}"
            for c in system.components.values()
            for v in c.variables.values()
            if v.causality == "output" and v.type in ("Real", "Boolean")
        ]
        record += [t for t in signals if t not in record]
    record = list(dict.fromkeys(record))  # each name once, in order
    for target in record:
        _, var = _variable(system, target, "record")
        recordable = var.causality == "output" and var.type in ("Real", "Boolean")
        if not recordable and target not in signals:
            raise ArgumentError(
                f"record {target!r}: it is {_causality(var)}; only Real and Boolean outputs "
                "and signal-driven inputs can be recorded"
            )
    n_rows = n_steps // every + 1 + (1 if n_steps % every else 0)
    _check_table_size(n_rows, 1 + len(record))
    return RunPlan(t0, t1, h, n_steps, every, overrides, record)


def _seconds(name: str, value, default) -> float:
    """A time argument [s] as a finite float (``default`` when None)."""
    raw = default if value is None else value
    try:
        x = float(raw)
    except (TypeError, ValueError):
        raise ArgumentError(f"{name} = {raw!r} is not a number of seconds") from None
    if not math.isfinite(x):
        raise ArgumentError(f"{name} = {x!r} s must be finite")
    return x


def _check_table_size(n_rows: int, n_columns: int) -> None:
    """Refuse a results table larger than half of the machine's memory (it is allocated
    before the first step)."""
    import os

    try:
        memory = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (AttributeError, OSError, ValueError):  # pragma: no cover - not POSIX
        return
    size = 8 * n_rows * n_columns
    if size > memory / 2:
        raise ArgumentError(
            f"the results would take {n_rows} rows × {n_columns} columns = {size / 2**30:.3g} "
            f"GiB, more than half of this machine's {memory / 2**30:.3g} GiB: record fewer "
            "variables, keep fewer rows (output_interval) or run shorter (stop)"
        )


def _variable(system: System, target: str, what: str):
    """(component, variable) of ``target``, or ArgumentError starting with ``what``."""
    try:
        return system.variable(target)
    except HarnessError as exc:
        raise ArgumentError(f"{what} {exc}") from None


def _causality(var) -> str:
    return {"output": "an output", "input": "an input", "parameter": "a parameter"}.get(
        var.causality, f"a {var.causality} variable"
    )


def _overrides(system: System, parameters, connected=None) -> dict[str, object]:
    if parameters is None:
        return {}
    connected = {} if connected is None else connected
    items = parameters if isinstance(parameters, list) else [parameters]
    out: dict[str, object] = {}
    for item in items:
        if isinstance(item, str):
            if item not in system.variants:
                raise ParameterError(
                    f"parameter set {item!r} is not one of the variants {sorted(system.variants)}"
                    f"{suggest(item, system.variants)} (or give an .ssv file)"
                )
            out.update({k: v for k, (_, v) in system.variants[item].items()})
        else:
            out.update(item)
    for target, value in out.items():
        try:
            comp, var = system.variable(target)
        except HarnessError as exc:
            raise ParameterError(str(exc)) from None
        if var.causality not in ("parameter", "input") or var.variability == "constant":
            raise ParameterError(
                f"parameter {target}: it is {_causality(var)}; only parameters and unconnected "
                "inputs can be set"
            )
        source = connected.get((comp.name, var.name))
        if source is not None:
            raise ParameterError(
                f"parameter {target}: the input is driven by the connection from "
                f"{'.'.join(source)}, which would overwrite the value"
            )
        out[target] = _typed(target, var, value)
        if problem := out_of_range(var, out[target]):
            raise ParameterError(f"parameter {target} {problem}")
    return out


def _typed(target: str, var, value):
    """``value`` (text from a command line, or a Python value) as the type of ``var``; a
    choice takes an item name or its value."""
    if var.items is not None:
        return _item(target, var, value)
    try:
        if var.type == "Real":
            x = float(value)
            if x != x or x in (float("inf"), float("-inf")):
                raise ValueError
            return x
        if var.type in ("Integer", "Enumeration"):
            return int(value)
        if var.type == "Boolean":
            if isinstance(value, str):
                if value.strip().lower() not in ("true", "false", "1", "0"):
                    raise ValueError
                return value.strip().lower() in ("true", "1")
            return bool(value)
        return str(value)
    except (TypeError, ValueError):
        raise ParameterError(
            f"parameter {target} = {value!r} is not a finite {var.type} value"
        ) from None


def _item(target: str, var, value) -> int:
    """The value of choice ``var`` named by ``value``: an item name, or its value (an int, or
    text or a float that reads as one); a number that is no item value may still be an item
    name that reads as a number (a bearing "71803" from a command line)."""
    if isinstance(value, str):
        text = value.strip()
        if text in var.items:
            return var.items[text]
        value = int(text) if text.lstrip("+-").isdigit() else text
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    if type(value) is int:
        if value in var.items.values():
            return value
        if str(value) in var.items:
            return var.items[str(value)]
    raise ParameterError(
        f"parameter {target} = {value!r} is not one of {describe_items(var.items)}"
    )


@dataclass(frozen=True)
class _Settings:
    """How a run steps and what it keeps (see :func:`run`)."""

    algorithm: str
    record: list | None
    out_dir: object
    progress: object  # a bool, or an open bar (see run)
    output_interval: float | None
    rates: dict


def _run(system, plan: RunPlan, signals, settings: _Settings, stop_request):
    order = order_components(system)
    units: dict[str, _Unit] = {}
    journal = _Journal()
    t0_wall = _time.perf_counter()
    try:
        for comp in system.components.values():  # FMUs unpacked once per loaded system
            _stop_if_requested(stop_request, f"before instantiating {comp.name!r}")
            units[comp.name] = _Unit(comp, system.unpacked(comp.fmu), journal)
        wiring = _wire(system, units, order, plan.record, signals)
        cosim = _Cosimulation(system, units, order, wiring, plan, settings, t0_wall)
        cosim.initialize()
        return cosim.step_all(stop_request)
    finally:
        for u in units.values():
            u.close()


def _stop_if_requested(stop_request, where: str) -> None:
    """Ctrl-C or SIGTERM before the first row: stop now, nothing computed to keep."""
    if stop_request is not None and stop_request.requested:
        raise Interrupted(
            f"interrupted {where}, {1e3 * stop_request.delay():.3g} ms after the signal",
            signum=stop_request.signum,
        )


@dataclass
class _UnitWiring:
    """One unit's part of the run's buffers: the value references it sets and reads (its Real
    outputs that other units read first, ``n_linked`` of them, then those only recorded),
    where its blocks start (its inputs and Real outputs in the values buffer, its Boolean
    outputs in the flags buffer), its links ``(input position, output position, factor,
    offset)`` and its signals ``(input position, callable)``."""

    input_vrs: list = field(default_factory=list)
    output_vrs: list = field(default_factory=list)
    bool_vrs: list = field(default_factory=list)
    n_linked: int = 0
    first_input: int = 0
    first_output: int = 0
    first_bool: int = 0
    links: list = field(default_factory=list)
    signals: list = field(default_factory=list)


@dataclass
class _Wiring:
    """Where every value of a run lives: one buffer of Reals holding every unit's outputs read
    after a step (connected or recorded) and then every unit's inputs (from a connection, with
    its factor and offset, or from a signal), each unit's in one block; one buffer of Booleans
    (as FMI's int) for the Boolean outputs read; and where each recorded column comes from.

    Attributes
    ----------
    values, flags : the ctypes buffers (at least one element each)
    units : component → its :class:`_UnitWiring`
    columns : per recorded column, ("r", position in values) or ("b", position in flags)
    """

    values: object
    flags: object
    units: dict
    columns: list


def _block(ctype, items):
    """(count, ctypes array of ``items``)."""
    return len(items), (ctype * len(items))(*items)


def _view(buffer, ctype, first: int, n: int):
    """The ``n`` elements of ``buffer`` from ``first`` on, as a ctypes array sharing its
    memory."""
    return (ctype * n).from_buffer(buffer, first * ctypes.sizeof(ctype))


def _wire(system, units, order, record, signals) -> _Wiring:
    """The :class:`_Wiring` of a run; each unit bound to its blocks of the buffers."""
    linked = {c.start for c in system.connections}
    recorded = {tuple(r.split(".", 1)) for r in record}
    wiring = {name: _UnitWiring() for name in order}
    out_index: dict[tuple[str, str], int] = {}
    bool_index: dict[tuple[str, str], int] = {}
    for name in order:
        w = wiring[name]
        w.first_output, w.first_bool = len(out_index), len(bool_index)
        outputs = [v for v in system.components[name].variables.values() if v.causality == "output"]
        for v in outputs:  # what other units read first: the block read after every step
            if v.type == "Real" and (name, v.name) in linked:
                out_index[(name, v.name)] = len(out_index)
                w.output_vrs.append(v.value_reference)
        w.n_linked = len(w.output_vrs)
        for v in outputs:  # then what is only recorded: read when a row is kept
            if (name, v.name) in recorded and (name, v.name) not in linked:
                if v.type == "Real":
                    out_index[(name, v.name)] = len(out_index)
                    w.output_vrs.append(v.value_reference)
                elif v.type == "Boolean":
                    bool_index[(name, v.name)] = len(bool_index)
                    w.bool_vrs.append(v.value_reference)
    n_values, signal_index = len(out_index), {}
    for name in order:
        comp, w = system.components[name], wiring[name]
        w.first_input = n_values
        for c in system.connections:
            if c.end[0] == name:
                var = comp.variables[c.end[1]]
                if var.type != "Real":
                    raise HarnessError(
                        f"connection to {name}.{var.name}: only Real connections are supported"
                    )
                w.links.append((n_values, out_index[c.start], c.factor, c.offset))
                w.input_vrs.append(var.value_reference)
                n_values += 1
        for target, sig in signals.items():
            cname, _, vname = target.partition(".")
            if cname == name:
                signal_index[target] = n_values
                w.signals.append((n_values, sig))
                w.input_vrs.append(comp.variables[vname].value_reference)
                n_values += 1
    values = (ctypes.c_double * max(1, n_values))()
    flags = (ctypes.c_int * max(1, len(bool_index)))()
    for name in order:
        units[name].bind(values, flags, wiring[name])
    columns = []
    for target in record:
        comp, var = system.variable(target)
        key = (comp.name, var.name)
        if key in out_index:
            columns.append(("r", out_index[key]))
        elif key in bool_index:
            columns.append(("b", bool_index[key]))
        elif target in signals:  # the value the input holds (set at the step's start)
            columns.append(("r", signal_index[target]))
        else:  # pragma: no cover - check_run refused it
            raise ArgumentError(
                f"record {target!r}: only outputs and signal-driven inputs can be recorded"
            )
    return _Wiring(values, flags, wiring, columns)


class _Schedule:
    """Which units step at communication step ``k`` and over what, and which slow units
    publish when it ends (``rates``): built once per step of the rates' common period, not
    per step.

    :meth:`at` gives ``(due, ended, readers)``: ``due`` the units stepping, in order, each as
    ``(unit, step size, read after the step)`` (a slow unit steps over N·h, the last one over
    what is left, and is read when its step ends); ``ended`` the slow units whose step ends
    at t + h; ``readers`` the algebraic units that read them (updated then)."""

    #: Longest common period of the rates kept as a table; a longer one keeps its patterns.
    TABLE = 10_000

    def __init__(self, system, units, order, rates: dict, n_steps: int, h: float):
        self.system, self.units, self.order = system, units, order
        self.rates = [(name, rates.get(name, 1)) for name in order]
        self.slow = [(name, r) for name, r in self.rates if r > 1]
        self.n_steps, self.h = n_steps, h
        self.fast = (tuple((units[n], h, True) for n, _ in self.rates), (), ())
        # from this step on a slow unit's step may be cut short by the end of the run
        self.tail = n_steps - max((r for _, r in self.slow), default=1)
        self.period = math.lcm(*(r for _, r in self.slow)) if self.slow else 1
        self._table = [None] * self.period if self.period <= self.TABLE else None
        self._patterns: dict[tuple, tuple] = {}

    def at(self, k: int):
        if not self.slow:
            return self.fast
        if k < self.tail and self._table is not None:
            entry = self._table[k % self.period]
            if entry is None:
                entry = self._table[k % self.period] = self._pattern(k)
            return entry
        return self._pattern(k)

    def _pattern(self, k: int):
        key = tuple(k % r == 0 for _, r in self.slow) + tuple(
            (k + 1) % r == 0 or k + 1 == self.n_steps for _, r in self.slow
        )
        if k >= self.tail:
            return self._build(k, key)
        pattern = self._patterns.get(key)
        if pattern is None:
            pattern = self._patterns[key] = self._build(k, key)
        return pattern

    def _build(self, k: int, key: tuple):
        starts = {n for (n, _), due in zip(self.slow, key, strict=False) if due}
        ends = [n for (n, _), end in zip(self.slow, key[len(self.slow) :], strict=True) if end]
        due = tuple(
            (self.units[n], min(r, self.n_steps - k) * self.h, r == 1)
            for n, r in self.rates
            if r == 1 or n in starts
        )
        readers = _readers(self.system, self.order, ends) if ends else []
        return (
            due,
            tuple(self.units[n] for n in ends),
            tuple(self.units[n] for n in readers),
        )


class _Cosimulation:
    """One run's stepping over its :class:`_Wiring`: initialization, one step per algorithm
    (:meth:`step_jacobi`, :meth:`step_gauss_seidel`), the slow components of ``rates``, the
    rows kept, and the end of a failed or interrupted run with the rows so far."""

    def __init__(self, system, units, order, wiring: _Wiring, plan: RunPlan, settings, t0_wall):
        self.system, self.units, self.order, self.w = system, units, order, wiring
        self.plan, self.settings, self.t0_wall = plan, settings, t0_wall
        n, every = plan.n_steps, plan.every
        self.rows = np.empty((n // every + 1 + (1 if n % every else 0), 1 + len(wiring.columns)))
        self.stored = -1  # index of the last row written
        self.values = np.frombuffer(wiring.values, dtype=float)
        self.flags = np.frombuffer(wiring.flags, dtype=np.intc)
        reals = [(j, p) for j, (kind, p) in enumerate(wiring.columns, start=1) if kind == "r"]
        bools = [(j, p) for j, (kind, p) in enumerate(wiring.columns, start=1) if kind == "b"]
        self.real_columns = np.array([j for j, _ in reals], dtype=np.intp)
        self.real_sources = np.array([p for _, p in reals], dtype=np.intp)
        self.bool_columns = np.array([j for j, _ in bools], dtype=np.intp)
        self.bool_sources = np.array([p for _, p in bools], dtype=np.intp)

    # ------------------------------------------------------------------ results and ends
    def result(self, failed=False, message="") -> RunResult:
        """The rows kept so far as a :class:`RunResult` (and ``results.csv``)."""
        record = self.plan.record
        dtype = [("time", float)] + [(t, float) for t in record]
        k = self.stored
        data = (
            np.rec.fromarrays(self.rows[: k + 1].T, dtype=dtype).view(np.ndarray)
            if k >= 0
            else np.empty(0, dtype=dtype)
        )
        res = RunResult(
            self.system.name,
            data,
            failed,
            message,
            wall_time=_time.perf_counter() - self.t0_wall,
            units={t: self.system.scale(t) for t in record},
            warnings=self.warnings(),
        )
        if self.settings.out_dir is not None:
            res.csv = res.to_csv(Path(self.settings.out_dir) / "results.csv")
        return res

    def warnings(self) -> list[str]:
        """The distinct warnings the components logged, "component (FMU): message"."""
        if not self.units:
            return []
        journal = next(iter(self.units.values())).journal
        return [
            f"{n} ({self.units[n].comp.model_identifier}): {text}" for n, text in journal.warnings
        ]

    def stop(self, message, error=HarnessError, **kw):
        """End the run: the rows so far (on disk too), the FMUs' log in failure.log."""
        res = self.result(True, message)
        details = "\n".join(
            [message, ""] + [f"[{n}] {line}" for n, unit in self.units.items() for line in unit.log]
        )
        where = ""
        if self.settings.out_dir is not None:
            log_file = write_text(Path(self.settings.out_dir) / "failure.log", details + "\n")
            where = f"; the FMUs' log in {log_file}"
        if res.csv and len(res.data):
            where += f"; results up to t = {res.data['time'][-1]:.6g} s in {res.csv}"
        raise error(message + where, result=res, details=details, **kw)

    def fail(self, name, what, status, t):
        u = self.units[name]
        label = STATUS[status] if 0 <= status < 6 else str(status)
        self.stop(
            f"component {name!r} ({u.comp.model_identifier}) returned fmi2{label} from {what} at "
            f"t = {t:.6g} s: {self.explain(name)}"
        )

    def explain(self, name) -> str:
        """The log messages that explain a failure of component ``name``, each naming the
        component that logged it and quoting it: its own warnings and errors, else the last
        ones of any component (a bad value often comes from a component upstream)."""
        journal = next(iter(self.units.values())).journal if self.units else ()
        problems = [(n, s, text) for n, s, text in journal if s >= 1]
        chosen = [p for p in problems if p[0] == name][-3:] or problems[-3:]
        if not chosen:
            return "no component logged a warning or an error"
        return " | ".join(
            f"{n} ({self.units[n].comp.model_identifier}) logged {STATUS[s] if 0 <= s < 6 else s}:"
            f' "{text}"'
            for n, s, text in chosen
        )

    # ------------------------------------------------------------------ values
    def store(self, t):
        self.stored += 1
        row = self.rows[self.stored]
        row[0] = t
        row[self.real_columns] = self.values[self.real_sources]
        if len(self.bool_columns):
            row[self.bool_columns] = self.flags[self.bool_sources]

    def exchange(self, t):
        """Inputs set and outputs read for every unit at ``t``, in order; fail on an error."""
        for name in self.order:
            u = self.units[name]
            if (status := u.set_inputs(t)) > 1:
                self.fail(name, "fmi2SetReal", status, t)
            if (status := u.get_all()) > 1:
                self.fail(name, "fmi2GetReal", status, t)

    # ------------------------------------------------------------------ initialization
    def initialize(self):
        """Parameters and overrides in Initialization Mode, connections propagated (chains
        of direct feedthrough settled), then the first row."""
        from fmpy.fmi1 import FMICallException

        start = self.plan.start
        for name in self.order:
            u = self.units[name]
            try:
                u.slave.setupExperiment(startTime=start)
                u.slave.enterInitializationMode()
                for pname, (_, value) in u.comp.parameters.items():
                    _set_value(u.slave, u.comp.variables[pname], value)
                for target, value in self.plan.overrides.items():
                    cname, _, vname = target.partition(".")
                    if cname == name:
                        _set_value(u.slave, u.comp.variables[vname], value)
            except FMICallException as exc:
                self.fail(name, "initialization", getattr(exc, "status", 3), start)
        for _ in range(2):  # settle chains of direct feedthrough
            self.exchange(start)
        for name in self.order:
            u = self.units[name]
            try:
                u.slave.exitInitializationMode()
            except FMICallException as exc:
                self.fail(name, "fmi2ExitInitializationMode", getattr(exc, "status", 3), start)
            if u.log and any(m.startswith("[Error]") for m in u.log):
                self.fail(name, "fmi2ExitInitializationMode", 3, start)
        self.exchange(start)
        self.store(start)

    # ------------------------------------------------------------------ one step
    def step_jacobi(self, t, due):
        """Jacobi: every due unit's inputs from the outputs at ``t``, then all step, then all
        are read."""
        for u, _, _ in due:
            if (status := u.set_inputs(t)) > 1:
                self.fail(u.name, "fmi2SetReal", status, t)
        for u, span, _ in due:
            if (status := u.do_step(u.c, t, span, 1)) > 1:
                self.fail(u.name, "fmi2DoStep", status, t)
        for u, _, now in due:
            if now and (status := u.get_outputs()) > 1:
                self.fail(u.name, "fmi2GetReal", status, t)

    def step_gauss_seidel(self, t, due):
        """Gauss-Seidel: each due unit in order sets its inputs from the newest outputs,
        steps and is read."""
        for u, span, now in due:
            if (status := u.set_inputs(t)) > 1:
                self.fail(u.name, "fmi2SetReal", status, t)
            if (status := u.do_step(u.c, t, span, 1)) > 1:
                self.fail(u.name, "fmi2DoStep", status, t)
            if now and (status := u.get_outputs()) > 1:
                self.fail(u.name, "fmi2GetReal", status, t)

    def publish_slow(self, ended, readers, t):
        """After a step from ``t``: the slow units ``ended`` (``rates``), whose step ends at
        t + h, publish their outputs, and the algebraic units that read them are updated
        (connected inputs set, outputs read, no step)."""
        for u in ended:
            if (status := u.get_all()) > 1:
                self.fail(u.name, "fmi2GetReal", status, t)
        for u in readers:
            if (status := u.refresh()) > 1:
                self.fail(u.name, "fmi2SetReal/fmi2GetReal", status, t + self.plan.step)

    def step_all(self, stop_request) -> RunResult:
        """Every communication step of the run; the :class:`RunResult`."""
        start, h, n_steps, every = (
            self.plan.start,
            self.plan.step,
            self.plan.n_steps,
            self.plan.every,
        )
        step = self.step_jacobi if self.settings.algorithm == "jacobi" else self.step_gauss_seidel
        schedule = _Schedule(self.system, self.units, self.order, self.settings.rates, n_steps, h)
        bar, own_bar = _bar(self.settings.progress, n_steps, self.system.name)
        done = 0  # steps not yet shown on the bar
        varying, (due, ended, readers) = bool(schedule.slow), schedule.fast
        # outputs only recorded are read when a row is kept (a slow unit's when it publishes)
        kept = tuple(
            self.units[n] for n, r in schedule.rates if r == 1 and self.units[n].recorded_only
        )
        try:
            for k in range(n_steps):
                t = start + k * h
                if stop_request is not None and stop_request.requested:  # Ctrl-C: stop here
                    self.stop(
                        f"interrupted at t = {t:.6g} s, "
                        f"{1e3 * stop_request.delay():.3g} ms after the signal",
                        Interrupted,
                        time=t,
                        signum=stop_request.signum,
                    )
                if varying:
                    due, ended, readers = schedule.at(k)
                step(t, due)
                if ended:
                    self.publish_slow(ended, readers, t)
                if (k + 1) % every == 0 or k + 1 == n_steps:
                    for u in kept:
                        if (status := u.get_recorded()) > 1:
                            self.fail(u.name, "fmi2GetReal", status, t)
                    self.store(start + (k + 1) * h)
                done += 1
                if done == BAR_STEPS:
                    bar.update(done)
                    done = 0
        finally:
            bar.update(done)
            if own_bar:
                bar.close()
        return self.result()


#: Steps between two updates of a run's progress bar (an update costs about a step).
BAR_STEPS = 64


def _bar(progress, n_steps: int, name: str):
    """(bar, whether the run owns it): the caller's open bar (``progress`` with an
    ``update`` method, advanced by the steps), else a bar of its own that shows after two
    seconds, disabled when ``progress`` is false."""
    if hasattr(progress, "update"):
        return progress, False
    return progress_bar(n_steps, desc=name, unit="step", enabled=bool(progress)), True

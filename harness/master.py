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
to the failure (written to disk too when the run has an output folder).
"""

from __future__ import annotations

import ctypes
import time as _time
from collections import deque
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .errors import HarnessError, ParameterError
from .system import System, describe_items, load_system

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

    @property
    def names(self) -> tuple[str, ...]:
        return self.data.dtype.names

    def __getitem__(self, name: str) -> np.ndarray:
        return self.data[name]

    def to_csv(self, path) -> Path:
        """Write the results as CSV (header: field names)."""
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        np.savetxt(
            path,
            self.data.view((float, len(self.names)))
            if len(self.data)
            else np.empty((0, len(self.names))),
            delimiter=",",
            header=",".join(self.names),
            comments="",
            fmt="%.12g",
        )
        return path

    def plot(self, path, names, title: str = "") -> Path:
        """Plot the fields ``names`` against time to a PNG (one axis each)."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        fig, axes = plt.subplots(
            len(names), 1, sharex=True, figsize=(7, 1.8 + 1.6 * len(names)), squeeze=False
        )
        for ax, name in zip(axes[:, 0], names, strict=True):
            ax.plot(self.data["time"], self.data[name])
            ax.set_ylabel(name, fontsize=8)
            ax.grid(True, alpha=0.3)
        axes[-1, 0].set_xlabel("time [s]")
        fig.suptitle(title or self.system, fontsize=10)
        fig.tight_layout()
        fig.savefig(path, dpi=100)
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


class _Unit:
    """One instantiated component with preallocated ctypes buffers for the step loop."""

    def __init__(self, comp, unzip_dir: Path):
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

        def logger(env, instance, status, category, message):
            text = message.decode(errors="replace") if isinstance(message, bytes) else str(message)
            self.log.append(f"[{STATUS[status] if 0 <= status < 6 else status}] {text}")

        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        try:
            from fmpy.logging import addLoggerProxy

            addLoggerProxy(ctypes.byref(cb))
        except Exception:  # pragma: no cover - the proxy only formats printf-style messages
            pass
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

    def buffers(self, inputs: list[int], reals: list[int], booleans: list[int]):
        vr = ctypes.c_uint
        self.n_in, self.in_vr = len(inputs), (vr * len(inputs))(*inputs)
        self.in_val = (ctypes.c_double * len(inputs))()
        self.n_out, self.out_vr = len(reals), (vr * len(reals))(*reals)
        self.out_val = (ctypes.c_double * len(reals))()
        self.n_bool, self.bool_vr = len(booleans), (vr * len(booleans))(*booleans)
        self.bool_val = (ctypes.c_int * len(booleans))()

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
    progress: bool = True,
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
    progress : show a progress bar when the run takes longer than two seconds
    output_interval : keep a row every this many seconds (a multiple of the step; default
        every step), and always the last one
    rates : ``{"component": N}``: that component steps once every N communication steps,
        over N·h (the last one over what is left), its inputs set at the start of that step;
        its outputs reach the others when that step ends and hold until the next one ends
        (they lag by up to N·h), and the algebraic components that read them are updated
        then (inputs set, outputs read, no step), so that a row's values belong together: a
        slow subsystem such as a thermal network beside a millisecond motor loop; the
        others step every h
    """
    own = not isinstance(system, System)
    sys_ = load_system(system, fmu_dir=fmu_dir) if own else system
    try:
        settings = _Settings(algorithm, record, out_dir, progress, output_interval, rates or {})
        return _run(sys_, parameters, signals or {}, start, stop, step, settings)
    finally:
        if own:
            sys_.close()


def _overrides(system: System, parameters) -> dict[str, object]:
    if parameters is None:
        return {}
    items = parameters if isinstance(parameters, list) else [parameters]
    out: dict[str, object] = {}
    for item in items:
        if isinstance(item, str):
            if item not in system.variants:
                raise ParameterError(
                    f"parameter set {item!r} is not one of the variants {sorted(system.variants)}"
                )
            out.update({k: v for k, (_, v) in system.variants[item].items()})
        else:
            out.update(item)
    for target, value in out.items():
        try:
            _, var = system.variable(target)
        except HarnessError as exc:
            raise ParameterError(str(exc)) from None
        out[target] = _typed(target, var, value)
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
    progress: bool
    output_interval: float | None
    rates: dict


def _run(system, parameters, signals, start, stop, step, settings: _Settings):
    algorithm = settings.algorithm
    if algorithm not in ALGORITHMS:
        raise HarnessError(f"algorithm = {algorithm!r} is not one of {list(ALGORITHMS)}")
    start = system.start_time if start is None else float(start)
    stop = system.stop_time if stop is None else float(stop)
    h = system.step_size if step is None else float(step)
    if h is None or not h > 0:
        raise HarnessError(f"step = {h!r}: give a positive communication step (none in the SSD)")
    if not stop > start:
        raise HarnessError(f"stop = {stop!r} s must be after start = {start!r} s")
    if settings.output_interval is not None and not settings.output_interval > 0:
        raise HarnessError(f"output_interval = {settings.output_interval!r} s must be > 0")
    for name, n in settings.rates.items():
        if name not in system.components:
            raise HarnessError(f"rates: {name!r} is not a component of {list(system.components)}")
        if type(n) is not int or n < 1:
            raise HarnessError(f"rates[{name!r}] = {n!r} must be a whole number of steps ≥ 1")
    overrides = _overrides(system, parameters)
    connected = {c.end for c in system.connections}
    for target, sig in signals.items():
        comp, var = system.variable(target)
        if var.causality != "input" or (comp.name, var.name) in connected:
            raise HarnessError(f"signal {target!r}: only unconnected inputs can be driven")
        if not callable(sig):
            raise HarnessError(f"signal {target!r} is not a function of time")
    order = order_components(system)
    n_steps = round((stop - start) / h)
    units: dict[str, _Unit] = {}
    t0_wall = _time.perf_counter()
    try:
        for comp in system.components.values():  # FMUs unpacked once per loaded system
            units[comp.name] = _Unit(comp, system.unpacked(comp.fmu))
        return _simulate(
            system, units, order, overrides, signals, start, h, n_steps, settings, t0_wall
        )
    finally:
        for u in units.values():
            u.close()


def _simulate(system, units, order, overrides, signals, start, h, n_steps, settings, t0_wall):
    algorithm, record, out_dir = settings.algorithm, settings.record, settings.out_dir
    progress, output_interval = settings.progress, settings.output_interval
    # --- what to record -----------------------------------------------------------------
    if record is None:
        record = [
            f"{c.name}.{v.name}"
            for c in system.components.values()
            for v in c.variables.values()
            if v.causality == "output" and v.type in ("Real", "Boolean")
        ]
        record += [t for t in signals if t not in record]
    for target in record:
        system.variable(target)
    # --- outputs read after each step (connected or recorded), as one flat list "latest" --
    needed = {c.start for c in system.connections} | {tuple(r.split(".", 1)) for r in record}
    out_index: dict[tuple[str, str], int] = {}
    bool_index: dict[tuple[str, str], int] = {}
    reals, bools = {}, {}
    for name in order:
        outputs = [
            v
            for v in system.components[name].variables.values()
            if v.causality == "output" and (name, v.name) in needed
        ]
        reals[name] = [v for v in outputs if v.type == "Real"]
        bools[name] = [v for v in outputs if v.type == "Boolean"]
        for v in reals[name]:
            out_index[(name, v.name)] = len(out_index)
        for v in bools[name]:
            bool_index[(name, v.name)] = len(bool_index)
    latest = [0.0] * len(out_index)
    latest_bool = [0.0] * len(bool_index)
    # --- inputs of each unit: (slot, source index, factor, offset) or a signal ---------
    plan, signal_slot = {}, {}
    for name in order:
        comp = system.components[name]
        links, sigs, vrs = [], [], []
        for c in system.connections:
            if c.end[0] == name:
                var = comp.variables[c.end[1]]
                if var.type != "Real":
                    raise HarnessError(
                        f"connection to {name}.{var.name}: only Real connections are supported"
                    )
                links.append((len(vrs), out_index[c.start], c.factor, c.offset))
                vrs.append(var.value_reference)
        for target, sig in signals.items():
            cname, _, vname = target.partition(".")
            if cname == name:
                signal_slot[target] = len(vrs)
                sigs.append((len(vrs), sig))
                vrs.append(comp.variables[vname].value_reference)
        units[name].buffers(
            vrs, [v.value_reference for v in reals[name]], [v.value_reference for v in bools[name]]
        )
        plan[name] = (links, sigs, out_index[(name, reals[name][0].name)] if reals[name] else 0)
    getters = []
    for target in record:
        comp, var = system.variable(target)
        key = (comp.name, var.name)
        if key in out_index:
            getters.append(("r", out_index[key]))
        elif key in bool_index:
            getters.append(("b", bool_index[key]))
        elif target in signals:  # the value the input holds (set at the step's start)
            getters.append(("s", (units[comp.name].in_val, signal_slot[target])))
        else:
            raise HarnessError(
                f"record {target!r}: only outputs and signal-driven inputs can be recorded"
            )
    every = max(1, round(output_interval / h)) if output_interval else 1
    n_rows = n_steps // every + 1 + (1 if n_steps % every else 0)
    rows = np.empty((n_rows, 1 + len(getters)))
    stored = [-1]  # index of the last row written
    dtype = [("time", float)] + [(t, float) for t in record]

    def result(k, failed=False, message=""):
        data = (
            np.rec.fromarrays(rows[: k + 1].T, dtype=dtype).view(np.ndarray)
            if k >= 0
            else np.empty(0, dtype=dtype)
        )
        res = RunResult(
            system.name, data, failed, message, wall_time=_time.perf_counter() - t0_wall
        )
        if out_dir is not None:
            res.csv = res.to_csv(Path(out_dir) / "results.csv")
        return res

    def fail(name, what, status, t):
        u = units[name]
        label = STATUS[status] if 0 <= status < 6 else str(status)
        log = " | ".join(list(u.log)[-5:]) or "(no log message)"
        message = (
            f"component {name!r} ({u.comp.model_identifier}) returned fmi2{label} from {what} at "
            f"t = {t:.6g} s: {log}"
        )
        res = result(stored[0], True, message)
        details = "\n".join(
            [message, ""] + [f"[{n}] {line}" for n, unit in units.items() for line in unit.log]
        )
        where = ""
        if out_dir is not None:
            log_file = Path(out_dir) / "failure.log"
            log_file.write_text(details + "\n")
            where = f"; the FMUs' log in {log_file}"
        if res.csv and len(res.data):
            where += f"; results up to t = {res.data['time'][-1]:.6g} s in {res.csv}"
        raise HarnessError(message + where, result=res, details=details)

    def read(name):
        u = units[name]
        if u.n_out:
            status = u.get_real(u.c, u.out_vr, u.n_out, u.out_val)
            if status > 1:
                return status
            o = plan[name][2]
            latest[o : o + u.n_out] = u.out_val
        if u.n_bool:
            status = u.get_boolean(u.c, u.bool_vr, u.n_bool, u.bool_val)
            if status > 1:
                return status
            for i, v in enumerate(bools[name]):
                latest_bool[bool_index[(name, v.name)]] = float(u.bool_val[i])
        return 0

    def write_inputs(name, t):
        u = units[name]
        links, sigs, _ = plan[name]
        val = u.in_val
        for slot, src, factor, offset in links:
            val[slot] = factor * latest[src] + offset
        for slot, sig in sigs:
            val[slot] = sig(t)
        if u.n_in:
            return u.set_real(u.c, u.in_vr, u.n_in, val)
        return 0

    def refresh(name):
        # an algebraic component's outputs from its connected inputs now, without a step
        u = units[name]
        for slot, src, factor, offset in plan[name][0]:
            u.in_val[slot] = factor * latest[src] + offset
        if u.n_in and (status := u.set_real(u.c, u.in_vr, u.n_in, u.in_val)) > 1:
            return status
        return read(name)

    def store(t):
        stored[0] += 1
        row = rows[stored[0]]
        row[0] = t
        for j, (kind, ref) in enumerate(getters, start=1):
            if kind == "r":
                row[j] = latest[ref]
            elif kind == "b":
                row[j] = latest_bool[ref]
            else:
                row[j] = ref[0][ref[1]]

    # --- initialization -------------------------------------------------------------------
    from fmpy.fmi1 import FMICallException

    for name in order:
        u = units[name]
        try:
            u.slave.setupExperiment(startTime=start)
            u.slave.enterInitializationMode()
            for pname, (_, value) in u.comp.parameters.items():
                _set_value(u.slave, u.comp.variables[pname], value)
            for target, value in overrides.items():
                cname, _, vname = target.partition(".")
                if cname == name:
                    _set_value(u.slave, u.comp.variables[vname], value)
        except FMICallException as exc:
            fail(name, "initialization", exc.status if hasattr(exc, "status") else 3, start)
    for _ in range(2):  # settle chains of direct feedthrough
        for name in order:
            if (status := write_inputs(name, start)) > 1:
                fail(name, "fmi2SetReal", status, start)
            if (status := read(name)) > 1:
                fail(name, "fmi2GetReal", status, start)
    for name in order:
        try:
            units[name].slave.exitInitializationMode()
        except FMICallException as exc:
            fail(name, "fmi2ExitInitializationMode", getattr(exc, "status", 3), start)
        if units[name].log and any(m.startswith("[Error]") for m in units[name].log):
            fail(name, "fmi2ExitInitializationMode", 3, start)
    for name in order:
        if (status := write_inputs(name, start)) > 1:
            fail(name, "fmi2SetReal", status, start)
        if (status := read(name)) > 1:
            fail(name, "fmi2GetReal", status, start)
    store(start)
    # --- stepping -------------------------------------------------------------------------
    from tqdm import tqdm

    bar = tqdm(
        total=n_steps, delay=2.0, disable=not progress, unit="step", desc=system.name, leave=False
    )
    jacobi = algorithm == "jacobi"
    rates = [(name, settings.rates.get(name, 1)) for name in order]
    try:
        for k in range(n_steps):
            t = start + k * h
            # the components due at this step: (name, step size, read now): a slow one steps
            # over N·h and its outputs reach the others when that step ends (read below)
            due = [(n, min(r, n_steps - k) * h, r == 1) for n, r in rates if k % r == 0]
            if jacobi:
                for name, _, _ in due:
                    if (status := write_inputs(name, t)) > 1:
                        fail(name, "fmi2SetReal", status, t)
                for name, span, _ in due:
                    u = units[name]
                    if (status := u.do_step(u.c, t, span, 1)) > 1:
                        fail(name, "fmi2DoStep", status, t)
                for name, _, now in due:
                    if now and (status := read(name)) > 1:
                        fail(name, "fmi2GetReal", status, t)
            else:
                for name, span, now in due:
                    u = units[name]
                    if (status := write_inputs(name, t)) > 1:
                        fail(name, "fmi2SetReal", status, t)
                    if (status := u.do_step(u.c, t, span, 1)) > 1:
                        fail(name, "fmi2DoStep", status, t)
                    if now and (status := read(name)) > 1:
                        fail(name, "fmi2GetReal", status, t)
            ended = [n for n, r in rates if r > 1 and ((k + 1) % r == 0 or k + 1 == n_steps)]
            if ended:  # slow components whose step ends at t + h: publish, and update the
                for name in ended:  # algebraic components that read them
                    if (status := read(name)) > 1:
                        fail(name, "fmi2GetReal", status, t)
                for name in _readers(system, order, ended):
                    if (status := refresh(name)) > 1:
                        fail(name, "fmi2SetReal/fmi2GetReal", status, t + h)
            if (k + 1) % every == 0 or k + 1 == n_steps:
                store(start + (k + 1) * h)
            bar.update()
    finally:
        bar.close()
    return result(stored[0])

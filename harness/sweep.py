"""Sweeps and Monte-Carlo samples of independent runs on Dask (``servofmu sweep``).

A sweep is a list of *points* (dicts of parameter values: a grid, a random sample, or every
sample crossed with a grid) and a *task* that turns a chunk of points into result rows:

- :class:`ModelTask` evaluates the bearing model (the BearingFriction FMU's physics, through
  its parameter set) at each point: parameters of the pair plus the inputs ``temperature``,
  ``speed``, ``axial_load``, ``radial_load``; points that differ only in their inputs are
  evaluated together, vectorised;
- :class:`SystemTask` co-simulates an SSP system with the harness at each point (overrides
  ``component.variable``), and reports the recorded outputs at the end of the run (or their
  mean over the last part of it).

The chunks run on a Dask cluster: a ``LocalCluster`` of single-threaded worker processes by
default, an existing scheduler with ``scheduler=ADDRESS``. Each task instantiates its FMUs in
its worker process (the ``.ssp`` archive is sent to every worker once and unpacked there). A
point that fails becomes a row with its parameters and the error, and a chunk whose worker
fails marks its points so; the other results are kept. Rows come back in point order.

Before anything is submitted, every point is checked (``task.check``): each name is a
parameter or input of the model or system, each value has its type and lies in the range
the model or the FMU declares, each recorded name exists. Ctrl-C keeps the finished rows and
marks the others ``interrupted``.
"""

from __future__ import annotations

import contextlib
import hashlib
import itertools
import math
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

INPUTS = {"temperature": 293.15, "speed": 10.0 * math.pi / 180.0, "axial_load": 0.0,
          "radial_load": 0.0}  # fmt: skip


# ----------------------------------------------------------------------------- points
@dataclass(frozen=True)
class Uniform:
    """Uniform on [low, high]."""

    low: float
    high: float

    def draw(self, rng: np.random.Generator, n: int) -> np.ndarray:
        if not self.high >= self.low:
            raise ValueError(f"uniform: high = {self.high!r} must be ≥ low = {self.low!r}")
        return rng.uniform(self.low, self.high, n)


@dataclass(frozen=True)
class Normal:
    """Gaussian with mean and standard deviation sd."""

    mean: float
    sd: float

    def draw(self, rng: np.random.Generator, n: int) -> np.ndarray:
        if not self.sd >= 0:
            raise ValueError(f"normal: sd = {self.sd!r} must be ≥ 0")
        return rng.normal(self.mean, self.sd, n)


@dataclass(frozen=True)
class Choice:
    """One of ``values``, equally likely."""

    values: tuple

    def draw(self, rng: np.random.Generator, n: int) -> list:
        if not self.values:
            raise ValueError("choice: no values")
        return [self.values[i] for i in rng.integers(0, len(self.values), n)]


def grid_points(axes: Mapping[str, Sequence]) -> list[dict]:
    """Every combination of the axes' values (the last axis varies fastest)."""
    names = list(axes)
    for name in names:
        if len(axes[name]) == 0:
            raise ValueError(f"grid axis {name!r} has no values")
    return [
        {n: _plain(v) for n, v in zip(names, combo, strict=True)}
        for combo in itertools.product(*axes.values())
    ]


def sample_points(distributions: Mapping[str, object], n: int, seed: int = 0) -> list[dict]:
    """``n`` draws of every distribution (numpy ``default_rng(seed)``), with a ``sample``
    index."""
    if n < 1:
        raise ValueError(f"samples = {n!r} must be ≥ 1")
    rng = np.random.default_rng(seed)
    columns = {name: d.draw(rng, n) for name, d in distributions.items()}
    return [{"sample": i, **{k: _plain(v[i]) for k, v in columns.items()}} for i in range(n)]


def cross(samples: Sequence[dict], grid: Sequence[dict]) -> list[dict]:
    """Every sample with every grid point (a Monte-Carlo study over a grid)."""
    if not samples:
        return list(grid)
    if not grid:
        return list(samples)
    return [{**s, **g} for s in samples for g in grid]


def _plain(v):
    return v.item() if isinstance(v, np.generic) else v


# ----------------------------------------------------------------------------- tasks
@dataclass(frozen=True)
class ModelTask:
    """Bearing-model evaluations: ``base`` is a full BearingFriction parameter set
    (:func:`~servofmu.parameters.bearing.default_parameters`), a point overrides
    parameters and inputs, and may name presets (``mounting``, ``bearing``, ``lubricant``:
    catalogue entries whose numbers it takes before its own numbers,
    :func:`~servofmu.parameters.bearing.resolve`); ``outputs`` are fields of
    :class:`~servofmu.physics.bearing.BearingOutputs` (default: the FMU's outputs)."""

    base: Mapping[str, object]
    outputs: tuple[str, ...] = (
        "friction_torque",
        "running_torque",
        "breakaway_torque",
        "hysteresis_torque",
        "spin_torque",
        "sliding_torque",
        "viscous_torque",
        "preload",
        "contact_angle",
        "radial_clearance",
        "kinematic_viscosity",
        "axial_stiffness",
        "max_contact_pressure",
        "overloaded",
        "locked",
        "unloaded",
        "axial_play",
        "reverse_loaded",
        "outside_lubricant_range",
    )

    def check(self, points: Sequence[dict]) -> None:
        """Refuse, before anything is sent to the cluster, an unknown name, a value outside
        the range of its parameter (:mod:`~servofmu.parameters.bearing`) or input (the
        BearingFriction FMU's), and an output that the model does not have."""
        from dataclasses import fields

        from servofmu.parameters.bearing import PRESETS
        from servofmu.physics._checks import suggest
        from servofmu.physics.bearing import BearingOutputs

        known = set(self.base) | set(INPUTS) | set(PRESETS) | {"sample"}
        for name in {k for p in points for k in p}:
            if name not in known:
                raise ValueError(
                    f"sweep parameter {name!r} is neither a bearing parameter, a preset "
                    f"{list(PRESETS)} nor an input ({sorted(set(self.base) | set(INPUTS))})"
                    + suggest(name, known)
                )
        outputs = [f.name for f in fields(BearingOutputs)]
        for name in self.outputs:
            if name not in outputs:
                raise ValueError(
                    f"record {name!r} is not an output of the model ({outputs})"
                    + suggest(name, outputs)
                )
        seen = set()
        for i, p in enumerate(points):
            for name, value in p.items():
                if name == "sample" or (name, repr(value)) in seen:
                    continue
                seen.add((name, repr(value)))
                if problem := _model_value_problem(name, value):
                    raise ValueError(f"sweep point {i} ({_describe(p)}): {name} {problem}")

    def units(self) -> dict[str, str]:
        """Unit of each column this task writes (parameters, inputs, outputs)."""
        from servofmu.parameters.bearing import PARAMETERS

        fmu = _fmu_variables()
        units = {}
        for name in self.outputs:
            v = fmu.get(name)
            if v is not None and v.causality == "output":
                units[name] = "0/1" if v.type == "Boolean" else v.unit or ""
            else:
                units[name] = OUTPUT_UNITS.get(name, "")
        units.update({spec.name: spec.unit or "" for spec in PARAMETERS if spec.type == "Real"})
        units.update({n: unit for n, (_, _, unit) in input_ranges().items()})
        return {n: "-" if u == "1" else u for n, u in units.items() if u}

    def __call__(self, points: Sequence[dict]) -> list[dict]:
        from servofmu.parameters.bearing import pair_from_parameters, resolve
        from servofmu.physics.bearing import operating_outputs

        rows: list[dict | None] = [None] * len(points)
        groups: dict[tuple, list[int]] = {}
        for i, p in enumerate(points):
            key = tuple(sorted((k, v) for k, v in p.items() if k not in INPUTS))
            groups.setdefault(key, []).append(i)
        for key, idx in groups.items():
            changes = {k: _as_key(k, v) for k, v in key if k != "sample"}
            try:
                pair = pair_from_parameters(resolve(self.base, changes))
            except Exception as exc:  # a bad parameter fails its points, not the sweep
                for i in idx:
                    rows[i] = _failed(points[i], exc)
                continue
            inputs = {n: np.array([points[i].get(n, d) for i in idx]) for n, d in INPUTS.items()}
            if not np.any(inputs["radial_load"] != 0.0):  # vectorised over the group
                try:
                    out = operating_outputs(
                        pair, inputs["temperature"], inputs["speed"], inputs["axial_load"]
                    )
                    values = {
                        o: np.broadcast_to(getattr(out, o), (len(idx),)) for o in self.outputs
                    }
                    for j, i in enumerate(idx):
                        rows[i] = {**points[i], **{o: _plain(values[o][j]) for o in self.outputs}}
                    continue
                except Exception:  # a bad point fails the whole call: evaluate one by one
                    pass
            for j, i in enumerate(idx):  # radial loads are solved per point (Jones)
                rows[i] = self._one(pair, {n: float(v[j]) for n, v in inputs.items()}, points[i])
        return rows

    def _one(self, pair, inputs, point):
        from servofmu.physics.bearing import operating_outputs

        try:
            out = operating_outputs(
                pair,
                inputs["temperature"],
                inputs["speed"],
                inputs["axial_load"],
                inputs["radial_load"],
            )
            return {**point, **{o: _plain(np.asarray(getattr(out, o))[()]) for o in self.outputs}}
        except Exception as exc:
            return _failed(point, exc)


#: Units of the model's outputs that the BearingFriction FMU does not export (SI).
OUTPUT_UNITS = {
    "inner_ring_torque": "N.m",
    "outer_ring_torque": "N.m",
    "outer_fit_pressure": "Pa",
    "inner_fit_pressure": "Pa",
    "outer_interference": "m",
    "inner_interference": "m",
    "force_a": "N",
    "force_b": "N",
    "axial_displacement": "m",
}


def _fmu_variables() -> dict:
    """The BearingFriction FMU's variables (its inputs' ranges and outputs' units: one
    definition for the model and the FMU)."""
    from servofmu.fmus.BearingFriction import BearingFriction

    return {v.name: v for v in BearingFriction.VARIABLES}


def input_ranges() -> dict[str, tuple[float, float, str]]:
    """(min, max, unit) of the model's inputs, as the BearingFriction FMU declares them."""
    variables = _fmu_variables()
    return {n: (variables[n].min, variables[n].max, variables[n].unit) for n in INPUTS}


def _model_value_problem(name: str, value) -> str:
    """Why ``value`` cannot be given to model parameter or input ``name``, or ""."""
    from servofmu.parameters.bearing import PRESETS, parameter
    from servofmu.physics._checks import suggest

    if name in INPUTS:
        lo, hi, unit = input_ranges()[name]
    elif name in PRESETS:  # a catalogue entry whose numbers the point takes
        from servofmu.parameters import catalog

        keys = catalog.keys(f"{name}s")
        hint = suggest(str(value), keys)
        return "" if _as_key(name, value) in keys else f"= {value!r} is not one of {keys}{hint}"
    else:
        spec = parameter(name)
        if spec.choices:
            keys = [c.key for c in spec.choices]
            key = _as_key(name, value)
            return "" if key in keys else f"= {value!r} is not one of {[k for k in keys if k]}"
        lo, hi, unit = spec.min, spec.max, spec.unit
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return f"= {value!r} is not a finite number"
    lo = -math.inf if lo is None else lo
    hi = math.inf if hi is None else hi
    if not lo <= value <= hi:
        return f"= {value!r} is outside the valid range [{lo:g}, {hi:g}] {unit or ''}".rstrip()
    return ""


def _describe(point: dict) -> str:
    return ", ".join(f"{k}={v!r}" for k, v in point.items())


def _as_key(name: str, value):
    """A preset's catalogue key as text: a key that reads as a number (the bearing "71803",
    parsed from a command line as 71803.0) comes back as "71803"."""
    from servofmu.parameters.bearing import PRESETS

    if name in PRESETS and isinstance(value, (int, float)):
        return str(int(value)) if float(value).is_integer() else str(value)
    return value


@dataclass(frozen=True)
class SystemTask:
    """Co-simulations of one SSP system: ``ssp`` is the archive's bytes (sent to each worker
    once), a point holds ``component.variable`` overrides; each run records ``record`` and
    reports its last value, or its mean over the last ``tail`` fraction of the run."""

    ssp: bytes = field(repr=False)
    record: tuple[str, ...]
    stop: float | None = None
    step: float | None = None
    algorithm: str = "gauss-seidel"
    tail: float = 0.0

    @property
    def digest(self) -> str:
        return hashlib.sha256(self.ssp).hexdigest()[:16]

    def check(self, points: Sequence[dict]) -> None:
        """Load the system here once and check, before the sweep, the times, the recorded
        names and every point's values against their FMU variables (settable, typed, within
        range): :func:`~.master.check_run`."""
        from .master import check_run

        system = _system(self.digest, self.ssp)
        check_run(
            system, stop=self.stop, step=self.step, algorithm=self.algorithm, record=self.record
        )
        seen = set()
        for i, p in enumerate(points):
            values = {k: v for k, v in p.items() if k != "sample"}
            key = repr(sorted(values.items()))
            if key in seen:
                continue
            seen.add(key)
            try:
                check_run(system, parameters=values, stop=self.stop, step=self.step, record=[])
            except ValueError as exc:
                raise type(exc)(f"sweep point {i} ({_describe(p)}): {exc}") from None

    def units(self) -> dict[str, str]:
        """Unit of each column this task writes (the FMU variables' SI units)."""
        system = _system(self.digest, self.ssp)
        names = list(self.record) + [
            f"{c.name}.{v.name}" for c in system.components.values() for v in c.variables.values()
        ]
        return {n: system.scale(n).csv_unit for n in names}

    def __call__(self, points: Sequence[dict]) -> list[dict]:
        from servofmu.harness import run as run_system

        system = _system(self.digest, self.ssp)
        rows = []
        for p in points:
            try:
                res = run_system(
                    system,
                    parameters={k: v for k, v in p.items() if k != "sample"},
                    stop=self.stop,
                    step=self.step,
                    algorithm=self.algorithm,
                    record=list(self.record),
                    progress=False,
                )
                row = dict(p)
                n = len(res.data)
                start = min(n - 1, round((1.0 - self.tail) * (n - 1))) if self.tail else n - 1
                for name in self.record:
                    row[name] = float(np.mean(res[name][start:]))
                rows.append(row)
            except Exception as exc:  # a HarnessError or anything else: this run fails alone
                rows.append(_failed(p, exc))
        return rows


_SYSTEMS: dict[str, tuple] = {}  # per process: digest → (loaded System, its temp folder)


def _system(digest: str, data: bytes):
    """The system of archive ``data``, loaded once per process (the archive in a temporary
    folder that is removed when the process ends)."""
    from servofmu.files import scratch_folder
    from servofmu.harness import load_system

    if digest not in _SYSTEMS:
        folder = scratch_folder("servofmu_sweep_")
        archive = Path(folder.name) / f"{digest}.ssp"
        archive.write_bytes(data)
        _SYSTEMS[digest] = (load_system(archive), folder)
    return _SYSTEMS[digest][0]


def _failed(point: dict, exc: BaseException, lost: bool = False) -> dict:
    """The row of a failed point: its parameters and the error (``lost``: its chunk never
    came back from the cluster, which is said so)."""
    text = f"{type(exc).__name__}: {exc}".splitlines()[0]
    if lost:
        text = f"lost: its worker failed or the cluster has no worker left ({text})"
    return {**point, "error": text}


# ----------------------------------------------------------------------------- running
@dataclass
class SweepResult:
    """Rows in point order (each a dict: the point's parameters, the outputs, and ``error``
    for a failed one), with the cluster's worker count and the wall time."""

    rows: list[dict]
    workers: int
    wall_time: float
    interrupted: bool = False  # Ctrl-C: the rows not finished carry the error "interrupted"
    units: dict[str, str] = field(default_factory=dict)  # column → SI unit

    @property
    def failed(self) -> list[dict]:
        return [r for r in self.rows if r.get("error")]

    @property
    def columns(self) -> list[str]:
        cols = ["run"]
        for r in self.rows:
            for k in r:
                if k not in cols and k != "error":
                    cols.append(k)
        return [*cols, "error"]

    def column(self, name: str) -> np.ndarray:
        """One column as a float array (NaN where a row lacks it)."""
        return np.array([float(r.get(name, math.nan)) for r in self.rows])

    def header(self, column: str) -> str:
        """``column [unit]`` for a quantity with a known unit, else the bare name."""
        unit = self.units.get(column)
        return f"{column} [{unit}]" if unit else column

    def write(self, path) -> Path:
        """The table as CSV (headers ``name [unit]``), or Parquet when ``path`` ends in
        ``.parquet`` (bare names, the unit in each field's metadata), whole or not at all
        (:func:`servofmu.files.written`: a signal waits until it is in place)."""
        from servofmu.files import written

        path = Path(path)
        check_table_path(path)
        cols = self.columns
        table = {c: [r.get(c, i if c == "run" else None) for i, r in enumerate(self.rows)]
                 for c in cols}  # fmt: skip
        table["error"] = [r.get("error", "") for r in self.rows]
        if path.suffix == ".parquet":
            import pyarrow as pa
            import pyarrow.parquet as pq

            arrays = {c: _arrow_column(v) for c, v in table.items()}
            schema = pa.schema(
                [
                    pa.field(
                        c, a.type, metadata={"unit": self.units[c]} if c in self.units else None
                    )
                    for c, a in arrays.items()
                ]
            )
            with written(path) as part:
                pq.write_table(pa.table(arrays, schema=schema), part)
            return path
        import csv

        with written(path) as part, part.open("w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow([self.header(c) for c in cols])
            for i in range(len(self.rows)):
                w.writerow(["" if table[c][i] is None else _cell(table[c][i]) for c in cols])
        return path


TABLE_SUFFIXES = (".csv", ".parquet")


def check_table_path(path) -> None:
    """ValueError unless ``path`` ends in one of :data:`TABLE_SUFFIXES`, and the packages that
    write it are installed (:func:`require_sweep_extra`).

    Returns
    -------
    None

    Examples
    --------
    >>> check_table_path("out/sweep/results.csv")
    >>> try:
    ...     check_table_path("out/sweep/results.xlsx")
    ... except ValueError as exc:
    ...     print(str(exc).split(":")[0])
    out = 'out/sweep/results.xlsx'
    """
    if Path(path).suffix not in TABLE_SUFFIXES:
        raise ValueError(
            f"out = {str(path)!r}: a sweep table is written as {' or '.join(TABLE_SUFFIXES)}; "
            "name the file so"
        )
    if Path(path).suffix == ".parquet":
        require_sweep_extra(("pyarrow",))


#: The packages of the ``sweep`` extra that running a sweep needs.
SWEEP_PACKAGES = ("dask", "distributed")


def require_sweep_extra(packages=SWEEP_PACKAGES) -> None:
    """:class:`~servofmu.harness.errors.MissingExtra` naming the extra to install when one of
    ``packages`` is missing (sweeps and Monte-Carlo studies run on Dask, which a base install
    of servofmu leaves out).

    Parameters
    ----------
    packages : tuple of str
        Importable names to look for (default: :data:`SWEEP_PACKAGES`).

    Returns
    -------
    None
        When every package is importable.

    Examples
    --------
    >>> require_sweep_extra(("math",))
    >>> try:
    ...     require_sweep_extra(("no_such_package",))
    ... except ImportError as exc:
    ...     print(exc)  # doctest: +ELLIPSIS
    no_such_package not installed: ... (pip install 'servofmu[sweep]')
    """
    import importlib.util

    from .errors import MissingExtra

    missing = [p for p in packages if importlib.util.find_spec(p) is None]
    if missing:
        raise MissingExtra(
            f"{', '.join(missing)} not installed: sweeps and Monte-Carlo studies need the "
            "sweep extra (pip install 'servofmu[sweep]')"
        )


def _cell(v):
    if isinstance(v, bool):
        return int(v)
    if isinstance(v, float):
        return f"{v:.12g}"
    return v


def _arrow_column(values):
    import pyarrow as pa

    if all(isinstance(v, bool) or v is None for v in values):
        return pa.array(values, type=pa.bool_())
    if all(isinstance(v, int) and not isinstance(v, bool) for v in values):
        return pa.array(values, type=pa.int64())
    if all(v is None or (isinstance(v, (int, float)) and not isinstance(v, bool)) for v in values):
        return pa.array([None if v is None else float(v) for v in values], type=pa.float64())
    return pa.array(["" if v is None else str(v) for v in values], type=pa.string())


def run_sweep(
    task,
    points: Sequence[dict],
    *,
    workers: int | None = None,
    scheduler: str | None = None,
    chunk_size: int | None = None,
    progress: bool = True,
    client=None,
) -> SweepResult:
    """Run ``task`` over ``points`` on Dask: a LocalCluster of ``workers`` single-threaded
    processes (default: one per core), the scheduler at ``scheduler``, or an open Dask
    ``client`` (kept open). Points go in chunks of ``chunk_size`` (default: about four chunks
    per worker)."""
    from dask.distributed import Client, as_completed

    from .interrupt import protected
    from .progress import progress_bar

    points = [dict(p) for p in points]
    if not points:
        raise ValueError("a sweep needs at least one point")
    if chunk_size is not None and chunk_size < 1:
        raise ValueError(f"chunk_size = {chunk_size!r} must be ≥ 1")
    if workers is not None and workers < 1:
        raise ValueError(f"workers = {workers!r} must be ≥ 1")
    task.check(points)
    units = task.units() if hasattr(task, "units") else {}
    t0 = time.perf_counter()
    cluster, own = None, client is None
    try:
        if client is not None:
            pass
        elif scheduler:
            client = Client(scheduler)
        else:
            cluster = local_cluster(workers)
            client = Client(cluster)
    except KeyboardInterrupt:  # a signal while the cluster starts: nothing ran, all marked
        with protected(reraise=False):
            for part in (client if own else None, cluster):
                if part is not None:
                    with contextlib.suppress(Exception):  # a cluster half started may not close
                        part.close()
        rows = [{**p, "error": "interrupted"} for p in points]
        return SweepResult(rows, 0, time.perf_counter() - t0, True, units)
    interrupted = False
    try:
        n_workers = max(1, len(client.scheduler_info(n_workers=-1)["workers"]))
        size = chunk_size or max(1, math.ceil(len(points) / (4 * n_workers)))
        chunks = [list(range(i, min(i + size, len(points)))) for i in range(0, len(points), size)]
        shared = client.scatter(task, broadcast=True, hash=False)  # a fresh key per sweep

        def submit(c):
            return client.submit(_run_chunk, shared, [points[i] for i in c], pure=False)

        futures = {submit(c): c for c in chunks}
        tries = dict.fromkeys(map(tuple, chunks), 0)
        rows: list[dict | None] = [None] * len(points)
        bar = progress_bar(len(points), desc="sweep", unit="run", enabled=progress, delay=1.0)
        try:
            pending = as_completed(futures)
            for fut in pending:
                idx = futures[fut]
                try:
                    out = fut.result()
                except Exception as exc:  # the worker died, or the chunk raised
                    lost = _lost_with_a_worker(exc)
                    if lost and tries[tuple(idx)] < RERUNS and _workers(client):
                        tries[tuple(idx)] += 1
                        again = submit(idx)
                        futures[again] = idx
                        pending.add(again)
                        continue
                    out = [_failed(points[i], exc, lost=lost) for i in idx]
                for i, row in zip(idx, out, strict=True):
                    rows[i] = row
                bar.update(len(idx))
        except KeyboardInterrupt:  # Ctrl-C or SIGTERM: keep what is done, mark the rest
            interrupted = True
            with protected(reraise=False):
                client.cancel(list(futures))
                rows = [r if r is not None else {**p, "error": "interrupted"}
                        for r, p in zip(rows, points, strict=True)]  # fmt: skip
        finally:
            bar.close()
    finally:
        # closing a cluster takes seconds: a signal meanwhile waits for it, and then stops
        # the sweep as if it had come before (the caller writes the rows and exits so)
        with protected(reraise=False) as held:
            if own:
                client.close()
            if cluster is not None:
                cluster.close()
        interrupted = interrupted or bool(held)
    return SweepResult(rows, n_workers, time.perf_counter() - t0, interrupted, units)


#: How often a chunk lost with its worker is run again while the cluster has workers (Dask
#: itself retries a task whose worker died a few times before it gives up on it).
RERUNS = 2


def _lost_with_a_worker(exc: BaseException) -> bool:
    """True for the errors of a chunk whose worker died (Dask gave up on it, or forgot it
    when the workers went), not for an error the chunk itself raised."""
    from concurrent.futures import CancelledError

    from distributed.scheduler import KilledWorker

    return isinstance(exc, KilledWorker | CancelledError)


def _workers(client) -> int:
    """The number of workers the cluster has now (0 when it cannot be asked)."""
    try:
        return len(client.scheduler_info(n_workers=-1)["workers"])
    except Exception:
        return 0


#: Dask settings of servofmu's LocalCluster: the worker's statistical profiler (a 10 ms stack
#: sampler), the GIL monitor and the frequent event-loop ticks and monitors compete with the
#: single-threaded Python tasks for the GIL and the cores (measured: 2 workers on 2 cores gave
#: 1.72× the runs of 1 worker with the defaults, 1.95× with these).
LOCAL_CLUSTER_CONFIG = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.system-monitor.gil.enabled": False,
    "distributed.admin.system-monitor.interval": "2s",
    "distributed.worker.memory.monitor-interval": "1s",
    "distributed.admin.tick.interval": "200ms",
}


def local_cluster(workers: int | None = None):
    """A Dask LocalCluster of ``workers`` single-threaded worker processes (default: one per
    core), no dashboard, quiet logs, :data:`LOCAL_CLUSTER_CONFIG`."""
    import logging
    import os

    import dask
    from dask.distributed import LocalCluster

    n = (os.cpu_count() or 1) if workers is None else workers
    if n < 1:
        raise ValueError(f"workers = {workers!r} must be ≥ 1")
    with dask.config.set(LOCAL_CLUSTER_CONFIG):
        return LocalCluster(
            n_workers=n,
            threads_per_worker=1,
            processes=True,
            dashboard_address=":0",  # any free port: never collides with another cluster
            silence_logs=logging.ERROR,
        )


def _run_chunk(task, points):
    return task(points)

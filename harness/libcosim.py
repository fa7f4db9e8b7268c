"""Running an ``.ssp`` unchanged in libcosim (libcosimpy), for the cross-check against the
harness. libcosim's fixed-step algorithm sets every input from the outputs of the previous
communication point and steps all components (Jacobi), applies component-level .ssv bindings
and LinearTransformation, and takes its step from the OSP annotation of the SSD."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .errors import HarnessError


def run_libcosim(ssp, record, stop: float, step: float | None = None) -> dict[str, np.ndarray]:
    """Simulate ``ssp`` (archive or folder) in libcosim until ``stop`` [s], with the SSD's
    step or ``step`` [s]; returns ``{"time": ..., "component.variable": ...}`` for the Real
    variables in ``record``, sampled at every communication point from the start (libcosim's
    observer holds the points before ``stop``)."""
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver

    log_output_level(CosimLogLevel.ERROR)
    if step is None:
        ex = CosimExecution.from_ssp_file(str(Path(ssp)))
    else:
        ex = CosimExecution.from_ssp_file(str(Path(ssp)), step_size=round(step * 1e9))
    observer = CosimObserver.create_time_series()
    ex.add_observer(observer)
    refs = {}
    for target in record:
        comp, _, var = target.partition(".")
        index = ex.slave_index_from_instance_name(comp)
        if index is None:
            raise HarnessError(f"libcosim: no component {comp!r} in {ssp}")
        names = {v.name.decode(): v.reference for v in ex.slave_variables(index)}
        if var not in names:
            raise HarnessError(f"libcosim: component {comp!r} has no variable {var!r}")
        refs[target] = (index, names[var])
        observer.start_time_series(index, names[var], CosimVariableType.REAL)
    if not ex.simulate_until(target_time=round(stop * 1e9)):
        raise HarnessError(f"libcosim could not run {ssp} to {stop} s")
    out = {}
    for target, (index, vr) in refs.items():
        times, _, values = observer.time_series_real_samples(
            index, vr, from_step=0, sample_count=10**7
        )
        out.setdefault("time", np.asarray(times, dtype=float) * 1e-9)
        out[target] = np.asarray(values, dtype=float)
    return out

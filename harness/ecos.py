"""Running an ``.ssp`` unchanged in ecos (``ecospy``), a third engine beside the harness and
libcosim.

How ecos 0.7 reads a system (its SSP loader and ``simulation::init``, checked against runs):

- it applies component-level ``.ssv`` bindings only, and of those only the parameter sets
  whose ``ParameterSet name`` is given to ``init(parameter_set=...)``: one name per run, and
  nothing at all without a name. servofmu's ``.ssv`` files therefore all carry one name,
  :data:`PARAMETER_SET`;
- it honours ``LinearTransformation`` on connections;
- it steps every component from the outputs at the start of the step (Jacobi), at the step
  given to ``EcosSimulation`` (it does not read the OSP annotation);
- variables are named ``component::variable``.

ecospy's library needs Intel TBB (Debian: ``libtbb12``); :func:`ecos_unavailable` says why
ecos cannot be loaded here, if it cannot.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .errors import HarnessError

PARAMETER_SET = "servofmu"  # the ParameterSet name of every .ssv file of ssp/


def ecos_unavailable() -> str:
    """Why ecos cannot run here ("" when it can): ecospy missing, or its library not loadable
    (typically libtbb.so.12 missing)."""
    try:
        import ecospy  # noqa: F401  (loads libecosc)
    except ImportError as exc:
        return f"ecospy is not installed: {exc} (pip install ecospy)"
    except OSError as exc:
        return f"ecospy's library cannot be loaded: {exc} (Debian: apt-get install libtbb12)"
    return ""


def run_ecos(
    ssp, record, stop: float, step: float, parameter_set: str | None = PARAMETER_SET
) -> dict[str, np.ndarray]:
    """Simulate ``ssp`` (archive or folder) in ecos from 0 to ``stop`` [s] at the fixed
    ``step`` [s], applying the parameter sets named ``parameter_set``; returns
    ``{"time": ..., "component.variable": ...}`` for the Real variables in ``record``, at
    every communication point after the start (as libcosim's observer gives them)."""
    from ecospy import EcosLib, EcosSimulation

    EcosLib.set_log_level("err")
    try:
        sim = EcosSimulation(ssp_path=str(Path(ssp)), step_size=step)
    except Exception as exc:  # ecospy raises a bare Exception with ecos's message
        raise HarnessError(f"ecos could not load {ssp}: {exc}") from None
    try:
        if not sim.init(parameter_set=parameter_set):
            raise HarnessError(f"ecos could not initialise {ssp}: {EcosLib.get_last_error()}")
        names = [target.replace(".", "::", 1) for target in record]
        n = round(stop / step)
        out = np.empty((n + 1, len(names)))
        times = np.zeros(n + 1)
        for i in range(n + 1):
            if i:
                times[i] = sim.step()
            try:
                out[i] = [sim.get_real(name) for name in names]
            except Exception as exc:
                raise HarnessError(f"ecos: {exc} (reading {record})") from None
        sim.terminate()
    finally:
        sim.free()
    return {"time": times, **{target: out[:, k] for k, target in enumerate(record)}}

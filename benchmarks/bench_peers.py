"""The seeker gimbal over 200 s in servofmu's harness, in OMSimulator and in libcosim: the
same built ``seeker_gimbal.ssp`` (ServoController, DCMotor, BearingFriction; 1 ms
communication step), the same stop time, measured in one run (on demand: ``make bench``; not
part of the tests).

Each engine runs the archive unchanged in a fresh Python process, one after another and
interleaved over ``--repeat`` rounds: the harness (Gauss-Seidel, its default, and Jacobi,
the peers' scheme; three columns kept in memory), OMSimulator through its Python package
(classic route: ``importFile``, its fixed-step master at the system's 1 ms) without a result
file, with the same three signals in its result file, and with its default result file
(every variable at every step), and libcosim through libcosimpy (its fixed-step algorithm,
the OSP step, the three signals observed). Timed from loading the system to the end of the
run, set-up included, the modules every engine needs imported before; wall time and the
process's CPU time (user + system, all threads), best of the rounds. The ratios are the
harness's time over each peer's; CPU time moves less than wall time on a shared machine.
Every engine must end at the loop's reference speed (10 °/s): it ran the same system.
OMSimulator is not a dependency (its PyPI package downloads binaries at install time): it is
used when ``import OMSimulator`` works, else its command-line tool when on PATH (with the
environment of ``servofmu host-env``; every variable written to /dev/null, the process's
start included), else its rows say "not available".
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from results import add_output_options, emit  # benchmarks/ is the script's folder

SYSTEM = "seeker_gimbal"
STOP = 200.0  # s simulated
RECORD = ["motor.speed", "motor.current", "bearing.running_torque"]
OURS = ("harness, Gauss-Seidel", "harness, Jacobi")
#: OMSimulator's result file: none, the harness's three signals, or its default (every
#: variable at every step)
OMS = {
    "OMSimulator, no result file": "none",
    "OMSimulator, 3 signals in its result file": "record",
    "OMSimulator, every variable (its default)": "all",
}
PEERS = (*OMS, "libcosim")
ENGINES = (*OURS, *PEERS)
#: The start of the line of figures a measured process prints (an engine prints too).
MARK = "figures: "


# ----------------------------------------------------------------------------- one engine
def _harness(ssp: Path, stop: float, algorithm: str) -> float:
    from servofmu.harness import load_system, run

    system = load_system(ssp)
    try:
        res = run(system, stop=stop, record=RECORD, algorithm=algorithm, progress=False)
    finally:
        system.close()
    return float(res["motor.speed"][-1])


def _libcosim(ssp: Path, stop: float) -> float:
    from servofmu.harness.libcosim import run_libcosim

    return float(run_libcosim(ssp, RECORD, stop)["motor.speed"][-1])


def _omsimulator(ssp: Path, stop: float, results: str, tmp: str, system: str) -> float:
    """The archive through OMSimulator's classic Python route, its result file as ``results``
    says (:data:`OMS`) in the folder ``tmp``; the last motor speed [rad/s] (the model holds
    the SSD's system, named ``system``)."""
    from OMSimulator import OMSimulator

    oms = OMSimulator()
    oms.setTempDirectory(tmp)
    model, status = oms.importFile(str(ssp))
    if status != 0:
        raise RuntimeError(f"OMSimulator could not import {ssp} (status {status})")
    try:
        if results == "none":
            oms.setResultFile(model, "")
        else:
            oms.setResultFile(model, str(Path(tmp) / "results.mat"))
        if results == "record":
            oms.removeSignalsFromResults(model, ".*")
            oms.addSignalsToResults(model, "|".join(f".*{name}" for name in RECORD))
        oms.setStopTime(model, stop)
        for call in (oms.instantiate, oms.initialize, oms.simulate):
            if (status := call(model)) != 0:
                raise RuntimeError(f"OMSimulator: {call.__name__} returned status {status}")
        speed, status = oms.getReal(f"{model}.{system}.motor.speed")
        oms.terminate(model)
    finally:
        oms.delete(model)  # before the interpreter ends (pythonfmu's finaliser)
    return float(speed)


def _system_name(ssp: Path) -> str:
    from servofmu.harness import load_system

    system = load_system(ssp)
    try:
        return system.name
    finally:
        system.close()


def run_engine(engine: str, ssp: Path, stop: float) -> dict:
    """Run ``engine`` in this process; its wall and CPU time [s] (user + system, every thread
    of the process) and the last motor speed [rad/s]. The engine's modules and the package the
    FMUs import (servofmu, numpy, scipy: the first FMU to import it in a process uses it for
    all) are imported first, outside the timing, for every engine alike."""
    import servofmu.fmus
    import servofmu.harness  # noqa: F401

    if engine in OMS:
        import OMSimulator  # noqa: F401

        name = _system_name(ssp)

    with tempfile.TemporaryDirectory(prefix="servofmu_bench_") as tmp:
        t0, c0 = time.perf_counter(), time.process_time()
        if engine in OURS:
            speed = _harness(ssp, stop, "jacobi" if "Jacobi" in engine else "gauss-seidel")
        elif engine == "libcosim":
            speed = _libcosim(ssp, stop)
        else:
            speed = _omsimulator(ssp, stop, OMS[engine], tmp, name)
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    return {"wall [s]": wall, "CPU [s]": cpu, "final speed [rad/s]": speed}


def _omsimulator_command(ssp: Path, stop: float) -> dict:
    """OMSimulator's command-line tool on the archive, with the environment a non-Python host
    needs (``servofmu host-env``); wall and CPU time of the whole process (the interpreter's
    start and the FMUs' imports included), its result file (every variable, every step)
    written to /dev/null."""
    import os

    from servofmu.build.host import host_environment

    with tempfile.TemporaryDirectory(prefix="servofmu_oms_") as tmp:
        command = [shutil.which("OMSimulator"), f"--stopTime={stop:g}", "--resultFile=/dev/null",
                   f"--tempDir={tmp}", str(ssp)]  # fmt: skip
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        done = subprocess.run(
            command, env=os.environ | host_environment(), capture_output=True, text=True
        )
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        tail = ((done.stdout + done.stderr).strip().splitlines() or ["no message"])[-1]
        return {"error": f"exit {done.returncode}: {tail}"}
    cpu = sum(getattr(after, f) - getattr(before, f) for f in ("ru_utime", "ru_stime"))
    return {"wall [s]": wall, "CPU [s]": cpu, "final speed [rad/s]": None}


# ----------------------------------------------------------------------------- the comparison
def _oms_package() -> bool:
    return importlib.util.find_spec("OMSimulator") is not None


def available(engine: str) -> str:
    """ "" when ``engine`` can run here, else why not."""
    if engine in OMS and not _oms_package():
        if not shutil.which("OMSimulator"):
            return "not available: OMSimulator is neither importable nor on PATH"
        if OMS[engine] != "all":
            return "not available: needs OMSimulator's Python package (only its tool is on PATH)"
    if engine == "libcosim" and importlib.util.find_spec("libcosimpy") is None:
        return "not available: libcosimpy is not installed (pip install -e '.[test]')"
    return ""


def _figures(stdout: str) -> dict:
    return json.loads(next(s for s in stdout.splitlines() if s.startswith(MARK))[len(MARK) :])


def measure(engine: str, ssp: Path, stop: float) -> dict:
    """``engine`` in a fresh Python process: :func:`run_engine`'s figures, or the error."""
    if engine in OMS and not _oms_package():
        return _omsimulator_command(ssp, stop)
    done = subprocess.run(
        [sys.executable, __file__, "--engine", engine, "--ssp", str(ssp), "--stop", str(stop)],
        capture_output=True,
        text=True,
        check=False,
    )
    if done.returncode != 0 or MARK not in done.stdout:
        tail = (done.stderr.strip().splitlines() or ["no message"])[-1]
        return {"error": f"exit {done.returncode}: {tail}"}
    return _figures(done.stdout)


def compare(ssp: Path, stop: float, repeat: int) -> dict:
    from servofmu.physics.kernels.units import DEG

    rounds: dict[str, list[dict]] = {e: [] for e in ENGINES}
    for _ in range(repeat):
        for engine in ENGINES:
            if not available(engine):
                rounds[engine].append(measure(engine, ssp, stop))
    rows, best = [], {}
    for engine in ENGINES:
        runs = [r for r in rounds[engine] if "error" not in r]
        why = available(engine) or ("" if runs else rounds[engine][0]["error"])
        if why:
            rows.append({"engine": engine, "wall [s]": "", "CPU [s]": "", "speed [deg/s]": "",
                         "note": why})  # fmt: skip
            continue
        wall = min(r["wall [s]"] for r in runs)
        cpu = min(r["CPU [s]"] for r in runs)
        speed = runs[-1]["final speed [rad/s]"]
        best[engine] = (wall, cpu)
        note = f"best of {len(runs)}"
        if engine in OMS and not _oms_package():
            note += "; command line: every variable to /dev/null, process start included"
        rows.append({"engine": engine, "wall [s]": wall, "CPU [s]": cpu,
                     "speed [deg/s]": "" if speed is None else speed / DEG,
                     "note": note})  # fmt: skip
    ratios = {}
    for ours in OURS:
        for peer in PEERS:
            key = f"{ours} / {peer}"
            if ours in best and peer in best:
                ratios[f"{key}, wall"] = best[ours][0] / best[peer][0]
                ratios[f"{key}, CPU"] = best[ours][1] / best[peer][1]
            else:
                ratios[key] = "not available"
    return {"system": SYSTEM, "stop time [s]": stop, "versions": _versions(), "engines": rows,
            "ratios": ratios}  # fmt: skip


def _versions() -> dict:
    """The engines' versions as they report them."""
    from importlib.metadata import PackageNotFoundError, version

    out = {}
    for name in ("fmpy", "pythonfmu", "libcosimpy"):
        try:
            out[name] = version(name)
        except PackageNotFoundError:
            out[name] = "not installed"
    out["OMSimulator"] = "not available"
    if _oms_package():
        show = "import OMSimulator; print(OMSimulator.version)"
        done = subprocess.run([sys.executable, "-c", show], capture_output=True, text=True)
        out["OMSimulator"] = (done.stdout.strip().splitlines() or ["?"])[-1] + " (Python package)"
    elif shutil.which("OMSimulator"):
        done = subprocess.run(["OMSimulator", "--version"], capture_output=True, text=True)
        out["OMSimulator"] = (done.stdout.strip().splitlines() or ["?"])[-1] + " (command line)"
    return out


def main(argv=None) -> dict | None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stop", type=float, default=STOP, help="simulated time [s]")
    parser.add_argument("--repeat", type=int, default=2, help="interleaved rounds")
    parser.add_argument("--engine", choices=ENGINES, help=argparse.SUPPRESS)  # one run, here
    parser.add_argument("--ssp", help=argparse.SUPPRESS)
    add_output_options(parser)
    args = parser.parse_args(argv)
    if args.engine:  # a measured process: one line of figures
        print(MARK + json.dumps(run_engine(args.engine, Path(args.ssp), args.stop)), flush=True)
        return None
    from servofmu.harness.scenarios.common import system_path

    figures = compare(system_path(SYSTEM), args.stop, args.repeat)
    if not emit(args, figures, argv):
        print(f"{SYSTEM}, {args.stop:g} s simulated (1 ms step), best of {args.repeat}")
        print(f"{'engine':42s} {'wall [s]':>9s} {'CPU [s]':>9s} {'speed [°/s]':>12s}  note")
        for r in figures["engines"]:
            wall, cpu, speed = (_cell(r[k], w) for k, w in (("wall [s]", 9), ("CPU [s]", 9),
                                                             ("speed [deg/s]", 12)))  # fmt: skip
            print(f"{r['engine']:42s} {wall} {cpu} {speed}  {r['note']}")
        for name, value in figures["ratios"].items():
            print(f"{name:72s} {value if isinstance(value, str) else f'{value:.3f}'}")
    return figures


def _cell(value, width: int) -> str:
    return f"{value:{width}.4g}" if isinstance(value, float) else f"{'—':>{width}s}"


if __name__ == "__main__":
    main()

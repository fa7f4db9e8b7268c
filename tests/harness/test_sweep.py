"""Sweeps and Monte-Carlo on Dask, at small sizes: points, the two tasks, failures
that keep the other results, tables, the tolerance study and the command line."""

from __future__ import annotations

import numpy as np
import pytest

from servofmu.harness import load_system, run
from servofmu.harness.sweep import (
    Choice,
    ModelTask,
    Normal,
    SystemTask,
    Uniform,
    cross,
    grid_points,
    local_cluster,
    run_sweep,
    sample_points,
)
from servofmu.parameters.bearing import default_parameters, pair_from_parameters
from servofmu.physics.bearing import BearingModel

BASE = default_parameters("yu2017_gimbal")


@pytest.fixture(scope="module")
def client():
    """Two single-threaded worker processes, as `servofmu sweep` starts them."""
    from dask.distributed import Client

    with local_cluster(2) as cluster, Client(cluster) as c:
        yield c


def test_points_grid_sample_and_cross():
    grid = grid_points({"temperature": [250.0, 300.0], "speed": [0.1, 0.2, 0.3]})
    assert len(grid) == 6 and grid[1] == {"temperature": 250.0, "speed": 0.2}
    draws = sample_points(
        {"shim": Uniform(1e-6, 2e-6), "k": Normal(5.0, 0.0), "m": Choice(("a", "b"))}, 50, 7
    )
    assert [d["sample"] for d in draws] == list(range(50))
    assert all(1e-6 <= d["shim"] <= 2e-6 and d["k"] == 5.0 and d["m"] in "ab" for d in draws)
    assert draws == sample_points(
        {"shim": Uniform(1e-6, 2e-6), "k": Normal(5.0, 0.0), "m": Choice(("a", "b"))}, 50, 7
    )  # reproducible from the seed
    both = cross(draws[:3], grid)
    assert len(both) == 18 and both[7] == {**draws[1], **grid[1]}
    with pytest.raises(ValueError, match=r"high = 1\.0 must be ≥ low = 2\.0"):
        sample_points({"x": Uniform(2.0, 1.0)}, 3)
    with pytest.raises(ValueError, match="grid axis 'x' has no values"):
        grid_points({"x": []})


def test_model_task_matches_the_bearing_model_and_isolates_bad_points():
    task = ModelTask(BASE, ("running_torque", "preload", "overloaded"))
    points = [
        {"temperature": 253.15, "speed": 0.2},
        {"temperature": 273.15, "speed": 0.1, "axial_load": 20.0},
        {"temperature": 273.15, "radial_load": 30.0},  # the scalar (Jones) path
        {"temperature": 273.15, "mounting": "nowhere"},  # a bad parameter
        {"temperature": -5.0},  # a bad input, in a group with good ones
    ]
    rows = task(points)
    model = BearingModel(pair_from_parameters(BASE))
    assert rows[0]["running_torque"] == pytest.approx(model.evaluate(253.15, 0.2).running_torque)
    exact = model.load(273.15, 20.0)
    assert rows[1]["preload"] == pytest.approx(float(exact.preload), rel=1e-9)
    assert rows[2]["running_torque"] > 0 and "error" not in rows[2]
    assert "mounting" in rows[3]["error"] and rows[3]["mounting"] == "nowhere"
    assert "temperature" in rows[4]["error"]
    with pytest.raises(ValueError, match="'tempreature' is neither"):
        task.check([{"tempreature": 300.0}])


@pytest.mark.slow
def test_sweep_on_worker_processes_keeps_results_around_failures(client, tmp_path):
    points = grid_points({"temperature": [233.15, 293.15, 333.15], "shim": [2e-5, 3e-5]})
    # every value is valid alone; the 6205's 52 mm ring does not fit the gimbal's 36 mm boss
    points.append({"temperature": 293.15, "bearing": "6205"})
    res = run_sweep(ModelTask(BASE, ("running_torque",)), points, client=client, progress=False)
    assert res.workers == 2 and len(res.rows) == 7
    assert [r["temperature"] for r in res.rows] == [p["temperature"] for p in points]
    (bad,) = res.failed
    assert bad["bearing"] == "6205" and "housing_outer_diameter" in bad["error"]
    expected = ModelTask(BASE, ("running_torque",))(points[:6])
    assert [r["running_torque"] for r in res.rows[:6]] == [r["running_torque"] for r in expected]
    import csv

    with res.write(tmp_path / "t.csv").open(newline="") as fh:
        table = list(csv.DictReader(fh))
    assert len(table) == 7 and table[6]["error"] == bad["error"]  # quoted: it has commas
    assert float(table[0]["running_torque [N.m]"]) == pytest.approx(
        res.rows[0]["running_torque"], rel=1e-11
    )
    assert list(table[0])[:4] == ["run", "temperature [K]", "shim [m]", "running_torque [N.m]"]
    import pyarrow.parquet as pq

    parquet = pq.read_table(res.write(tmp_path / "t.parquet"))
    back = parquet.to_pylist()
    assert back[6]["error"] == bad["error"] and back[0]["run"] == 0
    assert parquet.schema.field("running_torque").metadata == {b"unit": b"N.m"}


def test_system_sweep_instantiates_fmus_in_the_workers(client, fmus):
    ssp = fmus["BearingFriction"].parent / "seeker_gimbal.ssp"
    task = SystemTask(ssp.read_bytes(), ("motor.current", "bearing.running_torque"), stop=0.2)
    points = grid_points({"bearing.temperature": [253.15, 293.15, 1000.0]})
    with pytest.raises(ValueError, match=r"sweep point 2 .*temperature = 1000\.0 is outside"):
        run_sweep(task, points, client=client, chunk_size=1, progress=False)  # before submitting
    # in range alone, but a 5 mm ball does not fit between the 71803's 17 mm bore and 26 mm
    # outside: the FMU refuses the geometry at initialization
    points[2] = {"bearing.temperature": 293.15, "bearing.ball_diameter": 5e-3}
    res = run_sweep(task, points, client=client, chunk_size=1, progress=False)
    assert "HarnessError" in res.rows[2]["error"] and "ball_diameter" in res.rows[2]["error"]
    system = load_system(ssp)
    try:
        direct = run(system, parameters=points[0], stop=0.2, record=list(task.record))
    finally:
        system.close()
    assert res.rows[0]["motor.current"] == direct["motor.current"][-1]  # bit for bit
    assert res.rows[1]["bearing.running_torque"] < res.rows[0]["bearing.running_torque"]
    with pytest.raises(Exception, match="no component 'motr'"):
        run_sweep(task, [{"motr.inertia": 1.0}], client=client, progress=False)


class _Exploding:
    """A task whose whole chunk fails (as when a worker dies)."""

    def check(self, points):
        pass

    def __call__(self, points):
        if any(p["x"] == 2 for p in points):
            raise RuntimeError("worker lost")
        return [dict(p, y=2 * p["x"]) for p in points]


def test_a_failed_chunk_marks_its_points_and_keeps_the_rest():
    from dask.distributed import Client, LocalCluster

    with LocalCluster(n_workers=1, processes=False, dashboard_address=":0") as c, Client(c) as cl:
        res = run_sweep(
            _Exploding(), grid_points({"x": [0, 1, 2, 3]}), client=cl, chunk_size=1, progress=False
        )
    assert [r.get("y") for r in res.rows] == [0, 2, None, 6]
    assert res.rows[2]["x"] == 2 and "worker lost" in res.rows[2]["error"]


@pytest.mark.slow
def test_tolerance_study(tmp_path):
    from servofmu.harness.tolerance import TEMPS_C, run, tolerance_points

    points = tolerance_points("yu2017_gimbal", 200, seed=5)
    fits = np.array([p["outer_interference"] for p in points])
    shims = np.array([p["shim"] for p in points])
    # bands: ring OD 5 µm and bore 9 µm around the drawn 12 µm; washer ±2 µm around 30 µm
    assert fits.min() >= 12e-6 - 7e-6 - 1e-12 and fits.max() <= 12e-6 + 7e-6 + 1e-12
    assert abs(fits.mean() - 12e-6) < 0.5e-6 and np.ptp(fits) > 8e-6
    assert shims.min() >= 28e-6 - 1e-12 and shims.max() <= 32e-6 + 1e-12
    result = run(tmp_path, samples=40, seed=5, workers=1, progress=False)
    rows = {r["temperature [degC]"]: r for r in result.rows}
    assert len(rows) == len(TEMPS_C) and result.summary["failed runs"] == 0
    # the default yoke mounting: never overloaded; the washer's preload is lost when warm
    # (above about 35 °C for the nominal parts) whatever the tolerances, and held when cold
    assert all(r["P(overloaded)"] == 0.0 for r in result.rows)
    assert rows[60.0]["P(unloaded)"] == 1.0 and rows[-40.0]["P(unloaded)"] == 0.0
    for r in result.rows:
        assert r["p5 [N.mm]"] <= r["median [N.mm]"] <= r["p95 [N.mm]"]
        for flag in ("overloaded", "unloaded"):
            low, high = r[f"P({flag}) low (95%)"], r[f"P({flag}) high (95%)"]
            assert low <= r[f"P({flag})"] <= high + 1e-12
    # the tolerances matter, if less than in a rigid frame: the compliant yoke absorbs part of
    # a fit or washer deviation (8 % between p5 and p95 at 0 °C)
    assert rows[0.0]["p95 [N.mm]"] > 1.05 * rows[0.0]["p5 [N.mm]"]
    assert {f.suffix for f in result.files} == {".csv", ".png"}


@pytest.mark.slow
def test_cli_sweep_and_montecarlo(tmp_path, capsys):
    from servofmu.cli import main

    out = tmp_path / "s.csv"
    rc = main(
        [
            "sweep",
            "model",
            "--grid",
            "temperature=253.15:293.15:3",
            "--sample",
            "shim=uniform:2.8e-5:3.2e-5",
            "--samples",
            "2",
            "--record",
            "running_torque",
            "--workers",
            "1",
            "--out",
            str(out),
        ]
    )
    assert rc == 0 and "6 runs on 1 worker(s)" in capsys.readouterr().out
    header = out.read_text().splitlines()[0]
    assert header == "run,sample,shim [m],temperature [K],running_torque [N.m],error"
    assert main(["sweep", "model", "--grid", "temperatur=300", "--out", str(out)]) == 2
    assert "'temperatur' is neither" in capsys.readouterr().err
    rc = main(["montecarlo", "--samples", "5", "--workers", "1", "--out", str(tmp_path / "mc")])
    assert rc == 0 and "P(overloaded)" in capsys.readouterr().out


GIMBAL = ["seeker_gimbal", "--grid", "motor.inertia=1e-5"]


@pytest.mark.parametrize(
    "args, message",
    [
        (["model", "--grid", "temperature=1e9"], "temperature = 1000000000.0 is outside the valid"),
        (["model", "--grid", "shim=2e-5,0.5"], "sweep point 1 (shim=0.5): shim = 0.5 is outside"),
        (["model", "--sample", "shim=normal:3e-5:1e-3", "--samples", "50"], "shim = 0.00133"),
        (["model", "--grid", "bearing=71804"], "bearing = 71804.0 is not one of"),
        (["model", "--grid", "lubricant=honey"], "lubricant = 'honey' is not one of"),
        (["model", "--grid", "speed=abc"], "speed = 'abc' is not a finite number"),
        (["model", "--grid", "temperature=300", "--record", "torque"], "record 'torque' is not"),
        (["model", "--grid", "temperature=300", "--workers", "0"], "--workers: '0' must be ≥ 1"),
        (["model", "--grid", "temperature=300", "--chunk", "0"], "--chunk: '0' must be ≥ 1"),
        (["model", "--grid", "temperature=300", "--samples", "0"], "--samples: '0' must be ≥ 1"),
        (["model", "--grid", "temperature=300", "--out", "x.xlsx"], "'x.xlsx': a sweep table"),
        (["model", "--grid", "temperature=300", "--tail", "1"], "--tail: '1' must lie in [0, 1)"),
        (
            ["seeker_gimbal", "--grid", "bearing.temperature=1000", "--record", "motor.current"],
            "parameter bearing.temperature = 1000.0 is outside the valid range [173.15, 473.15] K",
        ),
        (
            ["seeker_gimbal", "--grid", "motor.speed=3", "--record", "motor.current"],
            "parameter motor.speed: it is an output",
        ),
        (
            [*GIMBAL, "--record", "motor.nothing"],
            "record 'motor.nothing': DCMotor.fmu has no variable 'nothing'",
        ),
        (
            [*GIMBAL, "--record", "motor.voltage"],
            "record 'motor.voltage': it is an input",
        ),
        (
            [*GIMBAL, "--record", "motor.speed", "--stop", "0.1", "--step", "0.3"],
            "step = 0.3 s is longer than the run",
        ),
    ],
)
def test_cli_sweep_refuses_bad_arguments_before_submitting(
    fmus, tmp_path, capsys, monkeypatch, args, message
):
    from servofmu.build import fmu as build_fmu
    from servofmu.cli import main
    from servofmu.harness import sweep

    monkeypatch.setattr(build_fmu, "DEFAULT_OUT", fmus["BearingFriction"].parent)

    def no_cluster(*a, **k):
        raise AssertionError("a cluster was started")

    monkeypatch.setattr(sweep, "local_cluster", no_cluster)
    out = tmp_path / "s.csv"
    try:
        rc = main(["sweep", *args, *([] if "--out" in args else ["--out", str(out)])])
    except SystemExit as exc:  # argparse's own checks
        rc = exc.code
    err = capsys.readouterr().err
    assert rc == 2 and message in err, err
    assert len(err.strip().splitlines()) == 1 and not out.exists()


def test_ctrl_c_keeps_the_finished_rows_of_a_sweep(client, monkeypatch):
    import dask.distributed

    real = dask.distributed.as_completed

    def interrupted_after_one(futures):
        for i, fut in enumerate(real(futures)):
            if i == 1:
                raise KeyboardInterrupt  # what Ctrl-C raises in the waiting main thread
            yield fut

    monkeypatch.setattr(dask.distributed, "as_completed", interrupted_after_one)
    points = grid_points({"temperature": [233.15, 253.15, 273.15, 293.15]})
    res = run_sweep(ModelTask(BASE, ("running_torque",)), points, client=client, chunk_size=1)
    assert res.interrupted
    done = [r for r in res.rows if "error" not in r]
    assert len(done) == 1 and done[0]["running_torque"] > 0
    assert [r["error"] for r in res.rows if "error" in r] == ["interrupted"] * 3

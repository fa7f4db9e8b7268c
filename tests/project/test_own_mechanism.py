"""A user's own mechanism end to end (examples/my_gimbal_catalog.toml: a 7002-size pair with
a PAO grease in a 7075 yoke, spring preload): its build, its systems and scenarios give the
library's numbers for that pair and not Yu's; a calibration on data made from it with known
coefficients recovers them, and the rebuilt FMU uses them; the mechanism's build folder is
refreshed when its catalogue changes and another mechanism's build is never overwritten."""

from __future__ import annotations

import csv
import json
import math
import shutil
import tomllib
import zipfile
from pathlib import Path

import numpy as np
import pytest
from fmu_helpers import Fmu

from servofmu.build.mechanism import open_mechanism
from servofmu.cli import main
from servofmu.physics.bearing import BearingModel, BearingPair
from servofmu.physics.kernels.units import DEG, NMM, celsius_to_kelvin

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "my_gimbal_catalog.toml"
SPEED = 10.0 * DEG  # rad/s: the speed of the gimbal's speed loop in the scenario
TEMPS_C = (-40.0, 20.0)


def _library(temperature_c: float, speed: float = SPEED, catalogues=(EXAMPLE,), **changes):
    """The library's outputs of a mechanism's pair at one temperature [°C] and speed."""
    with open_mechanism([str(c) for c in catalogues]) as m:  # none: Yu's gimbal
        pair = BearingPair.from_catalog(m.mounting, m.lubricant)
    if changes:
        import dataclasses

        pair = dataclasses.replace(
            pair, coefficients=dataclasses.replace(pair.coefficients, **changes)
        )
    return BearingModel(pair).evaluate(celsius_to_kelvin(temperature_c), speed)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    """A working folder of the user's: the example catalogue as my.toml; commands run there."""
    path = tmp_path_factory.mktemp("user")
    shutil.copyfile(EXAMPLE, path / "my.toml")
    with pytest.MonkeyPatch.context() as mp:
        mp.chdir(path)
        yield path


@pytest.fixture(scope="module")
def built(folder):
    assert main(["build", "--catalog", "my.toml"]) == 0
    return folder / "build" / "my_gimbal"


def _rows(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


@pytest.mark.slow
def test_the_build_of_the_users_gimbal_binds_it(built):
    assert sorted(p.name for p in built.glob("*.ssp")) == [
        "seeker_gimbal.ssp",
        "seeker_gimbal_chamber.ssp",
        "seeker_gimbal_position.ssp",
    ]
    with zipfile.ZipFile(built / "BearingFriction.fmu") as zf:
        info = json.loads(zf.read("resources/servofmu_build.json"))
    assert info["mechanism"]["key"] == "my_gimbal" and info["start"]["bore"] == 0.015
    with zipfile.ZipFile(built / "seeker_gimbal.ssp") as zf:
        bearing = zf.read("bearing.ssv").decode()
        names = zf.namelist()
    assert '<ssv:Parameter name="bore"><ssv:Real value="0.015"/>' in bearing
    assert '"preload_method" description="spring"' in bearing
    # Yu's own mountings and interferences are left out; the temperature variants stay
    assert "variants/rigid.ssv" not in names and "variants/interference_0006.ssv" not in names
    assert "variants/cold.ssv" in names and "variants/grease_g1074.ssv" in names
    doc = (zipfile.ZipFile(built / "BearingFriction.fmu").read("documentation/index.html")).decode()
    defaults = doc.split("<h2>Defaults of this build</h2>")[1].split("<h2>")[0]
    assert "my_gimbal" in defaults and "uncalibrated" in defaults and "Yu" not in defaults


def test_friction_vs_temperature_gives_the_librarys_numbers_for_the_users_pair(built, folder):
    out = folder / "out" / "fvt"
    args = ["scenario", "friction_vs_temperature", "--catalog", "my.toml", "--coarse"]
    assert main([*args, "--out", str(out)]) == 0
    rows = _rows(out / "friction_vs_temperature.csv")
    for t_c in TEMPS_C:
        row = next(
            r for r in rows if float(r["temperature [degC]"]) == t_c and r["direction"] == "forward"
        )
        library = _library(t_c)
        yu = _library(t_c, catalogues=())
        model = float(row["model [N.mm]"]) * NMM
        measured = float(row["measured k_t*i [N.mm]"]) * NMM
        # the bearing in the loop is the user's pair: the library's torque and preload
        assert model == pytest.approx(library.running_torque, rel=1e-4), t_c
        assert float(row["preload [N]"]) == pytest.approx(library.preload, rel=1e-6), t_c
        # k_t·i is that torque plus the motor's viscous damping (b·ω = 0.0017 N·mm)
        assert measured == pytest.approx(library.running_torque + 1.7e-6, rel=5e-3), t_c
        # and not Yu's 71803 (3.17 N·mm at −40 °C, 0.30 at +20 °C)
        assert abs(model / yu.running_torque - 1.0) > 0.1, (t_c, model, yu.running_torque)
    models = _rows(out / "friction_models.csv")
    assert "Yu 2017 [N.mm]" not in models[0]  # Yu's measurement belongs to his gimbal
    assert not (out / "mountings.csv").exists()  # nor do his mountings


def test_a_system_run_on_the_users_gimbal_gives_the_librarys_numbers(built, folder):
    for variant, t_c in (("cold", -40.0), (None, 20.0)):  # the variant: −40 °C; else 20 °C
        out = folder / "out" / f"run_{variant}"
        args = ["run", "seeker_gimbal", "--catalog", "my.toml", "--stop", "1.5", "--out", str(out)]
        args += ["--parameters", variant] if variant else []
        record = ["bearing.running_torque", "bearing.preload", "motor.speed"]
        assert main([*args, *(a for r in record for a in ("--record", r))]) == 0
        with open(out / "results.csv", newline="") as fh:
            last = list(csv.reader(fh))[-1]
        _, torque, preload, speed = (float(x) for x in last)
        library = _library(t_c, speed)
        assert torque == pytest.approx(library.running_torque, rel=1e-9)
        assert preload == pytest.approx(library.preload, rel=1e-9)
        assert speed == pytest.approx(SPEED, rel=1e-3)


@pytest.mark.slow
def test_a_calibration_on_the_users_pair_recovers_its_coefficients_and_the_rebuild_uses_them(
    built, folder
):
    from servofmu.calibration.synthetic import synthesise, write_measurements

    truth = {"palmgren_s0": 2.2, "sliding_friction": 0.07}
    with open_mechanism([str(EXAMPLE)]) as m:
        params = m.parameters() | truth
    temps = [celsius_to_kelvin(t) for t in (-40, -20, 0, 20, 40, 60)]
    data = synthesise(params, temps, [5 * DEG, 20 * DEG], noise=0.03, seed=7)
    write_measurements(data, folder / "measured.csv", "synthetic: my_gimbal, s0 2.2, mu 0.07")
    assert main(["calibrate", "--catalog", "my.toml", "measured.csv", "--out", "cal"]) == 0
    calibrated = tomllib.loads((folder / "cal" / "calibrated.toml").read_text())
    entry = calibrated["coefficients"]["my_gimbal"]
    for name, value in truth.items():
        fitted = entry[name]
        assert fitted["kind"] == "calibrated" and "measured.csv" in fitted["ref"]
        # within 2 standard errors of the truth (95 % for a well-posed fit)
        assert abs(fitted["value"] - value) <= 2.0 * fitted["standard_error"], (name, fitted)
        assert 0 < fitted["standard_error"] < 0.1 * value
    assert entry["hysteresis_loss"]["kind"] == "assumed"  # not fitted: as it was
    record = entry["calibrated_on"]
    assert record["points"] == len(data) and record["data"] == "measured.csv"
    import hashlib

    assert record["sha256"] == hashlib.sha256((folder / "measured.csv").read_bytes()).hexdigest()

    # the next build with the calibration uses it: start values, documentation, the systems
    args = ["build", "--catalog", "my.toml", "--catalog", "cal/calibrated.toml"]
    assert main(args) == 0
    fmu_path = built / "BearingFriction.fmu"
    with zipfile.ZipFile(fmu_path) as zf:
        info = json.loads(zf.read("resources/servofmu_build.json"))
        doc = zf.read("documentation/index.html").decode()
    for name in truth:
        assert info["start"][name] == entry[name]["value"]
    assert len(info["mechanism"]["catalogues"]) == 2 and "calibrated by the user" in doc
    fmu = Fmu(fmu_path, "calibrated").init()
    fitted = {n: entry[n]["value"] for n in truth}
    for t_c in TEMPS_C:
        fmu.set(temperature=celsius_to_kelvin(t_c), speed=SPEED)
        fmu.slave.doStep(0.0, 1e-3)
        library = _library(t_c, **fitted)
        assert fmu.get("running_torque") == pytest.approx(library.running_torque, rel=1e-9)
        assert fmu.get("running_torque") != pytest.approx(_library(t_c).running_torque, rel=1e-3)
    fmu.close()
    with zipfile.ZipFile(built / "seeker_gimbal.ssp") as zf:
        bearing = zf.read("bearing.ssv").decode()
    s0 = entry["palmgren_s0"]["value"]
    assert f'<ssv:Parameter name="palmgren_s0"><ssv:Real value="{s0!r}"/>' in bearing


def test_the_mechanisms_build_is_refreshed_and_another_is_never_overwritten(folder, capsys):
    from servofmu.build.fmu import build_info

    # a mechanism's folder holding another mechanism's FMUs is refused, with what to do
    other = folder / "build" / "other"
    other.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(other / "BearingFriction.fmu", "w") as zf:
        zf.writestr("resources/servofmu_build.json", json.dumps({"mechanism": {"key": "x"}}))
    assert main(["build", "--catalog", "my.toml", "--out", str(other)]) == 2
    err = capsys.readouterr().err
    assert "holds the FMUs of x, not of my_gimbal" in err and "will not overwrite" in err
    assert build_info(other / "BearingFriction.fmu") == {"mechanism": {"key": "x"}}
    # a typo in a catalogue key: one line, a hint, nothing built
    assert main(["run", "seeker_gimbal", "--catalog", "my.toml", "--mounting", "my_gimbl"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "(did you mean 'my_gimbal'?)" in err


def test_a_library_temperature_that_looks_like_celsius_gets_a_hint():
    pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    model = BearingModel(pair)
    for value, kelvin in ((20.0, "293.15"), (-40.0, "233.15")):
        with pytest.raises(ValueError) as err:
            model.evaluate(value, 0.17)
        text = str(err.value)
        assert "[173.15, 473.15] K" in text and f"looks like °C: {kelvin} K" in text, text
    with pytest.raises(ValueError, match=r"temperature = 500.0 K is outside .*473.15\] K$"):
        model.evaluate(500.0, 0.17)  # no hint: 500 °C is outside too
    with pytest.raises(ValueError, match=r"looks like °C: 253\.15 K"):
        model.curves(np.array([253.15, -20.0]), 0.17)
    assert math.isfinite(model.evaluate(173.15, 0.17).running_torque)

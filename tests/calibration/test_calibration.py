"""Calibration from measured friction torque: recovery of known coefficients from
synthetic data within their standard errors, identifiability warnings, bad data, the .ssv
parameter set in the FMU, and the command line."""

from __future__ import annotations

import json

import numpy as np
import pytest

from servofmu.calibration import (
    DataError,
    calibrate,
    read_measurements,
    running_torque,
    write_ssv,
)
from servofmu.calibration.synthetic import synthesise, write_measurements
from servofmu.parameters.bearing import default_parameters
from servofmu.physics.kernels.units import DEG, celsius_to_kelvin

TEMPS = celsius_to_kelvin(np.arange(-40.0, 61.0, 10.0))
PRINTED = default_parameters("yu2017_gimbal_printed")
TRUTH = dict(PRINTED, palmgren_s0=0.8, sliding_friction=0.1)


def test_recovers_s0_and_mu_within_their_standard_errors():
    data = synthesise(TRUTH, TEMPS, [5 * DEG, 20 * DEG], noise=0.03, seed=11)
    cal = calibrate(data, PRINTED, ["palmgren_s0", "sliding_friction"])
    truth = np.array([0.8, 0.1])
    assert np.all(cal.standard_error < 0.05 * truth)  # tight enough to mean something
    assert np.all(np.abs(cal.estimate - truth) < 3.0 * cal.standard_error)
    assert cal.warnings == []  # two speeds: s0 is identifiable
    assert cal.rms == pytest.approx(0.03, rel=0.35)  # the residuals are the noise


@pytest.mark.slow
def test_standard_errors_are_calibrated_over_many_noise_draws():
    # with honest standard errors about 95 % of the estimates fall within 2 SE of the truth
    inside = 0
    for seed in range(20):
        data = synthesise(TRUTH, TEMPS[::2], [5 * DEG, 20 * DEG], noise=0.03, seed=seed)
        cal = calibrate(data, PRINTED, ["palmgren_s0", "sliding_friction"])
        inside += int(np.all(np.abs(cal.estimate - [0.8, 0.1]) < 2.0 * cal.standard_error))
    assert inside >= 15  # 2 SE on two parameters: expected about 18 of 20


def test_recovers_a_compliant_preload_loop():
    stated = default_parameters("yu2017_gimbal")
    truth = dict(stated, loop_stiffness=2.0e7)  # a compliant yoke
    temps = celsius_to_kelvin(np.arange(-40.0, 31.0, 10.0))  # the loop closes below 35 °C
    data = synthesise(truth, temps, [5 * DEG, 20 * DEG], noise=0.02, seed=3)
    cal = calibrate(data, stated, ["sliding_friction", "loop_stiffness"])
    k, se = cal.estimate[1], cal.standard_error[1]
    assert se < 0.2 * k and abs(k - 2.0e7) < 3.0 * se
    assert abs(cal.estimate[0] - stated["sliding_friction"]) < 3.0 * cal.standard_error[0]


def test_warns_that_s0_and_the_speed_are_not_separately_identifiable(tmp_path):
    data = synthesise(TRUTH, TEMPS, [10 * DEG], seed=1)
    path = write_measurements(data, tmp_path / "one_speed.csv", speed=False)
    cal = calibrate(read_measurements(path), PRINTED, ["palmgren_s0"], speed=10 * DEG)
    (warning,) = cal.warnings
    assert "s0·n^(2/3)" in warning and "10 °/s (assumed)" in warning
    with_column = calibrate(data, PRINTED, ["palmgren_s0"])  # one speed, but measured
    assert "the only one in the data" in with_column.warnings[0]


def test_warns_when_two_coefficients_scale_the_same_torque():
    # hysteresis (∝ α_r) and spin (∝ μ) torque both follow the ball loads; only the change of
    # preload and contact angle with temperature shifts their ratio. Over 10…30 °C it hardly
    # changes, and the data cannot part the two coefficients (over −40…60 °C they can)
    data = synthesise(
        TRUTH,
        celsius_to_kelvin(np.linspace(10.0, 30.0, 9)),
        [5 * DEG, 20 * DEG],
        noise=0.02,
        seed=5,
    )
    fixed_s0 = dict(PRINTED, palmgren_s0=0.8)
    cal = calibrate(data, fixed_s0, ["hysteresis_loss", "sliding_friction"])
    text = " ".join(cal.warnings)
    assert "hysteresis_loss and sliding_friction are correlated -0.99" in text
    wide = calibrate(
        synthesise(TRUTH, TEMPS, [5 * DEG, 20 * DEG], noise=0.02, seed=5),
        fixed_s0,
        ["hysteresis_loss", "sliding_friction"],
    )
    assert wide.warnings == [] and abs(wide.correlation[0, 1]) < 0.99


def test_warns_when_a_coefficient_has_no_effect_on_the_data():
    # stated reading: above 35 °C the preload loop is open, so its stiffness changes nothing
    stated = default_parameters("yu2017_gimbal")
    temps = celsius_to_kelvin(np.array([40.0, 45.0, 50.0, 55.0, 60.0]))
    data = synthesise(stated, temps, [5 * DEG, 20 * DEG], seed=2)
    cal = calibrate(data, stated, ["palmgren_s0", "loop_stiffness"])
    assert any("loop_stiffness is not identifiable" in w for w in cal.warnings)


def test_running_torque_is_the_model_of_the_fmu_parameters():
    from servofmu.parameters.bearing import pair_from_parameters
    from servofmu.physics.bearing import BearingModel

    model = BearingModel(pair_from_parameters(TRUTH))
    t, w = celsius_to_kelvin(-10.0), 7.0 * DEG
    expected = model.evaluate(t, w).running_torque
    assert running_torque(TRUTH, np.array([t]), np.array([w]))[0] == pytest.approx(expected)


def test_fitted_ssv_gives_the_same_torque_in_the_fmu(fmus, tmp_path):
    from fmu_helpers import Fmu

    from servofmu.build.xmlsafe import parse, validate
    from servofmu.harness.system import _read_parameter_set

    data = synthesise(TRUTH, TEMPS, [5 * DEG, 20 * DEG], seed=4)
    cal = calibrate(data, PRINTED, ["palmgren_s0", "sliding_friction"])
    ssv = write_ssv(cal.parameters, tmp_path / "calibrated.ssv")
    validate(parse(ssv.read_bytes(), str(ssv)), "ssv", str(ssv))  # SSP 1.0 schema
    values = {k: v for k, (_, v) in _read_parameter_set(ssv.read_bytes(), str(ssv)).items()}
    fmu = Fmu(fmus["BearingFriction"])
    try:
        fmu.init(**values, temperature=float(data.temperature[3]), speed=float(cal.speed[3]))
        assert fmu.get("running_torque") == pytest.approx(cal.model[3], rel=1e-9)
        assert fmu.get("palmgren_s0") == cal.estimate[0]
    finally:
        fmu.close()
    variant = write_ssv(cal.parameters, tmp_path / "v.ssv", component="bearing")
    assert 'name="bearing.sliding_friction"' in variant.read_text()


def test_fmu_defaults_are_the_yu_gimbal_parameter_set():
    from servofmu.fmus.BearingFriction import BearingFriction
    from servofmu.parameters.bearing import PARAMETER_NAMES, parameter

    defaults = default_parameters("yu2017_gimbal")
    for v in BearingFriction.VARIABLES:
        if v.name not in PARAMETER_NAMES:  # the FMU's own (temperature_mode): not the pair's
            continue
        if v.type == "Enumeration":  # the item whose catalogue key is the default
            assert v.start == parameter(v.name).item(defaults[v.name]), v.name
        elif v.causality == "parameter":
            assert v.start == defaults[v.name], v.name


GOOD = "temperature [degC],torque [N.mm],speed [deg/s],direction\n"


@pytest.mark.parametrize(
    "text, message",
    [
        ("temp [degC],torque [N.mm]\n20,1\n", "no 'temperature' column"),
        ("temperature [F],torque [N.mm]\n20,1\n", "unit 'F' is not one of ['degC', 'K']"),
        ("temperature [degC],torque\n20,1\n", "unit None is not one of ['N.mm', 'N.m']"),
        (GOOD + "20,1.2,10,forward\n40,abc,10,forward\n", "line 3, column 'torque [N.mm]'"),
        (GOOD + "20,,10,forward\n", "line 2, column 'torque [N.mm]': empty"),
        (GOOD + "-150,1,10,forward\n", "line 2, column 'temperature [degC]': -150 degC"),
        (GOOD + "20,0,10,forward\n", "line 2, column 'torque [N.mm]': a torque of 0"),
        (GOOD + "20,1,10,sideways\n", "line 2, column 'direction': 'sideways'"),
        (GOOD + "20,1,10\n", "line 2: 3 cells for 4 columns"),
        (GOOD + "20,nan,10,forward\n", "'nan' is not finite"),
        (GOOD, "a header but no data rows"),
        ("# only a comment\n", "no header and no data"),
    ],
)
def test_bad_data_names_line_and_column(tmp_path, text, message):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(DataError) as info:
        read_measurements(path)
    assert message in str(info.value)


def test_too_few_points_and_bad_requests(tmp_path):
    path = tmp_path / "two.csv"
    path.write_text(GOOD + "20,1.0,10,forward\n40,0.5,10,forward\n")
    data = read_measurements(path)
    with pytest.raises(ValueError, match="2 points for 2 unknowns"):
        calibrate(data, PRINTED, ["palmgren_s0", "sliding_friction"])
    with pytest.raises(ValueError, match="unknown = 'mu' is not one of"):
        calibrate(data, PRINTED, ["mu"])
    no_speed = tmp_path / "no_speed.csv"
    no_speed.write_text("temperature [K],torque [N.m]\n293.15,0.001\n313.15,0.002\n")
    with pytest.raises(ValueError, match="no speed column"):
        calibrate(read_measurements(no_speed), PRINTED, ["sliding_friction"])


def test_cli_report_plot_and_ssv(tmp_path, capsys):
    from pathlib import Path

    from servofmu.cli import main

    example = Path(__file__).resolve().parents[2] / "examples/data/gimbal_friction_synthetic.csv"
    out = tmp_path / "cal"
    args = ["calibrate", str(example), "--mounting", "yu2017_gimbal_printed"]
    assert main([*args, "--speed", "10 deg/s", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "palmgren_s0" in text and "WARNING" in text and "s0·n^(2/3)" in text
    for name in ("report.txt", "residuals.csv", "calibration.png", "calibrated.ssv"):
        assert (out / name).stat().st_size > 0
    assert main([*args, "--speed", "10 deg/s", "--json", "--out", str(out)]) == 0
    result = json.loads(capsys.readouterr().out)
    s0 = result["unknowns"][0]
    assert abs(s0["estimate"] - 0.8) < 3 * s0["standard_error"]  # the example's truth
    assert main([*args, "--out", str(out)]) == 2  # no speed column and no --speed
    assert "no speed column" in capsys.readouterr().err
    assert main([*args, "--speed", "10 furlongs", "--out", str(out)]) == 2
    assert "'10 furlongs'" in capsys.readouterr().err


# ------------------------------------------------------------------------ a fit that failed
EXAMPLE = "examples/data/gimbal_friction_synthetic.csv"
README_ARGS = ["--speed", "10 deg/s", "--fit", "palmgren_s0,sliding_friction"]


def _example():
    from pathlib import Path

    return str(Path(__file__).resolve().parents[2] / EXAMPLE)


def test_readme_example_without_mounting_names_the_choices_and_exits_2(tmp_path, capsys):
    from servofmu.cli import main

    out = tmp_path / "cal"
    assert main(["calibrate", _example(), *README_ARGS, "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "--mounting is required" in err and len(err.strip().splitlines()) == 1
    for key in ("yu2017_gimbal", "yu2017_gimbal_printed", "yu2017_gimbal_rigid"):
        assert f"'{key}'" in err
    assert not out.exists()  # refused before the data were read


def test_a_mounting_the_data_cannot_fit_is_no_calibration(tmp_path, capsys):
    """The example's data (printed reading, s0 = 0.8, μ = 0.1) against the yoke mounting:
    the model misses them by far more than their scatter; exit 1, no parameter set, unless
    --allow-poor-fit."""
    from servofmu.cli import main

    out = tmp_path / "cal"
    args = ["calibrate", _example(), *README_ARGS, "--mounting", "yu2017_gimbal"]
    assert main([*args, "--out", str(out)]) == 1
    captured = capsys.readouterr()
    assert "servofmu: calibration failed: the model misses the data by more than their scatter" in (
        captured.err
    )
    assert captured.out.startswith("POOR FIT: this is not a calibration")
    assert not (out / "calibrated.ssv").exists()
    assert (out / "report.txt").read_text().startswith("POOR FIT")
    assert (out / "calibration.png").is_file() and (out / "residuals.csv").is_file()
    assert main([*args, "--out", str(out), "--allow-poor-fit", "--json"]) == 0
    captured = capsys.readouterr()
    result = json.loads(captured.out)
    assert result["poor_fit"] and "misses the data" in result["problems"][0]
    assert result["lack_of_fit_p"] < 1e-3 and result["deviation_from_means"] > 0.5
    assert "warning: poor fit accepted" in captured.err and (out / "calibrated.ssv").is_file()
    # the mounting the data were made with fits them within 10 % of the truth
    assert main([*args[:-1], "yu2017_gimbal_printed", "--json", "--out", str(out)]) == 0
    result = json.loads(capsys.readouterr().out)
    assert not result["poor_fit"] and result["lack_of_fit_p"] > 0.01
    for u, truth in zip(result["unknowns"], (0.8, 0.1), strict=True):
        assert abs(u["estimate"] / truth - 1.0) < 0.10


def test_estimates_at_a_bound_are_refused_and_keep_their_sensitivity():
    """The rigid reading over-predicts the torque by up to 10×: the fit drives s0 and μ to
    0. Least squares' own Jacobian has zero columns there; the finite differences inside
    the bounds do not, so no 'no effect on the data' is claimed."""
    data = read_measurements(_example())
    rigid = default_parameters("yu2017_gimbal_rigid")
    cal = calibrate(data, rigid, ["palmgren_s0", "sliding_friction"], speed=10 * DEG)
    assert cal.poor
    assert any("palmgren_s0 = " in p and "sits at its lower bound 0" in p for p in cal.problems)
    assert any("sliding_friction" in p and "lower bound" in p for p in cal.problems)
    assert not [w for w in cal.warnings if "does not change the model" in w]
    assert np.all(np.isfinite(cal.standard_error)) and np.all(cal.standard_error > 0)


def test_model_jacobian_stays_inside_the_bounds_and_is_right_at_a_bound():
    from servofmu.calibration.fit import model_jacobian
    from servofmu.parameters.bearing import pair_from_parameters
    from servofmu.physics.bearing import operating_outputs

    temps, w = TEMPS[::3], np.full(TEMPS[::3].shape, 10 * DEG)
    seen = []

    def model(x):  # s0 (scale 1) and μ (scale 0.1), as fit.py scales them
        seen.append(np.array(x))
        return running_torque(dict(PRINTED, palmgren_s0=x[0], sliding_friction=0.1 * x[1]),
                              temps, w)  # fmt: skip

    lower, upper = np.array([0.0, 0.0]), np.array([20.0, 5.0])
    jac = model_jacobian(model, np.array([0.0, 1.0]), lower, upper)  # s0 at its lower bound
    seen = np.array(seen)
    assert np.all(seen >= lower) and np.all(seen <= upper)
    # Yu eq 8: the viscous torque is s0 times its value at s0 = 1, the rest does not depend
    # on s0: d(torque)/d(s0) is the viscous torque at s0 = 1
    out = operating_outputs(pair_from_parameters(dict(PRINTED, palmgren_s0=1.0)), temps, w)
    assert jac[:, 0] == pytest.approx(np.asarray(out.viscous_torque), rel=1e-6)
    assert np.all(jac[:, 1] > 0)  # μ scales spin and sliding


def test_fit_on_group_statistics_is_the_fit_on_every_point(tmp_path):
    """Repeated rows are reduced to per-group statistics: the optimum and the rms residual
    are those of least squares on every point (scipy on the per-point residuals, from the
    estimate, does not move)."""
    from scipy.optimize import least_squares

    runs = [  # four runs of the same test: every point measured four times
        read_measurements(write_measurements(
            synthesise(TRUTH, TEMPS[::2], [5 * DEG, 20 * DEG], noise=0.03, seed=s),
            tmp_path / f"run{s}.csv",
        ))
        for s in range(4)
    ]  # fmt: skip
    long = tmp_path / "long.csv"
    texts = [(tmp_path / f"run{s}.csv").read_text() for s in range(4)]
    long.write_text(texts[0] + "".join(x.split("\n", 1)[1] for x in texts[1:]))  # one header
    data = read_measurements(long)
    assert len(data) == 4 * runs[0].groups and data.groups == runs[0].groups
    cal = calibrate(data, PRINTED, ["palmgren_s0", "sliding_friction"])
    t, w, y = (np.concatenate([getattr(r, a) for r in runs]) for a in ("temperature", "speed",
                                                                        "torque"))  # fmt: skip

    def per_point(x):
        return running_torque(dict(PRINTED, palmgren_s0=x[0], sliding_friction=x[1]), t, w) / y - 1

    r = per_point(cal.estimate)
    assert np.sqrt(np.mean(r**2)) == pytest.approx(cal.rms, rel=1e-9)
    direct = least_squares(per_point, cal.estimate, x_scale=[1.0, 0.1], method="trf")
    assert direct.x == pytest.approx(cal.estimate, rel=1e-5)


def test_long_file_is_read_in_blocks_into_exact_group_statistics(tmp_path, monkeypatch):
    from servofmu.calibration import measurements

    rng = np.random.default_rng(3)
    temps = rng.choice([-40.0, 0.0, 40.0], 400)
    torque = rng.uniform(0.5, 3.0, 400)
    direction = rng.choice(["forward", " Reverse"], 400)
    lines = ["# made for the test", "temperature [degC],torque [N.mm],direction"]
    for i in range(400):
        lines.append(f"{temps[i]:g},{torque[i]:.17g},{direction[i]}")
        if i == 150:
            lines += ["", "# a comment in the middle"]
    path = tmp_path / "blocks.csv"
    path.write_text("\n".join(lines) + "\n")
    monkeypatch.setattr(measurements, "BLOCK_CHARS", 333)  # a few lines per block
    data = read_measurements(path)
    assert len(data) == 400 and data.groups == 6
    for g in range(data.groups):
        same = np.char.lower(np.char.strip(direction)) == data.direction[g]
        pick = (temps + 273.15 == data.temperature[g]) & same
        sel = torque[pick] * 1e-3
        assert data.count[g] == pick.sum()
        assert data.torque[g] == pytest.approx(sel.mean(), rel=1e-12)
        assert data.torque_sd[g] == pytest.approx(sel.std(ddof=1), rel=1e-9)
        assert data.inverse_mean[g] == pytest.approx(np.mean(1 / sel), rel=1e-12)
        assert data.lines[g] == 3 + int(np.flatnonzero(pick)[0])  # its first line
    # the first problem of the file is named, whichever block it falls in
    path.write_text("\n".join([*lines[:300], "20,1,sideways", "20,oops,forward"]) + "\n")
    with pytest.raises(DataError, match="line 301, column 'direction': 'sideways'"):
        read_measurements(path)


def test_without_repeated_points_a_fit_is_judged_against_an_assumed_scatter():
    one_direction = synthesise(
        TRUTH, TEMPS, [10 * DEG], noise=0.02, seed=4, directions=("forward",)
    )
    good = calibrate(one_direction, PRINTED, ["palmgren_s0", "sliding_friction"])
    assert not good.poor and good.scatter is None
    assert any("repeat no operating point" in w for w in good.warnings)
    yoke = default_parameters("yu2017_gimbal")
    bad = calibrate(one_direction, yoke, ["palmgren_s0", "sliding_friction"])
    assert bad.poor and "rms relative residual" in bad.problems[0]


@pytest.mark.parametrize(
    "args, message",
    [
        (["--fit", "mu"], "--fit mu: 'mu' is not one of"),
        (["--speed", "10 furlongs"], "speed = '10 furlongs': write a number and one of the units"),
        (["--speed", "nan deg/s"], "--speed 'nan deg/s': the test speed must be finite and ≥ 0"),
        (["--speed", "-5 deg/s"], "--speed '-5 deg/s': the test speed must be finite and ≥ 0"),
        (["--set", "shim=abc"], "--set 'shim=abc': shim takes a number"),
        (["--set", "nope=1"], "--set 'nope=1': write NAME=VALUE"),
        (["--lubricant", "honey"], "lubricant = 'honey' is not in the catalogue's lubricants"),
        (["--bearing", "9999"], "bearing key = '9999' is not one of"),
        (["--mounting", "nowhere"], "mounting = 'nowhere' is not in the catalogue's mountings"),
        (["--residual", "cubic"], "argument --residual: invalid choice: 'cubic'"),
    ],
)
def test_cli_calibrate_refuses_bad_arguments_before_reading_the_data(
    tmp_path, capsys, monkeypatch, args, message
):
    from servofmu import calibration
    from servofmu.cli import main

    def unread(path):
        raise AssertionError("the data were read")

    monkeypatch.setattr(calibration, "read_measurements", unread)
    base = ["calibrate", _example(), "--mounting", "yu2017_gimbal_printed", "--speed", "10 deg/s"]
    out = tmp_path / "cal"
    try:
        rc = main([*base, *args, "--out", str(out)])
    except SystemExit as exc:  # argparse's own checks
        rc = exc.code
    err = capsys.readouterr().err
    assert rc == 2 and message in err, err
    assert len(err.strip().splitlines()) == 1 and not out.exists()

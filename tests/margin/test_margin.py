"""The motorisation margin (servofmu.margin, ``servofmu margin``): ECSS-E-ST-33-01C 4.7.5.3
by hand, the bearing's torques as the library gives them, bad inputs refused before any work,
and the documented example and the example user catalogue run as stated."""

from __future__ import annotations

import csv
import math
import textwrap
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from servofmu.cli import main
from servofmu.margin import (
    CATEGORIES,
    MarginResult,
    ecss_factors,
    example_input,
    load_inputs,
    minimum_actuation_torque,
    run,
    torque_margin,
)
from servofmu.margin.inputs import Resistance
from servofmu.margin.standard import motorisation_ratio
from servofmu.margin.study import margin_terms, row_flags, row_verdict
from servofmu.parameters.bearing import pair_from_parameters
from servofmu.physics.bearing import BearingModel, operating_outputs

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CATALOG = EXAMPLES / "my_gimbal_catalog.toml"


# ------------------------------------------------------------------------------ the standard
def test_the_factors_are_table_4_2_of_the_2009_edition():
    """Typed from ECSS-E-ST-33-01C (6 March 2009) Table 4-2 (theoretical, measured) and the
    equation of 4.7.5.3.1 d (2 × the sum, 1,25 × T_D)."""
    f = ecss_factors()
    table = {
        "inertia": (1.1, 1.1),
        "spring": (1.2, 1.2),
        "motor_magnetic_losses": (1.5, 1.2),
        "friction": (3.0, 1.5),
        "hysteresis": (3.0, 1.5),
        "harness": (3.0, 1.5),
        "adhesion": (3.0, 3.0),
    }
    assert set(table) == set(CATEGORIES)
    for category, (theoretical, measured) in table.items():
        assert f.factor(category, "theoretical") == theoretical
        assert f.factor(category, "measured") == measured
        assert "Table 4-2" in f.sources[category] and "2009" in f.sources[category]
    assert (f.motorisation, f.inertial_resistance) == (2.0, 1.25)


def test_a_case_computed_by_hand():
    """Every category once, by hand from T_min = 2·Σ u·R + 1.25·T_D + T_L [mN·m]:

    friction 2.0 (theoretical, bearing)  × 3   = 6.0
    hysteresis 0.5 (theoretical, bearing) × 3  = 1.5
    spring 1.0 (measured)          × 1.2       = 1.2
    harness 0.5 (measured)         × 1.5       = 0.75
    motor magnetic losses 0.2 (theoretical) × 1.5 = 0.3
    adhesion 0.1 (measured)        × 3         = 0.3
    inertia 0.4 (theoretical)      × 1.1       = 0.44
                                      Σ u·R    = 10.49
    T_min = 2 × 10.49 + 1.25 × 0.8 + 0.5 = 20.98 + 1.0 + 0.5 = 22.48
    margin = 25 / 22.48 − 1 = 0.112099644128...
    """
    mN = 1.0e-3
    torques = [
        Resistance("spring", "spring", "measured", (1.0 * mN,)),
        Resistance("harness", "harness", "measured", (0.5 * mN,)),
        Resistance("cogging", "motor_magnetic_losses", "theoretical", (0.2 * mN,)),
        Resistance("stiction", "adhesion", "measured", (0.1 * mN,)),
        Resistance("spin-up", "inertia", "theoretical", (0.4 * mN,)),
        Resistance("slew", "inertial_resistance", "theoretical", (0.8 * mN,)),
        Resistance("output", "deliverable", "theoretical", (0.5 * mN,)),
    ]
    bearing = {"friction": 2.0 * mN, "hysteresis": 0.5 * mN}
    t = margin_terms(bearing, "theoretical", torques, [293.15], "run", "as given", [25.0 * mN],
                     ecss_factors())  # fmt: skip
    expected = {"friction": 6.0, "hysteresis": 1.5, "spring": 1.2, "harness": 0.75,
                "motor_magnetic_losses": 0.3, "adhesion": 0.3, "inertia": 0.44}  # fmt: skip
    for category, value in expected.items():
        assert t[f"factored_{category}"][0] == pytest.approx(value * mN, rel=1e-12)
    assert t["factored_sum"][0] == pytest.approx(10.49 * mN, rel=1e-12)
    assert t["minimum"][0] == pytest.approx(22.48 * mN, rel=1e-12)
    assert t["margin"][0] == pytest.approx(0.112099644128, rel=1e-10)
    # MR = (25 − 1.25 × 0.8 − 0.5) / 10.49 = 23.5 / 10.49 ≥ 2 (met: margin ≥ 0 with it)
    assert t["ecss_ratio"][0] == pytest.approx(23.5 / 10.49, rel=1e-12)
    # the same through the two public functions
    assert minimum_actuation_torque(10.49 * mN, 0.8 * mN, 0.5 * mN, ecss_factors()) == (
        pytest.approx(22.48 * mN, rel=1e-12)
    )
    assert torque_margin(25.0 * mN, 22.48 * mN) == pytest.approx(0.112099644128, rel=1e-10)
    # a torque that acts at start only does not count when running
    only_start = [replace(r, cases=("start",)) for r in torques]
    t = margin_terms(bearing, "measured", only_start, [293.15], "run", "as given", [25.0 * mN],
                     ecss_factors())  # fmt: skip
    assert t["minimum"][0] == pytest.approx(2 * (1.5 * 2.0 + 1.5 * 0.5) * mN, rel=1e-12)


def test_the_margin_is_nan_without_a_state_and_infinite_without_resistance():
    assert math.isnan(torque_margin(1.0, math.nan))
    assert torque_margin(1.0, 0.0) == math.inf
    assert motorisation_ratio(1.0, 0.0, 0.0, 0.0, ecss_factors()) == math.inf


def test_the_ratio_and_the_margin_meet_the_rule_at_the_same_point():
    """T = T_min exactly: margin 0 and MR = m = 2; 10 % more T: margin +0.1 while MR grows by
    0.1·T/Σu·R (the ratio leaves T_D and T_L out)."""
    f = ecss_factors()
    total, t_d, t_l = 10.0e-3, 2.0e-3, 1.0e-3
    t_min = minimum_actuation_torque(total, t_d, t_l, f)
    assert torque_margin(t_min, t_min) == 0.0
    assert motorisation_ratio(t_min, total, t_d, t_l, f) == pytest.approx(2.0, rel=1e-12)
    assert torque_margin(1.1 * t_min, t_min) == pytest.approx(0.1, rel=1e-12)
    assert motorisation_ratio(1.1 * t_min, total, t_d, t_l, f) == pytest.approx(
        2.0 + 0.1 * t_min / total, rel=1e-12
    )


@pytest.mark.parametrize(
    "row, flags, verdict",
    [
        ({"case": "run", "margin": 0.5}, "", "met"),
        ({"case": "run", "margin": -0.01}, "", "not met"),
        ({"case": "run", "margin": math.nan}, "", "not met"),  # no bearing state
        ({"case": "run", "margin": 0.5, "locked": True}, "L", "not verified"),
        ({"case": "run", "margin": 0.5, "overloaded": True}, "O", "not verified"),
        ({"case": "run", "margin": 0.5, "outside_lubricant_range": True}, "X", "not verified"),
        ({"case": "run", "margin": 0.5, "table_extrapolated": True}, "T", "not verified"),
        ({"case": "start", "margin": 0.5, "breakaway_lower_bound": True}, "B", "not verified"),
        ({"case": "run", "margin": 0.5, "breakaway_lower_bound": True}, "", "met"),
        ({"case": "run", "margin": 0.5, "unloaded": True, "max_contact_pressure": 0.0}, "U",
         "not verified"),
        ({"case": "run", "margin": 0.5, "unloaded": True, "max_contact_pressure": 8e8}, "",
         "met"),  # one bearing carries the external load: the torque model holds
        ({"case": "run", "margin": -0.5, "locked": True}, "L", "not met"),
    ],
)  # fmt: skip
def test_a_row_is_met_not_met_or_not_verified(row, flags, verdict):
    assert row_flags(row) == flags
    assert row_verdict(row["margin"], row_flags(row)) == verdict


def test_the_study_exits_by_its_rows_verdicts():
    inputs = load_inputs(example_input())
    result = MarginResult(inputs)
    result.steady = [{"verdict": "met"}, {"verdict": "met"}]
    assert (result.verdict, result.exit_code, result.passed) == ("met", 0, True)
    result.draws = [{"verdict": "not verified"}]
    assert (result.verdict, result.exit_code, result.passed) == ("not verified", 3, False)
    result.transient = [{"verdict": "not met"}]
    assert (result.verdict, result.exit_code) == ("not met", 1)


# ------------------------------------------------------------------------------ the bearing
@pytest.fixture(scope="module")
def example_result():
    inputs = replace(load_inputs(example_input()), tolerances=None, transient=None)
    return run(inputs)


def test_the_friction_terms_are_the_librarys_breakaway_and_running_torques(example_result):
    inputs = example_result.inputs
    temps = np.asarray(inputs.temperatures)
    for life, params in inputs.parameters.items():
        pair = pair_from_parameters(params)
        exact = operating_outputs(pair, temps, inputs.speed)
        per_step = BearingModel(pair)
        for case, library in (("start", exact.breakaway_torque),
                              ("run", exact.running_torque)):  # fmt: skip
            rows = [r for r in example_result.steady if r["life"] == life and r["case"] == case]
            assert [r["temperature"] for r in rows] == list(temps)
            got = np.array([r["bearing_torque"] for r in rows])
            assert np.array_equal(got, library)  # the same call, the same numbers
            hyst = np.array([r["hysteresis_torque"] for r in rows])
            assert np.array_equal(hyst, exact.hysteresis_torque)
            for r in rows:  # the FMU's per-step path agrees too
                out = per_step.evaluate(r["temperature"], inputs.speed)
                ref = out.breakaway_torque if case == "start" else out.running_torque
                assert r["bearing_torque"] == pytest.approx(ref, rel=1e-9)
            # the bearing is all of F_R and H_Y here (theoretical: × 3 each)
            factored = np.array([r["factored_friction"] + r["factored_hysteresis"] for r in rows])
            np.testing.assert_allclose(factored, 3.0 * library, rtol=1e-12)


def test_the_worst_case_is_the_smallest_margin_and_eol_is_worse(example_result):
    _, worst = example_result.worst
    margins = [r["margin"] for r in example_result.steady]
    assert worst["margin"] == min(margins)
    bol = {(r["case"], r["temperature"]): r["margin"] for r in example_result.steady
           if r["life"] == "BOL"}  # fmt: skip
    eol = {(r["case"], r["temperature"]): r["margin"] for r in example_result.steady
           if r["life"] == "EOL"}  # fmt: skip
    assert all(eol[k] < bol[k] for k in bol)  # more drag, more harness, less k_t


# ------------------------------------------------------------------------------ the command
SMALL = """
title = "test mechanism"
[mechanism]
mounting = "yu2017_gimbal"
friction_basis = "theoretical"
speed = { value = 10, unit = "deg/s" }
[temperatures]
values = { values = [-20, 20], unit = "degC" }
[motor]
torque_constant = { value = 0.05, unit = "N.m/A", kind = "assumed", ref = "test" }
current_limit = { value = 0.5, unit = "A" }
[[torques]]
name = "harness"
category = "harness"
basis = "measured"
torque = { value = 2.0, unit = "N.mm" }
[[torques]]
name = "slew"
category = "inertial_resistance"
inertia = { value = 1.0e-4, unit = "kg.m2" }
acceleration = { value = 10, unit = "rad/s2" }
[[torques]]
name = "output"
category = "deliverable"
torque = { value = 0.5, unit = "N.mm" }
"""


def _write(tmp_path, text=SMALL, name="m.toml") -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


def _csv(path) -> list[dict]:
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def test_the_command_applies_the_rule_to_the_librarys_torques(tmp_path, capsys):
    """By hand per row, from the CSV's own bearing torque [N·mm]:
    T_min = 2 × (3 × bearing + 1.5 × 2.0) + 1.25 × (1e-4 kg·m² × 10 rad/s² = 1.0) + 0.5,
    T = 0.05 N·m/A × 0.5 A = 25 N·mm."""
    out = tmp_path / "out"
    code = main(["margin", str(_write(tmp_path)), "--out", str(out)])
    text = capsys.readouterr().out
    rows = _csv(out / "margin.csv")
    assert len(rows) == 4  # 2 temperatures × (start, run), one life
    for r in rows:
        bearing = float(r["bearing torque [N.mm]"])
        t_min = 2 * (3 * bearing + 1.5 * 2.0) + 1.25 * 1.0 + 0.5
        assert float(r["minimum actuation torque T_min [N.mm]"]) == pytest.approx(t_min, 1e-9)
        assert float(r["actuation torque T [N.mm]"]) == pytest.approx(25.0, rel=1e-12)
        assert float(r["margin T/T_min-1 [-]"]) == pytest.approx(25.0 / t_min - 1, rel=1e-9)
        mr = (25.0 - 1.25 * 1.0 - 0.5) / (3 * bearing + 1.5 * 2.0)
        assert float(r[MR]) == pytest.approx(mr, rel=1e-9)
        # Krytox 143AA has no published starting torque: every start row is not verified
        assert (r["verdict"], r["flags"]) == (
            ("not verified", "B") if r["case"] == "start" else ("met", "")
        )
    # the bearing torque is the library's, at these temperatures and the speed
    params = load_inputs(_write(tmp_path)).parameters["as given"]
    lib = operating_outputs(pair_from_parameters(params), np.array([253.15, 293.15]),
                            np.deg2rad(10.0))  # fmt: skip
    start = [float(r["bearing torque [N.mm]"]) for r in rows if r["case"] == "start"]
    run_ = [float(r["bearing torque [N.mm]"]) for r in rows if r["case"] == "run"]
    np.testing.assert_allclose(start, lib.breakaway_torque * 1e3, rtol=1e-9)
    np.testing.assert_allclose(run_, lib.running_torque * 1e3, rtol=1e-9)
    assert code == 3 and "NOT VERIFIED" in text
    assert "worst: margin" in text and (out / "margin.png").stat().st_size > 10000


def _bad(text: str, old: str, new: str) -> str:
    assert old in text
    return text.replace(old, new)


BAD = {
    "negative torque": (
        _bad(SMALL, "value = 2.0, unit", "value = -2.0, unit"),
        "torques[0].torque",
    ),
    "unknown category": (_bad(SMALL, 'category = "harness"', 'category = "frction"'),
                         "torques[0].category"),
    "factor below 1": (
        SMALL + '[factors.uncertainty.harness]\nmeasured = 0.9\nsource = "a project letter"\n',
        "factors.uncertainty.harness.measured",
    ),
    "motorisation below 1": (
        SMALL + '[factors.motorisation]\nvalue = 0.5\nsource = "a project letter"\n',
        "factors.motorisation.value",
    ),
    "override without a source": (SMALL + "[factors.uncertainty.friction]\ntheoretical = 2.5\n",
                                  "factors.uncertainty.friction.source"),
    "unknown unit": (_bad(SMALL, 'unit = "N.mm" }\n[[torques]]\nname = "slew"',
                          'unit = "furlong" }\n[[torques]]\nname = "slew"'),
                     "torques[0].torque.unit"),
    "missing basis": (_bad(SMALL, 'basis = "measured"\n', ""), "torques[0].basis"),
    "negative current": (_bad(SMALL, "value = 0.5, unit = \"A\"", "value = -0.5, unit = \"A\""),
                         "motor.current_limit"),
    "unknown section": (SMALL + "[torque]\nname = 'x'\n", "unknown keys ['torque']"),
    "bad mechanism parameter": (
        _bad(SMALL, 'friction_basis = "theoretical"',
             'friction_basis = "theoretical"\nparameters = { no_such = 1.0 }'),
        "mechanism.parameters",
    ),
}  # fmt: skip


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_inputs_exit_2_naming_the_field_before_any_work(case, tmp_path, capsys):
    text, field = BAD[case]
    out = tmp_path / "out"
    assert main(["margin", str(_write(tmp_path, text)), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert field in err, err
    assert err.count("\n") == 1 and err.startswith("servofmu: error: ")
    assert not out.exists()  # nothing computed, nothing written


def test_an_unknown_mounting_or_catalogue_exits_2(tmp_path, capsys):
    path = _write(tmp_path)
    assert main(["margin", str(path), "--mounting", "no_such_gimbal", "--out", str(tmp_path)]) == 2
    assert "no_such_gimbal" in capsys.readouterr().err
    missing = tmp_path / "missing.toml"
    assert main(["margin", str(path), "--catalog", str(missing), "--out", str(tmp_path)]) == 2
    assert "missing.toml" in capsys.readouterr().err


def test_a_table_short_of_the_range_is_held_and_its_rows_not_verified(tmp_path, capsys):
    text = _bad(SMALL, 'torque = { value = 2.0, unit = "N.mm" }',
                'temperature = { values = [0, 60], unit = "degC" }\n'
                'torque = { values = [2, 1], unit = "N.mm" }')  # fmt: skip
    out = tmp_path / "out"
    assert main(["margin", str(_write(tmp_path, text)), "--out", str(out)]) == 3
    for r in _csv(out / "margin.csv"):
        cold = r["temperature [degC]"] == "-20"
        assert (r["table_extrapolated"] == "1") == cold
        assert ("T" in r["flags"]) == cold and r["verdict"] == (
            "not verified" if cold or r["case"] == "start" else "met"
        )
        harness = float(r["harness H_A factored [N.mm]"])
        assert harness == pytest.approx(1.5 * (2.0 if cold else 2.0 - 20 / 60), rel=1e-12)


def test_without_temperatures_the_mountings_operating_range_is_studied(tmp_path, capsys):
    text = SMALL.replace('[temperatures]\nvalues = { values = [-20, 20], unit = "degC" }\n', "")
    inputs = load_inputs(_write(tmp_path, text))
    # yu2017_gimbal declares Yu's chamber range, -40…60 °C: in steps of 10 K
    assert inputs.temperatures == pytest.approx([233.15 + 10 * k for k in range(11)])
    (note,) = [n for n in inputs.notes if "operating range mounting yu2017_gimbal declares" in n]
    assert note.count("Yu 2017 §3") == 1  # both ends cite the same test: cited once
    out = tmp_path / "out"
    assert main(["margin", str(_write(tmp_path, text)), "--mounting", "ning_space_shaft",
                 "--out", str(out)]) == 2  # fmt: skip
    err = capsys.readouterr().err
    assert "temperatures: missing" in err and "ning_space_shaft" in err and not out.exists()


def test_a_negative_margin_exits_1(tmp_path, capsys):
    text = _bad(SMALL, 'value = 0.5, unit = "A"', 'value = 0.05, unit = "A"')
    out = tmp_path / "out"
    assert main(["margin", str(_write(tmp_path, text)), "--out", str(out)]) == 1
    assert "NOT MET" in capsys.readouterr().out
    assert min(float(r["margin T/T_min-1 [-]"]) for r in _csv(out / "margin.csv")) < 0


def test_factors_of_another_standard_from_the_input_file(tmp_path, capsys):
    """A project's factors (e.g. another standard's): friction measured 2.0 instead of 1.5."""
    text = SMALL.replace('friction_basis = "theoretical"', 'friction_basis = "measured"')
    text += '[factors.uncertainty.friction]\nmeasured = 2.0\nsource = "project tailoring"\n'
    out = tmp_path / "out"
    main(["margin", str(_write(tmp_path, text)), "--out", str(out)])
    assert "project tailoring" in capsys.readouterr().out
    for r in _csv(out / "margin.csv"):
        bearing = float(r["bearing torque [N.mm]"])
        hyst = float(r["bearing hysteresis torque [N.mm]"])
        t_min = 2 * (2.0 * (bearing - hyst) + 1.5 * hyst + 1.5 * 2.0) + 1.25 * 1.0 + 0.5
        assert float(r["minimum actuation torque T_min [N.mm]"]) == pytest.approx(t_min, 1e-9)


# ------------------------------------------------------------------------------ the examples
MR = "ECSS ratio MR=(T-1.25T_D-T_L)/sum(u.R) [-]"


def _check_outputs(out: Path, text: str, code: int) -> None:
    """The table, the CSVs with units, the plot, and the exit code of a margin run: the
    verdicts of its rows (every CSV), each row's verdict from its margin and flags."""
    rows = _csv(out / "margin.csv")
    header = list(rows[0])
    assert "temperature [degC]" in header and "margin T/T_min-1 [-]" in header and MR in header
    flags = ("overloaded", "unloaded", "locked", "outside_lubricant_range",
             "breakaway_lower_bound", "table_extrapolated")  # fmt: skip
    assert set(flags) <= set(header)
    assert all("[" in h for h in header if h not in ("life", "case", "verdict", "flags", *flags))
    assert (out / "margin.png").stat().st_size > 20000
    for extra in ("margin_draws.csv", "margin_transient.csv"):
        if (out / extra).exists():
            rows += _csv(out / extra)
    for r in rows:
        margin = float(r["margin T/T_min-1 [-]"])
        expected = "not met" if not margin >= 0 else ("not verified" if r["flags"] else "met")
        assert r["verdict"] == expected, r
    verdicts = {r["verdict"] for r in rows}
    assert code == (1 if "not met" in verdicts else 3 if "not verified" in verdicts else 0)
    assert "life" in text and "T_min [N·mm]" in text and "worst: margin" in text


def test_without_arguments_it_runs_the_documented_example(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code = main(["margin"])
    text = capsys.readouterr().out
    out = tmp_path / "out" / "margin"
    _check_outputs(out, text, code)
    # every margin is positive, but Krytox 143AA has no published starting torque (every start
    # row B), the warm rows have lost their preload (U) and 27 draws lock at -40 °C (L)
    assert code == 3 and "NOT VERIFIED" in text
    assert "mechanism: yu2017_gimbal" in text and "ASSUMED" in text
    assert "Yu 2017 seeker gimbal" in text  # its own title
    rows = _csv(out / "margin.csv")
    assert min(float(r["margin T/T_min-1 [-]"]) for r in rows) > 0
    assert all("B" in r["flags"] for r in rows if r["case"] == "start")
    draws = _csv(out / "margin_draws.csv")
    assert len(draws) == 100 * 2 * 2 * 11
    cold = [r for r in draws if r["temperature [degC]"] == "-40" and r["case"] == "run"
            and r["life"] == "EOL"]  # fmt: skip
    assert sum(r["locked"] == "1" for r in cold) == 27
    worst = next(line for line in text.splitlines() if line.startswith("worst:"))
    assert "Monte-Carlo draw" in worst and "not verified" in worst and "L locked" in worst
    transient = _csv(out / "margin_transient.csv")
    assert {r["life"] for r in transient} == {"BOL", "EOL"}
    assert "housing temperature [degC]" in transient[0]


@pytest.mark.slow
def test_the_example_user_catalogue(tmp_path, capsys):
    out = tmp_path / "mine"
    code = main(["margin", "--catalog", str(CATALOG), "--out", str(out)])
    text = capsys.readouterr().out
    _check_outputs(out, text, code)
    assert "mechanism: my_gimbal" in text
    # the title and the temperatures are the mechanism's, not the input file's Yu gimbal
    assert "Yu 2017" not in text.split("input:")[0]
    assert "Example gimbal axis" in text.split("input:")[0]
    # the catalogue's own tolerance bands ([tolerances.my_gimbal]) are drawn
    draws = _csv(out / "margin_draws.csv")
    assert draws and "no tolerance bands" not in text
    # at -54 °C, the cold end of its declared range, the example grease's viscosity (known at
    # 40 and 100 °C only, extrapolated) leaves the running rows short: not met, exit 1
    assert code == 1 and "NOT MET" in text
    # the example grease is known at 40 and 100 °C only: every colder row is marked outside
    # the lubricant's data (its viscosity extrapolated), every row from 40 °C on is not
    rows = _csv(out / "margin.csv")
    temps = sorted({float(r["temperature [degC]"]) for r in rows})
    assert temps[0] == -54.0 and temps[-1] == 71.0  # its declared operating range
    for r in rows:
        outside = r["outside_lubricant_range"] == "1"
        assert outside == (float(r["temperature [degC]"]) < 40.0), r
        # the harness table of the input file covers -40…60 °C
        assert (r["table_extrapolated"] == "1") == (not -40 <= float(r["temperature [degC]"]) <= 60)


def test_a_row_at_minus_84_degc_is_not_met_or_not_verified(tmp_path, capsys):
    """The documented example with a row at −84 °C: Krytox 143AA's law extrapolated far below
    its data (X), the harness table held at its −40 °C value (T), the pair locked (L): the
    command says so and does not exit 0."""
    text = example_input().read_text()
    text = text.replace("# [temperatures]\n", "[temperatures]\n").replace(
        "# or: values = { values = [-84,", "values = { values = [-84,"
    )
    text = text.split("[tolerances]")[0]  # nominal parts only, no transient: quicker
    out = tmp_path / "out"
    code = main(["margin", str(_write(tmp_path, text)), "--out", str(out)])
    stdout = capsys.readouterr().out
    assert code in (1, 3) and "not verified" in stdout
    rows = [r for r in _csv(out / "margin.csv") if r["temperature [degC]"] == "-84"]
    assert len(rows) == 4
    for r in rows:
        assert r["verdict"] != "met" and {"X", "T"} <= set(r["flags"]), r


def test_a_torque_speed_curve_a_temperature_coefficient_and_drawn_bands(tmp_path):
    """The motor as a curve giving k_t·I at the speed: the same torques; a coefficient of
    −0.1 %/K about 20 °C: T(−20 °C) = 25 × (1 + 0.001 × 40) = 26 N·mm; bands drawn around the
    nominal interference stay in the band."""
    curve = SMALL.replace(
        'torque_constant = { value = 0.05, unit = "N.m/A", kind = "assumed", ref = "test" }\n'
        'current_limit = { value = 0.5, unit = "A" }',
        'torque_speed = { speed = { values = [0, 3], unit = "rad/s" }, '
        'torque = { values = [25, 25], unit = "N.mm" } }\n'
        'temperature_coefficient = { value = -0.1, unit = "%/K" }\n'
        'reference_temperature = { value = 20, unit = "degC" }',
    )
    curve += textwrap.dedent("""
        [tolerances]
        samples = 3
        seed = 7
        [tolerances.bands]
        outer_interference = { low = -2, high = 2, unit = "um", kind = "assumed", ref = "t" }
        """)
    assert curve != SMALL
    inputs = load_inputs(_write(tmp_path, curve))
    result = run(inputs)
    for r in result.steady:
        expected = 25.0 * (1.0 - 0.001 * (r["temperature"] - 293.15))
        assert r["available"] * 1e3 == pytest.approx(expected, rel=1e-12)
    nominal = inputs.parameters["as given"]["outer_interference"]
    drawn = {r["draw"]: r["outer_interference"] for r in result.draws}
    assert sorted(drawn) == [0, 1, 2]
    assert all(abs(v - nominal) <= 2e-6 + 1e-18 for v in drawn.values())
    assert len({round(v, 15) for v in drawn.values()}) == 3  # three different parts


def test_end_of_life_values_of_a_table_torque(tmp_path):
    text = _bad(
        SMALL,
        'torque = { value = 2.0, unit = "N.mm" }',
        'temperature = { values = [-40, 60], unit = "degC" }\n'
        'torque = { values = [3, 1], unit = "N.mm" }\n'
        'end_of_life = { values = [6, 2], unit = "N.mm" }',
    )
    text += '[end_of_life]\nsource = "test"\nscale = { palmgren_s0 = 1.0 }\n'
    result = run(load_inputs(_write(tmp_path, text)))
    rows = {(r["life"], r["case"], round(r["temperature"], 2)): r for r in result.steady}
    # at −20 °C the table gives 3 − 2 × 20/100 = 2.6 N·mm (BOL) and 6 − 4 × 0.2 = 5.2 (EOL);
    # harness measured: × 1.5
    bol = rows[("BOL", "run", 253.15)]["factored_harness"] * 1e3
    eol = rows[("EOL", "run", 253.15)]["factored_harness"] * 1e3
    assert (bol, eol) == (pytest.approx(1.5 * 2.6), pytest.approx(1.5 * 5.2))
    # the bearing is the same at both lives here (scale 1)
    assert (
        rows[("EOL", "run", 253.15)]["bearing_torque"]
        == (rows[("BOL", "run", 253.15)]["bearing_torque"])
    )


def test_a_point_without_a_bearing_state_is_nan_and_not_met(tmp_path, capsys, monkeypatch):
    """Where the bearing model finds no state (here made to at −20 °C), that point's margin is
    NaN, the report says why, and the command exits 1: a margin that cannot be shown is not
    met."""
    from servofmu.physics import bearing

    real = bearing.BearingModel.evaluate

    def evaluate(self, temperature, *args, **kwargs):
        if abs(float(temperature) - 253.15) < 1e-9:
            raise ValueError("no state here (test)")
        return real(self, temperature, *args, **kwargs)

    def exact(*args, **kwargs):
        raise ValueError("no state (test)")

    monkeypatch.setattr(bearing.BearingModel, "evaluate", evaluate)
    monkeypatch.setattr(bearing, "operating_outputs", exact)
    out = tmp_path / "out"
    assert main(["margin", str(_write(tmp_path)), "--out", str(out)]) == 1
    text = capsys.readouterr().out
    assert "no bearing state" in text and "NOT MET" in text
    rows = {(r["case"], r["temperature [degC]"]): r for r in _csv(out / "margin.csv")}
    assert rows[("run", "-20")]["margin T/T_min-1 [-]"] == "nan"
    assert float(rows[("run", "20")]["margin T/T_min-1 [-]"]) > -1.0

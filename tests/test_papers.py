import json

import pytest

from servofmu import cli
from servofmu.papers import report, run
from servofmu.papers.report import STATUSES


@pytest.fixture(scope="module")
def yu(tmp_path_factory):
    return run("yu2017", tmp_path_factory.mktemp("yu"))


@pytest.fixture(scope="module")
def ning(tmp_path_factory):
    return run("ning", tmp_path_factory.mktemp("ning"))


def rows(rep):
    return {r.id: r for r in rep.rows}


def test_report_format(yu, ning):
    for rep in (yu, ning):
        data = json.loads(rep.dumps())
        assert set(data) >= {"paper", "rows", "parameters"}
        for r in data["rows"]:
            assert set(r) == {
                "id",
                "quantity",
                "published",
                "computed",
                "unit",
                "status",
                "tolerance",
                "note",
            }
            assert r["status"] in STATUSES
        for p in data["parameters"]:
            assert set(p) == {"name", "value", "unit", "provenance"}
            assert p["provenance"].split(":")[0] in {
                "paper",
                "catalogue",
                "handbook",
                "assumed",
                "calibrated",
                "derived",
            } or p["name"] in {"bearing", "mounting"}


def test_every_not_reproduced_row_says_why(yu, ning):
    for rep in (yu, ning):
        for r in rep.rows:
            if r.status == "not-reproduced":
                assert len(r.note) > 20, r.id


def test_yu_calibrations_hit_their_points(yu):
    r = rows(yu)
    assert r["fig8.viscous_m40"].status == "calibrated"
    assert r["fig8.viscous_m40"].computed == pytest.approx(2.30, rel=1e-3)
    assert r["fig8.geometric_min.printed"].status == "calibrated"
    assert r["fig8.geometric_min.printed"].computed == pytest.approx(0.38, rel=1e-3)
    mu = next(p.value for p in yu.parameters if p.name.startswith("sliding_friction"))
    assert 0.01 < mu < 0.3  # a physical boundary-lubrication coefficient


def test_yu_known_gaps_are_reported_not_tuned(yu):
    r = rows(yu)
    # DESIGN §4: 0.87 / 3.17 / 72 % do not follow from the stated data with a rigid loop
    for rid in (
        "fig8.geometric_max.stated",
        "fig8.total_m40.stated",
        "fig8.viscous_share_m40.stated",
    ):
        assert r[rid].status == "not-reproduced"
    assert r["fig8.geometric_max.stated"].computed > 10 * 0.87
    assert "overloaded" in r["fig8.total_m40.stated"].note
    assert r["fig3.coupled"].status == "qualitative"
    assert r["fig4.locked"].status == "qualitative"


def test_yu_files_written(yu):
    names = {p.split("/")[-1] for p in yu.files}
    for fig in ("fig3_clearance", "fig4_contact_angle", "fig6_preload", "fig7_geometric_torque"):
        assert {f"{fig}.csv", f"{fig}.png"} <= names
    assert "fig8_components_stated.png" in names


def test_ning_rates_are_predictions(ning):
    r = rows(ning)
    assert r["fig9a.inner_rate"].status == "reproduced"
    assert r["fig9a.outer_rate"].status == "reproduced"
    assert r["fig9b.hot"].status == "calibrated"
    assert r["fig11.cycle_max"].status == "not-reproduced"  # a reversible model cannot drift


def test_status_comes_from_the_comparison():
    assert report.compare("x", "q", 1.0, 1.04, "N", rel=0.05).status == "reproduced"
    assert report.compare("x", "q", 1.0, 1.06, "N", rel=0.05).status == "not-reproduced"
    assert report.compare("x", "q", 1.0, float("nan"), "N", rel=0.05).status == "not-reproduced"
    assert report.trend("x", "q", "up", False, "down").status == "not-reproduced"
    assert report.calibrated("x", "q", 2.3, 2.0, "N", "s0").status == "not-reproduced"


def test_cli_json(tmp_path, capsys):
    assert cli.main(["paper", "ning", "--json", "--out", str(tmp_path)]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["paper"] == "ning" and data["rows"]


def test_cli_rejects_unknown_paper(capsys):
    with pytest.raises(SystemExit):
        cli.main(["paper", "smith1999"])
    assert "invalid choice" in capsys.readouterr().err


@pytest.fixture(scope="module")
def liu(tmp_path_factory):
    return run("liu2014", tmp_path_factory.mktemp("liu"))


def test_liu_report(liu):
    r = rows(liu)
    for m in ("100", "200", "300"):
        assert r[f"table1.series.{m}"].status == "reproduced"
    assert (
        r["table1.F3.100"].status == "calibrated" and r["table1.K_rod.100"].status == "calibrated"
    )
    assert r["table1.F3.300"].status == "reproduced"  # eq 10–11 linear in M
    assert r["table1.K_rod.300"].status == "not-reproduced"  # eq 9–20 cannot stiffen
    assert r["extension.measured.100"].status == "calibrated"
    assert r["extension.measured.300"].computed > r["extension.measured.100"].computed
    names = {p.split("/")[-1] for p in liu.files}
    assert {
        "fig2_reduction_ratio.png",
        "stiffness_vs_load.csv",
        "stiffness_vs_temperature.png",
    } <= names


def test_coefficient_records_hold_the_code_calibration():
    # data/coefficients.toml (the FMU defaults) must equal what servofmu.papers.yu2017 fits
    from servofmu.papers import yu2017
    from servofmu.physics import catalog

    s0, mu = yu2017.calibrated_coefficients()
    record = catalog.coefficients("yu2017_gimbal")
    assert record.palmgren_s0 == pytest.approx(s0, rel=1e-8)
    assert record.sliding_friction == pytest.approx(mu, rel=1e-8)
    assert record.source("sliding_friction").startswith("calibrated")


def test_ning_spacer_record_holds_the_code_calibration():
    from servofmu.papers import ning
    from servofmu.physics import catalog

    loop = {m.name: m for m in catalog.mounting("ning_space_shaft").loop.members}
    spacer = ning.calibrate_spacer()
    assert loop["spacer"].length == pytest.approx(spacer, rel=1e-6)
    assert loop["shaft"].length == pytest.approx(loop["bearings"].length + spacer, rel=1e-6)

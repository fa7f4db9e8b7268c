"""The numeric parameter set of a bearing pair: every physical input is a number,
the model uses exactly these numbers, catalogue entries (built in or a user's) are presets of
them; consistency checks; arrangement and preload method; round trip and "another bearing"
through the FMU; user catalogues for the build."""

from __future__ import annotations

import dataclasses
import math
import re
from pathlib import Path

import pytest
from fmpy.validation import validate_fmu
from fmu_helpers import Fmu

from servofmu.build import catalogs
from servofmu.build.archive import read_member
from servofmu.build.xmlsafe import parse
from servofmu.parameters import catalog
from servofmu.parameters.bearing import (
    BEARING_FIELDS,
    PARAMETER_NAMES,
    PARAMETERS,
    default_parameters,
    default_sources,
    pair_from_parameters,
    parameter_problems,
    resolve,
)
from servofmu.physics.bearing import BearingModel, BearingPair
from servofmu.physics.contact.geometry import BallBearing
from servofmu.physics.pair.preload import LoopMember

EXAMPLE = Path(__file__).parents[2] / "examples" / "my_gimbal_catalog.toml"
OUTPUTS = ("running_torque", "breakaway_torque", "preload", "contact_angle", "axial_stiffness",
           "kinematic_viscosity", "radial_clearance", "max_contact_pressure")  # fmt: skip
# (temperature [K], speed [rad/s], axial load [N], radial load [N]) along a trajectory
POINTS = ((293.15, 0.17, 0.0, 0.0), (253.15, 0.17, 5.0, 0.0), (233.15, -0.3, 0.0, 0.0),
          (313.15, 0.5, 2.0, 3.0), (333.15, 0.05, 0.0, 0.0))  # fmt: skip
CATALOGUE_PAIRS = (
    ("yu2017_gimbal", "krytox_143aa"),
    ("yu2017_gimbal_rigid", "krytox_143aa"),
    ("yu2017_gimbal_printed", "krytox_143aa"),
    ("yu2017_gimbal_spring", "krytox_143aa"),
    ("ning_space_shaft", "mos2_film"),
    ("liu2014_screw_support", "mos2_film"),
)


def _outputs(model, point):
    out = model.evaluate(point[0], point[1], point[2], point[3])
    return [getattr(out, f) for f in OUTPUTS]


# ------------------------------------------------------------------------------ library
@pytest.mark.parametrize("mounting, lubricant", CATALOGUE_PAIRS)
def test_a_catalogue_pair_and_its_preset_numbers_are_the_same_model(mounting, lubricant):
    """The catalogue's records (papers, library) and the numbers they preset (FMU,
    calibration, sweeps) give bit-identical outputs: the numbers lose nothing."""
    records = BearingModel(BearingPair.from_catalog(mounting, lubricant))
    numbers = BearingModel(pair_from_parameters(default_parameters(mounting, lubricant=lubricant)))
    for point in POINTS:
        assert _outputs(numbers, point) == _outputs(records, point), point


def test_the_default_preset_holds_yus_published_numbers():
    """Independent of the code: Yu 2017 §2's 71803 and §2.1's materials, the washer, eq 18."""
    p, src = default_parameters(), default_sources()
    assert (p["bore"], p["outer_diameter"], p["width"], p["n_balls"]) == (
        pytest.approx(17e-3),
        pytest.approx(26e-3),
        pytest.approx(5e-3),
        15,
    )
    assert p["pitch_diameter"] == pytest.approx(0.5 * (19.1109e-3 + 23.8891e-3), rel=1e-12)
    assert p["nominal_contact_angle"] == pytest.approx(math.radians(15.0), rel=1e-12)
    # Dw from the grooves and 15°: (d_o − d_i)/(2 + 2·(f_i + f_o − 1)·(1 − cos α0))
    dw = (23.8891 - 19.1109) / (2 + 2 * 0.1 * (1 - math.cos(math.radians(15)))) * 1e-3
    assert p["ball_diameter"] == pytest.approx(dw, rel=1e-12)
    assert (p["ring_youngs_modulus"], p["housing_expansion"]) == (206e9, pytest.approx(21.7e-6))
    assert p["shim"] == pytest.approx(0.03e-3) and p["preload_method"] == "shim"
    nu40 = 10 ** (10 ** (9.597 - 3.773 * math.log10(313.15))) - 0.932  # Yu eq 18 by hand, cSt
    assert p["lubricant_viscosity_40"] == pytest.approx(nu40 * 1e-6, rel=1e-12)
    assert src["bore"].startswith("paper: Yu 2017") and src["arm_length"].startswith("assumed")
    assert set(p) == set(PARAMETER_NAMES) == set(src)


def test_resolve_applies_presets_first_then_numbers():
    base = default_parameters()
    p = resolve(base, {"bearing": "7002C", "lubricant": "mos2_film", "n_balls": 10})
    assert p["bore"] == catalog.bearing("7002C").bore and p["n_balls"] == 10
    assert p["lubrication"] == "solid" and p["palmgren_s0"] == 0.0
    assert p["shim"] == base["shim"]  # the mounting's numbers stay
    ning = resolve(base, {"mounting": "ning_space_shaft", "assembly_preload": 150.0})
    assert ning["arrangement"] == "back_to_back" and ning["assembly_preload"] == 150.0
    with pytest.raises(ValueError, match=r"\['colour'\] are neither parameters nor presets"):
        resolve(base, {"colour": "red"})


@pytest.mark.parametrize(
    "changes, message",
    [
        ({"ball_diameter": 4.6e-3}, "ball_diameter = 0.0046 m must be below (outer_diameter"),
        ({"n_balls": 30}, "(the balls must fit on the pitch circle)"),
        ({"outer_curvature": 0.5}, "outer_curvature = 0.5 must exceed 0.5"),
        ({"nominal_contact_angle": math.radians(50)}, "is outside 0…45° (0…0.7854 rad)"),
        ({"pitch_diameter": 16.9e-3}, "pitch_diameter = 0.0169 m must lie between bore = 0.017"),
        (
            {"lubricant_viscosity_100": 40e-6},
            "lubricant_viscosity_100 = 4e-05 m2/s must be below lubricant_viscosity_40",
        ),
        (  # found by the FMI fuzzing: the message named Walther's nu2, not the parameter
            {"lubricant_viscosity_100": 1e-8},
            "lubricant_viscosity_100 = 1e-08 m2/s with lubricant_walther_c",
        ),
        ({"grease_f0": 5.0, "lubrication": "solid"}, "grease_f0 = 5.0 (a grease term) needs"),
        ({"friction_model": "palmgren"}, "friction_model = 'palmgren' is not one of"),
        ({"preload_method": "spring"}, "preload_method = spring needs spring_stiffness > 0"),
        ({"preload_method": "force"}, "preload_method = force needs assembly_preload > 0 N"),
        ({"housing_outer_diameter": 20e-3}, "housing_outer_diameter = 0.02 m must exceed"),
        ({"n_balls": 15.5}, "n_balls = 15.5 must be an integer"),
        ({"arrangement": "side_by_side"}, "arrangement = 'side_by_side' is not one of"),
        ({"arrangement": "tandem"}, "arrangement = tandem needs preload_method = spring or"),
    ],
)
def test_an_inconsistent_set_is_refused_naming_its_values(changes, message):
    p = default_parameters() | changes
    with pytest.raises(ValueError) as exc:
        pair_from_parameters(p)
    assert message in str(exc.value)


def test_a_set_can_name_several_problems_at_once():
    p = default_parameters() | {"ball_diameter": 5e-3, "n_balls": 40, "preload_method": "spring"}
    found = parameter_problems(p)
    assert len(found) == 4, found  # the spring lacks its stiffness and its compression


def _preload(p, temperatures):
    return BearingModel(pair_from_parameters(p)).evaluate(temperatures, 0.1).preload


def test_arrangement_flips_the_shaft_and_housing_growth():
    """Face-to-face: a warmer shaft (longer) raises the preload, a warmer housing relieves it;
    back-to-back the other way round (physics/pair/preload.py ARRANGEMENTS). Rigid members loop, no
    fits, so only the axial terms act."""
    base = default_parameters("yu2017_gimbal_rigid") | {"outer_interference": 0.0}
    t0 = base["assembly_temperature"]
    warm_shaft = (t0, t0 + 10.0, t0, t0)  # housing, shaft, outer ring, inner ring [K]
    warm_housing = (t0 + 10.0, t0, t0, t0)
    df = base | {"arrangement": "face_to_face"}
    db = base | {"arrangement": "back_to_back"}
    p0 = _preload(df, t0)
    assert _preload(db, t0) == pytest.approx(p0, rel=1e-12)  # the same at assembly
    # (the shaft's radial growth, the same in both, raises both a little)
    assert _preload(df, warm_shaft) > 2.0 * p0 and _preload(db, warm_shaft) < 0.7 * p0
    assert _preload(df, warm_housing) < 0.5 * p0 and _preload(db, warm_housing) > 1.5 * p0


def test_yus_cold_aluminium_frame_loads_a_face_to_face_pair_and_relieves_a_back_to_back_one():
    base = default_parameters("yu2017_gimbal")
    cold = base["assembly_temperature"] - 40.0
    df, db = (base | {"arrangement": a} for a in ("face_to_face", "back_to_back"))
    assert _preload(df, cold) > 2.0 * _preload(df, base["assembly_temperature"])
    assert _preload(db, cold) < _preload(db, base["assembly_temperature"])


def test_preload_methods_agree_at_assembly_and_a_spring_follows_less():
    """The same preload at assembly by a shim, by a force (then rigid) and by a spring: shim
    and force are one loop (the shim derived from the force); the spring in series takes up
    the thermal mismatch and its preload moves far less."""
    base = default_parameters("yu2017_gimbal")
    t0, cold = base["assembly_temperature"], base["assembly_temperature"] - 40.0
    p0 = _preload(base, t0)
    force = base | {"preload_method": "force", "assembly_preload": p0}
    spring = base | {"preload_method": "spring", "spring_stiffness": 1e5,
                     "spring_compression": p0 / 1e5}  # fmt: skip
    assert _preload(force, t0) == pytest.approx(p0, rel=1e-9)
    assert _preload(force, cold) == pytest.approx(_preload(base, cold), rel=1e-9)
    assert _preload(spring, t0) == pytest.approx(p0, rel=1e-9)
    shim_rise = _preload(base, cold) - p0
    assert 0 < _preload(spring, cold) - p0 < 0.5 * shim_rise


# ------------------------------------------------------------------------------ FMUs
_7002 = {  # a 7002C-like pair, numbers typed from ISO 15 and a 3/16 in ball set (assumed)
    "bore": 15e-3,
    "outer_diameter": 32e-3,
    "width": 9e-3,
    "ball_diameter": 4.7625e-3,
    "n_balls": 10,
    "pitch_diameter": 23.5e-3,
    "nominal_contact_angle": math.radians(15.0),
    "inner_curvature": 0.52,
    "outer_curvature": 0.53,
}


def _run(fmu, points=POINTS):
    rows = []
    for t, w, fa, fr in points:
        fmu.set(temperature=t, speed=w, axial_load=fa, radial_load=fr)
        fmu.slave.doStep(0.0, 1e-3)
        rows.append([fmu.get(n) for n in OUTPUTS])
    return rows


def _fmu_values(fmu, values):
    """``values`` as the FMU takes them (choices by item name)."""
    return {k: v for k, v in values.items() if k in fmu.vr}


def test_another_bearing_set_only_through_parameters_gives_the_librarys_numbers(fmus):
    path = fmus["BearingFriction"]
    assert validate_fmu(str(path)) == []
    fmu = Fmu(path, "7002").init(**_7002)
    assert not [m for s, m in fmu.log if s >= 2], fmu.log  # no warning, discard or error
    got = _run(fmu)
    fmu.close()
    # the library, told the same numbers through its own records: the catalogue pair with a
    # BallBearing of these numbers and the loop's ring widths 2·B
    pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    bearing = BallBearing(key="7002-like", name="typed", **_7002,
                          ring_material=pair.bearing.ring_material,
                          ball_material=pair.bearing.ball_material)  # fmt: skip
    loop = pair.mounting.loop
    members = tuple(
        LoopMember(m.name, m.role, 2 * 9e-3, m.material, m.area) if m.name == "bearings" else m
        for m in loop.members
    )
    mounting = dataclasses.replace(pair.mounting, loop=dataclasses.replace(loop, members=members))
    library = BearingModel(dataclasses.replace(pair, bearing=bearing, mounting=mounting))
    expected = [_outputs(library, p) for p in POINTS]
    assert got == expected
    assert got[0][2] != _run(Fmu(path, "default").init(), POINTS[:1])[0][2]  # it is another


def test_bad_geometry_is_refused_with_a_message_and_no_step(fmus):
    fmu = Fmu(fmus["BearingFriction"], "bad")
    with pytest.raises(Exception, match="fmi2ExitInitializationMode failed with status 3"):
        fmu.init(**(_7002 | {"ball_diameter": 9e-3}))
    assert any("ball_diameter = 0.009 m must be below (outer_diameter − bore)/2 = 0.0085 m" in m
               and s == 3 for s, m in fmu.log), fmu.log  # fmt: skip
    with pytest.raises(Exception, match="status 3"):
        fmu.slave.doStep(0.0, 1e-3)
    fmu.slave.reset()  # a fixed parameter: set again from the start
    fmu.init(**_7002)
    fmu.slave.doStep(0.0, 1e-3)
    fmu.close()


@pytest.fixture(scope="module")
def user_fmus(tmp_path_factory):
    """BearingFriction built with the example user catalogue: its defaults are the user's
    gimbal (a 7002-size bearing, a PAO grease, a 7075 yoke, a spring)."""
    from servofmu.build.fmu import build_fmu

    out = tmp_path_factory.mktemp("user_fmus")
    defaults = catalogs.load([EXAMPLE])
    try:
        path = build_fmu("BearingFriction", out, defaults)
        library = BearingModel(BearingPair.from_catalog("my_gimbal", "my_pao_grease"))
        expected = [_outputs(library, p) for p in POINTS]
        values = default_parameters("my_gimbal")
    finally:
        catalogs.unload()
    return path, expected, values


def test_a_user_catalogue_builds_fmus_whose_defaults_are_the_users_bearing(user_fmus):
    path, expected, values = user_fmus
    assert validate_fmu(str(path)) == []
    md = parse(read_member(path, "modelDescription.xml"), "md")
    start = {sv.get("name"): sv[0].get("start") for sv in md.iter("ScalarVariable")}
    assert float(start["bore"]) == 15e-3 and int(start["n_balls"]) == 10
    assert float(start["ball_diameter"]) == 4.7625e-3
    assert float(start["lubricant_viscosity_40"]) == 26e-6
    assert int(start["preload_method"]) == 3  # spring
    fmu = Fmu(path, "user").init()
    assert _run(fmu) == expected  # the library's model of the user's catalogue entries
    fmu.close()
    names = {Path(n).as_posix() for n in _members(path)}
    assert "resources/presets/bearings/my_7002.ssv" in names
    assert "resources/presets/mountings/ning_space_shaft.ssv" in names
    doc = read_member(path, "documentation/index.html").decode()
    assert "ASM: 7075-T6, 71.7 GPa" in doc and "(user catalogue)" in doc
    assert values["bore"] == 15e-3


def _members(path):
    import zipfile

    with zipfile.ZipFile(path) as zf:
        return zf.namelist()


def test_round_trip_the_71803_numbers_set_explicitly_give_the_default_outputs(fmus, user_fmus):
    """Every parameter set to the 71803 gimbal's values, in an FMU built with other defaults
    (the user's 7002-size gimbal) and in the default one: exactly the default outputs."""
    p = default_parameters()
    default = Fmu(fmus["BearingFriction"], "default").init()
    expected = _run(default)
    again = Fmu(fmus["BearingFriction"], "again").init(**_fmu_values(default, p))
    default.close()
    other = Fmu(user_fmus[0], "other")
    assert _run(other.init()) != expected  # its own defaults differ
    other.close()
    explicit = Fmu(user_fmus[0], "explicit").init(**_fmu_values(again, p))
    assert set(p) <= set(explicit.vr)  # every parameter was set
    assert _run(explicit) == expected and _run(again) == expected
    explicit.close()
    again.close()


def test_each_system_binds_its_preset_in_full():
    """The systems' bearing.ssv files carry the whole parameter set of their preset (no
    String, no reliance on the FMU's start values): space_bearing runs Ning's pair in every
    engine."""
    from servofmu.build.ssp import SSP_DIR

    for ssv, mounting, lubricant in (
        ("seeker_gimbal/bearing.ssv", "yu2017_gimbal", "krytox_143aa"),
        ("seeker_gimbal_position/bearing.ssv", "yu2017_gimbal", "krytox_143aa"),
        ("space_bearing/bearing.ssv", "ning_space_shaft", "mos2_film"),
        ("seeker_gimbal_chamber/bearing.ssv", "yu2017_gimbal", "krytox_143aa"),
        ("space_bearing_vacuum/bearing.ssv", "ning_space_shaft", "mos2_film"),
        # the mounting variants the main job compares (system-level names)
        ("seeker_gimbal/variants/rigid.ssv", "yu2017_gimbal_rigid", "krytox_143aa"),
        ("seeker_gimbal/variants/printed.ssv", "yu2017_gimbal_printed", "krytox_143aa"),
        ("seeker_gimbal/variants/spring.ssv", "yu2017_gimbal_spring", "krytox_143aa"),
    ):
        system = ssv
        root = parse((SSP_DIR / ssv).read_bytes(), ssv)
        bound = {}
        for prm in root.iter("{*}Parameter"):
            (value,) = list(prm)
            name = prm.get("name").removeprefix("bearing.")
            bound[name] = (value.tag.split("}")[1], value.get("value"))
        preset = default_parameters(mounting, lubricant=lubricant)
        for spec in PARAMETERS:
            kind, text = bound[spec.name]
            if spec.choices:
                assert (kind, int(text)) == ("Integer", spec.item(preset[spec.name])), spec.name
            elif spec.type == "Integer":
                assert (kind, int(text)) == ("Integer", preset[spec.name]), spec.name
            else:
                assert (kind, float(text)) == ("Real", preset[spec.name]), (system, spec.name)
        assert "String" not in {k for k, _ in bound.values()}


# ------------------------------------------------------------------------------ catalogues
def _write(tmp_path, text, name="mine.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


_Q = '{ value = %s, unit = "%s", kind = "assumed", ref = "test" }'


_FULL_71803 = (
    "[bearings.71803]\nname = 'again'\n"
    + "".join(
        f"{f} = {_Q % (v, u)}\n"
        for f, v, u in (
            ("bore", 17, "mm"),
            ("outer_diameter", 26, "mm"),
            ("width", 5, "mm"),
            ("n_balls", 15, "-"),
            ("ball_diameter", 2.381, "mm"),
            ("pitch_diameter", 21.5, "mm"),
            ("contact_angle", 15, "deg"),
            ("inner_curvature", 0.56, "-"),
            ("outer_curvature", 0.54, "-"),
        )
    )
    + "ring_material = 'bearing_steel_yu'\nball_material = 'bearing_steel_yu'\n"
)  # a whole entry under a key the package has


@pytest.mark.parametrize(
    "text, message",
    [
        (
            "[bearings.b]\nname = 'x'\nbore = 15\n",
            r"\[bearings\.b\] bore = 15 is an integer, not a",
        ),
        ("[bearings.b]\nname = 'x'\n", r"\[bearings\.b\] bore: missing \(required keys"),
        (
            "[materials.m]\nname = 'm'\nyoungs_modulus = 70\n",
            r"\[materials\.m\] youngs_modulus = 70 is an integer, not a table",
        ),
        (
            "[materials.m]\nname = 'm'\nyoungs_modulus = "
            + _Q % (70, "GPa")
            + "\npoisson_ratio = "
            + _Q % (0.3, "-")
            + "\n",
            r"\[materials\.m\] expansion: missing",
        ),
        (
            _FULL_71803,
            r"bearings\.71803 exists already",
        ),
        ("[gears.g]\nname = 'g'\n", r"table \[gears\] is not a catalogue table"),
        ("[defaults]\nmounting = 'nowhere'\n", r"\[defaults\]: mounting = 'nowhere' is not in"),
        ("[bearings.b\n", r"not valid TOML"),
        (
            "[mountings.m]\nbase = 'yu2017_gimbal_rigid'\nname = 'm'\nhousing_material = 'tc4'\n",
            r"mountings\.m: .*loop member 'frame' material = 'cast_aluminium' differs from 'tc4'",
        ),
    ],
)
def test_user_catalogue_errors_name_the_file_the_entry_and_the_field(tmp_path, capsys, text,
                                                                      message):  # fmt: skip
    from servofmu.cli import main

    path = _write(tmp_path, text)
    assert main(["build", "--catalog", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and str(path) in err, err
    assert re.search(message, err), err
    assert not (tmp_path / "out").exists()  # nothing built
    assert "b" not in catalog.keys("bearings")  # nothing stays merged


def test_servofmu_catalog_lists_the_users_entries_and_writes_a_preset(tmp_path, capsys):
    from servofmu.cli import main

    assert main(["catalog", "--catalog", str(EXAMPLE)]) == 0
    out = capsys.readouterr().out
    assert re.search(r"my_7002 +15 × 32 × 9, 10 × 4\.763.*my_gimbal_catalog\.toml", out)
    assert re.search(r"71803 +17 × 26 × 5, 15 × 2\.381, 21\.5, 15.*data/bearings\.toml", out)
    ssv = tmp_path / "ning.ssv"
    args = ["catalog", "--preset", "ning_space_shaft", "--ssv", str(ssv), "--component", "b"]
    assert main(args) == 0
    assert "assembly_preload" in capsys.readouterr().out
    assert '<ssv:Parameter name="b.arrangement" description="back_to_back">' in ssv.read_text()
    assert "my_7002" not in catalog.keys("bearings")  # the listing merged it for itself only


def test_the_bearing_fields_are_the_bearing_records():
    assert BEARING_FIELDS[:9] == ("bore", "outer_diameter", "width", "ball_diameter", "n_balls",
                                  "pitch_diameter", "nominal_contact_angle", "inner_curvature",
                                  "outer_curvature")  # fmt: skip


def test_the_examples_in_the_docstrings_run():
    import doctest

    from servofmu.parameters import bearing as bearing_parameters
    from servofmu.parameters import presets
    from servofmu.parameters import table as parameter_table
    from servofmu.physics.lubrication import viscosity
    from servofmu.physics.pair import preload

    for module in (bearing_parameters, parameter_table, presets, preload, viscosity):
        result = doctest.testmod(module)
        assert result.attempted > 0 and result.failed == 0, (module.__name__, result)


def test_every_lubricant_value_says_where_it_comes_from():
    """At least eight greases and oils; every ν40/ν100 with its provenance, and a value that
    could not be checked against a source says so (kind assumed, "verify")."""
    fluids = [k for k in catalog.keys("lubricants") if catalog.lubricant(k) is not None]
    assert len(fluids) >= 8
    for key in fluids:
        rec = catalog.lubricant_record(key)
        for field in ("viscosity_40", "viscosity_100"):
            source = rec.source(field)
            kind_ = source.split(":")[0]
            assert kind_ in ("paper", "catalogue", "handbook", "derived", "assumed"), (key, source)
            if kind_ == "assumed":
                assert "verify" in source, (key, source)

"""Input read strictly: a user catalogue fits its table's schema (known keys, types, the
dimension of each unit) or the command exits 2 naming the file, the table, the entry, the key,
what was given and what is allowed; the package's own tables fit the same schemas; every unit
a catalogue may use has, by pint, the factor servofmu converts it with; input files are read
within a size cap as UTF-8 text; no FMU ships a start value its own range refuses; the
schema libraries stay out of what an FMU imports."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from importlib import resources

import pytest

from servofmu import cli
from servofmu.build import schema
from servofmu.physics.kernels.units import TO_SI, to_si


def _q(value, unit):
    v = str(value).lower() if isinstance(value, bool) else value
    return f'{{ value = {v}, unit = "{unit}", kind = "assumed", ref = "test" }}'


MATERIAL = (
    '[materials.my_alu]\nname = "alu"\n'
    f"youngs_modulus = {_q(70, 'GPa')}\npoisson_ratio = {_q(0.33, '-')}\n"
    f"expansion = {_q(23e-6, '1/K')}\n"
)


def _bearing(**changes) -> str:
    fields = {
        "bore": _q(17, "mm"),
        "outer_diameter": _q(26, "mm"),
        "width": _q(5, "mm"),
        "n_balls": _q(15, "-"),
        "ball_diameter": _q(2.381, "mm"),
        "pitch_diameter": _q(21.5, "mm"),
        "contact_angle": _q(15, "deg"),
        "inner_curvature": _q(0.56, "-"),
        "outer_curvature": _q(0.54, "-"),
    }
    fields.update(changes)
    lines = "\n".join(f"{k} = {v}" for k, v in fields.items())
    return (
        f'[bearings.my_b]\nname = "b"\n{lines}\n'
        'ring_material = "bearing_steel_yu"\nball_material = "bearing_steel_yu"\n'
    )


MOUNTING = '[mountings.my_m]\nbase = "yu2017_gimbal_rigid"\nname = "mine"\n'

# (catalogue text, what the one-line error must say): each of these was accepted (exit 0)
CASES = {
    "misspelt optional key": (
        MOUNTING + 'loop_modle = "yoke"\n',
        ["[mountings.my_m] loop_modle: unknown key", "did you mean 'loop_model'?"],
    ),
    "misspelt arrangement key": (
        MOUNTING + 'arangement = "back_to_back"\n',
        ["[mountings.my_m] arangement", "did you mean 'arrangement'?"],
    ),
    "misspelt lubricant key": (
        '[lubricants.my_oil]\nname = "oil"\nmodel = "walther"\n'
        f"viscosity_40 = {_q(32, 'cSt')}\nviscosity_100 = {_q(5.4, 'cSt')}\n"
        f"minimum_temprature = {_q(-40, 'degC')}\n",
        ["[lubricants.my_oil] minimum_temprature", "did you mean 'minimum_temperature'?"],
    ),
    "pressure for a length": (
        MOUNTING + f"outer_interference = {_q(4, 'MPa')}\n",
        [
            "outer_interference.unit = 'MPa' (a unit of pressure) is not a unit of length",
            "['m', 'mm', 'in', 'um']",
        ],
    ),
    "length for an expansion": (
        MATERIAL.replace(_q(23e-6, "1/K"), _q(23e-6, "m")),
        ["expansion.unit = 'm' (a unit of length) is not a unit of thermal expansion"],
    ),
    "torque for a width": (
        _bearing(width=_q(5, "N.mm")),
        ["width.unit = 'N.mm' (a unit of torque) is not a unit of length"],
    ),
    "a Boolean for a number": (
        _bearing(bore=_q(True, "mm")),
        ["[bearings.my_b] bore.value = true is a Boolean, not a number"],
    ),
    "a fraction for a count": (
        _bearing(n_balls=_q(10.5, "-")),
        ["n_balls.value = 10.5 is a number with a fraction, not a whole number (a count)"],
    ),
    "a ratio for an angle": (
        _bearing(contact_angle=_q(0.26, "-")),
        ["contact_angle.unit = '-'", "is not a unit of plane angle"],
    ),
    "an unknown table": (
        "[bearing.my_b]\nname = 'b'\n",
        ["table [bearing] is not a catalogue table (did you mean 'bearings'?)"],
    ),
}


@pytest.mark.parametrize("case", CASES)
def test_a_catalogue_off_its_schema_exits_2_naming_file_table_key_and_the_choices(
    tmp_path, capsys, case
):
    text, expected = CASES[case]
    path = tmp_path / "mine.toml"
    path.write_text(text)
    out = tmp_path / "out"
    assert cli.main(["build", "--catalog", str(path), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"servofmu: error: {path}: "), err
    for part in expected:
        assert part in err, (part, err)
    assert not out.exists()


def test_a_good_catalogue_passes_its_schema():
    data = tomllib.loads(MATERIAL + _bearing() + MOUNTING)
    assert schema.catalogue_problems(data, "mine.toml") == []


def test_every_problem_of_a_file_is_listed(tmp_path):
    from servofmu.build import catalogs

    path = tmp_path / "mine.toml"
    path.write_text(_bearing(bore=_q(True, "mm"), width=_q(5, "N.mm")) + MOUNTING + "x = 1\n")
    with pytest.raises(catalogs.CatalogueError) as info:
        catalogs.read(path)
    assert len(info.value.problems) == 3, info.value.problems


@pytest.mark.parametrize("table", sorted(schema.ENTRY_SCHEMAS))
def test_the_packages_tables_fit_their_schemas(table):
    """A key the schema does not know fails here: add it to build/schema.py with its unit."""
    with resources.files("servofmu.parameters").joinpath(f"data/{table}.toml").open("rb") as fh:
        data = tomllib.load(fh)
    problems = []
    for key, entry in data.items():
        problems += schema.entry_problems(table, key, entry, f"data/{table}.toml:")
    assert problems == []


def test_the_schema_finds_a_misspelt_key_in_the_packages_table():
    with resources.files("servofmu.parameters").joinpath("data/mountings.toml").open("rb") as fh:
        entry = dict(tomllib.load(fh)["ning_space_shaft"])
    entry["arangement"] = entry.pop("arrangement")
    assert schema.entry_problems("mountings", "ning_space_shaft", entry, "x:")


RULES = "parameters/data/bearing_rules.toml"
GREASES = "parameters/data/grease_torques.toml"
MEASURED = "papers/data/friction_measurements.toml"


def _data_file(name: str) -> str:
    return resources.files("servofmu").joinpath(name).read_text(encoding="utf-8")


@pytest.mark.parametrize("name", sorted(schema.DATA_SCHEMAS))
def test_the_packages_data_files_fit_their_schemas(name):
    """A key the schema does not know fails here: add it to build/schema.py with its unit."""
    assert schema.data_problems(name, tomllib.loads(_data_file(name))) == []


# (package file, text in it, its replacement in a copy, what the copy's message must say)
DATA_CASES = {
    "rules: misspelt key": (
        RULES,
        "fill = {",
        "fil = {",
        "copy.toml: ball_set.fil: unknown key 'fil' (did you mean 'fill'?)",
    ),
    "rules: a Boolean for a number": (
        RULES,
        "section_ratio = { value = 0.2859,",
        "section_ratio = { value = true,",
        "copy.toml: ball_set.section_ratio.value = true is a Boolean, not a number",
    ),
    "rules: a length for a ratio": (
        RULES,
        'fill = { value = 0.570, unit = "-"',
        'fill = { value = 0.570, unit = "mm"',
        "copy.toml: ball_set.fill.unit = 'mm' (a unit of length) is not a unit of ratio",
    ),
    "rules: the clearances in mm, read as um": (
        RULES,
        'unit = "um"',
        'unit = "mm"',
        "copy.toml: radial_clearance.unit = 'mm' is not the unit this value is read in: "
        "one of ['um']",
    ),
    "greases: misspelt key": (
        GREASES,
        'hold = "2 h',
        'hlod = "2 h',
        "copy.toml: tests.jis_k2220.hlod: unknown key 'hlod' (did you mean 'hold'?)",
    ),
    "greases: a Boolean for a number": (
        GREASES,
        "starting_torque = { value = 99,",
        "starting_torque = { value = true,",
        "copy.toml: greases.molykote_g1074.points[0].starting_torque.value = true is a "
        "Boolean, not a number",
    ),
    "greases: a force for a mass": (
        GREASES,
        'housing_mass = { value = 454, unit = "g"',
        'housing_mass = { value = 454, unit = "N"',
        "copy.toml: tests.astm_d1478.housing_mass.unit = 'N' (a unit of force) is not a unit "
        "of mass",
    ),
    "measurements: misspelt key": (
        MEASURED,
        "groove_radius = {",
        "grove_radius = {",
        "copy.toml: balan2015.grove_radius: unknown key 'grove_radius' (did you mean "
        "'groove_radius'?)",
    ),
    "measurements: misspelt key of a searched record": (
        MEASURED,
        'details = "outside',
        'detials = "outside',
        "copy.toml: searched[1].detials: unknown key 'detials' (did you mean 'details'?)",
    ),
    "measurements: a Boolean for a count": (
        MEASURED,
        "n_balls = { value = 3,",
        "n_balls = { value = true,",
        "copy.toml: balan2015.n_balls.value = true is a Boolean, not a whole number",
    ),
    "measurements: a force for a torque": (
        MEASURED,
        'k_star = { value = 4.001e-05, unit = "N.m"',
        'k_star = { value = 4.001e-05, unit = "N"',
        "copy.toml: balan2015.series[0].points[0].k_star.unit = 'N' (a unit of force) is not "
        "a unit of torque",
    ),
}


@pytest.mark.parametrize("case", DATA_CASES)
def test_a_copy_of_a_data_file_off_its_schema_is_refused_naming_the_key(case):
    name, old, new, expected = DATA_CASES[case]
    text = _data_file(name)
    assert old in text, old
    problems = schema.data_problems(name, tomllib.loads(text.replace(old, new, 1)), "copy.toml")
    assert any(expected in p for p in problems), problems


@pytest.mark.parametrize("unit", [*TO_SI, "degC"])
def test_pint_agrees_with_every_conversion_factor(unit):
    """The factors servofmu converts catalogue units with (physics/kernels/units.py), against
    pint."""
    ureg = schema.registry()
    q = schema.pint_quantity(unit)
    if unit == "degC":
        assert ureg.Quantity(20.0, "degC").to("K").magnitude == pytest.approx(to_si(20.0, unit))
        return
    si = q.to_base_units()
    # pint's base of mass is the kilogram and of a plane angle the radian (plane_angle): SI
    assert si.magnitude == pytest.approx(TO_SI[unit], rel=1e-12), (unit, si)


def test_units_of_one_dimension_are_grouped_and_angles_are_not_ratios():
    assert schema.units_of("N.m/rad") == ("N.m/rad", "N.m/deg")
    assert "-" not in schema.units_of("rad") and "N.m" not in schema.units_of("N.m/rad")
    assert set(schema.units_of("N.m")) == {"N.m", "mN.m", "N.mm", "g.cm"}  # g.cm: gram-force


def test_the_margin_input_suggests_the_key_meant(tmp_path):
    from servofmu.margin.inputs import example_input, input_problems, read_toml

    data = read_toml(example_input())
    data["motor"]["gear_ratoi"] = data["motor"].pop("gear_ratio")
    problems = input_problems(data, example_input().parent)
    assert any("did you mean 'gear_ratio'?" in p for p in problems), problems


@pytest.mark.parametrize(
    "change, expected",
    [
        (
            {"mechanism": {"parameters": {"grease_f0": True}}},
            "mechanism.parameters.grease_f0 = true is a Boolean, not a number",
        ),
        (
            {"mechanism": {"parameters": {"n_balls": 10.5}}},
            "n_balls = 10.5 is a number with a fraction, not a whole number (a count)",
        ),
        (
            {"end_of_life": {"parameters": {"lubrication": "grese"}}},
            "end_of_life.parameters.lubrication = 'grese' is not one of ['grease', 'solid'] "
            "(did you mean 'grease'?)",
        ),
        (
            {"tolerances": {"bands": {"shim": {"low": -1, "high": 1, "unit": "MPa"}}}},
            "tolerances.bands.shim.unit = 'MPa' (a unit of pressure) is not a unit of length",
        ),
    ],
)
def test_a_margin_input_off_its_schema_is_refused_naming_the_key(change, expected):
    """Each of these was accepted: a Boolean read as 1, a band's MPa converted as a length."""
    from servofmu.margin.inputs import example_input, input_problems, read_toml

    data = read_toml(example_input())
    for section, values in change.items():
        for key, value in values.items():
            data.setdefault(section, {})[key] = value
    problems = input_problems(data, example_input().parent)
    assert any(expected in p for p in problems), problems


# ----------------------------------------------------------------------------- files
@pytest.mark.parametrize(
    "content, expected",
    [
        ("utf-16", "is UTF-16 text (a byte-order mark): save it as UTF-8"),
        ("latin-1", "is not UTF-8 text (byte 0xe9 at offset"),
        ("nul", "holds a NUL byte"),
    ],
)
def test_an_input_file_in_another_encoding_is_named(tmp_path, capsys, content, expected):
    path = tmp_path / "mine.toml"
    text = '[materials.my_alu]\nname = "café"\n'
    if content == "nul":
        path.write_bytes(text.encode("utf-16-le"))
    else:
        path.write_bytes(text.encode(content))
    for argv in (["build", "--catalog", str(path)], ["margin", str(path)]):
        assert cli.main([*argv, "--out", str(tmp_path / "out")]) == 2
        err = capsys.readouterr().err
        assert f"{path}: " in err and expected in err, err


def test_an_endless_input_file_is_refused_within_the_cap(capsys, monkeypatch, tmp_path):
    from servofmu import files

    monkeypatch.setattr(files, "MAX_INPUT_BYTES", 1 << 20)  # the same path, a smaller cap
    assert cli.main(["build", "--catalog", "/dev/zero", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "/dev/zero: catalogue is larger than 1048576 bytes: not read" in err, err


def test_a_parameter_set_larger_than_the_cap_is_refused_unread(tmp_path, monkeypatch):
    from types import SimpleNamespace

    from servofmu import files
    from servofmu.harness.system import parameter_file

    monkeypatch.setattr(files, "MAX_INPUT_BYTES", 1 << 20)  # the same path, a smaller cap
    big = tmp_path / "big.ssv"
    big.write_bytes(b" " * (2 << 20))
    system = SimpleNamespace(name="demo", components={})
    with pytest.raises(ValueError, match=r"big\.ssv: parameter set is larger than 1048576 bytes"):
        parameter_file(system, big)


def test_a_utf8_byte_order_mark_is_accepted(tmp_path):
    from servofmu.build import catalogs

    path = tmp_path / "mine.toml"
    path.write_bytes(b"\xef\xbb\xbf" + MATERIAL.encode())
    tables, _ = catalogs.read(path)
    assert list(tables["materials"]) == ["my_alu"]


# ----------------------------------------------------------------------------- start values
def test_a_start_value_outside_its_variables_range_is_refused_before_packing(tmp_path, monkeypatch):
    from servofmu.build import fmu

    def start(name, defaults):
        return {"bore": (-0.017, "test: a sign lost")} if name == "BearingFriction" else {}

    monkeypatch.setattr(fmu, "start_values", start)
    with pytest.raises(ValueError, match=r"BearingFriction: start value bore = -0.017 .*outside"):
        fmu.build_fmu("BearingFriction", tmp_path)
    assert not list(tmp_path.glob("*.fmu"))


def test_the_fmus_import_no_schema_library(fmus):
    """The catalogue is read at build time: a host needs nothing new."""
    paths = [str(p) for p in fmus.values() if p.suffix == ".fmu"]
    code = (
        "import sys\n"
        "from fmpy import extract, simulate_fmu\n"
        "before = set(sys.modules)\n"
        f"for path in {paths!r}:\n"  # extracted for the process: FMUs share one servofmu
        "    simulate_fmu(extract(path), stop_time=0.002, output_interval=0.001)\n"
        "new = {m.split('.')[0] for m in set(sys.modules) - before}\n"
        "print(sorted(new & {'jsonschema', 'fastjsonschema', 'pint', 'referencing'}))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "[]", out.stdout


def test_the_merged_catalogue_table_is_built_once_per_change():
    """Not a timing: the merged table is built once per change of the catalogue, not per
    lookup (a lookup copied the table: quadratic in the number of entries)."""
    from servofmu.parameters import catalog

    q = {"value": 70, "unit": "GPa", "kind": "assumed", "ref": "x"}
    entry = {"name": "x", "youngs_modulus": q}
    try:
        catalog.add_entries({"materials": {f"m{i}": entry for i in range(1000)}}, "many.toml")
        first = catalog._table("materials")
        assert all(catalog._table("materials") is first for _ in range(3))
    finally:
        catalog.remove_user_entries()

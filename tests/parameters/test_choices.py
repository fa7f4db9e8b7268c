"""Choices (lubrication, arrangement, preload method, loop model and reading, controller
mode): enumeration items in the modelDescription, range-checked integers in the FMUs, saved in
the state, bound from .ssv files and set by item name in the harness; the FMI encoding
alternative; the variable-table checks. (Catalogue entries are presets of the numbers, not
choices: tests/parameters/test_parameters.py.)"""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
import pytest
from fmpy.validation import validate_fmu
from fmu_helpers import Fmu

from servofmu.build.archive import read_member
from servofmu.build.choices import choice_items, problems
from servofmu.build.ssp import SSP_DIR, systems
from servofmu.build.xmlsafe import parse, validate
from servofmu.fmus import declarations, model_description
from servofmu.fmus.BearingFriction import BearingFriction
from servofmu.fmus.runtime import ServoSlave
from servofmu.harness import HarnessError, SystemError_, load_system, run
from servofmu.parameters import bearing as bearing_parameters
from servofmu.parameters.bearing import PARAMETERS, parameter

SSV = (
    '<?xml version="1.0" encoding="UTF-8"?>\n<ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/'
    'SSP1/SystemStructureParameterValues" version="1.0" name="{name}"><ssv:Parameters>'
    "{parameters}</ssv:Parameters></ssv:ParameterSet>"
)


def _items(fmu_path) -> dict[str, dict[str, int]]:
    return choice_items(parse(read_member(fmu_path, "modelDescription.xml"), "md"))


def test_every_choice_is_a_structural_choice_with_named_items(fmus):
    items = _items(fmus["BearingFriction"])
    choices = {p.name for p in PARAMETERS if p.choices}
    assert choices == {
        "lubrication", "arrangement", "preload_method", "loop_model", "loop_reading",
        "friction_model", "lubricant_below_flow_limit",
    }  # fmt: skip
    assert set(items) == choices | {"temperature_mode"}  # the FMU's own choice of inputs
    assert list(items["temperature_mode"]) == ["uniform", "housing_shaft", "parts"]
    assert list(items["lubrication"]) == ["grease", "solid"]
    assert list(items["lubricant_below_flow_limit"]) == ["hold", "extrapolate"]
    assert list(items["arrangement"]) == ["face_to_face", "back_to_back", "tandem"]
    assert list(items["preload_method"]) == ["shim", "force", "spring"]
    assert items["loop_model"]["yoke"] == parameter("loop_model").item("yoke") == 2
    assert list(items["friction_model"]) == ["yu2017", "skf2004", "ehl_per_contact"]
    assert _items(fmus["ServoController"]) == {"mode": {"position": 1, "speed": 2}}
    actuator = _items(fmus["ActuatorStiffness"])
    assert set(actuator) == {
        f"support_{c}"
        for c in choices - {"lubrication", "friction_model", "lubricant_below_flow_limit"}
    } | {"temperature_mode"}
    for path in fmus.values():  # no String variable is left
        if path.suffix == ".fmu":
            xml = read_member(path, "modelDescription.xml")
            assert b"<String" not in xml and problems(parse(xml, "md")) == []


def test_choice_values_survive_a_serialised_state(fmus):
    path = fmus["BearingFriction"]
    setting = dict(lubrication="solid", arrangement="back_to_back", loop_model="members")
    fmu = Fmu(path, "a").init(temperature=300.0, speed=0.3, **setting)
    blob = fmu.slave.serializeFMUstate(fmu.slave.getFMUstate())
    expected = fmu.real_outputs()
    fmu.close()
    fresh = Fmu(path, "b").init()  # the defaults: Yu's gimbal with grease
    assert fresh.get("kinematic_viscosity") > 0
    fresh.slave.setFMUstate(fresh.slave.deSerializeFMUstate(blob))
    refs = [fresh.vr[n] for n in setting]
    assert fresh.slave.getInteger(refs) == [fresh.items[n][v] for n, v in setting.items()]
    fresh.slave.doStep(0.0, 1e-3)
    assert fresh.real_outputs() == expected and fresh.get("kinematic_viscosity") == 0.0
    fresh.close()


def test_ssv_choices_carry_the_value_of_their_item_name(fmus):
    """Each .ssv binds a choice as ssv:Integer with the item name as description (every engine
    applies an Integer): the two must agree, so a reordered catalogue cannot shift a value
    silently."""
    checked = 0
    for folder in systems():
        system = load_system(folder, fmu_dir=fmus["BearingFriction"].parent)
        try:
            for ssv in folder.rglob("*.ssv"):  # <component>.ssv, or variants/ (comp.var)
                root = parse(ssv.read_bytes(), str(ssv))
                for p in root.iter("{*}Parameter"):
                    target = p.get("name")
                    if ssv.parent == folder:
                        target = f"{ssv.stem}.{target}"
                    _, var = system.variable(target)
                    if var.items is None:
                        continue
                    value = int(p.find("{*}Integer").get("value"))
                    assert var.items[p.get("description")] == value, (ssv, target)
                    checked += 1
        finally:
            system.close()
    assert checked >= 18  # five bearing choices ×3 systems, the controllers' modes


def test_harness_takes_item_names_and_refuses_others(fmus):
    system = load_system(fmus["BearingFriction"].parent / "space_bearing.ssp")
    try:
        assert system.components["bearing"].parameters["lubrication"] == ("Integer", 2)
        res = run(system, stop=0.02, record=["bearing.kinematic_viscosity"], progress=False)
        assert np.all(res["bearing.kinematic_viscosity"] == 0.0)  # solid, from the .ssv
        greased = {"bearing.lubrication": "grease"}  # with the .ssv's (unused) viscosities
        res = run(system, parameters=greased, stop=0.02, record=["bearing.kinematic_viscosity"])
        assert np.all(res["bearing.kinematic_viscosity"] > 0)
        res = run(system, parameters={"bearing.lubrication": "2"}, stop=0.02, progress=False)
        with pytest.raises(HarnessError, match=r"lubrication = 'oil' is not one of the items "):
            run(system, parameters={"bearing.lubrication": "oil"}, stop=0.02)
        with pytest.raises(HarnessError, match=r"grease \(1\), solid \(2\)"):
            run(system, parameters={"bearing.lubrication": 3}, stop=0.02)
    finally:
        system.close()


@pytest.mark.parametrize(
    "binding, message",
    [
        ('<ssv:String value="solid"/>', r"lubrication = 'solid' \(String\) is not one of"),
        ('<ssv:Integer value="7"/>', r"lubrication = 7 \(Integer\) is not one of the items"),
        ('<ssv:Enumeration value="oil"/>', r"'oil' \(Enumeration\) is not one of"),
        ('<ssv:Enumeration value="solid"/>', None),  # an item name: schema-valid and applied
    ],
)
def test_ssv_bindings_of_a_choice(fmus, tmp_path, binding, message):
    folder = tmp_path / "space_bearing"
    source = SSP_DIR / "space_bearing"
    for f in source.rglob("*"):
        if f.is_file():
            (folder / f.relative_to(source)).parent.mkdir(parents=True, exist_ok=True)
            (folder / f.relative_to(source)).write_bytes(f.read_bytes())
    ssv = folder / "bearing.ssv"
    text = ssv.read_text()
    old = '<ssv:Parameter name="lubrication" description="solid"><ssv:Integer value="2" />'
    assert old in text
    ssv.write_text(text.replace(old, f'<ssv:Parameter name="lubrication">{binding}'))
    validate(parse(ssv.read_bytes(), str(ssv)), "ssv", str(ssv))  # fmpy's SSP 1.0 schema
    if message is None:
        system = load_system(folder, fmu_dir=fmus["BearingFriction"].parent)
        assert system.components["bearing"].parameters["lubrication"] == ("Integer", 2)
        system.close()
        return
    with pytest.raises(SystemError_, match=message):
        load_system(folder, fmu_dir=fmus["BearingFriction"].parent)


@pytest.mark.slow
def test_choices_written_as_fmi_enumerations_validate_and_run(tmp_path, monkeypatch):
    """The other encoding (model_description.CHOICES_AS = "Enumeration"): 0 problems in fmpy
    and servofmu validate, and the harness binds the same .ssv files (ssv:Integer sets an
    Enumeration)."""
    from servofmu.build.fmu import build_all
    from servofmu.build.validate import validate as validate_fmu_servofmu

    monkeypatch.setattr(model_description, "CHOICES_AS", "Enumeration")
    out = build_all(tmp_path)
    for path in out:
        if path.suffix == ".fmu":
            xml = read_member(path, "modelDescription.xml").decode()
            assert ("<Enumeration declaredType=" in xml) == (path.stem != "DCMotor")
            assert validate_fmu(str(path)) == [] and validate_fmu_servofmu(path) == []
    system = load_system(tmp_path / "space_bearing.ssp")
    try:
        assert system.components["bearing"].variables["lubrication"].type == "Enumeration"
        res = run(system, stop=0.02, record=["bearing.kinematic_viscosity"], progress=False)
        assert np.all(res["bearing.kinematic_viscosity"] == 0.0)
    finally:
        system.close()


def test_variable_table_checks_name_what_is_wrong():
    out = declarations.output("y", "an output", initial_depends=("u", "nowhere"), depends=("k",))
    u = declarations.real_input("u", "an input", start=0.0, min=-1.0, max=1.0)
    choice = declarations.Var(name="c", type="Enumeration", causality="parameter", description="c")
    found = declarations.check_variables(
        (u, out, u, choice, declarations.output("z", "no initial"))
    )
    assert any("duplicate variable names" in p for p in found)
    assert any("output y: dependencies ['k', 'nowhere', 'k']" in p for p in found)
    assert any("c: an Enumeration needs items" in p for p in found)
    assert any("output z: initial_depends not declared" in p for p in found)
    assert declarations.check_variables(BearingFriction.VARIABLES) == []
    with pytest.raises(TypeError, match="initial_depends not declared"):
        type("Broken", (ServoSlave,), {"VARIABLES": (declarations.output("z", "z"),)})


def test_speed_path_refreshes_exactly_the_outputs_that_depend_on_speed():
    speed = {v.name for v in BearingFriction.VARIABLES if "speed" in v.depends}
    assert set(BearingFriction._SPEED_OUTPUTS) == speed


def test_physics_does_not_import_the_fmu_layer():
    folder = Path(bearing_parameters.__file__).parent
    for source in folder.glob("*.py"):
        for node in ast.walk(ast.parse(source.read_text())):
            if isinstance(node, ast.ImportFrom):
                assert "fmus" not in (node.module or ""), source.name
            if isinstance(node, ast.Import):
                assert not [a for a in node.names if "fmus" in a.name], source.name


def test_a_catalogue_key_that_reads_as_a_number_stays_a_key():
    """The command line parses --grid values as floats when they read as one: the bearing
    preset "71803" must still name the bearing (the sweep's model task)."""
    from servofmu.harness.sweep import ModelTask
    from servofmu.parameters.bearing import default_parameters

    base = default_parameters("yu2017_gimbal")
    rows = ModelTask(base, ("preload",))(
        [{"bearing": 71803.0}, {"bearing": "71803"}, {"bearing": 71804.0}]
    )
    assert "error" not in rows[0] and rows[0]["preload"] == rows[1]["preload"]
    assert "bearing key = '71804' is not one of" in rows[2]["error"]


def test_command_line_refuses_a_bad_item_with_exit_2(fmus, tmp_path, capsys):
    from servofmu.cli import main

    ssp = str(fmus["BearingFriction"].parent / "space_bearing.ssp")
    args = ["run", ssp, "--stop", "0.02", "--out", str(tmp_path)]
    assert main([*args, "--parameters", "bearing.arrangement=nowhere"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "bearing.arrangement = 'nowhere'" in err
    assert "face_to_face (1)" in err and not (tmp_path / "results.csv").exists()
    assert main([*args, "--parameters", "bearing.arrangement=face_to_face"]) == 0

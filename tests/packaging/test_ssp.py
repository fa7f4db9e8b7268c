"""The SSP systems of ssp/: schema-valid as fmpy reads them, the project's conventions
(flat, hyphen-free names, connector units, the OSP step annotation, one .ssv per component),
and packed with their FMUs by ``servofmu build``."""

from __future__ import annotations

import inspect
import zipfile

import pytest
from lxml import etree

from servofmu.build.ssp import SSP_DIR, fmu_sources, systems

NS = {
    "ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
    "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
    "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues",
    "osp": "http://opensimulationplatform.com/SSP/OSPAnnotations",
    "oms": "https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd",
}
SYSTEMS = [s.name for s in systems()]


def test_the_issue_systems_exist():
    assert {"seeker_gimbal", "ema_actuator", "space_bearing"} <= set(SYSTEMS)


@pytest.mark.parametrize("name", SYSTEMS)
def test_fmpy_reads_the_packed_system_with_schema_validation(fmus, name):
    from fmpy.ssp.ssd import read_ssd, read_ssv

    archive = fmus["BearingFriction"].parent / f"{name}.ssp"
    ssd = read_ssd(str(archive), validate=True)
    assert ssd.system.name == name
    for ssv in (SSP_DIR / name).rglob("*.ssv"):
        read_ssv(str(ssv), validate=True)


@pytest.mark.parametrize("name", SYSTEMS)
def test_system_conventions(name):
    folder = SSP_DIR / name
    root = etree.parse(str(folder / "SystemStructure.ssd")).getroot()
    assert root.get("version") == "1.0"
    system = root.find("ssd:System", NS)
    assert system.find("ssd:Elements/ssd:System", NS) is None  # flat
    names = [root.get("name"), system.get("name")]
    for comp in system.iterfind("ssd:Elements/ssd:Component", NS):
        names.append(comp.get("name"))
        for conn in comp.iterfind("ssd:Connectors/ssd:Connector", NS):
            names.append(conn.get("name"))
            real = conn.find("ssc:Real", NS)
            if real is not None and conn.get("name") not in ("reference", "measurement"):
                assert real.get("unit"), f"{comp.get('name')}.{conn.get('name')} has no unit"
        bindings = comp.findall("ssd:ParameterBindings/ssd:ParameterBinding", NS)
        assert [b.get("source") for b in bindings] == [f"{comp.get('name')}.ssv"]
        assert (folder / f"{comp.get('name')}.ssv").is_file()
    assert not [n for n in names if "-" in n], "hyphens in names"
    step = root.find("ssd:DefaultExperiment//osp:FixedStepAlgorithm", NS)
    assert step is not None and float(step.get("baseStepSize")) > 0
    assert list((folder / "variants").glob("*.ssv")), "no parameter-set variants"


def test_packed_archive_holds_the_system_and_its_fmus(fmus):
    archive = fmus["BearingFriction"].parent / "seeker_gimbal.ssp"
    with zipfile.ZipFile(archive) as zf:
        entries = set(zf.namelist())
    assert "SystemStructure.ssd" in entries and "variants/cold.ssv" in entries
    assert set(fmu_sources(SSP_DIR / "seeker_gimbal")) <= entries


@pytest.mark.parametrize("name", SYSTEMS)
def test_every_engine_finds_the_step_and_the_parameter_values(name):
    """OMSimulator's classic route needs the org.openmodelica master annotation on the system
    (the same step as the OSP annotation that libcosim reads); ecos applies the .ssv files of
    one ParameterSet name only, so every .ssv of the system carries the same name."""
    from servofmu.calibration import write_ssv
    from servofmu.harness.ecos import PARAMETER_SET

    folder = SSP_DIR / name
    root = etree.parse(str(folder / "SystemStructure.ssd")).getroot()
    osp = root.find("ssd:DefaultExperiment//osp:FixedStepAlgorithm", NS)
    annotation = root.find("ssd:System/ssd:Annotations/ssc:Annotation", NS)
    assert annotation is not None and annotation.get("type") == "org.openmodelica"
    master = annotation.find("oms:Annotations/oms:SimulationInformation/oms:FixedStepMaster", NS)
    assert master.get("description") == "oms-ma"
    assert float(master.get("stepSize")) == float(osp.get("baseStepSize"))
    for ssv in sorted(folder.rglob("*.ssv")):
        assert etree.parse(str(ssv)).getroot().get("name") == PARAMETER_SET, ssv
    assert inspect.signature(write_ssv).parameters["name"].default == PARAMETER_SET


@pytest.mark.parametrize(
    "name, preset, ssv",
    [
        ("seeker_gimbal_chamber", "yu2017_gimbal_chamber", "thermal.ssv"),
        ("space_bearing_vacuum", "ning_space_vacuum", "thermal.ssv"),
        ("space_bearing_vacuum", "ning_chamber_air", "variants/chamber_air.ssv"),
    ],
)
def test_thermal_systems_bind_the_network_presets(name, preset, ssv):
    """The ThermalNetwork of each thermal system (and Ning's chamber-air variant) carries its
    preset's values exactly (the library's derived parameters), and the bearing reads the
    network's part temperatures."""
    from servofmu.physics.thermal import network as tn

    def values(ssv):
        root = etree.parse(str(SSP_DIR / name / ssv)).getroot()
        out = {}
        for p in root.iterfind("ssv:Parameters/ssv:Parameter", NS):
            (v,) = list(p)
            out[p.get("name")] = v.get("value")
        return out

    params = tn.preset(preset)
    prefix = "thermal." if ssv.startswith("variants") else ""
    bound = {k.removeprefix(prefix): v for k, v in values(ssv).items()}
    for field, value in params.as_dict().items():
        if field == "environment":
            assert int(bound[field]) == tn.ENVIRONMENTS.index(value) + 1
        else:
            # the file holds the library's value as written when it was generated; libm's
            # pow/exp may round the last digit differently in another numpy build
            assert float(bound[field]) == pytest.approx(value, rel=1e-12), field
    assert values("bearing.ssv")["temperature_mode"] == "3"  # parts

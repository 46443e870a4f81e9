"""modelDescription.xml of each FMU: generated from its C variable table, up to date, valid FMI 2.0."""
import subprocess
import sys
import zipfile

import pytest

from fmpy import read_model_description
from fmpy.validation import validate_fmu

import gen_model_description as gen


def test_committed_model_description_is_up_to_date(repo):
    result = subprocess.run([sys.executable, str(repo / "scripts" / "gen_model_description.py"), "--check"],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr


@pytest.mark.parametrize("name", list(gen.MODELS))
def test_fmu_validates(build_dir, name):
    assert validate_fmu(str(build_dir / f"{name}.fmu")) == []


@pytest.mark.parametrize("name", list(gen.MODELS))
def test_fmu_contains_the_committed_xml_and_sources(build_dir, name):
    model = gen.MODELS[name]
    with zipfile.ZipFile(build_dir / f"{name}.fmu") as zf:
        names = set(zf.namelist())
        assert zf.read("modelDescription.xml").decode() == model["output"].read_text()
    assert f"binaries/linux64/{name}.so" in names
    for f in model["sources"] + ["fmu_model.h", "cs_cvode.h", model["header"].name]:
        assert f"sources/{f}" in names


@pytest.mark.parametrize("name", list(gen.MODELS))
def test_model_exchange_and_co_simulation_declared(build_dir, name):
    md = read_model_description(str(build_dir / f"{name}.fmu"))
    assert md.modelExchange.modelIdentifier == md.coSimulation.modelIdentifier == name
    assert md.coSimulation.canHandleVariableCommunicationStepSize
    assert md.coSimulation.canInterpolateInputs
    assert md.modelExchange.canBeInstantiatedOnlyOncePerProcess is False
    for interface in (md.modelExchange, md.coSimulation):  # FMU state
        assert interface.canGetAndSetFMUstate and interface.canSerializeFMUstate


def test_variables_match_the_c_table(rockingwall_fmu):
    table, _, defines = gen.parse_model("RockingWall")
    md = read_model_description(str(rockingwall_fmu))
    assert md.guid == defines["RW_GUID"]
    assert md.numberOfEventIndicators == int(defines["RW_NUMBER_OF_EVENT_INDICATORS"])
    assert md.buildConfigurations[0].sourceFileSets[0].sourceFiles == gen.SOURCE_FILES
    xml = {v.name: v for v in md.modelVariables}
    assert [v.name for v in md.modelVariables] == [v["name"] for v in table]
    for v in table:
        x = xml[v["name"]]
        assert x.valueReference == v["vr"]
        assert x.type == v["type"]
        assert x.causality == v["causality"]
        assert x.variability == v["variability"]
        if v["unit"]:
            assert x.unit == v["unit"]
    states = [d.variable.name for d in md.derivatives]
    assert states == ["dq1", "dq2", "der(dq1)", "der(dq2)"]
    assert [d.variable.derivative.name for d in md.derivatives] == ["q1", "q2", "dq1", "dq2"]
    expected_names = {"h", "b", "W", "psi", "Kd", "er", "g", "delta1Ratio", "delta2A", "delta2B", "hingeSat",
                      "restRate", "support", "hingeLaw", "ag", "u_top", "s1", "s2", "F_top", "collapsed", "impacts",
                      "q1", "q2", "dq1", "dq2"}
    assert expected_names <= set(xml)
    assert "model" not in xml  # renamed to support: "model" is a Modelica keyword and broke an importer
    assert xml["Kd"].unit == "N/m2" and xml["W"].unit == "N/m" and xml["F_top"].unit == "N/m"
    assert xml["q1"].nominal == "0.01" or float(xml["q1"].nominal) == 0.01
    assert float(xml["dq1"].nominal) == 0.1
    assert xml["P_ground"].unit == "W/m" and xml["dissipated"].variability == "discrete"


def test_diaphragm_variables_match_its_c_table(build_dir):
    model = gen.MODELS["Diaphragm"]
    table, _, defines = gen.parse_model("Diaphragm")
    md = read_model_description(str(build_dir / "Diaphragm.fmu"))
    assert md.guid == defines["RW_GUID"] and md.numberOfEventIndicators == 0
    assert [(v.name, v.valueReference, v.causality) for v in md.modelVariables] == \
        [(v["name"], v["vr"], v["causality"]) for v in table]
    assert [d.variable.derivative.name for d in md.derivatives] == ["u", "v"]


def test_parameter_ranges_in_the_xml(rockingwall_fmu):
    """Every wall parameter carries the C table's range as min/max, and its default lies inside; the
    other parameters are the record's (agFile, agScale) of the variable table."""
    md = read_model_description(str(rockingwall_fmu))
    xml = {v.name: v for v in md.modelVariables}
    params = gen.parse_parameters()
    record_params = {v["name"] for v in gen.parse_header()[0] if v["causality"] == "parameter"}
    assert record_params == {"agFile", "agScale"}
    assert {p["name"] for p in params} | record_params == \
        {v.name for v in md.modelVariables if v.causality == "parameter"}
    for p in params:
        v = xml[p["name"]]
        assert float(v.min) == p["min"] and float(v.max) == p["max"], p["name"]
        assert p["min"] <= float(v.start) <= p["max"], p["name"]

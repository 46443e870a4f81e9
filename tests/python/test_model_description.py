"""modelDescription.xml: generated from fmu_src/model_variables.h, up to date, valid FMI 2.0."""
import subprocess
import sys
import zipfile

from fmpy import read_model_description
from fmpy.validation import validate_fmu

import gen_model_description as gen


def test_committed_model_description_is_up_to_date(repo):
    result = subprocess.run([sys.executable, str(repo / "scripts" / "gen_model_description.py"), "--check"],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr


def test_fmu_validates(rockingwall_fmu):
    assert validate_fmu(str(rockingwall_fmu)) == []


def test_fmu_contains_the_committed_xml_and_sources(repo, rockingwall_fmu):
    with zipfile.ZipFile(rockingwall_fmu) as zf:
        names = set(zf.namelist())
        assert zf.read("modelDescription.xml").decode() == (repo / "modelDescription.xml").read_text()
    assert "binaries/linux64/RockingWall.so" in names
    for f in gen.SOURCE_FILES + ["rw_physics.h", "model_variables.h"]:
        assert f"sources/{f}" in names


def test_variables_match_the_c_table(rockingwall_fmu):
    table, _, defines = gen.parse_header()
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
                      "restRate", "model", "hingeLaw", "ag", "u_top", "s1", "s2", "F_top", "collapsed", "impacts",
                      "q1", "q2", "dq1", "dq2"}
    assert expected_names <= set(xml)
    assert xml["Kd"].unit == "N/m2" and xml["W"].unit == "N/m" and xml["F_top"].unit == "N/m"
    assert xml["q1"].nominal == "0.01" or float(xml["q1"].nominal) == 0.01
    assert float(xml["dq1"].nominal) == 0.1
    assert not md.coSimulation and md.modelExchange.canBeInstantiatedOnlyOncePerProcess is False

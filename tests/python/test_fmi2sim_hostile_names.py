"""fmi2sim names what is wrong and where it came from: a variable name the model description
declares twice (the CSV header repeated it), a --set given twice, an --input that is a folder, an
input whose value makes CVODE fail, and a stop time out of range that came from the model
description rather than the command line."""
import pytest

from fmi2sim_harness import MD, assert_one_clear_error, hostile_fmu, run


def test_finding_a_variable_name_declared_twice_is_refused(fmi2sim_exe, rockingwall_fmu, tmp_path):
    def rename(text):  # s2 renamed s1: the header read time,s1,s1 and --set s1 took the first
        return text.replace('<ScalarVariable name="s2"', '<ScalarVariable name="s1"', 1)
    fmu = hostile_fmu(rockingwall_fmu, tmp_path / "twice.fmu", md=rename)
    proc = run(fmi2sim_exe, fmu, "--stop-time", "0.1", "--output", tmp_path / "out.csv", check=False)
    assert_one_clear_error(proc, "twice.fmu", "'s1'", "twice")
    assert not (tmp_path / "out.csv").exists()


def test_finding_a_set_given_twice_is_refused(fmi2sim_exe, rockingwall_fmu):
    proc = run(fmi2sim_exe, rockingwall_fmu, "--set", "Kd=1e5", "--set", "Kd=2e5", "--stop-time", "0.1", check=False)
    assert_one_clear_error(proc, "--set Kd", "twice")


def test_finding_an_input_folder_is_named_as_a_folder(fmi2sim_exe, rockingwall_fmu, tmp_path):
    for option in ("--input", "--ag"):
        proc = run(fmi2sim_exe, rockingwall_fmu, option, tmp_path, check=False)
        assert_one_clear_error(proc, str(tmp_path), "folder")
        assert "empty file" not in proc.stderr


def test_finding_a_cvode_failure_names_the_inputs_there(fmi2sim_exe, rockingwall_fmu, tmp_path):
    table = tmp_path / "huge.csv"
    table.write_text("time,ag\n0,1e99\n1,1e99\n")
    proc = run(fmi2sim_exe, rockingwall_fmu, "--input", table, check=False)
    assert_one_clear_error(proc, "huge.csv", "ag = 1e+99")


@pytest.mark.parametrize("attribute, value", [("stopTime", "1e10"), ("startTime", "-1e10")])
def test_finding_an_out_of_range_time_names_the_model_description(fmi2sim_exe, rockingwall_fmu, tmp_path,
                                                                   attribute, value):
    fmu = hostile_fmu(rockingwall_fmu, tmp_path / "far.fmu",
                      md=lambda text: text.replace(f'{attribute}="', f'{attribute}="{value}" x{attribute}="', 1))
    proc = run(fmi2sim_exe, fmu, check=False)
    assert_one_clear_error(proc, value.replace("1e10", "1e+10"), "DefaultExperiment", MD)

"""fmi2sim's stop time with a record: without --stop-time the run covers the whole record (the
inputs' last sample, no tail), not the FMU's DefaultExperiment stopTime (10 s for RockingWall);
an explicit --stop-time before the record's end is run, with a note saying so."""
import subprocess

import numpy as np
import pytest

from test_fmi2sim import write_at2, write_input

RECORD_END = 40.0   # s: longer than RockingWall's DefaultExperiment stopTime (10 s)


def run(exe, *args):
    proc = subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    return proc


def record(dt=0.02):
    """A 40-s record in g: a weak 2 Hz shake that keeps the wall on its base (fast to run)."""
    t = np.arange(0.0, RECORD_END + dt / 2, dt)
    return t, 0.01 * np.sin(2 * np.pi * 2.0 * t)


@pytest.fixture
def at2(tmp_path):
    t, acc_g = record()
    return write_at2(tmp_path / "long.AT2", acc_g, 0.02)


def last_time(csv):
    return float(np.genfromtxt(csv, delimiter=",", names=True)["time"][-1])


def test_ag_record_is_run_to_its_end_by_default(fmi2sim_exe, rockingwall_fmu, tmp_path, at2):
    """Before: 10 s of the 40-s record, silently."""
    out = tmp_path / "out.csv"
    proc = run(fmi2sim_exe, rockingwall_fmu, "--ag", at2, "--output", out)
    assert last_time(out) == pytest.approx(RECORD_END, abs=1e-9)
    assert "note" not in proc.stderr


def test_input_csv_is_run_to_its_end_by_default(fmi2sim_exe, rockingwall_fmu, tmp_path):
    t, acc_g = record()
    out = tmp_path / "out.csv"
    run(fmi2sim_exe, rockingwall_fmu, "--input", write_input(tmp_path / "in.csv", t, acc_g * 9.81), "--output", out)
    assert last_time(out) == pytest.approx(RECORD_END, abs=1e-9)


def test_explicit_stop_before_the_record_end_says_so(fmi2sim_exe, rockingwall_fmu, tmp_path, at2):
    out = tmp_path / "out.csv"
    proc = run(fmi2sim_exe, rockingwall_fmu, "--ag", at2, "--stop-time", 12, "--output", out)
    assert last_time(out) == pytest.approx(12.0, abs=1e-9)
    assert "stops at t = 12 s (--stop-time), before the inputs end at t = 40 s" in proc.stderr


def test_without_inputs_the_default_experiment_stands(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """No record: the FMU's DefaultExperiment stopTime, read from its modelDescription.xml."""
    from fmpy import read_model_description
    out = tmp_path / "out.csv"
    run(fmi2sim_exe, rockingwall_fmu, "--output", out)
    assert last_time(out) == pytest.approx(float(read_model_description(str(rockingwall_fmu)).defaultExperiment.stopTime))


def test_help_states_the_default(fmi2sim_exe):
    text = run(fmi2sim_exe, "--help").stdout
    assert "default with --input/--ag: the time of the inputs' last sample" in text

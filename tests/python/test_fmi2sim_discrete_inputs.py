"""fmi2sim and inputs of every kind (tests/stepinputs: x' = gain u, z' = d + k + b, an FMU that
refuses what FMI 2.0 forbids): a discrete Real, Integer or Boolean input and a tunable parameter
change only at events (time events at the table's samples), a continuous input is set in
continuous time, two rows of one time are a step. The run agrees with the closed form and with
fmpy; Reference-FMUs-style input files run as they are."""
import numpy as np
import pandas as pd
import pytest

from fmi2sim_harness import ASAN_BUILD, assert_one_clear_error, run

# the layout of the Reference FMUs' Feedthrough input file: a step of u at 0.5 (two rows), the
# discrete inputs from 0 to 1 at 1.0, the tunable parameter from 1 to -1 at 1.5
TABLE = """time,u,d,k,b,gain
0.0,0.0,0,0,0,1
0.5,0.0,0,0,0,1
0.5,2.0,0,0,0,1
1.0,1.0,1,1,1,1
1.5,1.0,1,1,1,-1
2.0,1.0,1,1,1,-1
"""


def closed_form(t):
    """x and z of the table above, integrated by hand."""
    t = np.asarray(t, float)
    s = np.clip(t - 0.5, 0.0, 0.5)                     # u = 2 - 2 s on the ramp
    x = 2 * s - s * s + np.clip(t - 1.0, 0.0, 0.5) - np.clip(t - 1.5, 0.0, 0.5)
    z = 3 * np.clip(t - 1.0, 0.0, None)
    return x, z


@pytest.fixture()
def stepinputs_fmu(build_dir):
    path = build_dir / "StepInputs.fmu"
    assert path.exists(), f"{path} is missing: build first"
    return path


def simulate(fmi2sim_exe, fmu, tmp_path, table=TABLE, *extra):
    (tmp_path / "in.csv").write_text(table)
    out = tmp_path / "out.csv"
    proc = run(fmi2sim_exe, fmu, "--input", tmp_path / "in.csv", "--output", out, "--output-interval", "0.05", *extra,
               check=False)
    return proc, out


def test_finding_discrete_inputs_change_only_at_events(fmi2sim_exe, stepinputs_fmu, tmp_path):
    proc, out = simulate(fmi2sim_exe, stepinputs_fmu, tmp_path, TABLE, "--summary", tmp_path / "s.json")
    assert proc.returncode == 0, proc.stderr
    rows = pd.read_csv(out)
    x, z = closed_form(rows.time)
    assert np.abs(rows.x - x).max() < 1e-7 and np.abs(rows.z - z).max() < 1e-7
    # the discrete inputs as the model saw them: 0 up to the row before the event at 1.0, 1 after
    at_one = rows[rows.time == 1.0]
    assert at_one.d_seen.tolist()[0] == 0 and at_one.d_seen.tolist()[-1] == 1
    assert (rows[rows.time < 1.0].k_seen == 0).all() and (rows[rows.time > 1.0].b_seen == 1).all()
    assert rows.events.iloc[-1] == 3  # the step of u at 0.5, d, k and b at 1.0, gain at 1.5


def test_finding_a_discrete_real_input_is_never_set_in_continuous_time(fmi2sim_exe, stepinputs_fmu, tmp_path):
    proc, out = simulate(fmi2sim_exe, stepinputs_fmu, tmp_path, "time,d\n0,0\n0.4,0\n1,2\n")
    assert proc.returncode == 0, proc.stderr  # the FMU refuses fmi2SetReal on d in Continuous-Time Mode
    rows = pd.read_csv(out)
    assert np.abs(rows.z - 2 * np.clip(rows.time - 1.0, 0.0, None)).max() < 1e-9  # held: 0 until 1, then 2


def test_finding_a_repeated_time_is_a_step(fmi2sim_exe, ball_fmu, stepinputs_fmu, tmp_path):
    proc, out = simulate(fmi2sim_exe, stepinputs_fmu, tmp_path, "time,u\n0,0\n0.5,0\n0.5,2\n1,2\n")
    assert proc.returncode == 0, proc.stderr
    rows = pd.read_csv(out)
    expected = 2 * np.clip(rows.time - 0.5, 0.0, None)  # u = 0, then 2 from 0.5 on
    assert np.abs(rows.x - expected).max() < 1e-9
    proc, _ = simulate(fmi2sim_exe, stepinputs_fmu, tmp_path, "time,u\n0,0\n0.5,0\n0.5,2\n0.5,3\n1,2\n")
    assert_one_clear_error(proc, "in.csv:5", "third row")


@pytest.mark.skipif(ASAN_BUILD, reason="fmpy cannot load an FMU built with the sanitizers into this interpreter")
def test_finding_discrete_inputs_agree_with_fmpy(fmi2sim_exe, stepinputs_fmu, tmp_path):
    from fmpy import simulate_fmu
    proc, out = simulate(fmi2sim_exe, stepinputs_fmu, tmp_path)
    assert proc.returncode == 0, proc.stderr
    table = pd.read_csv(pd.io.common.StringIO(TABLE))
    signals = np.array([tuple(r) for r in table.itertuples(index=False)],
                       dtype=[("time", float), ("u", float), ("d", float), ("k", np.int32), ("b", bool), ("gain", float)])
    theirs = simulate_fmu(str(stepinputs_fmu), fmi_type="ModelExchange", stop_time=2.0, input=signals,
                          output=["x", "z", "events"], relative_tolerance=1e-10, output_interval=1e-3)
    ours = pd.read_csv(out).iloc[-1]
    # the discrete inputs alike: the same events, the same z
    assert ours.events == theirs["events"][-1] == 3
    assert ours.z == pytest.approx(theirs["z"][-1], abs=1e-9)
    # fmpy holds continuous inputs over its output interval (1 ms here): x agrees to that order
    assert ours.x == pytest.approx(theirs["x"][-1], abs=3e-3)


@pytest.mark.parametrize("column, value, needle", [("k", "2.5", "Integer"), ("b", "2", "Boolean")])
def test_integer_and_boolean_columns_take_their_values_only(fmi2sim_exe, stepinputs_fmu, tmp_path, column, value, needle):
    table = f"time,{column}\n0,0\n1,{value}\n"
    proc, _ = simulate(fmi2sim_exe, stepinputs_fmu, tmp_path, table)
    assert_one_clear_error(proc, "in.csv", f"'{column}'", needle, "time 1")


def test_a_column_that_is_no_input_is_refused(fmi2sim_exe, stepinputs_fmu, tmp_path):
    proc, _ = simulate(fmi2sim_exe, stepinputs_fmu, tmp_path, "time,x\n0,0\n1,1\n")
    assert_one_clear_error(proc, "in.csv:1", "'x'", "not an input")

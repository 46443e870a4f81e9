"""fmi2sim, the CVODE host: an analytic test FMU, agreement with fmpy and with the reference
solver on RockingWall, its summary, and valgrind's memcheck. Bad input: test_fmi2sim_bad_input.py."""
import math
import shutil
import subprocess

import numpy as np
import pytest

from fmi2sim_harness import ASAN_BUILD, run
from rockingwall import fmu as rw_fmu
from rwref import Params, inputs, simulate


def read_csv(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def bounce_times(data):
    """Times at which the bounce counter steps up (the row after each bounce event)."""
    steps = np.nonzero(np.diff(data["bounces"]) > 0)[0] + 1
    return data["time"][steps]


def analytic_bounces(h0, g, e, n):
    v1 = math.sqrt(2 * g * h0)
    times = [math.sqrt(2 * h0 / g)]
    for k in range(1, n):
        times.append(times[-1] + 2 * e**k * v1 / g)
    return np.array(times)


@pytest.mark.parametrize("solver", ["bdf", "adams"])
def test_ball_hits_the_analytic_bounce_times(fmi2sim_exe, ball_fmu, tmp_path, solver):
    out = tmp_path / "ball.csv"
    run(fmi2sim_exe, ball_fmu, "--solver", solver, "--rtol", "1e-10", "--set", "h=2", "--set", "e=0.8",
        "--stop-time", "5", "--output", out)
    data = read_csv(out)
    got = bounce_times(data)[:5]
    want = analytic_bounces(2.0, 9.81, 0.8, 5)
    np.testing.assert_allclose(got, want, rtol=1e-7)
    # a row before and after each event: the event time appears twice, h = 0 after the bounce
    for t in got:
        rows = data[np.isclose(data["time"], t, rtol=0, atol=1e-12)]
        assert len(rows) >= 2 and rows["v"][0] < 0 < rows["v"][-1]


def test_ball_comes_to_rest_without_zeno(fmi2sim_exe, ball_fmu, tmp_path):
    out = tmp_path / "ball.csv"
    proc = run(fmi2sim_exe, ball_fmu, "--stop-time", "20", "--output", out, "--stats")
    data = read_csv(out)
    assert data["time"][-1] == pytest.approx(20.0)
    assert abs(data["h"][-1]) < 1e-9 and data["v"][-1] == 0.0
    assert "events" in proc.stderr and int(data["bounces"][-1]) < 100


def test_ball_time_event(fmi2sim_exe, ball_fmu, tmp_path):
    out = tmp_path / "ball.csv"
    run(fmi2sim_exe, ball_fmu, "--set", "t_kick=0.2", "--set", "kick=3", "--rtol", "1e-10",
        "--stop-time", "1", "--output", out)
    data = read_csv(out)
    at = data[np.isclose(data["time"], 0.2, rtol=0, atol=1e-12)]
    assert len(at) >= 2
    assert at["v"][-1] - at["v"][0] == pytest.approx(3.0, abs=1e-9)
    assert at["v"][0] == pytest.approx(-9.81 * 0.2, rel=1e-8)


@pytest.mark.skipif(ASAN_BUILD, reason="fmpy (no ASan runtime) cannot load FMUs built with ASan")
def test_ball_agrees_with_fmpy(fmi2sim_exe, ball_fmu, tmp_path):
    from fmpy import simulate_fmu
    out = tmp_path / "ball.csv"
    run(fmi2sim_exe, ball_fmu, "--rtol", "1e-9", "--stop-time", "3", "--output", out)
    ours = bounce_times(read_csv(out))[:5]
    res = simulate_fmu(str(ball_fmu), stop_time=3, relative_tolerance=1e-9, output=["bounces"])
    theirs = bounce_times(res)[:5]
    np.testing.assert_allclose(ours, theirs, rtol=1e-6)


# ---- RockingWall --------------------------------------------------------------------------

def write_input(path, t, a):
    np.savetxt(path, np.column_stack([t, a]), delimiter=",", header="time,ag", comments="")
    return path


def gaussian_signal(t_end=8.0):
    return inputs.sampled(inputs.gaussian(0.04, 1.0), t_end, 0.002)


@pytest.mark.parametrize("model,law", [("simplySupported", "semiRigidHinge"), ("flexibleTop", "semiRigidHinge"),
                                       ("flexibleTop", "semiRigidPaper"), ("flexibleTop", "dohertyHinge")])
def test_rockingwall_agrees_with_fmpy_and_reference(fmi2sim_exe, rockingwall_fmu, tmp_path, model, law):
    sig = gaussian_signal()
    out = tmp_path / "wall.csv"
    sets = rw_fmu.start_values(support=model, hinge_law=law, Kd=1e5)
    args = [a for name, v in sets.items() for a in ("--set", f"{name}={v}")]
    run(fmi2sim_exe, rockingwall_fmu, "--input", write_input(tmp_path / "in.csv", sig.t, sig.a),
        "--rtol", "1e-8", "--stop-time", sig.t[-1], "--output-interval", 0.01, "--output", out, *args)
    data = read_csv(out)
    ref = simulate(Params(support=model, hinge_law=law, Kd=1e5), sig, float(sig.t[-1]),
                   method="DOP853", rtol=1e-9, atol=1e-12)
    peak1, peak2 = np.max(np.abs(data["s1"])), np.max(np.abs(data["s2"]))
    assert peak1 == pytest.approx(ref.peak_s1, rel=0.01)
    assert peak2 == pytest.approx(ref.peak_s2, rel=0.01, abs=1e-6)
    assert int(data["impacts"][-1]) == ref.impacts
    if not ASAN_BUILD:
        fm = rw_fmu.simulate(rockingwall_fmu, float(sig.t[-1]), sig.t, sig.a, rtol=1e-8, support=model,
                             hinge_law=law, Kd=1e5)
        assert peak1 == pytest.approx(fm.peak_s1, rel=0.01)
        assert int(data["impacts"][-1]) == fm.impacts


def write_at2(path, acc_g, dt):
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD", "IMPERIAL VALLEY 1940, EL CENTRO (quakeio copy)",
             "ACCELERATION TIME SERIES IN UNITS OF G", f"NPTS=  {len(acc_g)}, DT=   {dt:.4f} SEC"]
    for i in range(0, len(acc_g), 5):
        lines.append("".join(f"{a:15.7E}" for a in acc_g[i:i + 5]))
    path.write_text("\n".join(lines) + "\n")
    return path


def test_el_centro_csv_and_at2_agree_with_reference(fmi2sim_exe, rockingwall_fmu, tmp_path):
    rec = inputs.el_centro(0.5)
    t_end = float(rec.t[-1])
    common = ["--set", "support=2", "--rtol", "1e-8", "--stop-time", t_end, "--output-interval", 0.01]
    run(fmi2sim_exe, rockingwall_fmu, "--input", write_input(tmp_path / "in.csv", rec.t, rec.a),
        "--output", tmp_path / "csv.csv", *common)
    at2 = write_at2(tmp_path / "elce.AT2", rec.a / 9.81 / 0.5, 0.02)
    run(fmi2sim_exe, rockingwall_fmu, "--ag", at2, "--ag-scale", 0.5, "--output", tmp_path / "at2.csv", *common)
    a, b = read_csv(tmp_path / "csv.csv"), read_csv(tmp_path / "at2.csv")
    ref = simulate(Params(support="simplySupported"), rec, t_end, method="DOP853", rtol=1e-9, atol=1e-12)
    assert np.max(np.abs(a["s1"])) == pytest.approx(ref.peak_s1, rel=0.01)
    assert np.max(np.abs(b["s1"])) == pytest.approx(np.max(np.abs(a["s1"])), rel=1e-5)


@pytest.mark.skipif(shutil.which("valgrind") is None, reason="valgrind is not installed")
@pytest.mark.skipif(ASAN_BUILD, reason="valgrind and ASan do not mix")
def test_valgrind_memcheck_is_clean(fmi2sim_exe, ball_fmu, rockingwall_fmu, tmp_path):
    sig = gaussian_signal(2.0)
    inp = write_input(tmp_path / "in.csv", sig.t, sig.a)
    for args in ([ball_fmu, "--stop-time", "3"], [rockingwall_fmu, "--input", inp, "--stop-time", "2"],
                 [rockingwall_fmu, "--input", tmp_path / "missing.csv"]):
        proc = subprocess.run(["valgrind", "--error-exitcode=99", "--leak-check=full",
                               "--errors-for-leak-kinds=definite", str(fmi2sim_exe), *map(str, args),
                               "--output", str(tmp_path / "o.csv")], capture_output=True, text=True, timeout=300)
        assert proc.returncode in (0, 2), proc.stderr[-3000:]   # 2: the intended error exit, 99: memcheck errors
        assert "ERROR SUMMARY: 0 errors" in proc.stderr, proc.stderr[-3000:]


def test_summary_gives_peaks_and_final_values_without_time_history(fmi2sim_exe, ball_fmu, tmp_path):
    """--summary: max |value| and last value of every output; alone it writes no time history."""
    import json
    common = ["--set", "h=2", "--set", "e=0.8", "--rtol", "1e-10", "--stop-time", "5"]
    alone = run(fmi2sim_exe, ball_fmu, *common, "--summary", tmp_path / "alone.json")
    assert alone.stdout == ""
    run(fmi2sim_exe, ball_fmu, *common, "--output", tmp_path / "ball.csv", "--summary", tmp_path / "both.json")
    alone_out = json.loads((tmp_path / "alone.json").read_text())["outputs"]
    both = json.loads((tmp_path / "both.json").read_text())
    assert both["outputs"] == alone_out  # the CSV does not change the peaks
    assert both["end_time"] == 5 and both["terminated_by_model"] is False
    data = read_csv(tmp_path / "ball.csv")
    assert set(alone_out) == set(data.dtype.names) - {"time"}
    assert alone_out["h"]["max_abs"] == 2.0  # dropped from rest at h = 2
    assert alone_out["v"]["max_abs"] == pytest.approx(math.sqrt(2 * 9.81 * 2.0), rel=1e-7)  # first impact
    for name, s in alone_out.items():
        assert s["final"] == pytest.approx(data[name][-1], rel=1e-11, abs=1e-11)
        assert s["max_abs"] >= np.max(np.abs(data[name])) * (1 - 1e-11)  # steps as well as rows

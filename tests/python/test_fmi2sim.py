"""fmi2sim, the CVODE host: an analytic test FMU, agreement with fmpy and with the reference
solver on RockingWall, and a clear message with a non-zero exit for every kind of bad input."""
import math
import os
import re
import shutil
import subprocess
import zipfile

import numpy as np
import pytest

from rockingwall import fmu as rw_fmu
from rwref import Params, inputs, simulate

ASAN_BUILD = "asan" in str(os.environ.get("RW_BUILD_DIR", ""))


def run(exe, *args, check=True):
    proc = subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True, timeout=300)
    if check:
        assert proc.returncode == 0, proc.stderr
    return proc


def read_csv(path):
    return np.genfromtxt(path, delimiter=",", names=True)


@pytest.fixture(scope="module")
def ball_fmu(build_dir):
    path = build_dir / "BouncingBall.fmu"
    assert path.exists(), f"{path} is missing: build it first"
    return path


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


# ---- bad input: one clear message, non-zero exit -----------------------------------------

def bad_zip(tmp_path):
    p = tmp_path / "nomd.fmu"
    with zipfile.ZipFile(p, "w") as z:
        z.writestr("binaries/linux64/x.so", b"")
    return p


def wrong_guid(tmp_path, ball):
    d = tmp_path / "wrongguid"
    with zipfile.ZipFile(ball) as z:
        z.extractall(d)
    md = d / "modelDescription.xml"
    md.write_text(md.read_text().replace("{6f3d1f0e-2b1c-4c1a-9a55-b0c1d2e3f401}", "{00000000-0000-0000-0000-000000000000}"))
    out = tmp_path / "wrongguid.fmu"
    shutil.make_archive(str(out.with_suffix("")), "zip", d)
    out.with_suffix(".zip").rename(out)
    return out


CSV_CASES = {
    "empty": ("", "empty file"),
    "header_only": ("time,ag\n", "no data rows"),
    "non_numeric": ("time,ag\n0,0\n0.1,abc\n", ":3: column 2: 'abc' is not a number"),
    "non_monotonic": ("time,ag\n0,0\n0.2,1\n0.1,2\n", ":4: time 0.1 is before"),
    "duplicate_time": ("time,ag\n0,0\n0.1,1\n0.1,2\n", ":4: time 0.1 repeats"),
    "column_count": ("time,ag\n0,0\n0.1,1,5\n", ":3: 3 columns, the header has 2"),
    "unknown_column": ("time,nosuch\n0,0\n", "column 'nosuch' is not a variable"),
    "huge": ("time,ag\n0,0\n0.1,1e999\n", ":3: column 2: '1e999' is out of range"),
    "binary": ("time,ag\n0,0\x00\x01\x02\n", ":2: binary data"),
    # finite but absurd values would overflow inside the model, far from their line
    "huge_finite": ("time,ag\n0,0\n0.1,1e300\n", ":3: column 2: '1e300' is out of range"),
    "huge_time": ("time,ag\n0,0\n-1e300,0\n", ":3: column 1: '-1e300' is out of range"),
    "nan_time": ("time,ag\nnan,0\n", ":2: column 1: 'nan' is out of range"),
    "inf_value": ("time,ag\n0,inf\n", ":2: column 2: 'inf' is out of range"),
    "truncated": ("time,ag\n0,0\n0.1,", ":3: column 2 is empty"),
    "truncated_number": ("time,ag\n0,0\n0.1,1e", ":3: column 2: '1e' is not a number"),
    "empty_field": ("time,ag\n0,0\n0.1,,1\n", ":3: column 2 is empty"),   # was read as "0.1,1"
    "header_gap": ("time,,ag\n0,0,0\n", ":1: header column 2 has no name"),
    "gzip": ("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03", ":1: binary data"),
    "png": ("\x89PNG\r\n\x1a\n\x00\x00", ":1: header names no input column"),
    "output_column": ("time,s1\n0,0\n", ":1: 's1' is not an input of the model"),
    "blank_lines_only": ("\n\n  \n", "empty file"),
}


def assert_one_clear_error(proc, *needles):
    """Non-zero exit, exactly one 'fmi2sim: error:' line holding every needle, no sanitizer report."""
    assert proc.returncode != 0, proc.stderr
    errors = [line for line in proc.stderr.splitlines() if line.startswith("fmi2sim: error:")]
    assert len(errors) == 1, proc.stderr
    for needle in needles:
        assert str(needle) in errors[0], (needle, proc.stderr)
    for report in ("Sanitizer", "runtime error", "Segmentation", "Traceback"):
        assert report not in proc.stderr, proc.stderr


AT2_CASES = {
    "bad_header": ("a\nb\nc\nno numbers here\n0.1 0.2\n", ":4: expected 'NPTS= N, DT= dt SEC'"),
    "npts_mismatch": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 0.2\n", "2 values, the header says NPTS = 3"),
    "non_numeric": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 x 0.3\n", ":5: 'x' is not a number"),
    "truncated": ("a\nb\n", ":3: file ends inside the 4-line AT2 header"),
    "empty": ("", ":1: file ends inside the 4-line AT2 header"),
    "binary": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1\x00\x07 0.2\n", ":5: binary data"),
    "huge": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 1e400 0.3\n", ":5: '1e400' is out of range"),
    "huge_finite": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 1e300 0.3\n", ":5: '1e300' is out of range"),
    "nan": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 nan 0.3\n", ":5: 'nan' is out of range"),
    "dt_zero": ("a\nb\nc\nNPTS=  3, DT=   0 SEC\n0.1 0.2 0.3\n", ":4: expected 'NPTS= N, DT= dt SEC'"),
    "dt_huge": ("a\nb\nc\nNPTS=  3, DT=   1e308 SEC\n0.1 0.2 0.3\n", ":4: NPTS * DT = 3 * 1e+308 is out of range"),
    "npts_negative": ("a\nb\nc\nNPTS=  -3, DT=   .02 SEC\n0.1 0.2 0.3\n", ":4: expected 'NPTS= N, DT= dt SEC'"),
    "npts_too_large": ("a\nb\nc\nNPTS=  999999999, DT=   .02 SEC\n0.1\n", ":4: NPTS = 999999999 is too large"),
    "npts_claims_more": ("a\nb\nc\nNPTS=  99999999, DT=   .02 SEC\n0.1\n", "1 values, the header says NPTS = 99999999"),
    "more_than_npts": ("a\nb\nc\nNPTS=  2, DT=   .02 SEC\n0.1 0.2\n0.3\n", ":6: more values than NPTS = 2"),
}


# (option, file suffix, cases) of the two readers of input files
READERS = [("--input", ".csv", CSV_CASES), ("--ag", ".AT2", AT2_CASES)]


@pytest.mark.parametrize("option,suffix,case", [(o, x, c) for o, x, cases in READERS for c in sorted(cases)])
def test_input_file_errors_name_file_and_line(fmi2sim_exe, rockingwall_fmu, tmp_path, option, suffix, case):
    text, message = (CSV_CASES if suffix == ".csv" else AT2_CASES)[case]
    path = tmp_path / f"{case}{suffix}"
    path.write_bytes(text.encode("latin-1"))
    proc = run(fmi2sim_exe, rockingwall_fmu, option, path, check=False)
    assert_one_clear_error(proc, path, message)


def test_at2_scale_that_overflows_is_reported(fmi2sim_exe, rockingwall_fmu, tmp_path):
    path = tmp_path / "ok.AT2"
    path.write_text("a\nb\nc\nNPTS=  2, DT=   .0200 SEC\n0.1 0.2\n")
    proc = run(fmi2sim_exe, rockingwall_fmu, "--ag", path, "--ag-scale", "1e300", check=False)
    assert_one_clear_error(proc, f"{path}:5:", "is out of range")


def repacked(tmp_path, fmu, name, change):
    """A copy of `fmu` with change(folder) applied to its unpacked files."""
    d = tmp_path / name
    with zipfile.ZipFile(fmu) as z:
        z.extractall(d)
    change(d)
    out = tmp_path / f"{name}.fmu"
    shutil.make_archive(str(out.with_suffix("")), "zip", d)
    out.with_suffix(".zip").rename(out)
    return out


def test_broken_fmus_name_the_file(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """An FMU that is empty, cut short, without its binary, with a broken binary or XML, a GUID its
    binary does not know, or a folder without modelDescription.xml: one error naming it."""
    so = "binaries/linux64/RockingWall.so"
    empty = tmp_path / "empty.fmu"
    empty.write_bytes(b"")
    cut = tmp_path / "cut.fmu"
    cut.write_bytes(rockingwall_fmu.read_bytes()[:20000])
    no_md = tmp_path / "folder"
    no_md.mkdir()
    cases = [
        (empty, "not a valid FMU"),
        (cut, "not a valid FMU"),
        (repacked(tmp_path, rockingwall_fmu, "nobin", lambda d: (d / so).unlink()), "cannot load the FMU binary"),
        (repacked(tmp_path, rockingwall_fmu, "badso", lambda d: (d / so).write_text("not ELF")), "cannot load the FMU binary"),
        (repacked(tmp_path, rockingwall_fmu, "badxml",
                  lambda d: (d / "modelDescription.xml").write_text("<fmiModelDescription")), "modelDescription.xml:1: not well-formed XML"),
        (repacked(tmp_path, rockingwall_fmu, "guid", lambda d: (d / "modelDescription.xml").write_text(
            re.sub(r'guid="\{[^}]*\}"', 'guid="{00000000-0000-0000-0000-000000000000}"',
                   (d / "modelDescription.xml").read_text()))), "GUID"),
        (no_md, "modelDescription.xml: No such file"),
    ]
    for fmu, message in cases:
        proc = run(fmi2sim_exe, fmu, "--stop-time", "0.1", check=False)
        assert_one_clear_error(proc, fmu, message)


def test_fmu_and_option_errors(fmi2sim_exe, ball_fmu, tmp_path):
    cases = [
        ([tmp_path / "missing.fmu"], "No such file"),
        ([tmp_path / "notzip.fmu"], "not a valid FMU"),
        ([bad_zip(tmp_path)], "modelDescription.xml"),
        ([wrong_guid(tmp_path, ball_fmu)], "GUID"),
        ([ball_fmu, "--set", "nosuch=1"], "no variable 'nosuch'"),
        ([ball_fmu, "--set", "e=abc"], "'abc' is not a Real"),
        ([ball_fmu, "--set", "bounces=1"], "cannot be set"),
        ([ball_fmu, "--set", "der(h)=1"], "cannot be set"),
        ([ball_fmu, "--frobnicate"], "unknown option"),
        ([ball_fmu, "--rtol"], "--rtol needs a value"),
        ([ball_fmu, "--rtol", "-1"], "--rtol -1 is out of range: it must lie in [1e-12, 0.01]"),
    ]
    (tmp_path / "notzip.fmu").write_text("this is not a zip file")
    for args, message in cases:
        proc = run(fmi2sim_exe, *args, check=False)
        assert proc.returncode != 0, args
        assert message in proc.stderr, (args, proc.stderr)
        assert "Traceback" not in proc.stderr and "Segmentation" not in proc.stderr


def test_integer_type_is_checked(fmi2sim_exe, rockingwall_fmu):
    proc = run(fmi2sim_exe, rockingwall_fmu, "--set", "support=1.5", check=False)
    assert proc.returncode != 0 and "'1.5' is not an Integer" in proc.stderr


def test_fmu_error_is_reported(fmi2sim_exe, rockingwall_fmu):
    proc = run(fmi2sim_exe, rockingwall_fmu, "--set", "h=-1", check=False)
    assert proc.returncode != 0 and "fmi2SetReal" in proc.stderr and "h" in proc.stderr


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

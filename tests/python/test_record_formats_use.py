"""The downloaded record formats where users meet them: `rockingwall run FILE --pga 0.3 --wall
paper1` runs on each and gives the peaks of the file's two-column source; a sweep over a folder of
them runs each record's own samples (converted once to an AT2 file that the exact engine and
fmi2sim read), with the peaks of `rockingwall run`, and computes again only the record whose file
changed."""
import json

import numpy as np
import pandas as pd
import pytest

import record_files as rf
from record_files import FORMATS, write
from rockingwall import cli, records
from rockingwall.commands import sweep as command
from rockingwall.sweep import suites as suite

NAMES = {"esm": "r HNE", "knet": "r EW", "geonet": "r N28W", "cosmos": "r chan 1"}  # the records' names


def run_json(capsys, *args):
    """`rockingwall run ARGS --json` in this process: (exit status, the JSON it printed)."""
    capsys.readouterr()
    status = cli.main(["run", *map(str, args), "--json"])
    out = capsys.readouterr().out
    return status, (json.loads(out) if status == 0 else None)


@pytest.mark.parametrize("fmt", FORMATS)
def test_run_takes_each_format_like_its_two_column_source(fmt, tmp_path, capsys):
    path = tmp_path / FORMATS[fmt]
    rf.two_columns(tmp_path / "source.csv", write(fmt, path))
    status, got = run_json(capsys, path, "--pga", "0.3", "--wall", "paper1")
    assert status == 0
    status, want = run_json(capsys, tmp_path / "source.csv", "--csv-units", "m/s2", "--pga", "0.3", "--wall", "paper1")
    assert status == 0
    (run,), (source_run,) = got["runs"], want["runs"]
    assert run.pop("record") == f"{NAMES[fmt]} at 0.3 g" and source_run.pop("record") == "source at 0.3 g"
    assert run.pop("engine") == source_run.pop("engine") == "exact"
    # peaks, impacts, the time of collapse (a collapsed wall's peaks are null in both)
    assert [k for k, v in run.items() if v is None] == [k for k, v in source_run.items() if v is None]
    numbers = {k: v for k, v in source_run.items() if v is not None}
    assert {k: run[k] for k in numbers} == pytest.approx(numbers, rel=1e-12, nan_ok=True)


def test_run_refuses_a_damaged_file_with_its_line_and_no_traceback(tmp_path, capsys):
    path = tmp_path / "r.V2A"
    write("geonet", path)
    lines = path.read_text().splitlines()
    lines[25] = lines[25][:8] + "  x.5000" + lines[25][16:]  # a real of the first component's header
    path.write_text("\n".join(lines) + "\n")
    capsys.readouterr()
    assert cli.main(["run", str(path), "--pga", "0.3", "--wall", "paper1"]) == 2
    err = capsys.readouterr().err
    assert f"{path}:26: cannot read 'x.5000' as a number" in err and "Traceback" not in err


@pytest.fixture()
def formats_suite(tmp_path, monkeypatch):
    """A folder with a file of each format (and a note that is not a record), the conversion cache
    in the test's folder."""
    monkeypatch.setenv("RW_RECORDS_CACHE", str(tmp_path / "cache"))
    folder = tmp_path / "suite"
    folder.mkdir()
    for fmt, name in FORMATS.items():
        write(fmt, folder / name)
    (folder / "notes.txt").write_text("where the records come from\n")
    return folder


def test_a_suite_folder_takes_each_format_with_its_own_samples_and_hash(formats_suite, tmp_path):
    recs = {r.name: r for r in suite.at2_folder(formats_suite)}
    assert set(recs) == set(NAMES.values()) and not any(r.error for r in recs.values())
    assert len({r.sha256 for r in recs.values()}) == 4
    for fmt, name in NAMES.items():
        r = recs[name]
        assert str(tmp_path / "cache" / "converted") in r.path
        given = records.load(formats_suite / FORMATS[fmt])
        converted = records.read_at2(r.path)  # what the exact engine's tasks and fmi2sim read
        np.testing.assert_allclose(converted.ag, given.ag, rtol=1e-15, atol=0)
        np.testing.assert_array_equal(converted.t, given.t)
        assert r.pga_g == pytest.approx(given.pga / records.G_STD, rel=1e-15)
        assert r.duration == pytest.approx(given.t[-1], rel=1e-12)
    # the same files give the same cached files and hashes; another component is another record
    assert {r.name: r.sha256 for r in suite.at2_folder(formats_suite)} == {n: r.sha256 for n, r in recs.items()}


def sweep(folder, out, *extra):
    return command.main(["--suite", str(folder), "--walls", "paper1", "--kd", "50", "--pga", "0.3", "--tail", "0",
                         "--out", str(out), "--scheduler", "synchronous", "--no-progress", *extra])


def test_a_sweep_runs_the_formats_like_run_and_resumes_by_content(formats_suite, tmp_path, capsys):
    out = tmp_path / "sweep.csv"
    assert sweep(formats_suite, out) == 0
    rows = pd.read_csv(out).set_index("record")
    assert set(rows.index) == set(NAMES.values()) and (rows["status"] == "ok").all()
    for fmt, name in NAMES.items():
        status, got = run_json(capsys, formats_suite / FORMATS[fmt], "--pga", "0.3", "--wall", "paper1",
                               "--Kd", "50kN/m/m")
        assert status == 0
        (run,) = got["runs"]
        assert bool(rows.loc[name, "collapsed"]) == run["collapsed"]
        if run["collapsed"]:  # run's JSON gives the collapse's time, the sweep's row where the run ended
            assert rows.loc[name, "end_time"] == pytest.approx(run["t_collapse_s"], rel=1e-9)
        else:
            assert rows.loc[name, "peak_s1"] == pytest.approx(run["peak_s1_m"], rel=1e-9)
            assert rows.loc[name, "peak_s2"] == pytest.approx(run["peak_s2_m"], rel=1e-9)
    capsys.readouterr()
    assert sweep(formats_suite, out) == 0
    assert "nothing to do: all 4 runs are done" in capsys.readouterr().out
    write("knet", formats_suite / FORMATS["knet"], scale=1.1)  # the K-NET record is edited in place
    assert sweep(formats_suite, out) == 0
    assert "1 runs (0 errors, 0 killed or timed out, 3 already done)" in capsys.readouterr().out


def test_fmi2sim_reads_the_converted_record_of_a_sweep(formats_suite, tmp_path, fmi2sim_exe, rockingwall_fmu):
    exact, cvode = tmp_path / "exact.csv", tmp_path / "fmi2sim.csv"
    assert sweep(formats_suite, exact, "--records", "r N28W") == 0
    assert sweep(formats_suite, cvode, "--records", "r N28W", "--engine", "fmi2sim", "--fmi2sim", str(fmi2sim_exe),
                 "--fmu", str(rockingwall_fmu)) == 0
    a, b = pd.read_csv(exact).iloc[0], pd.read_csv(cvode).iloc[0]
    assert b["status"] == "ok" and b["record_sha256"] == a["record_sha256"]
    assert b["peak_s1"] == pytest.approx(a["peak_s1"], rel=1e-4)


def test_a_damaged_file_in_a_suite_becomes_error_rows_naming_its_line(formats_suite, tmp_path):
    path = formats_suite / FORMATS["esm"]
    path.write_text(path.read_text().replace("NDATA: 400", "NDATA: 399"))
    (bad,) = [r for r in suite.at2_folder(formats_suite) if r.error]
    assert bad.error.startswith(f"{path}:") and "the header announces 399 samples" in bad.error
    out = tmp_path / "sweep.csv"
    assert sweep(formats_suite, out) == 0
    rows = pd.read_csv(out)
    errors = rows[rows["status"] == "error"]
    assert len(errors) == 1 and "the header announces 399 samples" in errors["message"].iloc[0]

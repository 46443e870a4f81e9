"""The sweeps under hostile use: resumed results are never reused from other inputs, killed runs are never
counted as finished, a damaged results line costs that line only, one sweep per results file,
absurd options and hostile files are refused with a message, and nothing is left in the temporary
folder. Each test is named after its finding and failed on the code before the fix."""
import os
import pathlib
import subprocess
import sys
import time
import zipfile

import numpy as np
import pandas as pd
import pytest

from rockingwall.commands import ida as ida_command
from rockingwall.commands import sweep
from rockingwall.sweep import ida
from rockingwall.sweep import fmi2sim_task, suites
from rockingwall.sweep import rows as result_rows
from test_sweep import pulse_record



@pytest.fixture()
def one_record(tmp_path):
    d = tmp_path / "suite"
    d.mkdir()
    pulse_record(d / "p1.AT2", 0.10, 0.6)
    return d


@pytest.fixture()
def private_tmp(tmp_path, monkeypatch):
    """A temporary folder of the test's own (TMPDIR for this process and its children), so a
    test can check that a sweep leaves nothing in it."""
    import tempfile
    tmp = tmp_path / "tmpdir"
    tmp.mkdir()
    monkeypatch.setenv("TMPDIR", str(tmp))
    monkeypatch.setattr(tempfile, "tempdir", str(tmp))
    return tmp


def sweep_args(suite, out, fmi2sim, fmu, *extra):
    return ["--suite", str(suite), "--kd", "50", "--scales", "1", "--tail", "1", "--scheduler", "synchronous", "--engine", "fmi2sim",
            "--no-progress", "--out", str(out), "--fmi2sim", str(fmi2sim), "--fmu", str(fmu), *map(str, extra)]


def rows(path):
    return pd.read_csv(path)


def fake_fmi2sim(path, real, action):
    """An fmi2sim stand-in: runs `action` (shell) while the file MARKER beside it exists, then the
    real fmi2sim. Its content does not change when the marker goes, so neither does its hash."""
    marker = path.with_name("MARKER")
    path.write_text(f'#!/bin/sh\nif [ -e "{marker}" ]; then\n{action}\nfi\nexec "{real}" "$@"\n')
    path.chmod(0o755)
    marker.touch()
    return marker


# ---------------------------------------------------------------- finding 2: the key of a row

def test_finding02_resume_key_covers_record_content(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path, capsys):
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, fmi2sim_exe, rockingwall_fmu)
    assert sweep.main(args) == 0
    weak = rows(out).peak_s1[0]
    pulse_record(one_record / "p1.AT2", 0.30, 0.6)  # same name, other content
    capsys.readouterr()
    assert sweep.main(args) == 0
    err = capsys.readouterr().err
    assert "1 rows of" in err and "not reused" in err and "record content differs" in err
    fresh = tmp_path / "fresh.csv"
    assert sweep.main(sweep_args(one_record, fresh, fmi2sim_exe, rockingwall_fmu)) == 0
    got = rows(out)
    assert len(got) == 1 and got.peak_s1[0] == rows(fresh).peak_s1[0] != weak
    backups = list(tmp_path.glob("res.csv.set-aside-*"))  # the stale row is kept, not deleted
    assert len(backups) == 1 and str(weak) in backups[0].read_text()


def test_finding02_resume_key_covers_fmu_and_fmi2sim(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path, capsys):
    import shutil
    fmu, exe = tmp_path / "RockingWall.fmu", tmp_path / "fmi2sim"
    shutil.copy(rockingwall_fmu, fmu)
    shutil.copy(fmi2sim_exe, exe)
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, exe, fmu)
    assert sweep.main(args) == 0
    with zipfile.ZipFile(fmu, "a") as z:  # another build of the FMU: one member more
        z.writestr("resources/changed.txt", "another build")
    capsys.readouterr()
    assert sweep.main(args) == 0
    assert "FMU differs" in capsys.readouterr().err
    with open(exe, "ab") as f:  # another fmi2sim (bytes after the ELF image: it still runs)
        f.write(b"\0another build")
    assert sweep.main(args) == 0
    assert "fmi2sim differs" in capsys.readouterr().err
    assert sweep.main(args + ["--rtol", "1e-7"]) == 0  # other settings: another run, both kept
    assert len(rows(out)) == 2 and (rows(out).status == "ok").all()
    assert sweep.main(args) == 0
    assert "nothing to do" in capsys.readouterr().out


def test_finding02_rows_without_a_key_are_recomputed_and_kept_aside(fmi2sim_exe, rockingwall_fmu, one_record,
                                                                     tmp_path, capsys):
    """A results file of the sweep before keys (no provenance columns): its rows cannot be shown
    to match, so the planned ones are run again; the others stay, with the new columns."""
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, fmi2sim_exe, rockingwall_fmu)
    assert sweep.main(args) == 0
    old = rows(out)[result_rows.COLUMNS[:result_rows.COLUMNS.index("key")]]
    other = old.assign(run_id="another plan's run")
    pd.concat([old, other]).to_csv(out, index=False, lineterminator="\n")
    capsys.readouterr()
    assert sweep.main(args) == 0
    assert "1 no key (written before keys were recorded)" in capsys.readouterr().err
    d = rows(out)
    assert list(d.columns) == result_rows.COLUMNS and len(d) == 2
    by_id = d.set_index("run_id")
    assert pd.isna(by_id.loc["another plan's run", "key"])  # not ours to judge: kept, without a key
    assert len(by_id.drop("another plan's run").key.iloc[0]) == 16  # the planned run, computed again
    assert len(next(tmp_path.glob("res.csv.set-aside-*")).read_text().splitlines()) == 2


# ---------------------------------------------------------------- finding 3: killed runs

def test_finding03_killed_runs_are_retried_on_resume_and_reported(fmi2sim_exe, rockingwall_fmu, one_record,
                                                                   tmp_path, capsys):
    exe = tmp_path / "fmi2sim_oom"
    marker = fake_fmi2sim(exe, fmi2sim_exe, "kill -9 $$")  # the OOM killer's SIGKILL
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, exe, rockingwall_fmu, "--scales", "0.5", "1")
    assert sweep.main(args) == 1  # not finished
    d = rows(out)
    assert (d.status == "killed").all() and d.message.str.contains("signal 9").all()
    assert "2 runs were killed or timed out" in capsys.readouterr().err
    # ida.py names them instead of dropping them silently
    assert ida.report_not_ok(d.astype(str).replace("nan", ""), out) is None
    assert "2 runs were killed or timed out and are NOT in the plots" in capsys.readouterr().err
    marker.unlink()
    assert sweep.main(args) == 0  # the same command: the killed runs are run again
    assert "2 killed or timed-out rows" in capsys.readouterr().err
    d = rows(out)
    assert len(d) == 2 and (d.status == "ok").all()


def test_finding03_timed_out_runs_are_retried(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path, private_tmp, capsys):
    exe = tmp_path / "fmi2sim_slow"
    # what fmi2sim does first (unpack the FMU into $TMPDIR), then never finish
    marker = fake_fmi2sim(exe, fmi2sim_exe, 'mkdir "$TMPDIR/fmi2sim_unpacked"; exec sleep 60')
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, exe, rockingwall_fmu)
    runner_timeout = fmi2sim_task.TIMEOUT_S
    try:
        fmi2sim_task.TIMEOUT_S = 1.0
        assert sweep.main(args) == 1
    finally:
        fmi2sim_task.TIMEOUT_S = runner_timeout
    assert rows(out).status[0] == "timeout"
    assert list(private_tmp.iterdir()) == []  # finding 9: the killed run's files are gone
    marker.unlink()
    assert sweep.main(args) == 0
    assert rows(out).status.tolist() == ["ok"]


# ---------------------------------------------------------------- finding 4: a damaged line

def test_finding04_damaged_line_costs_only_that_line(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path, capsys):
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, fmi2sim_exe, rockingwall_fmu, "--scales", *np.arange(1, 9) / 8)
    assert sweep.main(args) == 0
    lines = out.read_text().splitlines(keepends=True)
    assert len(lines) == 9
    damaged = lines[2].replace(",ok,", ',"ok,', 1)  # an unmatched quote on line 3
    out.write_text("".join(lines[:2]) + damaged + "".join(lines[3:]))
    capsys.readouterr()
    assert sweep.main(args) == 1  # complete again, but the damage is not hidden from a script
    captured = capsys.readouterr()
    assert f"{out}:3: " in captured.err and "set aside" in captured.err
    assert "1 runs (" in captured.out and "7 already done" in captured.out  # only the damaged run again
    again = out.read_text().splitlines(keepends=True)
    untouched = lines[1:2] + lines[3:]
    assert again[1:-1] == untouched  # the 7 good rows kept byte for byte, the damaged run appended
    cols = ["run_id", "peak_s1", "peak_s2", "collapsed"]
    assert again[-1].split(",")[:1] == lines[2].split(",")[:1]
    pd.testing.assert_frame_equal(rows(out)[cols].sort_values("run_id").reset_index(drop=True),
                                  pd.read_csv(pd.io.common.StringIO("".join(lines)))[cols]
                                  .sort_values("run_id").reset_index(drop=True))
    backup = next(tmp_path.glob("res.csv.set-aside-*")).read_text()
    assert damaged in backup  # set aside, never deleted


def test_finding04_analysis_keeps_every_good_row(tmp_path, capsys):
    path = synthetic_results(tmp_path)
    lines = path.read_text().splitlines(keepends=True)
    lines[5] = lines[5].replace(",ok,", ',"ok,', 1)
    path.write_text("".join(lines))
    rows_read = ida.load(path, 1, "flexibleTop", "dohertyHinge")
    assert len(rows_read) == len(lines) - 2
    assert f"{path}:6: " in capsys.readouterr().err


# ---------------------------------------------------------------- finding 9: temporary files

@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_finding09_interrupted_sweep_leaves_no_temporary_files(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path,
                                                               private_tmp, sig):
    """Ctrl-C (SIGINT) or SIGTERM while a run is under way: the sweep removes its folders and
    says how to resume."""
    exe = tmp_path / "fmi2sim_interrupt"
    # the sweep process is the stand-in's parent; the sleep stands for a long run
    fake_fmi2sim(exe, fmi2sim_exe, f'mkdir "$TMPDIR/fmi2sim_unpacked"; kill -{sig} $PPID; exec sleep 30')
    out = tmp_path / "res.csv"
    proc = subprocess.run([sys.executable, "-m", "rockingwall", "sweep",
                           *sweep_args(one_record, out, exe, rockingwall_fmu)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 130, proc.stderr[-2000:]
    assert "run the same command again to resume" in proc.stderr
    assert list(private_tmp.iterdir()) == []


def test_finding09_killed_dask_worker_leaves_no_temporary_files(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path,
                                                               private_tmp, capsys):
    """A Dask worker killed in the middle of a run (OOM): the runs become 'killed' rows, run again
    on resume, and the killed run's files are removed with the sweep's folder."""
    import dask
    import distributed  # noqa: F401  loads its config first: set() would otherwise drop it on exit
    exe = tmp_path / "fmi2sim_kills_worker"
    pid_file = tmp_path / "orphan.pid"
    # a long run whose worker dies under it: the run (its command line kept, as fmi2sim's) is left
    # an orphan
    marker = fake_fmi2sim(exe, fmi2sim_exe, f'mkdir "$TMPDIR/fmi2sim_unpacked"; echo $$ > "{pid_file}"; kill -9 $PPID; '
                                            f'exec "{sys.executable}" -c "import time; time.sleep(60)" "$@"')
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, exe, rockingwall_fmu, "--workers", 1)
    args.remove("--scheduler"), args.remove("synchronous")
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):  # no retry inside Dask
        assert sweep.main(args) == 1
    assert rows(out).status.tolist() == ["killed"]
    assert not [p for p in private_tmp.iterdir() if p.name.startswith(("rw_sweep", "fmi2sim"))]
    orphan = pathlib.Path(f"/proc/{int(pid_file.read_text())}")
    for _ in range(50):  # SIGKILLed by the sweep; init reaps it
        if not orphan.exists():
            break
        time.sleep(0.1)
    assert not orphan.exists(), "the killed worker's run is still running"
    marker.unlink()
    assert sweep.main(args) == 0
    assert rows(out).status.tolist() == ["ok"]
    assert not [p for p in private_tmp.iterdir() if p.name.startswith(("rw_sweep", "fmi2sim"))]


# ---------------------------------------------------------------- finding 16: hostile use

def test_finding16_second_sweep_on_the_same_file_is_refused(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path, capsys):
    """A second sweep on a results file a running sweep is writing is refused, naming the first."""
    exe = tmp_path / "fmi2sim_slow_start"
    started = tmp_path / "STARTED"
    fake_fmi2sim(exe, fmi2sim_exe, f'touch "{started}"; sleep 4')
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, exe, rockingwall_fmu)
    first = subprocess.Popen([sys.executable, "-m", "rockingwall", "sweep", *args],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 60
        while not started.exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert started.exists()
        assert sweep.main(args) == 2
    finally:
        first.communicate(timeout=120)
    assert first.returncode == 0
    err = capsys.readouterr().err
    assert "in use by another sweep" in err and f"pid {first.pid}" in err
    assert len(rows(out)) == 1  # computed once
    assert sweep.main(args) == 0  # the lock went with the first sweep
    assert "nothing to do" in capsys.readouterr().out


def test_finding16_ida_counts_a_run_once(tmp_path):
    path = synthetic_results(tmp_path)
    lines = path.read_text().splitlines(keepends=True)
    path.write_text("".join(lines + lines[1:4]))  # two sweeps wrote three runs twice
    assert len(ida.load(path, 1, "flexibleTop", "dohertyHinge")) == len(lines) - 1


def test_finding16_finished_sweep_run_again_says_nothing_to_do(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path,
                                                               capsys):
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, fmi2sim_exe, rockingwall_fmu)
    assert sweep.main(args) == 0
    args.remove("--scheduler"), args.remove("synchronous")  # a LocalCluster: must not even start
    capsys.readouterr()
    assert sweep.main(args + ["--workers", "1"]) == 0
    assert "nothing to do: all 1 runs are done" in capsys.readouterr().out


@pytest.mark.parametrize("option, value, range_text", [
    ("--workers", "0", "[1, 1024]"), ("--workers", "-3", "[1, 1024]"), ("--batch", "0", "[1, 100000]"),
    ("--timeout", "0", "[1, 604800]"), ("--timeout", "nan", "[1, 604800]"), ("--kd", "0", "(0, 1e+09]"),
    ("--kd", "inf", "(0, 1e+09]"), ("--scales", "-1", "(0, 100]"), ("--pga", "1e9", "(0, 10]"),
    ("--er", "2", "[0, 1]"), ("--tail", "-1", "[0, 3600]"), ("--rtol", "10", "[1e-12, 0.01]"),
    ("--scan-workers", "0", "[1, 1024]")])
def test_finding16_absurd_options_are_refused_with_the_range(one_record, tmp_path, capsys, option, value, range_text):
    argv = ["--suite", str(one_record), "--out", str(tmp_path / "res.csv"), "--dry-run", option, value]
    assert sweep.main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("rockingwall sweep: error: ") and range_text in err and "Traceback" not in err


def test_finding16_fifo_record_is_refused_before_planning(one_record, tmp_path):
    os.mkfifo(one_record / "x.AT2")
    proc = subprocess.run([sys.executable, "-m", "rockingwall", "sweep", "--suite", str(one_record),
                           "--out", str(tmp_path / "res.csv"), "--dry-run"], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2
    assert f"{one_record / 'x.AT2'}: not a regular file (a FIFO)" in proc.stderr


def test_finding16_huge_record_is_planned_in_bounded_memory(tmp_path, monkeypatch):
    big = tmp_path / "big.AT2"
    line = b"  1.0000000E-01  -2.0000000E-01  3.0000000E-02  4.0000000E-02  5.0000000E-02\n"
    n = 24 * 2**20 // len(line)
    big.write_bytes(b"t\nx\ny\nNPTS= %d, DT= 0.005 SEC\n" % (5 * n) + line * n)
    import tracemalloc
    tracemalloc.start()
    try:
        rec = suites.read_at2(big)
        peak = tracemalloc.get_traced_memory()[1] / 2**20
    finally:
        tracemalloc.stop()
    assert rec.pga_g == 0.2 and not rec.error
    assert peak < 32, f"planning a 24 MiB record took {peak:.0f} MiB"
    monkeypatch.setattr(suites, "MAX_RECORD_BYTES", 2**20)  # the bound, made small
    rec = suites.read_at2(big)
    assert "24 MiB, more than the 1 MiB a record may have" in rec.error


def test_finding16_symlinked_record_keeps_its_own_name(one_record, tmp_path):
    links = tmp_path / "links"
    links.mkdir()
    (links / "mylink.AT2").symlink_to(one_record / "p1.AT2")
    (rec,) = suites.at2_folder(links)
    assert rec.name == "mylink" and rec.path == str(links / "mylink.AT2")
    assert rec.pga_g == suites.read_at2(one_record / "p1.AT2").pga_g


def test_finding16_non_utf8_byte_in_the_results_is_named(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path, capsys):
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, fmi2sim_exe, rockingwall_fmu)
    assert sweep.main(args) == 0
    good = out.read_bytes()
    out.write_bytes(good + b"w1|x\xff\n")
    capsys.readouterr()
    assert sweep.main(args) == 1
    assert f"{out}:3: byte 0xff at column 5 is not UTF-8" in capsys.readouterr().err
    assert out.read_bytes() == good
    assert next(tmp_path.glob("res.csv.set-aside-*")).read_bytes().endswith(b"w1|x\xff\n")
    assert sweep.main(args) == 0  # nothing damaged left


def test_finding16_non_utf8_config_and_folder_as_out_are_refused(one_record, tmp_path, capsys):
    cfg = tmp_path / "grid.toml"
    cfg.write_bytes(b"[grid]\nkd_kN = [5]\n# caf\xe9\n")
    assert sweep.main(["--config", str(cfg), "--suite", str(one_record), "--dry-run"]) == 2
    assert f"{cfg}: not a valid TOML file" in capsys.readouterr().err
    folder = tmp_path / "outdir"
    folder.mkdir()
    assert sweep.main(["--suite", str(one_record), "--out", str(folder), "--dry-run"]) == 2
    assert f"{folder}: the results file is a folder" in capsys.readouterr().err


def test_finding16_garbage_in_an_ok_row_is_named_by_ida(tmp_path, capsys):
    path = synthetic_results(tmp_path)
    lines = path.read_text().splitlines(keepends=True)
    fields = lines[4].split(",")
    fields[result_rows.COLUMNS.index("peak_s1")] = "banana"
    lines[4] = ",".join(fields)
    path.write_text("".join(lines))
    assert ida_command.main([str(path), "--out", str(tmp_path / "plots")]) == 1  # plots made, damage reported
    err = capsys.readouterr().err
    assert f"{path}:5: peak_s1 = 'banana' is not a number" in err
    assert (tmp_path / "plots" / "kd_map.png").exists()
    (tmp_path / "empty.csv").write_text("a,b\n1,2\n")
    assert ida_command.main([str(tmp_path / "empty.csv"), "--out", str(tmp_path / "plots")]) == 2
    assert "not a results file" in capsys.readouterr().err


def test_ida_on_a_single_kd_gives_plots_not_a_traceback(tmp_path):
    path = synthetic_results(tmp_path)
    d = pd.read_csv(path)
    d[d.kd_kN == 5.0].to_csv(path, index=False, lineterminator="\n")
    assert ida_command.main([str(path), "--out", str(tmp_path / "plots")]) == 0
    assert (tmp_path / "plots" / "kd_map.png").exists()


def synthetic_results(tmp_path):
    """A results file written as sweep.py writes it, without running fmi2sim: 2 records x 2 K_d x
    4 PGAs of wall 1, collapse above 0.3 g."""
    out = []
    for rec in ("r1", "r2"):
        for kd in (5.0, 50.0):
            for pga in (0.1, 0.2, 0.3, 0.4):
                spec = dict(run_id=f"w1|flexibleTop|dohertyHinge|kd{kd:g}|{rec}|pga{pga:g}", wall=1,
                            model="flexibleTop", hinge_law="dohertyHinge", kd_kN=kd, record=rec, record_pga_g=0.3,
                            scale=pga / 0.3, pga_g=pga, key="0" * 16)
                out.append(result_rows.make_row(spec, "ok", peak_s1=0.1 * pga + (kd == 5.0) * 0.01, peak_s2=0.05 * pga,
                                       peak_F_top=10.0, collapsed=pga > 0.3 + 0.05 * (rec == "r2"), impacts=3,
                                       end_time=4.0, steps=100, cpu_s=0.01, elapsed_s=0.02))
    path = tmp_path / "synthetic.csv"
    pd.DataFrame(out, columns=result_rows.COLUMNS).to_csv(path, index=False, lineterminator="\n")
    return path

"""Resuming a sweep: resumed results are never reused from other inputs, killed or timed-out runs
are never counted as finished, a damaged results line costs that line only, and a finished sweep
run again does nothing. Each test is named after its finding and failed on the code before the
fix."""
import zipfile

import numpy as np
import pandas as pd

from rockingwall.commands import sweep
from rockingwall.sweep import fmi2sim_task, ida
from rockingwall.sweep import rows as result_rows
from sweep_harness import fake_fmi2sim, pulse_record, rows, sweep_args


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


def test_finding16_finished_sweep_run_again_says_nothing_to_do(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path,
                                                               capsys):
    out = tmp_path / "res.csv"
    args = sweep_args(one_record, out, fmi2sim_exe, rockingwall_fmu)
    assert sweep.main(args) == 0
    args.remove("--scheduler"), args.remove("synchronous")  # a LocalCluster: must not even start
    capsys.readouterr()
    assert sweep.main(args + ["--workers", "1"]) == 0
    assert "nothing to do: all 1 runs are done" in capsys.readouterr().out

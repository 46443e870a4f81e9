"""What a SIGKILLed `run`, `assess` or `sweep` leaves in the temporary folder (an unpacked FMU,
fmi2sim's and the sweep's scratch folders) is removed by the next run of the program, and only
that: our prefixes, dead processes, this user's real folders. A Dask worker that dies while the
LocalCluster starts is one clear line, not a traceback."""
import os
import signal
import subprocess
import sys

import pytest

from cli_harness import assert_refused, cli, pulse
from sweep_harness import fake_fmi2sim, pulse_record

# a `rockingwall run --engine fmi2sim` SIGKILLed while fmi2sim runs (its folders exist then)
KILLED_RUN = """
import os, signal, sys
from rockingwall import cli, fmi2sim
fmi2sim.subprocess.run = lambda *a, **k: os.kill(os.getpid(), signal.SIGKILL)
sys.exit(cli.main(sys.argv[1:]))
"""


def dead_pid():
    proc = subprocess.Popen(["true"])
    proc.wait()
    return proc.pid


def ours(tmp):
    return sorted(p.name for p in tmp.iterdir() if p.name.startswith("rw_"))


def test_finding_temporary_folders_of_killed_processes_are_reclaimed(tmp_path, private_tmp, rockingwall_fmu):
    rec = pulse(tmp_path / "REC.csv")
    env = dict(os.environ, TMPDIR=str(private_tmp))
    for command in (["run", rec, "--engine", "fmi2sim"], ["assess", rec, "--pga", "0.2", "--engine", "fmi2sim",
                                                          "--out", tmp_path / "a"]):
        proc = subprocess.run([sys.executable, "-c", KILLED_RUN, *map(str, command)], env=env, capture_output=True,
                              text=True, timeout=300)
        assert proc.returncode == -signal.SIGKILL, proc.stderr
    left = ours(private_tmp)
    assert any(n.startswith("rw_simulate_") for n in left) and any(n.startswith("rw_fmi2sim_") for n in left), left
    suite = tmp_path / "suite"
    suite.mkdir()
    pulse_record(suite / "p.AT2", 0.1, 0.6)
    exe = tmp_path / "fmi2sim_kills_its_sweep"
    fake_fmi2sim(exe, rockingwall_fmu.with_name("fmi2sim"), 'mkdir "$TMPDIR/fmi2sim_unpacked"; kill -9 $PPID; sleep 1')
    proc = cli("sweep", "--suite", suite, "--scales", "1", "--engine", "fmi2sim", "--fmi2sim", exe, "--scheduler",
               "synchronous", "--no-progress", "--out", tmp_path / "s.csv", env=env)
    assert proc.returncode == -signal.SIGKILL, proc.stderr
    assert [n for n in ours(private_tmp) if n.startswith("rw_sweep_")], ours(private_tmp)

    keep = {  # what the next run must leave alone
        f"rw_simulate_{os.getpid()}_alive": "a live process's folder",
        f"other_{dead_pid()}_x": "not our prefix",
        f"rw_simulate_{dead_pid()}_link": "a symlink",
        f"rw_simulate_{dead_pid()}_nobody": "another user's",
    }
    for name in keep:
        if name.endswith("_link"):
            target = tmp_path / "target"
            target.mkdir()
            (target / "f").write_text("x")
            (private_tmp / name).symlink_to(target)
        else:
            (private_tmp / name).mkdir()
    if os.getuid() == 0:
        os.chown(private_tmp / f"rw_simulate_{[n for n in keep if n.endswith('nobody')][0].split('_')[2]}_nobody",
                 65534, 65534)
    else:
        keep.pop(next(n for n in keep if n.endswith("_nobody")))
        os.rmdir(next(p for p in private_tmp.iterdir() if p.name.endswith("_nobody")))
    assert cli("run", rec, env=env).returncode == 0  # any next run: this one makes no folder of its own
    assert sorted(p.name for p in private_tmp.iterdir()) == sorted(keep)
    assert (tmp_path / "target" / "f").read_text() == "x"


def test_finding_a_dask_start_up_failure_is_one_clear_line(tmp_path):
    suite = tmp_path / "suite"
    suite.mkdir()
    pulse_record(suite / "p.AT2", 0.1, 0.6)
    killer = tmp_path / "killer.py"
    killer.write_text("import os, signal\nos.kill(os.getpid(), signal.SIGKILL)\n")  # the worker dies as it starts
    env = dict(os.environ, DASK_DISTRIBUTED__WORKER__PRELOAD=f'["{killer}"]')
    proc = cli("sweep", "--suite", suite, "--scales", "1", "--workers", "1", "--no-progress", "--out",
               tmp_path / "s.csv", env=env, timeout=300)
    assert_refused(proc, "could not start a Dask LocalCluster", "run the command again", code=1)


@pytest.mark.parametrize("name", ["rw_simulate_12x_a", "rw_simulate__a", "rw_simulatex_1_a", "rw_simulate_1234567890_a"])
def test_reclaim_takes_only_names_it_made(tmp_path, name):
    from rockingwall import scratch
    (tmp_path / name).mkdir()
    scratch.reclaim(tmp_path)
    assert (tmp_path / name).is_dir()

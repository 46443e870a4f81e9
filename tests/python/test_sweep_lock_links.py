"""One sweep at a time per results file, whatever name reaches it: a second sweep on a hard link
of the file a running sweep writes is refused (the lock is the file's, not only its name's)."""
import os
import subprocess
import sys
import time

from rockingwall.commands import sweep
from sweep_harness import fake_fmi2sim, rows, sweep_args


def test_finding_a_hard_link_of_a_running_sweeps_file_is_refused(fmi2sim_exe, rockingwall_fmu, one_record, tmp_path,
                                                                 capsys):
    first_name, second_name = tmp_path / "res.csv", tmp_path / "linked.csv"
    assert sweep.main(sweep_args(one_record, first_name, fmi2sim_exe, rockingwall_fmu, "--kd", "10")) == 0
    os.link(first_name, second_name)
    exe = tmp_path / "fmi2sim_slow_start"
    started = tmp_path / "STARTED"
    fake_fmi2sim(exe, fmi2sim_exe, f'touch "{started}"; sleep 4')
    first = subprocess.Popen([sys.executable, "-m", "rockingwall", "sweep",
                              *sweep_args(one_record, first_name, exe, rockingwall_fmu)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 60
        while not started.exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert started.exists()
        capsys.readouterr()
        assert sweep.main(sweep_args(one_record, second_name, exe, rockingwall_fmu)) == 2
    finally:
        first.communicate(timeout=120)
    assert first.returncode == 0
    assert "in use by another sweep" in capsys.readouterr().err
    assert len(rows(first_name)) == 2  # K_d = 10 and 50, each computed once
    assert rows(first_name).run_id.is_unique

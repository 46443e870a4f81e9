"""A sweep on a real Dask cluster: a `dask scheduler` and two `dask worker` processes started
separately on 127.0.0.1, with no PYTHONPATH and a working folder of their own, so the workers
can run the sweep only by importing the installed package; the records travel with the tasks.
The rows equal those of a local run, and running the command again recomputes nothing."""
import json
import os
import pathlib
import subprocess
import sys
import time

import numpy as np
import pandas as pd
import pytest

from rockingwall.sweep import suites

DASK = pathlib.Path(sys.executable).with_name("dask")
CONFIG = """
[grid]
walls = ["mine", "paper2"]
kd_kN = [5.0, 500.0]
pga_g = [0.2, 0.4]
tail = 1.0

[walls.mine]
b = "230 mm"
h = 3.2
W = "14.08 kN/m"
psi = 0.2
"""


def _clean_env():
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "RW_BUILD_DIR")}
    return dict(env, DASK_DISTRIBUTED__WORKER__DAEMON="False")


@pytest.fixture()
def cluster(tmp_path):
    """(scheduler address, processes): stopped and waited for at the end, whatever happens."""
    work = tmp_path / "cluster"
    work.mkdir()
    info = work / "scheduler.json"
    procs = [subprocess.Popen([str(DASK), "scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                               "--scheduler-file", str(info)], cwd=work, env=_clean_env(),
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    try:
        address = _scheduler_address(info, time.monotonic() + 60)
        for i in range(2):
            procs.append(subprocess.Popen([str(DASK), "worker", address, "--nthreads", "1", "--no-dashboard",
                                           "--local-directory", str(work / f"w{i}")], cwd=work, env=_clean_env(),
                                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        yield address
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=30)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()


def _scheduler_address(info, deadline):
    """The address in the scheduler's file, once it is there whole: the scheduler creates the file
    before it writes it, and a read in between found it empty (JSONDecodeError in one CI run)."""
    while True:
        try:
            return json.loads(info.read_text())["address"]
        except (OSError, ValueError, KeyError):
            if time.monotonic() > deadline:
                raise
            time.sleep(0.2)


def _wait_for_workers(address, n):
    from dask.distributed import Client
    with Client(address, timeout=60) as client:
        client.wait_for_workers(n, timeout=60)


def _suite(folder):
    folder.mkdir()
    for name, amp, period in [("p1", 0.25, 0.6), ("p2", 0.2, 0.9)]:
        t = np.arange(0.0, 3.0, 0.01)
        suites.write_at2(folder / f"{name}.AT2", np.where(t < 2.0, amp * np.sin(2 * np.pi * t / period), 0.0),
                          0.01, name)
    return folder


def _sweep(*args, cwd):
    return subprocess.run([sys.executable, "-m", "rockingwall", "sweep", "--no-progress", *map(str, args)],
                          capture_output=True, text=True, timeout=600, cwd=cwd)


def test_sweep_on_a_real_cluster_equals_a_local_run(cluster, tmp_path):
    suite = _suite(tmp_path / "suite")
    config = tmp_path / "grid.toml"
    config.write_text(CONFIG)
    _wait_for_workers(cluster, 2)
    common = ["--config", config, "--suite", suite]
    remote = _sweep(*common, "--scheduler", cluster, "--out", tmp_path / "remote.csv", cwd=tmp_path)
    assert remote.returncode == 0, remote.stderr
    local = _sweep(*common, "--scheduler", "synchronous", "--out", tmp_path / "local.csv", cwd=tmp_path)
    assert local.returncode == 0, local.stderr
    cols = ["run_id", "status", "peak_s1", "peak_s2", "collapsed", "impacts", "engine", "key"]
    a = pd.read_csv(tmp_path / "remote.csv").sort_values("run_id")[cols].reset_index(drop=True)
    b = pd.read_csv(tmp_path / "local.csv").sort_values("run_id")[cols].reset_index(drop=True)
    assert len(a) == 2 * 2 * 2 * 2 and (a.status == "ok").all() and (a.engine == "exact").all()
    assert a.peak_s1.max() > 0.005  # the walls rock
    pd.testing.assert_frame_equal(a, b)  # the same engine, bit for bit
    again = _sweep(*common, "--scheduler", cluster, "--out", tmp_path / "remote.csv", cwd=tmp_path)
    assert again.returncode == 0 and "nothing to do" in again.stdout

"""`rockingwall assess --out DIR` leaves DIR holding one run's files: those of an earlier, larger
run are removed (never a file the user put there or edited), and a run killed while it writes
never leaves a mix that looks complete."""
import json
import os
import subprocess
import sys

import pytest

from cli_harness import cli, pulse

# a child that runs `assess` and is SIGKILLed by itself at a chosen moment of its writing
KILLER = """
import os, signal, sys
from rockingwall import cli
import rockingwall.{module} as target
original = target.{function}
calls = []
def dying(*args, **kw):
    calls.append(1)
    if len(calls) > {after}:
        os.kill(os.getpid(), signal.SIGKILL)
    return original(*args, **kw)
target.{function} = dying
sys.exit(cli.main(sys.argv[1:]))
"""


def assess(out, *recs, **kw):
    proc = cli("assess", *recs, "--pga", "0.2", "0.4", "--out", out, **kw)
    assert proc.returncode == 0, proc.stderr
    return proc


def snapshot(folder):
    return {p.name: p.read_bytes() for p in folder.iterdir() if p.is_file()}


def manifest(folder):
    return json.loads((folder / "manifest.json").read_text())


@pytest.fixture()
def recs(tmp_path):
    return [pulse(tmp_path / f"{name}.csv", amp_g=amp) for name, amp in (("quake_a", 0.3), ("quake_b", 0.2),
                                                                          ("quake_c", 0.25))]


def test_finding_assess_out_holds_one_runs_files(tmp_path, recs):
    out = tmp_path / "out"
    assess(out, *recs[:2])
    assert {"quake_a.png", "quake_b.png", "cases.csv"} <= set(os.listdir(out))
    (out / "notes.txt").write_text("mine\n")          # the user's own file
    assess(out, recs[0])                                # fewer records
    files = set(os.listdir(out))
    assert "quake_b.png" not in files, "a plot of the earlier run is left beside this run's tables"
    assert (out / "notes.txt").read_text() == "mine\n"
    m = manifest(out)
    assert m["complete"] is True
    assert set(m["files"]) == files - {"notes.txt", "manifest.json"}
    assert set(m["files"]) == {"cases.csv", "fragility.csv", "fragility.png", "quake_a.png"}


def test_assess_never_deletes_a_file_the_user_edited(tmp_path, recs):
    out = tmp_path / "out"
    assess(out, *recs[:2])
    (out / "quake_b.png").write_bytes(b"edited by hand")
    assess(out, recs[0])
    assert (out / "quake_b.png").read_bytes() == b"edited by hand"


@pytest.mark.parametrize("module, function, after", [
    ("assessment_plots", "ida", 0),          # killed after the tables, while the plots are drawn
    ("output_folder", "place", 1),           # killed while this run's files are moved into place
])
def test_finding_a_killed_assess_never_looks_complete(tmp_path, recs, module, function, after):
    out = tmp_path / "out"
    assess(out, *recs)
    earlier = snapshot(out)
    script = KILLER.format(module=module, function=function, after=after)
    proc = subprocess.run([sys.executable, "-c", script, "assess", recs[0], "--pga", "0.3", "--out", out],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == -9, proc.stderr
    now = snapshot(out)
    m = manifest(out) if "manifest.json" in now else {"complete": True, "files": {}}
    if m["complete"]:
        assert now == earlier, "the folder says complete but mixes two runs"
    else:
        assert set(now) - {"manifest.json"} <= set(m["files"]), "a file the manifest does not name"
    assess(out, recs[0])  # the next run cleans up after the killed one
    assert set(os.listdir(out)) == {"cases.csv", "fragility.csv", "fragility.png", "quake_a.png", "manifest.json"}
    assert manifest(out)["complete"] is True

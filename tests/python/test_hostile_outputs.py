"""No command writes over one of its inputs (the same path, a symlink or a hard link to it); a
full disk or a full standard output is one line naming the file (exit 1), never a traceback nor a
cut file; outputs get the permissions the umask gives, not a private 0600."""
import os
import resource
import shutil
import signal
import stat
import subprocess
import sys

import pytest

from cli_harness import assert_refused, cli, pulse
from sweep_harness import pulse_record


def refused_and_intact(proc, victim, before, *needles):
    line = assert_refused(proc, "refusing to overwrite an input", *needles)
    assert victim.read_bytes() == before, "the input was changed"
    return line


@pytest.fixture()
def rec(tmp_path):
    return pulse(tmp_path / "REC.csv")


@pytest.mark.parametrize("how", ["itself", "hardlink", "symlink"])
def test_finding_run_out_in_the_records_folder_never_overwrites_the_record(tmp_path, rec, how):
    before = rec.read_bytes()
    out = tmp_path if how == "itself" else tmp_path / "out"
    out.mkdir(exist_ok=True)
    if how == "hardlink":
        os.link(rec, out / "REC.csv")
    elif how == "symlink":
        (out / "REC.csv").symlink_to(rec)
    refused_and_intact(cli("run", rec, "--out", out), rec, before, "REC.csv")
    assert not (out / "REC.png").exists()


def test_finding_run_refuses_two_records_that_write_one_file(tmp_path, rec):
    (tmp_path / "b").mkdir()
    other = pulse(tmp_path / "b" / "REC.csv", amp_g=0.1)
    assert_refused(cli("run", rec, other, "--out", tmp_path / "out"), "written twice")


def test_finding_assess_never_overwrites_a_record_named_like_its_tables(tmp_path, rec):
    cases = tmp_path / "cases.csv"
    shutil.copy(rec, cases)
    before = cases.read_bytes()
    refused_and_intact(cli("assess", cases, "--pga", "0.2", "--out", tmp_path), cases, before, "cases.csv")


def test_finding_animate_never_overwrites_its_record(tmp_path, rec):
    refused_and_intact(cli("animate", rec, "--t-end", "0.2", "--out", rec), rec, rec.read_bytes())


def test_finding_ida_never_overwrites_its_results_file(tmp_path, rec):
    suite = tmp_path / "suite"
    suite.mkdir()
    pulse_record(suite / "p1.AT2", 0.10, 0.6)
    results = tmp_path / "out" / "fragility.png"
    results.parent.mkdir()
    proc = cli("sweep", "--suite", suite, "--scales", "0.5", "1", "--out", results, "--scheduler", "synchronous",
               "--no-progress")
    assert proc.returncode == 0, proc.stderr
    before = results.read_bytes()
    refused_and_intact(cli("ida", results, "--out", results.parent), results, before, "fragility.png")


def test_finding_sweep_never_appends_to_one_of_its_records(tmp_path):
    suite = tmp_path / "suite"
    suite.mkdir()
    record = suite / "p1.AT2"
    pulse_record(record, 0.10, 0.6)
    before = record.read_bytes()
    os.link(record, tmp_path / "results.csv")
    proc = cli("sweep", "--suite", suite, "--scales", "1", "--out", tmp_path / "results.csv", "--scheduler",
               "synchronous", "--no-progress")
    refused_and_intact(proc, record, before, "p1.AT2")


def test_finding_couple_never_overwrites_its_fmus_or_record(tmp_path, rockingwall_fmu):
    wall = tmp_path / "wall.fmu"
    shutil.copy(rockingwall_fmu, wall)
    before = wall.read_bytes()
    proc = cli("couple", "--wall-fmu", wall, "--t-end", "0.05", "--plot", wall, "--out", tmp_path / "c.csv")
    refused_and_intact(proc, wall, before, "wall.fmu")


def test_finding_couple_building_never_writes_its_ssp_over_an_input(tmp_path):
    from rockingwall.building import ssp
    from rockingwall.building.scene import default_scene
    scene_file = ssp.write(default_scene(1, None, 1, 1e6, 0, "dohertyHinge"), tmp_path / "scene.ssp")
    before = scene_file.read_bytes()
    proc = cli("couple-building", "--from-ssp", scene_file, "--ssp", scene_file, "--record", "gaussian", "--t-end",
               "0.01")
    refused_and_intact(proc, scene_file, before, "scene.ssp")
    building = tmp_path / "Building.fmu"
    shutil.copy(default_scene(1, None, 1, 1e6, 0, "dohertyHinge").building_fmu, building)
    before = building.read_bytes()
    scene = default_scene(1, None, 1, 1e6, 0, "dohertyHinge")
    scene.building_fmu = str(building)
    with pytest.raises(ValueError, match="refusing to overwrite an input"):
        ssp.write(scene, building)
    assert building.read_bytes() == before


def test_finding_paper_writes_beside_a_symlink_not_through_it(tmp_path):
    precious = tmp_path / "precious.txt"
    precious.write_text("mine\n")
    out = tmp_path / "out"
    out.mkdir()
    (out / "table_5_1.csv").symlink_to(precious)
    proc = cli("paper", "--quick", "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert precious.read_text() == "mine\n"
    assert (out / "table_5_1.csv").read_text().startswith("table,")


def limited_fsize(nbytes):
    def preexec():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write past the limit fails with EFBIG, as on a full disk
        resource.setrlimit(resource.RLIMIT_FSIZE, (nbytes, nbytes))
    return preexec


@pytest.mark.parametrize("command", [["run"], ["assess", "--pga", "0.2", "0.3"]])
def test_finding_a_full_disk_is_named_and_never_a_traceback(tmp_path, rec, command):
    out = tmp_path / "out"
    proc = cli(command[0], rec, *command[1:], "--out", out, preexec_fn=limited_fsize(20000))
    line = assert_refused(proc, str(out), code=1)
    assert "File too large" in line
    leftovers = [p.name for p in out.iterdir() if p.name.startswith(".") and "manifest" not in p.name]
    assert leftovers == []  # no temporary file left behind


def test_finding_a_full_standard_output_is_one_line(rec):
    with open("/dev/full", "w") as full:
        proc = subprocess.run([sys.executable, "-m", "rockingwall", "run", str(rec)], stdout=full,
                              stderr=subprocess.PIPE, text=True, timeout=300)
    line = assert_refused(proc, "standard output", code=1)
    assert "No space left on device" in line


@pytest.mark.parametrize("umask, mode", [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
def test_finding_outputs_follow_the_umask(tmp_path, rec, umask, mode):
    out = tmp_path / "out"
    proc = cli("run", rec, "--out", out, preexec_fn=lambda: os.umask(umask))
    assert proc.returncode == 0, proc.stderr
    assert {stat.S_IMODE((out / n).stat().st_mode) for n in ("REC.csv", "REC.png")} == {mode}
    proc = cli("assess", rec, "--pga", "0.2", "--out", tmp_path / "a", preexec_fn=lambda: os.umask(umask))
    assert proc.returncode == 0, proc.stderr
    assert stat.S_IMODE((tmp_path / "a" / "cases.csv").stat().st_mode) == mode
    os.chmod(out / "REC.csv", 0o640)  # an existing output keeps the mode its owner gave it
    assert cli("run", rec, "--out", out, preexec_fn=lambda: os.umask(umask)).returncode == 0
    assert stat.S_IMODE((out / "REC.csv").stat().st_mode) == 0o640

"""fmi2sim against hostile surroundings: full disks, outputs that are inputs, absurd options,
signals, a full TMPDIR, closed standard streams. Each test names the finding it guards
(test_findingNN_...); each saw the old fmi2sim fail. Hostile FMUs: test_fmi2sim_hostile_fmus.py."""
import os
import resource
import shutil
import signal
import subprocess
import time
import zipfile

import pytest

from child_signals import default_signals
from fmi2sim_harness import MD, SO, assert_one_clear_error, hostile_fmu, leftovers, tmp_env
from fmi2sim_harness import run_limited as run


# ---- 1: full disk, closed stdout ---------------------------------------------------------------

def test_finding01_full_disk_exits_nonzero(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """/dev/full, a file-size limit and a closed stdout: a non-zero exit naming the file, and an
    existing output left as it was (the old fmi2sim exited 0 with the CSV cut mid-row)."""
    proc = run(fmi2sim_exe, rockingwall_fmu, "--stop-time", 1, "--output", "/dev/full")
    assert_one_clear_error(proc, "/dev/full", "No space left on device")

    out = tmp_path / "out.csv"
    out.write_text("precious\n")
    with zipfile.ZipFile(rockingwall_fmu) as z:
        room = z.getinfo(SO).file_size + (1 << 20)  # the binary is unpacked, the CSV (500 000 rows, > 15 MB) is not
    proc = run(fmi2sim_exe, rockingwall_fmu, "--stop-time", 10, "--output-interval", 2e-5, "--output", out,
               limits={resource.RLIMIT_FSIZE: room})
    assert_one_clear_error(proc, out, "write failed", "File too large")
    assert out.read_text() == "precious\n"
    assert leftovers(tmp_path) == ["out.csv"]

    proc = run(fmi2sim_exe, rockingwall_fmu, "--stop-time", 1, "--summary", "/dev/full")
    assert_one_clear_error(proc, "/dev/full", "No space left on device")

    proc = subprocess.run([str(fmi2sim_exe), str(rockingwall_fmu), "--stop-time", "1"], capture_output=False,
                          stderr=subprocess.PIPE, text=True, timeout=120, preexec_fn=lambda: os.close(1))
    assert_one_clear_error(proc, "standard output is closed")


# ---- 6: options outside meaningful ranges -------------------------------------------------------

OPTION_CASES = {
    "rtol": (["--rtol", "10"], "--rtol 10 is out of range: it must lie in [1e-12, 0.01]"),
    "atol": (["--atol", "1e300"], "--atol 1e+300 is out of range"),
    "max_step": (["--max-step", "1e-300"], "--max-step 1e-300 is out of range: it must be >= (stop - start) x 1e-8"),
    "output_interval": (["--stop-time", "1", "--output-interval", "1e-300"], "--output-interval 1e-300 is out of range: it must lie in [1e-07, 1]"),
    "output_interval_long": (["--stop-time", "1", "--output-interval", "5"], "--output-interval 5 is out of range"),
    "start_time_far": (["--start-time", "1e8", "--stop-time", "100000000.001"], "it must be >= 1e-6 x max(1, |start|, |stop|)"),
    "stop_time_huge": (["--stop-time", "1e12"], "--stop-time 1e+12 is out of range: it must lie in [-1e+09, 1e+09]"),
    "gravity": (["--g", "1e-300"], "--g 1e-300 is out of range: it must lie in [0.1, 100]"),
}


@pytest.mark.parametrize("case", sorted(OPTION_CASES))
def test_finding06_options_out_of_range_are_refused(fmi2sim_exe, rockingwall_fmu, tmp_path, case):
    """The old fmi2sim ran these with wrong answers and exit 0, hung, or wrote without bound."""
    args, message = OPTION_CASES[case]
    proc = run(fmi2sim_exe, rockingwall_fmu, *args, "--output", tmp_path / "o.csv", timeout=30,
               limits={resource.RLIMIT_FSIZE: 64 << 20})
    assert_one_clear_error(proc, message)
    assert not (tmp_path / "o.csv").exists()


def test_finding06_help_states_the_ranges(fmi2sim_exe):
    text = run(fmi2sim_exe, "--help").stdout
    for needle in ("[1e-12, 0.01]", "[1e-16, 0.01] x the nominal", "(stop - start) x 1e-8", "[-1e9, 1e9]",
                   "[(stop - start) x 1e-7, stop - start]", "[0.1, 100]"):
        assert needle in text, needle


# ---- 8: outputs that are inputs, failed runs --------------------------------------------------

def test_finding08_outputs_never_overwrite_inputs(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """--output equal to --input or to the FMU, --summary equal to --ag, through a symlink or a hard
    link: refused before anything is written (the old fmi2sim destroyed the input)."""
    fmu = tmp_path / "copy.fmu"
    shutil.copy(rockingwall_fmu, fmu)
    inp = tmp_path / "in.csv"
    inp.write_text("time,ag\n0,0\n1,0.1\n")
    at2 = tmp_path / "rec.AT2"
    at2.write_text("a\nb\nc\nNPTS=  2, DT=   .5000 SEC\n0.0 0.01\n")
    (tmp_path / "link.csv").symlink_to(inp)
    os.link(inp, tmp_path / "hard.csv")
    before = {p: p.read_bytes() for p in (fmu, inp, at2)}
    cases = [
        (["--input", inp, "--output", inp], ["--output", "is the same file as --input"]),
        (["--ag", at2, "--summary", at2], ["--summary", "is the same file as --ag"]),
        (["--output", fmu], ["--output", "is the same file as the FMU"]),
        (["--input", inp, "--output", tmp_path / "link.csv"], ["link.csv is the same file as --input"]),
        (["--input", inp, "--output", tmp_path / "hard.csv"], ["hard.csv is the same file as --input"]),
        (["--output", tmp_path / "x.json", "--summary", tmp_path / "x.json"], ["are both"]),
    ]
    for args, needles in cases:
        proc = run(fmi2sim_exe, fmu, "--stop-time", 1, *args)
        assert_one_clear_error(proc, *needles)
        assert {p: p.read_bytes() for p in before} == before, args


def test_finding08_outputs_never_write_into_a_folder_fmu(fmi2sim_exe, rockingwall_fmu, tmp_path):
    folder = tmp_path / "unpacked"
    with zipfile.ZipFile(rockingwall_fmu) as z:
        z.extractall(folder)
    md_before = (folder / MD).read_bytes()
    proc = run(fmi2sim_exe, folder, "--stop-time", 1, "--output", folder / MD)
    assert_one_clear_error(proc, "lies inside the FMU folder")
    assert (folder / MD).read_bytes() == md_before


def test_finding08_failed_run_keeps_the_existing_output(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """Outputs go to a temporary file renamed into place on success only: a failing run leaves the
    old file as it was (the old fmi2sim truncated it), a good one replaces it through a symlink."""
    out, summary = tmp_path / "out.csv", tmp_path / "s.json"
    out.write_text("precious\n")
    summary.write_text("{}\n")
    proc = run(fmi2sim_exe, rockingwall_fmu, "--set", "h=-1", "--output", out, "--summary", summary)
    assert proc.returncode != 0
    assert out.read_text() == "precious\n" and summary.read_text() == "{}\n"
    assert leftovers(tmp_path) == ["out.csv", "s.json"]
    (tmp_path / "via.csv").symlink_to(out)
    os.chmod(out, 0o640)
    proc = run(fmi2sim_exe, rockingwall_fmu, "--stop-time", 0.1, "--output", tmp_path / "via.csv")
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "via.csv").is_symlink() and out.read_text().startswith("time,")
    assert leftovers(tmp_path) == ["out.csv", "s.json", "via.csv"]


# ---- 9: signals ---------------------------------------------------------------------------------

@pytest.mark.parametrize("sig", ["SIGINT", "SIGTERM", "SIGHUP", "SIGPIPE"])
def test_finding09_signals_remove_the_unpack_folder(fmi2sim_exe, rockingwall_fmu, tmp_path, sig):
    """Killed while it writes to a pipe (for SIGPIPE: the reader goes away), fmi2sim removes its
    unpacked FMU and dies of the signal (the old one left ~400 KiB behind each time)."""
    env, tdir = tmp_env(tmp_path)
    proc = subprocess.Popen([str(fmi2sim_exe), str(rockingwall_fmu), "--stop-time", "100", "--output-interval", "1e-4"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, preexec_fn=default_signals)
    assert proc.stdout.readline().startswith(b"time,")  # unpacked, loaded and writing
    assert leftovers(tdir)
    if sig == "SIGPIPE":
        proc.stdout.close()
    else:
        proc.send_signal(getattr(signal, sig))
    proc.wait(timeout=60)
    assert proc.returncode == -getattr(signal, sig)
    assert leftovers(tdir) == []


def test_finding09_signal_removes_the_temporary_output(fmi2sim_exe, rockingwall_fmu, tmp_path):
    env, tdir = tmp_env(tmp_path)
    out = tmp_path / "out.csv"
    proc = subprocess.Popen([str(fmi2sim_exe), str(rockingwall_fmu), "--stop-time", "1e4", "--output-interval", "1e-3",
                             "--output", str(out)],
                            stderr=subprocess.PIPE, env=env)
    deadline = time.monotonic() + 60
    while not list(tmp_path.glob("out.csv.*")) and time.monotonic() < deadline:
        time.sleep(0.02)
    assert list(tmp_path.glob("out.csv.*")), "no temporary output appeared"
    proc.send_signal(signal.SIGTERM)
    proc.wait(timeout=60)
    assert proc.returncode == -signal.SIGTERM
    assert leftovers(tdir) == [] and not list(tmp_path.glob("out.csv*"))


# ---- 10: full temporary folder, cut binary ------------------------------------------------------

def test_finding10_full_tmpdir_and_cut_binary_are_reported(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """Extraction's writes are checked (the old fmi2sim died of SIGBUS in dlopen, or reported a cut
    modelDescription.xml as bad XML), and a binary cut short inside the archive is refused."""
    env, tdir = tmp_env(tmp_path)
    proc = run(fmi2sim_exe, rockingwall_fmu, "--stop-time", 0.1, env=env, limits={resource.RLIMIT_FSIZE: 100 << 10})
    assert_one_clear_error(proc, rockingwall_fmu, "cannot write", "RockingWall.so", "File too large")
    proc = run(fmi2sim_exe, rockingwall_fmu, "--stop-time", 0.1, env=env, limits={resource.RLIMIT_FSIZE: 4 << 10})
    assert_one_clear_error(proc, rockingwall_fmu, "cannot write", MD, "File too large")
    assert leftovers(tdir) == []

    with zipfile.ZipFile(rockingwall_fmu) as z:
        so = z.read(SO)
    cut = hostile_fmu(rockingwall_fmu, tmp_path / "cut.fmu", entries={SO: so[:len(so) * 2 // 3]})
    proc = run(fmi2sim_exe, cut, "--stop-time", 0.1, env=env)
    assert_one_clear_error(proc, cut, "cannot load the FMU binary", "is cut short")
    assert leftovers(tdir) == []


# ---- 13: closed stderr ---------------------------------------------------------------------------

def test_finding13_closed_stderr_keeps_the_csv_clean(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """With fd 2 closed the CSV must not take its number (the old fmi2sim wrote its stats into it)."""
    out = tmp_path / "out.csv"
    proc = subprocess.run([str(fmi2sim_exe), str(rockingwall_fmu), "--stop-time", "1", "--stats", "--output", str(out)],
                          stdout=subprocess.PIPE, timeout=120, preexec_fn=lambda: os.close(2))
    assert proc.returncode == 0
    text = out.read_text()
    assert "fmi2sim" not in text and text.startswith("time,")

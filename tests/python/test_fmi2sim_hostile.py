"""fmi2sim against hostile input: full disks, outputs that are inputs, hostile FMUs
(generated here from the built ones, never stored), absurd options, signals, closed standard
streams. Each test names the finding it guards (test_findingNN_...); each saw the old fmi2sim fail."""
import os
import pathlib
import re
import resource
import shutil
import signal
import subprocess
import time
import zipfile

import pytest

from test_fmi2sim import ASAN_BUILD, assert_one_clear_error

SO = "binaries/linux64/RockingWall.so"
MD = "modelDescription.xml"
# the FMU's own count, as the committed model description declares it
NZ_DECLARED = re.search(r'numberOfEventIndicators="\d+"',
                        (pathlib.Path(__file__).resolve().parents[2] / "fmu_src" / "models" / "RockingWall" / "fmi2"
                         / MD).read_text()).group(0)


def limited(limits):
    """A preexec_fn setting resource limits, with SIGXFSZ ignored so that a write over the
    file-size limit fails with EFBIG (what a full disk does) instead of killing the process."""
    def preexec():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        for what, value in (limits or {}).items():
            resource.setrlimit(what, (value, value))
    return preexec


def run(exe, *args, limits=None, env=None, timeout=120, **kw):
    return subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True, timeout=timeout,
                          preexec_fn=limited(limits), env=env, **kw)


def memory_cap():
    """Bound the address space where the sanitizer (which reserves terabytes) is not in use, so that
    an old fmi2sim that allocates what a hostile file says cannot take the machine down."""
    return {} if ASAN_BUILD else {resource.RLIMIT_AS: 4 << 30}


def hostile_fmu(src, dst, md=None, entries=None, drop=()):
    """A copy of the FMU src with the model description rewritten by md(text), entries added or
    replaced ({name: bytes or a callable writing into a zip member}), and entries dropped."""
    entries = dict(entries or {})
    with zipfile.ZipFile(src) as zin, zipfile.ZipFile(dst, "w", zipfile.ZIP_DEFLATED) as zout:
        for info in zin.infolist():
            if info.filename in drop or info.filename in entries:
                continue
            data = zin.read(info.filename)
            if info.filename == MD and md:
                data = md(data.decode()).encode()
            zout.writestr(info, data)
        for name, data in entries.items():
            if callable(data):
                with zout.open(name, "w", force_zip64=True) as member:
                    data(member)
            else:
                zout.writestr(name, data)
    return dst


def tmp_env(tmp_path):
    """TMPDIR of its own, so that the test can see what fmi2sim unpacks and leaves behind."""
    tdir = tmp_path / "tmpdir"
    tdir.mkdir(exist_ok=True)
    return dict(os.environ, TMPDIR=str(tdir)), tdir


def leftovers(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


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


# ---- 5: numbers in the model description -------------------------------------------------------

def sub(old, new):
    def change(text):
        assert old in text, old
        return text.replace(old, new, 1)
    return change


# counted from the committed model description, so the cases follow the model's variables
_XML = (pathlib.Path(__file__).resolve().parents[2] / "fmu_src" / "models" / "RockingWall" / "fmi2"
        / "modelDescription.xml").read_text()
N_OUTPUTS = len(re.findall(r'causality="output"', _XML))


def first_derivative_index(text):
    """<Derivatives>' first Unknown given the index 999."""
    return re.sub(r'(<Derivatives>\s*<Unknown index=")\d+', r"\g<1>999", text, count=1)


MD_CASES = {
    "indicators_word": (sub(NZ_DECLARED, 'numberOfEventIndicators="five"'),
                        ["modelDescription.xml:7:", "numberOfEventIndicators 'five'", "[0, 1000000]"]),
    "indicators_negative": (sub(NZ_DECLARED, 'numberOfEventIndicators="-1"'),
                            ["modelDescription.xml:7:", "numberOfEventIndicators '-1'"]),
    "indicators_zero": (sub(NZ_DECLARED, 'numberOfEventIndicators="0"'),
                        ["refuses 0 event indicators", "numberOfEventIndicators"]),
    "no_derivatives": (lambda t: re.sub(r"<Derivatives>.*?</Derivatives>", "", t, flags=re.S),
                       ["ModelStructure lists 0 Derivatives, but 4 variables have a derivative attribute"]),
    "derivative_index": (first_derivative_index, ["Derivatives Unknown index '999'"]),
    "output_not_listed": (lambda t: re.sub(r"<Outputs>\s*<Unknown[^>]*/>", "<Outputs>", t, count=1),
                          [f"ModelStructure lists {N_OUTPUTS - 1} Outputs, but {N_OUTPUTS} variables have causality output"]),
    "output_index": (lambda t: re.sub(r'(<Outputs>\s*<Unknown index=")\d+', r"\g<1>1", t, count=1),
                     ["Outputs Unknown index '1' is not the index"]),
    "value_reference_wraps": (sub('name="s1" valueReference="30"', 'name="s1" valueReference="4294967326"'),
                              ["variable 's1' has valueReference '4294967326'", "[0, 4294967295]"]),
    "value_reference_negative": (sub('name="s1" valueReference="30"', 'name="s1" valueReference="-2"'),
                                 ["variable 's1' has valueReference '-2'"]),
    "nominal_negative": (lambda t: re.sub(r'(<Real[^>]*?) nominal="[^"]*"', r'\1 nominal="-1"', t, count=1),
                         ["has a nominal that is not a finite number > 0"]),
    "stop_time_nan": (lambda t: re.sub(r'stopTime="[^"]*"', 'stopTime="nan"', t)
                      if "stopTime" in t else t.replace("<ModelVariables>", '<DefaultExperiment stopTime="nan"/>\n  <ModelVariables>'),
                      ["DefaultExperiment stopTime is not a finite number"]),
}


@pytest.mark.parametrize("case", sorted(MD_CASES))
def test_finding05_model_description_numbers_are_validated(fmi2sim_exe, rockingwall_fmu, tmp_path, case):
    """Every number fmi2sim reads from the XML is checked (the old one ran with root-finding off,
    with frozen states or a wrapped value reference, and exited 0)."""
    change, needles = MD_CASES[case]
    fmu = hostile_fmu(rockingwall_fmu, tmp_path / f"{case}.fmu", md=change)
    proc = run(fmi2sim_exe, fmu, "--stop-time", 2, "--summary", tmp_path / "s.json", limits=memory_cap())
    assert_one_clear_error(proc, fmu, *needles)
    assert "fmi2sim_" not in proc.stderr.split("fmi2sim: error:")[1]  # no name of the deleted unpack folder


# ---- 6: options outside meaningful ranges -------------------------------------------------------

OPTION_CASES = {
    "rtol": (["--rtol", "10"], "--rtol 10 is out of range: it must lie in [1e-12, 0.01]"),
    "atol": (["--atol", "1e300"], "--atol 1e+300 is out of range"),
    "max_step": (["--max-step", "1e-300"], "--max-step 1e-300 is out of range: it must be >= (stop - start) x 1e-8"),
    "output_interval": (["--stop-time", "1", "--output-interval", "1e-300"], "--output-interval 1e-300 is out of range: it must lie in [1e-07, 1]"),
    "output_interval_long": (["--stop-time", "1", "--output-interval", "5"], "--output-interval 5 is out of range"),
    "start_time_far": (["--start-time", "1e8", "--stop-time", "100000000.001"], "it must be >= 1e-6 x max(1, |start|, |stop|)"),
    "stop_time_huge": (["--stop-time", "1e12"], "stop time 1e+12 is out of range: it must lie in [-1e+09, 1e+09]"),
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

def default_signals():
    """In the child: the caught signals at their default disposition. fmi2sim keeps a signal its
    parent ignores (nohup, or a background job of a non-interactive shell, which ignores SIGINT),
    so a test run launched that way would otherwise wait for a signal that never acts."""
    for name in ("SIGINT", "SIGTERM", "SIGHUP"):
        signal.signal(getattr(signal, name), signal.SIG_DFL)


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


# ---- 11: resource limits ------------------------------------------------------------------------

def zeros(nbytes):
    def write(member):
        block = bytes(1 << 20)
        for _ in range(nbytes >> 20):
            member.write(block)
    return write


def test_finding11_only_needed_entries_are_extracted(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """sources/ (here a 300 MB zip bomb) and documentation/ are never written: only the model
    description, the binary and resources/ (the old fmi2sim extracted everything)."""
    env, tdir = tmp_env(tmp_path)
    fmu = hostile_fmu(rockingwall_fmu, tmp_path / "bomb.fmu",
                      entries={"sources/bomb.c": zeros(300 << 20), "documentation/index.html": b"<html/>",
                               "resources/table.txt": b"1 2 3\n"})
    proc = subprocess.Popen([str(fmi2sim_exe), str(fmu), "--stop-time", "100", "--output-interval", "1e-4"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                            preexec_fn=limited({resource.RLIMIT_FSIZE: 64 << 20}))
    try:
        assert proc.stdout.readline().startswith(b"time,")
        (unpacked,) = tdir.iterdir()
        assert leftovers(unpacked) == ["binaries", "binaries/linux64", SO, MD, "resources", "resources/table.txt"]
    finally:
        proc.kill()
        proc.wait(timeout=60)
        shutil.rmtree(tdir, ignore_errors=True)


def test_finding11_sizes_and_counts_are_bounded(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """A resources/ bomb, a quadratic entity expansion and 2e9 event indicators: refused at once
    with the limit in the message (the old fmi2sim wrote gigabytes, parsed for 91 s, took 23 GB)."""
    env, tdir = tmp_env(tmp_path)
    cap = {**memory_cap(), resource.RLIMIT_FSIZE: 64 << 20}
    bomb = hostile_fmu(rockingwall_fmu, tmp_path / "bomb.fmu", entries={"resources/bomb.bin": zeros(300 << 20)})
    proc = run(fmi2sim_exe, bomb, "--stop-time", 0.1, env=env, limits=cap)
    assert_one_clear_error(proc, bomb, "resources/bomb.bin", "larger than the limit of 256 MiB")

    def entities(text):
        head, rest = text.split("<fmiModelDescription", 1)
        decl = '<!DOCTYPE fmiModelDescription [<!ENTITY a "' + "x" * 2000 + '">]>\n'
        return head + decl + "<fmiModelDescription" + rest.replace('description="Wall height (&gt; 0)"',
                                                                     'description="' + "&a;" * 2000 + '"')
    quad = hostile_fmu(rockingwall_fmu, tmp_path / "quad.fmu", md=entities)
    t0 = time.monotonic()
    proc = run(fmi2sim_exe, quad, "--stop-time", 0.1, env=env, limits=cap)
    assert_one_clear_error(proc, quad, "modelDescription.xml:3:", "DOCTYPE or entity declaration is not allowed")
    assert time.monotonic() - t0 < 10

    many = hostile_fmu(rockingwall_fmu, tmp_path / "many.fmu",
                       md=sub(NZ_DECLARED, 'numberOfEventIndicators="2000000000"'))
    proc = run(fmi2sim_exe, many, "--stop-time", 0.1, env=env, limits=cap)
    assert_one_clear_error(proc, many, "numberOfEventIndicators '2000000000'", "[0, 1000000]")
    assert leftovers(tdir) == []


# ---- 12: the binary lies inside the FMU ---------------------------------------------------------

def test_finding12_binary_must_lie_inside_the_fmu(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """A modelIdentifier that climbs out of the FMU, or a folder FMU whose binary is a link to
    elsewhere, is refused (the old fmi2sim loaded, and ran the constructors of, the outside one)."""
    env, tdir = tmp_env(tmp_path)
    with zipfile.ZipFile(rockingwall_fmu) as z:
        so = z.read(SO)
    (tdir / "x.so").write_bytes(so)  # where binaries/linux64/../../../x.so points from the unpack folder
    climb = hostile_fmu(rockingwall_fmu, tmp_path / "climb.fmu",
                        md=sub('modelIdentifier="RockingWall"', 'modelIdentifier="../../../x"'))
    proc = run(fmi2sim_exe, climb, "--stop-time", 0.1, "--summary", tmp_path / "s.json", env=env)
    assert_one_clear_error(proc, climb, "modelIdentifier '../../../x' is not a C identifier")
    assert leftovers(tdir) == ["x.so"]

    folder = tmp_path / "linked"
    with zipfile.ZipFile(rockingwall_fmu) as z:
        z.extractall(folder)
    (folder / SO).unlink()
    (folder / SO).symlink_to(tdir / "x.so")
    proc = run(fmi2sim_exe, folder, "--stop-time", 0.1, "--summary", tmp_path / "s.json")
    assert_one_clear_error(proc, "resolves to", "outside the FMU's folder")


def test_finding12_legal_names_pass_and_climbing_names_do_not(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """Names are checked component by component: 'release..notes.txt' is a file name (the old
    substring test refused it), '../' is not."""
    env, tdir = tmp_env(tmp_path)
    legal = hostile_fmu(rockingwall_fmu, tmp_path / "legal.fmu", entries={"resources/release..notes.txt": b"notes"})
    proc = run(fmi2sim_exe, legal, "--stop-time", 0.1, "--summary", tmp_path / "s.json", env=env)
    assert proc.returncode == 0, proc.stderr
    slip = hostile_fmu(rockingwall_fmu, tmp_path / "slip.fmu", entries={"resources/../../evil.txt": b"evil"})
    proc = run(fmi2sim_exe, slip, "--stop-time", 0.1, env=env)
    assert_one_clear_error(proc, slip, "'resources/../../evil.txt' has an unsafe name")
    assert leftovers(tdir) == [] and not (tmp_path / "evil.txt").exists()


# ---- 13: closed stderr ---------------------------------------------------------------------------

def test_finding13_closed_stderr_keeps_the_csv_clean(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """With fd 2 closed the CSV must not take its number (the old fmi2sim wrote its stats into it)."""
    out = tmp_path / "out.csv"
    proc = subprocess.run([str(fmi2sim_exe), str(rockingwall_fmu), "--stop-time", "1", "--stats", "--output", str(out)],
                          stdout=subprocess.PIPE, timeout=120, preexec_fn=lambda: os.close(2))
    assert proc.returncode == 0
    text = out.read_text()
    assert "fmi2sim" not in text and text.startswith("time,")


# ---- 15: no leak when CVODE fails ---------------------------------------------------------------

def test_finding15_cvode_failure_does_not_leak(fmi2sim_exe, build_dir, tmp_path):
    """CVodeGetReturnFlagName's string is freed (the old fmi2sim lost 24 bytes per failure). Under
    ASan LeakSanitizer checks it; otherwise valgrind does, where installed."""
    ball = build_dir / "BouncingBall.fmu"
    args = [str(ball), "--set", "g=1e300", "--stop-time", "1", "--summary", str(tmp_path / "s.json")]
    if ASAN_BUILD:
        env = dict(os.environ, ASAN_OPTIONS="detect_leaks=1")
        proc = subprocess.run([str(fmi2sim_exe), *args], capture_output=True, text=True, timeout=120, env=env)
        assert_one_clear_error(proc, "CVODE failed")
        assert "LeakSanitizer" not in proc.stderr, proc.stderr
        return
    if shutil.which("valgrind") is None:
        pytest.skip("valgrind is not installed")
    proc = subprocess.run(["valgrind", "--leak-check=full", "--errors-for-leak-kinds=definite", "--error-exitcode=99",
                           str(fmi2sim_exe), *args], capture_output=True, text=True, timeout=300)
    assert "CVODE failed" in proc.stderr
    assert proc.returncode == 2, proc.stderr[-3000:]
    assert "definitely lost" not in proc.stderr, proc.stderr[-3000:]

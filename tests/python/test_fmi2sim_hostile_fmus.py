"""fmi2sim against hostile FMUs (generated here from the built ones, never stored): numbers in the
model description, archive sizes and counts, binary paths, a CVODE failure. Each test names the
finding it guards (test_findingNN_...); each saw the old fmi2sim fail."""
import os
import pathlib
import re
import resource
import shutil
import subprocess
import time
import zipfile

import pytest

from fmi2sim_harness import (ASAN_BUILD, MD, NZ_DECLARED, SO, assert_one_clear_error, hostile_fmu, leftovers, limited,
                             memory_cap, tmp_env)
from fmi2sim_harness import run_limited as run


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

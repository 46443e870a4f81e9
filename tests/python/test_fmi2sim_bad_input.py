"""fmi2sim on bad input: a clear message naming the file (and line) with a non-zero exit for
every kind of bad input file, broken FMU and bad option."""
import re
import shutil
import zipfile

import pytest

from fmi2sim_harness import assert_one_clear_error, run


# ---- bad input: one clear message, non-zero exit -----------------------------------------

def bad_zip(tmp_path):
    p = tmp_path / "nomd.fmu"
    with zipfile.ZipFile(p, "w") as z:
        z.writestr("binaries/linux64/x.so", b"")
    return p


def wrong_guid(tmp_path, ball):
    d = tmp_path / "wrongguid"
    with zipfile.ZipFile(ball) as z:
        z.extractall(d)
    md = d / "modelDescription.xml"
    md.write_text(md.read_text().replace("{6f3d1f0e-2b1c-4c1a-9a55-b0c1d2e3f401}", "{00000000-0000-0000-0000-000000000000}"))
    out = tmp_path / "wrongguid.fmu"
    shutil.make_archive(str(out.with_suffix("")), "zip", d)
    out.with_suffix(".zip").rename(out)
    return out


CSV_CASES = {
    "empty": ("", "empty file"),
    "header_only": ("time,ag\n", "no data rows"),
    "non_numeric": ("time,ag\n0,0\n0.1,abc\n", ":3: column 2: 'abc' is not a number"),
    "non_monotonic": ("time,ag\n0,0\n0.2,1\n0.1,2\n", ":4: time 0.1 is before"),
    # two rows of one time are a step (test_fmi2sim_discrete_inputs.py); a third is refused
    "triplicate_time": ("time,ag\n0,0\n0.1,1\n0.1,2\n0.1,3\n", ":5: time 0.1 is on a third row"),
    "column_count": ("time,ag\n0,0\n0.1,1,5\n", ":3: 3 columns, the header has 2"),
    "unknown_column": ("time,nosuch\n0,0\n", "column 'nosuch' is not a variable"),
    "huge": ("time,ag\n0,0\n0.1,1e999\n", ":3: column 2: '1e999' is out of range"),
    "binary": ("time,ag\n0,0\x00\x01\x02\n", ":2: binary data"),
    # finite but absurd values would overflow inside the model, far from their line
    "huge_finite": ("time,ag\n0,0\n0.1,1e300\n", ":3: column 2: '1e300' is out of range"),
    "huge_time": ("time,ag\n0,0\n-1e300,0\n", ":3: column 1: '-1e300' is out of range"),
    "nan_time": ("time,ag\nnan,0\n", ":2: column 1: 'nan' is out of range"),
    "inf_value": ("time,ag\n0,inf\n", ":2: column 2: 'inf' is out of range"),
    "truncated": ("time,ag\n0,0\n0.1,", ":3: column 2 is empty"),
    "truncated_number": ("time,ag\n0,0\n0.1,1e", ":3: column 2: '1e' is not a number"),
    "empty_field": ("time,ag\n0,0\n0.1,,1\n", ":3: column 2 is empty"),   # was read as "0.1,1"
    "header_gap": ("time,,ag\n0,0,0\n", ":1: header column 2 has no name"),
    "gzip": ("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03", ":1: binary data"),
    "png": ("\x89PNG\r\n\x1a\n\x00\x00", ":1: header names no input column"),
    "output_column": ("time,s1\n0,0\n", ":1: 's1' is not an input of the model"),
    "blank_lines_only": ("\n\n  \n", "empty file"),
}


AT2_CASES = {
    "bad_header": ("a\nb\nc\nno numbers here\n0.1 0.2\n", ":4: expected 'NPTS= N, DT= dt SEC'"),
    "npts_mismatch": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 0.2\n", "2 values, the header says NPTS = 3"),
    "non_numeric": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 x 0.3\n", ":5: 'x' is not a number"),
    "truncated": ("a\nb\n", ":3: file ends inside the 4-line AT2 header"),
    "empty": ("", ":1: file ends inside the 4-line AT2 header"),
    "binary": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1\x00\x07 0.2\n", ":5: binary data"),
    "huge": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 1e400 0.3\n", ":5: '1e400' is out of range"),
    "huge_finite": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 1e300 0.3\n", ":5: '1e300' is out of range"),
    "nan": ("a\nb\nc\nNPTS=  3, DT=   .0200 SEC\n0.1 nan 0.3\n", ":5: 'nan' is out of range"),
    "dt_zero": ("a\nb\nc\nNPTS=  3, DT=   0 SEC\n0.1 0.2 0.3\n", ":4: expected 'NPTS= N, DT= dt SEC'"),
    "dt_huge": ("a\nb\nc\nNPTS=  3, DT=   1e308 SEC\n0.1 0.2 0.3\n", ":4: NPTS * DT = 3 * 1e+308 is out of range"),
    "npts_negative": ("a\nb\nc\nNPTS=  -3, DT=   .02 SEC\n0.1 0.2 0.3\n", ":4: expected 'NPTS= N, DT= dt SEC'"),
    "npts_too_large": ("a\nb\nc\nNPTS=  999999999, DT=   .02 SEC\n0.1\n", ":4: NPTS = 999999999 is too large"),
    "npts_claims_more": ("a\nb\nc\nNPTS=  99999999, DT=   .02 SEC\n0.1\n", "1 values, the header says NPTS = 99999999"),
    "more_than_npts": ("a\nb\nc\nNPTS=  2, DT=   .02 SEC\n0.1 0.2\n0.3\n", ":6: more values than NPTS = 2"),
}


# (option, file suffix, cases) of the two readers of input files
READERS = [("--input", ".csv", CSV_CASES), ("--ag", ".AT2", AT2_CASES)]


@pytest.mark.parametrize("option,suffix,case", [(o, x, c) for o, x, cases in READERS for c in sorted(cases)])
def test_input_file_errors_name_file_and_line(fmi2sim_exe, rockingwall_fmu, tmp_path, option, suffix, case):
    text, message = (CSV_CASES if suffix == ".csv" else AT2_CASES)[case]
    path = tmp_path / f"{case}{suffix}"
    path.write_bytes(text.encode("latin-1"))
    proc = run(fmi2sim_exe, rockingwall_fmu, option, path, check=False)
    assert_one_clear_error(proc, path, message)


def test_at2_scale_that_overflows_is_reported(fmi2sim_exe, rockingwall_fmu, tmp_path):
    path = tmp_path / "ok.AT2"
    path.write_text("a\nb\nc\nNPTS=  2, DT=   .0200 SEC\n0.1 0.2\n")
    proc = run(fmi2sim_exe, rockingwall_fmu, "--ag", path, "--ag-scale", "1e300", check=False)
    assert_one_clear_error(proc, f"{path}:5:", "is out of range")


def repacked(tmp_path, fmu, name, change):
    """A copy of `fmu` with change(folder) applied to its unpacked files."""
    d = tmp_path / name
    with zipfile.ZipFile(fmu) as z:
        z.extractall(d)
    change(d)
    out = tmp_path / f"{name}.fmu"
    shutil.make_archive(str(out.with_suffix("")), "zip", d)
    out.with_suffix(".zip").rename(out)
    return out


def test_broken_fmus_name_the_file(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """An FMU that is empty, cut short, without its binary, with a broken binary or XML, a GUID its
    binary does not know, or a folder without modelDescription.xml: one error naming it."""
    so = "binaries/linux64/RockingWall.so"
    empty = tmp_path / "empty.fmu"
    empty.write_bytes(b"")
    cut = tmp_path / "cut.fmu"
    cut.write_bytes(rockingwall_fmu.read_bytes()[:20000])
    no_md = tmp_path / "folder"
    no_md.mkdir()
    cases = [
        (empty, "not a valid FMU"),
        (cut, "not a valid FMU"),
        (repacked(tmp_path, rockingwall_fmu, "nobin", lambda d: (d / so).unlink()), "cannot load the FMU binary"),
        (repacked(tmp_path, rockingwall_fmu, "badso", lambda d: (d / so).write_text("not ELF")), "cannot load the FMU binary"),
        (repacked(tmp_path, rockingwall_fmu, "badxml",
                  lambda d: (d / "modelDescription.xml").write_text("<fmiModelDescription")), "modelDescription.xml:1: not well-formed XML"),
        (repacked(tmp_path, rockingwall_fmu, "guid", lambda d: (d / "modelDescription.xml").write_text(
            re.sub(r'guid="\{[^}]*\}"', 'guid="{00000000-0000-0000-0000-000000000000}"',
                   (d / "modelDescription.xml").read_text()))), "GUID"),
        (no_md, "modelDescription.xml: No such file"),
    ]
    for fmu, message in cases:
        proc = run(fmi2sim_exe, fmu, "--stop-time", "0.1", check=False)
        assert_one_clear_error(proc, fmu, message)


def test_fmu_and_option_errors(fmi2sim_exe, ball_fmu, tmp_path):
    cases = [
        ([tmp_path / "missing.fmu"], "No such file"),
        ([tmp_path / "notzip.fmu"], "not a valid FMU"),
        ([bad_zip(tmp_path)], "modelDescription.xml"),
        ([wrong_guid(tmp_path, ball_fmu)], "GUID"),
        ([ball_fmu, "--set", "nosuch=1"], "no variable 'nosuch'"),
        ([ball_fmu, "--set", "e=abc"], "'abc' is not a Real"),
        ([ball_fmu, "--set", "bounces=1"], "cannot be set"),
        ([ball_fmu, "--set", "der(h)=1"], "cannot be set"),
        ([ball_fmu, "--frobnicate"], "unknown option"),
        ([ball_fmu, "--rtol"], "--rtol needs a value"),
        ([ball_fmu, "--rtol", "-1"], "--rtol -1 is out of range: it must lie in [1e-12, 0.01]"),
    ]
    (tmp_path / "notzip.fmu").write_text("this is not a zip file")
    for args, message in cases:
        proc = run(fmi2sim_exe, *args, check=False)
        assert proc.returncode != 0, args
        assert message in proc.stderr, (args, proc.stderr)
        assert "Traceback" not in proc.stderr and "Segmentation" not in proc.stderr


def test_integer_type_is_checked(fmi2sim_exe, rockingwall_fmu):
    proc = run(fmi2sim_exe, rockingwall_fmu, "--set", "support=1.5", check=False)
    assert proc.returncode != 0 and "'1.5' is not an Integer" in proc.stderr


def test_fmu_error_is_reported(fmi2sim_exe, rockingwall_fmu):
    proc = run(fmi2sim_exe, rockingwall_fmu, "--set", "h=-1", check=False)
    assert proc.returncode != 0 and "fmi2SetReal" in proc.stderr and "h" in proc.stderr

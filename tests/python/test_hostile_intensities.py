"""Intensities, run lengths and magnitudes that mean nothing physically are refused with one
line naming the value and the bound (exit 2), and what is meaningful always runs: the output
grid ends exactly at the run's end, whatever the record's length and the tail."""
import numpy as np
import pandas as pd
import pytest

import rockingwall as rw
from rockingwall import limits
from cli_harness import assert_refused, cli, pulse, write_csv_record


@pytest.fixture(scope="module")
def rec(tmp_path_factory):
    return pulse(tmp_path_factory.mktemp("rec") / "REC.csv")


@pytest.mark.parametrize("args, needle", [
    (["run", "--pga", "-0.3"], "-0.3"), (["run", "--pga", "0"], "0"), (["run", "--scale", "-1"], "-1"),
    (["run", "--scale", "nan"], "nan"), (["run", "--pga", "inf"], "inf"),
    (["assess", "--pga", "0.2", "-0.3"], "-0.3"), (["assess", "--scale", "-1"], "-1"),
    (["assess", "--sa", "-0.2", "--sa-period", "0.5"], "-0.2"),
    (["animate", "--scale", "-1"], "-1"),
])
def test_finding_non_positive_intensities_are_refused_everywhere(rec, tmp_path, args, needle):
    proc = cli(args[0], rec, *args[1:], "--out", tmp_path / "out")
    assert_refused(proc, needle)
    assert not (tmp_path / "out" / "cases.csv").exists()


@pytest.mark.parametrize("command", [["demo", "--scale", "-0.5"], ["couple", "--scale", "-0.5", "--t-end", "0.1"],
                                     ["couple-building", "--scale", "-1", "--t-end", "0.01"]])
def test_finding_non_positive_scale_is_refused_by_the_other_commands(tmp_path, command):
    assert_refused(cli(*command, cwd=tmp_path), "-0.5" if "-0.5" in command else "-1")


def test_finding_non_positive_intensities_are_refused_by_the_api():
    record = rw.gaussian()
    for bad in (-0.3, 0.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="finite number > 0"):
            record.to_pga(bad)
        with pytest.raises(ValueError, match="finite number > 0"):
            record.scaled(bad)


def test_finding_output_grid_never_overshoots_the_end(tmp_path):
    # a real record's length: 16 392 samples every 2.4 ms = 39.3384 s, not a multiple of 10 ms
    t = np.arange(16392) * 0.0024
    path = write_csv_record(tmp_path / "long.csv", t, 0.05 * np.sin(2 * np.pi * t / 0.7))
    record = rw.read_csv(path)
    wall = rw.Wall.make(preset="paper1")
    for tail in (0.0, 0.013, 1.0, 44.0):
        history = rw.simulate(wall, record, tail=tail).history
        assert history.time.iloc[-1] == pytest.approx(t[-1] + tail, abs=1e-12)
        assert (np.diff(history.time) > 0).all() and history.time.iloc[-1] <= t[-1] + tail
    el_centro = rw.el_centro()
    for tail in range(0, 60):  # 1 893 of 10 001 integer tails overshot the end on El Centro
        r = rw.simulate(wall, el_centro, tail=float(tail))
        assert r.history.time.iloc[-1] == pytest.approx(el_centro.t[-1] + tail, abs=1e-9)
    proc = cli("run", path, "--tail", "44", "--json")
    assert proc.returncode == 0, proc.stderr
    proc = cli("assess", path, "--pga", "0.1", "--out", tmp_path / "assess")
    assert proc.returncode == 0, proc.stderr
    assert len(pd.read_csv(tmp_path / "assess" / "cases.csv")) == 1


def test_finding_run_length_is_bounded_with_the_bound_in_the_message(tmp_path, rec):
    from rockingwall import bounds
    bound = f"{bounds.MAX_RUN_S:g} s"
    huge = write_csv_record(tmp_path / "huge.csv", [0.0, 1e9], [0.1, 0.1])
    assert_refused(cli("run", huge), bound)
    assert_refused(cli("run", rec, "--tail", "1e9"), bound)
    assert_refused(cli("run", rec, "--stop-time", "1e8"), bound)
    assert_refused(cli("run", "gaussian:0.04,1e9"), bound)
    assert_refused(cli("assess", huge, "--pga", "0.2", "--out", tmp_path / "a"), bound)
    with pytest.raises(ValueError, match=bound):
        rw.simulate(rw.Wall.make(), rw.read_csv(huge))


@pytest.mark.parametrize("args, needle", [
    (["--scale", "nan"], "nan"), (["--pga", "nan"], "nan"), (["--stop-time", "-5"], "-5"),
    (["--tail", "-3"], "--tail"),
    # a parapet runs now (slender ones on the engine, stocky ones on fmi2sim), but not a stocky
    # one's ensemble, which only the engine runs: the refusal is one line too
    (["--support", "parapet", "--b", "0.3", "--h", "1.5", "--ensemble", "10"], "--ensemble 0"),
])
def test_finding_package_errors_are_one_line_and_exit_2(rec, args, needle):
    assert_refused(cli("run", rec, *args), needle)


def test_finding_a_record_starting_before_zero_is_one_clear_line(tmp_path):
    early = write_csv_record(tmp_path / "early.csv", [-1.0, 1.0, 2.0], [0.1, 0.2, 0.0])
    assert_refused(cli("run", early), "early.csv", "t = -1")


def test_finding_physically_meaningless_magnitudes_are_refused_with_the_bound(tmp_path, rec):
    from rockingwall import bounds
    big = write_csv_record(tmp_path / "big.csv", [0.0, 1.0, 2.0], [0.1, 1e300, 0.0])
    assert_refused(cli("run", big), "big.csv", f"{bounds.MAX_AG_G:g} g")
    assert_refused(cli("run", rec, "--pga", "1e6"), f"{bounds.MAX_AG_G:g} g")
    assert_refused(cli("assess", rec, "--pga", "0.2", "--limit", "A: s1 >= 1e999mm", "--out", tmp_path / "a"),
                   "1e999mm")
    wall = rw.Wall.make(preset="paper1")
    with pytest.raises(ValueError, match="2.5 m"):  # beyond the wall's height: no displacement of the wall
        limits.parse("A: s2 >= 3 m", wall)
    with pytest.raises(ValueError, match="not finite|finite"):
        rw.Wall.make(b="1e999mm")


def test_finding_a_utf16_csv_record_is_read_or_named(tmp_path, rec):
    text = rec.read_text()
    for encoding in ("utf-16", "utf-16-le", "utf-8-sig"):
        path = tmp_path / f"r_{encoding}.csv"
        bom = {"utf-16-le": "\ufeff"}.get(encoding, "")
        path.write_bytes((bom + text).encode(encoding))
        same = rw.read_csv(path)
        assert np.array_equal(same.ag, rw.read_csv(rec).ag) and np.array_equal(same.t, rw.read_csv(rec).t)
    garbage = tmp_path / "latin.csv"
    garbage.write_bytes(b"time,ag\n0,0\n1,0.1\xff\n")
    assert_refused(cli("run", garbage), "latin.csv:3", "UTF-8")


def test_finding_a_file_named_gaussian_is_a_file(tmp_path, rec):
    named = tmp_path / "gaussian_site.csv"
    named.write_text(rec.read_text())
    loaded = rw.read_record(str(named))
    assert loaded.name == "gaussian_site" and np.array_equal(loaded.ag, rw.read_csv(rec).ag)
    assert rw.read_record("gaussian:0.04,1").name.startswith("Gaussian")
    assert_refused(cli("run", "gaussian:abc"), "gaussian:abc")

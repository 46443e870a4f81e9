"""Sweeps of a building file (rockingwall.sweep.building_runs): one row per storey, record and
intensity, each the storey's wall in the building solved in one integration; resumable, and an
edited building file makes its rows stale."""
import shutil

import numpy as np
import pandas as pd
import pytest

from rockingwall.building import building_file, monolithic
from rockingwall.commands import sweep as sweep_command
from rockingwall.records import read_at2
from rockingwall.sweep import building_runs, rows as row_format, store, suites


@pytest.fixture
def building(tmp_path, repo):
    path = tmp_path / "house.toml"
    shutil.copy(repo / "examples" / "two-storey-brick.toml", path)
    return path


def sweep(building, out, *extra):
    return sweep_command.main(["--building", str(building), "--suite", "fema", "--records", "ff07a", "ff03a",
                               "--pga", "0.2", "0.5", "--tail", "1", "--out", str(out), "--scheduler",
                               "synchronous", "--no-progress", *extra])


def test_a_building_sweep_has_one_row_per_storey_as_the_building_run_gives(building, tmp_path):
    out = tmp_path / "sweep.csv"
    assert sweep(building, out) == 0
    rows = pd.read_csv(out)
    assert len(rows) == 2 * 2 * 2 and set(rows.status) == {"ok"} and set(rows.model) == {"building"}
    assert sorted(rows.wall.unique()) == ["two-storey brick, timber floors: storey 1",
                                          "two-storey brick, timber floors: storey 2"]
    fema = {r.name: r for r in suites.fema_farfield(suites.fema_cache())}
    b = building_file.read(building)
    for row in rows.itertuples():
        record = read_at2(fema[row.record].path).scaled(row.scale)
        result, _ = monolithic.simulate_building(b, record, t_end=float(record.t[-1]) + 1.0)
        s = result.storeys[int(row.wall[-1]) - 1]
        assert row.collapsed == s.collapsed
        assert row.peak_s1 == pytest.approx(s.peak_s1_m, rel=1e-12)
        assert row.peak_s2 == pytest.approx(s.peak_s2_m, rel=1e-12)
    assert rows.peak_F_top.isna().all()  # the tie force is not computed here: empty, not a 0 that reads as none
    assert np.allclose(rows.scale * rows.record_pga_g, rows.pga_g)


def test_a_resumed_building_sweep_reuses_rows_until_the_file_changes(building, tmp_path, capsys):
    out = tmp_path / "sweep.csv"
    assert sweep(building, out) == 0
    assert sweep(building, out) == 0
    assert "nothing to do" in capsys.readouterr().out
    building.write_text(building.read_text().replace('stiffness = "20 kN/m/m"', 'stiffness = "200 kN/m/m"'))
    capsys.readouterr()
    assert sweep(building, out) == 0
    rows = pd.read_csv(out)
    assert (rows.kd_kN == 200.0).sum() == 4  # the upper storey's runs again, with the new roof
    # the edited file's runs replace the old ones (set aside, named): the file holds one study. Its
    # runs were named by the file's content and kept beside the new ones, and ida drew the two
    # buildings as one ('2 runs' of one record and intensity)
    assert len(rows) == 8 and rows.run_id.is_unique
    assert capsys.readouterr().err.count("computed from other inputs (settings differ") == 8
    (aside,) = tmp_path.glob("sweep.csv.set-aside-*")
    assert (pd.read_csv(aside).kd_kN == 20.0).sum() == 4


def test_ida_refuses_a_file_with_two_versions_of_a_building(building, tmp_path):
    """A results file with runs of one building name from two versions of its file (an earlier
    sweep's rows, or two files joined) is refused by ida, not drawn as one building."""
    from rockingwall.sweep import ida
    out, other = tmp_path / "sweep.csv", tmp_path / "other.csv"
    assert sweep(building, out) == 0
    building.write_text(building.read_text().replace('mass = "600 kg/m"', 'mass = "650 kg/m"'))
    assert sweep(building, other) == 0
    joined = tmp_path / "joined.csv"
    joined.write_text(out.read_text() + "".join(other.read_text().splitlines(keepends=True)[1:]).replace(
        "|storey", "|copy|storey"))  # distinct run_ids, as files of earlier versions had
    with pytest.raises(ValueError, match="in the file twice, computed from different inputs"):
        ida.load(joined, "storey 2")
    assert len(ida.load(out, "storey 2")) == 4


def test_rows_of_the_earlier_format_are_computed_again(building, tmp_path, monkeypatch, capsys):
    """Rows written when a building row's peak_F_top was 0 are not reused on resume: the row format
    is part of each run's key."""
    out = tmp_path / "sweep.csv"
    monkeypatch.setattr(building_runs, "ROW_FORMAT", "1")
    assert sweep(building, out) == 0
    monkeypatch.undo()
    capsys.readouterr()
    assert sweep(building, out) == 0
    said = capsys.readouterr()
    assert said.err.count("computed from other inputs (settings differ") == 8
    assert "8 runs (0 errors, 0 killed or timed out, 0 already done)" in said.out
    rows = pd.read_csv(out)
    assert len(rows) == 8 and rows.peak_F_top.isna().all()


def test_only_a_building_row_may_leave_its_tie_force_empty():
    good = {c: "1" for c in row_format.COLUMNS} | dict(run_id="r", status="ok", collapsed="False", steps="3",
                                                 impacts="2", model=row_format.BUILDING_MODEL, peak_F_top="")
    assert store.check_row(good) == ""
    assert "peak_F_top" in store.check_row(dict(good, model="RockingWall"))
    assert "peak_s1" in store.check_row(dict(good, peak_s1=""))


def test_a_bad_building_file_is_refused_with_its_line(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text('[[storey]]\nheight = "3 m"\n')
    assert sweep(bad, tmp_path / "out.csv", "--dry-run") == 2
    assert f"{bad}:1: storey 1.wall is missing" in capsys.readouterr().err


def test_the_plan_names_the_building_scene(building, tmp_path, capsys):
    """A building sweep's plan echoed the building but not the scene its runs are solved in."""
    assert sweep(building, tmp_path / "out.csv", "--dry-run") == 0
    printed = capsys.readouterr().out
    assert "scene: walls in a 2-storey building (two-storey brick, timber floors): each wall stands on the floor " \
           "below and is tied to the diaphragm above" in printed
    assert "left out: the diaphragms' higher modes" in printed

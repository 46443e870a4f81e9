"""`assess` beyond the paper's scene: a wall under a diaphragm with mass, and every storey's wall
of a building file; each case's scene named, its nominal run the scene solver's, its ensemble
run through the scene solver."""
import numpy as np
import pandas as pd
import pytest

import rockingwall as rw
from rockingwall.building import building_file, monolithic, tie_force
from rockingwall.building.description import Diaphragm
from rockingwall.cli import main

PULSE = "gaussian:0.04,1.0"


def test_assess_a_building_per_storey(repo, tmp_path, capsys):
    path = repo / "examples" / "two-storey-brick.toml"
    assert main(["assess", PULSE, "--building", str(path), "--pga", "0.2", "0.6", "--ensemble", "6",
                 "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    cases = pd.read_csv(tmp_path / "cases.csv")
    assert list(cases.storey) == [1, 2, 1, 2] and set(cases.scene) == {"building"}
    assert cases.collapse_probability.between(0, 1).all()
    nominal, _ = monolithic.simulate_building(building_file.read(path), rw.read_record(PULSE).to_pga(0.2))
    for s in nominal.storeys:
        row = cases[(cases.storey == s.storey) & (cases.level == 0.2)].iloc[0]
        if s.collapsed:
            assert row.collapsed and np.isnan(row.peak_s1_mm)
        else:
            assert row.peak_s1_mm == pytest.approx(s.peak_s1_m * 1e3, rel=1e-5)
    frag = pd.read_csv(tmp_path / "fragility.csv")
    assert set(frag.storey) == {1, 2} and set(frag.over) == {"records", "records and parameters"}
    assert "scene: walls in a 2-storey building" in out and "storey 2" in out
    assert "note:" not in capsys.readouterr().err  # linear diaphragms: the exact engine, nothing to say


def assess_edited_house(repo, tmp_path, old, new):
    """`assess` of the assessor's house with `old` replaced by `new` in its file (two intensities,
    an ensemble of 2): the exit code"""
    path = tmp_path / "edited.toml"
    path.write_text((repo / "examples" / "two-storey-brick.toml").read_text().replace(old, new))
    return main(["assess", PULSE, "--building", str(path), "--pga", "0.1", "0.2", "--ensemble", "2",
                 "--out", str(tmp_path / "out")])


def test_a_bouc_wen_building_runs_on_the_exact_engine(repo, tmp_path, capsys):
    """A study of a building with Bouc-Wen diaphragms ran on CVODES, seconds a run, and a note said
    so. The exact engine now takes the law (its hysteretic force a fitted input over each step):
    nothing to say."""
    assert assess_edited_house(repo, tmp_path, "damping = 0.05 }",
                               'damping = 0.05, law = "boucWen", yield_force = "2.2 kN/m", post_yield = 0.1 }') == 0
    assert "note:" not in capsys.readouterr().err


def test_a_building_cvodes_takes_says_what_its_study_costs(repo, tmp_path, capsys):
    """A building the exact engine does not cover (a wall on the rigid hinge law) runs on CVODES,
    seconds a run: a note counts the runs first and gives the exact engine's reason."""
    assert assess_edited_house(repo, tmp_path, 'overburden = "1.5 kN/m" }',
                               'overburden = "1.5 kN/m", hinge_law = "rigid" }') == 0
    assert ("rockingwall: note: 6 runs of a building with linear diaphragms, on CVODES: seconds a run (storey 2: "
            "the exact engine takes hinge laws whose moments are affine on a region (semiRigidHinge, dohertyHinge), "
            "not rigid)" in capsys.readouterr().err)


def test_assess_a_wall_under_a_diaphragm_with_mass(tmp_path, capsys):
    args = ["--b", "230mm", "--h", "3.6", "--W", "14.904kN/m", "--psi", "0.2013"]
    assert main(["assess", PULSE, *args, "--kd-values", "20kN/m/m", "--diaphragm-mass", "200kg/m", "--pga", "0.3",
                 "--ensemble", "4", "--out", str(tmp_path)]) == 0
    row = pd.read_csv(tmp_path / "cases.csv").iloc[0]
    wall = rw.Wall.make(b=0.23, h=3.6, W=14904.0, psi=0.2013, Kd=20e3)
    alone = rw.simulate(wall, rw.read_record(PULSE).to_pga(0.3), diaphragm=Diaphragm(20e3, 200.0))
    assert row.scene == "diaphragm" and row.peak_s1_mm == pytest.approx(alone.peak_s1 * 1e3, rel=1e-5)
    assert "diaphragm of K_d (each above), 200 kg/m" in capsys.readouterr().out


def test_a_limit_on_the_tie_force_has_its_probability_over_the_members(tmp_path, monkeypatch):
    """Under a diaphragm with mass the members' tie forces are computed as the nominal run's
    (filtered at 25 Hz) where a limit state asks for F_top: a threshold below every member's force
    is reached by all, one far above by none (the probability was left blank: no member had it).
    Where no limit is on F_top only the nominal run's tie force is computed."""
    calls = []
    real_sample = tie_force.sample
    monkeypatch.setattr(tie_force, "sample", lambda *a, **kw: calls.append(1) or real_sample(*a, **kw))
    args = ["--b", "230mm", "--h", "3.6", "--W", "14.904kN/m", "--psi", "0.2013", "--kd-values", "20kN/m/m",
            "--diaphragm-mass", "200kg/m", "--pga", "0.1", "--ensemble", "4"]
    limits = ["--limit", "low: F_top >= 0.1kN/m", "--limit", "high: F_top >= 100kN/m"]
    assert main(["assess", "elcentro", *args, *limits, "--out", str(tmp_path / "f")]) == 0
    row = pd.read_csv(tmp_path / "f" / "cases.csv").iloc[0]
    assert not row.collapsed and 0.5 < row.peak_F_top_kN_per_m < 5.0
    assert row.p_low == 1.0 and row.p_high == 0.0
    assert len(calls) == 1 + 4
    calls.clear()
    assert main(["assess", "elcentro", *args, "--out", str(tmp_path / "s")]) == 0
    assert len(calls) == 1

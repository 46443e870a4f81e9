"""A scene the exact engine does not cover (here: the rigid hinge law, whose moments are not affine
on a region) runs on CVODES, seconds a run, and `run` and `assess` say first how many runs they
will make. The count was each case once and each ensemble member once. But a case of a wall
under a diaphragm with mass also runs the sensitivity check's two scaled records and a dense run
for its tie force, and a member runs its own tie force's where a limit state is on F_top. A dense
run is repeated at a finer sampling where its filtered peaks do not settle, up to
floor_acc.REFINEMENTS times. So the note now gives the fewest and the most runs. These tests
count the runs the command really makes against it."""
import re

import pytest

from rockingwall import scene_engine
from rockingwall.building import floor_acc
from rockingwall.cli import main

PULSE = "gaussian:0.04,1.0"
WALL = ["--b", "230mm", "--h", "3.6", "--W", "14.904kN/m", "--psi", "0.2013", "--Kd", "20kN/m/m",
        "--diaphragm-mass", "200kg/m", "--hinge-law", "rigid"]
TIE_LIMIT = ["--limit", "anchor: F_top >= 100kN/m"]


@pytest.fixture
def runs(monkeypatch):
    """The engine of every scene run the command makes, in order."""
    made, real = [], scene_engine.run

    def counted(*args, **kwargs):
        made.append(kwargs.get("engine"))
        return real(*args, **kwargs)
    monkeypatch.setattr(scene_engine, "run", counted)
    return made


def noted(err):
    """(fewest, most) runs in the command's CVODES note."""
    (line,) = [line for line in err.splitlines() if "on CVODES" in line]
    m = re.search(r"note: (\d+)(?: to (\d+))? runs? of ", line)
    return int(m[1]), int(m[2] or m[1])


def check(runs, err, fewest, dense_runs):
    """The note's count is the hand count (`fewest`, and `dense_runs` dense runs each refined at
    most REFINEMENTS times), and the runs made are within it, every one on CVODES."""
    assert noted(err) == (fewest, fewest + floor_acc.REFINEMENTS * dense_runs)
    assert fewest <= len(runs) <= fewest + floor_acc.REFINEMENTS * dense_runs
    assert set(runs) == {"cvode"}


def test_run_counts_the_checks_and_the_members(runs, capsys):
    """One record, an ensemble of 2: the nominal run, the sensitivity check's 2, the tie force's
    dense run, and a run per member (the default limit states ask for no tie force): 6 at least."""
    assert main(["run", PULSE, *WALL, "--pga", "0.3", "--ensemble", "2", "--json"]) == 0
    check(runs, capsys.readouterr().err, 6, dense_runs=1)


def test_assess_counts_the_members_tie_forces(runs, tmp_path, capsys):
    """One intensity, one K_d, an ensemble of 2, a limit state on F_top: the nominal case's 4 runs
    and 2 per member (its own and its tie force's), 8 at least with 3 dense runs."""
    assert main(["assess", PULSE, *WALL, *TIE_LIMIT, "--pga", "0.3", "--ensemble", "2",
                 "--out", str(tmp_path)]) == 0
    check(runs, capsys.readouterr().err, 8, dense_runs=3)


def test_assess_a_building_counts_its_runs(repo, runs, tmp_path, capsys):
    """A building study runs no sensitivity check: with an ensemble of 2 and a limit state on
    F_top, each intensity runs the nominal building, its tie forces, and 2 runs per member."""
    text = (repo / "examples" / "two-storey-brick.toml").read_text().replace(
        'overburden = "1.5 kN/m" }', 'overburden = "1.5 kN/m", hinge_law = "rigid" }')
    path = tmp_path / "rigid.toml"
    path.write_text(text)
    assert main(["assess", PULSE, "--building", str(path), *TIE_LIMIT, "--pga", "0.1", "--ensemble", "2",
                 "--out", str(tmp_path / "out")]) == 0
    check(runs, capsys.readouterr().err, 6, dense_runs=3)

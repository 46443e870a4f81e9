"""`rockingwall run` on a wall under a diaphragm with mass (the scene solver): the tie's force is a
force only while the wall stands, and the sensitivity check `rockingwall building` makes is made
and reported here too."""
import json

import numpy as np
import pytest

import rockingwall as rw
from rockingwall.building import monolithic
from rockingwall.building.description import Diaphragm
from rockingwall.cli import main

# the assessor's upper wall under its existing roof diaphragm; El Centro at 0.3 g topples it at 4.4 s
WALL_ARGS = ["--b", "230mm", "--h", "3.6", "--W", "14.904kN/m", "--psi", "0.2013", "--Kd", "20kN/m/m"]
ROOF = Diaphragm(20e3, 200.0)
TIE = 1e8


@pytest.fixture(scope="module")
def toppled():
    wall = rw.Wall.make(b=0.23, h=3.6, W=14904.0, psi=0.2013, Kd=20e3, warn=False)
    return rw.simulate(wall, rw.read_record("elcentro").to_pga(0.3), diaphragm=ROOF, tie=TIE)


def test_a_toppled_walls_tie_force_is_the_one_while_it_stood(toppled):
    """After a collapse the wall's histories hold its last state while the diaphragm moves on, free:
    their difference times the tie (1e8 N/m per m) was reported as a force of 36.6 MN/m. The force
    is the largest stretch while the wall stood: about 12 kN/m, the diaphragm's own scale (its
    spring at the wall's top displacement plus its mass at a few g)."""
    r = toppled
    assert r.collapsed and 4.0 < r.t_collapse < 5.0
    h = r.history
    standing = h["time"] < r.t_collapse
    diaphragm_force = 20e3 * np.max(np.abs(h["s2"][standing])) + 200.0 * 5 * 9.81
    assert 0.0 < r.peak_F_top < 2.0 * diaphragm_force < 1e5


def test_the_sensitivity_check_is_made_and_in_the_json(toppled, capsys):
    """The peaks' sensitivity to a 1e-9 change of the record, as the building command gives it."""
    assert toppled.peak_sensitivity is not None and toppled.peak_sensitivity >= 0.0
    assert main(["run", *WALL_ARGS, "--diaphragm-mass", "200kg/m", "--pga", "0.3", "elcentro", "--json"]) == 0
    (run,) = json.loads(capsys.readouterr().out)["runs"]
    assert run["peak_sensitivity"] == toppled.peak_sensitivity
    assert run["sensitive"] is (toppled.peak_sensitivity > monolithic.SENSITIVITY_SHARE)


def test_a_sensitive_run_is_said_under_the_table(monkeypatch, capsys):
    """Where the check finds the peaks move (made so here), the table says so in a line of its own;
    the paper's scene (no diaphragm mass) makes no check and says nothing."""
    monkeypatch.setattr(monolithic, "peak_sensitivity", lambda r, scaled: 0.08)
    assert main(["run", *WALL_ARGS, "--diaphragm-mass", "200kg/m", "--pga", "0.2", "gaussian:0.04,1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert any(line.startswith("sensitive: ") and "8.0%" in line for line in lines)
    assert main(["run", *WALL_ARGS, "--pga", "0.2", "gaussian:0.04,1", "--json"]) == 0
    (run,) = json.loads(capsys.readouterr().out)["runs"]
    assert "peak_sensitivity" not in run

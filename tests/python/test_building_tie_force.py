"""Each storey's tie force in a building (`rockingwall building`, `assess --building`): the force the
tie puts on its diaphragm, filtered at 25 Hz as the floor's acceleration is, from the scene's own
tie-force history; the same whatever the tie's stiffness, on both engines, and for one storey the
wall under its diaphragm's."""
import json

import numpy as np
import pandas as pd
import pytest

import rockingwall as rw
from rockingwall.building import building_file, monolithic
from rockingwall.cli import main

HOUSE = """\
[building]
name = "two-storey brick, timber floors"

[[storey]]
height = "4.0 m"
wall = {{ b = "350 mm", W = "25.2 kN/m", overburden = "3.2 kN/m" }}
diaphragm = {{ stiffness = "60 kN/m/m", mass = "600 kg/m", damping = 0.05 }}
tie = "{tie} N/m/m"

[[storey]]
height = "3.6 m"
wall = {{ b = "230 mm", unit_weight = "18 kN/m3", overburden = "1.5 kN/m" }}
diaphragm = {{ stiffness = "20 kN/m/m", mass = "200 kg/m", damping = 0.05 }}
tie = "{tie} N/m/m"
"""


def house(tie):
    return building_file.parse(HOUSE.format(tie=f"{tie:g}"), "house.toml")


@pytest.fixture(scope="module")
def record():
    return rw.read_record("elcentro").to_pga(0.1)


def test_every_storeys_tie_force_is_the_filtered_one_the_ties_stiffness_leaves_alone(record):
    """El Centro at 0.1 g, both walls standing: each storey's filtered tie force is the same at ties
    of 1e8, 3e8, 1e9 N/m per m within 5 % (the walls' own peaks move by 2 % between these ties, and
    the force, which carries the diaphragm's inertia, by 3 %), while the raw one is 8 times larger at
    1e8 and grows with the tie; at 1e8 the exact
    engine and CVODES agree within 1 %. (A tie of 1e7 under the floor's 600 kg/m rings at 20 Hz,
    inside the band: there its ringing is part of the floor's motion and of the force, 2.5 kN/m
    against 1.4.) A building's tie forces were not computed before."""
    forces, raws = [], []
    for tie in (1e8, 3e8, 1e9):
        result, _ = monolithic.simulate_building(house(tie), record, filter_floor=False, tie_forces=True)
        assert result.tie_resolved and not any(s.collapsed for s in result.storeys)
        forces.append([s.tie_force_N_per_m for s in result.storeys])
        raws.append([s.tie_force_raw_N_per_m for s in result.storeys])
    forces, raws = np.array(forces), np.array(raws)
    assert np.all(forces.max(axis=0) / forces.min(axis=0) < 1.05)
    assert np.all(raws[2] > 2.5 * raws[0]) and np.all(raws.min(axis=0) > 5.0 * forces.max(axis=0))
    cvode, _ = monolithic.simulate_building(house(1e8), record, filter_floor=False, tie_forces=True, solver="cvode")
    assert [s.tie_force_N_per_m for s in cvode.storeys] == pytest.approx(forces[0], rel=0.01)


def test_one_storeys_tie_force_is_that_of_the_wall_under_its_diaphragm(record):
    """A building of the upper storey alone on rigid in-plane walls is the wall under its roof
    (scene b): the same tie force as `run --diaphragm-mass` gives."""
    one = building_file.parse(HOUSE.format(tie="1e8").split("[[storey]]")[0] + "[[storey]]" +
                              HOUSE.format(tie="1e8").split("[[storey]]")[2], "roof.toml")
    result, _ = monolithic.simulate_building(one, record, filter_floor=False, tie_forces=True)
    (s,) = result.storeys
    wall = rw.Wall.make(warn=False, **one.wall_parameters(0))
    alone = rw.simulate(wall, record, diaphragm=one.storeys[0].diaphragm, tie=one.storeys[0].tie)
    assert s.tie_force_N_per_m == pytest.approx(alone.peak_F_top, rel=1e-9)
    assert s.peak_s1_m == pytest.approx(alone.peak_s1, rel=1e-9)


def test_the_command_prints_and_gives_the_tie_forces(tmp_path, capsys):
    path = tmp_path / "house.toml"
    path.write_text(HOUSE.format(tie="1e8"))
    assert main(["building", str(path), "elcentro", "--pga", "0.1", "--json"]) == 0
    (run,) = json.loads(capsys.readouterr().out)["runs"]
    assert run["tie_force"]["resolved"] is True and run["tie_force"]["cutoff_hz"] == 25.0
    for s in run["storeys"]:
        assert 0 < s["tie_force_N_per_m"] < s["tie_force_raw_N_per_m"]
    assert main(["building", str(path), "elcentro", "--pga", "0.1"]) == 0
    out = capsys.readouterr().out
    assert "tie [kN/m]" in out
    assert f"{run['storeys'][1]['tie_force_N_per_m'] / 1e3:.2f}" in out


def test_assess_a_buildings_ties(tmp_path):
    """`assess --building --limit "anchor: F_top >= ..."` was refused (the tie forces were not
    computed); now each storey's row has its tie force and the limit its probability over the
    members: reached by all below every force, by none far above."""
    path = tmp_path / "house.toml"
    path.write_text(HOUSE.format(tie="1e8"))
    limits = ["--limit", "low: F_top >= 0.05kN/m", "--limit", "high: F_top >= 100kN/m"]
    assert main(["assess", "gaussian:0.04,1", "--building", str(path), "--pga", "0.2", *limits,
                 "--ensemble", "4", "--out", str(tmp_path / "out")]) == 0
    cases = pd.read_csv(tmp_path / "out" / "cases.csv")
    assert list(cases.storey) == [1, 2] and not cases.collapsed.any()
    assert (cases.peak_F_top_kN_per_m > 0.1).all()
    assert (cases.p_low == 1.0).all() and (cases.p_high == 0.0).all()



def test_the_floors_and_the_ties_are_sampled_from_one_run(record, monkeypatch):
    """`rockingwall building` ran the floors' and the ties' dense histories as two runs of the same
    scene on the same grid (five runs a record with the sensitivity check's two; 8.4 s of
    wall-clock time for a hysteretic two-storey building). One run now gives both, with the same
    samples as each alone gave."""
    from rockingwall import scene_engine
    from rockingwall.building import floor_acc, tie_force
    b = house(1e8)
    spec, walls = monolithic.building_spec(b), [b.wall_parameters(i) for i in range(2)]
    calls, real_run = [], scene_engine.run
    monkeypatch.setattr(scene_engine, "run", lambda *a, **kw: calls.append(kw.get("histories")) or real_run(*a, **kw))
    alone = floor_acc.sample(spec, record), tie_force.sample(spec, record)
    runs_alone = len(calls)  # each sampler's, its sampling refined as the ringing asks (here once)
    calls.clear()
    result, _ = monolithic.respond(spec, walls, record, check_sensitivity=True, tie_forces=True)
    dense = [c for c in calls if c and "s1" not in c]
    assert dense == [("base_acc", "tie")] * (runs_alone // 2) and len(calls) == 3 + len(dense)
    floor, ties = monolithic.sampled(spec, record, None, 1e-8, "exact", True, True)
    for one, each in zip((floor, ties), alone):
        assert one.dt == each.dt and np.array_equal(one.filtered, each.filtered)
    assert [s.tie_force_N_per_m for s in result.storeys] == [float(x) for x in ties.filtered_peak]

"""A storey without a face-loaded wall (`wall = "none"` in the building file: an open front, a
shopfront on a beam or a frame), as main-street masonry buildings often have at the ground: its
diaphragm is there, the walls above stand on its floor, no wall above bears on a wall below it.

Checked: the file reads it and refuses what cannot go with it; the weight of the walls above stops
at it; the upper wall on an open ground storey whose floor cannot move is the upper wall standing on
the ground (a one-storey building); `rockingwall building` says "no wall" where the wall's numbers
would be, in the table, the JSON and the CSV; `assess --building` and the sweeps take the walls
only; BuildingWithWalls.fmu runs it as the scene solver does."""
import json

import numpy as np
import pandas as pd
import pytest
from fmpy import simulate_fmu

import rockingwall as rw
from rockingwall import records
from rockingwall.building import building_file, monolithic, with_walls
from rockingwall.cli import main

UPPER = 'wall = { b = "230 mm", unit_weight = "18 kN/m3", overburden = "1.5 kN/m" }'
SHOPFRONT = f"""\
[building]
name = "shopfront below, brick above"

[[storey]]
height = "4.0 m"
wall = "none"
diaphragm = {{ stiffness = "60 kN/m/m", mass = "600 kg/m", damping = 0.05 }}

[[storey]]
height = "3.6 m"
{UPPER}
diaphragm = {{ stiffness = "20 kN/m/m", mass = "200 kg/m", damping = 0.05 }}
"""


@pytest.fixture()
def shopfront(tmp_path):
    path = tmp_path / "shopfront.toml"
    path.write_text(SHOPFRONT)
    return path


def test_the_file_takes_a_storey_without_a_wall():
    b = building_file.parse(SHOPFRONT, "shopfront.toml")
    assert b.storeys[0].wall is None and b.walled() == [1] and b.wall_parameters(0) is None
    assert "storey 1: h = 4 m; no face-loaded wall (an open front" in b.describe()
    spec = monolithic.building_spec(b)
    assert spec.storeys[0].wall is None and spec.storeys[1].wall["psiWeightOnly"] == 0.0


@pytest.mark.parametrize("edit, line, words", [
    (lambda t: t.replace('wall = "none"\n', ''), 4, 'wall = "none" for a storey without one'),  # its header
    (lambda t: t.replace('wall = "none"\n', 'wall = "none"\ntie = "1e7 N/m/m"\n'), 7,
     "a storey without a wall has no tie"),
    (lambda t: t.replace(UPPER, 'wall = "none"'), 1, "no storey has a face-loaded wall"),
])
def test_what_cannot_go_with_it_is_refused_on_its_line(edit, line, words):
    with pytest.raises(building_file.BuildingFileError) as err:
        building_file.parse(edit(SHOPFRONT), "shopfront.toml")
    assert str(err.value).startswith(f"shopfront.toml:{line}:") and words in str(err.value), str(err.value)


def test_the_weight_of_the_walls_above_stops_at_a_storey_without_one():
    """Three storeys, the middle one open: the top wall bears on the open storey's beam, so the
    ground wall carries no walls above it; without the opening it carries the top wall's weight
    and overburden, and nothing for an open storey."""
    ground = '\n[[storey]]\nheight = "4.0 m"\nwall = { b = "350 mm", W = "25.2 kN/m", overburden = "3.2 kN/m" }\n' \
             'diaphragm = { stiffness = "60 kN/m/m", mass = "600 kg/m" }\n'
    middle = '\n[[storey]]\nheight = "3.6 m"\nwall = "none"\ndiaphragm = { stiffness = "60 kN/m/m", mass = "600 kg/m" }\n'
    top = f'\n[[storey]]\nheight = "3.6 m"\n{UPPER}\ndiaphragm = {{ stiffness = "20 kN/m/m", mass = "200 kg/m" }}\n'
    head = '[building]\nname = "three"\n'
    opened = building_file.parse(head + ground + middle + top)
    closed = building_file.parse(head + ground + top.replace('"3.6 m"', '"3.6 m"', 1) + top)
    assert opened.weight_above(0) == 0.0
    assert closed.weight_above(0) == pytest.approx(2 * (18e3 * 0.23 * 3.6 + 1.5e3))
    assert opened.wall_parameters(0)["psiWeightOnly"] == 0.0 and opened.wall_parameters(1) is None


def test_an_open_storey_with_a_floor_that_cannot_move_is_the_ground():
    """The upper wall on an open ground storey whose floor diaphragm is rigid (1e10 N/m per m)
    stands on the ground: its peaks are those of a one-storey building of that wall alone, within
    1e-3, and its floor's deformation is a few micrometres."""
    rec = rw.read_record("elcentro").to_pga(0.1)
    stiff = SHOPFRONT.replace('stiffness = "60 kN/m/m"', 'stiffness = "1e10 N/m/m"')
    one = SHOPFRONT[SHOPFRONT.index("[[storey]]"):]
    one = '[building]\nname = "one"\n\n' + one[one.index("[[storey]]", 5):]
    open_ground, _ = monolithic.simulate_building(building_file.parse(stiff), rec, filter_floor=False)
    alone, _ = monolithic.simulate_building(building_file.parse(one), rec, filter_floor=False)
    upper, (single,) = open_ground.storeys[1], alone.storeys
    assert open_ground.solver == "exact" and not upper.collapsed and upper.peak_s1_m > 0.01
    print(f"upper wall on the rigid open storey: s1 {upper.peak_s1_m:.6f}, s2 {upper.peak_s2_m:.6f} m; alone on the "
          f"ground: {single.peak_s1_m:.6f}, {single.peak_s2_m:.6f} m; floor {open_ground.storeys[0].diaphragm_peak_m:.2e} m")
    assert upper.peak_s1_m == pytest.approx(single.peak_s1_m, rel=1e-3)
    assert upper.peak_s2_m == pytest.approx(single.peak_s2_m, rel=1e-3)
    assert open_ground.storeys[0].diaphragm_peak_m < 1e-5


def test_the_outputs_say_no_wall(shopfront, tmp_path, capsys):
    assert main(["building", str(shopfront), "elcentro", "--pga", "0.1", "--out", str(tmp_path / "out")]) == 0
    rows = [line for line in capsys.readouterr().out.splitlines() if line.startswith("El Centro")]
    assert rows[0].split()[-2:] == ["no", "wall"] and rows[0].split()[7:10] == ["-", "-", "-"]
    assert rows[1].split()[-1] == "standing"
    assert main(["building", str(shopfront), "elcentro", "--pga", "0.1", "--json"]) == 0
    first, second = json.loads(capsys.readouterr().out)["runs"][0]["storeys"]
    assert first["wall"] is False and first["peak_s1_m"] is None and first["s1_over_Delta_u"] is None
    assert first["diaphragm_peak_m"] > 0 and second["wall"] is True and second["peak_s1_m"] > 0
    (csv,) = (tmp_path / "out").glob("*.csv")
    history = pd.read_csv(csv)
    assert history["s1_m_1"].isna().all() and history["diaphragm_m_1"].notna().all()
    assert history["s1_m_2"].notna().all()


def test_assess_takes_the_walls_only(shopfront, tmp_path, capsys):
    assert main(["assess", "gaussian:0.04,1", "--building", str(shopfront), "--pga", "0.1", "0.3", "--ensemble", "4",
                 "--code", "nzsee", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    cases = pd.read_csv(tmp_path / "cases.csv")
    assert set(cases.storey) == {2} and len(cases) == 2
    assert set(pd.read_csv(tmp_path / "fragility.csv").storey) == {2}
    assert "codes on storey 2's wall" in out and "codes on storey 1's wall" not in out


def test_a_sweep_has_rows_for_the_walls_only(shopfront):
    from rockingwall.sweep import building_runs, suites
    suite = [suites.Record("pulse", "pulse.csv", 0.1, 1.0)]
    specs = building_runs.expand({"building": str(shopfront), "pga_g": [0.1, 0.2], "scales": None, "tail": 0.0}, suite)
    assert [s.run_id.split("|")[1] for s in specs] == ["storey2", "storey2"]


def test_the_fmu_runs_it_as_the_scene_solver(shopfront, build_dir):
    house = building_file.read(shopfront)
    values = with_walls.start_values(house)
    assert values["hasWall_1"] == 0 and "b_1" not in values and values["hasWall_2"] == 1
    rec = records.el_centro().to_pga(0.1)
    ref, _ = monolithic.simulate_building(house, rec, t_end=6.0, filter_floor=False)
    signal = np.array(list(zip(rec.t, rec.ag)), dtype=[("time", float), ("ag", float)])
    res = simulate_fmu(str(build_dir / "BuildingWithWalls.fmu"), fmi_type="ModelExchange", stop_time=6.0,
                       output_interval=1e-3, start_values=values, input=signal, relative_tolerance=1e-8,
                       output=["s1_2", "s2_2", "d_diaph_1", "d_diaph_2"])
    upper = ref.storeys[1]
    assert float(np.abs(res["s1_2"]).max()) == pytest.approx(upper.peak_s1_m, rel=1e-2)
    assert float(np.abs(res["d_diaph_1"]).max()) == pytest.approx(ref.storeys[0].diaphragm_peak_m, rel=1e-2)

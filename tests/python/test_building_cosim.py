"""A building file co-simulated (`rockingwall couple-building --building`, rockingwall.building.cosim)
and the energy stop of the coupled runs (rockingwall.coupling.energy_guard):

- past the limit, the assessor's building at its real masses ends with an error naming the cause
  and the remedy, exit 1, no peak or collapse printed (without the stop the same run "collapses"
  both walls at 0.1 s under 1e-6 g: the issue this fixes);
- within the limit (light walls on heavy diaphragms) the co-simulation equals the one-integration
  solver within 1 %;
- `rockingwall couple` stops too: the stiff tie at the old 1 ms step over 15 s ends with the error,
  before the false collapse it used to report at 8.1 s, and writes nothing;
- the Building FMU's dashpots cd_i: a free vibration decays by the damping ratio they stand for,
  and with the defaults (0) it does not decay at all.
"""
import json
import pathlib
import re
import shlex

import numpy as np
import pytest
from fmpy import simulate_fmu

from rockingwall import cli, paths, records
from rockingwall.building import building_file, cosim, monolithic, scene as bs
from rockingwall.commands import couple as couple_command
from rockingwall.commands import couple_building

LIGHT = """
[building]
name = "two storeys, light walls on heavy diaphragms"
tie = "1e5 N/m/m"
[[storey]]
height = "2.5 m"
wall = { b = "150 mm", W = "6.622 kN/m" }
diaphragm = { stiffness = "700 kN/m/m", mass = "2000 kg/m", damping = 0.05 }
[[storey]]
height = "2.5 m"
wall = { b = "150 mm", W = "6.622 kN/m" }
diaphragm = { stiffness = "700 kN/m/m", mass = "2000 kg/m", damping = 0.05 }
"""


def test_the_assessors_building_past_the_limit_ends_with_the_error(repo, capsys):
    path = repo / "examples" / "two-storey-brick.toml"
    status = couple_building.main(["--building", str(path), "--record", "elcentro", "--pga", "1e-6", "--t-end", "1"])
    out, err = capsys.readouterr()
    assert status == 1
    assert "went unstable" in err and "storey 2" in err and "0.36 times" in err
    # the remedy runs the same building, record and intensity (it named the file alone: El Centro as given)
    remedy = re.search(r"`(rockingwall building [^`]*)`", err).group(1)
    assert remedy == f"rockingwall building {path} elcentro --pga 1e-06"
    assert cli.main(shlex.split(remedy)[1:]) == 0
    assert "storey 2" in capsys.readouterr().out
    fmu = paths.where("BuildingWithWalls.fmu")  # the one FMU an FMI user can take instead: where it is
    assert f"in an FMI tool {fmu} " in err and fmu.is_file()
    assert "peak" not in out and "collapsed" not in out and out == ""
    # the same run without the stop: the scheme's motion, reported as collapses
    scene = cosim.scene_of(building_file.read(path))
    r = bs.run(scene, records.el_centro().to_pga(1e-6), 1.0, 1e-3, order=2, energy_stop=None)
    assert sorted(r["collapsed"]) == [1, 2] and max(r["collapsed"].values()) < 0.2


def test_within_the_limit_co_simulation_equals_one_integration(tmp_path, capsys):
    path = tmp_path / "light.toml"
    path.write_text(LIGHT)
    building = building_file.read(path)
    # 0.18 g: the lower wall, under the upper one's weight (weight-only overburden), rocks too
    rec = records.el_centro().to_pga(0.18)
    mono, _ = monolithic.simulate_building(building, rec, t_end=8.0)
    r = bs.run(cosim.scene_of(building), rec, 8.0, 1e-3, order=2)
    assert not r["collapsed"] and r.energy_share_max < 0.01
    for s in mono.storeys:
        i = s.storey
        assert not s.collapsed and s.peak_s1_m > 0.012  # rocking (twice Delta_1 or more), standing
        assert r.peak(i, "s1") == pytest.approx(s.peak_s1_m, rel=0.01)
        assert r.peak(i, "s2") == pytest.approx(s.peak_s2_m, rel=0.01)
        assert np.abs(r[f"u_diaph_{i}"] - r[f"u_floor_{i}"]).max() == pytest.approx(s.diaphragm_peak_m, rel=0.01)
    # and the command prints them
    assert couple_building.main(["--building", str(path), "--record", "elcentro", "--pga", "0.12", "--t-end", "2"]) == 0
    assert "wall in storey 2: peak s1" in capsys.readouterr().out


def test_couple_stops_the_stiff_tie_at_the_old_step(build_dir, tmp_path, capsys):
    out = tmp_path / "new" / "deeper" / "c.csv"  # folders couple makes for its outputs: gone after the failure
    status = couple_command.main([f"--wall-fmu={build_dir / 'RockingWall.fmu'}",
                                  f"--diaphragm-fmu={build_dir / 'Diaphragm.fmu'}", f"--out={out}",
                                  f"--plot={tmp_path / 'c.png'}", "--set=b=0.23", "--set=h=3.2", "--set=W=14080",
                                  "--set=psi=0.2", "--Kd=1e6", "--m=400", "--k=30e3", "--scale=0.4705",
                                  "--t-end=15", "--macro-step=1e-3"])
    captured = capsys.readouterr()
    assert status == 1
    assert "went unstable" in captured.err and "--monolithic" in captured.err and "2.35e-05" in captured.err
    assert f"in an FMI tool {paths.where('BuildingWithWalls.fmu')})" in captured.err
    assert not out.exists() and not (tmp_path / "c.png").exists() and "peak" not in captured.out
    assert not (tmp_path / "new").exists()  # they were left behind, empty


def free_vibration(build_dir, cd):
    start = {"nStoreys": 1, "storeyLaw": 0, "diaphragmLaw": 0, "m_1": 1000.0, "k_1": 1e11,
             "cs_1": 2 * np.sqrt(1e14), "md_1": 600.0, "kd_1": 6e4, "rayleighMass": 0.0,
             "rayleighStiffness": 0.0, "u_diaph_1": 0.01}
    if cd is not None:
        start["cd_1"] = cd
    res = simulate_fmu(str(build_dir / "Building.fmu"), fmi_type="ModelExchange", stop_time=3.0, output_interval=1e-3,
                       start_values=start, output=["u_diaph_1"], relative_tolerance=1e-9)
    return res["time"], res["u_diaph_1"]


def test_building_dashpot_is_the_damping_ratio(build_dir):
    zeta = 0.05
    t, y = free_vibration(build_dir, 2 * zeta * np.sqrt(6e4 * 600.0))
    peaks = [y[k] for k in range(1, len(y) - 1) if y[k] > y[k - 1] and y[k] > y[k + 1] and y[k] > 0]
    decrement = np.mean(np.log(np.array(peaks[:-1]) / np.array(peaks[1:])))
    assert decrement == pytest.approx(2 * np.pi * zeta / np.sqrt(1 - zeta ** 2), rel=0.01)
    _, undamped = free_vibration(build_dir, None)  # the default cd_1 = 0: no decay
    assert undamped.max() == pytest.approx(0.01, rel=1e-4) and undamped[-500:].max() == pytest.approx(0.01, rel=1e-3)


def test_the_coupled_commands_name_their_scene(build_dir, tmp_path, capsys):
    """`couple` and `couple-building` printed peaks without saying which scene they ran (every other
    command names it and what it leaves out); couple's JSON summary had no scene either."""
    out = tmp_path / "c.csv"
    assert couple_command.main(["--t-end=1", f"--out={out}", f"--plot={tmp_path / 'c.png'}", "--m=400", "--k=30e3",
                                "--Kd=1e6"]) == 0
    printed = capsys.readouterr().out
    scene = ("a wall tied (1e+06 N/m per m) to a diaphragm of 30 kN/m per m, 400 kg/m, 5 % damping, whose supports "
             "(the in-plane walls) move with the ground")
    assert f"scene: {scene}\nleft out: the floor's motion below the wall" in printed
    assert json.loads(out.with_suffix(".json").read_text())["scene"]["description"] == scene
    assert couple_building.main(["--record", "elcentro", "--pga", "0.05", "--t-end", "0.5"]) == 0
    printed = capsys.readouterr().out
    assert printed.startswith("scene: walls in a 2-storey building (the Building FMU's defaults; the paper's wall 1 "
                              "in storeys 1, 2): each wall stands on the floor below and is tied to the diaphragm "
                              "above; pinched Bouc-Wen diaphragms with mass and damping\nleft out: ")
    assert "solved by co-simulation: Building.fmu and a RockingWall.fmu per wall, Jacobi, H = 0.001 s" in printed


def test_a_collapsed_wall_is_printed_as_its_collapse_not_as_peaks(capsys):
    """couple-building printed 'wall in storey 1: peak s1 0.14255 m, s2 0.02015 m' and, lines
    later, that the wall collapsed at 10.335 s: the 'peak' was the state it fell from (wall 1 is
    0.15 m thick), which a reader takes for a displacement. A collapsed wall's line is now its
    collapse; a standing wall's line keeps its peaks."""
    assert couple_building.main(["--storeys", "2", "--record", "elcentro", "--scale", "0.5"]) == 0
    lines = [l for l in capsys.readouterr().out.splitlines() if l.startswith("wall in storey")]
    assert [l.split(" and ")[0] for l in lines] == ["wall in storey 1: collapsed at t = 10.335 s",
                                                    "wall in storey 2: collapsed at t = 10.668 s"]
    assert couple_building.main(["--storeys", "2", "--record", "elcentro", "--scale", "0.1", "--t-end", "5"]) == 0
    lines = [l for l in capsys.readouterr().out.splitlines() if l.startswith("wall in storey")]
    assert len(lines) == 2 and all(" peak s1 " in l and "collapsed" not in l for l in lines)


def test_couple_building_takes_the_building_and_the_record_as_building_does(capsys):
    """`rockingwall building FILE.toml RECORD` against `couple-building --building FILE --record R`:
    the same building in the two commands took two spellings. couple-building now takes the file
    and the record as `building` does too (the options stay), and refuses one given both ways."""
    path = str(pathlib.Path(__file__).resolve().parents[2] / "examples" / "two-storey-brick.toml")
    a = couple_building.parse_args([path, "gaussian:0.03,1", "--pga", "0.1"])
    assert (a.building, a.record) == (path, "gaussian:0.03,1")
    a = couple_building.parse_args(["--building", path])
    assert (a.building, a.record) == (path, "elcentro")
    assert couple_building.parse_args(["--storeys", "2"]).building is None
    with pytest.raises(SystemExit) as stop:
        couple_building.parse_args([path, "--building", path])
    assert stop.value.code == 2 and "the building is given twice" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        couple_building.parse_args([path, "elcentro", "--record", "elcentro"])
    assert "the record is given twice" in capsys.readouterr().err

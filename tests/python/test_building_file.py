"""The building file (rockingwall.building.building_file), the command `rockingwall building` and
the scene every output names: values with units, errors naming the file and the line, strict JSON."""
import json

import pytest

import rockingwall as rw
from rockingwall import cli
from rockingwall.building import building_file

CONTRACT = """\
[building]
name = "two-storey brick, timber floors"

[[storey]]                                   # ground storey first
height = "4.0 m"
wall = { b = "350 mm", W = "25.2 kN/m", overburden = "3.2 kN/m" }
diaphragm = { stiffness = "60 kN/m/m", mass = "600 kg/m", damping = 0.05 }
tie = "1e6 N/m/m"

[[storey]]
height = "3.6 m"
wall = { b = "230 mm", unit_weight = "18 kN/m3", overburden = "1.5 kN/m" }
diaphragm = { stiffness = "20 kN/m/m", mass = "200 kg/m", damping = 0.05 }
tie = "1e6 N/m/m"
"""


def test_the_contract_reads_in_si_units():
    b = building_file.parse(CONTRACT, "house.toml")
    ground, upper = b.storeys
    assert ground.height == 4.0 and ground.wall.b == pytest.approx(0.35) and ground.wall.W == pytest.approx(25.2e3)
    assert ground.wall.overburden == pytest.approx(3.2e3)
    assert ground.diaphragm.stiffness == pytest.approx(60e3) and ground.diaphragm.mass == pytest.approx(600.0)
    assert upper.wall.W == pytest.approx(18e3 * 0.23 * 3.6)  # 14.904 kN/m from the unit weight
    assert upper.tie == pytest.approx(1e6) and b.rigid_in_plane
    params = b.wall_parameters(1)
    assert params["psi"] == pytest.approx(2 * 1.5e3 / (18e3 * 0.23 * 3.6)) and params["Kd"] == pytest.approx(1e6)


def test_an_eccentric_overburden_reaches_the_wall_and_the_echo():
    """e_top: where the storey's overburden bears (toward the inner face); the walls above bear on
    the centreline as weight only, so the ground wall's eTop is its own overburden's alone."""
    text = CONTRACT.replace('overburden = "1.5 kN/m"', 'overburden = "1.5 kN/m", e_top = "-80 mm"')
    b = building_file.parse(text.replace('overburden = "3.2 kN/m"', 'overburden = "3.2 kN/m", e_top = "175 mm"'))
    assert [s.wall.e_top for s in b.storeys] == pytest.approx([0.175, -0.08])
    assert [b.wall_parameters(i)["eTop"] for i in (0, 1)] == pytest.approx([0.175, -0.08])
    assert "overburden 3.2 kN/m at 175 mm from the centreline" in b.describe()
    assert building_file.parse(CONTRACT).wall_parameters(0)["eTop"] == 0.0


def test_the_echo_gives_a_hysteretic_diaphragms_yield_force_and_post_yield():
    """`rockingwall building` echoed a Bouc-Wen diaphragm as '60 kN/m per m, 600 kg/m, 5 % damping
    (boucWen; own period 0.628 s)': the yield force and post-yield ratio the file gave each storey
    (3 and 1 kN/m here) were not in the echo, so the output did not say what ran. They are, with a
    pinched law's pinching."""
    hysteretic = CONTRACT.replace('damping = 0.05 }', 'damping = 0.05, law = "boucWen", yield_force = "3 kN/m", '
                                  'post_yield = 0.1 }', 1)
    hysteretic = hysteretic.replace('damping = 0.05 }', 'damping = 0.05, law = "boucWen", yield_force = "1 kN/m", '
                                    'post_yield = 0.1 }')
    said = building_file.parse(hysteretic).describe()
    assert "5 % damping (boucWen, yield force 3 kN/m, post-yield 0.1; own period 0.628 s)" in said
    assert "5 % damping (boucWen, yield force 1 kN/m, post-yield 0.1; own period 0.628 s)" in said
    pinched = building_file.parse(hysteretic.replace('"boucWen"', '"boucWenPinched"')).describe()
    assert "post-yield 0.1, pinching pinch_size 0.8, pinch_width 0.2, pinch_centre 0.1;" in pinched
    assert "5 % damping (linear; own period 0.628 s)" in building_file.parse(CONTRACT).describe()


def test_a_bilinear_diaphragm_is_read_echoed_and_run_on_the_exact_engine(tmp_path, capsys):
    """law = "bilinear" (elastoplastic with kinematic hardening) takes a yield force and a post-yield
    ratio as the Bouc-Wen laws do; the building runs on the exact engine, and its diaphragms yield."""
    text = CONTRACT.replace('damping = 0.05 }', 'damping = 0.05, law = "bilinear", yield_force = "0.4 kN/m", '
                            'post_yield = 0.1 }')
    b = building_file.parse(text)
    assert [s.diaphragm.law for s in b.storeys] == ["bilinear", "bilinear"]
    assert "5 % damping (bilinear, yield force 0.4 kN/m, post-yield 0.1; own period 0.628 s)" in b.describe()
    path = tmp_path / "bilinear.toml"
    path.write_text(text)
    assert cli.main(["building", str(path), "gaussian:0.04,1", "--scale", "1", "--json"]) == 0
    (run,) = _strict(capsys.readouterr().out)["runs"]
    assert run["solver"] == "exact"
    dy = [0.4e3 / s.diaphragm.stiffness for s in b.storeys]
    assert all(s["diaphragm_peak_m"] > 2 * y for s, y in zip(run["storeys"], dy))
    with pytest.raises(building_file.BuildingFileError, match="yield_force is given with a hysteretic law"):
        building_file.parse(text.replace(', yield_force = "0.4 kN/m"', '', 1))


@pytest.mark.parametrize("edit, line, words", [  # the line the problem is on (was its storey's header's)
    (lambda t: t.replace('damping = 0.05 }\ntie = "1e6', 'dampin = 0.05 }\ntie = "1e6', 1), 7, "unknown key"),
    (lambda t: t.replace('stiffness = "60 kN/m/m"', 'stiffness = "60 kN/m"'), 7, "not a unit of"),
    (lambda t: t.replace('W = "25.2 kN/m", ', 'W = "25.2 kN/m", unit_weight = "18 kN/m3", '), 6, "one of the two"),
    (lambda t: t.replace('height = "3.6 m"', 'height = "3.6 m"\nheight = "3 m"'), 12, "not valid TOML"),
    (lambda t: t.replace('mass = "200 kg/m"', 'mass = "-200 kg/m"'), 13, "outside"),
    (lambda t: t.replace('wall = { b = "350 mm"', 'wal = { b = "350 mm"'), 6, "unknown key"),
    (lambda t: t.replace('overburden = "1.5 kN/m"', 'overburden = "1.5 kN/m", e_top = "120 mm"'), 12,
     "|e_top| <= b/2 = 115 mm"),
    (lambda t: t.replace('tie = "1e6 N/m/m"\n\n', 'tie = "1e6 N/m"\n\n'), 8, "not a unit of"),
    (lambda t: t.replace('wall = { b = "230 mm", unit_weight = "18 kN/m3", overburden = "1.5 kN/m" }\n', '')
     + '\n[storey.wall]\nb = "230 mm"\nunit_weight = "18 kN/m3"\noverburden = "-1.5 kN/m"\n', 18,
     "outside"),  # a sub-table's key on its own line
    (lambda t: t.replace('diaphragm = { stiffness = "20 kN/m/m", mass = "200 kg/m", damping = 0.05 }', ''), 10,
     "diaphragm is missing"),  # nothing to point at: the storey's header
    # a damping ratio written as a percentage without its sign: the range ended in a unit '1'
    (lambda t: t.replace('mass = "200 kg/m", damping = 0.05', 'mass = "200 kg/m", damping = 5'), 13,
     'storey 2.diaphragm.damping = 5 is outside [0, 2] (a ratio: 5 % is 0.05 or "5 %")'),
    # a TOML boolean is named as the file has it ('cannot read True' was Python's spelling)
    (lambda t: t.replace('height = "3.6 m"', 'height = true'), 11, "storey 2.height: cannot read true as a number"),
])
def test_a_bad_file_names_the_file_the_line_and_the_problem(edit, line, words):
    with pytest.raises(building_file.BuildingFileError) as err:
        building_file.parse(edit(CONTRACT), "house.toml")
    assert str(err.value).startswith(f"house.toml:{line}:") and words in str(err.value)


def test_the_command_line_refuses_a_bad_file_without_a_traceback(tmp_path, capsys):
    path = tmp_path / "house.toml"
    path.write_bytes(b"\xff\xfe[building]")
    assert cli.main(["building", str(path), "gaussian"]) == 2
    err = capsys.readouterr().err
    assert f"{path}:1: not UTF-8" in err and "Traceback" not in err


def _strict(text):
    def refuse(name):
        raise ValueError(f"not JSON: {name}")
    return json.loads(text, parse_constant=refuse)


@pytest.fixture(scope="module")
def house(tmp_path_factory):
    path = tmp_path_factory.mktemp("house") / "house.toml"
    path.write_text(CONTRACT)
    return path


def test_the_json_contract(house, capsys):
    """A list `storeys` per run, each with the contract's keys; a standing wall's t_collapse_s is
    null; valid JSON (no NaN); the scene named."""
    assert cli.main(["building", str(house), "gaussian:0.04,1", "--scale", "1", "--json"]) == 0
    data = _strict(capsys.readouterr().out)
    assert data["scene"]["name"] == "building" and "left" not in data["scene"]["leaves_out"][:0]
    (run,) = data["runs"]
    assert [s["storey"] for s in run["storeys"]] == [1, 2]
    for s in run["storeys"]:
        assert {"peak_s1_m", "peak_s2_m", "collapsed", "t_collapse_s", "diaphragm_peak_m",
                "base_peak_acc_m_s2"} <= set(s)
        assert s["collapsed"] is False and s["t_collapse_s"] is None
        assert 0 < s["peak_s1_m"] < 0.1 and s["diaphragm_peak_m"] > 0
    assert run["storeys"][0]["base_peak_acc_m_s2"] == pytest.approx(2.56, rel=0.01)  # the ground's own peak


def test_a_collapse_is_a_time_in_the_table_and_in_json(house, capsys):
    """A collapsed wall's peaks were numbers in the JSON (the state it collapsed at: 0.23 m, its
    thickness, for the upper wall), where the table prints '-'; a program reading peak_s1_m took
    them as displacements. They are null now, as its s1/Delta_u, and the notes say why."""
    assert cli.main(["building", str(house), "gaussian:0.3,1", "--scale", "1", "--json"]) == 0
    data = _strict(capsys.readouterr().out)
    storeys = data["runs"][0]["storeys"]
    fallen = [s for s in storeys if s["collapsed"]]
    assert fallen and all(isinstance(s["t_collapse_s"], float) and s["t_collapse_s"] > 0 for s in fallen)
    assert all(s[k] is None for s in fallen for k in ("peak_s1_m", "peak_s2_m", "s1_over_Delta_u"))
    assert all(isinstance(s["peak_s1_m"], float) for s in storeys if not s["collapsed"])
    assert "null for a collapsed wall" in data["notes"]["peak_s1_m"]
    assert cli.main(["building", str(house), "gaussian:0.3,1", "--scale", "1"]) == 0
    out = capsys.readouterr().out
    assert "collapsed at" in out and "scene: walls in a 2-storey building" in out and "left out:" in out


def test_run_names_the_scene_it_ran(capsys):
    wall = ["--b", "230mm", "--h", "3.6", "--W", "14.904kN/m", "--psi", "0.2013", "--Kd", "20kN/m/m"]
    assert cli.main(["run", *wall, "gaussian:0.04,1"]) == 0
    paper = capsys.readouterr().out
    assert "scene: the paper's" in paper and "diaphragm's mass and damping and the floor's motion" in paper
    assert cli.main(["run", *wall, "--diaphragm-mass", "200kg/m", "--tie", "1e6", "gaussian:0.04,1", "--json"]) == 0
    data = _strict(capsys.readouterr().out)
    assert data["scene"]["name"] == "diaphragm" and "200 kg/m" in data["scene"]["description"]


def test_run_with_a_building_file_is_the_building_command(house, capsys):
    assert cli.main(["run", "--building", str(house), "gaussian:0.04,1", "--json"]) == 0
    assert len(_strict(capsys.readouterr().out)["runs"][0]["storeys"]) == 2
    assert cli.main(["run", "--building", str(house), "--b", "0.3", "gaussian"]) == 2


def test_the_floor_acceleration_is_filtered_and_says_at_what(house, capsys):
    """The raw peak above the ground carries the tie's ringing after the impacts and grows with the
    tie's stiffness (docs/your-building.md, "Floor acceleration"); the table and the JSON give it
    low-pass filtered at 25 Hz, say so beside the number, and keep the raw one apart in the JSON."""
    assert cli.main(["building", str(house), "gaussian:0.04,1", "--scale", "1"]) == 0
    assert "low-pass filtered at 25 Hz" in capsys.readouterr().out
    assert cli.main(["building", str(house), "gaussian:0.04,1", "--scale", "1", "--json"]) == 0
    data = _strict(capsys.readouterr().out)
    assert "25 Hz" in data["notes"]["base_peak_acc_m_s2"] and "tie" in data["notes"]["base_peak_acc_raw_m_s2"]
    (run,) = data["runs"]
    assert run["floor_acc"]["cutoff_hz"] == 25.0 and run["floor_acc"]["resolved"] is True
    for s in run["storeys"]:
        assert 0 < s["base_peak_acc_m_s2"] and 0 < s["base_peak_acc_raw_m_s2"]


def test_a_ratio_may_be_written_in_percent(house, capsys):
    """'5 %' is 0.05 wherever a ratio is read: the building file's damping, --diaphragm-damping, psi."""
    b = building_file.parse(CONTRACT.replace("damping = 0.05", 'damping = "5 %"'))
    assert [s.diaphragm.damping for s in b.storeys] == [pytest.approx(0.05)] * 2
    args = ["run", "--wall", "paper1", "--Kd", "50kN/m/m", "--diaphragm-mass", "200kg/m", "gaussian", "--json"]
    runs = []
    for damping in ("0.05", "5%"):
        assert cli.main(args + ["--diaphragm-damping", damping]) == 0
        runs.append(json.loads(capsys.readouterr().out)["runs"][0])
    assert runs[0] == runs[1]
    assert cli.main(["run", "--wall", "paper1", "--psi", "20 %", "gaussian", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["wall"]["psi"] == pytest.approx(0.2)


def test_a_diaphragm_option_without_the_diaphragm_is_refused(capsys):
    """--diaphragm-damping (as --tie) describes a diaphragm with mass: alone it was silently ignored."""
    assert cli.main(["run", "--wall", "paper1", "--Kd", "50kN/m/m", "--diaphragm-damping", "0.1", "gaussian"]) == 2
    assert "--diaphragm-damping is of a diaphragm with mass" in capsys.readouterr().err


def test_a_bare_number_the_wall_model_cannot_take_names_its_line_and_the_slip():
    """A bare number is SI: `W = 25.2` is 25.2 N/m, and the overburden of 3.2 kN/m is then 254 times
    half of it. The file was read, and the run failed in the scene solver ('invalid parameter psi =
    253.97') with no file, no line and no word of the unit."""
    with pytest.raises(building_file.BuildingFileError) as err:
        building_file.parse(CONTRACT.replace('W = "25.2 kN/m"', "W = 25.2"), "house.toml")
    message = str(err.value)
    assert message.startswith("house.toml:6: storey 1.wall: psi = ") and "must be in [0, 20]" in message
    assert "W/(b h) = 0.018 kN/m^3 is not a masonry unit weight" in message and '"25.2 kN/m"' in message


def test_an_implausible_number_is_warned_with_its_line_and_refused_with_strict(tmp_path, capsys):
    """`stiffness = 20` is 20 N/m per m, a diaphragm with a period of 20 s: it ran without a word.
    It is now a warning naming the line and the likely unit, an error with --strict (as `run` does
    for K_d and the wall's unit weight), and so are a diaphragm's mass and a tie out of range."""
    text = CONTRACT.replace('stiffness = "20 kN/m/m"', "stiffness = 20").replace('mass = "600 kg/m"', "mass = 0.6")
    with pytest.warns(rw.PlausibilityWarning) as caught:
        building_file.parse(text, "house.toml")
    assert sorted(str(w.message) for w in caught) == [
        "house.toml:13: storey 2: the diaphragm's stiffness 20 N/m per m is outside [500, 1e+10] N/m per m: did you "
        'mean kN/m per m ("20 kN/m/m")?',
        "house.toml:7: storey 1: the diaphragm's mass 0.6 kg/m is outside [10, 100000] kg/m per metre of wall: is the "
        'unit right ("0.6 t/m")?']
    path = tmp_path / "house.toml"
    path.write_text(text)
    assert cli.main(["building", str(path), "gaussian", "--pga", "0.1", "--strict"]) == 2
    assert "house.toml:7: storey 1: the diaphragm's mass 0.6 kg/m" in capsys.readouterr().err  # the first
    assert cli.main(["building", str(path), "gaussian", "--pga", "0.1"]) == 0
    assert capsys.readouterr().err.count(f"rockingwall: warning: {path}:") == 2
    with pytest.warns(rw.PlausibilityWarning, match="the tie 100 N/m per m"):
        building_file.parse(CONTRACT.replace('tie = "1e6 N/m/m"', 'tie = "100 N/m/m"', 1), "house.toml")


@pytest.mark.parametrize("option, value, said", [
    ("--diaphragm-damping", "5", "--diaphragm-damping 5: must be in [0, 2] (a ratio: 5 % is 0.05 or 5%)"),
    ("--tie", "0.5", "--tie 0.5 N/m per m: must be in [1, 1e+12] N/m per m"),
    ("--diaphragm-mass", "2e8kg/m", "--diaphragm-mass 2e+08 kg/m: must be in [1e-06, 1e+07] kg/m"),
    ("--diaphragm-mass", "1e-7kg/m", "--diaphragm-mass 1e-07 kg/m: must be in [1e-06, 1e+07] kg/m"),
])
def test_a_diaphragm_option_out_of_range_is_named_alone(option, value, said, capsys):
    """One of --diaphragm-mass, --diaphragm-damping and --tie out of range was refused with all three
    ranges in one sentence, naming neither the option nor the value."""
    args = ["run", "--wall", "paper1", "--Kd", "50kN/m/m", "--diaphragm-mass", "200kg/m", "gaussian"]
    assert cli.main(args + [option, value]) == 2
    assert capsys.readouterr().err.strip() == f"rockingwall: error: {said}"


@pytest.mark.parametrize("key, option, unit", [("mass", "--diaphragm-mass", "kg/m"), ("damping", "--diaphragm-damping", ""),
                                               ("tie", "--tie", "N/m/m")])
def test_the_diaphragm_options_take_the_building_files_ranges(key, option, unit, capsys):
    """The command line took a diaphragm mass in (0, 1e7) kg/m where the building file takes
    [1e-6, 1e7]: a mass of 1e-7 ran from the command line and 1e7 was refused, the file the other
    way round. The command line now takes each end of the file's range (building_file.RANGES) and
    refuses a step past it."""
    args = ["run", "--wall", "paper1", "--Kd", "50kN/m/m", "--diaphragm-mass", "200kg/m", "gaussian", "--pga", "0.01",
            "--stop-time", "0.05", "--json"]
    low, high = building_file.RANGES[key]
    for value, ok in ((low, True), (high, True), (low * (1 - 1e-3) if low else -1e-3, False), (high * (1 + 1e-3), False)):
        code = cli.main(args + [option, f"{value!r}{unit}"])
        capsys.readouterr()
        assert code == (0 if ok else 2), (option, value)

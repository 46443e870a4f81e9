"""Scene (b) with a hysteretic diaphragm from the command line: `run` and `assess` took a
diaphragm with mass as linear only (--diaphragm-mass, --diaphragm-damping, --tie), where a
one-storey building file could already say law = "bilinear" or "boucWen" with a yield force. The
options --diaphragm-law, --diaphragm-yield and --diaphragm-post-yield give the same scene, take
the building file's ranges, are named in the scene line, and an ensemble perturbs the yield force."""
import json

import pytest

from rockingwall import ensemble as ens
from rockingwall.building import monolithic
from rockingwall.building.description import POST_YIELD_DEFAULT
from rockingwall.cli import main

PULSE = "gaussian:0.04,1.0"
# the assessor's upper wall (overburden 1.5 kN/m: psi = 2 x 1500.0876 / 14904) under its existing roof
WALL_ARGS = ["--b", "230mm", "--h", "3.6", "--W", "14.904kN/m", "--psi", "0.2013", "--Kd", "20kN/m/m",
             "--diaphragm-mass", "200kg/m"]
ONE_STOREY = """[building]
name = "the upper wall alone"
[[storey]]
height = "3.6 m"
wall = {{ b = "230 mm", W = "14.904 kN/m", overburden = "1500.0876 N/m" }}
diaphragm = {{ stiffness = "20 kN/m/m", mass = "200 kg/m", damping = 0.05, law = "{law}", yield_force = "{fy}" }}
"""


def run_json(capsys, *extra, record=PULSE, pga="0.3", notes=None):
    """The run's JSON; its notes on stderr appended to `notes`."""
    assert main(["run", record, *WALL_ARGS, "--pga", pga, "--json", *extra]) == 0
    out, err = capsys.readouterr()
    if notes is not None:
        notes += [line for line in err.splitlines() if line.startswith("rockingwall: note:")]
    return json.loads(out)


def test_a_bilinear_diaphragm_that_never_yields_is_the_linear_one(capsys):
    """Every branch of the bilinear law is linear: with a yield force it never reaches (1e9 N/m,
    against the 1.7 kN/m the roof takes) the exact engine gives the linear diaphragm's peaks."""
    linear = run_json(capsys)["runs"][0]
    never = run_json(capsys, "--diaphragm-law", "bilinear", "--diaphragm-yield", "1e9")["runs"][0]
    assert linear["engine"] == never["engine"] == "scene (exact)"
    assert not linear["collapsed"] and linear["peak_s1_m"] > 0.02
    for key in ("peak_s1_m", "peak_s2_m"):
        assert never[key] == pytest.approx(linear[key], rel=1e-9)


@pytest.mark.parametrize("law", ["bilinear", "boucWen"])
def test_a_yielding_diaphragm_is_the_one_storey_building_files(law, tmp_path, capsys):
    """The same wall and diaphragm as a one-storey building file (its supports on the ground, the
    default tie): the same peaks within 1e-6 on the same solver, and a yield force that changes the
    answer (the roof yields at 1 kN/m: peak s1 moves by more than 5 % from the linear roof's).
    Both laws run on the exact engine, and say nothing of CVODES."""
    linear = run_json(capsys)["runs"][0]
    notes = []
    got = run_json(capsys, "--diaphragm-law", law, "--diaphragm-yield", "1kN/m", notes=notes)
    assert notes == []
    (r,) = got["runs"]
    assert f"({law}, yield force 1 kN/m, post-yield {POST_YIELD_DEFAULT:g})" in got["scene"]["description"]
    path = tmp_path / "one.toml"
    path.write_text(ONE_STOREY.format(law=law, fy="1 kN/m"))
    assert main(["building", str(path), PULSE, "--pga", "0.3", "--json"]) == 0
    (storey,) = json.loads(capsys.readouterr().out)["runs"][0]["storeys"]
    assert r["engine"] == "scene (exact)"
    assert r["peak_s1_m"] == pytest.approx(storey["peak_s1_m"], rel=1e-6)
    assert r["peak_s2_m"] == pytest.approx(storey["peak_s2_m"], rel=1e-6)
    assert abs(r["peak_s1_m"] / linear["peak_s1_m"] - 1) > 0.05


@pytest.mark.parametrize("options, message", [
    (["--diaphragm-law", "bilinear"], "--diaphragm-law bilinear: give its yield force too (--diaphragm-yield"),
    (["--diaphragm-yield", "2kN/m"], "--diaphragm-yield is of a hysteretic diaphragm: give --diaphragm-law too"),
    (["--diaphragm-law", "boucWen", "--diaphragm-yield", "0"], "--diaphragm-yield 0 N/m: must be in [0.001, 1e+09]"),
    (["--diaphragm-law", "bilinear", "--diaphragm-yield", "2kN/m", "--diaphragm-post-yield", "1.5"],
     "--diaphragm-post-yield 1.5: must be in [0, 1]"),
    (["--diaphragm-law", "bilinear", "--diaphragm-yield", "2kN"], "--diaphragm-yield: unit 'kN' is not a unit"),
])
def test_the_law_options_are_checked(options, message, capsys):
    assert main(["run", PULSE, *WALL_ARGS, "--pga", "0.3", *options]) != 0
    assert message in capsys.readouterr().err


@pytest.mark.parametrize("options", [["--diaphragm-law", "bilinear"], ["--diaphragm-yield", "2kN/m"]])
def test_a_law_without_a_diaphragm_with_mass_is_refused(options, capsys):
    """The paper's scene has a massless spring to a fixed point: a law given there would be dropped."""
    assert main(["run", PULSE, *WALL_ARGS[:-2], "--pga", "0.3", *options]) != 0
    assert "is of a diaphragm with mass: give --diaphragm-mass too" in capsys.readouterr().err


def test_a_building_file_takes_no_law_options(repo, capsys):
    house = str(repo / "examples" / "two-storey-brick.toml")
    for command in ("run", "assess"):
        assert main([command, PULSE, "--building", house, "--pga", "0.3", "--diaphragm-law", "bilinear"]) != 0
        assert "--building FILE describes the walls and diaphragms" in capsys.readouterr().err


def test_an_ensemble_perturbs_a_hysteretic_diaphragms_yield_force(monkeypatch, tmp_path, capsys):
    """Each member's yield force is the nominal's times its diaphragm_yield factor, as a building's
    is, and the report's ensemble line names the spread; a linear scene (b) still does not."""
    built = []
    spec_of = monolithic.wall_under_diaphragm_spec
    monkeypatch.setattr(monolithic, "wall_under_diaphragm_spec",
                        lambda w, d, tie: built.append(d) or spec_of(w, d, tie))
    args = ["assess", PULSE, *WALL_ARGS, "--pga", "0.3", "--ensemble", "3", "--out", str(tmp_path / "a")]
    assert main([*args, "--diaphragm-law", "bilinear", "--diaphragm-yield", "1kN/m"]) == 0
    assert "diaphragm_yield 0.3" in capsys.readouterr().out
    factors = ens.Ensemble(3).factors()["diaphragm_yield"][:, 0]
    members = built[-3:]
    assert [d.yield_force for d in members] == pytest.approx(1e3 * factors, rel=1e-12)
    assert len(set(factors)) == 3
    assert main([*args[:-1], str(tmp_path / "b")]) == 0
    assert "diaphragm_yield" not in capsys.readouterr().out


def test_a_bouc_wen_scene_b_study_runs_on_the_exact_engine(tmp_path, capsys):
    """Bouc-Wen ran on CVODES, seconds a run, and the study said so first (two intensities, two
    K_d, no ensemble: 16 to 24 runs). The exact engine takes it now: no note."""
    args = ["assess", PULSE, *WALL_ARGS[:-4], "--kd-values", "20kN/m/m", "40kN/m/m", *WALL_ARGS[-2:],
            "--pga", "0.1", "0.2", "--ensemble", "0", "--out", str(tmp_path),
            "--diaphragm-law", "boucWen", "--diaphragm-yield", "5kN/m"]
    assert main(args) == 0
    assert "note:" not in capsys.readouterr().err

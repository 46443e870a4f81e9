"""`rockingwall assess --building FILE --code`: every storey's wall checked by the codes where it
stands in the building, beside its time history. By hand here: C8 on the assessor's two walls
(examples/two-storey-brick.toml) at their mid-heights, the ASCE 41 storeys and limits, and the
places' options refused or checked.

The building: a 350-mm, 4.0-m ground wall (W = 25.2 kN/m) carrying 3.2 kN/m and, as weight only,
the upper wall and its roof load (14.904 + 1.5 kN/m); a 230-mm, 3.6-m upper wall (18 kN/m3:
W = 14.904 kN/m) carrying 1.5 kN/m, every load at mid-thickness. The roof is at 7.6 m."""
import json
import math

import pandas as pd
import pytest

from rockingwall.cli import main

G = 9.81
SITE = ["--nz-Z", "0.4", "--nz-soil", "C", "--asce-SX1", "0.3g"]


def assess(repo, out, *args):
    return main(["assess", "elcentro", "--building", str(repo / "examples" / "two-storey-brick.toml"),
                 "--pga", "0.3", "--ensemble", "0", "--out", str(out), *args])


def c8_by_hand(b, h, W, P, h_i, h_n):
    """C8 on a wall between floors with a top load P at mid-thickness (Doherty's Delta_i), its mass
    W/(3g), the secant at 0.6 Delta_m, C(0) = 1.33 x 0.4 (soil C), demand 1.5 (Tp/2pi)^2 Cp g."""
    half, hb = W / 2, h / 2
    A = (half * b / 2 + half * 1.5 * b + P * 1.5 * b) / hb   # the weights' rise per unit hinge displacement
    B = (half / 4 + half * 0.75 + P) / hb                      # and their drop to second order
    delta_i = A / (2 * B)
    k_s = (A - 2 * B * 0.6 * delta_i) / (0.6 * delta_i)
    tp = 2 * math.pi * math.sqrt(W / (3 * G) / k_s)
    c_i = 2.0 if tp <= 0.75 else 2 * (1.75 - tp) if tp <= 1.5 else 0.5
    c_hi = min(1 + h_i / 6, 1 + 10 * h_i / h_n, 3.0)
    cp = 1.33 * 0.4 * c_hi * c_i
    demand = 1.5 * (tp / (2 * math.pi)) ** 2 * cp * G
    return dict(nzsee_delta_i_mm=delta_i * 1e3, nzsee_Tp_s=tp, nzsee_C_Hi=c_hi, nzsee_Cp_g=cp,
                nzsee_nbs=100 * 0.6 * delta_i / demand)


def test_every_storeys_wall_is_checked_where_it_stands(repo, tmp_path, capsys):
    assert assess(repo, tmp_path, "--code", "nzsee", "ntc", "asce41", *SITE) == 0
    cases = pd.read_csv(tmp_path / "cases.csv").set_index("storey")
    ground = c8_by_hand(0.35, 4.0, 25200.0, 3200.0 + 14904.0 + 1500.0, h_i=2.0, h_n=7.6)
    upper = c8_by_hand(0.23, 3.6, 14904.0, 1500.0, h_i=4.0 + 1.8, h_n=7.6)
    for storey, expected in ((1, ground), (2, upper)):
        for name, value in expected.items():
            assert cases.loc[storey, name] == pytest.approx(value, rel=1e-5), (storey, name)
    # the assessor's hand numbers for the upper wall: Delta_i 220.4 mm, Tp 1.74 s, C_Hi 1.97
    assert (round(upper["nzsee_delta_i_mm"], 1), round(upper["nzsee_Tp_s"], 2)) == (220.4, 1.74)
    assert round(upper["nzsee_C_Hi"], 2) == 1.97
    # ASCE 41 at S_X1 = 0.3 g: the first storey of a multistorey building 18, its top storey 14
    assert list(cases.asce41_limit) == [18.0, 14.0]
    assert list(cases.asce41_h_over_t) == pytest.approx([4.0 / 0.35, 3.6 / 0.23], rel=1e-5)
    assert list(cases.asce41_verdict) == ["pass", "fail"]
    # what docs/codes.md says of this case: C8 fails both walls, the upper wall collapses, and NTC
    # passes the ground wall whose mid-height goes past NTC's usable displacement
    assert [round(v) for v in cases.nzsee_nbs] == [43, 22] and list(cases.nzsee_verdict) == ["fail", "fail"]
    assert list(cases.collapsed) == [False, True]
    assert cases.loc[1, "ntc_verdict"] == "pass" and list(cases.ntc_unconservative) == [True, False]
    assert not cases.nzsee_unconservative.any() and not cases.asce41_unconservative.any()
    out = capsys.readouterr().out
    assert "codes on storey 1's wall:" in out and "codes at height 5.8 m of a 7.6-m building" in out
    assert "each wall at its mid-height in the building" in out
    codes = json.loads((tmp_path / "codes.json").read_text())
    assert [(c["storey"], c["site"][0]) for c in codes] == [(1, "codes at height 2 m of a 7.6-m building"),
                                                           (2, "codes at height 5.8 m of a 7.6-m building")]
    assert codes[1]["asce41"]["storey"] == "top_storey"


def test_a_taller_building_moves_the_floor_spectrum_not_the_walls(repo, tmp_path):
    """--building-height: h_n of C8 (here 1 + 10 h_i/h_n stays above 1 + h_i/6) and the
    Circolare's H; the walls stay at their mid-heights."""
    assert assess(repo, tmp_path, "--code", "nzsee", "ntc", *SITE, "--building-height", "9m") == 0
    codes = json.loads((tmp_path / "codes.json").read_text())
    assert [c["site"][0] for c in codes] == ["codes at height 2 m of a 9-m building",
                                             "codes at height 5.8 m of a 9-m building"]
    assert codes[1]["nzsee"]["C_Hi"] == pytest.approx(1 + 5.8 / 6)


@pytest.mark.parametrize("args, message", [
    (["--attachment-height", "3m"], "--attachment-height: with --building each storey's wall takes its own place"),
    (["--asce-storey", "top_storey"], "--asce-storey: with --building each storey's wall takes its own place"),
    (["--building-height", "5m"], "--building-height = 5 m: below the top of the building's walls (7.6 m)"),
])
def test_a_place_for_one_wall_is_refused_with_a_building(repo, tmp_path, capsys, args, message):
    assert assess(repo, tmp_path / "out", "--code", "nzsee", "asce41", *args) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err
    assert not (tmp_path / "out" / "cases.csv").exists()


def test_the_codes_take_where_the_building_file_says_the_overburden_bears(repo, tmp_path):
    """wall.e_top = 100 mm (joists on the upper wall's inner leaf): C8 governs outward, where the
    load's lever at the hinge is shortened by e_top (1.5 b - e); by hand as above."""
    text = (repo / "examples" / "two-storey-brick.toml").read_text()
    path = tmp_path / "house.toml"
    path.write_text(text.replace('overburden = "1.5 kN/m" }', 'overburden = "1.5 kN/m", e_top = "100 mm" }'))
    assert main(["assess", "elcentro", "--building", str(path), "--pga", "0.1", "--ensemble", "0",
                 "--out", str(tmp_path / "out"), "--code", "nzsee", *SITE]) == 0
    row = pd.read_csv(tmp_path / "out" / "cases.csv").set_index("storey").loc[2]
    W, P, b, hb, e = 14904.0, 1500.0, 0.23, 1.8, 0.1
    A = (W / 2 * b / 2 + W / 2 * 1.5 * b + P * (1.5 * b - e)) / hb
    B = (W / 8 + W / 2 * 0.75 + P) / hb
    assert row.nzsee_delta_i_mm == pytest.approx(A / (2 * B) * 1e3, rel=1e-5)
    assert row.nzsee_delta_i_mm < 220.4 - 8  # the centred load: 220.4 mm


def test_the_building_command_puts_the_codes_beside_its_runs(repo, capsys):
    """`rockingwall building --code`: the same checks as assess (the upper wall's C8 at 22 %NBS),
    and a line where a code passes a wall that the run takes past the code's usable displacement:
    NTC on the ground wall at El Centro 0.3 g (assess's flag above)."""
    house = str(repo / "examples" / "two-storey-brick.toml")
    args = ["building", house, "elcentro", "--pga", "0.3", "--code", "nzsee", "ntc", "asce41", *SITE]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "codes on storey 2's wall:" in out and "220.4 mm" in out and "22 %NBS, fail" in out
    assert ("UNCONSERVATIVE: El Centro 1940 at 0.3 g, storey 1: passed by NTC 2018; the run takes it past the "
            "code's usable displacement") in out
    assert main(args + ["--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [c["storey"] for c in data["codes"]] == [1, 2]
    assert data["code_unconservative"] == [{"record": "El Centro 1940 at 0.3 g", "storey": 1, "codes": ["NTC 2018"],
                                            "collapsed": False}]
    assert main(["building", house, "elcentro", "--pga", "0.3", "--json"]) == 0
    assert "codes" not in json.loads(capsys.readouterr().out)  # the contract without --code is unchanged
    assert main(["building", house, "elcentro", "--pga", "0.3", "--nz-Z", "0.3"]) == 2
    assert "--nz-Z is an input of the code checks: give --code too" in capsys.readouterr().err

"""Two storeys of the assessor's upper wall (b = 0.23 m, h = 3.6 m, W = 14.904 kN/m, psi = 0.2013,
dohertyHinge, e_r = 0.86) on diaphragms of 200 kg/m, 200 kN/m per m, 5 % and flexible in-plane
walls (3 000 kg/m, 30 MN/m per m, 5 %), under FEMA P695 ff19a, its first 80 s at PGA 0.2 g. With a
tie of 1e8 N/m per m the exact engine and CVODES agree to 1e-4 and the motion is insensitive; with
1e9 the impacts through the tie make it sensitive: a change of the record's scale in the ninth digit
moves the peaks by several %, and `rockingwall building` says so."""
import json

import numpy as np
import pytest

import bench_scenes as bench
from rockingwall import cli, scene_engine as se
from rockingwall.sweep import suites as suite

def two_storeys(tie):
    return bench.scenes(tie)["2 storeys"]


@pytest.fixture(scope="module")
def ff19a():
    """(t, ag, the record's file) of bench_scenes' record"""
    return (*bench.record(0.2), {r.name: r for r in suite.fema_farfield(suite.fema_cache())}["ff19a"].path)


def peaks_over_scalings(tie, record, ks=range(-3, 4)):
    t, ag, _ = record
    return np.array([np.r_[se.run(two_storeys(tie), t, ag * (1 + k * 1e-9), engine="exact").peak_s1] for k in ks])


def test_exact_and_cvodes_agree_with_a_stiff_tie(ff19a):
    t, ag, _ = ff19a
    exact = se.run(two_storeys(1e8), t, ag, engine="exact")
    cvode = se.run(two_storeys(1e8), t, ag, engine="cvode", rtol=1e-10)
    for key in ("peak_s1", "peak_s2", "peak_diaphragm"):
        np.testing.assert_allclose(getattr(exact, key), getattr(cvode, key), rtol=1e-4, err_msg=key)
    assert list(exact.impacts) == list(cvode.impacts)


def test_the_ninth_digit_of_the_record_moves_the_peaks_with_a_very_stiff_tie_only(ff19a):
    stiff = peaks_over_scalings(1e8, ff19a)
    very_stiff = peaks_over_scalings(1e9, ff19a)
    spread = lambda p: np.max((p.max(axis=0) - p.min(axis=0)) / p.mean(axis=0))  # noqa: E731
    assert spread(stiff) < 1e-6          # smooth: a change of 3e-9 moves the peaks by about as much
    assert spread(very_stiff) > 0.02     # sensitive: the same change moves them by several %


BUILDING = """\
[building]
name = "two storeys, tie {tie}"
tie = "{tie} N/m/m"
[[storey]]
height = "3.6 m"
wall = {{ b = "230 mm", W = "14.904 kN/m", overburden = "1.5 kN/m" }}
diaphragm = {{ stiffness = "200 kN/m/m", mass = "200 kg/m", damping = 0.05 }}
in_plane = {{ stiffness = "30 MN/m/m", mass = "3000 kg/m", damping = 0.05 }}
[[storey]]
height = "3.6 m"
wall = {{ b = "230 mm", W = "14.904 kN/m", overburden = "1.5 kN/m" }}
diaphragm = {{ stiffness = "200 kN/m/m", mass = "200 kg/m", damping = 0.05 }}
in_plane = {{ stiffness = "30 MN/m/m", mass = "3000 kg/m", damping = 0.05 }}
"""


@pytest.mark.parametrize("tie, sensitive", [("1e8", False), ("1e9", True)])
def test_building_says_when_its_peaks_are_sensitive(ff19a, tmp_path, capsys, tie, sensitive):
    house = tmp_path / "house.toml"
    house.write_text(BUILDING.format(tie=tie))
    args = ["building", str(house), str(ff19a[2]), "--pga", "0.2"]
    assert cli.main(args + ["--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    (run,) = data["runs"]
    assert run["sensitive"] is sensitive and (run["peak_sensitivity"] > 0.01) is sensitive
    assert "1e-09" in data["notes"]["peak_sensitivity"]
    assert cli.main(args) == 0
    assert ("sensitive: ff19a" in capsys.readouterr().out) is sensitive

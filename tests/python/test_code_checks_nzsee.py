"""NZSEE C8 out-of-plane checks and the NZS 1170.5 parts spectrum (rockingwall.codes.nzsee,
nzs1170): each coefficient and each check against arithmetic done by hand here."""
import math

import pytest

from rockingwall.codes import FaceLoadedWall, NzSite, Parapet, TopLoad, nzsee, nzs1170

G = 9.81
WALL = FaceLoadedWall(h=3.6, b=0.23, W=14904.0, top_loads=(TopLoad(1500.0, 0.0),))


@pytest.mark.parametrize("soil, shape", [("A", 1.0), ("B", 1.0), ("C", 1.33), ("D", 1.12), ("E", 1.12)])
def test_c0_is_the_modal_shape_at_zero_times_z_r(soil, shape):
    assert NzSite(Z=0.3, soil=soil, R=1.3).C0 == pytest.approx(shape * 0.39, rel=1e-12)


def test_z_r_is_capped_at_0_7():
    assert NzSite(Z=0.6, soil="C", R=1.5).C0 == pytest.approx(1.33 * 0.7, rel=1e-12)   # Z R = 0.9 -> 0.7


def test_floor_height_coefficient_rules():
    assert nzs1170.floor_height_coefficient(5.8, 9.0) == pytest.approx(1 + 5.8 / 6)      # 1.967 < 1 + 58/9
    assert round(nzs1170.floor_height_coefficient(5.8, 9.0), 2) == 1.97                  # the assessor's
    assert nzs1170.floor_height_coefficient(0.0, 9.0) == 1.0
    assert nzs1170.floor_height_coefficient(12.0, 30.0) == 3.0                          # h_i >= 12 m
    assert nzs1170.floor_height_coefficient(13.0, 100.0) == pytest.approx(1 + 10 * 13 / 100)  # h_i < 0.2 h_n
    assert nzs1170.floor_height_coefficient(1.0, 4.0) == pytest.approx(1 + 1 / 6)       # 1 + 10/4 is larger


def test_part_spectral_shape():
    assert nzs1170.part_spectral_shape(0.2) == 2.0
    assert nzs1170.part_spectral_shape(0.75) == 2.0
    assert nzs1170.part_spectral_shape(1.0) == pytest.approx(2 * 0.75)
    assert nzs1170.part_spectral_shape(1.5) == pytest.approx(0.5)
    assert round(nzs1170.part_spectral_shape(1.74), 1) == 0.5                            # the assessor's


def test_part_coefficient_is_capped_at_3_6():
    site = NzSite(Z=0.6, soil="C", R=1.3)                 # C(0) = 1.33 * 0.7 = 0.931
    cp, capped = nzs1170.part_coefficient(site, 12.0, 20.0, 0.3, rp=1.0)
    assert capped and cp == 3.6                            # 0.931 * 3 * 2 = 5.586 -> 3.6
    cp, capped = nzs1170.part_coefficient(site, 3.0, 20.0, 1.0, rp=1.5)
    assert not capped and cp == pytest.approx(0.931 * 1.5 * 1.5 * 1.5)   # 3.14


def test_the_assessors_wall_checked_by_hand():
    r = nzsee.check_wall(WALL, NzSite(Z=0.4, soil="C"), h_i=5.8, h_n=9.0)
    # statics: Delta_i = 0.23 * 34308 / 35808, Delta_m = 0.6 Delta_i
    delta_i = 0.23 * 34308 / 35808
    assert r.delta_i == pytest.approx(delta_i, rel=1e-12)
    assert r.capacity == pytest.approx(0.6 * delta_i, rel=1e-12)
    # period: M = 14904 / (3 * 9.81) = 506.42 kg/m; K_s = F(0.6 Di)/(0.6 Di) = (35808/3.6)(0.4/0.6) = 6631.1
    mass, k_s = 14904 / (3 * G), 35808 / 3.6 * 0.4 / 0.6
    assert r.Tp == pytest.approx(2 * math.pi * math.sqrt(mass / k_s), rel=1e-12)
    assert round(r.Tp, 2) == 1.74
    # spectrum: C(0) = 1.33 * 0.4 = 0.532; C_Hi = 1 + 5.8/6; C_i(1.74 s) = 0.5; Cp = 0.5231
    cp = 0.532 * (1 + 5.8 / 6) * 0.5
    assert (r.C0, r.C_i) == (pytest.approx(0.532), 0.5)
    assert r.Cp == pytest.approx(cp, rel=1e-12)
    # demand: gamma (Tp / 2 pi)^2 Cp g = 1.5 (M / K_s) Cp g = 0.5879 m; %NBS = 100 * 0.1322 / 0.5879 = 22
    demand = 1.5 * mass / k_s * cp * G
    assert r.demand == pytest.approx(demand, rel=1e-12)
    assert r.nbs == pytest.approx(100 * 0.6 * delta_i / demand, rel=1e-12)
    assert round(r.nbs) == 22 and r.verdict == "fail"


def test_an_eccentric_top_bearing_governs_outward():
    e = 0.115 - 0.1 / 3                     # joists bearing 100 mm into the inner face
    wall = FaceLoadedWall(h=3.6, b=0.23, W=14904.0, top_loads=(TopLoad(1500.0, e),))
    r = nzsee.check_wall(wall, NzSite(Z=0.4, soil="C"), h_i=5.8, h_n=9.0)
    # outward (free body): D_i = (1500 (0.345 - e) + 7452 (0.345 + 0.115)) / 17904; the stiffness is
    # F0 / D_i = 2B = 35808 / 3.6, unchanged by e, so only D_i moves
    delta_i = (1500 * (0.345 - e) + 7452 * 0.46) / 17904
    k_s = 35808 / 3.6 * 0.4 / 0.6
    tp = 2 * math.pi * math.sqrt(14904 / (3 * G) / k_s)
    demand = 1.5 * (tp / (2 * math.pi)) ** 2 * 0.532 * (1 + 5.8 / 6) * 0.5 * G
    assert r.direction == "outward"
    assert r.delta_i == pytest.approx(delta_i, rel=1e-12)
    assert r.nbs == pytest.approx(100 * 0.6 * delta_i / demand, rel=1e-12)
    assert any(n.startswith("inward:") for n in r.notes)


def test_a_strong_site_passes_a_weak_one():
    # Z = 0.13 on rock at the ground floor: C(0) = 0.13, C_Hi = 1 + 1.8/6 = 1.3, C_i = 0.5
    r = nzsee.check_wall(WALL, NzSite(Z=0.13, soil="A"), h_i=1.8, h_n=9.0)
    demand = 1.5 * (14904 / (3 * G)) / (35808 / 3.6 * 0.4 / 0.6) * 0.13 * 1.3 * 0.5 * G
    assert r.demand == pytest.approx(demand, rel=1e-12)
    assert r.nbs == pytest.approx(100 * 0.6 * 0.23 * 34308 / 35808 / demand, rel=1e-12)
    assert r.nbs > 100 and r.verdict == "pass"


def test_parapet_by_hand():
    parapet = Parapet(h=1.2, b=0.23, W=1.2 * 0.23 * 18000)          # W = 4968 N/m
    r = nzsee.check_parapet(parapet, NzSite(Z=0.4, soil="C"), h_i=9.0, h_n=9.0)
    # Delta_TOP,ins = b = 0.23 m; F0 = 4968 * 0.115 / 1.2 = 476.1 N/m; K_s = 0.4 F0 / 0.138 = 1380
    # M = 4968 / 29.43 = 168.81 kg/m; Tp = 2 pi sqrt(M / K_s) = 2.20 s; C_Hi = min(1 + 9/6, 3) = 2.5
    k_s = 0.4 * 4968 * 0.115 / 1.2 / (0.6 * 0.23)
    mass = 4968 / (3 * G)
    cp = 0.532 * 2.5 * 0.5
    demand = 1.5 * mass / k_s * cp * G
    assert r.delta_i == pytest.approx(0.23, rel=1e-12)
    assert r.secant_stiffness == pytest.approx(k_s, rel=1e-12)
    assert r.C_Hi == 2.5 and r.Cp == pytest.approx(cp, rel=1e-12)
    assert r.demand == pytest.approx(demand, rel=1e-12)
    assert r.nbs == pytest.approx(100 * 0.138 / demand, rel=1e-12)
    assert r.element == "parapet" and r.verdict == "fail"


def test_secant_fraction_changes_the_period_and_says_so():
    r = nzsee.check_wall(WALL, NzSite(Z=0.4, soil="C"), h_i=5.8, h_n=9.0, secant_fraction=0.36)
    k_s = 35808 / 3.6 * 0.64 / 0.36
    assert r.Tp == pytest.approx(2 * math.pi * math.sqrt(14904 / (3 * G) / k_s), rel=1e-12)
    assert any("0.36 Delta_i" in n for n in r.notes)


def test_results_name_their_unconfirmed_formulas_and_the_diaphragm_assumption():
    r = nzsee.check_wall(WALL, NzSite(Z=0.4, soil="C"), h_i=5.8, h_n=9.0)
    unconfirmed = {ref.quantity for ref in r.refs if ref.status == "unconfirmed"}
    assert {"Delta_m", "Tp", "D_ph", "%NBS"} <= unconfirmed
    assert sum(n.startswith("UNCONFIRMED") for n in r.notes) == len(unconfirmed)
    assert any("diaphragm" in n for n in r.notes)


@pytest.mark.parametrize("call, words", [
    (lambda: NzSite(Z=0.8, soil="C"), "Z = 0.8"),
    (lambda: NzSite(Z=0.4, soil="F"), "soil class"),
    (lambda: NzSite(Z=0.4, soil="C", R=0.0), "R = 0"),
    (lambda: NzSite(Z=0.4, soil="C", N=0.5), "N = 0.5"),
    (lambda: nzsee.check_wall(WALL, NzSite(0.4, "C"), h_i=10.0, h_n=9.0), "h_i = 10"),
    (lambda: nzsee.check_wall(WALL, NzSite(0.4, "C"), h_i=5.8, h_n=9.0, Rp=3.0), "Rp = 3"),
    (lambda: nzsee.check_wall(WALL, NzSite(0.4, "C"), h_i=5.8, h_n=9.0, direction="up"), "direction"),
    (lambda: nzsee.check_wall(WALL, NzSite(0.4, "C"), h_i=5.8, h_n=9.0, secant_fraction=1.0), "secant_fraction"),
    (lambda: nzsee.check_wall(WALL, (0.4, "C"), h_i=5.8, h_n=9.0), "NzSite"),
    (lambda: nzsee.check_parapet(WALL, NzSite(0.4, "C"), h_i=5.8, h_n=9.0), "Parapet"),
    (lambda: nzsee.check_wall(WALL, NzSite(0.4, "C"), h_i="5.8", h_n=9.0), "h_i: expected a number"),
])
def test_bad_inputs_are_refused_by_name(call, words):
    with pytest.raises(ValueError, match=words):
        call()

"""NTC 2018 spectra and the Circolare 2019 kinematic checks (rockingwall.codes.ntc_spectrum, ntc),
against arithmetic done by hand here."""
import math

import pytest

from rockingwall.codes import FaceLoadedWall, NtcSite, Parapet, TopLoad, ntc
from rockingwall.codes import ntc_spectrum as sp

G = 9.81
WALL = FaceLoadedWall(h=3.6, b=0.23, W=14904.0, top_loads=(TopLoad(1500.0, 0.0),))
SITE = NtcSite(ag=0.25, F0=2.4, Tc_star=0.3, soil="B")


def test_site_factors_by_hand():
    # soil B: S_S = 1.40 - 0.40 * 2.4 * 0.25 = 1.16 (inside [1.00, 1.20]); C_C = 1.10 * 0.3^-0.20
    cc = 1.10 * 0.3 ** -0.20                                   # 1.3995
    assert SITE.S == pytest.approx(1.16, rel=1e-12)
    assert SITE.T_C == pytest.approx(cc * 0.3, rel=1e-12)      # 0.4198 s
    assert SITE.T_B == pytest.approx(cc * 0.3 / 3, rel=1e-12)
    assert SITE.T_D == pytest.approx(4 * 0.25 + 1.6, rel=1e-12)
    assert SITE.eta == 1.0


def test_soil_factor_limits_and_topography():
    assert NtcSite(ag=0.05, F0=2.5, Tc_star=0.3, soil="C").S_S == 1.5      # 1.70 - 0.075 capped at 1.50
    assert NtcSite(ag=0.6, F0=2.5, Tc_star=0.3, soil="D").S_S == 0.9       # 2.40 - 2.25 raised to 0.90
    assert NtcSite(ag=0.35, F0=2.5, Tc_star=0.3, soil="E").S_S == pytest.approx(2.0 - 1.1 * 0.875)
    assert NtcSite(ag=0.25, F0=2.4, Tc_star=0.3, soil="A", topography="T4").S == 1.4
    assert NtcSite(ag=0.25, F0=2.4, Tc_star=0.4, soil="D").T_C == pytest.approx(1.25 * 0.4 ** 0.5, rel=1e-12)


def test_damping_correction():
    assert NtcSite(0.25, 2.4, 0.3, damping=10.0).eta == pytest.approx(math.sqrt(10 / 15), rel=1e-12)
    assert NtcSite(0.25, 2.4, 0.3, damping=40.0).eta == 0.55               # sqrt(10/45) = 0.47 -> 0.55


def test_elastic_spectrum_by_hand():
    plateau = 0.25 * G * 1.16 * 2.4                                        # a_g S eta F0 = 6.828 m/s^2
    t_c, t_d = SITE.T_C, 2.6
    assert sp.elastic_acceleration(SITE, 0.0) == pytest.approx(0.25 * G * 1.16, rel=1e-12)
    half_tb = 1 + (2.4 - 1) * 0.5                                          # halfway up the first branch
    assert sp.elastic_acceleration(SITE, SITE.T_B / 2) == pytest.approx(0.25 * G * 1.16 * half_tb, rel=1e-12)
    assert sp.elastic_acceleration(SITE, 0.3) == pytest.approx(plateau, rel=1e-12)
    assert sp.elastic_acceleration(SITE, 1.0) == pytest.approx(plateau * t_c / 1.0, rel=1e-12)
    assert sp.elastic_acceleration(SITE, 3.0) == pytest.approx(plateau * t_c * t_d / 9.0, rel=1e-12)
    assert sp.elastic_displacement(SITE, 1.0) == pytest.approx(plateau * t_c / (4 * math.pi ** 2), rel=1e-12)
    with pytest.raises(ValueError, match="T_E"):
        sp.elastic_displacement(SITE, 5.5)


@pytest.mark.parametrize("T1, a, b, ap", [(0.4, 0.8, 1.4, 5.0), (0.8, 0.3, 1.2, 4.0), (1.5, 0.3, 1.0, 2.5)])
def test_floor_spectrum_by_hand(T1, a, b, ap):
    top = 0.25 * 1.16 * (1 + 6.0 / 9.0) * ap * G                          # alpha S (1 + z/H) a_p g
    below, above = 0.5 * a * T1, 2.0 * b * T1
    assert sp.floor_acceleration(SITE, below, 6.0, 9.0, T1) == pytest.approx(top / (1 + (ap - 1) * 0.25), rel=1e-12)
    near = 0.95 * a * T1                                                  # just below the plateau
    assert sp.floor_acceleration(SITE, near, 6.0, 9.0, T1) == pytest.approx(top / (1 + (ap - 1) * 0.0025), rel=1e-12)
    assert sp.floor_acceleration(SITE, 0.5 * (a + b) * T1, 6.0, 9.0, T1) == pytest.approx(top, rel=1e-12)
    assert sp.floor_acceleration(SITE, above, 6.0, 9.0, T1) == pytest.approx(top / (1 + (ap - 1) * 1.0), rel=1e-12)
    # at Ta = 0 the floor spectrum is the floor's peak acceleration alpha S (1 + z/H) g
    assert sp.floor_acceleration(SITE, 0.0, 6.0, 9.0, T1) == pytest.approx(top / ap, rel=1e-12)


def test_the_assessors_wall_at_ground_level_by_hand():
    r = ntc.check_mechanism(WALL, SITE, FC=1.35)
    # alpha0: forces alpha W/2 on each half's centroid moving D/2 do the work of gravity's
    # first-order term (t/h)(Wb + 3 Wt + 3 P) = (0.23/3.6) 34308 = 2191.9 N/m: alpha0 = 2191.9 / 7452
    alpha0 = 0.23 / 3.6 * 34308 / 7452                                     # 0.2941 = (4b/h)(1 + 0.75 psi)
    # centroids move 1/2 per unit D: M* = (W/2)^2 / (g W/4) = W/g; e* = g M* / W = 1
    a0 = alpha0 * G / 1.35                                                 # 2.137 m/s^2 = 0.218 g
    d0 = 0.23 * 34308 / 35808 / 2                                          # the centroids at D = Delta_i
    du, ds = 0.4 * d0, 0.16 * d0
    ts = 2 * math.pi * math.sqrt(ds / (a0 * (1 - 0.16)))                    # 0.623 s
    assert r.alpha0 == pytest.approx(alpha0, rel=1e-12)
    assert r.M_star == pytest.approx(14904 / G, rel=1e-12) and r.e_star == pytest.approx(1.0, rel=1e-12)
    assert r.a0_star == pytest.approx(a0, rel=1e-12)
    assert (r.d0_star, r.du_star, r.ds_star) == (pytest.approx(d0), pytest.approx(du), pytest.approx(ds))
    assert r.Ts == pytest.approx(ts, rel=1e-12)
    # linear: a_g S / q = 0.25 * 9.81 * 1.16 / 2 = 1.422 m/s^2 < 2.137: passes
    assert r.linear_demand == pytest.approx(0.25 * G * 1.16 / 2, rel=1e-12) and r.linear_verdict == "pass"
    # nonlinear: Ts between T_C and T_D: S_De = 6.828 (T_C / Ts)(Ts / 2 pi)^2 = 0.0452 m > du* = 0.0441
    sde = 0.25 * G * 1.16 * 2.4 * (SITE.T_C / ts) * (ts / (2 * math.pi)) ** 2
    assert r.nonlinear_demand == pytest.approx(sde, rel=1e-12)
    assert r.nonlinear_verdict == "fail" and r.verdict == "fail"


def test_above_ground_the_floor_spectrum_governs():
    r = ntc.check_mechanism(WALL, SITE, FC=1.0, z=5.4, H=9.0, T1=0.3)
    # linear: the floor's peak alpha S (1 + z/H) g / q = 0.25 * 1.16 * 1.6 * 9.81 / 2
    assert r.linear_demand == pytest.approx(0.25 * 1.16 * 1.6 * G / 2, rel=1e-12)
    # nonlinear: T1 = 0.3 s gives (a, b, a_p) = (0.8, 1.4, 5); Ts = 0.536 s is above b T1 = 0.42 s,
    # so Sa = top / (1 + 4 (1 - Ts / 0.42)^2)
    ts = r.Ts
    top = 0.25 * 1.16 * 1.6 * 5.0 * G
    floor = top / (1 + 4 * (1 - ts / 0.42) ** 2) * (ts / (2 * math.pi)) ** 2
    ground = sp.elastic_displacement(SITE, ts)
    assert ts > 0.42 and floor > ground
    assert r.nonlinear_demand == pytest.approx(floor, rel=1e-12)


def test_fc_divides_a0_only():
    a = ntc.check_mechanism(WALL, SITE, FC=1.0)
    b = ntc.check_mechanism(WALL, SITE, FC=1.2)
    assert b.a0_star == pytest.approx(a.a0_star / 1.2, rel=1e-12)
    assert b.d0_star == a.d0_star


def test_parapet_kinematics_by_hand():
    parapet = Parapet(h=1.0, b=0.25, W=4500.0)
    r = ntc.check_mechanism(parapet, SITE, FC=1.0)
    # alpha0 = b/h = 0.25; M* = W/g; control point the top, d_k0 = b: d0* = b/2 (the centroid)
    assert r.alpha0 == pytest.approx(0.25, rel=1e-12)
    assert r.a0_star == pytest.approx(0.25 * G, rel=1e-12)
    assert r.d0_star == pytest.approx(0.125, rel=1e-12)


def test_eccentric_top_load_governs_outward():
    e = 0.115 - 0.1 / 3
    wall = FaceLoadedWall(h=3.6, b=0.23, W=14904.0, top_loads=(TopLoad(1500.0, e),))
    r = ntc.check_mechanism(wall, SITE)
    # outward the load's lever is (e_b + 2 e_m - e) = 0.345 - e: alpha0 = (2/h)(Wb e_b + Wt 3 e_m + P(0.345 - e)) / (W/2)
    alpha0 = (2 / 3.6) * (7452 * 0.115 + 7452 * 0.345 + 1500 * (0.345 - e)) / 7452
    assert r.direction == "outward" and r.alpha0 == pytest.approx(alpha0, rel=1e-12)


@pytest.mark.parametrize("call, words", [
    (lambda: NtcSite(ag=0.0, F0=2.4, Tc_star=0.3), "ag = 0"),
    (lambda: NtcSite(ag=0.25, F0=2.4, Tc_star=0.3, soil="S1"), "soil category"),
    (lambda: NtcSite(ag=0.25, F0=2.4, Tc_star=0.3, topography="T5"), "topography"),
    (lambda: ntc.check_mechanism(WALL, SITE, FC=1.5), "FC = 1.5"),
    (lambda: ntc.check_mechanism(WALL, SITE, q=0.5), "q = 0.5"),
    (lambda: ntc.check_mechanism(WALL, SITE, z=3.0), "z, H and T1 go together"),
    (lambda: ntc.check_mechanism(WALL, SITE, z=12.0, H=9.0, T1=0.3), "z = 12"),
    (lambda: ntc.check_mechanism(WALL, "B"), "NtcSite"),
    (lambda: ntc.check_mechanism((3.6, 0.23), SITE), "FaceLoadedWall or a Parapet"),
])
def test_bad_inputs_are_refused_by_name(call, words):
    with pytest.raises(ValueError, match=words):
        call()

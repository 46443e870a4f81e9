"""The rocking mechanisms behind the code checks (rockingwall.codes.mechanism): instability
displacement, restoring force, mass and load multiplier, against Doherty's closed form, the
package's own Wall.delta_u, and hand calculations by free-body moment equilibrium (not the
module's energy method)."""
import math

import pytest

import rockingwall as rw
from rockingwall.codes import FaceLoadedWall, Parapet, TopLoad

G = 9.81


def doherty(b, psi):
    return b * (1 + 0.75 * psi) / (1 + psi)


@pytest.mark.parametrize("b, h, W, psi", [
    (0.15, 2.5, 6622.0, 0.0), (0.15, 2.5, 6622.0, 0.2), (0.23, 3.6, 14904.0, 2 * 1500 / 14904),
    (0.11, 3.0, 5900.0, 1.0), (0.35, 4.2, 27000.0, 4.0), (0.47, 6.0, 52000.0, 0.05),
])
def test_delta_i_is_doherty_for_a_centred_top_load(b, h, W, psi):
    P = psi * W / 2  # psi is the top load over the weight of one half
    wall = FaceLoadedWall(h=h, b=b, W=W, top_loads=(TopLoad(P, 0.0),))
    for direction in ("outward", "inward"):
        assert wall.mechanism(direction).delta_i == pytest.approx(doherty(b, psi), rel=1e-9, abs=0)


def test_delta_i_equals_the_packages_own_delta_u():
    for psi in (0.0, 0.3, 1.7):
        model = rw.Wall.make(b=0.23, h=3.2, W=14080.0, psi=psi, warn=False)
        wall = FaceLoadedWall(h=3.2, b=0.23, W=14080.0, top_loads=(TopLoad(psi * 14080.0 / 2),))
        assert wall.mechanism("outward").delta_i == pytest.approx(model.delta_u, rel=1e-9)


def test_the_assessors_wall_to_the_printed_digits():
    # b = 230 mm, h = 3.6 m, W = 14.904 kN/m in two halves, P = 1.5 kN/m at mid-thickness
    wall = FaceLoadedWall(h=3.6, b=0.23, W=14904.0, top_loads=(TopLoad(1500.0, 0.0),))
    mech = wall.mechanism("outward")
    # by hand: Wb + 3 Wt + 3 P = 7452 + 22356 + 4500 = 34308; Wb + 3 Wt + 4 P = 35808
    assert round(mech.delta_i * 1e3, 1) == 220.4                       # 0.23 * 34308 / 35808
    assert round(mech.mass / 1e3, 3) == 0.506                          # 14904 / (3 * 9.81) kg/m
    k_i = mech.A / mech.delta_i                                        # F0 / Delta_i = 35808 / 3.6
    assert round(k_i / 1e3, 2) == 9.95
    k_s = mech.secant_stiffness(0.6 * mech.delta_i)                    # (2/3) of k_i
    assert round(k_s / 1e3, 2) == 6.63
    assert round(2 * math.pi * math.sqrt(mech.mass / k_s), 2) == 1.74  # Tp


def free_body_delta_i(W_b, W_t, h_b, h_t, e_b, e_m, loads):
    """Delta_i by moment equilibrium of the two blocks with no lateral load, written out:
    upper block about the hinge gives the top reaction H_t; lower block about its base pivot
    then balances when
      (P + W_t)(D - e_m - e_b) - (h_b/h_t)[sum P_k (e_k + e_m - D) + W_t (e_m - D/2)] + W_b (D/2 - e_b) = 0,
    linear in D (e_k: a top load's eccentricity toward the motion)."""
    P = sum(f for f, _ in loads)
    r = h_b / h_t
    slope = (P + W_t) + r * (P + W_t / 2) + W_b / 2
    constant = (P + W_t) * (e_m + e_b) + r * (sum(f * (e + e_m) for f, e in loads) + W_t * e_m) + W_b * e_b
    return constant / slope


def test_an_eccentric_top_bearing_by_hand():
    # joists bearing 100 mm into the inner face: the load at b/2 - 0.1/3 = 0.08167 m toward the inside
    e = 0.115 - 0.1 / 3
    wall = FaceLoadedWall(h=3.6, b=0.23, W=14904.0, top_loads=(TopLoad(1500.0, e),))
    # outward the load sits against the motion (e_rel = -e):
    # numerator   1500 (0.115 + 0.23 - 0.08167) + 7452 (0.115 + 0.23) + 7452 (0.115) = 3822.87
    # denominator 2 (1500) + 1.5 (7452) + 0.5 (7452)                                  = 17904
    outward = (1500 * (0.345 - e) + 7452 * 0.345 + 7452 * 0.115) / 17904
    inward = (1500 * (0.345 + e) + 7452 * 0.345 + 7452 * 0.115) / 17904
    assert round(outward, 4) == 0.2135 and round(inward, 4) == 0.2272
    assert wall.mechanism("outward").delta_i == pytest.approx(outward, rel=1e-12)
    assert wall.mechanism("inward").delta_i == pytest.approx(inward, rel=1e-12)


@pytest.mark.parametrize("hinge_height, e_base, e_hinge, loads", [
    (2.0, None, None, ((1500.0, 0.05), (4000.0, -0.03))),
    (1.2, 0.08, 0.1, ((800.0, 0.0),)),
    (2.7, 0.115, 0.06, ()),
])
def test_general_walls_agree_with_the_free_body(hinge_height, e_base, e_hinge, loads):
    h, b, W = 3.6, 0.25, 16000.0
    wall = FaceLoadedWall(h=h, b=b, W=W, top_loads=tuple(TopLoad(f, e) for f, e in loads),
                          e_base=e_base, e_hinge=e_hinge, hinge_height=hinge_height)
    e_b = b / 2 if e_base is None else e_base
    e_m = b / 2 if e_hinge is None else e_hinge
    h_b, h_t = hinge_height, h - hinge_height
    for direction, sign in (("inward", 1), ("outward", -1)):
        expected = free_body_delta_i(W * h_b / h, W * h_t / h, h_b, h_t, e_b, e_m, [(f, sign * e) for f, e in loads])
        assert wall.mechanism(direction).delta_i == pytest.approx(expected, rel=1e-12)


def test_restoring_force_is_linear_and_vanishes_at_delta_i():
    mech = FaceLoadedWall(h=3.0, b=0.2, W=11000.0, top_loads=(TopLoad(3000.0, 0.04),)).mechanism("outward")
    assert mech.force(mech.delta_i) == pytest.approx(0.0, abs=1e-9 * mech.A)
    assert mech.force(0.5 * mech.delta_i) == pytest.approx(0.5 * mech.A, rel=1e-12)


def test_alpha0_is_the_uplift_acceleration_of_the_simply_supported_wall():
    # the model's rigid law lifts off at |ag| = (4 b / h)(1 + 0.75 psi) g (docs/model.md)
    for psi in (0.0, 0.2, 1.5):
        wall = FaceLoadedWall(h=2.5, b=0.15, W=6622.0, top_loads=(TopLoad(psi * 6622.0 / 2),))
        assert wall.mechanism("outward").alpha0 == pytest.approx(4 * 0.15 / 2.5 * (1 + 0.75 * psi), rel=1e-12)


def test_pointing_reduces_the_thickness_on_both_faces():
    plain = FaceLoadedWall(h=3.6, b=0.21, W=14904.0)
    pointed = FaceLoadedWall(h=3.6, b=0.23, W=14904.0, pointing=0.01)
    assert pointed.t == pytest.approx(0.21)
    assert pointed.mechanism("outward").delta_i == pytest.approx(plain.mechanism("outward").delta_i, rel=1e-12)


def test_parapet_by_hand():
    # a block rocking on its toe: the centroid passes over the pivot when theta = b/h, the top then
    # displaced h * (b/h) = b; at rest the overturning moment needs W (b/2) / h at the top
    parapet = Parapet(h=1.2, b=0.23, W=4968.0)
    mech = parapet.mechanism("outward")
    assert mech.delta_i == pytest.approx(0.23, rel=1e-12)
    assert mech.A == pytest.approx(4968.0 * 0.115 / 1.2, rel=1e-12)
    assert mech.alpha0 == pytest.approx(0.23 / 1.2, rel=1e-12)          # b/h, the block's classic multiplier
    assert mech.mass == pytest.approx(4968.0 / (3 * G), rel=1e-12)
    assert mech.participation == pytest.approx(1.5, rel=1e-12)


@pytest.mark.parametrize("kwargs, words", [
    (dict(h=3.6, b=0.23, W=14904.0, pointing=0.2), "pointing depth"),
    (dict(h=3.6, b=0.23, W=-1.0), "W = -1"),
    (dict(h=3.6, b=0.23, W=14904.0, e_base=0.2), "e_base"),
    (dict(h=3.6, b=0.23, W=14904.0, hinge_height=3.5), "hinge_height"),
    (dict(h=3.6, b=0.23, W=14904.0, top_loads=(TopLoad(100.0, 0.2),)), "eccentricity"),
    (dict(h=3.6, b=0.23, W=14904.0, top_loads=(1500.0,)), "top_loads"),
    (dict(h=0.2, b=0.23, W=14904.0), "h = 0.2"),
])
def test_bad_walls_are_refused_by_name(kwargs, words):
    with pytest.raises(ValueError, match=words):
        FaceLoadedWall(**kwargs)


def test_a_wall_the_top_load_turns_over_is_refused():
    # reactions near the centreline and a heavy load on the inner face: outward, gravity's first-order
    # work per unit D is P (e_b + 2 e_m - e) + ... < 0 at rest
    wall = FaceLoadedWall(h=3.0, b=0.23, W=1000.0, top_loads=(TopLoad(50000.0, 0.115),), e_base=0.01, e_hinge=0.01)
    with pytest.raises(ValueError, match="cannot stand moving outward"):
        wall.mechanism("outward")
    assert wall.mechanism("inward").delta_i > 0

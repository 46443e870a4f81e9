"""NZSEE C8's statics in the wall model (docs/model.md "The reactions and the effective thickness"):
the instability displacement of the model against C8's two-block mechanism
(rockingwall.codes.mechanism, written independently by virtual work), in both directions, and a
worked example computed by hand, step by step, here."""
import numpy as np
import pytest

from rockingwall import Wall, engine
from rockingwall.codes.mechanism import FaceLoadedWall, TopLoad
from rwref import Params

# walls by the FMU's names: the paper's walls, and with pointing, reactions set in from the faces,
# an eccentric top load (toward either face) and a weight-only overburden
WALLS = {
    "paper wall 1": dict(h=2.5, b=0.15, W=6622.0, psi=0.0),
    "paper wall 3": dict(h=2.5, b=0.15, W=6622.0, psi=1.0),
    "pointing": dict(h=2.5, b=0.15, W=6622.0, psi=0.5, pointing=0.01),
    "reactions set in": dict(h=3.0, b=0.23, W=12000.0, psi=0.3, eBaseRatio=0.8, eHingeRatio=0.6),
    "joists on the inner face": dict(h=3.6, b=0.23, W=14904.0, psi=0.2013, eTop=0.07),
    "joists on the outer face": dict(h=3.6, b=0.23, W=14904.0, psi=0.8, eTop=-0.05, pointing=0.012),
    "walls above": dict(h=3.0, b=0.35, W=25200.0, psi=0.25, psiWeightOnly=2.4),
    "all of them": dict(h=2.8, b=0.3, W=16000.0, psi=1.5, pointing=0.02, eBaseRatio=0.9, eHingeRatio=0.75,
                        eTop=0.06, psiWeightOnly=0.8),
}
DIRECTIONS = {1: "inward", -1: "outward"}   # +x is the inner face
REF_NAMES = {"eBaseRatio": "e_base_ratio", "eHingeRatio": "e_hinge_ratio", "eTop": "e_top",
             "psiWeightOnly": "psi_weight_only"}


def c8_wall(w):
    """C8's mechanism of the wall: the overburden Wd = psi W/2 at eTop, the weight-only overburden
    on the centreline, the reactions at ratio * t/2 of the effective thickness t."""
    t = w["b"] - 2 * w.get("pointing", 0.0)
    loads = (TopLoad(w["psi"] * w["W"] / 2, w.get("eTop", 0.0)), TopLoad(w.get("psiWeightOnly", 0.0) * w["W"] / 2))
    return FaceLoadedWall(h=w["h"], b=w["b"], W=w["W"], top_loads=loads, pointing=w.get("pointing", 0.0),
                          e_base=w.get("eBaseRatio", 1.0) * t / 2, e_hinge=w.get("eHingeRatio", 1.0) * t / 2)


@pytest.mark.parametrize("direction", sorted(DIRECTIONS))
@pytest.mark.parametrize("name", sorted(WALLS))
def test_delta_u_of_the_model_is_c8s_delta_i(name, direction):
    w = WALLS[name]
    delta_i = c8_wall(w).mechanism(DIRECTIONS[direction]).delta_i
    assert engine.statics(**w)["Delta_u"][direction] == pytest.approx(delta_i, rel=1e-9)
    ref = Params(**{REF_NAMES.get(k, k): v for k, v in w.items()})
    assert ref.direction(direction).Delta_u == pytest.approx(delta_i, rel=1e-9)


# the model's own loss of restoring force: at rest a hair inside Delta_u the wall stands, a hair
# outside it collapses at once; the 1DOF (to 1e-9) and the 2DOF with its top pinned by a stiff
# spring (1e12 N/m per m; to 1e-7, as the spring gives a little)
SUPPORTS = {"1DOF trilinear": (2, 4, 0.0, 1e-9), "1DOF rigid": (2, 1, 0.0, 1e-9),
            "2DOF pinned dohertyHinge": (3, 4, 1e12, 1e-7), "2DOF pinned rigid": (3, 1, 1e12, 1e-7),
            "2DOF pinned semiRigidHinge": (3, 3, 1e12, 1e-7)}


@pytest.mark.parametrize("support", sorted(SUPPORTS))
@pytest.mark.parametrize("direction", sorted(DIRECTIONS))
@pytest.mark.parametrize("name", ["paper wall 3", "joists on the inner face", "joists on the outer face",
                                  "all of them"])
def test_the_model_loses_its_restoring_force_at_c8s_delta_i(name, direction, support):
    w = WALLS[name]
    code, law, kd, margin = SUPPORTS[support]
    delta_i = c8_wall(w).mechanism(DIRECTIONS[direction]).delta_i
    t, ag = np.array([0.0, 1.0]), np.zeros(2)
    for factor, collapses in ((1 - margin, False), (1 + margin, True)):
        q1 = 2 * direction * delta_i * factor / w["h"]
        r = engine.run(t, ag, t_end=0.3, x0=[q1, -q1, 0.0, 0.0], support=code, hingeLaw=law, Kd=kd, **w)
        assert r.collapsed == collapses, (factor, r)


def test_worked_example_joists_on_the_inner_face():
    """A wall with pointing, its hinge's reaction set in, joists bearing 60 mm toward the inner face
    and the walls of the storeys above on it, by hand:
    b = 230 mm, pointing 15 mm: t = 0.23 - 2(0.015) = 0.200 m; e_b = 1.0 t/2 = 0.100 m,
    e_m = 0.9 t/2 = 0.090 m; h = 3.5 m, W = 14 kN/m: W1 = 7000 N/m;
    the floor Wd = 2800 N/m (psi = 2800/7000 = 0.4) at e_t = +0.060 m: E = Wd e_t = 168 N m/m;
    the walls above Wo = 3500 N/m (psiWeightOnly = 0.5); Wt = Wd + Wo = 6300 N/m."""
    wall = dict(h=3.5, b=0.23, W=14000.0, psi=0.4, pointing=0.015, eBaseRatio=1.0, eHingeRatio=0.9, eTop=0.06,
                psiWeightOnly=0.5)
    # base: the moments about its pivot on side +1 (the inner face) of 2 W1 + Wo at the centreline,
    # 0.100 m away, and of Wd, 0.100 - 0.060 = 0.040 m away; on side -1 Wd is 0.160 m away
    cap_b = {1: 17500 * 0.100 + 2800 * 0.040, -1: 17500 * 0.100 + 2800 * 0.160}      # 1862, 2198
    # mid-height: W1 + Wo at 0.090 m, Wd at 0.090 - 0.060 = 0.030 m (side +1), 0.150 m (side -1)
    cap_m = {1: 10500 * 0.090 + 2800 * 0.030, -1: 10500 * 0.090 + 2800 * 0.150}      # 1029, 1365
    assert (cap_b[1], cap_b[-1], cap_m[1], cap_m[-1]) == pytest.approx((1862, 2198, 1029, 1365), rel=1e-12)
    # moving inward (+1) the base turns to +1, the mid-height hinge to -1:
    #   F_r(+1) = (2/h)(cap_b(+1) + 2 cap_m(-1)) = (2/3.5)(1862 + 2730) = (2/3.5)(4592) = 2624 N/m;
    # outward: F_r(-1) = (2/3.5)(2198 + 2(1029)) = (2/3.5)(4256) = 2432 N/m;
    # the gravity stiffness 4 (W1 + Wt)/h = 4 (13300)/3.5 = 15200 N/m per m, the same both ways:
    #   Delta_i inward = 2624/15200 = 0.172631... m, outward = 2432/15200 = 0.160 m
    F_r = {1: 2 / 3.5 * 4592, -1: 2 / 3.5 * 4256}
    delta_i = {1: 2624 / 15200, -1: 2432 / 15200}
    assert F_r[1] == pytest.approx(2624, rel=1e-12) and F_r[-1] == pytest.approx(2432, rel=1e-12)
    assert delta_i[-1] == pytest.approx(0.16, rel=1e-12)
    # C8's virtual work, h_b = h_t = 1.75 m, inward (the floor's load toward the motion, +0.060):
    #   A = [7000(0.1) + 7000(0.19 + 0.09) + 2800(0.19 + 0.06 + 0.09) + 3500(0.19 + 0.09)]/1.75
    #     = (700 + 1960 + 952 + 980)/1.75 = 2624 N/m
    #   B = 7000/7 + 7000(1/3.5 + 1/7) + 6300(2/3.5) = 1000 + 3000 + 3600 = 7600 N/m per m
    assert (700 + 1960 + 952 + 980) / 1.75 / (2 * 7600) == pytest.approx(delta_i[1], rel=1e-12)

    got = engine.statics(**wall)
    for s in (1, -1):
        assert got["cap_b"][s] == pytest.approx(cap_b[s], rel=1e-12)
        assert got["cap_m"][s] == pytest.approx(cap_m[s], rel=1e-12)
        assert got["F_r"][s] == pytest.approx(F_r[s], rel=1e-12)
        assert got["Delta_u"][s] == pytest.approx(delta_i[s], rel=1e-12)
        assert c8_wall(wall).mechanism(DIRECTIONS[s]).delta_i == pytest.approx(delta_i[s], rel=1e-12)
        ref = Params(**{REF_NAMES.get(k, k): v for k, v in wall.items()})
        assert ref.cap_b_side(s) == pytest.approx(cap_b[s], rel=1e-12)
        assert ref.direction(s).Delta_u == pytest.approx(delta_i[s], rel=1e-12)
    # the constants of the conditions (docs/model.md): Cb = 20300 (0.1) = 2030, Cm = 13300 (0.09) = 1197,
    # the eccentric load adds Wd e_t = 168 to every B and nothing to A
    ref = Params(hinge_law="rigid", **{REF_NAMES.get(k, k): v for k, v in wall.items()})
    want = {1: (-(2030 + 1197), 1197 + 168), 2: (2030 + 1197, -1197 + 168), 3: (-2030 + 1197, -1197 + 168),
            4: (2030 - 1197, 1197 + 168)}
    for c, (A, B) in want.items():
        assert ref.conditions()[c] == pytest.approx((A, B), rel=1e-12), c
    # the package's Wall reports the smaller, outward, as its Delta_u
    assert Wall.make(**wall).delta_u == pytest.approx(0.16, rel=1e-12)


@pytest.mark.parametrize("values, needle", [
    (dict(pointing=0.08), "pointing"),
    (dict(psi=1.0, eTop=0.08), "eTop"),
    (dict(psi=3.0, eTop=0.07, eHingeRatio=0.3), "cannot stand"),
])
def test_walls_that_cannot_be_are_refused_with_the_parameters_named(values, needle):
    with pytest.raises(ValueError, match=needle):
        Wall.make("paper1", **values)

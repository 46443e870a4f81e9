"""Bilinear diaphragms on the exact scene engine (fmu_src/scene/rw_scene_exact_bilinear.c): each
branch of the law is linear, its ends are events. Checked against a hand-computed free vibration
(an elastoplastic diaphragm thrown through its elastic range into yield), the linear law it reduces
to where it cannot yield, CVODES on the law's rate form (the same physics, the kinks stepped over
by error control) converging to it, and the energy balance."""
import dataclasses

import numpy as np
import pytest

from rockingwall import read_record, scene_engine as se

WALL = dict(b=0.23, h=3.6, W=14904.0, psi=0.2013, hingeLaw=4, er=0.86, support=3)


def house(tie=1e8, fy=0.02, alpha=0.1, law="bilinear"):
    """the assessor's two storeys (timber floors, rigid in-plane walls), the diaphragms bilinear
    with a yield force of fy x k_d x 1 m"""
    storeys = tuple(se.StoreySpec(wall=dict(WALL, Kd=tie), md=md, kd=kd, cd=2 * 0.05 * np.sqrt(kd * md),
                                  Fyd=fy * kd, alphad=alpha) for md, kd in ((600.0, 6e4), (200.0, 2e4)))
    return se.Spec(storeys=storeys, rigid_in_plane=True, diaphragm_law=law)


def test_a_thrown_elastoplastic_diaphragm_yields_as_computed_by_hand():
    """A diaphragm alone (no wall), elastoplastic (alpha = 0), no damping, at its yield deformation
    Dy with z = 1 and thrown back at v0: its force falls from Fy to -Fy over 2 Dy (the spring gives
    back the work it took, so the speed is v0 again at -Dy), then it yields at -Fy until the
    kinetic energy is spent, s = m v0^2 / (2 Fy) further, and vibrates elastically about where it
    stopped. Peak deformation Dy + s; the energy (the spring's work counted) is kept."""
    m, k, fy, v0 = 300.0, 5e4, 500.0, 0.8
    dy = fy / k
    spec = se.Spec(storeys=(se.StoreySpec(md=m, kd=k, Fyd=fy, alphad=0.0),), diaphragm_law="bilinear")
    x0 = np.zeros(se.state_size(spec))
    x0[4 + 3], x0[4 + 4], x0[4 + 5] = dy, -v0, 1.0  # the floor's block: u, v, z, y, w, z_d, works
    r = se.run(spec, [0.0, 5.0], [0.0, 0.0], engine="exact", x0=x0)
    s = m * v0 ** 2 / (2 * fy)
    assert r.engine == "exact" and r.events >= 2  # the yield and the unloading
    assert r.peak_diaphragm[0] == pytest.approx(dy + s, rel=1e-12)
    assert abs(r.energy_end - r.energy_start) <= 1e-12 * r.energy_start


def test_a_bilinear_diaphragm_that_cannot_yield_is_the_linear_one():
    t = np.arange(0.0, 20.0, 0.005)
    rec = read_record("elcentro").to_pga(0.3)
    ag = np.interp(t, rec.t, rec.ag)
    linear = se.run(house(law="linear"), t, ag, engine="exact")
    for fy, alpha in ((1e3, 0.1), (0.02, 1.0)):  # a yield force never reached; no hysteresis
        bilinear = se.run(house(fy=fy, alpha=alpha), t, ag, engine="exact")
        for name in ("peak_s1", "peak_s2", "peak_diaphragm", "peak_base_acc"):
            np.testing.assert_allclose(getattr(bilinear, name), getattr(linear, name), rtol=1e-10, err_msg=name)
        # the spring's energy is the work done on it: the same as the linear one's, the balance closed
        # (alpha = 1 left that work unkept: 24 % of the input work as residual)
        assert bilinear.energy_end == pytest.approx(linear.energy_end, rel=1e-9)
        assert bilinear.max_residual <= 1e-9 * bilinear.max_work


@pytest.fixture(scope="module")
def house_under_el_centro():
    rec = read_record("elcentro").to_pga(0.2)
    keep = rec.t <= 15.0
    t, ag = rec.t[keep], rec.ag[keep]
    spec = house()
    return spec, t, ag, se.run(spec, t, ag)


def test_the_exact_engine_runs_bilinear_diaphragms_by_default(house_under_el_centro):
    spec, _, _, r = house_under_el_centro
    assert se.exact_covers(spec) == (True, "") and r.engine == "exact"
    dy = [s.Fyd / s.kd for s in spec.storeys]
    assert (r.peak_diaphragm > 2 * np.array(dy)).all()  # both diaphragms yield well past Dy


def test_bilinear_diaphragms_agree_with_cvodes(house_under_el_centro):
    """CVODES on the rate form converges to the exact engine (the upper wall's s1 at rtol 1e-10,
    1e-11, 1e-12, 1e-13: 3e-3, 3e-4, 3e-6, 5e-7 from it): within 2e-5 at rtol 1e-12, about what a
    change of the record's scale by 1e-9 moves the motion's peaks by (1e-5)."""
    spec, t, ag, exact = house_under_el_centro
    cvode = se.run(spec, t, ag, engine="cvode", rtol=1e-12)
    assert not exact.collapsed.any() and not cvode.collapsed.any()
    for name in ("peak_s1", "peak_s2", "peak_diaphragm"):
        np.testing.assert_allclose(getattr(exact, name), getattr(cvode, name), rtol=2e-5, err_msg=name)
    np.testing.assert_array_equal(exact.impacts, cvode.impacts)


def test_the_energy_balance_closes_with_yielding_diaphragms(house_under_el_centro):
    _, _, _, r = house_under_el_centro
    assert r.work_damping > 0.05 * r.max_work
    assert r.max_residual <= 1e-9 * r.max_work

"""CVODES on scenes (rw_scene_run.c): Adams with fixed-point iteration, Newton from where a scene
proves stiff, and peaks found inside its steps. Checked against a closed form, against BDF with
Newton throughout (the former method) and against the exact engine."""
import dataclasses

import numpy as np
import pytest

from rockingwall import records, scene_engine as se
from rockingwall.sweep import suites as suite

WALL = dict(b=0.23, h=3.6, W=14904.0, psi=0.2013, hingeLaw=4, er=0.86, support=3)


def storey(tie, zeta=0.05):
    md, kd, m, k = 200.0, 2e5, 3000.0, 3e7
    return se.StoreySpec(wall=dict(WALL, Kd=tie), md=md, kd=kd, cd=2 * zeta * np.sqrt(kd * md),
                         m=m, k=k, cs=2 * 0.05 * np.sqrt(k * m), Fyd=0.02 * kd, alphad=0.1)


def hysteretic(tie, zeta=0.05):
    """two storeys, Bouc-Wen diaphragms, flexible in-plane walls (scripts/bench_scenes.py's scene)"""
    return se.Spec(storeys=(storey(tie, zeta), storey(tie, zeta)), rigid_in_plane=False, diaphragm_law="boucWen")


@pytest.fixture(scope="module")
def chichi():
    """ff19a at 0.2 g, its first 40 s (the strong motion is from 20 s on)"""
    by_name = {r.name: r for r in suite.fema_farfield(suite.fema_cache())}
    rec = records.read_at2(by_name["ff19a"].path).to_pga(0.2)
    keep = rec.t <= 40.0
    return rec.t[keep], rec.ag[keep]


def test_the_peak_inside_a_step_is_the_closed_form_peak():
    """A diaphragm alone (no wall, rigid in-plane walls) set moving at v0 from rest position: its
    deformation peaks at v0/wd exp(-zeta w t*) sin(wd t*), tan(wd t*) = wd/(zeta w). Adams's steps at
    rtol 1e-8 are long against this oscillation: their ends alone miss the peak by about 1e-3, the
    cubic through them by about 2e-7."""
    md, kd, zeta, v0 = 200.0, 2e5, 0.05, 0.3
    spec = se.Spec(storeys=(se.StoreySpec(wall=None, md=md, kd=kd, cd=2 * zeta * np.sqrt(kd * md)),))
    w = np.sqrt(kd / md)
    wd = w * np.sqrt(1.0 - zeta ** 2)
    t_star = np.arctan(wd / (zeta * w)) / wd
    expected = v0 / wd * np.exp(-zeta * w * t_star) * np.sin(wd * t_star)
    x0 = np.zeros(se.state_size(spec))
    x0[4 + 4] = v0  # the diaphragm's velocity (the floor's states: u, v, z, y, w, ...)
    for bdf in (False, True):
        r = se.run(spec, [0.0, 0.05], [0.0, 0.0], engine="cvode", rtol=1e-8, x0=x0, bdf=bdf)
        assert r.peak_diaphragm[0] == pytest.approx(expected, rel=1e-6)
    exact = se.run(spec, [0.0, 0.05], [0.0, 0.0], engine="exact", x0=x0)
    assert exact.peak_diaphragm[0] == pytest.approx(expected, rel=1e-9)


def test_adams_agrees_with_bdf_in_fewer_steps(chichi):
    """The hysteretic two-storey scene: Adams (fixed-point iteration held throughout) and BDF agree
    on every peak within 1e-5 at rtol 1e-10; Adams takes fewer steps (the reason it is the method)."""
    t, ag = chichi
    adams = se.run(hysteretic(1e6), t, ag, engine="cvode", rtol=1e-10)
    bdf = se.run(hysteretic(1e6), t, ag, engine="cvode", rtol=1e-10, bdf=True)
    assert np.isnan(adams.t_newton) and bdf.t_newton == t[0]
    for name in ("peak_s1", "peak_s2", "peak_diaphragm", "peak_base_acc"):
        np.testing.assert_allclose(getattr(adams, name), getattr(bdf, name), rtol=1e-5, err_msg=name)
    assert not adams.collapsed.any() and adams.peak_s1.min() > 1e-3
    assert adams.steps < 0.8 * bdf.steps
    assert adams.max_residual < 1e-6 * adams.max_work


def test_a_stiff_scene_goes_on_with_newton(chichi):
    """A very stiff dashpot (the diaphragm's damping 300 times critical: a mode decaying at 2e4 1/s)
    defeats fixed-point iteration: the run goes on with Newton early and agrees with BDF."""
    t, ag = chichi
    adams = se.run(hysteretic(1e6, zeta=300.0), t, ag, engine="cvode", rtol=1e-10)
    bdf = se.run(hysteretic(1e6, zeta=300.0), t, ag, engine="cvode", rtol=1e-10, bdf=True)
    assert 0.0 < adams.t_newton < 1.0
    for name in ("peak_s1", "peak_s2", "peak_diaphragm"):
        np.testing.assert_allclose(getattr(adams, name), getattr(bdf, name), rtol=1e-5, err_msg=name)


def test_a_loose_tolerance_on_a_stiff_tie_goes_on_with_newton(chichi):
    """At rtol 1e-6 the stiff tie's mode (112 Hz) is fast against the steps: fixed-point iteration
    stops converging and Newton takes over; the run ends with its energy balance closed."""
    t, ag = chichi
    loose = se.run(hysteretic(1e8), t, ag, engine="cvode", rtol=1e-6)
    tight = se.run(hysteretic(1e8), t, ag, engine="cvode", rtol=1e-8)
    assert t[0] < loose.t_newton < t[-1] and np.isnan(tight.t_newton)
    assert loose.max_residual < 1e-3 * loose.max_work

"""Rigid rest / closed-hinge states (no Zeno) and input readers."""
import numpy as np
import pytest

from rwref import Params, simulate, inputs


@pytest.mark.parametrize("model", ["parapet", "simplySupported", "flexibleTop"])
def test_rigid_free_rocking_ends_at_rest(model):
    p = Params(support=model, hinge_law="rigid", er=0.5, Kd=0.0)
    th = 0.02
    q0 = {"parapet": (th, th), "simplySupported": (th, -th), "flexibleTop": (th, -th)}[model]
    r = simulate(p, None, 5.0, q0=q0)
    kinds = [k for _, k in r.events]
    assert "close" in kinds and not r.collapsed
    assert r.impacts < 60
    assert r.q1[-1] == 0 and r.dq1[-1] == 0 and r.t[-1] == 5.0


@pytest.mark.parametrize("model", ["parapet", "simplySupported"])
def test_er0_stops_at_first_impact(model):
    p = Params(support=model, hinge_law="rigid", er=0.0)
    r = simulate(p, None, 5.0, q0=(0.02, 0.02 if model == "parapet" else -0.02))
    assert r.impacts == 1
    assert [k for _, k in r.events] == ["base_impact", "close"]
    assert r.q1[-1] == 0 and r.dq1[-1] == 0


def test_signal_interpolation_holds_ends():
    s = inputs.Signal([0.0, 1.0, 2.0], [0.0, 2.0, 4.0])
    assert s(0.5) == 1.0 and s(-1.0) == 0.0 and s(5.0) == 4.0


def test_gaussian_is_second_derivative_of_displacement():
    gp = inputs.gaussian(0.04, 1.0)
    assert gp.sigma == 1.0 / 8 and gp.t0 == 0.5
    t, h = 0.37, 1e-4
    num = (gp.displacement(t + h) - 2 * gp.displacement(t) + gp.displacement(t - h)) / h**2
    assert gp(t) == pytest.approx(num, rel=1e-5)


def test_el_centro():
    s = inputs.el_centro(0.5)
    assert s.dt == pytest.approx(0.02)
    assert np.max(np.abs(s.a)) == pytest.approx(0.5 * 0.3128806 * 9.81, rel=1e-4)

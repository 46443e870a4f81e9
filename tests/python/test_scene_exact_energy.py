"""The exact scene engine's energy and its limits. Energy: without damping (e_r = 1, no dashpots,
no Rayleigh damping) a pushed scene vibrating freely for 100 s keeps its energy; with damping
under a record the balance E(t) - E(0) = W_ground - W_damping - losses closes to rounding. Limits
(the wall under a diaphragm with mass, docs/your-building.md): a diaphragm of vanishing mass on rigid in-plane walls is a massless spring,
so the scene is the paper's wall with K_d = the tie and the diaphragm in series; a diaphragm of
vanishing flexibility pins the tie, so the scene is the paper's wall with K_d = the tie. The paper's
wall runs on the single wall's exact engine (rockingwall.engine), an independent code path."""
import numpy as np
import pytest

from rockingwall import engine, records, scene_engine as se
from rockingwall.sweep import suites as suite

WALL = dict(b=0.23, h=3.6, W=14904.0, psi=0.2013, hingeLaw=4, er=0.86, support=3)


def pushed(spec):
    """A start state: the ground storey's wall turned and moving, the rest at rest."""
    x0 = np.zeros(se.state_size(spec))
    x0[:4] = (0.012, -0.004, 0.0, 0.05)
    return x0


def gaussian_pulse(D, T, t_end, dt=0.002):
    s = T / 8.0
    t = np.arange(0.0, t_end + 0.5 * dt, dt)
    u = t - 4.0 * s
    return t, D * (u ** 2 / s ** 4 - 1.0 / s ** 2) * np.exp(-u ** 2 / (2.0 * s ** 2))


@pytest.mark.parametrize("storeys, rigid, law", [(1, True, 4), (2, False, 3), (2, True, 4)])
def test_energy_is_kept_without_damping(storeys, rigid, law):
    wall = dict(WALL, er=1.0, Kd=1e6, hingeLaw=law)
    spec = se.Spec(storeys=tuple(se.StoreySpec(wall=wall, md=200.0, kd=5e4, m=2000.0, k=5e7) for _ in range(storeys)),
                   rigid_in_plane=rigid)
    r = se.run(spec, [0.0, 100.0], [0.0, 0.0], engine="exact", x0=pushed(spec))
    assert r.t_reached == 100.0 and not r.collapsed.any()
    assert r.impacts[0] > 100  # it rocks all along, with an impact (e_r = 1) at every base crossing
    assert r.energy_start > 10.0
    assert r.work_ground == 0.0 and r.work_damping == 0.0 and r.event_losses == 0.0
    assert abs(r.energy_end - r.energy_start) <= 1e-6 * r.energy_start
    assert r.max_residual <= 1e-6 * r.energy_start


def test_energy_balance_with_damping_under_kobe():
    """Two storeys on flexible in-plane walls, dashpots beside every spring and Rayleigh damping,
    under Kobe (NIS000) at 0.5 g: the balance closes to 1e-8 of the ground's work."""
    by_name = {r.name: r for r in suite.fema_farfield(suite.fema_cache())}
    rec = records.read_at2(by_name["ff07a"].path).to_pga(0.5)
    storey = se.StoreySpec(wall=dict(WALL, Kd=1e7), md=200.0, kd=1e5, cd=2 * 0.05 * np.sqrt(1e5 * 200.0),
                           m=3000.0, k=3e7, cs=2 * 0.05 * np.sqrt(3e7 * 3000.0))
    spec = se.Spec(storeys=(storey, storey), rigid_in_plane=False, rayleigh_a0=0.05, rayleigh_a1=1e-4)
    r = se.run(spec, rec.t, rec.ag, engine="exact")
    assert r.engine == "exact" and r.impacts.sum() > 10
    assert r.work_damping > 0.1 * r.max_work and r.event_losses > 0.0
    assert r.max_residual <= 1e-8 * r.max_work
    balance = r.energy_end - r.energy_start - r.work_ground + r.work_damping + r.event_losses
    assert abs(balance) <= 1e-8 * r.max_work


def paper_wall(t, ag, Kd):
    return engine.run(t, ag, **dict(WALL, Kd=Kd))


def assert_same_motion(scene, paper, rel):
    assert scene.peak_s1[0] == pytest.approx(paper.peak_s1, rel=rel)
    assert scene.peak_s2[0] == pytest.approx(paper.peak_s2, rel=rel)
    assert scene.impacts[0] == paper.impacts
    assert bool(scene.collapsed[0]) == bool(paper.collapsed)


@pytest.mark.parametrize("D", [0.03, 0.05])
@pytest.mark.parametrize("tie, kd", [(1e5, 5e4), (1e6, 2e4)])
def test_a_massless_diaphragm_is_a_spring_in_series_with_the_tie(D, tie, kd):
    t, ag = gaussian_pulse(D, 1.0, t_end=6.0)
    spec = se.Spec(storeys=(se.StoreySpec(wall=dict(WALL, Kd=tie), md=1e-3, kd=kd),), rigid_in_plane=True)
    scene = se.run(spec, t, ag, engine="exact")
    assert scene.impacts[0] >= 5
    assert_same_motion(scene, paper_wall(t, ag, 1.0 / (1.0 / tie + 1.0 / kd)), rel=1e-3)


@pytest.mark.parametrize("tie", [1e5, 1e8])
def test_a_rigid_diaphragm_pins_the_tie(tie):
    t, ag = gaussian_pulse(0.05, 1.0, t_end=6.0)
    spec = se.Spec(storeys=(se.StoreySpec(wall=dict(WALL, Kd=tie), md=200.0, kd=1e12),), rigid_in_plane=True)
    scene = se.run(spec, t, ag, engine="exact")
    assert scene.impacts[0] >= 5
    assert_same_motion(scene, paper_wall(t, ag, tie), rel=1e-3)

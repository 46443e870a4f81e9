"""The exact event-driven engine (rockingwall.engine, and its command line rwengine) on its own:
rest with e_r = 0, energy kept with e_r = 1, the output grid and the peaks, the quiet path against
the general one, events only where the motion changes, errors on bad input."""
import math
import subprocess

import numpy as np
import pytest

from rockingwall import engine as rw_engine
from rwref import inputs


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    return tmp_path_factory.mktemp("engine_alone")


@pytest.mark.parametrize("support,law", [(3, 1), (2, 1), (3, 4), (2, 4)])
def test_er_zero_comes_to_rest(support, law):
    """e_r = 0: every impact stops the wall; the rigid law closes its hinges (rest), no Zeno."""
    sig = inputs.sampled(inputs.gaussian(0.05, 1.0), 6.0, 0.005)
    r = rw_engine.run(sig.t, sig.a, t_end=20.0, support=support, hingeLaw=law, er=0.0, Kd=1e5)
    assert not r.collapsed and 1 <= r.impacts < 50
    if law == 1:
        assert np.all(r.x_end == 0.0)
    else:  # the elastic hinges keep a free vibration that e_r = 0 stops at the next crossing
        assert np.max(np.abs(r.x_end)) < 1e-6


# NZSEE C8's statics away from their defaults (docs/model.md): an eccentric overburden makes the
# hinges' capacities and breakpoints differ between the sides
C8 = dict(psi=0.5, pointing=0.005, eBaseRatio=0.9, eHingeRatio=0.95, eTop=0.04, psiWeightOnly=0.6)


@pytest.mark.parametrize("support,law,kd,statics", [(3, 4, 5e4, {}), (3, 3, 1e6, {}), (3, 4, 1e9, {}), (2, 4, 0.0, {}),
                                                    (2, 1, 0.0, {}), (3, 4, 5e4, C8), (3, 3, 1e6, C8),
                                                    (2, 4, 0.0, C8), (2, 1, 0.0, C8)])
def test_er_one_keeps_energy_over_600_s(support, law, kd, statics):
    """Free rocking with e_r = 1 from a displaced start: the energy before every impact over 600 s
    equals the first to 1e-9. The rigid law's impacts happen RW_EPS_Q past zero (the model's
    indicator offset), where the active side's force has done work 2 F_r eps_D the potential does
    not count: its bound is that, per impact (measured: exactly that)."""
    t = np.array([0.0, 600.0])
    # past the base's elastic range of every law (semiRigidHinge's theta_y = 0.012 rad is the
    # largest), so that every crossing is a counted impact (docs/model.md "Impacts")
    q0 = 0.005 if law == 1 else 0.015
    x0 = [q0, -q0, 0.0, 0.0]  # the simply supported shape: the spring starts unstretched
    r = rw_engine.run(t, np.zeros(2), t_end=600.0, x0=x0, support=support, hingeLaw=law, er=1.0, Kd=kd,
                      impact_log=1000000, **statics)
    assert not r.collapsed and r.impacts > 1000
    e = r.impact_energy
    drift = np.max(np.abs(e - e[0])) / abs(e[0])
    bound = 1e-9
    if law == 1:
        b, h = 0.15, 2.5
        eps_d = 0.1 * 1e-10 * b / h * h / 2
        bound = r.impacts * 2.5 * eps_d / (q0 * h / 2)
    assert drift < bound, f"energy drift {drift:.3g} over {r.impacts} impacts"


def test_output_grid_matches_peaks():
    sig = inputs.el_centro(0.5)
    grid = np.linspace(0.0, 20.0, 20001)
    r = rw_engine.run(sig.t, sig.a, t_end=20.0, t_out=grid, support=3, hingeLaw=4, Kd=5e4)
    assert np.all(np.isfinite(r.s1))
    assert np.max(np.abs(r.s1)) <= r.peak_s1 * (1 + 1e-12)
    assert np.max(np.abs(r.s1)) == pytest.approx(r.peak_s1, rel=1e-4)
    np.testing.assert_allclose(r.s1, r.x[:, 0] * 2.5 / 2, rtol=0, atol=1e-15)


@pytest.mark.parametrize("law", [3, 4])
def test_peaks_under_a_stiff_spring_s_band_match_a_fine_grid(law):
    """With a stiff spring the peaks come from the slow motion plus the spring's fast oscillation,
    resolved only near a new peak (rw_engine_peaks.c rwe_peaks_under_band): a 5-us grid (about 1 800 points
    per period of the spring's mode, 713 rad/s) must never pass the peaks, and must come within 1e-7
    of them (measured: 3e-10 and 2.6e-9 below)."""
    sig = inputs.el_centro(0.5)
    grid = np.linspace(0.0, 10.0, 2_000_001)
    r = rw_engine.run(sig.t, sig.a, t_end=10.0, t_out=grid, support=3, hingeLaw=law, Kd=5e7)
    for peak, s in ((r.peak_s1, r.s1), (r.peak_s2, r.s2)):
        assert np.max(np.abs(s)) <= peak * (1 + 1e-12)
        assert np.max(np.abs(s)) >= peak * (1 - 1e-7)


@pytest.mark.parametrize("law", [1, 2, 3, 4])
@pytest.mark.parametrize("kd", [5e4, 5e7])
def test_quiet_segments_take_the_general_path_s_motion(law, kd):
    """Most segments are taken by the quiet path (rwe_quiet_segment), which must give the
    general path's motion: with an output time at the end of every segment the quiet path is never
    taken, so both runs must agree (peaks to 1e-12, the same events, impacts and end state)."""
    sig = inputs.el_centro(0.5)
    keep = sig.t <= 30.0
    t, ag = sig.t[keep], sig.a[keep]
    params = dict(support=3, hingeLaw=law, Kd=kd)
    quiet = rw_engine.run(t, ag, t_end=30.0, **params)
    general = rw_engine.run(t, ag, t_end=30.0, t_out=t[1:], **params)
    assert (quiet.events, quiet.impacts, quiet.collapsed) == (general.events, general.impacts, general.collapsed)
    assert quiet.peak_s1 == pytest.approx(general.peak_s1, rel=1e-12)
    assert quiet.peak_s2 == pytest.approx(general.peak_s2, rel=1e-12, abs=1e-15)
    np.testing.assert_allclose(quiet.x_end, general.x_end, rtol=1e-9, atol=1e-15)


@pytest.mark.parametrize("kwargs,code", [
    (dict(t=[0.0, 1.0, 1.0], ag=[0.0, 0.0, 0.0]), 1),
    (dict(t=[0.0, 1.0], ag=[0.0, math.nan]), 1),
    (dict(t=[0.0, 1.0], ag=[0.0, 1.0], t_end=-1.0), 1),
    (dict(t=[0.0, 1.0], ag=[0.0, 1.0], support=1, b=0.5, h=1.0), 3),  # a stocky parapet
    (dict(t=[0.0, 1.0], ag=[0.0, 1.0], b=3.0, h=2.0), 2),
    (dict(t=[0.0, 1.0], ag=[0.0, 1.0], t_out=[0.5, 0.2]), 1),
])
def test_bad_input_gives_an_error_code_and_a_message(kwargs, code):
    with pytest.raises(rw_engine.EngineError) as exc:
        rw_engine.run(**kwargs)
    assert exc.value.code == code and len(str(exc.value)) > 30


@pytest.mark.parametrize("law", [3, 4])
def test_engine_stops_only_where_the_motion_changes(law):
    """Under a law of q alone the mid-height hinge's switch changes nothing in the motion, so the
    engine does not stop there. At 5 % of El Centro under a stiff spring the wall only vibrates
    within its hinges' elastic range: its events are then the base crossings alone (the sign
    changes of q1 on a fine grid), where it used to take each mid-height switch too, microseconds
    after each crossing (twice the events, a fifth of the run's time)."""
    sig = inputs.el_centro(0.05)
    grid = np.arange(0.0, 20.0, 2e-4)
    r = rw_engine.run(sig.t, sig.a, t_end=20.0, t_out=grid, support=3, hingeLaw=law, Kd=5e7)
    q1 = r.x[1:, 0]  # q1 = 0 at the start
    crossings = int(np.sum(np.sign(q1[1:]) != np.sign(q1[:-1])))
    assert crossings > 50 and r.events == crossings


def test_no_event_loop_under_a_violently_oscillating_stiff_spring():
    """A start with the K_d = 1e12 spring stretched (q1 = q2): the top oscillates at ~1e5 rad/s
    through the hinges' breakpoints. The engine used to find the breakpoint it had just applied
    again at the same instant (its next span rebuilt the state through P Pi, flipping an indicator
    of 1e-18): a Zeno stop. Now the run goes through with every event at its own instant."""
    r = rw_engine.run(np.array([0.0, 1.0]), np.zeros(2), t_end=1.0, x0=[0.005, 0.005, 0.0, 0.0], support=3,
                      hingeLaw=4, er=1.0, Kd=1e12, max_events_per_instant=1)
    assert r.t_reached == 1.0 and r.events > 1000


def test_command_line_run_matches_the_binding(build_dir, workdir):
    import json
    sig = inputs.el_centro(0.5)
    csv = workdir / "cli.csv"
    np.savetxt(csv, np.c_[sig.t, sig.a], delimiter=",", header="time,ag", comments="", fmt="%.17g")
    proc = subprocess.run([str(build_dir / "rwengine"), "--input", str(csv), "--stop-time", "30", "--set", "Kd=5e4",
                           "--set", "hingeLaw=3"], capture_output=True, text=True, timeout=60, check=True)
    got = json.loads(proc.stdout)
    r = rw_engine.run(sig.t, sig.a, t_end=30.0, Kd=5e4, hingeLaw=3)
    assert got["peak_s1"] == r.peak_s1 and got["impacts"] == r.impacts
    bad = subprocess.run([str(build_dir / "rwengine"), "--input", str(csv), "--set", "support=1", "--set", "b=0.5",
                          "--set", "h=1.0"], capture_output=True, text=True, timeout=60)
    assert bad.returncode == 2 and "parapet" in bad.stderr

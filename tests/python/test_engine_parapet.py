"""The parapet (support 1) on the exact engine: Housner's block in its small-rotation form against
fmi2sim (CVODE on the FMU's nonlinear block) on random slender scenes, against Housner's exact
free-rocking amplitude decay, the stocky parapet left to CVODE, and the command line."""
import math

import numpy as np
import pandas as pd
import pytest

from rockingwall import engine, fmi2sim, paths

G = 9.81


def _fmi2sim_peak(tmp_path, t, ag, t_end, **params):
    table = tmp_path / "input.csv"
    pd.DataFrame({"time": t, "ag": ag}).to_csv(table, index=False, float_format="%.17g")
    summary = fmi2sim.run(paths.wall_fmu(), input_csv=str(table), stop_time=t_end, rtol=1e-10, output_interval=0.01,
                          sets=list(params.items()), output=str(tmp_path / "out.csv"))
    o = summary["outputs"]
    return o["s1"]["max_abs"], bool(o["collapsed"]["final"]), int(o["impacts"]["final"])


def test_engine_matches_fmi2sim_on_random_slender_parapets(tmp_path):
    """The FMU solves the nonlinear block; the engine its small-rotation form. With h/b >= 1000
    (alpha <= 1e-3) the two forms' right-hand sides differ by O(alpha^2) < 1e-6 relative, so the
    peaks must agree to 1e-5 (relative): the comparison is at that slenderness, not at one
    linearisation of the FMU."""
    rng = np.random.default_rng(31)
    compared = 0
    for _ in range(6):
        h = rng.uniform(20.0, 30.0)
        b = 0.02
        alpha = math.atan(b / h)
        t = np.linspace(0.0, 20.0, 2001)
        w = 2.0 * math.pi * rng.uniform(0.1, 0.5)  # pulses slow against p = sqrt(3g/4R)
        ag = G * math.tan(alpha) * rng.uniform(1.3, 2.2) * np.sin(w * t + rng.uniform(0.0, 6.0)) \
            * np.exp(-rng.uniform(0.05, 0.3) * t)
        params = dict(support=1, h=h, b=b, W=3000.0, er=rng.uniform(0.7, 0.95))
        r = engine.run(t, ag, t_end=25.0, **params)
        peak, collapsed, impacts = _fmi2sim_peak(tmp_path, t, ag, 25.0, **params)
        assert r.collapsed == collapsed
        assert r.peak_s1 == pytest.approx(peak, rel=1e-5)
        if not collapsed:
            assert r.impacts == impacts
            compared += 1
    assert compared >= 3  # not every scene a collapse


def _housner_amplitudes(alpha, theta0, er, n):
    """Housner (1963), the small-rotation block released from rest at theta0: the amplitude after
    k impacts, theta_k/alpha = 1 - sqrt(1 - er^(2k) [1 - (1 - theta0/alpha)^2])."""
    return [alpha * (1.0 - math.sqrt(1.0 - er ** (2 * k) * (1.0 - (1.0 - theta0 / alpha) ** 2))) for k in range(n)]


def test_free_rocking_follows_housners_amplitude_decay():
    h, b, er = 3.0, 0.2, 0.9
    alpha, R = math.atan(b / h), math.hypot(b / 2, h / 2)
    p = math.sqrt(3.0 * G / (4.0 * R))
    theta0 = 0.6 * alpha
    amps = _housner_amplitudes(alpha, theta0, er, 6)
    # each half cycle: from the peak A to the impact in acosh(alpha / (alpha - A)) / p, and back
    quarter = [math.acosh(alpha / (alpha - a)) / p for a in amps]
    t_impacts = np.cumsum([quarter[0]] + [2.0 * q for q in quarter[1:-1]])
    t_peaks = np.concatenate([[0.0], t_impacts + np.array(quarter[1:])])
    t_end = float(t_peaks[-1]) + 1e-3
    t = np.array([0.0, t_end])
    r = engine.run(t, np.zeros(2), t_end=t_end, x0=[theta0, theta0, 0.0, 0.0], t_out=t_peaks, impact_log=8,
                   support=1, h=h, b=b, W=3000.0, er=er)
    assert r.impact_t[:len(t_impacts)] == pytest.approx(t_impacts, rel=1e-9)
    assert np.abs(r.x[:, 0]) == pytest.approx(amps, rel=1e-8)
    assert np.sign(r.x[:, 0]) == pytest.approx([(-1.0) ** k for k in range(len(amps))])


def test_stocky_parapet_is_left_to_cvode():
    t = np.linspace(0.0, 1.0, 11)
    with pytest.raises(engine.EngineError, match="small-rotation"):
        engine.run(t, 0.0 * t, t_end=1.0, support=1, h=1.0, b=0.15)
    assert engine.covers(dict(support=1, h=2.5, b=0.15)) and not engine.covers(dict(support=1, h=1.0, b=0.15))


@pytest.mark.parametrize("side", [1.0 - 1e-9, 1.0 + 1e-9])
def test_the_python_limit_is_the_c_engines(side):
    """engine.PARAPET_MAX_B_OVER_H is a copy of rw_engine.h's: either side of it, engine.covers says
    what the C engine does."""
    t = np.linspace(0.0, 1.0, 11)
    wall = dict(support=1, h=2.0, b=2.0 * engine.PARAPET_MAX_B_OVER_H * side)
    try:
        engine.run(t, 0.0 * t, t_end=1.0, **wall)
        ran = True
    except engine.EngineError:
        ran = False
    assert ran == engine.covers(wall) == (side < 1.0)


def test_command_line_runs_a_parapet_on_the_engine():
    import contextlib
    import io
    import json
    from rockingwall.cli import main
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        code = main(["run", "--wall", "paper1", "--support", "parapet", "--pga", "0.2", "--json", "elcentro"])
    assert code in (0, None)
    runs = json.loads(buf.getvalue())["runs"]
    assert [r["engine"] for r in runs] == ["exact"]
    assert runs[0]["impacts"] >= 1


def test_command_line_leaves_a_stocky_parapet_to_fmi2sim_and_says_so():
    from rockingwall.cli import main
    import contextlib
    import io
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        main(["run", "--wall", "paper1", "--support", "parapet", "--h", "1.0", "--pga", "0.2", "elcentro"])
    assert "solved by fmi2sim (a parapet with b/h > 0.1" in buf.getvalue()


def test_assess_names_fmi2sim_for_a_stocky_parapet(tmp_path):
    import contextlib
    import io
    from rockingwall.cli import main
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        main(["assess", "--wall", "paper1", "--support", "parapet", "--h", "1.0", "elcentro", "--pga", "0.1",
              "--ensemble", "0", "--out", str(tmp_path / "assess")])
    assert "solved by fmi2sim (a parapet with b/h > 0.1" in buf.getvalue()

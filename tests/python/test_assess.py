"""An engineer's assessment end to end. The scene: a top-storey wall (b = 0.23 m, h = 3.2 m,
W = 14.08 kN/m, psi = 0.2) tied to a diaphragm of K_d = 30 kN/m per m, under Loma Prieta 1989,
Capitola 000 (FEMA P695 far-field ff13a) scaled to 0.35 g, with the semiRigidHinge law: fmi2sim,
fmpy and the reference solver gave s1 = 73 mm, s2 = 96 mm when it was first tried."""
import numpy as np
import pandas as pd
import pytest

import rockingwall as rw
from rockingwall import fmi2sim, intensity, limits
from rockingwall.records import Record
from rockingwall.sweep import fragility
from rockingwall.sweep import suites as suite

ENGINEER = dict(b=0.23, h=3.2, W=14080.0, psi=0.2, Kd=30e3, hingeLaw=3)
WALL_FLAGS = ["--b", "230mm", "--h", "3.2", "--W", "14.08kN/m", "--psi", "0.2", "--hinge-law", "semiRigidHinge"]


@pytest.fixture(scope="module")
def capitola(tmp_path_factory):
    return pathlib_of(suite.fema_farfield(tmp_path_factory.mktemp("fema")), "ff13a")


def pathlib_of(recs, name):
    return next(r.path for r in recs if r.name == name)


def assess(tmp_path, *args):
    from rockingwall.cli import main
    return main(["assess", *map(str, args), "--out", str(tmp_path)])


@pytest.mark.parametrize("kd", ["30kN/m/m", "30000", "30 kN/m per m", "0.03MN/m/m"])
def test_engineer_scene_assess_api_and_fmi2sim_agree(capitola, tmp_path, kd, rockingwall_fmu):
    assert assess(tmp_path, capitola, *WALL_FLAGS, "--kd-values", kd, "--pga", "0.35") == 0
    case = pd.read_csv(tmp_path / "cases.csv").iloc[0]
    record = rw.read_at2(capitola).to_pga(0.35)
    api = rw.simulate(rw.Wall.make(**ENGINEER), record)
    scale = 0.35 * 9.81 / rw.read_at2(capitola).pga
    cvode = fmi2sim.run(rockingwall_fmu, ag=capitola, ag_scale=scale, stop_time=float(record.t[-1]), rtol=1e-9,
                        sets=[(k, v) for k, v in ENGINEER.items()])["outputs"]
    for s1, s2 in [(case.peak_s1_mm / 1e3, case.peak_s2_mm / 1e3), (api.peak_s1, api.peak_s2),
                   (cvode["s1"]["max_abs"], cvode["s2"]["max_abs"])]:
        assert s1 == pytest.approx(0.073, rel=0.01) and s2 == pytest.approx(0.096, rel=0.01)
    assert not case.collapsed and case.s1_over_Delta_u == pytest.approx(api.peak_s1 / 0.2204, rel=1e-3)


def test_a_wall_past_its_thickness_is_past_a_limit_state():
    """Kobe at 0.8 g once gave s1 = 236 mm > b = 230 mm and 'not collapsed', with no word of a limit."""
    wall = rw.Wall.make(**ENGINEER)
    states = limits.parse_all(["thickness: s1 >= 1.0*b"], wall)
    peaks = dict(peak_s1=0.236, peak_s2=0.422, peak_F_top=0.0, collapsed=False)
    assert [s.name for s in states if s.exceeded(peaks)] == ["0.6 Delta_u", "Delta_u", "thickness"]
    assert states[0].threshold == pytest.approx(0.6 * wall.delta_u)
    assert not any(s.exceeded(dict(peaks, peak_s1=0.05)) for s in states)
    with pytest.raises(ValueError, match="QUANTITY"):
        limits.parse("s3 >= 5mm", wall)


def test_fragility_from_two_records_warns_and_separated_data_say_beta_is_not_identified():
    im = np.array([0.1, 0.2, 0.3, 0.1, 0.2, 0.3])
    exceeded = np.array([False, False, True, False, True, True])
    est = fragility.fit_with_uncertainty(im, exceeded, np.array(["a"] * 3 + ["b"] * 3))
    assert est.fit is not None and est.n_records == 2
    assert any("only 2 records" in w for w in est.warnings)
    est = fragility.fit_with_uncertainty(im, im > 0.15, np.array(["a"] * 3 + ["b"] * 3))
    assert any("beta is not identified" in w for w in est.warnings)


def test_fragility_intervals_cover_a_known_lognormal():
    rng = np.random.default_rng(3)
    capacity = np.exp(np.log(0.4) + 0.3 * rng.standard_normal(40))  # 40 records' collapse PGA
    levels = np.linspace(0.1, 1.0, 10)
    im = np.tile(levels, 40)
    names = np.repeat([f"r{i}" for i in range(40)], 10)
    est = fragility.fit_with_uncertainty(im, im >= np.repeat(capacity, 10), names)
    assert est.theta_90[0] < 0.4 < est.theta_90[1] and est.beta_90[0] < 0.3 < est.beta_90[1]
    assert not est.warnings


def test_resurrection_is_reported():
    assert fragility.resurrections([0.2, 0.4, 0.3, 0.5], [False, False, True, True]) == [0.4]
    assert fragility.resurrections([0.1, 0.2], [False, True]) == []


def test_sa_of_a_harmonic_record_is_the_steady_state_amplitude():
    period, forcing, zeta = 0.5, 0.8, 0.05
    t = np.arange(0.0, 60.0, 0.005)
    edge = np.clip(np.minimum(t, t[-1] - t) / 10.0, 0.0, 1.0)
    ramp = 0.5 * (1 - np.cos(np.pi * edge))  # a smooth 10-s start and end: no free transient to speak of
    w, W = 2 * np.pi / period, 2 * np.pi / forcing
    record = Record("sine", t, 0.2 * 9.81 * ramp * np.sin(W * t))
    expected = w**2 * 0.2 / np.hypot(w**2 - W**2, 2 * zeta * w * W)
    assert intensity.sa(record, period, zeta) == pytest.approx(expected, rel=0.01)


def test_assess_of_two_records_reports_fragility_with_warning_and_plots(capitola, tmp_path, capsys):
    gaussian = "gaussian:0.04,1.0"
    assert assess(tmp_path, capitola, gaussian, *WALL_FLAGS, "--kd-values", "30kN/m/m", "--pga", "0.2", "0.5", "0.9",
                  "--limit", "connection: s2 >= 60mm") == 0
    out = capsys.readouterr().out
    assert "only 2 records" in out and "connection" in out
    cases = pd.read_csv(tmp_path / "cases.csv")
    assert len(cases) == 6 and {"0.6 Delta_u", "Delta_u", "connection", "collapsed"} <= set(cases.columns)
    assert (tmp_path / "ff13a.png").stat().st_size > 1000 and (tmp_path / "fragility.png").stat().st_size > 1000

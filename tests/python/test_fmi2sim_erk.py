"""fmi2sim --solver erk (ARKODE ERKStep): against the exact engine on El Centro, and the bouncing
ball's analytic bounce times."""
import math
import subprocess

import numpy as np
import pytest

from engine_scenes import PEAK_RTOL, engine_run
from rwref import inputs


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    return tmp_path_factory.mktemp("erk")


# ---- fmi2sim --solver erk (ARKODE ERKStep) ------------------------------------------------------------

def test_fmi2sim_erk_agrees_with_the_engine(fmi2sim_exe, rockingwall_fmu, workdir):
    sig = inputs.el_centro(0.5)
    params = dict(support=3, hingeLaw=4, Kd=5e4)
    sc = dict(seed=9300, t=sig.t, ag=sig.a, t_end=20.0, label="El Centro 50 %", params=params)
    csv = workdir / "in9300.csv"
    np.savetxt(csv, np.c_[sig.t, sig.a], delimiter=",", header="time,ag", comments="", fmt="%.17g")
    out = workdir / "erk.json"
    args = [str(fmi2sim_exe), str(rockingwall_fmu), "--solver", "erk", "--rtol", "1e-10", "--input", str(csv),
            "--stop-time", "20", "--summary", str(out)] + sum((["--set", f"{k}={v}"] for k, v in params.items()), [])
    subprocess.run(args, check=True, capture_output=True, timeout=300)
    import json
    o = json.loads(out.read_text())["outputs"]
    r = engine_run(sc)
    assert o["impacts"]["final"] == r.impacts
    scale = max(r.peak_s1, r.peak_s2)
    assert abs(o["s1"]["max_abs"] - r.peak_s1) <= PEAK_RTOL * scale
    assert abs(o["s2"]["max_abs"] - r.peak_s2) <= PEAK_RTOL * scale


def test_fmi2sim_erk_bouncing_ball(fmi2sim_exe, build_dir, tmp_path):
    """The analytic bounce times (tests/bouncingball) with the explicit Runge-Kutta integrator."""
    out = tmp_path / "ball.csv"
    subprocess.run([str(fmi2sim_exe), str(build_dir / "BouncingBall.fmu"), "--solver", "erk", "--rtol", "1e-10",
                    "--set", "h=2", "--set", "e=0.8", "--stop-time", "5", "--output", str(out)], check=True,
                   capture_output=True, timeout=60)
    d = np.genfromtxt(out, delimiter=",", names=True)
    steps = np.nonzero(np.diff(d["bounces"]) > 0)[0] + 1
    got = d["time"][steps][:5]
    v1 = math.sqrt(2 * 9.81 * 2.0)
    want = [math.sqrt(2 * 2.0 / 9.81)]
    for k in range(1, 5):
        want.append(want[-1] + 2 * 0.8**k * v1 / 9.81)
    np.testing.assert_allclose(got, want, rtol=1e-7)

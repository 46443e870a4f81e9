"""What the `impacts` output counts with the semi-rigid hinge laws (docs/model.md "Impacts"): a
base crossing q1 = 0 only after the base has passed the end of its elastic range (the law's first
base breakpoint) since the previous crossing, i.e. a return from an uplift. Before any uplift the
base oscillates elastically through q1 = 0 (El Centro 50 % on wall 1: from t = 0.1 s, at |s1| of
0.04 mm); those crossings were counted as impacts (170 to 218 of them), they no longer are. The
restitution still applies at every crossing: only the count changed. The count is recounted here
from fmi2sim's time history (a row before and after every event) and checked against the exact
engine and the reference solver."""
import subprocess

import numpy as np
import pytest

from rockingwall import engine as rw_engine
from rwref import Params, inputs, simulate

LAWS = {2: "semiRigidPaper", 3: "semiRigidHinge", 4: "dohertyHinge"}


def uplift_s1(law, support="flexibleTop"):
    """|s1| = h|q1|/2 at the end of the base's elastic range, from the reference's parameters."""
    p = Params(support=support, hinge_law=LAWS[law])
    if law == 4 or support == "simplySupported":
        return p.Delta_1
    return p.theta_y * p.h / 2


def fmi2sim_history(exe, fmu, tmp_path, law, scale=0.5, t_end=30.0, support=3):
    rec = inputs.el_centro(scale)
    csv = tmp_path / "ag.csv"
    np.savetxt(csv, np.c_[rec.t, rec.a], delimiter=",", header="time,ag", comments="", fmt="%.17g")
    out = tmp_path / "out.csv"
    proc = subprocess.run([str(exe), str(fmu), "--input", str(csv), "--stop-time", str(t_end), "--rtol", "1e-10",
                           "--set", f"hingeLaw={law}", "--set", f"support={support}", "--output", str(out)],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    return np.genfromtxt(out, delimiter=",", names=True)


def recount(d, limit):
    """Base crossings (sign changes of s1 between rows) after |s1| reached `limit` since the
    previous crossing."""
    s1 = d["s1"]
    count, peak, side = 0, 0.0, 0
    for v in s1:
        if v != 0.0 and side != 0 and np.sign(v) != side:
            count += peak >= limit * (1 - 1e-6)
            peak = 0.0
        if v != 0.0:
            side = int(np.sign(v))
        peak = max(peak, abs(v))
    return count


@pytest.mark.parametrize("law", [2, 3, 4])
def test_impacts_are_returns_from_uplift(fmi2sim_exe, rockingwall_fmu, tmp_path, law):
    """El Centro 50 % on wall 1: no impact before the base first passes its elastic range, and
    the count equals the crossings after an uplift recounted from the time history."""
    d = fmi2sim_history(fmi2sim_exe, rockingwall_fmu, tmp_path, law)
    limit = uplift_s1(law)
    impacts = d["impacts"]
    first = np.nonzero(impacts > 0)[0]
    assert first.size, "the wall rocks under El Centro 50 %"
    assert np.abs(d["s1"][:first[0]]).max() >= limit * (1 - 1e-6), (d["time"][first[0]], limit)
    assert int(impacts[-1]) == recount(d, limit)
    crossings = np.count_nonzero(np.diff(np.sign(d["s1"][d["s1"] != 0])))
    assert crossings > impacts[-1]  # the elastic crossings happen, they are not counted


@pytest.mark.parametrize("law", [2, 3, 4])
def test_engine_and_reference_count_the_same_impacts(law):
    """The exact engine (the FMU's event logic) and the scipy reference solver (its own) agree on
    the count under a pulse that rocks the wall and leaves it oscillating elastically (8 to 14
    impacts out of 34 to 47 crossings). A swing whose peak grazes the elastic limit is counted or
    not on rounding: at a third of this pulse, dohertyHinge gives 19 in the engine, 18 here."""
    sig = inputs.sampled(inputs.gaussian(0.05, 0.5), 8.0, 0.002)
    r = rw_engine.run(sig.t, sig.a, t_end=8.0, support=3, hingeLaw=law, Kd=1e5)
    ref = simulate(Params(support="flexibleTop", hinge_law=LAWS[law], Kd=1e5), sig, 8.0, method="DOP853",
                   rtol=1e-10, atol=1e-13)
    crossings = sum(1 for _, k in ref.events if k == "base_impact")
    assert r.impacts == ref.impacts >= 1
    assert crossings > ref.impacts

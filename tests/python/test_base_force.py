"""RockingWall's F_base against the horizontal momentum balance along simulated trajectories.

The wall's horizontal momentum relative to the ground, P(t), is written here from the geometry
(docs/model.md: centroids of the two bodies at h q1/4 and h q1/2 + h q2/4, the overburden at the
top s2; the parapet's centroid at R from its pivot), not from the C code. Newton for the wall with
its overburden: dP/dt + m_tot ag = (reaction of the support) + (force of the spring on the wall)
= -F_base - F_top. dP/dt is taken by central finite differences of the simulated states on the
uniform output grid; windows that hold an event are left out (a base impact: the rates jump, an
impulsive base force that no sample can show; a hinge breakpoint: the third derivative jumps and
the difference's error grows to O(dt)).

Tolerance: the 3-point difference errs by about (2 pi f dt)^2/6 ~ 1e-4 of the force at dt = 1 ms
and the wall's few-Hz motion, the solver's rtol 1e-9 adds less; 2e-3 of max |F_base| leaves a
margin and still fails if any term (the overburden's inertia, the spring force, the rates'
quadratic term of the parapet) is missing: each is checked to be far larger than the tolerance.
The wall also runs with NZSEE C8's statics (pointing, reactions set in from the faces, an
eccentric top load and a weight-only overburden): the parapet's centroid is then at e_b from its
pivot horizontally, and the weight-only overburden has no mass, so the balance must not count it.
"""
import math

import numpy as np
import pytest
from fmpy import simulate_fmu

G = 9.81
H, B, W, PSI, KD = 3.0, 0.2, 8000.0, 1.0, 3e4
# the statics parameters: the paper's wall, and one with all of them away from their defaults
STATICS = {"paper": {}, "C8": {"pointing": 0.005, "eBaseRatio": 0.95, "eHingeRatio": 0.9, "eTop": 0.03,
                               "psiWeightOnly": 1.0}}
DT = 1e-3
STOP = 3.0


def momentum(support, rows, statics):
    """Horizontal momentum of the wall relative to the ground, from the states."""
    q1, q2, dq1, dq2 = rows["q1"], rows["q2"], rows["dq1"], rows["dq2"]
    m_body, m_over = W / 2 / G, PSI * W / 2 / G   # the weight-only overburden has no mass
    if support == 1:  # one block (no overburden): centroid velocity (s e_b sin th + H cos th) th'
        side = np.where(q1 != 0, np.sign(q1), 1.0)
        e_b = statics.get("eBaseRatio", 1.0) * (B - 2 * statics.get("pointing", 0.0)) / 2
        return (W / G) * (side * e_b * np.sin(q1) + H / 2 * np.cos(q1)) * dq1
    if support == 2:  # q2 = -q1: both centroids at h q1/4, the top held
        return 2 * m_body * H / 4 * dq1
    v1 = H / 4 * dq1
    v2 = H / 2 * dq1 + H / 4 * dq2
    v_top = H / 2 * (dq1 + dq2)
    return m_body * v1 + m_body * v2 + m_over * v_top


# ground motion amplitude per support [m/s2]: the wall rocks (and impacts) but stands for the whole run
AMPLITUDE = {1: 0.8, 2: 1.5, 3: 2.5}


def inputs(support, scale=1.0):
    t = np.arange(0.0, STOP + DT / 2, DT / 4)
    ag = scale * AMPLITUDE[support] * np.sin(2 * math.pi * 1.3 * t) * np.exp(-0.3 * t)
    u_top = 0.004 * np.sin(2 * math.pi * 0.9 * t)
    return np.array(list(zip(t, ag, u_top)), dtype=[("time", float), ("ag", float), ("u_top", float)])


def simulate(fmu, support, statics):
    start = {"h": H, "b": B, "W": W, "psi": PSI, "Kd": KD, "support": support, "q1": 0.01,
             "q2": 0.01 if support == 1 else (-0.01 if support == 2 else 0.004), **statics}
    return simulate_fmu(str(fmu), fmi_type="ModelExchange", start_values=start, stop_time=STOP,
                        output_interval=DT, relative_tolerance=1e-9,
                        input=inputs(support, 0.6 if statics else 1.0),  # the C8 wall is the weaker
                        output=["q1", "q2", "dq1", "dq2", "ag", "u_top", "F_base", "F_top", "impacts"])


def central_difference(t, y):
    """dy/dt at the inner samples of a (possibly uneven) grid, 3-point Lagrange formula."""
    h0, h1 = t[1:-1] - t[:-2], t[2:] - t[1:-1]
    return (-h1 / (h0 * (h0 + h1)) * y[:-2] + (h1 - h0) / (h0 * h1) * y[1:-1] + h0 / (h1 * (h0 + h1)) * y[2:])


@pytest.mark.parametrize("statics", sorted(STATICS))
@pytest.mark.parametrize("support", [1, 2, 3])
def test_base_force_is_the_momentum_balance(rockingwall_fmu, support, statics):
    r = simulate(rockingwall_fmu, support, STATICS[statics])
    # event instants appear twice in fmpy's result: keep one sample per time
    keep = np.concatenate([np.diff(r["time"]) > 1e-12, [True]])
    r = r[keep]
    t = r["time"]
    assert t[-1] == pytest.approx(STOP), "the wall collapsed: the run is too short to check much"
    P = momentum(support, r, STATICS[statics])
    m_tot = (W + (PSI * W / 2 if support != 1 else 0.0)) / G
    dPdt = central_difference(t, P)
    inner = r[1:-1]
    uniform = (np.abs(t[1:-1] - t[:-2] - DT) < 1e-9) & (np.abs(t[2:] - t[1:-1] - DT) < 1e-9)
    smooth = uniform & (r["impacts"][2:] == r["impacts"][:-2])
    assert smooth.sum() > 0.8 * len(smooth), "most windows hold an impact: the check would see little"
    predicted = -(dPdt + m_tot * inner["ag"]) - inner["F_top"]
    err = np.abs(predicted - inner["F_base"])[smooth]
    scale = np.max(np.abs(inner["F_base"]))
    tol = 2e-3 * scale
    print(f"support {support}: max |F_base| = {scale:.4g} N/m, max |momentum balance error| = {err.max():.3g} N/m "
          f"({err.max() / scale:.2e}), {(~smooth).sum()} windows with events left out")
    assert err.max() < tol
    # every term counts: without the wall's motion the balance is off by far more than the tolerance
    assert np.max(np.abs(dPdt[smooth])) > 20 * tol
    if support == 3:
        assert np.max(np.abs(inner["F_top"])) > 20 * tol
        assert (PSI * W / 2 / G) * np.max(np.abs(inner["ag"])) > 20 * tol
        # counting the weight-only overburden's mass would break the balance
        assert (STATICS[statics].get("psiWeightOnly", 0.0) * W / 2 / G) * np.max(np.abs(inner["ag"])) > 20 * tol \
            or statics == "paper"

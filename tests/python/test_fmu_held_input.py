"""The FMU's answer must not depend on the importer's communication step for the record.

The README's fmpy call without `output_interval`: fmpy picks Co-Simulation and a communication
step of 0.04 s for a 40-s record (it doubles the FMU's 5-ms stepSize until at most 1000 output
points), and holds `ag` over each step, 8 samples of a 0.005-s accelerogram. On the assessor's
wall (b = 230 mm, h = 3.6 m, W = 14.904 kN/m, psi = 0.2013) under Loma Prieta, Capitola 000 at
0.35 g with K_d = 30 kN/m per m the converged peak s1 is 55.3 mm; that call collapsed the wall
at 9.33 s when this was written (with output_interval 0.005 s: 55.2 mm)."""
import numpy as np
import pytest
from fmpy import simulate_fmu

import rockingwall as rw
from rockingwall.sweep import suites as suite

WALL = dict(b=0.23, h=3.6, W=14904.0, psi=0.2013, Kd=30e3)


@pytest.mark.xfail(strict=True, reason="the FMU holds the importer's input over the communication step and does "
                   "not warn; needs the FMU to read the record itself or to warn (C change in the RockingWall "
                   "FMU, pending the restructuring of its FMI layers)")
def test_finding6_readme_fmpy_call_without_output_interval_is_within_1_percent_or_warns(rockingwall_fmu,
                                                                                       tmp_path):
    path = next(r.path for r in suite.fema_farfield(tmp_path) if r.name == "ff13a")
    record = rw.read_at2(path).to_pga(0.35)
    converged = rw.simulate(rw.Wall.make(**WALL), record).peak_s1
    messages = []

    def logger(env, instance, status, category, message):
        messages.append((status, message.decode(errors="replace")))
    signal = np.array(list(zip(record.t, record.ag, 0 * record.t)),
                      dtype=[("time", float), ("ag", float), ("u_top", float)])
    res = simulate_fmu(str(rockingwall_fmu), stop_time=float(record.t[-1]), start_values=WALL, input=signal,
                       output=["s1", "s2", "collapsed"], logger=logger)
    peak = float(np.abs(res["s1"]).max())
    warned = any(status >= 1 and "input" in text and ("step" in text or "held" in text) for status, text in messages)
    assert abs(peak - converged) <= 0.01 * converged or warned, f"peak s1 {peak:.4f} m against {converged:.4f} m"

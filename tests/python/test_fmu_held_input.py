"""The FMU's answer must not depend on the importer's communication step for the record.

The README's fmpy call without `output_interval`: fmpy picks Co-Simulation and a communication
step of 0.04 s for a 40-s record (it doubles the FMU's 5-ms stepSize until at most 1000 output
points). Given as the input `ag`, the record is held over each step, 8 samples of a 0.005-s
accelerogram: on the assessor's wall (b = 230 mm, h = 3.6 m, W = 14.904 kN/m, psi = 0.2013) under
Loma Prieta, Capitola 000 at 0.35 g with K_d = 30 kN/m per m that call collapsed the wall at 9.33 s
against a converged peak s1 of 55.3 mm. Given as the file parameter `agFile`, the FMU follows the
record itself whatever the step; given as `ag` over long steps, the FMU warns."""
import numpy as np
import pytest
from fmpy import simulate_fmu

import rockingwall as rw
from rockingwall.sweep import suites as suite

WALL = dict(b=0.23, h=3.6, W=14904.0, psi=0.2013, Kd=30e3)
G = 9.81  # the FMU's default g, and the g of read_at2 / to_pga


@pytest.fixture(scope="module")
def capitola(tmp_path_factory):
    """(path of the AT2 file, the record at 0.35 g, agScale that makes the file 0.35 g)."""
    path = next(r.path for r in suite.fema_farfield(tmp_path_factory.mktemp("ff")) if r.name == "ff13a")
    raw = rw.read_at2(path)
    return path, raw.to_pga(0.35), 0.35 / float(np.abs(raw.ag / G).max())


@pytest.fixture(scope="module")
def converged(capitola):
    return rw.simulate(rw.Wall.make(**WALL), capitola[1]).peak_s1


def _run(fmu, record, messages, **kw):
    def logger(env, instance, status, category, message):
        messages.append((status, message.decode(errors="replace")))
    res = simulate_fmu(str(fmu), stop_time=kw.pop("stop_time", float(record.t[-1])), logger=logger,
                       output=["s1", "s2", "collapsed"], **kw)
    return float(np.abs(res["s1"]).max())


def _held_warnings(messages):
    return [text for status, text in messages if status == 1 and "input ag is held" in text]


@pytest.mark.parametrize("fmi_type", ["CoSimulation", "ModelExchange"])
def test_readme_fmpy_call_with_agFile_without_output_interval_is_within_1_percent(rockingwall_fmu, capitola,
                                                                                 converged, fmi_type):
    path, record, scale = capitola
    messages = []
    peak = _run(rockingwall_fmu, record, messages, fmi_type=fmi_type,
                start_values=dict(WALL, agFile=str(path), agScale=scale))
    assert abs(peak - converged) <= 0.01 * converged, f"peak s1 {peak:.5f} m against {converged:.5f} m"
    assert not _held_warnings(messages)


def test_agFile_as_csv_gives_the_at2_answer(rockingwall_fmu, capitola, tmp_path):
    """The same record as a CSV in m/s2 (written here from the Python reader's samples) and as the
    AT2 file scaled by agScale: the same peak, in a run at the record's own steps."""
    path, record, scale = capitola
    csv = tmp_path / "capitola.csv"
    csv.write_text("time,ag\n" + "".join(f"{t!r},{a!r}\n" for t, a in zip(record.t.tolist(), record.ag.tolist())))
    peaks = [_run(rockingwall_fmu, record, [], output_interval=0.005, start_values=dict(WALL, agFile=str(f), agScale=s))
             for f, s in ((path, scale), (csv, 1.0))]
    assert peaks[0] == pytest.approx(peaks[1], rel=1e-6)


def test_ag_held_over_the_default_step_warns(rockingwall_fmu, capitola):
    """The input route without output_interval: fmpy holds ag over 0.04 s (here 0.01 s over a 2-s
    run); the FMU says so once, and says nothing when the steps are 5 ms."""
    _, record, _ = capitola
    signal = np.array(list(zip(record.t, record.ag, 0 * record.t)),
                      dtype=[("time", float), ("ag", float), ("u_top", float)])
    coarse, fine = [], []
    _run(rockingwall_fmu, record, coarse, stop_time=2.0, output_interval=0.01, start_values=WALL, input=signal)
    _run(rockingwall_fmu, record, fine, stop_time=2.0, output_interval=0.005, start_values=WALL, input=signal)
    warnings = _held_warnings(coarse)
    assert len(warnings) == 1 and "0.01 s" in warnings[0] and "agFile" in warnings[0], coarse
    assert not _held_warnings(fine)

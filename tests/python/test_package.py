"""The package as users meet it: `rockingwall run` with their own wall and an AT2 file gives the
peaks of the API and of fmi2sim; units are accepted in every documented form and a unit slip is
warned about; a missing output folder is created; `rockingwall info` lists the parameters."""
import json
import subprocess
import sys
import warnings

import numpy as np
import pytest

import rockingwall as rw
from rockingwall import fmi2sim
from rockingwall.sweep import suites as suite_records

# An engineer's top-storey wall: b = 0.23 m, h = 3.2 m, W = 14.08 kN/m, psi = 0.2, K_d = 30 kN/m per m
ENGINEER = dict(b=0.23, h=3.2, W=14080.0, psi=0.2, Kd=30e3)


@pytest.fixture(scope="module")
def pulse_at2(tmp_path_factory):
    path = tmp_path_factory.mktemp("rec") / "pulse.AT2"
    t = np.arange(0.0, 4.0, 0.01)
    suite_records.write_at2(path, np.where(t < 2.4, 0.3 * np.sin(2 * np.pi * t / 0.8), 0.0), 0.01, "test pulse")
    return path


def cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "rockingwall", *map(str, args)], capture_output=True, text=True,
                          timeout=300, cwd=cwd)


def test_run_equals_api_and_fmi2sim(pulse_at2, rockingwall_fmu):
    proc = cli("run", "--b", "230mm", "--h", "3.2", "--W", "14.08kN/m", "--psi", "0.2", "--Kd", "30kN/m/m",
               pulse_at2, "--json")
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    run = report["runs"][0]
    api = rw.simulate(rw.Wall.make(**ENGINEER), rw.read_at2(pulse_at2))
    # the wall by the names a reader and Wall.make know (it read "support": 3.0, "hingeLaw": 4.0)
    assert (report["wall"]["support"], report["wall"]["hingeLaw"]) == ("flexibleTop", "dohertyHinge")
    assert rw.Wall.make(**report["wall"]).params == api.wall.params
    by_fmi2sim = fmi2sim.run(rockingwall_fmu, ag=pulse_at2, stop_time=api.history.time.iloc[-1], rtol=1e-10,
                             sets=[(k, v) for k, v in ENGINEER.items()])["outputs"]
    # this pulse topples the wall: the JSON gives its collapse, not the state it collapsed at
    assert run["collapsed"] == api.collapsed and run["t_collapse_s"] == api.t_collapse
    assert (run["peak_s1_m"], run["peak_s2_m"]) == ((None, None) if api.collapsed else (api.peak_s1, api.peak_s2))
    assert api.peak_s1 > 0.01  # the wall rocks
    assert api.peak_s1 == pytest.approx(by_fmi2sim["s1"]["max_abs"], rel=1e-5)
    assert api.peak_s2 == pytest.approx(by_fmi2sim["s2"]["max_abs"], rel=1e-5)
    assert api.impacts == by_fmi2sim["impacts"]["final"]


@pytest.mark.parametrize("kd", ["30kN/m/m", "30 kN/m per m", "30e3", "30000 N/m2", "0.03 MN/m/m", "30 kN/m^2"])
def test_kd_in_each_unit_form(kd):
    assert rw.Wall.make(Kd=kd).params["Kd"] == pytest.approx(30e3)


def test_unit_slips_are_warned_and_wrong_units_refused():
    with pytest.warns(rw.PlausibilityWarning, match="kN/m per m"):
        rw.Wall.make(**dict(ENGINEER, Kd=30))           # meant 30 kN/m per m
    with pytest.warns(rw.PlausibilityWarning) as caught:
        rw.Wall.make(**dict(ENGINEER, W=14.08))         # meant 14.08 kN/m: W's range and the unit weight
    messages = " | ".join(str(w.message) for w in caught)
    assert "W = 14.08 N/m is outside" in messages and "unit weight" in messages
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        rw.Wall.make(**ENGINEER)                        # the real wall: no warning
    with pytest.raises(ValueError, match="not a unit of Kd"):
        rw.Wall.make(Kd="30 kN/m")
    with pytest.raises(ValueError, match=r"W = .*must be in"):
        rw.Wall.make(W=1)


@pytest.mark.parametrize("given, said", [
    # a height in mm and a ratio in % were refused with their range alone, the ratio's unit a bare '1'
    (dict(h=3600), "h = 3600 m: must be in [0.3, 30]; did you mean 3600 mm (write '3600mm')?"),
    (dict(b=230), "b = 230 m: must be in [0.02, 3]; did you mean 230 mm (write '230mm')?"),
    (dict(er=86), "er = 86: must be in [0, 1] (a ratio); did you mean 86 % (write '86%')?"),
    (dict(psi=-1), "psi = -1: must be in [0, 20] (a ratio)"),  # no unit lands it in range: no guess
])
def test_an_out_of_range_parameter_names_the_unit_slip_that_explains_it(given, said):
    with pytest.raises(ValueError) as err:
        rw.Wall.make(**dict(ENGINEER, **given), warn=False)
    assert str(err.value) == said


def test_cli_warns_of_a_unit_slip_and_creates_the_output_folder(pulse_at2, tmp_path):
    out = tmp_path / "not" / "yet"
    proc = cli("run", "--wall", "paper1", "--Kd", "30", pulse_at2, "--out", out)
    assert proc.returncode == 0, proc.stderr
    assert "warning: Kd = 30 N/m per m" in proc.stderr
    assert (out / "pulse.csv").is_file() and (out / "pulse.png").stat().st_size > 1000
    assert not list(out.glob(".*"))  # no temporary file left


def test_cli_errors_name_the_file_and_line(tmp_path):
    bad = tmp_path / "bad.AT2"
    bad.write_text("x\ny\nUNITS OF G\nNPTS= 2, DT= 0.01 SEC\n0.1 abc\n")
    proc = cli("run", bad)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert f"{bad}:5: cannot read 'abc'" in proc.stderr
    proc = cli("run", "--hinge-law", "cubic")
    assert proc.returncode == 2 and "unknown hinge law 'cubic'" in proc.stderr


def test_info_lists_every_parameter_with_unit_and_range():
    proc = cli("info")
    assert proc.returncode == 0, proc.stderr
    rows = {line.split()[0]: line for line in proc.stdout.splitlines()[1:] if line.strip()}
    for name, unit in [("Kd", "N/m2"), ("W", "N/m"), ("h", "m"), ("hingeLaw", "")]:
        assert name in rows and unit in rows[name]
    assert "[0.0, 1000000000000.0]  Top spring" in rows["Kd"]  # the widest range still apart from its text

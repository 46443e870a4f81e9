"""build/BuildingWithWalls.fmu (fmu_src/models/BuildingWithWalls, docs/building-with-walls.md): the
assessor's building (examples/two-storey-brick.toml) as one FMU, against the one-integration scene
solver (rockingwall.building.monolithic, the exact engine) on the same physics:

- through fmpy, Model Exchange (fmpy's CVODE with the FMU's event indicators) and Co-Simulation
  (the FMU's own CVODE), FMI 2.0 and 3.0, and through fmi2sim: peaks of s1, s2 and the
  diaphragms within 1 %, the energy balance closing;
- a wall that collapses leaves the scene at the solver's time and the other runs on;
- bad parameters are refused with the parameter named.
"""
import json

import numpy as np
import pytest
from fmpy import simulate_fmu

from rockingwall import records
from rockingwall.building import building_file, monolithic, with_walls

T_END = 6.0


@pytest.fixture(scope="module")
def assessor(repo):
    return building_file.read(repo / "examples" / "two-storey-brick.toml")


def reference(building, pga):
    rec = records.el_centro().to_pga(pga)
    res, raw = monolithic.simulate_building(building, rec, t_end=T_END)
    return rec, res, raw


def run_fmu(path, building, rec, fmi_type):
    signal = np.array(list(zip(rec.t, rec.ag)), dtype=[("time", float), ("ag", float)])
    outs = [f"{q}_{i}" for i in (1, 2) for q in ("s1", "s2", "d_diaph", "collapsed")] + [
        "energy_residual", "work_ground"]
    return simulate_fmu(str(path), fmi_type=fmi_type, stop_time=T_END, output_interval=1e-3,
                        start_values=with_walls.start_values(building), input=signal, output=outs,
                        relative_tolerance=1e-8)


def assert_peaks(res, reference_result, get):
    for s in reference_result.storeys:
        i = s.storey
        assert get(f"s1_{i}") == pytest.approx(s.peak_s1_m, rel=0.01), i
        assert get(f"s2_{i}") == pytest.approx(s.peak_s2_m, rel=0.01), i
        assert get(f"d_diaph_{i}") == pytest.approx(s.diaphragm_peak_m, rel=0.01), i


def test_fmpy_validates_the_fmi2_fmu(build_dir):
    from fmpy.validation import validate_fmu
    assert validate_fmu(str(build_dir / "BuildingWithWalls.fmu")) == []


@pytest.fixture(scope="module")
def standing(assessor):
    return reference(assessor, 0.1)


@pytest.mark.parametrize("version", ["fmi2", "fmi3"])
@pytest.mark.parametrize("fmi_type", ["ModelExchange", "CoSimulation"])
def test_fmpy_runs_equal_the_scene_solver(build_dir, assessor, standing, fmi_type, version):
    rec, ref, _ = standing
    assert not any(s.collapsed for s in ref.storeys) and ref.storeys[1].peak_s1_m > 0.01  # rocking, standing
    path = build_dir / ("fmi3" if version == "fmi3" else "") / "BuildingWithWalls.fmu"
    res = run_fmu(path, assessor, rec, fmi_type)
    assert_peaks(res, ref, lambda name: float(np.abs(np.asarray(res[name])).max()))
    assert not any(np.asarray(res[f"collapsed_{i}"]).any() for i in (1, 2))
    work = float(np.max(np.asarray(res["work_ground"])))
    assert work > 10.0 and np.abs(np.asarray(res["energy_residual"])).max() < 1e-3 * work


def test_an_eccentric_overburden_reaches_the_fmu(build_dir, repo, tmp_path):
    """wall.e_top of the building file is the FMU's eTop_i: joists 100 mm toward the inner face on
    the upper wall, El Centro at 0.1 g (both walls rocking and standing)."""
    text = (repo / "examples" / "two-storey-brick.toml").read_text()
    path = tmp_path / "house.toml"
    path.write_text(text.replace('overburden = "1.5 kN/m" }', 'overburden = "1.5 kN/m", e_top = "100 mm" }'))
    house = building_file.read(path)
    assert with_walls.start_values(house)["eTop_2"] == pytest.approx(0.1)
    rec, ref, _ = reference(house, 0.1)
    centred = reference(building_file.read(repo / "examples" / "two-storey-brick.toml"), 0.1)[1]
    assert abs(ref.storeys[1].peak_s1_m / centred.storeys[1].peak_s1_m - 1) > 0.02  # it matters
    res = run_fmu(build_dir / "BuildingWithWalls.fmu", house, rec, "ModelExchange")
    assert_peaks(res, ref, lambda name: float(np.abs(np.asarray(res[name])).max()))


def test_bilinear_diaphragms_in_the_fmu_equal_the_exact_engine(build_dir, repo, tmp_path):
    """diaphragmLaw 3: the FMU's rate form of the bilinear law (its kinks stepped over by fmpy's
    CVODE) against the exact engine's branches, on the assessor's building with diaphragms that
    yield (yield forces 1.2 and 0.4 kN/m: 2 cm of deformation) under El Centro at 0.1 g."""
    text = (repo / "examples" / "two-storey-brick.toml").read_text()
    for k, fy in (('"60 kN/m/m"', "1.2 kN/m"), ('"20 kN/m/m"', "0.4 kN/m")):
        text = text.replace(f"stiffness = {k}, mass", f'law = "bilinear", yield_force = "{fy}", post_yield = 0.1, '
                                                      f"stiffness = {k}, mass")
    path = tmp_path / "bilinear.toml"
    path.write_text(text)
    house = building_file.read(path)
    assert with_walls.start_values(house)["diaphragmLaw"] == 3
    rec, ref, _ = reference(house, 0.1)
    assert ref.solver == "exact" and ref.storeys[1].diaphragm_peak_m > 2 * 0.02  # yields well past Dy
    res = run_fmu(build_dir / "BuildingWithWalls.fmu", house, rec, "ModelExchange")
    assert_peaks(res, ref, lambda name: float(np.abs(np.asarray(res[name])).max()))


def test_fmi2sim_equals_the_scene_solver(build_dir, assessor, standing, tmp_path):
    from rockingwall import paths
    rec, ref, _ = standing
    table = tmp_path / "ag.csv"
    np.savetxt(table, np.column_stack([rec.t, rec.ag]), delimiter=",", header="time,ag", comments="")
    summary = tmp_path / "s.json"
    sets = [a for k, v in with_walls.start_values(assessor).items() for a in ("--set", f"{k}={v}")]
    import subprocess
    proc = subprocess.run([str(paths.fmi2sim()), str(build_dir / "BuildingWithWalls.fmu"), "--input", str(table),
                           "--stop-time", str(T_END), "--summary", str(summary)] + sets,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    data = json.loads(summary.read_text())
    outputs = data.get("outputs", data)
    assert_peaks(None, ref, lambda name: outputs[name]["max_abs"])


def test_a_collapsed_wall_leaves_and_the_other_runs_on(build_dir, assessor):
    rec, ref, raw = reference(assessor, 0.15)
    assert [s.collapsed for s in ref.storeys] == [False, True]
    res = run_fmu(build_dir / "BuildingWithWalls.fmu", assessor, rec, "ModelExchange")
    t = np.asarray(res["time"])
    fell = np.asarray(res["collapsed_2"]).astype(bool)
    assert not np.asarray(res["collapsed_1"]).any() and fell.any()
    assert t[np.argmax(fell)] == pytest.approx(raw.scene.t_collapse[1], abs=2e-3)
    s1 = np.asarray(res["s1_1"])
    assert np.ptp(s1[t > t[np.argmax(fell)]]) > 1e-3  # the storey-1 wall still rocks
    assert np.abs(s1).max() == pytest.approx(ref.storeys[0].peak_s1_m, rel=0.01)


@pytest.mark.parametrize("values, message", [
    ({"h_2": 0.1}, "h_2: "),
    ({"md_1": -600.0}, "md_1 = -600"),
    ({"hingeLaw_1": 7}, "hingeLaw_1 = 7"),
    ({"b_1": 2.0, "h_1": 1.0}, "storey 1 wall"),
])
def test_bad_parameters_are_refused(build_dir, values, message):
    logged = []

    def logger(component, instance, status, category, text):
        logged.append(text.decode() if isinstance(text, bytes) else str(text))

    with pytest.raises(Exception):
        simulate_fmu(str(build_dir / "BuildingWithWalls.fmu"), stop_time=0.1, start_values=values,
                     logger=logger, debug_logging=False)
    assert any(message in m for m in logged), logged

"""The FMI 3.0 FMUs (build/fmi3/RockingWall.fmu, build/fmi3/Diaphragm.fmu) against fmpy and against
their FMI 2.0 twins (build/RockingWall.fmu, build/Diaphragm.fmu), which share the models and the
core but not the API layer (fmu_src/fmi/fmi3Functions.c vs fmu_src/fmi/fmi2Functions.c).

- fmpy's validator finds nothing in either FMU;
- each binary exports the fmi3* API and nothing else;
- under El Centro 1940 at 50 %, RockingWall's FMI 3.0 FMU gives the FMI 2.0 FMU's peaks of s1 and
  s2 (within 0.1 %), impacts and collapse outcome, in Model Exchange (fmpy's CVode) and in
  Co-Simulation (the FMU's own exact engine or CVODE), for every hinge law with the flexible top,
  the simply supported wall, and a parapet that collapses;
- Diaphragm's FMI 3.0 FMU follows its FMI 2.0 twin under the same inputs;
- a Co-Simulation rolled back with fmi3SetFMUState (or a deserialized state in another instance)
  repeats its steps bitwise;
- fmpy's missing input in its CVode right-hand side (rockingwall.fmu) hits the FMI 3.0 path
  too, and the workaround fixes it there.
"""
import pathlib
import shutil
import subprocess
import zipfile

import numpy as np
import pytest
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

from rockingwall import fmu as rw_fmu
from rwref import Params, inputs, simulate


@pytest.fixture(scope="module")
def fmi3_dir(build_dir):
    path = build_dir / "fmi3"
    for name in ("RockingWall.fmu", "Diaphragm.fmu"):
        if not (path / name).exists():
            pytest.fail(f"{path / name} is missing: build it first (cmake --build build)")
    return path


@pytest.fixture(scope="module")
def el_centro():
    return inputs.el_centro(0.5)


@pytest.mark.parametrize("name", ["RockingWall", "Diaphragm", "Building", "BuildingWithWalls"])
def test_fmpy_validates_the_fmi3_fmu(fmi3_dir, name):
    assert validate_fmu(str(fmi3_dir / f"{name}.fmu")) == []


@pytest.mark.parametrize("name", ["RockingWall", "Diaphragm", "BuildingWithWalls"])
def test_the_binary_exports_only_the_fmi3_api(fmi3_dir, tmp_path, name):
    nm = shutil.which("nm")
    if nm is None:
        pytest.skip("nm not found")
    with zipfile.ZipFile(fmi3_dir / f"{name}.fmu") as z:
        so = pathlib.Path(z.extract(f"binaries/x86_64-linux/{name}.so", tmp_path))
    out = subprocess.run([nm, "-D", "--defined-only", str(so)], check=True, capture_output=True, text=True).stdout
    symbols = [line.split()[-1] for line in out.splitlines() if line.strip()]
    assert [s for s in symbols if not s.startswith("fmi3")] == []
    # every function of fmi3Functions.h: 75 in FMI 3.0
    assert len(symbols) == 75 and "fmi3DoStep" in symbols and "fmi3UpdateDiscreteStates" in symbols


FMI3_TYPE = {"Real": "Float64", "Integer": "Int32", "Boolean": "Boolean"}


def _unknowns(unknowns):
    """{name: sorted names of its dependencies (None: not given)}"""
    return {u.variable.name: None if u.dependencies is None else sorted(d.name for d in u.dependencies)
            for u in unknowns}


@pytest.mark.parametrize("name", ["RockingWall", "Diaphragm", "BuildingWithWalls"])
def test_fmi3_model_description_says_what_the_fmi2_one_says(build_dir, fmi3_dir, name):
    """Every variable of the FMI 2.0 FMU, with its attributes, outputs, derivatives, their
    dependencies, the initial unknowns and the default experiment, is in the FMI 3.0 FMU; what
    FMI 3.0 adds is `time` and one Float64 per event indicator."""
    two = read_model_description(str(build_dir / f"{name}.fmu"))
    three = read_model_description(str(fmi3_dir / f"{name}.fmu"))
    by_name = {v.name: v for v in three.modelVariables}
    for v in two.modelVariables:
        w = by_name.pop(v.name)
        assert w.type == FMI3_TYPE[v.type], v.name
        for attr in ("valueReference", "causality", "variability", "initial", "unit", "min", "max", "start",
                     "nominal", "description"):
            assert getattr(w, attr) == getattr(v, attr), (v.name, attr)
        assert (w.derivative and w.derivative.name) == (v.derivative and v.derivative.name), v.name
    extra = sorted(by_name)
    assert by_name.pop("time").causality == "independent"
    assert len(by_name) == two.numberOfEventIndicators == three.numberOfEventIndicators, extra
    assert sorted(u.variable.name for u in three.eventIndicators) == sorted(by_name)
    assert _unknowns(three.outputs) == _unknowns(two.outputs)
    assert _unknowns(three.derivatives) == _unknowns(two.derivatives)
    assert [u.variable.name for u in three.derivatives] == [u.variable.name for u in two.derivatives]
    assert sorted(u.variable.name for u in three.initialUnknowns) == sorted(u.variable.name for u in two.initialUnknowns)
    for attr in ("startTime", "stopTime", "tolerance", "stepSize"):
        assert getattr(three.defaultExperiment, attr) == getattr(two.defaultExperiment, attr), attr
    assert three.guid == two.guid
    assert sorted(u.name for u in three.unitDefinitions) == sorted(u.name for u in two.unitDefinitions)


# (support, hinge law): every law with the flexible top, the simply supported wall, a parapet
CASES = [("flexibleTop", law) for law in ("rigid", "semiRigidPaper", "semiRigidHinge", "dohertyHinge")] + [
    ("simplySupported", "dohertyHinge"), ("parapet", "rigid")]


def _run(fmu, record, support, hinge_law, fmi_type):
    return rw_fmu.simulate(fmu, float(record.t[-1]), record.t, record.a, rtol=1e-6, output_interval=0.005,
                           support=support, hinge_law=hinge_law, fmi_type=fmi_type)


@pytest.mark.parametrize("fmi_type", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("support,hinge_law", CASES)
def test_rockingwall_fmi3_agrees_with_fmi2_under_el_centro(rockingwall_fmu, fmi3_dir, el_centro, support, hinge_law,
                                                           fmi_type):
    two = _run(rockingwall_fmu, el_centro, support, hinge_law, fmi_type)
    three = _run(fmi3_dir / "RockingWall.fmu", el_centro, support, hinge_law, fmi_type)
    d1 = abs(three.peak_s1 - two.peak_s1) / two.peak_s1
    d2 = abs(three.peak_s2 - two.peak_s2) / two.peak_s2 if two.peak_s2 > 0 else abs(three.peak_s2)
    print(f"{support}/{hinge_law} {fmi_type}: peak s1 {two.peak_s1:.6e} (FMI 2.0) {three.peak_s1:.6e} (FMI 3.0), "
          f"rel. diff {d1:.1e}; peak s2 rel. diff {d2:.1e}; impacts {two.impacts}/{three.impacts}; "
          f"collapsed {two.collapsed}/{three.collapsed}")
    assert two.peak_s1 > 1e-5, "the wall must move for the comparison to mean something"
    assert d1 <= 1e-3 and d2 <= 1e-3
    assert three.collapsed == two.collapsed
    assert three.impacts == two.impacts
    if support == "parapet":
        assert two.collapsed, "the parapet case is the one that collapses"


def _diaphragm_inputs(record):
    table = np.zeros(len(record.t), dtype=[("time", np.float64), ("ag", np.float64), ("F_top", np.float64)])
    table["time"], table["ag"] = record.t, record.a
    table["F_top"] = 2000.0 * np.sin(2 * np.pi * 1.5 * record.t)  # a wall pushing at 1.5 Hz
    return table


@pytest.mark.parametrize("fmi_type", ["ModelExchange", "CoSimulation"])
def test_diaphragm_fmi3_follows_its_fmi2_twin(build_dir, fmi3_dir, el_centro, fmi_type):
    t_end = 20.0
    kw = dict(start_time=0.0, stop_time=t_end, relative_tolerance=1e-8, output_interval=0.005,
              input=_diaphragm_inputs(el_centro), output=["u", "v", "energy", "P_damping"], fmi_type=fmi_type,
              start_values={"k": 4e5, "zeta": 0.03})
    with rw_fmu.fmpy_input_in_rhs(True):  # the inputs inside fmpy's CVode steps (Model Exchange)
        two = simulate_fmu(str(build_dir / "Diaphragm.fmu"), **kw)
        three = simulate_fmu(str(fmi3_dir / "Diaphragm.fmu"), **kw)
    grid = np.linspace(0.0, t_end, 2001)
    for name in ("u", "v", "energy"):
        a = rw_fmu.on_grid(two["time"], two[name], grid)
        b = rw_fmu.on_grid(three["time"], three[name], grid)
        scale = np.max(np.abs(a))
        print(f"{fmi_type} {name}: max |FMI 3.0 - FMI 2.0| = {np.max(np.abs(a - b)):.2e} of peak {scale:.3e}")
        assert scale > 0
        assert np.max(np.abs(a - b)) <= 1e-3 * scale


def test_fmpy_rhs_without_inputs_hits_the_fmi3_path_too(fmi3_dir):
    """fmpy's CVodeSolver.f is shared by its FMI 2.0 and FMI 3.0 Model Exchange loops: without
    rockingwall.fmu's workaround the FMI 3.0 FMU sees lagged inputs as well (same case as
    tests/python/test_fmpy_known_issues.py)."""
    fmu = fmi3_dir / "RockingWall.fmu"
    signal = inputs.sampled(inputs.gaussian(0.04, 1.0), 6.0, 0.002)
    kw = dict(support="simplySupported", hinge_law="rigid", rtol=1e-6, output_interval=0.01)
    plain = rw_fmu.simulate(fmu, 6.0, signal.t, signal.a, fmpy_input_fix=False, **kw)
    fixed = rw_fmu.simulate(fmu, 6.0, signal.t, signal.a, **kw)
    ref = simulate(Params(support="simplySupported", hinge_law="rigid"), signal, 6.0,
                   method="DOP853", rtol=1e-9, atol=1e-12)
    err_fixed = abs(fixed.peak_s1 - ref.peak_s1) / ref.peak_s1
    err_plain = abs(plain.peak_s1 - ref.peak_s1) / ref.peak_s1
    print(f"FMI 3.0 peak s1: reference {ref.peak_s1:.6f}, fmpy+fix {fixed.peak_s1:.6f} ({err_fixed:.1e}), "
          f"plain fmpy {plain.peak_s1:.6f} ({err_plain:.1e})")
    assert err_fixed < 1e-3
    assert err_plain > 0.01, "plain fmpy now agrees on FMI 3.0: fmpy applies inputs in f"


def _slave(fmu, tmp_path, name):
    md = read_model_description(str(fmu))
    slave = FMU3Slave(guid=md.guid, unzipDirectory=extract(str(fmu), str(tmp_path / name)),
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
    slave.instantiate()
    return slave, {v.name: v.valueReference for v in md.modelVariables}


def _steps(slave, vr, t, n, step=0.05):
    out = []
    for _ in range(n):
        slave.doStep(t, step)
        t += step
        out.append(slave.getFloat64([vr["s1"], vr["energy"]]))
    return t, np.array(out)


@pytest.mark.parametrize("support", [1, 3])  # parapet: CVODE inside the FMU; flexibleTop: the exact engine
def test_fmi3_fmu_state_rolls_a_co_simulation_back_bitwise(fmi3_dir, tmp_path, support):
    """fmi3GetFMUState / fmi3SetFMUState and (de)serialization through fmpy: the steps taken after
    restoring a state repeat the steps taken after saving it, bit for bit, in the same instance and
    in a second instance that deserialized it."""
    fmu = fmi3_dir / "RockingWall.fmu"
    a, vr = _slave(fmu, tmp_path, "a")
    a.setInt32([vr["support"]], [support])
    a.setFloat64([vr["q1"]], [0.02])
    a.enterInitializationMode(tolerance=1e-8, startTime=0.0)
    a.exitInitializationMode()
    a.setFloat64([vr["ag"]], [0.3 if support == 3 else 0.0])  # the parapet rocks freely (0.3 topples it)
    t, _ = _steps(a, vr, 0.0, 10)
    state = a.getFMUState()
    serialized = a.serializeFMUState(state)
    _, first = _steps(a, vr, t, 20)
    a.setFMUState(state)
    _, again = _steps(a, vr, t, 20)
    b, _ = _slave(fmu, tmp_path, "b")
    b.enterInitializationMode(tolerance=1e-8, startTime=0.0)
    b.exitInitializationMode()
    b.setFMUState(b.deserializeFMUState(serialized))
    _, elsewhere = _steps(b, vr, t, 20)
    print(f"support {support}: s1 after the rollback {again[-1, 0]:.9e}, energy {again[-1, 1]:.9e}")
    assert np.ptp(first[:, 0]) > 1e-4, "the wall must move over the steps compared"
    assert np.array_equal(first, again) and np.array_equal(first, elsewhere)
    a.freeFMUState(state)
    for s in (a, b):
        s.terminate()
        s.freeInstance()


def test_co_simulation_event_mode_through_fmpy_changes_nothing(fmi3_dir):
    """With eventModeUsed fmpy enters Event Mode after initialization and at every input change
    (fmi3EnterEventMode, fmi3UpdateDiscreteStates, fmi3EnterStepMode); the steps handle their own
    events, so the run must equal the one without Event Mode, and must move."""
    t = np.linspace(0.0, 2.0, 201)
    table = np.zeros(len(t), dtype=[("time", np.float64), ("ag", np.float64), ("u_top", np.float64)])
    table["time"], table["ag"] = t, 0.5 * np.sin(6.0 * t)
    kw = dict(stop_time=2.0, start_values={"q1": 0.01, "support": 1}, output=["s1", "impacts"],
              fmi_type="CoSimulation", input=table, output_interval=0.01)
    with_events = simulate_fmu(str(fmi3_dir / "RockingWall.fmu"), use_event_mode=True, **kw)
    without = simulate_fmu(str(fmi3_dir / "RockingWall.fmu"), **kw)
    print(f"parapet: {with_events['impacts'][-1]} impacts, final s1 {with_events['s1'][-1]:.9e}")
    assert with_events["impacts"][-1] > 0
    grid = np.linspace(0.0, 2.0, 201)
    assert np.array_equal(rw_fmu.on_grid(with_events["time"], with_events["s1"], grid),
                          rw_fmu.on_grid(without["time"], without["s1"], grid))

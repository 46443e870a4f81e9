"""The stability limit of the co-simulated building (rockingwall.coupling.step_map,
linear_models, rules.scene_stability, building.limits; docs/building-coupling.md "The limit"):

- the linear models are the FMUs' own equations: RockingWall's and the Building's rates and
  outputs by central differences at rest equal the models' matrices;
- the sharp limits of the base exchange come out of the step map as the recurrences written by
  hand here predict: a_(n+2) = -r a_n with held inputs (r < 1), z^4 + r (2z - 1)^2 = 0 with
  ramped ones (r < 0.1547);
- real runs of the master grow at the rate the map predicts, and hold where it says they hold;
- the plot's legend and colours.
"""
import ctypes
import shutil

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Model

from rockingwall.building import limits
from rockingwall.coupling import linear_models, rules, step_map

UPPER = dict(h=3.6, b=0.23, W=14904.0, psi=0.2013)


class MEProbe:
    """One Model-Exchange instance at rest in continuous-time mode with the given parameters."""

    def __init__(self, path, reals, integers):
        self.md = read_model_description(str(path))
        self.dir = extract(str(path))
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.f = f = FMU2Model(guid=self.md.guid, unzipDirectory=self.dir,
                               modelIdentifier=self.md.modelExchange.modelIdentifier, instanceName="probe")
        self.nx = len(self.md.derivatives)
        f.instantiate()
        f.setupExperiment(startTime=0.0)
        f.enterInitializationMode()
        f.setReal([self.vars[k].valueReference for k in reals], list(reals.values()))
        f.setInteger([self.vars[k].valueReference for k in integers], list(integers.values()))
        f.exitInitializationMode()
        while f.newDiscreteStates()[0]:
            pass
        f.enterContinuousTimeMode()

    def evaluate(self, x, inputs, outputs):
        xs = (ctypes.c_double * self.nx)(*x)
        self.f.setContinuousStates(xs, self.nx)
        self.f.setReal([self.vars[k].valueReference for k in inputs], list(inputs.values()))
        dx = (ctypes.c_double * self.nx)()
        self.f.getDerivatives(dx, self.nx)
        return np.array(list(dx)), np.array(self.f.getReal([self.vars[k].valueReference for k in outputs]))

    def jacobians(self, state_index, input_names, outputs, eps):
        """(A, B, C, D) over the states of state_index by central differences at rest."""
        n = len(state_index)
        zero_u = {k: 0.0 for k in input_names}

        def at(dxs, dus):
            x = np.zeros(self.nx)
            x[state_index] = dxs
            d, y = self.evaluate(x, dict(zero_u, **dus), outputs)
            return d[state_index], y

        cols_x = []
        for j in range(n):
            e = np.zeros(n)
            e[j] = eps
            (dp, yp), (dm, ym) = at(e, {}), at(-e, {})
            cols_x.append(((dp - dm) / (2 * eps), (yp - ym) / (2 * eps)))
        cols_u = []
        for k in input_names:
            (dp, yp), (dm, ym) = at(np.zeros(n), {k: 1.0}), at(np.zeros(n), {k: -1.0})
            cols_u.append(((dp - dm) / 2, (yp - ym) / 2))
        A = np.array([c[0] for c in cols_x]).T
        C = np.array([c[1] for c in cols_x]).T
        B = np.array([c[0] for c in cols_u]).T
        D = np.array([c[1] for c in cols_u]).T
        return A, B, C, D

    def close(self):
        self.f.terminate()
        self.f.freeInstance()
        shutil.rmtree(self.dir, ignore_errors=True)


def assert_close(mine, fmu, what):
    scale = max(np.abs(fmu).max(), 1e-300)
    assert np.abs(mine - fmu).max() < 1e-6 * scale, (what, mine, fmu)


@pytest.mark.parametrize("law", [3, 4])
def test_linear_wall_is_the_fmus_equations_at_rest(build_dir, law):
    params = dict(UPPER, Kd=2e6)
    probe = MEProbe(build_dir / "RockingWall.fmu", params, {"support": 3, "hingeLaw": law})
    try:
        A, B, C, D = probe.jacobians([0, 1, 2, 3], ["ag", "u_top"], ["F_top", "F_base"], 1e-7)
    finally:
        probe.close()
    s = linear_models.wall_slave("w", params, law)
    for mine, fmu, what in ((s.A, A, "A"), (s.B, B, "B"), (s.C, C, "C"), (s.D, D, "D")):
        assert_close(mine, fmu, what)
    # the effective mass on the base is -dF_base/d ag
    assert linear_models.base_mass(params, law) == pytest.approx(-D[1, 0], rel=1e-9)


def test_linear_building_is_the_fmus_equations_at_rest(build_dir):
    values = {"m_1": 3000.0, "k_1": 2e7, "md_1": 600.0, "kd_1": 6e4, "cd_1": 700.0, "cs_1": 5e3,
              "m_2": 2500.0, "k_2": 1.5e7, "md_2": 200.0, "kd_2": 2e4, "cd_2": 300.0, "cs_2": 4e3,
              "rayleighMass": 0.3, "rayleighStiffness": 2e-3}
    probe = MEProbe(build_dir / "Building.fmu", values, {"nStoreys": 2, "storeyLaw": 0, "diaphragmLaw": 0})
    index = [0, 3, 8, 11, 1, 4, 9, 12]  # u_1, y_1, u_2, y_2 and their rates in the FMU's state vector
    s = linear_models.building_slave("b", values, 2)
    try:
        A, B, C, D = probe.jacobians(index, s.inputs, s.outputs, 1e-6)
    finally:
        probe.close()
    for mine, fmu, what in ((s.A, A, "A"), (s.B, B, "B"), (s.C, C, "C"), (s.D, D, "D")):
        assert_close(mine, fmu, what)


def hand_ramped_limit():
    """The ratio at which a root of z^4 + r (2z - 1)^2 leaves the unit circle: the base exchange
    with only its algebraic parts (F_base = -m_b a, a = F/m_d) and the master's extrapolated slopes,
    each input read at the end of the step (2 v_n - v_(n-1))."""
    lo, hi = 1e-3, 1.0
    for _ in range(60):
        r = 0.5 * (lo + hi)
        grows = max(abs(np.roots([1, 0, 4 * r, -4 * r, r]))) > 1
        lo, hi = (lo, r) if grows else (r, hi)
    return lo


def test_sharp_limits_of_the_base_exchange():
    assert hand_ramped_limit() == pytest.approx(0.1547, abs=1e-4)
    # held: the sharp limit shows where the diaphragm's 5 % damping covers the weak negative damping
    # the delay adds to the wall's own modes (the table's other row); ramped: with or without it
    assert limits.ratio_limit(1e-4, 1, damped=True) == pytest.approx(1.0, rel=0.01)
    for H in (1e-4, 1e-3):
        assert limits.ratio_limit(H, 2, damped=False) == pytest.approx(hand_ramped_limit(), rel=0.01)


def test_the_assessors_building_is_past_the_limit_and_a_light_one_is_not(repo):
    from rockingwall.building import building_file, cosim, scene
    heavy = cosim.scene_of(building_file.read(repo / "examples" / "two-storey-brick.toml"))
    st = rules.scene_stability(heavy, 1e-3, 2)
    upper = st.walls[1]
    assert not st.stable and not upper.base_holds
    assert upper.ratio == pytest.approx(linear_models.base_mass(UPPER) / 600.0)
    assert "storey 2" in st.cause() and "0.36 times" in st.cause()
    light = scene.default_scene(2)   # the paper's wall 1 on diaphragms of 2000 kg/m: m_b/m_d = 0.048
    assert rules.scene_stability(light, 1e-3, 2).stable


@pytest.mark.parametrize("order, H, ratio", [(2, 1e-3, 0.13), (2, 1e-3, 0.18), (1, 2.5e-4, 1.25)])
def test_runs_of_the_master_grow_as_the_step_map_predicts(order, H, ratio):
    run = limits.measure_run(order, H, ratio, seconds=0.6)
    if run.stable:
        assert run.predicted_sigma <= 1e-9
        assert run.measured_sigma < 10.0  # the record's own build-up, no exponential growth
    else:
        assert run.predicted_sigma > 40.0
        assert run.measured_sigma == pytest.approx(run.predicted_sigma, rel=0.02)


def test_limits_plot_legend_and_colours(tmp_path):
    table = {(o, d): [0.1 + 0.01 * k for k in range(len(limits.STEPS_MS))] for o, d, _, _ in limits.CURVES}
    runs = [limits.Run(2, 1e-3, 0.13, 0.0, 1.0, True), limits.Run(2, 1e-3, 0.18, 57.0, 57.0, False)]
    fig = limits.plot(table, runs, tmp_path / "l.png", assessor=0.36)
    ax = fig.axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert labels == [c[2] for c in limits.CURVES] + [limits.RUN_LABELS[True], limits.RUN_LABELS[False],
                                                      limits.ASSESSOR_LABEL]
    colours = {line.get_label(): matplotlib_colour(line.get_color()) for line in ax.get_lines()}
    curve_colours = [colours[c[2]] for c in limits.CURVES]
    assert len(set(curve_colours)) == len(curve_colours)
    assert colours[limits.RUN_LABELS[True]] != colours[limits.RUN_LABELS[False]]
    assert colours[limits.RUN_LABELS[True]] == matplotlib_colour(limits.RUN_COLOURS[True])
    assert (tmp_path / "l.png").stat().st_size > 10_000


def matplotlib_colour(c):
    from matplotlib.colors import to_hex
    return to_hex(c)


def test_step_map_of_a_held_exchange_by_hand():
    """Two slaves without states that pass their input on (y = g u), joined in a loop: the inputs
    of step k are the outputs read after step k - 1, so u_(k+1) = g1 g2 u_(k-1) and the map's
    eigenvalues are +-sqrt(g1 g2)."""
    a = step_map.LinearSlave("a", np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)), np.array([[0.5]]), ["in"], ["out"])
    b = step_map.LinearSlave("b", np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)), np.array([[-8.0]]), ["in"], ["out"])
    S = step_map.jacobi_step_map([a, b], [("a", "out", "b", "in"), ("b", "out", "a", "in")], 1e-3, 1)
    assert max(abs(np.linalg.eigvals(S))) == pytest.approx(2.0)


def test_limits_command_writes_its_plot_where_it_is_told(tmp_path, capsys):
    """`rockingwall couple-building --limits` wrote its plot into the package's source tree
    (docs/img/building_coupling_limits.png, two folders above the package): a user's command
    changed the documentation, and an installed package has no such folder. It writes into
    --out (default results/) now; the document's figure is the one written with --out docs/img."""
    import pathlib
    from rockingwall.commands import couple_building
    docs_png = pathlib.Path(couple_building.__file__).resolve().parents[3] / "docs" / "img" / "building_coupling_limits.png"
    before = docs_png.stat().st_mtime_ns if docs_png.exists() else None
    assert couple_building.main(["--limits", "--out", str(tmp_path / "out")]) == 0
    assert (tmp_path / "out" / "building_coupling_limits.png").stat().st_size > 10000
    assert str(tmp_path / "out" / "building_coupling_limits.png") in capsys.readouterr().out
    assert (docs_png.stat().st_mtime_ns if docs_png.exists() else None) == before

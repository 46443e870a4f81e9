"""Safety of the wall-diaphragm coupling (rockingwall.coupling.wall_diaphragm, rockingwall.coupling.rules,
rockingwall.coupling.monolithic, docs/coupling.md): the macro-step rule of the tie, the energy check,
and the monolithic run (both FMUs as Model Exchange under one CVODE) as the independent result.

The stiff case is an engineer's top-storey wall (b = 0.23 m, h = 3.2 m, W = 14 080 N/m, psi = 0.2)
tied by K_d = 1e6 N/m per m to a diaphragm of 400 kg/m on 30 kN/m per m, under El Centro at
0.15 g for 5 s (the strong motion)."""
import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rockingwall.commands import couple as couple_command
from rockingwall.coupling import monolithic, wall_diaphragm
from rockingwall.coupling import rules as coupling_rules
from rwref.inputs import el_centro

STIFF_WALL = {"b": 0.23, "h": 3.2, "W": 14080.0, "psi": 0.2}
STIFF_ARGS = ["--set=b=0.23", "--set=h=3.2", "--set=W=14080", "--set=psi=0.2", "--Kd=1e6", "--m=400",
              "--k=30e3", "--scale=0.4705", "--t-end=5", "--rtol=1e-8"]   # 0.4705 x El Centro: 0.15 g


@pytest.fixture(scope="module")
def fmus(build_dir):
    return build_dir / "RockingWall.fmu", build_dir / "Diaphragm.fmu"


def run_cli(fmus, tmp_path, name, extra, capsys):
    """`rockingwall couple` on the stiff case; (exit status, summary dict, stderr)."""
    out = tmp_path / f"{name}.csv"
    status = couple_command.main([f"--wall-fmu={fmus[0]}", f"--diaphragm-fmu={fmus[1]}", f"--out={out}",
                          f"--plot={tmp_path / name}.png"] + STIFF_ARGS + extra)
    err = capsys.readouterr().err
    return status, json.loads(out.with_suffix(".json").read_text()), err


@pytest.fixture(scope="module")
def monolithic_stiff(fmus):
    """The stiff case under one CVODE: the reference of the co-simulation runs."""
    sig = el_centro(0.4705)
    wall = wall_diaphragm.wall_start_values(1, 1e6, overrides=STIFF_WALL)
    return monolithic.run_monolithic(*fmus, np.asarray(sig.t), np.asarray(sig.a), 5.0, wall,
                                            {"m": 400.0, "k": 30e3, "zeta": 0.05}, rtol=1e-8, output_interval=1e-3)


def held_input_scheme_growth(m_w, m_d, Kd, H, n_steps=400):
    """The amplitude growth per step of couple.py's Jacobi scheme on two masses joined by Kd,
    stepped by solve_ivp with the inputs held over each step exactly as the master does (wall's top
    on the spring to the held u, diaphragm under the held force, F = Kd (s2(t+H) - u(t)) after
    the step): fitted from the energy of the tie over n_steps steps."""
    s2, v2, u, v, F = 1e-3, 0.0, 0.0, 0.0, Kd * 1e-3
    energies = []
    for _ in range(n_steps):
        wall = solve_ivp(lambda t, y: [y[1], -Kd / m_w * (y[0] - u)], (0, H), [s2, v2], rtol=1e-11, atol=1e-15)
        dia = solve_ivp(lambda t, y: [y[1], F / m_d], (0, H), [u, v], rtol=1e-11, atol=1e-15)
        s2_new, v2 = wall.y[:, -1]
        F = Kd * (s2_new - u)
        s2, (u, v) = s2_new, dia.y[:, -1]
        energies.append(0.5 * m_w * v2 ** 2 + 0.5 * m_d * v ** 2 + 0.5 * Kd * (s2 - u) ** 2)
    # the energy oscillates within a tie period; compare its means over the first and last quarters
    q = n_steps // 4
    return (np.mean(energies[-q:]) / np.mean(energies[:q])) ** (1.0 / (2 * (n_steps - q)))


@pytest.mark.parametrize("ratio", [0.1, 1.0, 10.0])
def test_step_map_growth_matches_the_stepped_scheme(ratio):
    """The spectral radius of coupling_rules.jacobi_step_map (matrix exponential) is the growth per
    step that stepping the scheme by an ODE solver gives, within 0.3 % of rho - 1; rho - 1 scales
    with H^2 (no step is free of it: the documented alpha (omega_t H)^2)."""
    m_d, Kd = 400.0, 1e6
    m_w = ratio * m_d
    omega_t = coupling_rules.tie_frequency(m_w, m_d, Kd, 0.0)
    H = 0.05 / omega_t
    rho = max(abs(np.linalg.eigvals(coupling_rules.jacobi_step_map(m_w, m_d, Kd, 0.0, 0.0, H))))
    measured = held_input_scheme_growth(m_w, m_d, Kd, H)
    assert rho - 1 > 0
    assert measured - 1 == pytest.approx(rho - 1, rel=0.05)
    rho_half = max(abs(np.linalg.eigvals(coupling_rules.jacobi_step_map(m_w, m_d, Kd, 0.0, 0.0, H / 2))))
    assert (rho - 1) / (rho_half - 1) == pytest.approx(4.0, rel=0.02)


def test_rule_step_meets_its_bound_and_scales_with_the_tie():
    """max_macro_step gives the step where the scheme's negative damping reaches ZETA_NUM_MAX
    (within 1 %), and a tie 100 times stiffer needs a step about 10 times smaller (the sqrt(m/K)
    law, within 20 %: the diaphragm's own spring shifts it slightly)."""
    m_w = coupling_rules.wall_top_mass(14080.0, 0.2, 3.2)
    H = coupling_rules.max_macro_step(m_w, 400.0, 1e6, 30e3)
    assert coupling_rules.numerical_damping(m_w, 400.0, 1e6, 30e3, 0.0, H) == pytest.approx(
        coupling_rules.ZETA_NUM_MAX, rel=0.01)
    H_stiff = coupling_rules.max_macro_step(m_w, 400.0, 1e8, 30e3)
    assert H / H_stiff == pytest.approx(10.0, rel=0.2)


def test_wall_top_mass_of_two_slender_bodies():
    """Two uniform slender bodies of mass m each, hinged at mid-height: the mass at the top is
    7 m / 24 (by hand from the bodies' kinetic energy, hinge free to move)."""
    W, g = 6622.0, 9.81
    assert coupling_rules.wall_top_mass(W, 0.0, 2.5, g) == pytest.approx(7.0 / 24.0 * W / 2.0 / g, rel=1e-12)


def test_stiff_tie_at_the_old_1_ms_step_is_flagged(fmus, tmp_path, capsys):
    """Before: the stiff tie at H = 1 ms ran silently to a result whose energy residual was 28 %
    of the ground work (exit 0, no warning). Now the step is reported above the tie's limit, the
    energy check fails on stderr and in the summary, and --strict exits with 3."""
    status, info, err = run_cli(fmus, tmp_path, "coarse", ["--macro-step=1e-3", "--strict"], capsys)
    assert status == couple_command.EXIT_FLAGGED
    assert "exceeds the step the tie allows" in err and "ENERGY CHECK FAILED" in err
    assert info["step_ok"] is False and info["energy_ok"] is False and info["flagged"] is True
    assert info["energy_residual_share"] > 0.1


def test_stiff_tie_default_step_agrees_with_the_monolithic_run(fmus, tmp_path, capsys, monolithic_stiff):
    """Without --macro-step the master takes the tie's step: energy residual within 1 % of the
    ground work and peaks within 1 % of the monolithic run (no macro step at all), which itself
    keeps its energy to 1e-5 of the ground work."""
    status, info, err = run_cli(fmus, tmp_path, "auto", ["--strict"], capsys)
    assert status == 0, err
    assert info["macro_step"] <= info["macro_step_limit"] * (1 + 1e-9) and info["energy_ok"], info
    mono = monolithic_stiff
    share, ok = coupling_rules.energy_check(mono.energy_residual(), mono.ground_work(), 1e-5)
    assert ok, share
    for key, col in [("peak_s1", "wall_s1"), ("peak_s2", "wall_s2"), ("peak_u", "dia_u")]:
        assert info[key] == pytest.approx(np.abs(mono[col]).max(), rel=0.01), key


def test_monolithic_agrees_with_co_simulation_at_a_small_step(fmus):
    """The README's case (wall 1, K_d = 1e5, diaphragm 2000 kg/m on 7e5 N/m per m, El Centro x 0.5,
    10 s): the monolithic run and the fmpy master at H = 62.5 us agree in the peaks of s1, s2, u
    and F_top within 0.5 %."""
    sig = el_centro(0.5)
    t_in, ag_in = np.asarray(sig.t), np.asarray(sig.a)
    wall, dia = wall_diaphragm.wall_start_values(1, 1e5), {"m": 2000.0, "k": 7e5, "zeta": 0.05}
    mono = monolithic.run_monolithic(*fmus, t_in, ag_in, 10.0, wall, dia, rtol=1e-8, output_interval=1e-3)
    cosim = wall_diaphragm.run_fmpy(*fmus, t_in, ag_in, 10.0, 62.5e-6, wall, dia, rtol=1e-8)
    for col in ("wall_s1", "wall_s2", "dia_u", "wall_F_top"):
        assert np.abs(mono[col]).max() == pytest.approx(np.abs(cosim[col]).max(), rel=0.005), col
    assert mono["collapsed_at"] is None and mono["wall_dissipated"][-1] > 0  # it rocked and impacted


def test_monolithic_collapse_ends_the_run_like_the_co_simulation(fmus):
    """A wall that collapses: the monolithic run stops at the FMU's terminateSimulation, within
    2 % of the time the fmpy master at a small step sees the wall's fmi2Discard."""
    sig = el_centro(0.35 / 0.312987481555883)  # the stiff case at 0.35 g collapses
    t_in, ag_in = np.asarray(sig.t), np.asarray(sig.a)
    wall = wall_diaphragm.wall_start_values(1, 1e5, overrides=STIFF_WALL)
    dia = {"m": 400.0, "k": 30e3, "zeta": 0.05}
    mono = monolithic.run_monolithic(*fmus, t_in, ag_in, 10.0, wall, dia, rtol=1e-8)
    cosim = wall_diaphragm.run_fmpy(*fmus, t_in, ag_in, 10.0, 50e-6, wall, dia, rtol=1e-8)
    assert cosim["collapsed_at"] is not None
    assert mono["collapsed_at"] == pytest.approx(cosim["collapsed_at"], rel=0.02)


@pytest.mark.parametrize("args, message", [
    (["--monolithic", "--master=libcosim"], "--monolithic runs one CVODE"),
    (["--energy-share=0"], "--energy-share 0.0 must be a positive number"),
    (["--energy-share=nan"], "--energy-share nan must be a positive number"),
    (["--set=b"], "--set 'b': expected NAME=VALUE"),
    (["--set=bb=0.2"], "'bb' is not a Real parameter of RockingWall"),
    (["--set=hingeLaw=3"], "'hingeLaw' is not a Real parameter of RockingWall"),
    (["--set=W=14.08kN/m/m"], "unit 'kN/m/m' is not a unit of W"),
    (["--set=b=-0.2"], "b = -0.2 m: must be in"),
])
def test_bad_safety_options_are_refused(tmp_path, capsys, args, message):
    assert couple_command.main(["--t-end=0.5", f"--out={tmp_path / 'c.csv'}"] + args) == 2
    assert message in capsys.readouterr().err


def test_set_reads_units_as_every_other_command():
    """`couple --set` took bare numbers only (W=14.08kN/m was refused), unlike --set elsewhere."""
    assert wall_diaphragm.parse_settings(["W=14.08kN/m", "b = 230mm", "psi=0.2"]) == pytest.approx(
        {"W": 14080.0, "b": 0.23, "psi": 0.2})
    assert wall_diaphragm.parse_settings(["W=14080"]) == {"W": 14080.0}


def test_energy_check_share():
    assert coupling_rules.energy_check(np.array([0.0, 0.5, -2.0]), np.array([0.0, 100.0, 200.0])) == (0.01, True)
    assert coupling_rules.energy_check(np.array([0.0, 2.1]), np.array([0.0, 200.0]))[1] is False
    share, ok = coupling_rules.energy_check(np.array([0.0, 1.0]), np.array([0.0, 0.0]))
    assert math.isinf(share) and not ok


def test_the_plot_names_its_record_and_scene(fmus, tmp_path, capsys, figures):
    """couple's plot was titled 'Wall 1 + diaphragm (m = 2000 kg/m, k = 700 kN/m per m, zeta = 0.05),
    K_d = 100 kN/m per m, monolithic': no record, no intensity, and not the scene's words that
    `couple` prints. Its title now names the record as run and the scene."""
    out = tmp_path / "c.csv"
    assert couple_command.main([f"--wall-fmu={fmus[0]}", f"--diaphragm-fmu={fmus[1]}", f"--out={out}",
                                f"--plot={tmp_path / 'c.png'}", "--monolithic", "--t-end", "2"]) == 0
    scene = json.loads(out.with_suffix(".json").read_text())["scene"]["description"]
    (fig,) = figures
    title = " ".join(fig._suptitle.get_text().split())
    assert title.startswith("El Centro 1940 x0.5, wall 1, monolithic"), title
    assert f"scene: {scene}" in title and scene in capsys.readouterr().out

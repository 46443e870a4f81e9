"""A stiff tie costs the Model Exchange FMU what the held wall costs: where the tie is far stiffer
than the wall (fmu_src/wall/rw_rigid_tie.c), the FMU holds it rigid instead of making every
importer resolve its oscillation. Before, fmi2sim took 125 times the steps at K_d = 1e12 that it
took at 5e4 on El Centro x0.5 (dohertyHinge), in proportion to sqrt(K_d). Checked here: the steps,
the peaks against the exact engine (which solves the tie's mode exactly whatever K_d), the tie's
force, FMI 3.0 in fmpy, and that a driven far end (u_top) turns the holding off."""
import dataclasses
import re
import subprocess
import tempfile

import numpy as np
import pytest

import stability_cases as sc
from rockingwall import engine
from rockingwall import fmu as rw_fmu

LAW_NUMBER = {"semiRigidPaper": 2, "semiRigidHinge": 3, "dohertyHinge": 4}
EL_CENTRO = sc.Case("El Centro x0.5", "flexibleTop", "dohertyHinge", record="elcentro", amp_g=0.5, duration=35.0,
                    rtol=1e-8)


def _fmi2sim(exe, fmu, case):
    with tempfile.TemporaryDirectory() as wd:
        return sc.run_fmi2sim(exe, fmu, case, sc.signal(case), wd)


def _exact(case):
    sig = sc.signal(case)
    return engine.run(sig.t, sig.a, t_end=case.duration, support=3, hingeLaw=LAW_NUMBER[case.law], **case.params)


def _exact_peak_s1(case):
    return _exact(case).peak_s1


@pytest.mark.parametrize("law", ["dohertyHinge", "semiRigidHinge", "semiRigidPaper"])
def test_finding_19_a_stiff_tie_costs_what_a_soft_one_costs(fmi2sim_exe, rockingwall_fmu, law):
    soft = dataclasses.replace(EL_CENTRO, law=law, Kd=5e4)
    rigid = dataclasses.replace(EL_CENTRO, law=law, Kd=1e12)
    _, soft_steps, _, _ = _fmi2sim(fmi2sim_exe, rockingwall_fmu, soft)
    out, rigid_steps, _, _ = _fmi2sim(fmi2sim_exe, rockingwall_fmu, rigid)
    peak, peak_s2 = float(np.max(np.abs(out["s1"]))), float(np.max(np.abs(out["s2"])))
    exact = _exact(rigid)
    print(f"{law}: steps {soft_steps} at K_d = 5e4, {rigid_steps} at 1e12; peak s1 {peak:.8g} m, "
          f"exact engine {exact.peak_s1:.8g} m ({abs(peak - exact.peak_s1) / exact.peak_s1:.1e}); peak s2 (the tie's "
          f"deflection) {peak_s2:.4g} m, exact {exact.peak_s2:.4g} m")
    assert rigid_steps <= 1.5 * soft_steps
    # the stability matrix's 500 rtol at fmi2sim's 1e-8 is 5e-6, plus what holding the tie changes
    assert abs(peak - exact.peak_s1) <= 1e-5 * exact.peak_s1
    # s2 of the held tie is its quasi-static deflection F_top/K_d; the exact engine's adds the tie's ringing
    assert abs(peak_s2 - exact.peak_s2) <= 0.02 * exact.peak_s2


def _fmi2sim_steps(exe, fmu, case, solver, workdir):
    sig = sc.signal(case)
    inp = workdir / f"in_{case.Kd:g}.csv"
    np.savetxt(inp, np.column_stack([sig.t, sig.a]), delimiter=",", header="time,ag", comments="", fmt="%.17g")
    args = [str(exe), str(fmu), "--input", str(inp), "--stop-time", repr(case.duration), "--solver", solver, "--stats"]
    for name, v in rw_fmu.start_values(**case.start_values).items():
        args += ["--set", f"{name}={v!r}" if isinstance(v, float) else f"{name}={v}"]
    proc = subprocess.run(args, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    return int(re.search(r"steps (\d+)", proc.stderr).group(1))


@pytest.mark.parametrize("solver", ["adams", "erk"])
def test_non_stiff_solvers_take_a_stiff_tie_too(fmi2sim_exe, rockingwall_fmu, tmp_path, solver):
    """An importer with a non-stiff (Adams) or explicit (Runge-Kutta) solver had to step at the
    tie's period: 1.36 million and 437 000 steps on 10 s at K_d = 1e12, against 8 234 and 11 022 at 5e4."""
    soft = dataclasses.replace(EL_CENTRO, Kd=5e4, duration=10.0)
    rigid = dataclasses.replace(soft, Kd=1e12)
    n_soft = _fmi2sim_steps(fmi2sim_exe, rockingwall_fmu, soft, solver, tmp_path)
    n_rigid = _fmi2sim_steps(fmi2sim_exe, rockingwall_fmu, rigid, solver, tmp_path)
    print(f"{solver}: {n_soft} steps at K_d = 5e4, {n_rigid} at 1e12")
    assert n_rigid <= 1.5 * n_soft


def test_the_held_ties_force_is_the_full_models(fmi2sim_exe, rockingwall_fmu):
    """F_top of the held tie is the constraint's reaction: on the same record it matches the full
    model's spring force at a tie stiff enough to follow it closely and not yet held (3e9: its
    50-ms means differ by 0.3 N/m of 425; at 1e9 the slower ringing leaves 8)."""
    held = dataclasses.replace(EL_CENTRO, Kd=1e12, duration=6.0)
    full = dataclasses.replace(held, Kd=3e9)
    a, _, _, _ = _fmi2sim(fmi2sim_exe, rockingwall_fmu, held)
    b, _, _, _ = _fmi2sim(fmi2sim_exe, rockingwall_fmu, full)
    grid = np.arange(0.0, held.duration, 0.002)  # the outputs hold event rows too: one grid for both
    fa, fb = np.interp(grid, a["time"], a["F_top"]), np.interp(grid, b["time"], b["F_top"])
    scale = float(np.max(np.abs(fb)))
    assert scale > 100.0  # N/m: the tie carries a real force
    # the full model's spring rings at its own frequency after each impact: compare on a running mean
    kernel = np.ones(25) / 25
    diff = np.convolve(fa - fb, kernel, mode="valid")
    print(f"peak F_top {scale:.1f} N/m; largest difference of the 50-ms means {np.max(np.abs(diff)):.3g} N/m")
    assert np.max(np.abs(diff)) <= 0.01 * scale


def test_a_driven_far_end_is_not_held(fmi2sim_exe, rockingwall_fmu, tmp_path):
    """u_top is 0 at the start (the tie is held) and then moves: the tie transmits it, so the FMU
    must stop holding it, and its answer is the exact engine's with the same u_top."""
    case = dataclasses.replace(EL_CENTRO, Kd=1e11, duration=5.0)
    sig = sc.signal(case)
    t = sig.t[sig.t <= case.duration]
    ag = sig.a[: t.size]
    u_top = 0.002 * np.sin(2 * np.pi * 2.0 * t)
    inp, out = tmp_path / "in.csv", tmp_path / "out.csv"
    np.savetxt(inp, np.column_stack([t, ag, u_top]), delimiter=",", header="time,ag,u_top", comments="", fmt="%.17g")
    args = []
    for name, v in rw_fmu.start_values(**case.start_values).items():
        args += ["--set", f"{name}={v!r}" if isinstance(v, float) else f"{name}={v}"]
    proc = subprocess.run([str(fmi2sim_exe), str(rockingwall_fmu), "--input", str(inp), "--stop-time", "5",
                           "--output-interval", "0.002", "--output", str(out)] + args, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    data = np.genfromtxt(out, delimiter=",", names=True)
    exact = engine.run(t, ag, u_top=u_top, t_end=5.0, support=3, hingeLaw=4, **case.params)
    peak = float(np.max(np.abs(data["s2"])))
    print(f"peak s2 {peak:.6g} m (fmi2sim), {exact.peak_s2:.6g} m (exact engine)")
    assert peak > 1e-3  # the top follows u_top: not held at zero
    assert abs(peak - exact.peak_s2) <= 1e-3 * exact.peak_s2


@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_fmpy_holds_the_tie_in_both_fmi_versions(build_dir, version):
    """fmpy's own Model Exchange loop (CVode) at K_d = 1e12: it failed with "mxstep steps taken"
    at tight tolerances before; now it agrees with the exact engine."""
    fmu = build_dir / ("RockingWall.fmu" if version == "2.0" else "fmi3/RockingWall.fmu")
    case = dataclasses.replace(EL_CENTRO, Kd=1e12, duration=10.0)
    sig = sc.signal(case)
    run = rw_fmu.simulate(fmu, case.duration, sig.t, sig.a, rtol=1e-8, output_interval=0.002,
                          support="flexibleTop", hinge_law=case.law, **case.params)
    exact = _exact_peak_s1(case)
    print(f"FMI {version}: peak s1 {run.peak_s1:.8g} m, exact engine {exact:.8g} m, impacts {run.impacts}")
    assert abs(run.peak_s1 - exact) <= 1e-4 * exact


@pytest.mark.parametrize("Kd", [1e11, 1e12])
def test_the_rigid_law_rocks_in_fmpy_at_a_stiff_tie(rockingwall_fmu, fmi2sim_exe, Kd):
    """The rigid law at a stiff tie: fmpy gave a peak of 3e-9 m (1e11) or gave up (1e12) where the
    wall rocks to 0.607 mm, chattering between its closed-hinge states against the tie. Held, its
    hinges rest and open together as a mechanism, and both hosts give the stiff limit: the simply
    supported rigid wall, which the exact engine solves."""
    case = dataclasses.replace({c.name: c for c in sc.matrix()}["2dof-rigid Kd=1e+12"], Kd=Kd)
    sig = sc.signal(case)
    limit = engine.run(sig.t, sig.a, t_end=case.duration, support=2, hingeLaw=1, **case.params).peak_s1
    run = rw_fmu.simulate(rockingwall_fmu, case.duration, sig.t, sig.a, rtol=1e-6, output_interval=0.002,
                          **case.start_values)
    out, steps, _, _ = _fmi2sim(fmi2sim_exe, rockingwall_fmu, case)
    peak = float(np.max(np.abs(out["s1"])))
    print(f"K_d {Kd:g}: fmpy {run.peak_s1:.7g} m, fmi2sim {peak:.7g} m ({steps} steps), stiff limit {limit:.7g} m")
    assert abs(run.peak_s1 - limit) <= 1e-3 * limit
    assert abs(peak - limit) <= 1e-3 * limit

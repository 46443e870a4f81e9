"""The exact event-driven engine (fmu_src/engine/ via rockingwall.engine) against fmi2sim.
The engine on its own: test_engine_alone.py; inside the FMU's Co-Simulation: test_cosim_engine.py.

Random scenes (tests/python/engine_scenes.py): the same collapse outcome and impact count, and
peaks within 1e-5, against fmi2sim at rtol 1e-10; where the two disagree, fmi2sim at rtol 1e-12
is run too (with --max-step 1e-4, so that its peaks are not sampled low by long steps) and the
engine must sit within what separates the two CVODE runs (the spread CVODE itself shows, which for
the chaotic rigid 2DOF is the only meaningful yardstick).

Two measurement effects of fmi2sim are accounted for, not hidden:
- its peak is a maximum over solver steps and output rows, so a peak of s2 under a stiff spring
  (s2 ~ 1e-9 m, oscillating faster than the steps) is sampled low: peaks are compared to 1e-5 of
  the larger of the two peaks of the scene;
- after a collapse the FMU runs RW_TERMINATE_DELAY = 1e-6 s further: the tolerance of a collapsed
  scene's peaks adds 1e-6 s times the engine's velocity at the collapse.
Impacts: when the raw counts differ, counts are compared on the impacts at an energy above 1e-6
of the run's largest (amplitudes above 1e-3 of the peak), from fmi2sim's event rows. Below that
are the impacts of a wall settling to rest: the elastic laws' last crossings at rotations of
~1e-13 rad (the size of the hinge indicators' offsets, below what CVODE resolves) and the rigid
2DOF's chatter near rest, where a 1e-12 relative perturbation changes the count (CVODE's own
counts differ between rtol 1e-10 and 1e-12 there, e.g. scene 68: 80 and 77, the engine 95). An
impact within a factor 3 of that cut-off counts either way: the engine's count must lie between
fmi2sim's above 3e-6 and above 3.3e-7 of the largest. In a long chatter tail the count at a sharp
cut-off moves with any rounding: scene 736 (rigid, K_d = 1e12 N/m per m) counts 159 in the engine,
165 with the record scaled by 1 + 1e-10, 168 and 172 in CVODE at rtol 1e-10 and 1e-12, while the
engine's impact times agree with CVODE's at 1e-12 to 1e-6 s over the first 100 of them (CVODE's
at 1e-10 are off by 1e-4 s).
"""
import os
import subprocess
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import engine_scenes as es
from engine_scenes import PEAK_RTOL, engine_run
from rwref import inputs


# The random scenes: seeds 0-199 and what the longer study found (scripts/engine_study.sh, seeds
# 200-1199) in every test run: 361, semiRigidPaper under a 1e12 spring (the kink of its Q at q1 = 0
# was no breakpoint); 651, a wall without a spring that collapses as its base leaves the elastic
# range; 736, a rigid wall's long chatter (the impact count at its cut-off). The study runs the
# range FIRST:LAST of RW_ENGINE_SCENES instead, with the same checks.
STUDY_FINDINGS = (361, 651, 736)


# and 40 scenes of walls with NZSEE C8's statics (engine_scenes.STATICS_SEEDS): capacities and
# breakpoints that differ between the hinges' sides
SCENES = (range(*(int(v) for v in os.environ["RW_ENGINE_SCENES"].split(":"))) if os.environ.get("RW_ENGINE_SCENES")
          else [*range(200), *STUDY_FINDINGS, *range(es.STATICS_SEEDS, es.STATICS_SEEDS + 40)])


TERMINATE_DELAY = 1e-6




SIGNIFICANT = 1e-6  # of the largest impact energy


BORDERLINE = 3.0  # an impact within this factor of the cut-off may count either way


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    return tmp_path_factory.mktemp("engine")


def impact_energies_fmi2sim(exe, fmu, sc, rtol, workdir):
    """The energy just before each impact, from fmi2sim's event rows."""
    csv = workdir / f"in{sc['seed']}.csv"
    out = workdir / f"h{sc['seed']}_{rtol:g}.csv"
    args = [str(exe), str(fmu), "--input", str(csv), "--rtol", f"{rtol:g}", "--stop-time", f"{sc['t_end']:.17g}",
            "--output-interval", f"{sc['t_end']:.17g}", "--output", str(out)]
    for k, v in sc["params"].items():
        args += ["--set", f"{k}={v:.17g}" if isinstance(v, float) else f"{k}={v}"]
    subprocess.run(args, check=True, capture_output=True, timeout=600)
    d = np.genfromtxt(out, delimiter=",", names=True)
    steps = np.nonzero(np.diff(d["impacts"]) > 0)[0]
    return d["energy"][steps]


def counts_around(energies, e_cut):
    """Impacts above BORDERLINE x e_cut, above e_cut, and above e_cut / BORDERLINE."""
    return tuple(int(np.sum(energies > e)) for e in (BORDERLINE * e_cut, e_cut, e_cut / BORDERLINE))


def peak_tolerance(r, sc, cv):
    scale = max(cv["peak_s1"], cv["peak_s2"], r.peak_s1, r.peak_s2)
    tol = PEAK_RTOL * scale
    if r.collapsed:
        h = sc["params"]["h"]
        v1, v2 = r.x_end[2], r.x_end[3]
        tol += 1.5 * TERMINATE_DELAY * h / 2 * max(abs(v1), abs(v1 + v2))
    return tol


def compare(r, sc, cv, e_sig_engine, sig_cv, spread=None):
    """Messages of what disagrees (empty: agreement)."""
    bad = []
    if r.collapsed != cv["collapsed"]:
        bad.append(f"collapse engine {r.collapsed} fmi2sim {cv['collapsed']}")
        return bad
    tol = peak_tolerance(r, sc, cv)
    for k in ("peak_s1", "peak_s2"):
        extra = spread[k] if spread else 0.0
        if abs(getattr(r, k) - cv[k]) > tol + 2 * extra:
            bad.append(f"{k} engine {getattr(r, k):.12g} fmi2sim {cv[k]:.12g} (tol {tol:.3g} + 2x spread {extra:.3g})")
    if r.collapsed:
        t_cv = cv["end_time"] - TERMINATE_DELAY
        extra = spread["t_collapse"] if spread else 0.0
        if abs(r.t_collapse - t_cv) > 1e-6 * max(1.0, t_cv) + 2 * extra:
            bad.append(f"collapse time engine {r.t_collapse:.12g} fmi2sim {t_cv:.12g}")
    if r.impacts != cv["impacts"]:
        strict, cut, loose = sig_cv()
        extra = spread["impacts"] if spread else 0
        if not strict - 2 * extra <= e_sig_engine <= loose + 2 * extra:
            bad.append(f"impacts engine {r.impacts} ({e_sig_engine} significant) fmi2sim {cv['impacts']} "
                       f"({cut} significant, {strict} to {loose} with the borderline ones), spread {extra}")
    return bad


@pytest.fixture(scope="module")
def fmi2sim_runs(fmi2sim_exe, rockingwall_fmu, workdir):
    """fmi2sim at rtol 1e-10 on every scene, two processes at a time (the machine's two cores)."""
    def one(seed):
        return es.fmi2sim(fmi2sim_exe, rockingwall_fmu, es.scene(seed), 1e-10, workdir)
    with ThreadPoolExecutor(2) as pool:
        return dict(zip(SCENES, pool.map(one, SCENES)))


@pytest.mark.parametrize("seed", SCENES)
def test_random_scene_against_fmi2sim(seed, fmi2sim_exe, rockingwall_fmu, workdir, fmi2sim_runs):
    sc = es.scene(seed)
    r = engine_run(sc)
    cv10 = fmi2sim_runs[seed]
    # the energy scale of the run: the largest energy at an impact (kinetic at q1 = 0)
    e_max = max([1e-300] + list(np.abs(r.impact_energy)))
    e_sig = int(np.sum(r.impact_energy > SIGNIFICANT * e_max))
    cache = {}

    def sig(rtol):
        if rtol not in cache:
            energies = impact_energies_fmi2sim(fmi2sim_exe, rockingwall_fmu, sc, rtol, workdir)
            cache[rtol] = counts_around(energies, SIGNIFICANT * e_max)
        return cache[rtol]

    bad = compare(r, sc, cv10, e_sig, lambda: sig(1e-10))
    if not bad:
        return
    # second opinion: CVODE at 1e-12, and the spread between the two CVODE runs
    try:
        cv12 = es.fmi2sim(fmi2sim_exe, rockingwall_fmu, sc, 1e-12, workdir, max_step=1e-4)
    except subprocess.CalledProcessError:  # CVODE may refuse 1e-12 on a stiff scene: the next best
        cv12 = es.fmi2sim(fmi2sim_exe, rockingwall_fmu, sc, 1e-11, workdir, max_step=1e-4)
    spread = {k: abs(cv10[k] - cv12[k]) for k in ("peak_s1", "peak_s2")}
    spread["t_collapse"] = abs(cv10["end_time"] - cv12["end_time"])
    spread["impacts"] = abs(sig(1e-10)[1] - sig(1e-12)[1]) if r.impacts != cv12["impacts"] else 0
    bad12 = compare(r, sc, cv12, e_sig, lambda: sig(1e-12), spread)
    assert not bad12, f"scene {seed} ({sc['label']}, {sc['params']}): " + "; ".join(bad12)


# ---- named cases ----------------------------------------------------------------------------------

def el_centro_csv(workdir, scale=0.5):
    sig = inputs.el_centro(scale)
    path = workdir / f"elcentro{scale:g}.csv"
    np.savetxt(path, np.c_[sig.t, sig.a], delimiter=",", header="time,ag", comments="", fmt="%.17g")
    return sig, path


@pytest.mark.parametrize("law", [3, 4])
def test_grazing_case_el_centro_kd_10914(law, fmi2sim_exe, rockingwall_fmu, workdir):
    """K_d = 10914.9 N/m per m under El Centro 50 %: a trajectory that touches a breakpoint. The
    engine must neither loop (Zeno stop) nor pick the wrong region (it would drift from CVODE)."""
    sig, _ = el_centro_csv(workdir)
    sc = dict(seed=9000 + law, t=sig.t, ag=sig.a, t_end=float(sig.t[-1]), label="El Centro 50 % grazing",
              params=dict(support=3, hingeLaw=law, Kd=10914.9))
    r = engine_run(sc)
    # no event storm: at most 50 events per second of record (930 events in the record for
    # law 3); a loop at the breakpoint would give thousands at one instant. (Impacts are no
    # yardstick: the semi-rigid laws count only the crossings after an uplift.)
    assert r.events < 50 * sc["t_end"]
    cv = es.fmi2sim(fmi2sim_exe, rockingwall_fmu, sc, 1e-12, workdir)
    assert r.collapsed == cv["collapsed"] and r.impacts == cv["impacts"]
    scale = max(cv["peak_s1"], cv["peak_s2"])
    assert abs(r.peak_s1 - cv["peak_s1"]) <= PEAK_RTOL * scale
    assert abs(r.peak_s2 - cv["peak_s2"]) <= PEAK_RTOL * scale


def test_collapse_time_against_cvode(fmi2sim_exe, rockingwall_fmu, workdir):
    sig, _ = el_centro_csv(workdir, 1.5)
    sc = dict(seed=9100, t=sig.t, ag=sig.a, t_end=20.0, label="El Centro 150 %",
              params=dict(support=3, hingeLaw=4, Kd=5e4))
    r = engine_run(sc)
    cv = es.fmi2sim(fmi2sim_exe, rockingwall_fmu, sc, 1e-12, workdir)
    assert r.collapsed and cv["collapsed"]
    assert r.t_collapse == pytest.approx(cv["end_time"] - TERMINATE_DELAY, abs=1e-7)

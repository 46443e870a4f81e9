"""Where `rockingwall assess` spends its time, and the fragility fits before and after they were
vectorised, in one run.

The assessor's wall (b = 230 mm, h = 3.6 m, W = 14.904 kN/m, psi = 0.2013, dohertyHinge):
- the 16-case study: FEMA P695 ff13a, ff07a, ff03a, ff19a x K_d 20, 200 kN/m per m x PGA 0.3,
  0.5 g: the nominal runs, the ensembles (100 members per case), the fits (3 limit states x 2
  K_d, 200 bootstrap resamples each) by the Newton fits of rockingwall.sweep.fragility and by the
  Nelder-Mead fits they replaced (written out below as the reference);
- the large study: the 44 FEMA P695 far-field components x 10 PGAs (0.1-1.0 g) x K_d 20, 50, 200,
  1000 kN/m per m (1 760 nominal runs, no ensembles): the fits over the records, and over the
  records and the members (the same tables with one member each: the fit's cost does not depend
  on the members' number); the Nelder-Mead fits timed on one of the 12 and multiplied by 12.
- the building: `rockingwall assess --building examples/two-storey-brick.toml fema` at 10 PGAs
  (0.1-1.0 g), `--ensemble 0` (440 runs of the two-storey building, 880 rows), the whole command
  as a user runs it (records read, runs, fits, plots and files written) on at most 2 cores,
  against its target of 60 s; and the same house with Bouc-Wen diaphragms (yield force 2.2 kN/m,
  post-yield 0.1) beside it.
Wall-clock times on a shared machine: read the ratios. The fits' results are compared too.

    .venv/bin/python scripts/bench_assess.py [--skip-large] [--building-only]
"""
import argparse
import os
import pathlib
import subprocess
import sys
import tempfile
import time
import types

import numpy as np
from scipy import optimize, stats

import rockingwall as rw
from rockingwall import assessment, ensemble, limits
from rockingwall.sweep import suites

WALL = dict(b=0.23, h=3.6, W=14904.0, psi=0.2013)
REPO = pathlib.Path(__file__).resolve().parents[1]
BUILDING = REPO / "examples" / "two-storey-brick.toml"
BUILDING_TARGET_S = 60.0
BOUC_WEN = ', law = "boucWen", yield_force = "2.2 kN/m", post_yield = 0.1 }'  # the diaphragms' law, edited in
CORES = 2


def nelder_mead_fit(im, exceeded):
    levels = np.unique(im)
    n = np.array([np.sum(im == x) for x in levels])
    z = np.array([np.sum(exceeded[im == x]) for x in levels])
    if z.sum() in (0, n.sum()):
        return None

    def nll(p):
        prob = np.clip(stats.norm.cdf((np.log(levels) - p[0]) / np.exp(p[1])), 1e-12, 1 - 1e-12)
        return -np.sum(z * np.log(prob) + (n - z) * np.log1p(-prob))
    res = optimize.minimize(nll, x0=[np.log(levels[np.argmin(np.abs(z / n - 0.5))]), np.log(0.4)],
                            method="Nelder-Mead", options=dict(xatol=1e-8, fatol=1e-10, maxiter=4000))
    return np.exp(res.x[0]), np.exp(res.x[1])


def nelder_mead_bootstrap(im, exceeded, records, n_boot=200, seed=1):
    im, exceeded, records = np.asarray(im, float), np.asarray(exceeded, bool), np.asarray(records)
    names = np.unique(records)
    rng = np.random.default_rng(seed)
    by_record = {n: np.flatnonzero(records == n) for n in names}
    fits = [nelder_mead_fit(im, exceeded)]
    for _ in range(n_boot):
        pick = np.concatenate([by_record[n] for n in rng.choice(names, size=len(names), replace=True)])
        fits.append(nelder_mead_fit(im[pick], exceeded[pick]))
    return fits


def old_fragilities(cases, states, only=None):
    jobs = [(d, name) for _, d in cases.groupby(assessment.KD_COLUMN) for name in [s.name for s in states] + ["collapsed"]]
    for d, name in jobs[:only]:
        nelder_mead_bootstrap(d.im, d[name], d.record)
    return len(jobs[:only])


def clock(f):
    t = time.perf_counter()
    value = f()
    return time.perf_counter() - t, value


def study(recs, kds, pgas, size):
    wall = rw.Wall.make(**WALL, Kd=kds[0], warn=False)
    walls = {kd: wall.replace(Kd=kd) for kd in kds}
    states = limits.parse_all(None, wall)
    args = types.SimpleNamespace(pga=pgas, sa=None, scale=None, sa_period=None, engine="exact")
    lvs = assessment.levels(recs, args)
    t_runs, (cases, _) = clock(lambda: assessment.run_cases(walls, lvs, args, states))
    t_ens, outcomes = None, None
    if size:
        t_ens, (_, outcomes) = clock(lambda: assessment.run_cases(walls, lvs, args, states,
                                                                   ensemble.Ensemble(size=size)))
    return cases, states, outcomes, t_runs, t_ens


def small():
    fema = {r.name: r.path for r in suites.fema_farfield(suites.fema_cache())}
    recs = [rw.read_at2(fema[n]) for n in ("ff13a", "ff07a", "ff03a", "ff19a")]
    cases, states, outcomes, t_runs, t_ens = study(recs, [20e3, 200e3], [0.3, 0.5], 100)
    t_new, frag = clock(lambda: assessment.fragilities(cases, states))
    t_both, _ = clock(lambda: assessment.fragilities(cases, states, outcomes=outcomes))
    t_old, n_old = clock(lambda: old_fragilities(cases, states))
    print(f"16-case study: nominal runs {t_runs:.2f} s, ensembles (100 members per case) {t_ens:.2f} s")
    print(f"  fragility, {len(frag)} fits over the records: Newton {t_new:.3f} s, Nelder-Mead {t_old:.1f} s "
          f"({n_old} fits): {t_old / t_new:.0f} times faster")
    print(f"  fragility over the records and over the records and the members ({2 * len(frag)} fits): {t_both:.3f} s")
    check = cases[cases[assessment.KD_COLUMN] == 200]
    print(f"  K_d 200, 0.6 Delta_u: Newton median {frag.iloc[3]['median']:.6g} beta {frag.iloc[3]['beta']:.6g}; "
          f"Nelder-Mead {nelder_mead_fit(check.im.to_numpy(), check['0.6 Delta_u'].to_numpy())}")


def large():
    recs = [rw.read_at2(r.path) for r in suites.fema_farfield(suites.fema_cache())]
    kds = [20e3, 50e3, 200e3, 1000e3]
    pgas = [round(0.1 * k, 1) for k in range(1, 11)]
    cases, states, _, t_runs, _ = study(recs, kds, pgas, 0)
    members = [{name: np.array([bool(row[name])]) for name in [s.name for s in states] + ["collapsed"]}
               for row in cases.to_dict("records")]
    t_new, frag = clock(lambda: assessment.fragilities(cases, states))
    t_both, _ = clock(lambda: assessment.fragilities(cases, states, outcomes=members))
    t_one_old, _ = clock(lambda: old_fragilities(cases, states, only=1))
    print(f"{len(recs)} records x {len(pgas)} PGAs x {len(kds)} K_d: {len(cases)} nominal runs {t_runs:.2f} s")
    print(f"  fragility, {len(frag)} fits over the records: Newton {t_new:.3f} s; over the records and over the "
          f"records and the members ({2 * len(frag)} fits): {t_both:.3f} s")
    print(f"  Nelder-Mead: {t_one_old:.1f} s for one fit, about {12 * t_one_old:.0f} s for the 12: "
          f"{12 * t_one_old / t_new:.0f} times the Newton fits")


def two_cores():
    """Pins the child to the first CORES processors this process may use (where the OS allows it)."""
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, sorted(os.sched_getaffinity(0))[:CORES])


def assess_building(path):
    """`rockingwall assess --building path fema` at 10 PGAs, --ensemble 0, on CORES cores: its
    wall-clock seconds"""
    pgas = [f"{0.1 * k:.1f}" for k in range(1, 11)]
    with tempfile.TemporaryDirectory() as out:
        command = [sys.executable, "-m", "rockingwall", "assess", "--building", str(path), "fema",
                   "--pga", *pgas, "--ensemble", "0", "--out", out]
        start = time.perf_counter()
        done = subprocess.run(command, capture_output=True, text=True, preexec_fn=two_cores)
        seconds = time.perf_counter() - start
    if done.returncode:
        raise SystemExit(f"assess --building failed:\n{done.stderr[-2000:]}")
    return seconds


def building():
    seconds = assess_building(BUILDING)
    verdict = f"met, {BUILDING_TARGET_S / seconds:.1f} times under" if seconds <= BUILDING_TARGET_S else "MISSED"
    print(f"assess --building {BUILDING.relative_to(REPO)}: 44 records x 10 PGAs (440 building runs), "
          f"--ensemble 0, {CORES} cores: {seconds:.1f} s wall-clock against the target of "
          f"{BUILDING_TARGET_S:.0f} s ({verdict})")
    with tempfile.TemporaryDirectory() as folder:
        bouc_wen = pathlib.Path(folder) / "bouc-wen.toml"
        bouc_wen.write_text(BUILDING.read_text().replace("damping = 0.05 }", "damping = 0.05" + BOUC_WEN))
        hysteretic = assess_building(bouc_wen)
    print(f"the same with Bouc-Wen diaphragms ({BOUC_WEN.strip(', }')}): {hysteretic:.1f} s wall-clock "
          f"({hysteretic / seconds:.1f} times the linear house's)")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--skip-large", action="store_true", help="without the large study")
    p.add_argument("--building-only", action="store_true", help="only the building's assessment")
    a = p.parse_args()
    if not a.building_only:
        small()
        if not a.skip_large:
            large()
    building()


if __name__ == "__main__":
    main()

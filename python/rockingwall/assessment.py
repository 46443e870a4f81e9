"""A wall's assessment: one wall under records at several intensities and diaphragm stiffnesses
(or the walls of a building, assessment_building.py), the peaks, s1/Delta_u and the limit states
reached per case with the case's robustness (an ensemble), a fragility per limit state with its
uncertainty, and IDA 'resurrections' (the logic of `rockingwall assess`)."""
import concurrent.futures
import dataclasses
import os
import sys

import numpy as np
import pandas as pd
from tqdm import tqdm

from . import ensemble as ens
from . import intensity, outputs, records, robustness
from .api import simulate
from .sweep import fragility

KD_COLUMN = "Kd_kN_per_m_per_m"


def load_records(specs, csv_units):
    out = []
    for spec in specs:
        if spec == "fema":
            from .sweep import suites
            out += [records.read_at2(r.path) for r in suites.fema_farfield(suites.fema_cache())]
        else:
            out.append(records.load(spec, units=csv_units))
            outputs.protect(records.split_spec(spec)[0], "the record")
    names = [r.name for r in out]
    if len(set(names)) != len(names):
        raise ValueError(f"records with the same name: {sorted({n for n in names if names.count(n) > 1})}")
    return out


def scale_factor(record, args, level, sa_record):
    """(factor on the record for this intensity level, IM value of the level); sa_record is the
    record's own Sa(T) (scaling the record scales it)."""
    if args.pga:
        return level * intensity.G / record.pga, level
    if args.sa:
        return level / sa_record, level
    return level, record.pga * level / intensity.G


@dataclasses.dataclass(frozen=True)
class Level:
    """One record at one intensity level: the scaled record, its IM, PGA [g] and Sa [g]."""
    name: str
    level: float
    im: float
    record: records.Record
    sa_g: float


def levels(recs, args):
    """Every record at every intensity level the command asks for."""
    out = []
    for rec in recs:
        sa_record = intensity.sa(rec, args.sa_period) if args.sa_period else np.nan  # once per record
        for level in args.pga or args.sa or args.scale:
            factor, im = scale_factor(rec, args, level, sa_record)
            out.append(Level(rec.name, level, im, rec.scaled(factor), sa_record * factor))
    return out


def case_row(lv, group, scene_key, peaks, t_collapse, impacts, delta_u, states, summary):
    """One row of cases.csv: the nominal run (peaks in SI; a collapsed wall's peaks left empty,
    its collapse time given) and its ensemble's summary (None without one)."""
    collapsed = bool(peaks["collapsed"])
    row = dict(record=lv.name, level=lv.level, im=lv.im, pga_g=lv.record.pga / intensity.G, sa_g=lv.sa_g, **group,
               scene=scene_key, peak_s1_mm=np.nan if collapsed else peaks["peak_s1"] * 1e3,
               peak_s2_mm=np.nan if collapsed else peaks["peak_s2"] * 1e3,
               peak_F_top_kN_per_m=np.nan if collapsed else peaks["peak_F_top"] / 1e3,
               s1_over_Delta_u=np.nan if collapsed else peaks["peak_s1"] / delta_u,
               collapsed=collapsed, t_collapse_s=t_collapse if collapsed else np.nan, impacts=impacts,
               **{s.name: s.exceeded(peaks) for s in states})
    if summary is not None:
        row.update(collapse_probability=summary.collapse_probability,
                   **{f"s1_p{p}_mm": v * 1e3 for p, v in zip((16, 50, 84), summary.s1_percentiles)},
                   **{f"p_{name}": p for name, p in summary.limit_probabilities.items()},
                   flips=summary.flips, ensemble_failed=summary.failed)
    return row


def run_cases(walls, lvs, args, states, ensemble=None, diaphragm=None, tie=None):
    """walls: {K_d: Wall} (K_d None for a wall without the top spring), lvs: levels(). One row per record,
    intensity level and K_d, and the ensemble outcomes of each row (ensemble.reached) for the fragility over
    the records and the members. diaphragm, tie: the scene of a diaphragm with mass (its
    stiffness is each K_d)."""
    tasks = [(lv, kd, wall) for lv in lvs for kd, wall in walls.items()]

    def one(task):
        lv, kd, wall = task
        d = dataclasses.replace(diaphragm, stiffness=kd) if diaphragm is not None else None
        r = simulate(wall, lv.record, engine=args.engine, diaphragm=d, tie=tie)
        peaks = dict(peak_s1=r.peak_s1, peak_s2=r.peak_s2, peak_F_top=r.peak_F_top, collapsed=r.collapsed)
        summary, outcome = None, None
        if ensemble is not None:
            members = robustness.members(wall.params, lv.record, float(lv.record.t[-1]), ensemble, d, tie, states)
            summary = ens.summarize(members, states, robustness.nominal_outcome(states, peaks))
            outcome = ens.reached(members, states)
        group = {KD_COLUMN: kd / 1e3 if kd is not None else np.nan}
        row = case_row(lv, group, r.scene.key, peaks, r.t_collapse, r.impacts, wall.delta_u, states, summary)
        return [(row, outcome)]

    return collect(run_parallel(one, tasks, threads=args.engine == "exact"))


def collect(results):
    """(cases DataFrame, [ensemble outcomes of each row, or None]) from the tasks' row lists."""
    pairs = [pair for rows in results for pair in rows]
    return pd.DataFrame([row for row, _ in pairs]), [outcome for _, outcome in pairs]


def run_parallel(one, tasks, threads=True):
    """one(task) for every task, in order, with a progress bar; on threads (the engines release
    the GIL) unless threads is False."""
    workers = min(4, os.cpu_count() or 1) if threads else 1
    with tqdm(total=len(tasks), desc="runs", unit="case", file=sys.stderr, delay=2) as bar, \
            concurrent.futures.ThreadPoolExecutor(workers) as pool:
        futures = [pool.submit(one, t) for t in tasks]
        for f in futures:
            f.result()
            bar.update()
        return [f.result() for f in futures]


def groups(cases, column):
    """(value, rows) per group of the column (K_d or storey), NaN as one group."""
    if column not in cases or cases[column].isna().all():
        return [(np.nan, cases)]
    return list(cases.groupby(column))


def fragilities(cases, states, column=KD_COLUMN, outcomes=None):
    """A fit per group and limit state (and collapse) over the records; with the ensembles'
    outcomes, a second one over the records and the members together."""
    out = []
    names = [s.name for s in states] + ["collapsed"]
    jobs = [(value, d, name) for value, d in groups(cases, column) for name in names]
    for value, d, name in tqdm(jobs, desc="fragility", unit="fit", file=sys.stderr, delay=2):
        what = "collapse" if name == "collapsed" else name
        fits = [("records", fragility.fit_with_uncertainty(d.im, d[name], d.record, what=what))]
        if outcomes and all(outcomes[i] is not None and name in outcomes[i] for i in d.index):
            fits.append(("records and parameters", fragility.fit_tables(*member_tables(d, name, column, outcomes),
                                                                       what=what)))
        for over, est in fits:
            f = est.fit
            gap = f.gap if f and f.gap else (np.nan, np.nan)  # the data do not overlap: the median is in it
            out.append({column: value, "limit_state": name, "over": over, "records": est.n_records,
                        "median": f.theta if f else np.nan, "median_5": est.theta_90[0],
                        "median_95": est.theta_90[1], "beta": f.beta if f else np.nan, "beta_5": est.beta_90[0],
                        "beta_95": est.beta_90[1], "gap_lo": gap[0], "gap_hi": gap[1],
                        "warnings": " | ".join(est.warnings)})
    return pd.DataFrame(out)


def member_tables(d, name, column, outcomes):
    """(levels, runs, reached): records x levels tables of the ensembles' members of a group
    (outcomes: one per row of the cases, by the cases' index)."""
    names = sorted(d.record.unique())
    lv = np.unique(d.im.to_numpy())
    n = np.zeros((len(names), lv.size))
    z = np.zeros((len(names), lv.size))
    for index, record, im in zip(d.index, d.record, d.im):
        outcome = outcomes[index][name]
        i, j = names.index(record), int(np.searchsorted(lv, im))
        n[i, j] += outcome.size
        z[i, j] += outcome.sum()
    return lv, n, z


def resurrection_lines(cases, column=KD_COLUMN):
    lines = []
    for value, d in groups(cases, column):
        for rec, dr in d.groupby("record"):
            back = fragility.resurrections(dr.im.to_numpy(), dr.collapsed.to_numpy())
            if back:
                where = f", {group_label(column, value)}" if np.isfinite(value) else ""
                lines.append(f"{rec}{where}: collapses, then stands again at IM {', '.join(f'{x:g}' for x in back)}")
    return lines


def group_label(column, value):
    if column == KD_COLUMN:
        return f"K_d = {value:g} kN/m per m"
    return f"storey {int(value)}"

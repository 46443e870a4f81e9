"""A wall's assessment: one wall under records at several intensities and diaphragm stiffnesses,
the peaks, s1/Delta_u and the limit states reached per case, a fragility per limit state with its
uncertainty, and IDA 'resurrections' (the logic of `rockingwall assess`)."""
import sys

import numpy as np
import pandas as pd
from tqdm import tqdm

from . import intensity, outputs, records, units
from .api import simulate
from .sweep import fragility


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


def run_cases(walls, recs, args, states):
    """walls: {K_d: Wall}. One row per record, intensity level and K_d."""
    levels = args.pga or args.sa or args.scale
    rows = []
    with tqdm(total=len(recs) * len(levels) * len(walls), desc="runs", unit="run", file=sys.stderr) as bar:
        for rec in recs:
            sa_record = intensity.sa(rec, args.sa_period) if args.sa_period else np.nan  # once per record
            for level in levels:
                factor, im = scale_factor(rec, args, level, sa_record)
                case = rec.scaled(factor)
                for kd, wall in walls.items():
                    r = simulate(wall, case, engine=args.engine)
                    peaks = dict(peak_s1=r.peak_s1, peak_s2=r.peak_s2, peak_F_top=r.peak_F_top, collapsed=r.collapsed)
                    rows.append(dict(record=rec.name, level=level, im=im, pga_g=case.pga / intensity.G,
                                     sa_g=sa_record * factor, Kd_kN_per_m_per_m=kd / 1e3,
                                     peak_s1_mm=r.peak_s1 * 1e3, peak_s2_mm=r.peak_s2 * 1e3,
                                     peak_F_top_kN_per_m=r.peak_F_top / 1e3, s1_over_Delta_u=r.s1_over_delta_u,
                                     collapsed=r.collapsed, impacts=r.impacts,
                                     **{s.name: s.exceeded(peaks) for s in states}))
                    bar.update()
    return pd.DataFrame(rows)


def fragilities(cases, states):
    out = []
    for kd, d in cases.groupby("Kd_kN_per_m_per_m"):
        for name in [s.name for s in states] + ["collapsed"]:
            est = fragility.fit_with_uncertainty(d.im, d[name], d.record)
            f = est.fit
            out.append(dict(Kd_kN_per_m_per_m=kd, limit_state=name, records=est.n_records,
                            median=f.theta if f else np.nan, median_5=est.theta_90[0], median_95=est.theta_90[1],
                            beta=f.beta if f else np.nan, beta_5=est.beta_90[0], beta_95=est.beta_90[1],
                            warnings=" | ".join(est.warnings)))
    return pd.DataFrame(out)


def resurrection_lines(cases):
    lines = []
    for (rec, kd), d in cases.groupby(["record", "Kd_kN_per_m_per_m"]):
        back = fragility.resurrections(d.im.to_numpy(), d.collapsed.to_numpy())
        if back:
            lines.append(f"{rec}, K_d = {kd:g} kN/m per m: collapses, then stands again at IM {', '.join(f'{x:g}' for x in back)}")
    return lines


def report(wall, kds, states, cases, frag, im_name):
    lines = [f"wall: {wall.describe(with_kd=False)}", "K_d: " + ", ".join(units.format_kd(k) for k in kds), f"Delta_u = {wall.delta_u * 1e3:.1f} mm; limit states: "
             + "; ".join(s.describe() for s in states)]
    if len(cases) <= 60:
        lines.append(f"{'record':<22}{'IM':>7}{'K_d kN/m/m':>11}{'s1 mm':>8}{'s2 mm':>8}{'F_top kN/m':>11}"
                     f"{'s1/Du':>7}  limit states reached")
        for r in cases.to_dict("records"):
            reached = [s.name for s in states if r[s.name]] + (["COLLAPSE"] if r["collapsed"] else [])
            lines.append(f"{r['record'][:21]:<22}{r['im']:>7.3g}{r['Kd_kN_per_m_per_m']:>11.4g}{r['peak_s1_mm']:>8.1f}"
                         f"{r['peak_s2_mm']:>8.1f}{r['peak_F_top_kN_per_m']:>11.3g}{r['s1_over_Delta_u']:>7.2f}  "
                         f"{', '.join(reached) or '-'}")
    lines.append(f"\nfragility against {im_name} (lognormal MLE; 90 % bootstrap intervals over the records):")
    for r in frag.itertuples(index=False):
        if np.isnan(r.median):
            lines.append(f"  K_d = {r.Kd_kN_per_m_per_m:g} kN/m per m, {r.limit_state}: no estimate ({r.warnings})")
            continue
        lines.append(f"  K_d = {r.Kd_kN_per_m_per_m:g} kN/m per m, {r.limit_state}: median {r.median:.3g} "
                     f"[{r.median_5:.3g}, {r.median_95:.3g}], beta {r.beta:.2f} [{r.beta_5:.2f}, {r.beta_95:.2f}], "
                     f"{r.records} records")
        if r.warnings:
            lines.append(f"    warning: {r.warnings}")
    back = resurrection_lines(cases)
    if back:
        lines.append(f"\nresurrection (collapse at one intensity, standing at a higher one): {len(back)} record/K_d pairs")
        lines += [f"  {x}" for x in back]
    return "\n".join(lines)

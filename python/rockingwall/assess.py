"""rockingwall assess: one wall under one or more records, at several intensities and diaphragm
stiffnesses; per case the peaks with units, s1/Delta_u, the limit states reached and collapse;
per limit state a fragility with its uncertainty; IDA 'resurrections' reported.

  rockingwall assess --b 230mm --h 3.2 --W 14.08kN/m --psi 0.2 --kd-values 30kN/m/m 100kN/m/m \\
      --pga 0.1 0.2 0.35 0.5 fema --out results/assess

Records: .AT2 or .csv files, 'elcentro', 'gaussian[:D,T]', or 'fema' (the 44 FEMA P695 far-field
components). Intensities: --pga (each record scaled to each PGA, g), --sa with --sa-period (to
each Sa(T, 5 %), g) or --scale (factors on the records as given). Each run lasts its record.
Writes cases.csv, one IDA plot per record (<record>.png), fragility.png and fragility.csv."""
import sys

import numpy as np
import pandas as pd
from tqdm import tqdm

from . import cli_common as cc
from . import intensity, limits, records, units
from .api import ENGINES, simulate
from .sweep import fragility


def parser(sub):
    p = sub.add_parser("assess", help="a wall's assessment: records x intensities x K_d, limit states, fragility",
                       description=__doc__, formatter_class=cc.Parser().formatter_class)
    cc.add_wall_arguments(p)
    p.add_argument("records", nargs="+", help="records: files, elcentro, gaussian[:D,T] or fema")
    p.add_argument("--csv-units", default="g", choices=["g", "m/s2"])
    level = p.add_mutually_exclusive_group(required=True)
    level.add_argument("--pga", type=float, nargs="+", help="target PGAs [g]")
    level.add_argument("--sa", type=float, nargs="+", help="target Sa(T, 5 %%) [g] at --sa-period")
    level.add_argument("--scale", type=float, nargs="+", help="factors on the records as given")
    p.add_argument("--sa-period", type=float, help="T [s] of Sa (e.g. the diaphragm's period); also reported")
    p.add_argument("--kd-values", nargs="+", help="diaphragm stiffnesses (default: the wall's K_d), e.g. 30kN/m/m")
    p.add_argument("--limit", action="append", metavar="'NAME: Q >= VALUE'",
                   help="a limit state (repeatable), Q one of s1, s2, F_top; VALUE e.g. 50mm, 10kN/m, 0.6*Delta_u; "
                        f"checked besides {'; '.join(limits.DEFAULTS)} and collapse")
    p.add_argument("--engine", default="exact", choices=ENGINES)
    p.add_argument("--out", default="results/assess", help="output folder (created if missing)")
    p.set_defaults(command=main)
    return p


def load_records(specs, csv_units):
    out = []
    for spec in specs:
        if spec == "fema":
            from .sweep import suites
            out += [records.read_at2(r.path) for r in suites.fema_farfield(suites.fema_cache())]
        else:
            out.append(records.load(spec, units=csv_units))
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


def main(args):
    wall = cc.wall_from_args(args)
    if args.sa and not args.sa_period:
        raise ValueError("--sa needs --sa-period")
    kds = sorted({units.parse(k, "N/m2", "K_d") for k in args.kd_values}) if args.kd_values else [wall.params["Kd"]]
    walls = {kd: wall.replace(Kd=kd) for kd in kds}  # each K_d checked (range, plausibility) before any run
    states = limits.parse_all(args.limit, wall)
    recs = load_records(args.records, args.csv_units)
    out = cc.output_dir(args.out)
    cases = run_cases(walls, recs, args, states)
    frag = fragilities(cases, states)
    im_name = "PGA [g]" if args.pga else (f"Sa({args.sa_period:g} s) [g]" if args.sa else "PGA [g]")
    cc.write_atomic(out / "cases.csv", lambda tmp: cases.to_csv(tmp, index=False, float_format="%.6g"))
    cc.write_atomic(out / "fragility.csv", lambda tmp: frag.to_csv(tmp, index=False, float_format="%.6g"))
    from . import assess_plots
    for rec in recs:
        cc.write_atomic(out / f"{cc.file_stem(rec.name)}.png",
                        lambda tmp, rec=rec: assess_plots.ida(cases[cases.record == rec.name], wall, states, im_name, tmp))
    cc.write_atomic(out / "fragility.png", lambda tmp: assess_plots.fragility(frag, im_name, tmp))
    print(f"wrote {out}/cases.csv, fragility.csv, fragility.png and {len(recs)} IDA plots", file=sys.stderr)
    print(report(wall, kds, states, cases, frag, im_name))  # last: a closed pipe cannot lose the files
    return 0


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


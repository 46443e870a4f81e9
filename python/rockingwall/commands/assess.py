"""rockingwall assess: one wall under one or more records, at several intensities and diaphragm
stiffnesses; per case the peaks with units, s1/Delta_u, the limit states reached and collapse;
per limit state a fragility with its uncertainty; IDA 'resurrections' reported.

  rockingwall assess --b 230mm --h 3.2 --W 14.08kN/m --psi 0.2 --kd-values 30kN/m/m 100kN/m/m \\
      --pga 0.1 0.2 0.35 0.5 fema --out results/assess

Records: .AT2 or .csv files, 'elcentro', 'gaussian[:D,T]', or 'fema' (the 44 FEMA P695 far-field
components). Intensities: --pga (each record scaled to each PGA, g), --sa with --sa-period (to
each Sa(T, 5 %), g) or --scale (factors on the records as given). Each run lasts its record.
Writes cases.csv, one IDA plot per record (<record>.png), fragility.png, fragility.csv and
manifest.json (the run's files; "complete": true once all are in place). The folder then holds
this run's files only: those of an earlier assessment it does not write again are removed (unless
edited since), other files are left alone."""
import sys

from .. import assessment, limits, units
from ..api import ENGINES
from ..output_folder import MANIFEST, OutputFolder
from . import common as cc


def parser(sub):
    p = sub.add_parser("assess", help="a wall's assessment: records x intensities x K_d, limit states, fragility",
                       description=__doc__, formatter_class=cc.Parser().formatter_class)
    cc.add_wall_arguments(p)
    p.add_argument("records", nargs="+", help="records: files, elcentro, gaussian[:D,T] or fema")
    p.add_argument("--csv-units", default="g", choices=["g", "m/s2"])
    level = p.add_mutually_exclusive_group(required=True)
    level.add_argument("--pga", type=cc.intensity_g, nargs="+", help="target PGAs [g]")
    level.add_argument("--sa", type=cc.intensity_g, nargs="+", help="target Sa(T, 5 %%) [g] at --sa-period")
    level.add_argument("--scale", type=cc.scale_factor, nargs="+", help="factors on the records as given")
    p.add_argument("--sa-period", type=float, help="T [s] of Sa (e.g. the diaphragm's period); also reported")
    p.add_argument("--kd-values", nargs="+", help="diaphragm stiffnesses (default: the wall's K_d), e.g. 30kN/m/m")
    p.add_argument("--limit", action="append", metavar="'NAME: Q >= VALUE'",
                   help="a limit state (repeatable), Q one of s1, s2, F_top; VALUE e.g. 50mm, 10kN/m, 0.6*Delta_u; "
                        f"checked besides {'; '.join(limits.DEFAULTS)} and collapse")
    p.add_argument("--engine", default="exact", choices=ENGINES)
    p.add_argument("--out", default="results/assess", help="output folder (created if missing)")
    p.set_defaults(command=main)
    return p


def output_names(recs):
    return ["cases.csv", "fragility.csv", "fragility.png"] + [f"{cc.file_stem(r.name)}.png" for r in recs]


def write_outputs(out, recs, cases, frag, wall, states, im_name):
    """The tables and plots into the OutputFolder `out`."""
    out.write("cases.csv", lambda tmp: cases.to_csv(tmp, index=False, float_format="%.6g"))
    out.write("fragility.csv", lambda tmp: frag.to_csv(tmp, index=False, float_format="%.6g"))
    from .. import assessment_plots  # matplotlib: imported when the plots are drawn
    for rec in recs:
        out.write(f"{cc.file_stem(rec.name)}.png",
                  lambda tmp, rec=rec: assessment_plots.ida(cases[cases.record == rec.name], wall, states, im_name, tmp))
    out.write("fragility.png", lambda tmp: assessment_plots.fragility(frag, im_name, tmp))


def main(args):
    wall = cc.wall_from_args(args)
    if args.sa and not args.sa_period:
        raise ValueError("--sa needs --sa-period")
    kds = sorted({units.parse(k, "N/m2", "K_d") for k in args.kd_values}) if args.kd_values else [wall.params["Kd"]]
    walls = {kd: wall.replace(Kd=kd) for kd in kds}  # each K_d checked (range, plausibility) before any run
    states = limits.parse_all(args.limit, wall)
    recs = assessment.load_records(args.records, args.csv_units)
    out = OutputFolder(cc.output_dir(args.out), "rockingwall assess")
    out.check(output_names(recs))  # before the runs: no output replaces an input
    cases = assessment.run_cases(walls, recs, args, states)
    frag = assessment.fragilities(cases, states)
    im_name = "PGA [g]" if args.pga else (f"Sa({args.sa_period:g} s) [g]" if args.sa else "PGA [g]")
    with out:  # the folder holds this run's files only, swapped in when all are written
        write_outputs(out, recs, cases, frag, wall, states, im_name)
    print(f"wrote {out.path}/cases.csv, fragility.csv, fragility.png, {MANIFEST} and {len(recs)} IDA plots",
          file=sys.stderr)
    print(assessment.report(wall, kds, states, cases, frag, im_name))  # last: a closed pipe cannot lose the files
    return 0

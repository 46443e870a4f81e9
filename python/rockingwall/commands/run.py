"""rockingwall run: one wall under one or more records; prints the peaks with units, writes a CSV
of the time histories and a plot per record (and --json for programs)."""
import json
import sys

from .. import outputs, run_report
from ..api import ENGINES, simulate
from . import common as cc


def parser(sub=None):
    p = (sub.add_parser if sub else lambda name, **kw: cc.Parser(prog="rockingwall run", **kw))(
        "run", help="simulate one wall under records", description=__doc__)
    cc.add_wall_arguments(p)
    cc.add_record_arguments(p, many=True)
    p.add_argument("--engine", default="exact", choices=ENGINES,
                   help="exact (event-driven, default), fmi2sim (CVODE) or fmpy (the FMU's Model Exchange)")
    p.add_argument("--stop-time", type=float, help="[s] (default: the record's end plus --tail)")
    p.add_argument("--tail", type=float, default=0.0, help="free vibration after the record [s] (default 0)")
    p.add_argument("--rtol", type=float, default=1e-8, help="relative tolerance of fmi2sim and fmpy (default 1e-8)")
    p.add_argument("--out", help="folder for <record>.csv and <record>.png (created if missing)")
    p.add_argument("--json", action="store_true", help="print the results as JSON instead of a table")
    p.set_defaults(command=main)
    return p


def targets(out, recs):
    """[(CSV path, plot path)] per record, checked before any run: no target is an input, no two
    records write one file."""
    files = [tuple(out / f"{cc.file_stem(r.name)}{suffix}" for suffix in (".csv", ".png")) for r in recs]
    outputs.check_targets([p for pair in files for p in pair], "--out")
    return files


def main(args):
    wall = cc.wall_from_args(args)
    recs = [cc.record_from_args(spec, args) for spec in args.records]
    files = targets(cc.output_dir(args.out), recs) if args.out else []
    results = [simulate(wall, rec, engine=args.engine, stop_time=args.stop_time, tail=args.tail, rtol=args.rtol)
               for rec in recs]
    for r, (csv_path, png_path) in zip(results, files):  # files first: a closed pipe on stdout cannot lose them
        cc.write_atomic(csv_path, lambda tmp, r=r: r.history.to_csv(tmp, index=False, float_format="%.9g"))
        cc.write_atomic(png_path, lambda tmp, r=r: run_report.plot(r, tmp))
        print(f"wrote {csv_path} and {png_path}", file=sys.stderr)
    if args.json:
        json.dump({"wall": wall.params, "Delta_u_m": wall.delta_u,
                   "runs": [dict(record=r.record, engine=r.engine, **r.peaks()) for r in results]},
                  sys.stdout, indent=1, default=float)
        print()
    else:
        print(run_report.table(wall, results))
    return 0

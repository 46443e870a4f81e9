"""rockingwall run: one wall under one or more records; prints the peaks with units, writes a CSV
of the time histories and a plot per record (and --json for programs). A wall standing at
0.6 Delta_u or more is named as near collapse: one run is one sample there, and --ensemble N
gives the spread."""
import sys

from tqdm import tqdm

from .. import limits, outputs, run_report, strict_json
from ..api import ENGINES, simulate
from ..units import history_column
from . import common as cc
from .building import run_building


def parser(sub=None):
    p = (sub.add_parser if sub else lambda name, **kw: cc.Parser(prog="rockingwall run", **kw))(
        "run", help="simulate one wall under records", description=__doc__)
    cc.add_wall_arguments(p)
    cc.add_diaphragm_arguments(p)
    p.add_argument("--building", metavar="FILE", help="the walls of the building in FILE (TOML) instead of one wall: "
                   "as `rockingwall building FILE`")
    cc.add_record_arguments(p, many=True)
    p.add_argument("--engine", default="exact", choices=ENGINES,
                   help="exact (event-driven, default), fmi2sim (CVODE) or fmpy (the FMU's Model Exchange)")
    p.add_argument("--stop-time", type=float, help="[s] (default: the record's end plus --tail)")
    p.add_argument("--tail", type=float, default=0.0, help="free vibration after the record [s] (default 0)")
    p.add_argument("--rtol", type=float, default=1e-8, help="relative tolerance of fmi2sim and fmpy (default 1e-8)")
    p.add_argument("--out", help="folder for <record>.csv and <record>.png (created if missing)")
    p.add_argument("--json", action="store_true", help="print the results as JSON instead of a table")
    cc.add_ensemble_arguments(p, default=0)
    cc.add_strict_argument(p)
    p.set_defaults(command=main)
    return p


def targets(out, recs):
    """[(CSV path, plot path)] per record, checked before any run: no target is an input, no two
    records write one file."""
    files = [tuple(out / f"{cc.file_stem(r.name)}{suffix}" for suffix in (".csv", ".png")) for r in recs]
    outputs.check_targets([p for pair in files for p in pair], "--out")
    return files


def main(args):
    if args.building:
        if cc.wall_given(args) or cc.diaphragm_given(args):
            raise ValueError("--building FILE describes the walls and diaphragms: give no wall or diaphragm options")
        return run_building(args.building, args)
    wall = cc.wall_from_args(args)
    diaphragm, tie = cc.diaphragm_from_args(args, wall)
    if diaphragm is not None and args.engine != "exact":
        raise ValueError(f"--engine {args.engine} runs the paper's scene (the top spring to a fixed point); a wall "
                         "under a diaphragm with mass runs on the scene solver: drop --engine or --diaphragm-mass")
    ensemble = cc.ensemble_from_args(args)
    recs = [cc.record_from_args(spec, args) for spec in args.records]
    files = targets(cc.output_dir(args.out), recs) if args.out else []
    slow_note = cc.diaphragm_slow_note(wall, diaphragm, tie)
    if slow_note:
        cc.note(slow_note(len(recs), ensemble))
    results = [simulate(wall, rec, engine=args.engine, stop_time=args.stop_time, tail=args.tail, rtol=args.rtol,
                        diaphragm=diaphragm, tie=tie, ensemble=ensemble)
               for rec in tqdm(recs, desc="records", unit="record", file=sys.stderr, delay=2)]
    for r, (csv_path, png_path) in zip(results, files):  # files first: a closed pipe on stdout cannot lose them
        cc.write_atomic(csv_path, lambda tmp, r=r: r.history.rename(columns=history_column).to_csv(
            tmp, index=False, float_format="%.9g"))
        cc.write_atomic(png_path, lambda tmp, r=r: run_report.plot(r, tmp))
        print(f"wrote {csv_path} and {png_path}", file=sys.stderr)
    if args.json:
        strict_json.dump({"wall": wall.to_dict(), "Delta_u_m": wall.delta_u, "scene": results[0].scene.to_dict(),
                          "notes": {"near_collapse": limits.NEAR_COLLAPSE_NOTE},
                          "runs": [dict(record=r.record, engine=r.engine, pga_g=r.pga_g, **r.peaks(),
                                        **({"ensemble": r.ensemble.to_dict()} if r.ensemble else {}),
                                        **({"peak_sensitivity": r.peak_sensitivity, "sensitive": r.sensitive}
                                           if r.peak_sensitivity is not None else {}),
                                        **({"tie_force": r.tie_force.to_dict()} if r.tie_force else {}))
                                   for r in results]}, sys.stdout)
    else:
        print(run_report.table(wall, results))
    return 0

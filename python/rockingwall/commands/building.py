"""rockingwall building: the walls of a building under records, walls, diaphragms and floors in one
integration. The building file (TOML) gives each storey's wall, diaphragm and tie with units
(docs/your-building.md); prints per storey and record the peaks of s1 and s2 relative to the
wall's own base, s1/Delta_u, collapse and its time, the diaphragm's peak relative to its supports,
the peak absolute acceleration of the floor the wall stands on and the tie's force on the
diaphragm (both filtered at 25 Hz). A wall standing at 0.6 Delta_u or more is named as near
collapse: one run is one sample there, and `rockingwall assess --building` gives the spread.

With --code nzsee ntc asce41, each storey's wall is also checked by the codes where it stands in
the building (docs/codes.md), with a line where a code passes a wall that the run collapses or
takes past the code's usable displacement.

    rockingwall building house.toml kobe.AT2 duzce.AT2 --pga 0.5
    rockingwall building house.toml elcentro --scale 1 --json
    rockingwall building house.toml elcentro --pga 0.3 --code nzsee asce41
"""
import sys

from .. import assessment_codes_building as codes_building
from .. import intensity, strict_json
from ..building import building_file, concurrent_runs, monolithic, reports
from . import common as cc
from .code_options import add_code_arguments, code_checks


def parser(sub=None):
    p = (sub.add_parser if sub else lambda name, **kw: cc.Parser(prog="rockingwall building", **kw))(
        "building", help="the walls of a building under records (walls, diaphragms, floors in one run)",
        description=__doc__)
    p.add_argument("file", help="the building file (TOML)")
    cc.add_record_arguments(p, many=True)
    p.add_argument("--solver", choices=["exact", "cvode"], help="exact (linear diaphragms and storeys: the default "
                   "where it covers the building) or cvode (CVODES, every spring law)")
    p.add_argument("--rtol", type=float, default=1e-8, help="relative tolerance where CVODES runs (default 1e-8)")
    p.add_argument("--out", help="folder for <record>.csv (time histories per storey) and <record>.png")
    p.add_argument("--json", action="store_true", help="print the results as JSON (strict: null, never NaN)")
    cc.add_strict_argument(p)
    add_code_arguments(p)
    p.set_defaults(command=main)
    return p


def main(args):
    return run_building(args.file, args)


def run_building(path, args):
    """The building of the file at `path` under args.records (scaled as args say): what `rockingwall
    building` and `rockingwall run --building` print and write."""
    building = cc.plausible(lambda: building_file.read(path), args)
    records = [cc.record_from_args(spec, args) for spec in args.records]
    pgas = [record.pga / intensity.G for record in records]
    codes = code_checks(args, pgas, building=building)  # before any run: a bad option loses nothing
    with concurrent_runs.threads() as pool:   # each record's runs side by side
        runs = [monolithic.simulate_building(building, record, rtol=args.rtol, solver=getattr(args, "solver", None),
                                             check_sensitivity=True, output_interval=0.01 if args.out else None,
                                             executor=pool, tie_forces=True)
                for record in records]
    if args.out:
        write_histories(building, runs, cc.output_dir(args.out))
    results = [result for result, _ in runs]
    if args.json:
        data = reports.to_json(building, results)
        if codes is not None:
            data.update(codes=codes_building.to_json(codes),
                        code_unconservative=codes_building.unconservative_json(codes, results, pgas))
        strict_json.dump(data, sys.stdout)
    else:
        lines = [reports.table(building, results)]
        if codes is not None:
            lines += codes_building.head_lines(codes) + codes_building.unconservative_lines(codes, results, pgas)
        print("\n".join(lines))
    return 0


def write_histories(building, runs, out):
    """<record>.csv and <record>.png of every run into the folder out."""
    for result, history in runs:
        stem = cc.file_stem(result.record)
        cc.write_atomic(out / f"{stem}.csv", lambda tmp, r=result, h=history: reports.history_csv(
            h, tmp, [s.t_collapse_s if s.collapsed else None for s in r.storeys], [s.wall for s in r.storeys]))
        cc.write_atomic(out / f"{stem}.png", lambda tmp, r=result, h=history: reports.plot(building, r, h, tmp))
        print(f"wrote {out / stem}.csv and {out / stem}.png", file=sys.stderr)

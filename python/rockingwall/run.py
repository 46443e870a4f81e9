"""rockingwall run: one wall under one or more records; prints the peaks with units, writes a CSV
of the time histories and a plot per record (and --json for programs)."""
import json
import sys



from . import cli_common as cc
from .api import ENGINES, simulate


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


def main(args):
    wall = cc.wall_from_args(args)
    results = [simulate(wall, cc.record_from_args(spec, args), engine=args.engine, stop_time=args.stop_time,
                        tail=args.tail, rtol=args.rtol) for spec in args.records]
    if args.out:  # files first: a closed pipe on standard output cannot lose them
        out = cc.output_dir(args.out)
        for r in results:
            stem = cc.file_stem(r.record)
            cc.write_atomic(out / f"{stem}.csv", lambda tmp, r=r: r.history.to_csv(tmp, index=False, float_format="%.9g"))
            cc.write_atomic(out / f"{stem}.png", lambda tmp, r=r: plot(r, tmp))
            print(f"wrote {out / stem}.csv and {out / stem}.png", file=sys.stderr)
    if args.json:
        json.dump({"wall": wall.params, "Delta_u_m": wall.delta_u,
                   "runs": [dict(record=r.record, engine=r.engine, **r.peaks()) for r in results]},
                  sys.stdout, indent=1, default=float)
        print()
    else:
        print(table(wall, results))
    return 0


def table(wall, results):
    lines = [f"wall: {wall.describe()}", f"Delta_u = {wall.delta_u * 1e3:.1f} mm",
             f"{'record':<28}{'peak s1 [mm]':>13}{'peak s2 [mm]':>13}{'s1/Delta_u':>11}{'impacts':>9}  collapse"]
    for r in results:
        collapse = f"yes, at {r.t_collapse:.2f} s" if r.collapsed else "no"
        lines.append(f"{r.record[:27]:<28}{r.peak_s1 * 1e3:>13.1f}{r.peak_s2 * 1e3:>13.1f}"
                     f"{r.s1_over_delta_u:>11.2f}{r.impacts:>9}  {collapse}")
    return "\n".join(lines)


def plot(result, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    h = result.history
    fig, (ax_ag, ax_s) = plt.subplots(2, 1, figsize=(9, 4.5), sharex=True, height_ratios=[1, 2])
    ax_ag.plot(h["time"], h["ag"] / 9.81, lw=0.6, color="0.3")
    ax_ag.set_ylabel("ag [g]")
    ax_s.plot(h["time"], h["s1"] * 1e3, lw=0.8, label="s1, mid-height [mm]")
    ax_s.plot(h["time"], h["s2"] * 1e3, lw=0.8, label="s2, top [mm]")
    du = result.wall.delta_u * 1e3
    ax_s.axhline(du, color="r", lw=0.6, ls="--", label=f"Delta_u = {du:.0f} mm")
    ax_s.axhline(-du, color="r", lw=0.6, ls="--")
    ax_s.set_ylabel("displacement [mm]")
    ax_s.set_xlabel("time [s]")
    ax_s.legend(fontsize=8, loc="upper right")
    for ax in (ax_ag, ax_s):
        ax.grid(alpha=0.3)
    fig.suptitle(f"{result.record}: {result.wall.describe()}", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110, format="png")
    plt.close(fig)





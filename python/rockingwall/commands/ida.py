"""Incremental dynamic analysis, collapse fragility and the K_d x intensity map, from the results
CSV of `rockingwall sweep` (one wall, model and hinge law at a time).

Writes three PNGs to --out and prints the fragility fits:
  ida_curves.png   peak s1 and s2 against PGA for every record, one column per K_d
  fragility.png    collapse fraction against PGA per K_d, with its lognormal MLE fit
  kd_map.png       median peak s1 and s2 over the records against K_d and PGA
A run that collapsed has no meaningful peak (the run stops at the instability point): the IDA
curves end there with a cross, and the medians count it as larger than any peak.

  rockingwall ida results/sweep_fema.csv --out results/
"""
import argparse
import pathlib
import sys

from .. import outputs
from ..sweep import ida


def main(argv=None):
    p = argparse.ArgumentParser(prog="rockingwall ida", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("results", help="results CSV of `rockingwall sweep`")
    p.add_argument("--out", default="results")
    p.add_argument("--wall", help="the wall column of the results: a preset (1, paper2), a [walls.NAME] name "
                                  "or a building's storey ('storey 2' or 2) (default: the file's only wall)")
    p.add_argument("--model", help="the model column (default: the chosen wall's only model; a building's "
                                   "storeys: building)")
    p.add_argument("--hinge-law", help="the hinge_law column (default: the only one of the chosen runs)")
    p.add_argument("--ida-kd", type=float, nargs="+", help="K_d values for the IDA and fragility plots (default: all)")
    args = p.parse_args(argv)
    try:
        d = ida.load(args.results, args.wall, args.model, args.hinge_law)
    except (OSError, ValueError) as exc:
        print(f"rockingwall ida: error: {exc}", file=sys.stderr)
        return 2
    out = pathlib.Path(args.out)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        print(f"rockingwall ida: error: --out {out}: {exc.strerror}", file=sys.stderr)
        return 2
    outputs.protect(args.results, "the results file")
    outputs.check_targets([out / "ida_curves.png", out / "fragility.png", out / "kd_map.png"], "--out")
    sub = d[d.kd_kN.isin(args.ida_kd)] if args.ida_kd else d
    ida.ida_curves(sub, out / "ida_curves.png")
    fits = ida.fragility_plot(sub, out / "fragility.png")
    ida.kd_map(d, out / "kd_map.png")
    print(f"wall: {d.wall.iloc[0]} ({d.model.iloc[0]}, {d.hinge_law.iloc[0]})\n{ida.scene(d).text()}")
    print(f"{len(d)} runs, {d.record.nunique()} records; collapse fragility against PGA (lognormal MLE):")
    print("\n".join(ida.fragility_table(fits, d.record.nunique())))
    print(f"wrote {out / 'ida_curves.png'}, {out / 'fragility.png'}, {out / 'kd_map.png'}")
    # the plots are made from every good row, but a file with damaged lines or unfinished runs is
    # not a complete result: say so in the exit status too
    return 1 if d.attrs.get("damaged_lines") or d.attrs.get("unfinished") else 0

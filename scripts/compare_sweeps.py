"""Compare the peaks of two sweep result files run by run (e.g. one rtol against a tighter one):
how many runs change collapse outcome, and the relative differences of peak s1 and s2 over the
runs that survive in both (a collapsed run's peak is where the run was stopped, not a response).

  .venv/bin/python scripts/compare_sweeps.py results/acc_rtol1e-6.csv results/acc_rtol1e-8.csv
"""
import argparse
import pathlib
import sys

from rockingwall.sweep import store

KEY = ["wall", "model", "hinge_law", "kd_kN", "record", "pga_g", "scale"]


def load(path):
    """The 'ok' runs (damaged lines named and left out, rockingwall.sweep.store)."""
    d = store.load_frame(path)
    return d[d.status == "ok"].set_index(KEY).sort_index()


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("results")
    p.add_argument("reference")
    args = p.parse_args(argv)
    try:
        a, ref = load(args.results), load(args.reference)
    except (OSError, ValueError) as exc:
        print(f"compare_sweeps.py: error: {exc}", file=sys.stderr)
        return 2
    common = a.index.intersection(ref.index)
    if common.empty:
        sys.exit("the two files have no run in common")
    a, ref = a.loc[common], ref.loc[common]
    flips = int((a.collapsed != ref.collapsed).sum())
    alive = ~a.collapsed & ~ref.collapsed
    print(f"{len(common)} runs in common; collapse outcome differs in {flips}; "
          f"CPU {a.cpu_s.sum():.1f} s vs {ref.cpu_s.sum():.1f} s")
    for q in ("peak_s1", "peak_s2"):
        diff = (a[q] - ref[q]).abs()[alive]
        rel = diff / ref[q][alive]
        worst = diff.idxmax()
        print(f"{q}: {alive.sum()} surviving runs, relative difference median {rel.median():.1e}, "
              f"90th percentile {rel.quantile(0.9):.1e}, max {rel.max():.1e}; largest absolute "
              f"{1000 * diff.max():.1f} mm (K_d {worst[3]:g} kN/m, {worst[4]}, PGA {worst[5]:g} g, "
              f"peak {1000 * ref[q][worst]:.0f} mm)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

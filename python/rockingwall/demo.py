"""The main job: wall 1 of the paper under El Centro 1940 at 50 %, simulated through the
exact engine (or --engine fmi2sim / fmpy: the FMU) as the simply supported wall and with a flexible diaphragm
(K_d = 500, 50, 5 kN/m per metre of wall, the cases of the paper's Table 5.4 / Fig. 5.4), with
the default hinge law (dohertyHinge).

Prints the peak mid-height and top displacements beside the paper's, writes the time histories
to a CSV and draws them (results/main_elcentro.csv, results/main_elcentro.png)."""
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from . import cli_common as cc
from . import records
from .api import ENGINES, simulate
from .wall import Wall

# Table 5.4, El Centro at 50 %: (label, model, K_d in kN/m, paper s1, paper s2) [m]
CASES = [
    ("1DOF", "simplySupported", None, 0.043, None),
    ("2DOF Kd=500 kN/m per m", "flexibleTop", 500.0, 0.043, 0.004),
    ("2DOF Kd=50 kN/m per m", "flexibleTop", 50.0, 0.137, 0.019),
    ("2DOF Kd=5 kN/m per m", "flexibleTop", 5.0, 0.050, 0.109),
]


def main(argv=None):
    parser = cc.Parser(prog="rockingwall demo", description=__doc__)
    parser.add_argument("--scale", type=float, default=0.5, help="factor on the record as given (default 0.5)")
    parser.add_argument("--engine", default="exact", choices=ENGINES)
    parser.add_argument("--out", default="results", help="folder for the CSV and the plot (created if missing)")
    args = parser.parse_args(argv)

    record = records.el_centro().scaled(args.scale)
    out = cc.output_dir(args.out)
    runs = {}
    for label, support, kd, _, _ in CASES:
        extra = {} if kd is None else {"Kd": kd * 1e3}  # kN/m per m -> N/m per m
        wall = Wall.make("paper1", support=support, hingeLaw="dohertyHinge", er=0.86, **extra)
        runs[label] = simulate(wall, record, engine=args.engine)

    lines = [f"Wall 1 (b = 0.15 m, h = 2.5 m, W = 6.622 kN/m), El Centro 1940 x {args.scale}, e_r = 0.86, "
             "hinge law dohertyHinge",
             f"{'case':<24}{'peak s1 [m]':>12}{'paper':>8}{'peak s2 [m]':>13}{'paper':>8}{'impacts':>9}  collapsed"]
    for label, _, _, paper_s1, paper_s2 in CASES:
        run = runs[label]
        p1 = f"{paper_s1:.3f}" if args.scale == 0.5 else "-"
        p2 = f"{paper_s2:.3f}" if (paper_s2 is not None and args.scale == 0.5) else "-"
        lines.append(f"{label:<24}{run.peak_s1:>12.4f}{p1:>8}{run.peak_s2:>13.4f}{p2:>8}{run.impacts:>9}  {run.collapsed}")
    print("\n" + "\n".join(lines))
    cc.write_atomic(out / "main_job.txt", lambda tmp: pathlib.Path(tmp).write_text("\n".join(lines) + "\n"))

    csv_path = out / "main_elcentro.csv"
    grid = runs[CASES[0][0]].history["time"]
    table = {"time_s": grid, "ag_m_s2": runs[CASES[0][0]].history["ag"]}
    for label, run in runs.items():
        key = label.split(" kN")[0].replace(" ", "_").replace("=", "")
        for name in ("s1", "s2"):
            table[f"{name}_m_{key}"] = run.history[name]
    cc.write_atomic(csv_path, lambda tmp: pd.DataFrame(table).to_csv(tmp, index=False, float_format="%.6g"))

    png_path = out / "main_elcentro.png"
    fig, axes = plt.subplots(len(runs), 1, figsize=(9, 2.2 * len(runs)), sharex=True)
    for ax, (label, run) in zip(axes, runs.items()):
        ax.plot(run.history.time, run.history.s1, lw=0.8, label="s1 (mid-height)")
        ax.plot(run.history.time, run.history.s2, lw=0.8, label="s2 (top)")
        ax.set_ylabel("m")
        ax.set_title(label, fontsize=9, loc="left")
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel("time [s]")
    fig.suptitle(f"Wall 1, El Centro 1940 x {args.scale} ({args.engine} engine)")
    fig.tight_layout()
    cc.write_atomic(png_path, lambda tmp: fig.savefig(tmp, dpi=110, format="png"))
    print(f"\nwrote {csv_path} and {png_path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

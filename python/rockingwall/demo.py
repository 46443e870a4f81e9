"""The main job: wall 1 of the paper under El Centro 1940 at 50 %, simulated through the
RockingWall FMU (fmpy, CVode) as the simply supported wall and with a flexible diaphragm
(K_d = 500, 50, 5 kN/m per metre of wall, the cases of the paper's Table 5.4 / Fig. 5.4), with
the default hinge law (dohertyHinge).

Prints the peak mid-height and top displacements beside the paper's, writes the time histories
to a CSV and draws them (results/main_elcentro.csv, results/main_elcentro.png)."""
import argparse
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from tqdm import tqdm

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "reference"))
import rw_fmu  # noqa: E402
from rwref import inputs  # noqa: E402

# Table 5.4, El Centro at 50 %: (label, model, K_d in kN/m, paper s1, paper s2) [m]
CASES = [
    ("1DOF", "simplySupported", None, 0.043, None),
    ("2DOF Kd=500 kN/m per m", "flexibleTop", 500.0, 0.043, 0.004),
    ("2DOF Kd=50 kN/m per m", "flexibleTop", 50.0, 0.137, 0.019),
    ("2DOF Kd=5 kN/m per m", "flexibleTop", 5.0, 0.050, 0.109),
]
WALL_1 = dict(h=2.5, b=0.15, W=6622.0, psi=0.0, er=0.86)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--fmu", default=str(REPO / "build" / "RockingWall.fmu"))
    parser.add_argument("--scale", type=float, default=0.5, help="factor on the record as given (default 0.5)")
    parser.add_argument("--out", default=str(REPO / "results"))
    parser.add_argument("--rtol", type=float, default=1e-6)
    args = parser.parse_args()

    record = inputs.el_centro(args.scale)
    t_in, ag_in = record.t, record.a
    t_end = float(t_in[-1])
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    runs = {}
    with tqdm(total=round(len(CASES) * t_end), unit="s", desc="simulated time", mininterval=1.0,
              bar_format="{l_bar}{bar}| {n:.0f}/{total:.0f} s") as bar:
        for label, model, kd, _, _ in CASES:
            done = bar.n

            def progress(time, done=done):
                step = int(done + time) - bar.n  # whole seconds only: tqdm redraws at most once a second
                if step > 0:
                    bar.update(step)
            params = dict(WALL_1, support=model, hinge_law="dohertyHinge")
            if kd is not None:
                params["Kd"] = kd * 1e3  # kN/m per m -> N/m per m
            runs[label] = rw_fmu.simulate(args.fmu, t_end, t_in, ag_in, rtol=args.rtol,
                                          output_interval=0.01, progress=progress, **params)
            bar.update(round(done + t_end) - bar.n)

    lines = [f"Wall 1 (b = 0.15 m, h = 2.5 m, W = 6.622 kN/m), El Centro 1940 x {args.scale}, e_r = 0.86, "
             "hinge law dohertyHinge",
             f"{'case':<24}{'peak s1 [m]':>12}{'paper':>8}{'peak s2 [m]':>13}{'paper':>8}{'impacts':>9}  collapsed"]
    for label, _, _, paper_s1, paper_s2 in CASES:
        run = runs[label]
        p1 = f"{paper_s1:.3f}" if args.scale == 0.5 else "-"
        p2 = f"{paper_s2:.3f}" if (paper_s2 is not None and args.scale == 0.5) else "-"
        lines.append(f"{label:<24}{run.peak_s1:>12.4f}{p1:>8}{run.peak_s2:>13.4f}{p2:>8}{run.impacts:>9}  {run.collapsed}")
    print("\n" + "\n".join(lines))
    (out / "main_job.txt").write_text("\n".join(lines) + "\n")

    csv_path = out / "main_elcentro.csv"
    grid = np.arange(0.0, t_end + 1e-9, 0.01)
    columns = [grid, np.interp(grid, t_in, ag_in)]
    header = ["time", "ag"]
    for label, run in runs.items():
        key = label.split(" kN")[0].replace(" ", "_").replace("=", "")
        for name in ("s1", "s2"):
            columns.append(rw_fmu.on_grid(run.t, getattr(run, name), grid, right=np.nan))
            header.append(f"{name}_{key}")
    np.savetxt(csv_path, np.column_stack(columns), delimiter=",", header=",".join(header), comments="", fmt="%.6g")

    png_path = out / "main_elcentro.png"
    fig, axes = plt.subplots(len(runs), 1, figsize=(9, 2.2 * len(runs)), sharex=True)
    for ax, (label, run) in zip(axes, runs.items()):
        ax.plot(run.t, run.s1, lw=0.8, label="s1 (mid-height)")
        ax.plot(run.t, run.s2, lw=0.8, label="s2 (top)")
        ax.set_ylabel("m")
        ax.set_title(label, fontsize=9, loc="left")
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel("time [s]")
    fig.suptitle(f"Wall 1, El Centro 1940 x {args.scale} (RockingWall FMU, fmpy CVode)")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)
    print(f"\nwrote {csv_path.relative_to(REPO) if csv_path.is_relative_to(REPO) else csv_path}"
          f" and {png_path.relative_to(REPO) if png_path.is_relative_to(REPO) else png_path}")


if __name__ == "__main__":
    main()

"""An animated GIF of the two-body wall rocking under a record, restrained at the top by the
diaphragm spring K_d, drawn from an fmi2sim run, with the ground acceleration below. The wall is
drawn to scale but its rotations are exaggerated (--exaggerate, stated in the title): tens of
millimetres on a 2.5 m wall are invisible otherwise.

The bodies are placed from s1, s2 (q1 = 2 s1/h, q2 = 2 s2/h - q1): the lower body turns by q1 about
the base corner it rocks on (side sign(q1)), the upper body by q2 about the mid-height corner on
which the joint closes (side -sign(q2 - q1)), as in docs/model.md. The diaphragm is drawn fixed
(u_top = 0, as in the run), the ground moves with the record.

  .venv/bin/python scripts/animate_wall.py --record ff01a --pga 0.2 --kd 50 --out docs/img/rocking_wall.gif
"""
import argparse
import os
import pathlib
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib import animation
from tqdm import tqdm

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "reference"))
sys.path.insert(0, str(REPO / "scripts"))
from rwsweep import grid, records  # noqa: E402

BUILD = pathlib.Path(os.environ.get("RW_BUILD_DIR", REPO / "build"))


def simulate(args, rec, geometry, t_end):
    scale = args.pga / rec.pga_g if args.pga else args.scale
    sets = dict(geometry, Kd=args.kd * 1e3, support=3, hingeLaw=4, er=0.86)
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp) / "run.csv"
        cmd = [args.fmi2sim, args.fmu, "--ag", rec.path, "--ag-scale", repr(scale), "--stop-time", repr(t_end),
               "--output-interval", repr(args.speed / args.fps / 4), "--output", str(out)]
        cmd += [a for k, v in sets.items() for a in ("--set", f"{k}={v!r}")]
        subprocess.run(cmd, check=True, capture_output=True, text=True)
        return pd.read_csv(out), scale


def rotate(points, pivot, angle):
    """Clockwise rotation by angle (positive moves the top toward +x)."""
    c, s = np.cos(angle), np.sin(angle)
    d = points - pivot
    return pivot + np.column_stack([c * d[:, 0] + s * d[:, 1], -s * d[:, 0] + c * d[:, 1]])


def wall_outline(q1, q2, b, h):
    """Corner polygons of the lower and upper body for rotations q1, q2."""
    half = h / 2
    side_b = 1.0 if q1 >= 0 else -1.0
    lower = np.array([[-b / 2, 0], [b / 2, 0], [b / 2, half], [-b / 2, half]])
    lower = rotate(lower, np.array([side_b * b / 2, 0.0]), q1)
    side_m = -1.0 if q2 - q1 >= 0 else 1.0
    hinge = lower[2] if side_m > 0 else lower[3]  # the corner of the lower body's top face
    upper = np.array([[-b / 2, half], [b / 2, half], [b / 2, h], [-b / 2, h]])
    upper = rotate(upper - np.array([side_m * b / 2, half]) + hinge, hinge, q2)
    return lower, upper


def spring(x0, x1, y, coils=6, amp=0.04):
    xs = np.linspace(x0, x1, 2 * coils + 3)
    ys = np.full_like(xs, y)
    ys[2:-2:2] += amp
    ys[3:-2:2] -= amp
    return xs, ys


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--record", default="ff01a", help="FEMA P695 far-field component, or an .AT2 file")
    p.add_argument("--pga", type=float, default=0.2, help="scale the record to this PGA [g] (0: use --scale)")
    p.add_argument("--scale", type=float, default=1.0)
    p.add_argument("--kd", type=float, default=50.0, help="K_d [kN/m per m]")
    p.add_argument("--wall", type=int, default=1)
    p.add_argument("--t-end", type=float, default=20.0, help="seconds of the record shown")
    p.add_argument("--speed", type=float, default=1.0, help="simulated seconds per second of GIF")
    p.add_argument("--fps", type=int, default=12)
    p.add_argument("--exaggerate", type=float, default=5.0, help="factor on the drawn rotations")
    p.add_argument("--out", default=str(REPO / "results" / "rocking_wall.gif"))
    p.add_argument("--fmi2sim", default=str(BUILD / "fmi2sim"))
    p.add_argument("--fmu", default=str(BUILD / "RockingWall.fmu"))
    args = p.parse_args(argv)

    if args.record.lower().endswith(".at2"):
        rec = records.read_at2(args.record)
    else:
        rec = {r.name: r for r in records.fema_farfield(REPO / "results" / "records" / "fema_farfield")}[args.record]
    geometry = grid.wall_parameters(args.wall)
    b, h = geometry["b"], geometry["h"]
    t_end = min(args.t_end, rec.duration)
    run, scale = simulate(args, rec, geometry, t_end)
    body = pathlib.Path(rec.path).read_text().splitlines()[4:]  # after the 4 header lines, in g
    acc = np.array(" ".join(body).split(), dtype=float) * scale
    t_acc = np.arange(acc.size) * (rec.duration / (acc.size - 1))

    frames = np.arange(0.0, t_end, args.speed / args.fps)
    s1 = np.interp(frames, run.time, run.s1)
    s2 = np.interp(frames, run.time, run.s2)
    q1 = 2 * s1 / h
    q2 = 2 * s2 / h - q1

    fig, (ax, ax_ag) = plt.subplots(2, 1, figsize=(3.6, 4.6), gridspec_kw=dict(height_ratios=[4, 1]), dpi=72)
    ax.set_aspect("equal")
    ax.set_xlim(-0.6, 0.9)
    ax.set_ylim(-0.3, h + 0.15)
    ax.axis("off")
    ax.plot([-0.6, 0.9], [0, 0], color="0.3", lw=2)
    ax.plot([0.75, 0.75], [h - 0.15, h + 0.15], color="0.3", lw=3)  # the diaphragm
    lower_patch = plt.Polygon(np.zeros((4, 2)), closed=True, fc="#c8734a", ec="k")
    upper_patch = plt.Polygon(np.zeros((4, 2)), closed=True, fc="#d98c5f", ec="k")
    ax.add_patch(lower_patch)
    ax.add_patch(upper_patch)
    (spring_line,) = ax.plot([], [], color="tab:blue", lw=1.2)
    label = ax.text(-0.58, -0.08, "", fontsize=7, va="top")
    ax.set_title(f"wall {args.wall}, K_d = {args.kd:g} kN/m, {rec.name} at PGA {scale * rec.pga_g:.2f} g\n"
                 f"rotations drawn x{args.exaggerate:g}", fontsize=7)
    ax_ag.plot(t_acc[t_acc <= t_end], acc[t_acc <= t_end], color="0.4", lw=0.5)
    (marker,) = ax_ag.plot([], [], "o", color="tab:red", ms=3)
    ax_ag.set_xlim(0, t_end)
    ax_ag.set_xlabel("t [s]", fontsize=7)
    ax_ag.set_ylabel("ag [g]", fontsize=7)
    ax_ag.tick_params(labelsize=6)
    fig.tight_layout()

    def draw(i):
        lower, upper = wall_outline(args.exaggerate * q1[i], args.exaggerate * q2[i], b, h)
        lower_patch.set_xy(lower)
        upper_patch.set_xy(upper)
        top = upper[2:].mean(axis=0)
        spring_line.set_data(*spring(top[0], 0.75, top[1]))
        label.set_text(f"t = {frames[i]:5.2f} s  s1 = {1000 * s1[i]:5.1f} mm  s2 = {1000 * s2[i]:5.1f} mm")
        marker.set_data([frames[i]], [np.interp(frames[i], t_acc, acc)])
        return lower_patch, upper_patch, spring_line, label, marker

    anim = animation.FuncAnimation(fig, draw, frames=len(frames), blit=True)
    out = pathlib.Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    with tqdm(total=len(frames), desc="frames") as bar:
        anim.save(out, writer=animation.PillowWriter(fps=args.fps), progress_callback=lambda i, n: bar.update(1))
    print(f"wrote {out} ({out.stat().st_size / 1e6:.2f} MB, {len(frames)} frames); peaks in the clip: "
          f"s1 {1000 * np.abs(s1).max():.1f} mm, s2 {1000 * np.abs(s2).max():.1f} mm")
    return 0


if __name__ == "__main__":
    sys.exit(main())

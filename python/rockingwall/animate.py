"""An animated GIF of the two-body wall rocking under a record, restrained at the top by the
diaphragm spring K_d, drawn from a run of the exact engine, with the ground acceleration below. The wall is
drawn to scale but its rotations are exaggerated (--exaggerate, stated in the title): tens of
millimetres on a 2.5 m wall are invisible otherwise.

The bodies are placed from s1, s2 (q1 = 2 s1/h, q2 = 2 s2/h - q1): the lower body turns by q1 about
the base corner it rocks on (side sign(q1)), the upper body by q2 about the mid-height corner on
which the joint closes (side -sign(q2 - q1)), as in docs/model.md. The diaphragm is drawn fixed
(u_top = 0, as in the run), the ground moves with the record.

  rockingwall animate --wall paper1 --Kd 50kN/m/m --pga 0.2 RECORD.AT2 --out docs/img/rocking_wall.gif
"""
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib import animation
from tqdm import tqdm

from . import cli_common as cc
from .api import simulate
from .units import format_kd


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
    p = cc.Parser(prog="rockingwall animate", description=__doc__)
    cc.add_wall_arguments(p)
    cc.add_record_arguments(p)
    p.add_argument("--t-end", type=float, default=20.0, help="seconds of the record shown")
    p.add_argument("--speed", type=float, default=1.0, help="simulated seconds per second of GIF")
    p.add_argument("--fps", type=int, default=12)
    p.add_argument("--exaggerate", type=float, default=5.0, help="factor on the drawn rotations")
    p.add_argument("--out", default="results/rocking_wall.gif")
    args = p.parse_args(argv)

    wall = cc.wall_from_args(args)
    rec = cc.record_from_args(args.record, args)
    b, h = wall.params["b"], wall.params["h"]
    t_end = min(args.t_end, rec.duration)
    run = simulate(wall, rec, stop_time=t_end, output_interval=args.speed / args.fps / 4).history
    t_acc, acc = rec.t, rec.ag / 9.81

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
    ax.set_title(f"b = {b:g} m, h = {h:g} m, K_d = {format_kd(wall.params['Kd'])}, {rec.name}\n"
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
    cc.output_dir(out.parent)
    with tqdm(total=len(frames), desc="frames") as bar:
        anim.save(out, writer=animation.PillowWriter(fps=args.fps), progress_callback=lambda i, n: bar.update(1))
    print(f"wrote {out} ({out.stat().st_size / 1e6:.2f} MB, {len(frames)} frames); peaks in the clip: "
          f"s1 {1000 * np.abs(s1).max():.1f} mm, s2 {1000 * np.abs(s2).max():.1f} mm")
    return 0


if __name__ == "__main__":
    sys.exit(main())

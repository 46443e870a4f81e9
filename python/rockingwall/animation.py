"""An animated GIF of the two-body wall rocking under a record, restrained at the top by the
diaphragm spring K_d, drawn from a run of the exact engine, with the ground acceleration below
(the logic of `rockingwall animate`, whose help says how the bodies are drawn).
"""
import pathlib

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib import animation
from tqdm import tqdm

from . import figure_titles, outputs, scenes
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


def figure(wall, rec, t_end, exaggerate):
    """The animation's figure before its first frame: the wall, its spring and the ground over the
    record's first t_end seconds, titled with the record, the wall and its scene. Returns (figure,
    (lower body, upper body, spring, label, record marker))."""
    b, h = wall.params["b"], wall.params["h"]
    t_acc, acc = rec.t, rec.ag / 9.81
    fig, (ax, ax_ag) = plt.subplots(2, 1, figsize=(3.6, 4.8), gridspec_kw=dict(height_ratios=[4, 1]), dpi=72)
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
    # wrapped to the figure's width: a GIF 260 pixels wide cut the record's intensity off
    figure_titles.suptitle(fig, f"{rec.name}: b = {b:g} m, h = {h:g} m, K_d = {format_kd(wall.params['Kd'])}\n"
                                f"scene: {scenes.paper(wall.params).title}; rotations drawn x{exaggerate:g}", 7)
    ax_ag.plot(t_acc[t_acc <= t_end], acc[t_acc <= t_end], color="0.4", lw=0.5)
    (marker,) = ax_ag.plot([], [], "o", color="tab:red", ms=3)
    ax_ag.set_xlim(0, t_end)
    ax_ag.set_xlabel("t [s]", fontsize=7)
    ax_ag.set_ylabel("ag [g]", fontsize=7)
    ax_ag.tick_params(labelsize=6)
    fig.tight_layout()
    return fig, (lower_patch, upper_patch, spring_line, label, marker)


def animate(wall, rec, out, t_end=20.0, speed=1.0, fps=12, exaggerate=5.0):
    """Write the GIF of `wall` under the record `rec` (its first t_end seconds) to `out` (its folder
    must exist): `speed` simulated seconds per second of GIF, `fps` frames per second, rotations
    drawn x`exaggerate`. Returns (frames, peak |s1|, peak |s2|) of the clip [m]."""
    b, h = wall.params["b"], wall.params["h"]
    t_end = min(t_end, rec.duration)
    run = simulate(wall, rec, stop_time=t_end, output_interval=speed / fps / 4).history
    t_acc, acc = rec.t, rec.ag / 9.81

    frames = np.arange(0.0, t_end, speed / fps)
    s1 = np.interp(frames, run.time, run.s1)
    s2 = np.interp(frames, run.time, run.s2)
    q1 = 2 * s1 / h
    q2 = 2 * s2 / h - q1

    fig, (lower_patch, upper_patch, spring_line, label, marker) = figure(wall, rec, t_end, exaggerate)

    def draw(i):
        lower, upper = wall_outline(exaggerate * q1[i], exaggerate * q2[i], b, h)
        lower_patch.set_xy(lower)
        upper_patch.set_xy(upper)
        top = upper[2:].mean(axis=0)
        spring_line.set_data(*spring(top[0], 0.75, top[1]))
        label.set_text(f"t = {frames[i]:5.2f} s  s1 = {1000 * s1[i]:5.1f} mm  s2 = {1000 * s2[i]:5.1f} mm")
        marker.set_data([frames[i]], [np.interp(frames[i], t_acc, acc)])
        return lower_patch, upper_patch, spring_line, label, marker

    anim = animation.FuncAnimation(fig, draw, frames=len(frames), blit=True)
    with tqdm(total=len(frames), desc="frames") as bar:
        outputs.write_atomic(pathlib.Path(out), lambda tmp: anim.save(
            tmp, writer=animation.PillowWriter(fps=fps), progress_callback=lambda i, n: bar.update(1)), "--out")
    return len(frames), np.abs(s1).max(), np.abs(s2).max()

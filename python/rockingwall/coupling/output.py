"""What `rockingwall couple` writes of a coupled run: the CSV of its time histories and energy
terms, the plot, and the summary (peaks, the macro step and its limit, the energy residual's share
and the flags)."""
import math

import numpy as np

from .. import figure_titles, outputs
from . import rules


def save_csv(r, path):
    cols = ["time", "wall_s1", "wall_s2", "dia_u", "wall_F_top", "wall_energy", "dia_energy",
            "wall_P_ground", "dia_P_ground", "dia_P_damping", "wall_dissipated"]
    data = np.column_stack([r[c] for c in cols] + [r.energy_residual()])
    outputs.write_atomic(path, lambda tmp: np.savetxt(tmp, data, delimiter=",", header=",".join(cols + ["energy_residual"]),
                                                      comments=""), "--out")


def plot(r, path, title, other=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(9, 7), sharex=True)
    t = r["time"]
    ax[0].plot(t, 1e3 * r["wall_s1"], label="s1 (mid-height)")
    ax[0].plot(t, 1e3 * r["wall_s2"], label="s2 (top)")
    ax[0].plot(t, 1e3 * r["dia_u"], label="u (diaphragm)")
    if other is not None:
        ax[0].plot(other["time"], 1e3 * other["wall_s1"], "k:", lw=1, label="s1, libcosim master")
    ax[0].set_ylabel("displacement [mm]")
    ax[0].legend(loc="upper right", fontsize=8)
    ax[1].plot(t, r["wall_F_top"] / 1e3)
    ax[1].set_ylabel("F_top [kN/m]")
    ax[2].plot(t, r.ground_work(), label="ground work")
    ax[2].plot(t, r["wall_energy"] + r["dia_energy"], label="stored (wall + diaphragm)")
    ax[2].plot(t, r["wall_dissipated"], label="lost in impacts")
    ax[2].plot(t, r.damping_loss(), label="lost in diaphragm damping")
    ax[2].plot(t, r.energy_residual(), label="residual")
    ax[2].set_ylabel("energy [J/m]")
    ax[2].set_xlabel("time [s]")
    ax[2].legend(loc="upper left", fontsize=8)
    figure_titles.suptitle(fig, title, 10)
    fig.tight_layout()
    outputs.write_png(fig, path, "--plot")
    plt.close(fig)


def summary(r, master, macro_step, energy_share, step_limit, step_warning):
    """The run's summary: peaks, the step and its limit, the energy residual's share and the flags
    (energy_ok, step_ok, flagged)."""
    share, energy_ok = rules.energy_check(r.energy_residual(), r.ground_work(), energy_share)
    return {
        "master": master,
        "macro_step": None if master == "monolithic" else macro_step,
        "macro_step_limit": step_limit,
        "step_ok": step_warning is None,
        "peak_s1": float(np.abs(r["wall_s1"]).max()), "peak_s2": float(np.abs(r["wall_s2"]).max()),
        "peak_u": float(np.abs(r["dia_u"]).max()), "peak_F_top": float(np.abs(r["wall_F_top"]).max()),
        "collapsed_at": r.get("collapsed_at"),
        "energy_residual_max": float(np.abs(r.energy_residual()).max()),
        "ground_work_max": float(np.abs(r.ground_work()).max()),
        "energy_residual_share": share if math.isfinite(share) else None,
        "energy_share_max": energy_share,
        "energy_ok": energy_ok,
        "flagged": not (energy_ok and step_warning is None),
    }

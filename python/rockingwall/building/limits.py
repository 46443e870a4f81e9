"""The stability limit of the co-simulated building (docs/building-coupling.md, "The limit"): the
Jacobi exchange of a wall standing on a diaphragm, measured on the scheme's exact step map
(rockingwall.coupling.rules.base_ratio_limit) against the mass ratio m_b/m_d and the macro step H,
with held and ramped inputs, confirmed by real runs of the master whose growth rates are
measured; the step each tie allows; the table and the plot.

    rockingwall couple-building --limits [--out DIR]

prints the tables of the document and writes DIR/building_coupling_limits.png (DIR: results/; the
document's figure is the one written with --out docs/img).
"""
import dataclasses
import math
import pathlib

import numpy as np

from .. import outputs, records
from ..coupling import linear_models, rules
from . import scene as bs

# the assessor's upper wall (docs/your-building.md) standing on a diaphragm of 60 kN/m per m
WALL = dict(h=3.6, b=0.23, W=14904.0, psi=0.2013)
LAW = 4
KD = 6e4
ZETA = 0.05
STEPS_MS = (0.1, 0.25, 0.5, 1.0, 2.0, 4.0)
# real runs: (order, H [s], m_b/m_d) on either side of the limits
RUNS = ((2, 1e-3, 0.13), (2, 1e-3, 0.18), (1, 2.5e-4, 0.8), (1, 2.5e-4, 1.25))
RUN_SECONDS = 1.0
PNG = "building_coupling_limits.png"
CURVES = (  # (order, damping counted, label, colour)
    (1, True, "held inputs (order 1), 5 % diaphragm damping", "tab:blue"),
    (1, False, "held inputs (order 1), no damping counted", "tab:cyan"),
    (2, True, "ramped inputs (order 2), 5 % diaphragm damping", "tab:red"),
    (2, False, "ramped inputs (order 2), no damping counted", "tab:orange"),
)
RUN_COLOURS = {True: "tab:green", False: "black"}   # stable, unstable
RUN_LABELS = {True: "run of the master: stable", False: "run of the master: grows"}
ASSESSOR_LABEL = "the assessor's upper wall on its floor (600 kg/m)"


def dashpot(md, zeta=ZETA, kd=KD):
    return 2.0 * zeta * math.sqrt(kd * md)


def ratio_limit(H, order, damped):
    """m_b/m_d at which the base exchange starts to add more than rules.ZETA_NUM_MAX of negative
    damping. The dashpot follows the diaphragm's mass (a damping ratio), so it is found at the
    ratio by a fixed-point pass over the bisection."""
    if not damped:
        return rules.base_ratio_limit(WALL, LAW, KD, 0.0, H, order)
    m_b = linear_models.base_mass(WALL, LAW)
    r = 1.0
    for _ in range(6):
        r = rules.base_ratio_limit(WALL, LAW, KD, dashpot(m_b / max(r, 1e-3)), H, order)
    return r


def limit_table():
    """{(order, damped): [r_c at each of STEPS_MS]}."""
    return {(o, d): [ratio_limit(h * 1e-3, o, d) for h in STEPS_MS] for o, d, _, _ in CURVES}


def canonical_scene(ratio):
    """The wall in storey 2 of a Building whose floors do not move, standing on diaphragm 1 of
    mass m_b/ratio (60 kN/m per m, 5 % damping as its dashpot), its top free (K_d = 0)."""
    md = linear_models.base_mass(WALL, LAW) / ratio
    real = {"md_1": md, "kd_1": KD, "cd_1": dashpot(md), "m_1": 1000.0, "k_1": 1e11, "md_2": 1000.0, "kd_2": 1e5,
            "m_2": 1000.0, "k_2": 1e11, "rayleighMass": 0.0, "rayleighStiffness": 0.0}
    return bs.Scene(real, {"nStoreys": 2, "storeyLaw": 0, "diaphragmLaw": 0},
                    [bs.WallSpec(2, dict(WALL, Kd=0.0), {"support": 3, "hingeLaw": LAW})])


@dataclasses.dataclass(frozen=True)
class Run:
    order: int
    H: float
    ratio: float
    predicted_sigma: float   # 1/s, the step map's
    measured_sigma: float    # 1/s, fitted to the base force's envelope
    stable: bool             # as predicted (rules.scene_stability)


def growth_rate(t, values, skip=0.3):
    """Growth rate [1/s] of |values|: a line fitted to the log of its envelope over ten windows,
    the first `skip` of the run left out."""
    t, v = np.asarray(t), np.abs(np.asarray(values))
    windows = np.array_split(np.arange(len(t)), 10)
    tm = np.array([t[w].mean() for w in windows])
    env = np.array([v[w].max() for w in windows])
    keep = tm >= skip * t[-1]
    return float(np.polyfit(tm[keep], np.log(np.maximum(env[keep], 1e-300)), 1)[0])


def measure_run(order, H, ratio, seconds=RUN_SECONDS):
    """One real run of the master (no energy guard: the growth is what is measured) under El
    Centro at 1e-3 of its size (the motion stays linear), against the step map's prediction."""
    scene = canonical_scene(ratio)
    predicted = rules.scene_stability(scene, H, order)
    r = bs.run(scene, records.el_centro().scaled(1e-3), seconds, H, order=order, energy_stop=None)
    return Run(order, H, ratio, predicted.growth.sigma, growth_rate(r["time"], r["building_F_above_1_in"]),
               predicted.stable)


def assessor_ratio():
    return linear_models.base_mass(WALL, LAW) / 600.0


def plot(table, runs, path, assessor=None):
    """r_c against H per curve, the runs as markers (colour: stable or growing), and the
    assessor's ratio; returns the figure (saved to path when given)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 5))
    for order, damped, label, colour in CURVES:
        ax.plot(STEPS_MS, table[(order, damped)], "-o" if damped else "--", color=colour, label=label, ms=4)
    for stable in (True, False):
        sel = [r for r in runs if r.stable == stable]
        if sel:
            ax.plot([1e3 * r.H for r in sel], [r.ratio for r in sel], "x" if not stable else "o", color=RUN_COLOURS[stable],
                    ls="none", ms=9, mfc="none", mew=2, label=RUN_LABELS[stable])
    if assessor is not None:
        ax.axhline(assessor, color="tab:purple", ls=":", label=ASSESSOR_LABEL)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("macro step H [ms]")
    ax.set_ylabel("largest m_b / m_d the exchange holds")
    ax.set_title("Jacobi co-simulation of a wall standing on a diaphragm: stable below the curves")
    ax.legend(fontsize=7, loc="lower left")
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    if path:
        pathlib.Path(path).parent.mkdir(parents=True, exist_ok=True)
        outputs.write_atomic(path, lambda tmp: fig.savefig(tmp, dpi=110, format="png"))  # whole, never through a link
    return fig


def tie_table(ties=(1e6, 1e7, 1e8), md=200.0, kd=2e4):
    """The largest macro step [s] each tie allows the wall tied to a diaphragm of md on kd (5 %),
    held and ramped: {(tie, order): H}."""
    out = {}
    for tie in ties:
        for order in (1, 2):
            out[(tie, order)] = rules.tie_step_limit(dict(WALL, Kd=tie), LAW, md, kd, dashpot(md, kd=kd), order)
    return out


def markdown(table, runs, ties):
    lines = ["| m_b/m_d limit at H [ms] | " + " | ".join(f"{h:g}" for h in STEPS_MS) + " |",
             "|---|" + "---|" * len(STEPS_MS)]
    for order, damped, label, _ in CURVES:
        lines.append(f"| {label} | " + " | ".join(f"{v:.3g}" for v in table[(order, damped)]) + " |")
    lines += ["", "| run | H [ms] | m_b/m_d | predicted growth [1/s] | measured [1/s] |", "|---|---|---|---|---|"]
    for r in runs:
        predicted = f"{r.predicted_sigma:.4g}" if not r.stable else "none"
        measured = f"{r.measured_sigma:.4g}" if not r.stable else f"none ({r.measured_sigma:.2g}: the record's own build-up)"
        lines.append(f"| {'ramped' if r.order == 2 else 'held'} | {1e3 * r.H:g} | {r.ratio:g} | {predicted} | {measured} |")
    lines += ["", "| tie [N/m per m] | largest H, held [ms] | largest H, ramped [ms] |", "|---|---|---|"]
    for tie in sorted({k[0] for k in ties}):
        lines.append(f"| {tie:.0e}".replace("e+0", "e") + f" | {1e3 * ties[(tie, 1)]:.3g} | {1e3 * ties[(tie, 2)]:.3g} |")
    return "\n".join(lines)


def main(out_dir="results"):
    png = pathlib.Path(out_dir) / PNG
    table = limit_table()
    runs = [measure_run(*r) for r in RUNS]
    ties = tie_table()
    plot(table, runs, png, assessor_ratio())
    print(markdown(table, runs, ties))
    print(f"\nthe assessor's upper wall: m_b = {linear_models.base_mass(WALL, LAW):.0f} kg/m, "
          f"m_b/m_d = {assessor_ratio():.3f} on 600 kg/m; wrote {png}")
    return 0

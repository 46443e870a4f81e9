"""The codes' verdicts beside the time histories as the diaphragm softens: one wall at one site, its
peak s1/Delta_u (or collapse) under a few records for each K_d, in the paper's scene and with the
diaphragm's mass, and where each code passes the wall while a record collapses it or takes it past
the code's usable displacement (docs/code-checks-vs-dynamics.md; scripts/code_checks_vs_dynamics.py)."""
import dataclasses

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from . import assessment_codes  # noqa: E402
from .api import simulate  # noqa: E402
from .building.description import Diaphragm  # noqa: E402

CODE_COLOURS = {"nzsee": "tab:blue", "ntc": "tab:green", "asce41": "tab:purple"}
RECORD_STYLES = (("0.15", "o"), ("0.35", "s"), ("0.55", "^"), ("0.7", "D"), ("0.45", "v"), ("0.25", "P"))
COLLAPSE_Y = 1.15      # where a collapsed run is drawn, above Delta_u
FLAG_Y = 1.27          # the first code's row of unconservative marks


def dynamics(wall, records, kds, diaphragm_mass=None, damping=0.05):
    """One row per record and K_d [N/m per m]: s1/Delta_u of the peak (NaN when collapsed) and
    collapse; the paper's scene, or with diaphragm_mass [kg/m] the wall tied to a diaphragm of
    that mass, damping ratio and stiffness K_d."""
    rows = []
    for kd in kds:
        w = wall.replace(Kd=kd)
        d = Diaphragm(stiffness=kd, mass=diaphragm_mass, damping=damping) if diaphragm_mass else None
        for record in records:
            r = simulate(w, record, diaphragm=d)
            rows.append(dict(record=record.name, kd=kd, collapsed=bool(r.collapsed),
                             ratio=np.nan if r.collapsed else r.peak_s1 / wall.delta_u, peak_s1=r.peak_s1))
    return pd.DataFrame(rows)


def unconservative_kds(checks, frame):
    """{code: the K_d values at which the code passes the wall and some record collapses it or
    takes s1 past the code's usable displacement}."""
    out = {}
    for code in checks.codes:
        hits = [kd for kd, d in frame.groupby("kd")
                if any(assessment_codes.unconservative(checks, np.nan if c else s, c)[code]
                       for s, c in zip(d.peak_s1, d.collapsed))]
        out[code] = sorted(hits)
    return out


def code_label(code, result):
    """The legend's words for a code's check: its name, the numbers of its verdict, the verdict."""
    name = assessment_codes.LABELS[code]
    if code == "nzsee":
        return f"{name}: Δm = 0.6 Δi, {result.nbs:.0f} %NBS, {result.verdict}"
    if code == "ntc":
        return f"{name}: du* at the hinge, {result.linear_verdict}/{result.nonlinear_verdict}, {result.verdict}"
    return f"{name}: h/t {result.h_over_t:.1f} vs {result.limit:g}, {result.verdict} (limit: collapse)"


def code_line_y(checks, code, delta_u):
    """The height of a code's line: its usable displacement over Delta_u (ASCE 41: Delta_u)."""
    usable = checks.usable[code]
    return 1.0 if usable is None else usable / delta_u


@dataclasses.dataclass(frozen=True)
class Panel:
    """One scene's panel: its title and dynamics() frame."""
    title: str
    frame: pd.DataFrame


def plot(panels, checks, delta_u, title):
    """A figure with one axes per Panel: each record's s1/Delta_u against K_d (kN/m per m, log),
    collapse drawn at COLLAPSE_Y, each code's usable displacement as a dashed line in its colour and
    a mark in its colour at every K_d where it is unconservative; one legend for the figure."""
    fig, axes = plt.subplots(1, len(panels), figsize=(6.2 * len(panels), 5.6), sharey=True, squeeze=False)
    handles, lines, marks = {}, {}, {}   # records, the codes' lines, their marks: the legend's order
    for ax, panel in zip(axes[0], panels):
        for (name, d), (colour, marker) in zip(panel.frame.groupby("record", sort=False), RECORD_STYLES):
            y = np.where(d.collapsed, COLLAPSE_Y, d.ratio)
            (line,) = ax.plot(d.kd / 1e3, y, color=colour, marker=marker, lw=1, ms=5, label=name)
            handles.setdefault(name, line)
        flagged = unconservative_kds(checks, panel.frame)
        for i, (code, result) in enumerate(checks.results.items()):
            colour = CODE_COLOURS[code]
            line = ax.axhline(code_line_y(checks, code, delta_u), color=colour, ls="--", lw=1.2,
                              label=code_label(code, result))
            lines.setdefault(line.get_label(), line)
            kds = np.asarray(flagged[code], float) / 1e3
            if kds.size:
                label = f"{assessment_codes.LABELS[code]} unconservative"
                mark = ax.scatter(kds, np.full(kds.size, FLAG_Y + 0.06 * i), marker="v", s=46, color=colour,
                                  label=label, zorder=3)
                marks.setdefault(label, mark)
        ax.set_xscale("log")
        ax.set_xlabel("K_d [kN/m per m]")
        ax.set_title(panel.title, fontsize=10)
        ax.set_ylim(0, FLAG_Y + 0.06 * len(checks.results) + 0.04)
        ax.set_yticks([0, 0.2, 0.4, 0.6, 0.8, 1.0, COLLAPSE_Y], ["0", "0.2", "0.4", "0.6", "0.8", "1", "collapse"])
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("peak s1 / Δu")
    fig.suptitle(title, fontsize=10)
    handles.update(lines)
    handles.update(marks)
    fig.legend(list(handles.values()), list(handles), loc="lower center", ncol=2, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.2, 1, 0.95))
    return fig

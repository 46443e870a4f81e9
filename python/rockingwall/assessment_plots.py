"""The plots of `rockingwall assess`: an IDA plot per record and the fragility curves."""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from scipy import stats


def ida(cases, wall, states, im_name, path):
    """Peak s1 against the intensity, one line per K_d, collapses crossed, limit states drawn."""
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for kd, d in cases.groupby("Kd_kN_per_m_per_m"):
        d = d.sort_values("im")
        line, = ax.plot(d.peak_s1_mm, d.im, "o-", ms=3, lw=1, label=f"K_d = {kd:g} kN/m per m")
        c = d[d.collapsed]
        ax.plot(c.peak_s1_mm, c.im, "x", color=line.get_color(), ms=8)
    for s in states:
        if s.quantity == "s1":
            ax.axvline(s.threshold * 1e3, color="r", lw=0.7, ls="--")
            ax.text(s.threshold * 1e3, ax.get_ylim()[1], f" {s.name}", color="r", fontsize=7, va="top", rotation=90)
    ax.set_xlabel("peak s1, mid-height [mm]  (x: collapse)")
    ax.set_ylabel(im_name)
    ax.set_title(f"{cases.record.iloc[0]}: {wall.describe()}", fontsize=7)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110, format="png")
    plt.close(fig)


def fragility(frag, im_name, path):
    """One panel per limit state: the fitted curve per K_d with its 90 % band of medians."""
    names = list(dict.fromkeys(frag.limit_state))
    fig, axes = plt.subplots(1, len(names), figsize=(3.2 * len(names), 3.2), squeeze=False, sharey=True)
    fits = frag.dropna(subset=["median"])
    top = 2 * fits.median_95.max() if len(fits) and np.isfinite(fits.median_95.max()) else 1.0
    x = np.linspace(1e-3, top, 300)
    for ax, name in zip(axes[0], names):
        for r in frag[frag.limit_state == name].itertuples(index=False):
            if np.isnan(r.median):
                continue
            line, = ax.plot(x, stats.norm.cdf(np.log(x / r.median) / r.beta), lw=1.2,
                            label=f"K_d = {r.Kd_kN_per_m_per_m:g}")
            if np.isfinite(r.median_5):
                ax.axvspan(r.median_5, r.median_95, color=line.get_color(), alpha=0.12)
        ax.set_title(name, fontsize=8)
        ax.set_xlabel(im_name)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("P(reached)")
    if axes[0][0].get_legend_handles_labels()[0]:  # no fit at all: nothing to name
        axes[0][0].legend(fontsize=6, title="kN/m per m", title_fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=110, format="png")
    plt.close(fig)

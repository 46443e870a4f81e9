"""The plots of `rockingwall assess`: an IDA plot per record and the fragility curves. Every group
(a K_d, or a building's storey) has one colour in every panel, whichever groups have a fit."""

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from scipy import special

from . import figure_titles
from .assessment import KD_COLUMN, group_label
from .sweep.fragility import clipped, gap_median


def colours(values):
    """{group value: colour}, the same in every plot of a study (NaN: one group)."""
    keys = sorted({v for v in values if np.isfinite(v)}) or [np.nan]
    return {k: f"C{i % 10}" for i, k in enumerate(keys)}


def _key(value):
    return value if np.isfinite(value) else np.nan


def _colour(palette, value):
    return palette[value] if np.isfinite(value) else next(iter(palette.values()))


def ida(cases, title, states, im_name, path, column=KD_COLUMN, delta_u_mm=None):
    fig = ida_figure(cases, title, states, im_name, column, delta_u_mm)
    fig.savefig(path, dpi=110, format="png")
    plt.close(fig)


def ida_figure(cases, title, states, im_name, column=KD_COLUMN, delta_u_mm=None):
    """Peak s1 against the intensity, one line per group; collapses as crosses in their own column
    at the right (a collapsed wall's peak is no displacement), limit states on s1 drawn; the legend
    below the axes (inside them it hid the collapses' column and the ensembles' bands)."""
    groups = cases[column].nunique() if column in cases else 1
    fig, ax = plt.subplots(figsize=(6.5, 4.4 + 0.15 * ((groups + 2) // 3)))
    palette = colours(cases[column]) if column in cases else {np.nan: "C0"}
    standing_max = np.nanmax(cases.peak_s1_mm.to_numpy(dtype=float), initial=0.0)
    thresholds = [s.threshold * 1e3 for s in states if s.quantity == "s1"]
    x_collapse = 1.1 * max([standing_max, *thresholds, delta_u_mm or 0.0, 1.0])
    by_group = cases.groupby(column) if column in cases and cases[column].notna().any() else [(np.nan, cases)]
    for value, d in by_group:
        d = d.sort_values("im")
        colour = _colour(palette, value)
        label = group_label(column, value) if np.isfinite(value) else "peak s1"
        x = np.where(d.collapsed, x_collapse, d.peak_s1_mm)
        ax.plot(x, d.im, "o-", ms=3, lw=1, color=colour, label=label)
        ax.plot(x[d.collapsed.to_numpy()], d.im[d.collapsed], "x", color=colour, ms=8)
        if "s1_p16_mm" in d:  # the ensemble's 16-84 % peaks, a collapse at the collapse column
            lo, hi = (np.minimum(d[c].to_numpy(dtype=float), x_collapse) for c in ("s1_p16_mm", "s1_p84_mm"))
            ax.hlines(d.im, lo, hi, color=colour, lw=3, alpha=0.25)
    ax.axvline(x_collapse, color="0.6", lw=0.5)
    ax.text(x_collapse, 1.0, "collapse ", transform=ax.get_xaxis_transform(), ha="right", va="top", fontsize=7,
            color="0.3")
    for s in states:
        if s.quantity == "s1":
            ax.axvline(s.threshold * 1e3, color="r", lw=0.7, ls="--")
            ax.text(s.threshold * 1e3, 0.98, f" {s.name}", transform=ax.get_xaxis_transform(), color="r",
                    fontsize=7, va="top", rotation=90)
    ax.set_xlim(left=0)
    ax.set_xlabel("peak s1, mid-height [mm]  (x: collapse; bands: the ensemble's 16-84 %)")
    ax.set_ylabel(im_name)
    ax.set_title(figure_titles.wrapped(title, 90), fontsize=7)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=3, frameon=False)
    fig.tight_layout()
    return fig


def fragility_figure(frag, im_name, column=KD_COLUMN, title=""):
    """One panel per limit state: the fitted curve of every group in its own colour (solid: over
    the records; dashed: over the records and the ensembles' parameters), its 90 % band of
    medians, and a legend entry for every group, those without an estimate or without an
    identified dispersion (beta 0: the data do not overlap) said so."""
    names = list(dict.fromkeys(frag.limit_state))
    # the legends stand below their panels (over them they hid the curves' rise): room for their
    # lines, a second one where a median is only a gap
    lines = max(len(rows) + int((rows.beta == 0).sum()) for _, rows in frag.groupby("limit_state"))
    fig, axes = plt.subplots(1, len(names), figsize=(3.4 * len(names), 3.9 + 0.14 * lines), squeeze=False,
                             sharey=True)
    palette = colours(frag[column]) if column in frag else {np.nan: "C0"}
    fits = frag.dropna(subset=["median"])
    ends = fits.median_95[np.isfinite(fits.median_95)]
    top = 2 * max(ends.max() if len(ends) else 0.0, fits["median"].max() if len(fits) else 0.5)
    x = np.linspace(1e-3, top, 300)
    for ax, name in zip(axes[0], names):
        for r in frag[frag.limit_state == name].to_dict("records"):
            value = r.get(column, np.nan)
            colour = _colour(palette, value)
            label = (group_label(column, value) if np.isfinite(value) else "fit")
            solid = r.get("over", "records") == "records"
            if not solid:
                label += " (with parameters)"
            if np.isnan(r["median"]):
                ax.plot([], [], color=colour, ls="-" if solid else "--", lw=1.2, label=f"{label}: no estimate")
                continue
            p = (np.log(x / r["median"]) > 0).astype(float) if r["beta"] == 0 else special.ndtr(
                np.log(x / r["median"]) / r["beta"])
            if r["beta"] == 0:  # the data do not overlap: a step anywhere in the gap, not a known median
                label += ": beta not identified"
                gap = (r.get("gap_lo", np.nan), r.get("gap_hi", np.nan))
                if np.isfinite(gap[0]):  # where the median may be: shaded, and said on a second line
                    label += f"\n  median {gap_median(gap, 3)}"
                    ax.axvspan(*clipped(gap, top), color=colour, alpha=0.12, lw=0)
            ax.plot(x, p, color=colour, ls="-" if solid else "--", lw=1.2, label=label)
            if solid and r["beta"] != 0 and np.isfinite(r["median_5"]) and np.isfinite(r["median_95"]):
                ax.axvspan(r["median_5"], r["median_95"], color=colour, alpha=0.12)
        ax.set_title(name, fontsize=8)
        ax.set_xlabel(im_name)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6, loc="upper center", bbox_to_anchor=(0.5, -0.2), frameon=False)
    axes[0][0].set_ylabel("P(reached)")
    if title:
        figure_titles.suptitle(fig, title, 7)
    fig.tight_layout()
    return fig


def fragility(frag, im_name, path, column=KD_COLUMN, title=""):
    fig = fragility_figure(frag, im_name, column, title)
    fig.savefig(path, dpi=110, format="png")
    plt.close(fig)

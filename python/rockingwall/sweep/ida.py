"""Incremental dynamic analysis, collapse fragility and the K_d x intensity map from the results
file of a sweep (one wall, model and hinge law at a time): the runs read back, and the three
plots of `rockingwall ida`. A run that collapsed has no meaningful peak (the run stops at the
instability point): the IDA curves end there with a cross, and the medians count it as larger
than any peak."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.ticker
import numpy as np

from .. import figure_titles, outputs, scenes
from . import fragility, store
from .rows import ERROR, OK, RETRIED

def report_not_ok(d, path):
    """Killed or timed-out runs are the ones most likely near collapse: leaving them out biases the
    fragility, so they are named, not dropped silently."""
    unfinished = d[d.status.isin(RETRIED)]
    if len(unfinished):
        print(f"{path}: {len(unfinished)} runs were killed or timed out and are NOT in the plots (often the runs "
              f"nearest collapse), e.g. {unfinished.run_id.iloc[0]}: {unfinished.message.iloc[0]}; "
              "resume the sweep (the same rockingwall sweep command) to run them again", file=sys.stderr)
    failed = d[d.status == ERROR]
    if len(failed):
        print(f"{path}: {len(failed)} runs failed and are left out, e.g. {failed.record.iloc[0]}: "
              f"{failed.message.iloc[0]}", file=sys.stderr)


# the columns that pick one set of runs: (column, its name in a message, the option that chooses it)
CHOICES = (("wall", "walls", "--wall"), ("model", "models", "--model"), ("hinge_law", "hinge laws", "--hinge-law"))


def load(path, wall=None, model=None, hinge_law=None):
    """The 'ok' runs of one wall, model and hinge law (each None: the file's only one among the
    runs chosen so far, else the user must say which); damaged lines of the file are named and
    left out (rockingwall.sweep.store), and a run_id written twice counts once (the last row)."""
    d = store.load_frame(path)
    report_not_ok(d, path)
    d.attrs["unfinished"] = int(d.status.isin(RETRIED).sum())
    d = d[d.status == OK]
    if d.empty:
        raise ValueError(f"{path}: no successful runs")
    for (column, plural, option), given in zip(CHOICES, (wall, model, hinge_law)):
        values = sorted(d[column].unique())
        if given is None and len(values) > 1:
            raise ValueError(f"{path}: runs of {len(values)} {plural} ({', '.join(values)}): choose one with {option}")
        given = values[0] if given is None else _named(values, str(given))
        if given not in values:
            raise ValueError(f"{path}: no successful runs with {option} {given} (here: {', '.join(values)})")
        d = d[d[column] == given]
    _check_one_study(d, path)
    return d


def _check_one_study(d, path):
    """Refuses runs of one case (K_d, record, intensity) computed from different inputs: a building
    file edited under the same name, a wall's values changed between two sweeps into one file, or
    two files joined. Their peaks would be mixed into one curve and one fragility."""
    keys = d.groupby(["kd_kN", "record", "pga_g"], dropna=False)["key"].nunique()
    twice = keys[keys > 1]
    if len(twice):
        kd, record, pga = twice.index[0]
        raise ValueError(f"{path}: {len(twice)} runs of {d.wall.iloc[0]} are in the file twice, computed from "
                         f"different inputs (e.g. {record} at PGA {pga:.3g} g, K_d {kd:g} kN/m per m): one results "
                         "file holds one study; sweep the inputs you mean into a new --out file")


def scene(d):
    """The scene of a frame load() chose (one wall and model): scenes.swept's."""
    return scenes.swept(d.model.iloc[0])


def _named(values, given):
    """The value `given` names: itself, or the one storey of a building sweep's walls it names on its
    own ('storey 2' or '2' for 'two-storey brick, timber floors: storey 2'); else `given` unchanged."""
    if given in values:
        return given
    named = [v for v in values if v.rpartition(": ")[2] in (given, f"storey {given}")]
    return named[0] if len(named) == 1 else given


def collapse_column(d, q):
    """Where a panel of q (peak_s1 or peak_s2) draws collapses [mm]: right of every standing peak."""
    standing = 1000 * d.loc[~d.collapsed.astype(bool), q].to_numpy(dtype=float)
    return 1.3 * max(np.nanmax(standing, initial=0.0), 1.0)


def save(fig, path):
    """A figure into its PNG (through a temporary file), then closed."""
    outputs.write_png(fig, path, "--out")
    plt.close(fig)


def ida_curves(d, path):
    save(ida_curves_figure(d), path)


def ida_curves_figure(d):
    """Peak s1 and s2 against PGA per K_d, a line per record up to its first collapse, the median."""
    kds = sorted(d.kd_kN.unique())
    fig, axes = plt.subplots(2, len(kds), figsize=(3.2 * len(kds), 6.0), sharex=True, sharey="row", squeeze=False)
    # a collapse in its own column at the right, one per quantity for every K_d: a collapsed run's
    # peaks end at the state it fell from (s2 anywhere, 40 mm at 0.5 g read as a small response)
    columns = {q: collapse_column(d, q) for q in ("peak_s1", "peak_s2")}
    for j, kd in enumerate(kds):
        dk = d[d.kd_kN == kd]
        for i, q in enumerate(["peak_s1", "peak_s2"]):
            ax = axes[i, j]
            x_collapse = columns[q]
            for _, r in dk.groupby("record"):
                r = r.sort_values("pga_g")
                first = r.collapsed.values.argmax() if r.collapsed.any() else len(r)
                alive = r.iloc[:first]  # the curve up to the first collapse
                # a dot at each level: a record standing at one level only is a single point
                ax.plot(1000 * alive[q], alive.pga_g, "o-", lw=0.6, ms=2, alpha=0.5, color="tab:blue")
                if first < len(r):
                    ax.plot(x_collapse, r.pga_g.iloc[first], "x", ms=3, color="tab:red", alpha=0.6)
            ax.axvline(x_collapse, color="0.6", lw=0.5)
            med = dk.assign(v=np.where(dk.collapsed, np.inf, dk[q])).groupby("pga_g").v.median()
            ax.plot(1000 * med[np.isfinite(med)], med.index[np.isfinite(med)], "o-", color="k", lw=2, ms=3,
                    label="median")
            ax.set_xscale("log")
            ax.grid(True, which="both", alpha=0.3)
            if i == 0:
                ax.set_title(f"K_d = {kd:g} kN/m per m")
            ax.set_xlabel(f"peak {'s1 (mid-height)' if q == 'peak_s1' else 's2 (top)'} [mm]")
            if j == 0:
                ax.set_ylabel("PGA [g]")
    axes[0, 0].legend(loc="upper left", fontsize=8)
    _name_scene(fig, d, "IDA curves: one line per record component, x = collapse (in its own column at the right)")
    fig.tight_layout()
    return fig


def _name_scene(fig, d, head="", fontsize=8):
    """The figure's title: `head` (a line) over the wall and the scene its runs ran in, wrapped to
    the figure's width."""
    named = f"wall: {d.wall.iloc[0]}; scene: {scene(d).title}"
    figure_titles.suptitle(fig, f"{head}\n{named}" if head else named, fontsize)


def fragility_table(fits, n_records):
    """The fits of fragility_plot as lines to print, with what the data cannot support."""
    # a median the data do not place is where it may be ('above 0.3'), in a column as wide as that
    medians = {kd: fragility.gap_median(f.gap, 3) if f.gap else f"{f.theta:.3f}" for kd, f in fits.items()}
    width = max([len("median [g]"), *map(len, medians.values())])
    lines = [f"K_d [kN/m per m] {'median [g]':>{width + 2}}   beta   runs"]
    for kd, f in fits.items():
        lines.append(f"{kd:16g} {medians[kd]:>{width + 2}} {f.beta:6.2f} {f.n_runs:6d}"
                     + ("  (beta not identified)" if f.gap else ""))
    lines += [f"  warning: K_d = {kd:g} kN/m per m: {fragility.gap_message(f.gap, 'collapse', f.mixed)} g"
              for kd, f in fits.items() if f.gap]
    if n_records < fragility.MIN_RECORDS:
        lines.append(f"  warning: only {n_records} record{'s' if n_records != 1 else ''} (fewer than "
                     f"{fragility.MIN_RECORDS}): the median and above all the dispersion beta are poorly constrained")
    return lines


def fragility_figure(d):
    """The collapse fragility per K_d: (figure, {K_d: Fragility}). A fit whose data do not overlap
    is a dashed step over its gap, shaded, where the median may lie anywhere."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    x = np.linspace(d.pga_g.min(), d.pga_g.max(), 300)
    fits = {}
    for kd, color in zip(sorted(d.kd_kN.unique()), plt.cm.viridis(np.linspace(0, 0.9, d.kd_kN.nunique()))):
        dk = d[d.kd_kN == kd]
        levels, n, z = fragility.counts(dk.pga_g, dk.collapsed)
        ax.plot(levels, z / n, "o", color=color, ms=4)
        try:
            f = fragility.fit(dk.pga_g, dk.collapsed)
        except ValueError as exc:
            print(f"K_d = {kd:g} kN/m per m: {exc}")
            continue
        fits[kd] = f
        if f.gap is None:
            ax.plot(x, f(x), color=color, label=f"K_d = {kd:g} kN/m per m: median {f.theta:.3f} g, beta {f.beta:.2f}")
        else:
            ax.axvspan(*fragility.clipped(f.gap, x[-1]), color=color, alpha=0.12, lw=0)
            ax.plot(x, f(x), "--", color=color, label=f"K_d = {kd:g} kN/m per m: median {fragility.gap_median(f.gap, 3)} g, "
                                                       "beta not identified")
    ax.set_xlabel("PGA [g]")
    ax.set_ylabel("P(collapse)")
    ax.set_ylim(-0.02, 1.02)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title("Collapse fragility (dots: fraction of records; lines: lognormal MLE)", fontsize=10)
    _name_scene(fig, d, fontsize=7)
    fig.tight_layout()
    return fig, fits


def fragility_plot(d, path):
    """fragility_figure written to path (PNG): the fits."""
    fig, fits = fragility_figure(d)
    save(fig, path)
    return fits


def kd_map(d, path):
    save(kd_map_figure(d), path)


def plain_numbers(colorbar):
    """A log colour scale's ticks as plain numbers: over less than a decade matplotlib labels them
    '3.7 x 10^1', which no one reads as 37 mm at a glance (the minor ticks are labelled only then:
    over decades they would crowd)."""
    plain = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    colorbar.ax.yaxis.set_major_formatter(plain)
    within_a_decade = colorbar.norm.vmax < 10 * colorbar.norm.vmin
    colorbar.ax.yaxis.set_minor_formatter(plain if within_a_decade else matplotlib.ticker.NullFormatter())
    colorbar.ax.tick_params(which="both", labelsize=7)


def kd_map_figure(d):
    """Median peaks s1 and s2 per K_d and PGA (cells), the median run's collapse grey, and the
    16/50/84 % collapse contours."""
    kds = np.array(sorted(d.kd_kN.unique()))
    pgas = np.array(sorted(d.pga_g.unique()))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), sharey=True)
    for ax, q, label in zip(axes, ["peak_s1", "peak_s2"], ["s1 (mid-height)", "s2 (top)"]):
        v = d.assign(v=np.where(d.collapsed, np.inf, 1000 * d[q]))
        med = v.pivot_table(index="pga_g", columns="kd_kN", values="v", aggfunc="median").reindex(index=pgas, columns=kds)
        frac = d.pivot_table(index="pga_g", columns="kd_kN", values="collapsed", aggfunc="mean").reindex(index=pgas, columns=kds)
        shown = np.ma.masked_invalid(np.where(np.isfinite(med.values), med.values, np.nan))
        # cells, not coordinates, on both axes: K_d spans 3 decades and the PGA levels are denser
        # where the wall still stands, so each level gets the same room
        xe, ye = np.arange(len(kds) + 1) - 0.5, np.arange(len(pgas) + 1) - 0.5
        mesh = ax.pcolormesh(xe, ye, shown, cmap="magma_r",
                             norm=matplotlib.colors.LogNorm(vmin=max(shown.min(), 0.1), vmax=shown.max()))
        ax.pcolormesh(xe, ye, np.ma.masked_where(np.isfinite(med.values), np.ones_like(med.values)),
                      cmap=matplotlib.colors.ListedColormap(["0.55"]))
        if len(kds) >= 2 and len(pgas) >= 2:  # a contour needs a 2 x 2 grid at least
            cs = ax.contour(np.arange(len(kds)), np.arange(len(pgas)), frac.values, levels=[0.16, 0.5, 0.84],
                            colors=["w", "c", "b"], linewidths=1.2)
            ax.clabel(cs, fmt=lambda p: f"{p:.0%} collapse", fontsize=7)
        ax.set_xticks(np.arange(len(kds)), [f"{k:g}" for k in kds], rotation=45)
        ax.set_yticks(np.arange(len(pgas)), [f"{x:g}" for x in pgas], fontsize=7)
        ax.set_xlabel("K_d [kN/m per m]")
        ax.set_title(f"median peak {label} [mm]; grey: median run collapses", fontsize=9)
        plain_numbers(fig.colorbar(mesh, ax=ax))
    axes[0].set_ylabel("PGA [g]")
    _name_scene(fig, d)
    fig.tight_layout()
    return fig

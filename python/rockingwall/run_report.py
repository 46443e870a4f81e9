"""Runs of one wall for people: the peaks of simulate()'s results as a table, one result's time
histories as a plot (what `rockingwall run` prints and writes)."""
from .building import reports


def table(wall, results):
    """The wall, the scene, and a row per record: its PGA as run, the peaks (a collapsed wall's
    shown as its collapse, never as a displacement), and the ensemble's columns if one ran."""
    ensemble = any(r.ensemble is not None for r in results)
    width = reports.record_width(results)
    lines = [f"wall: {wall.describe()}", results[0].scene.text(), f"Delta_u = {wall.delta_u * 1e3:.1f} mm",
             f"{'record':<{width}}{'PGA [g]':>8}{'peak s1 [mm]':>13}{'peak s2 [mm]':>13}{'s1/Delta_u':>11}{'impacts':>9}"
             f"  {'collapse':<22}" + ("  P(collapse)  s1 16/50/84 % [mm]" if ensemble else "")]
    lines[-1] = lines[-1].rstrip()
    for r in results:
        collapse = f"collapsed at {r.t_collapse:.2f} s" if r.collapsed else "no"
        s1, s2, ratio = ("-", "-", "-") if r.collapsed else (f"{r.peak_s1 * 1e3:.1f}", f"{r.peak_s2 * 1e3:.1f}",
                                                             f"{r.s1_over_delta_u:.2f}")
        line = f"{r.record:<{width}}{r.pga_g:>8.3g}{s1:>13}{s2:>13}{ratio:>11}{r.impacts:>9}  {collapse:<22}"
        if r.ensemble is not None:
            e = r.ensemble
            spread = " / ".join("collapse" if v == float("inf") else f"{v * 1e3:.0f}" for v in e.s1_percentiles)
            line += f"  {e.collapse_probability:>11.2f}  {spread}" + ("  FLIPS" if e.flips else "")
        lines.append(line.rstrip())
    lines += reports.sensitivity_lines(results)
    lines += reports.near_collapse_lines([(r.record, r.s1_over_delta_u) for r in results
                                          if not r.collapsed and r.ensemble is None],
                                         "--ensemble 100 runs 100 walls within the inputs' uncertainty and gives "
                                         "the probability of collapse (docs/robustness.md)")
    engines = sorted({r.engine for r in results if r.engine != "exact"})
    lines += [f"solved by {_solver_words(name)}" for name in engines]
    if ensemble:
        e = next(r.ensemble for r in results if r.ensemble is not None)
        lines.append(f"ensemble: {e.size} runs per record within the inputs' uncertainty; FLIPS: the nominal "
                     "outcome (collapse, a limit state) differs in at least 5 % of them")
    return "\n".join(lines)


def _solver_words(engine):
    """An engine's name as a reader takes it: 'scene (exact)' is the scene solver, which runs the
    wall, its tie and the diaphragm in one integration."""
    if engine.startswith("scene (") and engine.endswith(")"):
        return f"the scene solver ({engine[7:-1]}): the wall, its tie and the diaphragm in one integration"
    return engine


def plot(result, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    h = result.history
    fig, (ax_ag, ax_s) = plt.subplots(2, 1, figsize=(9, 4.5), sharex=True, height_ratios=[1, 2])
    ax_ag.plot(h["time"], h["ag"] / 9.81, lw=0.6, color="0.3")
    ax_ag.set_ylabel("ag [g]")
    t_collapse = result.t_collapse if result.collapsed else None
    mark = reports.draw_wall(ax_s, h["time"], h["s1"] * 1e3, t_collapse, lw=0.8, color="C0", label="s1, mid-height [mm]")
    reports.draw_wall(ax_s, h["time"], h["s2"] * 1e3, t_collapse, lw=0.8, color="C1", label="s2, top [mm]")
    du = result.wall.delta_u * 1e3
    ax_s.axhline(du, color="r", lw=0.6, ls="--", label=f"Delta_u = {du:.0f} mm")
    ax_s.axhline(-du, color="r", lw=0.6, ls="--")
    ax_s.set_ylabel("displacement [mm]")
    ax_s.set_xlabel("time [s]")
    if mark is not None:
        reports.legend_collapse_last(ax_s, mark, t_collapse, fontsize=8, loc="upper right")
    else:
        ax_s.legend(fontsize=8, loc="upper right")
    for ax in (ax_ag, ax_s):
        ax.grid(alpha=0.3)
    fig.suptitle(f"{result.record}: {result.wall.describe()}\nscene: {result.scene.title}", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110, format="png")
    plt.close(fig)

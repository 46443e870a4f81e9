"""A building's response for people and programs: the table `rockingwall building` prints, its
strict JSON (null, never NaN), the time histories as CSV and a plot per record."""
import numpy as np
import pandas as pd

from .. import figure_titles, limits, scenes, strict_json
from ..units import history_column
from .floor_acc import CUTOFF_HZ
from .monolithic import SENSITIVITY_PERTURBATION, SENSITIVITY_SHARE


def _collapse(s):
    if not s.wall:
        return "no wall"
    return f"collapsed at {s.t_collapse_s:.2f} s" if s.collapsed else "standing"


# what the floor's peak accelerations are, said wherever they are printed
COLLAPSED_PEAKS_NOTE = ("peak_s1_m, peak_s2_m, s1_over_Delta_u: null for a collapsed wall (the run stops at its "
                        "instability point: no displacement; its collapse is t_collapse_s)")
FLOOR_ACC_NOTE = (f"base_peak_acc_m_s2: the peak absolute acceleration of the floor the wall stands on, low-pass "
                  f"filtered at {CUTOFF_HZ:g} Hz (4th-order Butterworth, zero phase): the floor's motion walls, parts "
                  f"and contents feel, independent of the tie's stiffness; for the ground storey the record's "
                  f"filtered PGA (docs/your-building.md, \"Floor acceleration\")")
FLOOR_ACC_RAW_NOTE = ("base_peak_acc_raw_m_s2: the same peak unfiltered: above the ground it carries the tie's "
                      "ringing after each impact and grows with the tie's stiffness, so it is no design value")
FLOOR_ACC_UNRESOLVED = ("the floor's acceleration was sampled at the finest interval tried and its filtered peak "
                        "still depends on the sampling (floor_acc.resolved false): read it as approximate")
# what the ties' peak forces are
TIE_FORCE_NOTE = (f"tie_force_N_per_m: the peak force of the wall-to-diaphragm tie on the diaphragm, low-pass "
                  f"filtered at {CUTOFF_HZ:g} Hz as the floor's acceleration: what the diaphragm's spring, dashpot "
                  f"and mass put on the connection, independent of the tie's stiffness; null for a wall that "
                  f"collapsed (docs/your-building.md, \"Tie force\")")
TIE_FORCE_RAW_NOTE = ("tie_force_raw_N_per_m: the same peak unfiltered: the tie's ringing after each impact, which "
                      "grows with the tie's stiffness, so it is no design value")
TIE_FORCE_UNRESOLVED = ("the ties' forces were sampled at the finest interval tried and their filtered peaks still "
                        "depend on the sampling (tie_force.resolved false): read them as approximate")


# what a sensitive run's peaks mean, said wherever they are printed
SENSITIVITY_NOTE = (f"peak_sensitivity: the largest relative change of a wall's peak s1 or s2 when the record is "
                    f"scaled by 1 -/+ {SENSITIVITY_PERTURBATION:g} (1 where a collapse comes or goes); above "
                    f"{SENSITIVITY_SHARE:g} the motion is sensitive (impacts through a stiff tie): its peaks are one "
                    f"sample of a spread that no solver's tolerance narrows, not digits to trust "
                    f"(docs/your-building.md, \"Tie\")")


def sensitivity_lines(results):
    """A line for each result whose peaks the sensitivity check found sensitive (results with
    `record`, `peak_sensitivity` and `sensitive`: a BuildingResult, or api.Result of a scene)."""
    return [f"sensitive: {r.record}: a change of {SENSITIVITY_PERTURBATION:g} in the record's scale moves a peak by "
            f"{r.peak_sensitivity:.1%}{' or flips a collapse' if r.peak_sensitivity >= 1.0 else ''}; these peaks are "
            f"one sample of a spread, not digits to trust ({_spread(r)})"
            for r in results if r.sensitive]


def near_collapse_lines(cases, remedy):
    """A line naming the standing walls near collapse (limits.near_collapse; cases: (label,
    s1/Delta_u) of standing walls), with where their spread comes from (`remedy`); none if none."""
    near = [f"{label} (s1 = {ratio:.2f} Delta_u)" for label, ratio in cases if limits.near_collapse(ratio, False)]
    if not near:
        return []
    return [f"near collapse: {'; '.join(near)}: standing past {limits.USABLE_SHARE:g} Delta_u, where rocking is chaotic "
            f"and a small change of the inputs can turn standing into collapse; one run is one sample of that "
            f"spread: {remedy}"]


def _spread(result):
    """Where the spread of a sensitive result comes from: the tie of a scene with one, else an ensemble."""
    if getattr(result, "scene", None) is not None and result.scene.key == "paper":
        return "an ensemble (--ensemble 100) or more records give the spread: docs/robustness.md"
    return "a softer tie or more records give the spread: docs/your-building.md, \"Tie\""


def _floor(s):
    return "-" if s.base_peak_acc_m_s2 is None else f"{s.base_peak_acc_m_s2 / 9.81:.3f}"


def _tie(s):
    return "-" if s.tie_force_N_per_m is None else f"{s.tie_force_N_per_m / 1e3:.2f}"


def record_width(results):
    """The record column's width: the longest record's name and two spaces (a name cut short could
    not be told from another record's at another intensity)."""
    return max(len("record"), *(len(r.record) for r in results)) + 2


def table(building, results):
    """The building echoed with units, the scene, then one row per storey and record."""
    width = record_width(results)
    lines = [building.describe(), scenes.building(building).text(), "",
             f"{'record':<{width}}{'storey':>7}{'peak s1 [mm]':>14}{'peak s2 [mm]':>14}{'s1/Delta_u':>12}"
             f"{'diaphragm [mm]':>16}{'floor acc [g]':>15}{'tie [kN/m]':>12}  collapse"]
    for r in results:
        for s in r.storeys:
            shown = s.wall and not s.collapsed
            s1 = f"{s.peak_s1_m * 1e3:.1f}" if shown else "-"
            s2 = f"{s.peak_s2_m * 1e3:.1f}" if shown else "-"
            ratio = f"{s.s1_over_delta_u:.2f}" if shown else "-"
            lines.append(f"{r.record:<{width}}{s.storey:>7}{s1:>14}{s2:>14}{ratio:>12}"
                         f"{s.diaphragm_peak_m * 1e3:>16.1f}{_floor(s):>15}{_tie(s):>12}  {_collapse(s)}")
    lines.append("peaks relative to each wall's own base; a collapsed wall's peaks are not displacements (-), and a "
                 "storey without a wall has none; "
                 f"floor acc: the floor the wall stands on, absolute, and tie: the tie's force on the diaphragm "
                 f"(none for a collapsed wall), both low-pass filtered at {CUTOFF_HZ:g} Hz (the raw peaks, which grow "
                 "with the tie's stiffness, are in --json)")
    if any(r.floor_resolved is False for r in results):
        lines.append(f"warning: {FLOOR_ACC_UNRESOLVED}")
    if any(r.tie_resolved is False for r in results):
        lines.append(f"warning: {TIE_FORCE_UNRESOLVED}")
    near = near_collapse_lines([(f"{r.record}, storey {s.storey}", s.s1_over_delta_u) for r in results
                                for s in r.storeys if s.wall and not s.collapsed],
                               "rockingwall assess --building FILE RECORDS --pga ... runs an ensemble of buildings "
                               "and gives each storey's probability of collapse (docs/robustness.md)")
    return "\n".join(lines + sensitivity_lines(results) + near)


def to_json(building, results):
    """{"scene", "building", "runs": [{"record", "solver", "storeys": [...], "energy"}]}; each
    storey with peak_s1_m, peak_s2_m, collapsed, t_collapse_s (null if standing), diaphragm_peak_m,
    base_peak_acc_m_s2 (filtered), and also base_peak_acc_raw_m_s2, tie_force_N_per_m (filtered;
    null for a collapsed wall), tie_force_raw_N_per_m, delta_u_m, s1_over_Delta_u, impacts."""
    return strict_json.clean({"scene": scenes.building(building).to_dict(),
                   "building": {"name": building.name, "file": building.source, "description": building.describe()},
                   "notes": {"peak_s1_m": COLLAPSED_PEAKS_NOTE, "base_peak_acc_m_s2": FLOOR_ACC_NOTE,
                             "base_peak_acc_raw_m_s2": FLOOR_ACC_RAW_NOTE,
                             "tie_force_N_per_m": TIE_FORCE_NOTE, "tie_force_raw_N_per_m": TIE_FORCE_RAW_NOTE,
                             "peak_sensitivity": SENSITIVITY_NOTE, "near_collapse": limits.NEAR_COLLAPSE_NOTE},
                   "runs": [r.to_dict() for r in results]})


def history_csv(histories, path, t_collapse=(), walls=()):
    """time [s] and, per storey, s1 and s2 [m] (relative to the wall's base), the diaphragm [m]
    (relative to its supports), and where computed the absolute acceleration of the floor the wall
    stands on [m/s2] and the tie's force on the diaphragm [N/m], both low-pass filtered at
    floor_acc.CUTOFF_HZ (monolithic.Histories): raw on this grid, the tie's ringing would alias
    into them. Each column's name carries its unit and storey (units.history_column: s1_m_1).
    t_collapse: each storey's collapse time (None or NaN: standing); after it the wall's s1, s2 and
    tie force are empty cells, as `rockingwall run` writes them: the run holds the state the wall
    collapsed at, which is no displacement, and a collapsed wall pulls on no tie. walls: whether
    each storey has a wall (those cells of one without are empty throughout)."""
    scene = histories.scene
    n = scene.s1.shape[1]
    per_storey = {"s1": scene.s1, "s2": scene.s2, "diaphragm": scene.diaphragm}
    for name, filtered in (("floor_acc", histories.floor_acc), ("tie_force", histories.tie_force)):
        if filtered is not None:
            per_storey[f"{name}_{CUTOFF_HZ:g}Hz"] = filtered
    table = pd.DataFrame({"time": scene.t} | {history_column(name, i + 1): np.asarray(a[:, i], dtype=float)
                                              for i in range(n) for name, a in per_storey.items()})

    def wall_columns(i):  # the columns of storey i's wall (the diaphragm's and the floor's are not)
        return [history_column(name, i + 1) for name in per_storey if name in ("s1", "s2") or name.startswith("tie_force")]
    for i, t_c in enumerate(t_collapse):
        blank_after_collapse(table, t_c, wall_columns(i))
    for i in np.flatnonzero(~np.asarray(walls, dtype=bool)):  # a storey without a wall: no wall's history
        table[wall_columns(i)] = np.nan
    table.rename(columns={"time": history_column("time")}).to_csv(path, index=False, float_format="%.9g", na_rep="")


def blank_after_collapse(table, t_collapse, columns):
    """NaN in `columns` of the history `table` (its 'time' column) after t_collapse (None or NaN:
    the wall stands): the run holds the state a wall collapsed at, which is no displacement, and a
    collapsed wall pulls on no tie."""
    if t_collapse is not None and np.isfinite(t_collapse):
        table.loc[table["time"] > t_collapse, columns] = np.nan


def draw_wall(ax, t, y, t_collapse, **style):
    """A wall's history on a plot, up to its collapse (t_collapse None or NaN: standing), which an x
    marks: after it the run holds the state it collapsed at, and a line drawn on would show a wall
    leaning there to the record's end. Returns the x's line (None for a standing wall)."""
    if t_collapse is None or not np.isfinite(t_collapse):
        ax.plot(t, y, **style)
        return None
    keep = np.asarray(t) <= t_collapse
    t, y = np.asarray(t)[keep], np.asarray(y)[keep]
    ax.plot(t, y, **style)
    (mark,) = ax.plot(t[-1:], y[-1:], "x", color=style.get("color"), ms=7, mew=1.5)
    return mark


def legend_collapse_last(ax, mark, t_collapse, **style):
    """The panel's legend with draw_wall's x (`mark`) named 'collapsed at ... s', last."""
    mark.set_label(f"collapsed at {t_collapse:.2f} s")
    handles = [h for h in ax.get_legend_handles_labels()[0] if h is not mark] + [mark]
    ax.legend(handles=handles, **style)


def plot(building, result, histories, path):
    """s1 of each storey's wall and its diaphragm over time, one panel per storey (top storey first)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    history = histories.scene
    n = len(result.storeys)
    fig, axes = plt.subplots(n, 1, figsize=(9, 2.4 * n + 0.6), sharex=True, squeeze=False)
    for panel, s in zip(axes[::-1, 0], result.storeys):
        i = s.storey - 1
        if s.wall:
            draw_wall(panel, history.t, history.s1[:, i] * 1e3, s.t_collapse_s if s.collapsed else None, lw=0.8,
                      color="C0", label="wall s1 (mid-height) [mm]")
        panel.plot(history.t, history.diaphragm[:, i] * 1e3, lw=0.8, color="C1", label="diaphragm [mm]")
        if s.wall:
            du = s.delta_u_m * 1e3
            panel.axhline(du, color="C3", lw=0.6, ls="--", label=f"Delta_u = {du:.0f} mm")
            panel.axhline(-du, color="C3", lw=0.6, ls="--")
        panel.set_ylabel(f"storey {s.storey}")
        panel.set_title(f"storey {s.storey}: {_collapse(s)}", fontsize=8)
        panel.legend(fontsize=7, loc="upper right")
        panel.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    figure_titles.suptitle(fig, f"{result.record}: {building.name}\nscene: {scenes.building(building).title}", 9)
    fig.tight_layout()
    fig.savefig(path, dpi=110, format="png")
    plt.close(fig)

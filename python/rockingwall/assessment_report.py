"""What `rockingwall assess` prints: the study echoed (wall or building, K_d, Delta_u, limit
states, scene, ensemble), the cases as a table (text or Markdown), the fragilities with their
intervals to two significant figures, rounded outward ('unbounded' where the bootstrap cannot bound an end) and
the resurrections."""
import math

import numpy as np

from . import report_table
from .building import reports
from .sweep import fragility
from .assessment import KD_COLUMN, group_label, resurrection_lines


def table_rows(cases, states, column=KD_COLUMN):
    """The report table's rows (report_table.cells) of the cases."""
    rows = []
    for r in cases.to_dict("records"):
        value = r.get(column, np.nan)
        reached = [s.name for s in states if r[s.name]] + (["collapse"] if r["collapsed"] else [])
        row = dict(r, case=group_label(column, value) if np.isfinite(value) else "", reached=reached)
        row["s1_over_0.6Delta_u"] = r["s1_over_Delta_u"] / 0.6
        if "collapse_probability" not in r:
            row["collapse_probability"] = None
        rows.append(row)
    return rows


def _end(x, up, zero_unbounded=False):
    """An interval's end to two significant figures, rounded outward (down for the lower end, up
    for the upper): rounded to nearest, the upper end of 0.514's interval printed 0.51, below the
    median 0.514 printed beside it."""
    if not math.isfinite(x) or (zero_unbounded and x == 0):
        return "unbounded"
    if x == 0:
        return "0"
    step = 10.0 ** (math.floor(math.log10(abs(x))) - 1)
    units = x / step
    units = round(units) if abs(units - round(units)) < 1e-9 * abs(units) else (math.ceil if up else math.floor)(units)
    return f"{units * step:.2g}"


def fragility_line(r, column):
    """One fit as a line: median [5 %, 95 %], beta [5 %, 95 %], records."""
    where = group_label(column, r[column]) + ", " if np.isfinite(r[column]) else ""
    head = f"  {where}{r['limit_state']} (over the {r['over']})"
    if np.isnan(r["median"]):
        return f"{head}: no estimate ({r['warnings']})"
    if np.isnan(r["median_5"]):
        interval = "", ""
    else:
        interval = (f" [{_end(r['median_5'], False, True)}, {_end(r['median_95'], True, True)}]",
                    f" [{_end(r['beta_5'], False)}, {_end(r['beta_95'], True)}]")
    beta = "0 (not identified)" if r["beta"] == 0 else f"{r['beta']:.2g}{interval[1]}"
    median = f"{r['median']:.3g}{interval[0]}"
    if np.isfinite(r.get("gap_lo", np.nan)):  # the data do not overlap: no estimate inside the gap is better
        median = fragility.gap_median((r["gap_lo"], r["gap_hi"]))
    line = f"{head}: median {median}, beta {beta}, {r['records']} record{'s' if r['records'] != 1 else ''}"
    return line + (f"\n    warning: {r['warnings']}" if r["warnings"] else "")


def fragility_lines(frag, im_name, column=KD_COLUMN):
    """The fits, a warning that every fit has said once above them."""
    rows = frag.to_dict("records")
    members = any(r.get("over") == "records and parameters" for r in rows)  # none without ensembles
    lines = [f"\nfragility against {im_name} (lognormal MLE; 90 % bootstrap intervals over the records"
             + ("; 'over the records and parameters': every ensemble member's run):" if members else "):")]
    split = [r["warnings"].split(" | ") if r["warnings"] else [] for r in rows]
    common = [w for w in (split[0] if split else []) if all(w in s for s in split)]
    lines += [f"  warning: {w}" for w in common]
    for r, warnings in zip(rows, split):
        r = dict(r, warnings=" | ".join(w for w in warnings if w not in common))
        lines.append(fragility_line(r, column))
    return lines


def near_collapse_without_ensemble(cases, column=KD_COLUMN):
    """Without ensembles (--ensemble 0), the standing cases near collapse named, as `run` names
    them: each is one sample there (with ensembles, P(collapse) and the s1 spread say it)."""
    if "collapse_probability" in cases:
        return []
    labels = [(f"{r['record']} at {r['pga_g']:g} g" + (f", {group_label(column, r[column])}"
                                                        if np.isfinite(r.get(column, np.nan)) else ""),
               r["s1_over_Delta_u"]) for r in cases.to_dict("records") if not r["collapsed"]]
    return reports.near_collapse_lines(labels, "--ensemble 100 (the default) gives each case's probability of "
                                               "collapse and the spread of s1 (docs/robustness.md)")


def report(head, states, cases, frag, im_name, table="text", sa_period=None, column=KD_COLUMN, scene_text=""):
    """The whole report: head (the study's lines), the cases' table, the fragilities."""
    rows = table_rows(cases, states, column)
    lines = list(head)
    if len(cases) <= 60 or table == "md":
        if table == "md":
            lines += ["", report_table.markdown(rows, scene_text, sa_period)]
        else:
            lines += ["", report_table.text(rows, sa_period)]
    lines += near_collapse_without_ensemble(cases, column)
    lines += fragility_lines(frag, im_name, column)
    back = resurrection_lines(cases, column)
    if back:
        lines.append(f"\nresurrection (collapse at one intensity, standing at a higher one): {len(back)} cases")
        lines += [f"  {x}" for x in back]
    return "\n".join(lines)

"""The table an engineer pastes into a report: per case the record and its PGA (and Sa(T) where
asked), the peaks, s1 over 0.6 Delta_u, the limit states reached, and the ensemble's collapse
probability and 16/50/84 % peaks; a collapsed wall shown as 'collapsed at T s', never as a
displacement. As Markdown or as aligned text (`rockingwall assess --table`, Result.summary())."""
import math

from .building.reports import near_collapse_lines

COLUMNS = ("record", "PGA [g]", "Sa [g]", "case", "peak s1 [mm]", "peak s2 [mm]", "s1/0.6Δu",
           "limit states reached", "P(collapse)", "s1 16/50/84 % [mm]", "flag")
# the code checks' columns (assess --code), each shown when its code was checked
CODE_COLUMNS = ("C8 %NBS", "NTC lin/nonlin", "ASCE 41 h/t", "code unconservative")
CODE_NAMES = {"nzsee": "C8", "ntc": "NTC", "asce41": "ASCE 41"}


def _number(x, fmt):
    return "-" if x is None or not math.isfinite(x) else format(x, fmt)


def _mm(x):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return "collapse" if math.isinf(x) else f"{x:.0f}"


def cells(row):
    """One case's cells, from a dict with record, pga_g, sa_g, case, peak_s1_mm, peak_s2_mm,
    s1_over_0.6Delta_u, collapsed, t_collapse_s, reached (names), and, with an ensemble,
    collapse_probability, s1_p16_mm, s1_p50_mm, s1_p84_mm, flips."""
    collapsed = bool(row["collapsed"])
    s1 = f"collapsed at {row['t_collapse_s']:.2f} s" if collapsed else _number(row["peak_s1_mm"], ".1f")
    spread = "-"
    if row.get("collapse_probability") is not None and math.isfinite(row.get("collapse_probability", math.nan)):
        spread = " / ".join(_mm(row[f"s1_p{p}_mm"]) for p in (16, 50, 84))
    return {"record": row["record"], "PGA [g]": _number(row["pga_g"], ".3g"), "Sa [g]": _number(row.get("sa_g"), ".3g"),
            "case": row.get("case", ""), "peak s1 [mm]": s1,
            "peak s2 [mm]": "-" if collapsed else _number(row["peak_s2_mm"], ".1f"),
            "s1/0.6Δu": "-" if collapsed else _number(row["s1_over_0.6Delta_u"], ".2f"),
            "limit states reached": ", ".join(row["reached"]) or "none",
            "P(collapse)": _number(row.get("collapse_probability"), ".2f"), "s1 16/50/84 % [mm]": spread,
            "flag": "FLIPS" if row.get("flips") else "", **code_cells(row)}


def code_cells(row):
    """The code checks' cells of a row with assess --code's columns (nothing without them)."""
    out = {}
    if row.get("nzsee_verdict") is not None:
        out["C8 %NBS"] = f"{_number(row['nzsee_nbs'], '.0f')} {row['nzsee_verdict']}"
    if row.get("ntc_verdict") is not None:
        out["NTC lin/nonlin"] = f"{row['ntc_linear_verdict']}/{row['ntc_nonlinear_verdict']}"
    if row.get("asce41_verdict") is not None:
        out["ASCE 41 h/t"] = f"{_number(row['asce41_h_over_t'], '.1f')}/{row['asce41_limit']:g} {row['asce41_verdict']}"
    if out:
        flagged = [name for code, name in CODE_NAMES.items() if row.get(f"{code}_unconservative")]
        out["code unconservative"] = ", ".join(flagged) if flagged else "none"
    return out


def _columns(rows, sa_period):
    drop = set()
    if sa_period is None:
        drop.add("Sa [g]")
    if all(not r.get("case") for r in rows):
        drop.add("case")
    codes = [c for c in CODE_COLUMNS if any(c in code_cells(r) for r in rows)]
    return [c for c in COLUMNS if c not in drop] + codes


def _title(column, sa_period):
    return f"Sa({sa_period:g} s, 5 %) [g]" if column == "Sa [g]" else column


def markdown(rows, scene_text, sa_period=None, notes=()):
    """A Markdown table of the cases, the scene below it."""
    columns = _columns(rows, sa_period)
    lines = ["| " + " | ".join(_title(c, sa_period) for c in columns) + " |",
             "|" + "|".join("---" for _ in columns) + "|"]
    for row in rows:
        c = cells(row)
        lines.append("| " + " | ".join(str(c[k]).replace("|", "/") for k in columns) + " |")
    lines += ["", *(f"{line}  " for line in scene_text.splitlines()), *notes]
    return "\n".join(lines)


def text(rows, sa_period=None):
    """The same table as aligned text (no scene: the report says it above)."""
    columns = _columns(rows, sa_period)
    table = [[_title(c, sa_period) for c in columns]] + [[str(cells(r)[k]) for k in columns] for r in rows]
    widths = [max(len(line[i]) for line in table) for i in range(len(columns))]
    return "\n".join("  ".join(cell.ljust(w) if i in (0, len(columns) - 1) or columns[i] in ("case", "limit states reached")
                               else cell.rjust(w) for i, (cell, w) in enumerate(zip(line, widths))).rstrip()
                     for line in table)


def result_row(result, states):
    """The table's row of an api.Result (its limit states `states`)."""
    peaks = dict(peak_s1=result.peak_s1, peak_s2=result.peak_s2, peak_F_top=result.peak_F_top,
                 collapsed=result.collapsed)
    row = {"record": result.record, "pga_g": result.pga_g, "sa_g": None, "case": "",
           "peak_s1_mm": result.peak_s1 * 1e3, "peak_s2_mm": result.peak_s2 * 1e3,
           "s1_over_0.6Delta_u": result.peak_s1 / (0.6 * result.wall.delta_u), "collapsed": result.collapsed,
           "t_collapse_s": result.t_collapse,
           "reached": [s.name for s in states if s.exceeded(peaks)] + (["collapse"] if result.collapsed else [])}
    if result.ensemble is not None:
        e = result.ensemble
        row.update(collapse_probability=e.collapse_probability, flips=e.flips,
                   **{f"s1_p{p}_mm": v * 1e3 for p, v in zip((16, 50, 84), e.s1_percentiles)})
    return row


def result_summary(result, fmt="md"):
    """Result.summary(): the table of one run, in Markdown ('md') or text ('text')."""
    from . import limits
    if fmt not in ("md", "text"):
        raise ValueError(f"summary format {fmt!r}: 'md' or 'text'")
    row = result_row(result, limits.parse_all(None, result.wall))
    notes = []
    if result.ensemble is not None:
        e = result.ensemble
        notes.append(f"P(collapse) and the s1 spread: an ensemble of {e.size} runs within the inputs' uncertainty"
                     + (f" ({e.failed} failed)" if e.failed else "") + (
                         "; FLIPS: the nominal outcome differs in at least 5 % of it" if e.flips else ""))
    if result.ensemble is None and not result.collapsed:
        notes += near_collapse_lines([(result.record, result.s1_over_delta_u)],
                                     "simulate(..., ensemble=100) gives the probability of collapse")
    if fmt == "md":
        return markdown([row], result.scene.text(), notes=notes)
    return "\n".join([text([row]), result.scene.text(), *notes])

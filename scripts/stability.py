"""Run the stability matrix (scripts/stability_cases.py says what it covers and why),
print one row per case, write results/stability.csv and the table between
'<!-- BEGIN stability -->' and '<!-- END stability -->' in docs/stability.md.

Per case: fmi2sim's CVODE steps and events (--stats), the wall times of fmi2sim and fmpy, the
largest energy gain beyond the input work (relative), whether any output is NaN or infinite,
collapse (fmi2sim / fmpy), and the difference of the peaks of fmpy and fmi2sim against the
tolerance the rtol implies. A very stiff spring (K_d >= 1e9 N/m per m) is also run as the
simply supported wall, the cheaper model it tends to, and the difference is reported.

    .venv/bin/python scripts/stability.py [--only TEXT] [--no-fmpy] [--no-readme]
(about 4 minutes on 2 cores)."""
import argparse
import contextlib
import csv
import dataclasses
import io
import pathlib
import sys
import tempfile

import numpy as np
from tqdm import tqdm

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(REPO / "scripts"), str(REPO / "reference")]
import stability_cases as sc  # noqa: E402



def cheaper_model(o, exe, fmu):
    """Peak s1 of the simply supported wall on the same input, vs the 2DOF's: (rel. diff, cost ratio)."""
    c = o.case
    law = "rigid" if c.law == "rigid" else "semiRigidHinge"
    cheap = dataclasses.replace(c, name=c.name + " as simplySupported", support="simplySupported", law=law)
    with tempfile.TemporaryDirectory() as wd:
        d, _, _, wall = sc.run_fmi2sim(exe, fmu, cheap, sc.signal(cheap), wd)
    peak = float(np.max(np.abs(d["s1"])))
    rel = abs(peak - o.peak_s1) / o.peak_s1 if o.peak_s1 > 0 else abs(peak)
    return rel, o.sim_wall / max(wall, 1e-9), peak


def notes(o, exe, fmu):
    out = []
    c = o.case
    if o.sim_wall > sc.SLOW_WALL_S or o.fmpy_wall > 10 * sc.SLOW_WALL_S:
        out.append(f"slow (fmi2sim {o.sim_wall:.1f} s, fmpy {o.fmpy_wall:.1f} s)")
    if c.stiff and not o.error:
        rel, ratio, peak = cheaper_model(o, exe, fmu)
        out.append(f"stiff spring: simplySupported gives peak s1 {peak:.4f} m against {o.peak_s1:.4f} m "
                   f"({100 * rel:.1f} % off) at 1/{ratio:.1f} of the cost")
    if o.fmpy_error:
        out.append(f"not compared with fmpy: {o.fmpy_error}")
    if c.chaotic and o.peak_diff > o.peak_tol:
        out.append(f"e_r = 1 (chaotic): fmpy and fmi2sim peaks differ by {o.peak_diff:.1e} m, not bounded")
    return "; ".join(out)


def row(o, bad, note):
    c = o.case
    return {"case": c.name, "support": c.support, "hinge_law": c.law, "Kd": c.Kd, "er": c.er, "psi": c.psi,
            "h_over_b": round(c.hb, 2), "record": c.record, "amp": c.amp_g, "dt": c.dt,
            "duration": c.duration, "rtol": c.rtol, "steps": o.steps, "events": o.events,
            "fmi2sim_s": round(o.sim_wall, 3), "fmpy_s": round(o.fmpy_wall, 3),
            "energy_gain": f"{o.energy_gain:.2e}", "energy_loss": f"{o.energy_loss:.2e}", "finite": o.finite, "collapsed": o.collapsed,
            "fmpy_collapsed": o.fmpy_collapsed, "peak_s1": f"{o.peak_s1:.5g}", "peak_s2": f"{o.peak_s2:.5g}",
            "peak_diff": f"{o.peak_diff:.2e}", "peak_tol": f"{o.peak_tol:.2e}",
            "ok": not bad, "problems": "; ".join(bad), "notes": note}


COLUMNS = [("case", 34), ("steps", 8), ("events", 7), ("fmi2sim_s", 9), ("fmpy_s", 7), ("energy_gain", 11), ("energy_loss", 11),
           ("finite", 6), ("collapsed", 9), ("peak_diff", 9), ("peak_tol", 9), ("ok", 5)]


def text_table(rows):
    lines = [" ".join(f"{name:>{w}}" if i else f"{name:<{w}}" for i, (name, w) in enumerate(COLUMNS))]
    for r in rows:
        lines.append(" ".join(f"{str(r[name]):>{w}}" if i else f"{str(r[name]):<{w}}"
                              for i, (name, w) in enumerate(COLUMNS)))
    return "\n".join(lines)


def stiff_tie_line(rows):
    """fmi2sim's steps at K_d = 1e12 over those at the base case's 5e4 under El Centro x0.5, per law:
    what a stiff tie costs a Model Exchange importer (docs/model.md "A stiff tie held rigid")."""
    by_name = {r["case"]: r for r in rows}
    parts = []
    for law in ("semiRigidPaper", "semiRigidHinge", "dohertyHinge"):
        soft, stiff = by_name.get(f"2dof-{law} El Centro x0.5"), by_name.get(f"2dof-{law} Kd=1e12 El Centro x0.5")
        if soft and stiff:
            parts.append(f"{law} {stiff['steps']} / {soft['steps']} = {stiff['steps'] / max(soft['steps'], 1):.2f}")
    return ("Stiff tie: fmi2sim's steps at K_d = 1e12 over those at 5e4 under El Centro x0.5 (60 s): "
            + "; ".join(parts) + ".") if parts else ""


def readme_block(rows):
    n_ok = sum(r["ok"] for r in rows)
    gains = [float(r["energy_gain"]) for r in rows if r["hinge_law"] != "semiRigidPaper" and r["finite"]]
    losses = [float(r["energy_loss"]) for r in rows if float(r["er"]) >= 1 and float(r["amp"]) == 0 and r["finite"]]
    ratio = [float(r["peak_diff"]) / float(r["peak_tol"]) for r in rows
             if float(r["peak_tol"]) > 0 and float(r["er"]) < 1]  # e_r = 1 is chaotic: not bounded
    lines = [f"{n_ok} of {len(rows)} cases meet every bound (`scripts/stability.py`, `results/stability.csv`). "
             f"Largest energy gain beyond the input work: {max(gains):.1e} (bound per case "
             f"{sc.ENERGY_GAIN_MAX:g} + {sc.ENERGY_GAIN_PER_EVENT} rtol x events); largest energy loss in free "
             f"rocking (e_r = 1, no input): {max(losses, default=0.0):.1e} (bound {sc.ENERGY_LOSS_PER_100S:g} "
             f"per 100 s); largest fmpy-fmi2sim peak "
             f"difference with e_r < 1: {max(ratio):.2f} of the tolerance rtol implies; "
             f"most steps {max(r['steps'] for r in rows)}, most events {max(r['events'] for r in rows)}.", "",
             stiff_tie_line(rows), ""]
    flagged = [r for r in rows if not r["ok"] or r["notes"]]
    if flagged:
        lines += ["| case | steps | events | fmi2sim [s] | fmpy [s] | problems and notes |", "|---|---|---|---|---|---|"]
        for r in flagged:
            lines.append(f"| {r['case']} | {r['steps']} | {r['events']} | {r['fmi2sim_s']} | {r['fmpy_s']} | "
                         f"{'; '.join(x for x in (r['problems'], r['notes']) if x)} |")
    lines += ["", "<details><summary>Every case</summary>", "", "```", text_table(rows), "```", "", "</details>"]
    return "\n".join(lines)


def load_rows(path):
    """Rows of a results CSV with the types row() gives them."""
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        for key in ("ok", "finite", "collapsed", "fmpy_collapsed"):
            r[key] = r[key] == "True"
        r["steps"], r["events"] = int(r["steps"]), int(r["events"])
    return rows


def write_readme(block):
    readme = REPO / "docs" / "stability.md"
    text = readme.read_text()
    begin, end = "<!-- BEGIN stability -->", "<!-- END stability -->"
    if begin not in text or end not in text:
        print("docs/stability.md has no stability markers; table not written", file=sys.stderr)
        return
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    readme.write_text(f"{head}{begin}\n{block}\n{end}{tail}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=str(REPO / "build"), help="build folder with fmi2sim and RockingWall.fmu")
    ap.add_argument("--only", default="", help="run only cases whose name contains this text")
    ap.add_argument("--no-fmpy", action="store_true", help="skip the fmpy runs (and the peak comparison)")
    ap.add_argument("--no-readme", action="store_true", help="do not write docs/stability.md")
    ap.add_argument("--out", default=str(REPO / "results" / "stability.csv"))
    ap.add_argument("--readme-from", metavar="CSV", help="only write docs/stability.md's table from an earlier run's CSV")
    a = ap.parse_args(argv)
    if a.readme_from:
        write_readme(readme_block(load_rows(a.readme_from)))
        return 0
    exe, fmu = pathlib.Path(a.build) / "fmi2sim", pathlib.Path(a.build) / "RockingWall.fmu"
    cases = [c for c in sc.matrix() if a.only in c.name]
    rows = []
    for c in tqdm(cases, desc="stability", unit="case"):
        with contextlib.redirect_stdout(io.StringIO()):  # fmpy prints the FMU's collapse warnings
            o = sc.run_case(c, exe, fmu, with_fmpy=not a.no_fmpy)
        bad = sc.check(o, with_fmpy=not a.no_fmpy)
        rows.append(row(o, bad, notes(o, exe, fmu)))
    print(text_table(rows))
    for r in rows:
        if r["problems"] or r["notes"]:
            print(f"{r['case']}: {'; '.join(x for x in (r['problems'], r['notes']) if x)}")
    out = pathlib.Path(a.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {out}")
    if not a.no_readme and not a.only:
        write_readme(readme_block(rows))
        print("wrote the stability table into docs/stability.md")
    return 0 if all(r["ok"] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())

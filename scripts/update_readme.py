"""Regenerate the README's result tables and pictures from results/ (written by
scripts/reproduce_paper.py, scripts/bench.py and scripts/main_job.py), so the README shows what
the current code computes, not a copy of an older run.

Each table stands between '<!-- BEGIN name -->' and '<!-- END name -->' in README.md; the PNGs
the README links are copied to docs/img/."""
import csv
import pathlib
import re
import shutil
import sys

REPO = pathlib.Path(__file__).resolve().parents[1]
RESULTS = REPO / "results"
IMAGES = ["main_elcentro.png", "fig_5_2.png", "fig_5_3.png", "fig_5_4.png", "work_precision.png"]


def rows(name):
    path = RESULTS / name
    return list(csv.DictReader(open(path))) if path.exists() else None


def number(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return None


def fmt(x, digits=3):
    return f"{number(x):.{digits}f}" if number(x) is not None else (x or "")


def diff(ours, paper):
    if number(ours) is None or number(paper) is None:
        return ours if ours else "missing"   # e.g. "collapse", or no record
    d = float(ours) - float(paper)
    return f"{d:+.3f} ({100 * d / float(paper):+.0f} %)" if float(paper) else f"{d:+.3f}"


def paper_table(name):
    data = rows(name)
    if data is None:
        return None
    out = ["| wall | input | model | K_d [kN/m] | quantity | ours | paper | ours - paper |",
           "|---|---|---|---|---|---|---|---|"]
    for r in data:
        digits = 3 if r["quantity"] in ("s1", "s2", "R_el", "Delta_u", "F0_over_W", "Delta_u_over_b") else 4
        out.append(f"| {r['wall']} | {r['input']} | {r['model']} | {r['Kd_kN_per_m']} | {r['quantity']} | "
                   f"{fmt(r['ours'], digits)} | {fmt(r['paper'], digits)} | {diff(r['ours'], r['paper'])} |")
    return "\n".join(out)


def bench_tables():
    data = rows("bench_work_precision.csv")
    if data is None:
        return None
    out = ["| scene | contender | setting (rtol or step) | error | CPU [s] |", "|---|---|---|---|---|"]
    for r in data:
        err = "failed" if r["error"] == "nan" else f"{float(r['error']):.1e}"
        cpu = "" if r["cpu_s"] == "nan" else f"{float(r['cpu_s']):.4f}"
        out.append(f"| {r['scene']} | {r['contender']} | {float(r['setting']):g} | {err} | {cpu} |")
    return "\n".join(out)


def ladder_table():
    data = rows("bench_model_ladder.csv")
    if data is None:
        return None
    out = ["| scene | model | CPU [s] | peak s1 [m] | peak s2 [m] | collapsed |", "|---|---|---|---|---|---|"]
    for r in data:
        out.append(f"| {r['scene']} | {r['model']} | {float(r['cpu_s']):.4f} | {float(r['peak_s1']):.4f} | "
                   f"{float(r['peak_s2']):.4f} | {r['collapsed']} |")
    return "\n".join(out)


def text_block(name):
    path = RESULTS / name
    return f"```\n{path.read_text().rstrip()}\n```" if path.exists() else None


def replace(readme, name, body):
    if body is None:
        print(f"update_readme: no data for '{name}', block left as it is", file=sys.stderr)
        return readme
    pattern = re.compile(rf"(<!-- BEGIN {name} -->\n)(?:.*?\n)?(<!-- END {name} -->)", re.S)
    if not pattern.search(readme):
        raise SystemExit(f"update_readme: README.md has no block '{name}'")
    return pattern.sub(lambda m: m.group(1) + body + "\n" + m.group(2), readme)


def main():
    readme = (REPO / "README.md").read_text()
    readme = replace(readme, "main-job", text_block("main_job.txt"))
    readme = replace(readme, "table-5-1", paper_table("table_5_1.csv"))
    readme = replace(readme, "table-5-2", paper_table("table_5_2.csv"))
    readme = replace(readme, "table-5-4", paper_table("table_5_4.csv"))
    readme = replace(readme, "bench-ratios", text_block("bench_summary.txt"))
    readme = replace(readme, "bench-ladder", ladder_table())
    readme = replace(readme, "bench-all", bench_tables())
    (REPO / "README.md").write_text(readme)
    img = REPO / "docs" / "img"
    img.mkdir(parents=True, exist_ok=True)
    for name in IMAGES:
        if (RESULTS / name).exists():
            shutil.copy(RESULTS / name, img / name)
    print("update_readme: README.md and docs/img/ updated")


if __name__ == "__main__":
    main()

"""Regenerate the result tables and pictures of the README and the docs pages from results/
(written by `rockingwall paper`, `rockingwall demo` and scripts/bench.py), so they show what the
current code computes, not a copy of an older run.

Each table stands between '<!-- BEGIN name -->' and '<!-- END name -->' in the page BLOCKS names;
the PNGs they link are copied to docs/img/."""
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


def replace(page, text, name, body):
    if body is None:
        print(f"update_docs: no data for '{name}', block left as it is", file=sys.stderr)
        return text
    pattern = re.compile(rf"(<!-- BEGIN {name} -->\n)(?:.*?\n)?(<!-- END {name} -->)", re.S)
    if not pattern.search(text):
        raise SystemExit(f"update_docs: {page} has no block '{name}'")
    return pattern.sub(lambda m: m.group(1) + body + "\n" + m.group(2), text)


# page -> [(block name, its new content)]
BLOCKS = {
    "README.md": [("main-job", lambda: text_block("main_job.txt"))],
    "docs/paper.md": [(f"table-5-{n}", lambda n=n: paper_table(f"table_5_{n}.csv")) for n in (1, 2, 4)],
    "docs/performance.md": [("bench-ratios", lambda: text_block("bench_summary.txt")),
                            ("bench-ladder", ladder_table), ("bench-all", bench_tables)],
}


def main():
    for page, blocks in BLOCKS.items():
        path = REPO / page
        text = path.read_text()
        for name, body in blocks:
            text = replace(page, text, name, body())
        path.write_text(text)
    img = REPO / "docs" / "img"
    img.mkdir(parents=True, exist_ok=True)
    for name in IMAGES:
        if (RESULTS / name).exists():
            shutil.copy(RESULTS / name, img / name)
    print("update_docs: README.md, docs/*.md and docs/img/ updated")


if __name__ == "__main__":
    main()

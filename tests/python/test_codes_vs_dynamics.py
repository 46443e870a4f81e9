"""The plot of the codes' verdicts against the time histories (docs/code-checks-vs-dynamics.md):
its legend's labels and colours, where it marks a code unconservative, on small data made here;
and the script's scene on one record and two K_d (the exact engine, milliseconds)."""
import math

import matplotlib.colors as mcolors
import numpy as np
import pandas as pd
import pytest

from rockingwall import Wall, assessment_codes, codes_vs_dynamics as cvd, records

WALL = Wall.make(b=0.23, h=3.6, W=14904.0, psi=0.2, support="flexibleTop", warn=False)
SITE = dict(nz_Z="0.2", nz_soil="B", ntc_ag="0.2g", ntc_soil="A", asce_SX1="0.2g")   # all three pass


def checks(**site):
    args = type("Args", (), site)()
    return assessment_codes.check(WALL, assessment_codes.CODES, assessment_codes.option_values(args))


def frame():
    """Two records at three K_d: record A collapses at 5 kN/m per m, reaches 0.5 Delta_u at 20
    (past NTC's 0.4 Delta_i, below C8's 0.6) and 0.1 at 1000; record B stays at 0.1 Delta_u."""
    du = WALL.delta_u
    rows = [("A", 5e3, True, math.nan), ("A", 20e3, False, 0.5), ("A", 1000e3, False, 0.1),
            ("B", 5e3, False, 0.1), ("B", 20e3, False, 0.1), ("B", 1000e3, False, 0.1)]
    return pd.DataFrame([dict(record=r, kd=kd, collapsed=c, ratio=x, peak_s1=x * du) for r, kd, c, x in rows])


def test_unconservative_where_a_passing_code_meets_collapse_or_its_own_limit():
    c = checks(**SITE)
    assert [r.verdict for r in c.results.values()] == ["pass", "pass", "pass"]
    assert cvd.unconservative_kds(c, frame()) == {"nzsee": [5e3], "ntc": [5e3, 20e3], "asce41": [5e3]}
    failing = checks(**dict(SITE, nz_Z="0.4", nz_soil="C"))        # C8 fails: never unconservative
    assert failing.results["nzsee"].verdict == "fail"
    assert cvd.unconservative_kds(failing, frame())["nzsee"] == []


def test_legend_labels_and_colours():
    c = checks(**SITE)
    fig = cvd.plot([cvd.Panel("paper", frame()), cvd.Panel("mass", frame())], c, WALL.delta_u, "title")
    legend = fig.legends[0]
    labels = [t.get_text() for t in legend.get_texts()]
    nbs = 100 * 0.6 * WALL.delta_u / c.results["nzsee"].demand
    assert labels == ["A", "B",
                      f"NZSEE C8: Δm = 0.6 Δi, {nbs:.0f} %NBS, pass",
                      "NTC 2018: du* at the hinge, pass/pass, pass",
                      f"ASCE 41-17: h/t {3.6 / 0.23:.1f} vs 20, pass (limit: collapse)",
                      "NZSEE C8 unconservative", "NTC 2018 unconservative", "ASCE 41-17 unconservative"]
    colour = {t.get_text(): h for t, h in zip(legend.get_texts(), legend.legend_handles)}
    for code, name in assessment_codes.LABELS.items():
        want = mcolors.to_rgba(cvd.CODE_COLOURS[code])
        line = next(h for label, h in colour.items() if label.startswith(name + ":"))
        assert mcolors.to_rgba(line.get_color()) == want
        mark = colour[f"{name} unconservative"]
        assert tuple(mark.get_facecolor()[0]) == pytest.approx(want)
    ax = fig.axes[0]
    # the codes' dashed lines at their usable displacements over Delta_u: 0.6, 0.4 and 1 (collapse)
    dashed = sorted(round(float(line.get_ydata()[0]), 9) for line in ax.get_lines() if line.get_linestyle() == "--")
    assert dashed == [0.4, 0.6, 1.0]
    # record A's collapse drawn at the collapse row, its standing peaks as they are
    a = next(line for line in ax.get_lines() if line.get_label() == "A")
    assert list(a.get_ydata()) == [cvd.COLLAPSE_Y, 0.5, 0.1]


def test_the_scripts_scene_on_one_record_is_the_simulation():
    """dynamics() is simulate() per K_d: El Centro at 0.2 g collapses the wall on a 5 kN/m per m
    diaphragm and not on a 1000 (the docs' table), in both scenes."""
    rec = records.el_centro().to_pga(0.2)
    for mass in (None, 200.0):
        d = cvd.dynamics(WALL, [rec], [5e3, 1000e3], diaphragm_mass=mass)
        assert list(d.collapsed) == [True, False]
        assert np.isnan(d.ratio[0]) and 0 < d.ratio[1] < 0.6


def test_the_docs_page_shows_what_the_script_prints(tmp_path, capsys):
    """docs/code-checks-vs-dynamics.md's tables are the script's output as the code computes it now."""
    import pathlib
    import runpy
    repo = pathlib.Path(__file__).resolve().parents[2]
    script = runpy.run_path(str(repo / "scripts" / "code_checks_vs_dynamics.py"))
    assert script["main"](["--out", str(tmp_path / "plot.png")]) == 0
    assert (tmp_path / "plot.png").stat().st_size > 10_000
    page = (repo / "docs" / "code-checks-vs-dynamics.md").read_text()
    table_rows = [line for line in capsys.readouterr().out.splitlines() if line.startswith("|")]
    assert len(table_rows) == 12
    for line in table_rows:
        assert line in page, line

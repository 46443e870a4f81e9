"""Outputs an engineer puts in a report: what each one said wrongly, and what it says now. Each
test is named after the finding it fixes (an assessor's trial of `run` and `assess`)."""
import ast
import json
import pathlib

import numpy as np
import pandas as pd
import pytest

import rockingwall as rw
from rockingwall import assessment_plots
from rockingwall.cli import main

PACKAGE = pathlib.Path(rw.__file__).parent
WALL = ["--b", "230mm", "--h", "3.6", "--W", "14.904kN/m", "--psi", "0.2013"]
PULSE = "gaussian:0.04,1.0"


def test_finding2_fragility_colours_are_keyed_to_kd_in_every_panel(tmp_path, figures):
    """'roof connection' has a fit for K_d = 200 only: its curve must be K_d = 200's colour, not
    the first colour of the panel, which the other panels give K_d = 20."""
    rows = []
    for state, kd20 in [("0.6 Delta_u", 0.45), ("roof connection", np.nan)]:
        rows.append(dict(Kd_kN_per_m_per_m=20.0, limit_state=state, records=4, median=kd20, median_5=np.nan,
                         median_95=np.nan, beta=0.3, beta_5=np.nan, beta_95=np.nan, warnings=""))
        rows.append(dict(Kd_kN_per_m_per_m=200.0, limit_state=state, records=4, median=0.387, median_5=0.3,
                         median_95=0.5, beta=0.38, beta_5=0.03, beta_95=0.76, warnings=""))
    assessment_plots.fragility(pd.DataFrame(rows), "PGA [g]", tmp_path / "fragility.png")
    (fig,) = figures
    colour = {}
    for ax in fig.axes:
        for line in ax.get_lines():
            label = line.get_label()
            if label.startswith("K_d = 200"):
                colour.setdefault("200", set()).add(line.get_color())
            elif label.startswith("K_d = 20 "):
                colour.setdefault("20", set()).add(line.get_color())
    assert len(colour["200"]) == 1 and len(colour["20"]) == 1 and colour["200"] != colour["20"]
    roof = next(ax for ax in fig.axes if ax.get_title() == "roof connection")
    drawn = [line for line in roof.get_lines() if len(line.get_xdata())]
    assert [line.get_color() for line in drawn] == list(colour["200"])


def test_a_fit_without_dispersion_says_so_in_the_legend(tmp_path, figures):
    """Where no run overlaps (every run below a PGA short of the limit, every run above past it) the
    fit has beta 0 and its median is anywhere in the gap. The printed report says so; the plot drew
    the step with a plain label, which pasted into a report reads as a known median."""
    rows = [dict(Kd_kN_per_m_per_m=kd, limit_state="collapsed", records=4, median=median, median_5=0.28,
                 median_95=0.4, beta=beta, beta_5=np.nan, beta_95=np.nan, warnings="") for kd, median, beta in
            ((20.0, 0.4, 0.0), (200.0, 0.387, 0.38))]
    assessment_plots.fragility(pd.DataFrame(rows), "PGA [g]", tmp_path / "fragility.png")
    (fig,) = figures
    assert [t.get_text() for t in fig.axes[0].get_legend().get_texts()] == [
        "K_d = 20 kN/m per m: beta not identified", "K_d = 200 kN/m per m"]



def test_a_median_the_data_cannot_place_is_printed_as_its_gap(tmp_path, figures):
    """Where every run below 0.1 g stands and every run above 0.3 g collapses, assess printed
    'median 0.173 [0.17, 0.18]' (the gap's geometric mean, and a bootstrap interval as tight as
    the one record's resamples are alike) beside a warning that the median is anywhere in [0.1,
    0.3]. The line now gives the gap as the median's place, fragility.csv has it (gap_lo, gap_hi),
    and the plot shades it and says it in the legend; one record is 'record'."""
    from rockingwall import assessment, assessment_report
    from rockingwall.limits import parse_all
    wall = rw.Wall.make("paper1", Kd=20e3, warn=False)
    cases = pd.DataFrame([dict(Kd_kN_per_m_per_m=20.0, record="r1", im=pga, collapsed=pga > 0.2,
                               **{"0.6 Delta_u": pga > 0.2, "Delta_u": pga > 0.2}) for pga in (0.1, 0.3)])
    frag = assessment.fragilities(cases, parse_all(None, wall))
    row = frag[frag.limit_state == "collapsed"].iloc[0]
    assert (row.gap_lo, row.gap_hi) == pytest.approx((0.1, 0.3))
    line = assessment_report.fragility_line(row.to_dict(), "Kd_kN_per_m_per_m")
    assert "median anywhere in [0.1, 0.3], beta 0 (not identified), 1 record" in line and "0.173" not in line
    assessment_plots.fragility(frag, "PGA [g]", tmp_path / "fragility.png")
    (fig,) = figures
    legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert legend == ["K_d = 20 kN/m per m: beta not identified\n  median anywhere in [0.1, 0.3]"]
    assert any(p.get_x() == pytest.approx(0.1) and p.get_width() == pytest.approx(0.2) for p in fig.axes[0].patches)

def test_fragility_legends_stand_below_their_panels_not_over_the_curves(tmp_path, figures):
    """In assess's fragility.png of the assessor's house under one record, each panel's legend (four
    entries, two of two lines) sat over the middle of the panel and hid the dashed curve's rise
    from 0.25 to 0.4 g. The legends now stand below their panels, inside the figure."""
    rows = [dict(storey=storey, limit_state=state, records=1, median=median, median_5=median, median_95=median,
                 beta=beta, beta_5=np.nan, beta_95=np.nan, gap_lo=lo, gap_hi=hi, warnings="", over=over)
            for state in ("0.6 Delta_u", "collapsed")
            for storey, median, beta, lo, hi, over in ((1.0, 0.35, 0.0, 0.3, 0.4, "records"),
                                                       (1.0, 0.341, 0.15, np.nan, np.nan, "records and parameters"),
                                                       (2.0, 0.14, 0.0, 0.1, 0.2, "records"))]
    assessment_plots.fragility(pd.DataFrame(rows), "PGA [g]", tmp_path / "fragility.png", column="storey")
    (fig,) = figures
    fig.canvas.draw()
    whole = fig.bbox
    for ax in fig.axes:
        legend, panel = ax.get_legend().get_window_extent(), ax.get_window_extent()
        assert len(ax.get_legend().get_texts()) == 3
        assert legend.y1 <= panel.y0, (ax.get_title(), legend, panel)  # below the panel, not over it
        assert legend.y0 >= whole.y0 and legend.x0 >= whole.x0 and legend.x1 <= whole.x1  # inside the figure


def test_the_ida_plots_legend_hides_no_collapse(tmp_path):
    """assess's IDA plot of El Centro (scene (b), K_d 20 and 200 kN/m per m, 0.2 and 0.5 g) kept its
    legend in the lower right, over the collapse column at the lowest intensity: the cross of the
    K_d = 20 wall collapsing at 0.2 g and its ensemble's band were under the legend. It stands below
    the axes, inside the figure."""
    from rockingwall import assessment
    cases = pd.DataFrame([dict(im=im, peak_s1_mm=peak, collapsed=collapsed, s1_p16_mm=lo, s1_p84_mm=hi,
                               **{assessment.KD_COLUMN: kd})
                          for kd, im, peak, collapsed, lo, hi in ((20.0, 0.2, np.nan, True, 136.0, np.inf),
                                                                  (20.0, 0.5, np.nan, True, np.inf, np.inf),
                                                                  (200.0, 0.2, 67.3, False, 49.0, 91.0),
                                                                  (200.0, 0.5, np.nan, True, np.inf, np.inf))])
    fig = assessment_plots.ida_figure(cases, "El Centro 1940", [], "PGA [g]", delta_u_mm=220.4)
    fig.canvas.draw()
    (ax,) = fig.axes
    legend, panel, whole = ax.get_legend().get_window_extent(), ax.get_window_extent(), fig.bbox
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["K_d = 20 kN/m per m", "K_d = 200 kN/m per m"]
    assert legend.y1 <= panel.y0 and legend.y0 >= whole.y0 and legend.x0 >= whole.x0 and legend.x1 <= whole.x1


def write_csv(path, record, factor):
    np.savetxt(path, np.column_stack([record.t, record.ag * factor]), delimiter=",", header="time,acc", comments="")


def test_finding3_a_record_in_cm_s2_is_read_with_its_unit_or_warned_about(tmp_path, capsys):
    record = rw.read_record(PULSE)  # m/s^2
    write_csv(tmp_path / "pulse_cms2.csv", record, 100.0)
    write_csv(tmp_path / "pulse_g.csv", record, 1 / 9.81)
    args = ["run", *WALL, "--Kd", "20kN/m/m", "--scale", "1"]
    assert main([*args, str(tmp_path / "pulse_g.csv")]) == 0
    in_g = capsys.readouterr().out
    assert main([*args, "--csv-units", "cm/s2", str(tmp_path / "pulse_cms2.csv")]) == 0
    in_cms2 = capsys.readouterr().out
    assert in_g.splitlines()[-1].split()[1:] == in_cms2.splitlines()[-1].split()[1:]  # same PGA and peaks
    pga = record.pga / 9.81
    assert f"{pga:.3g}" in in_g.splitlines()[-1]  # the record's PGA printed with --scale
    # the slip: cm/s^2 read as g, PGA about 100 x 9.81 x pga g: above 100 g it is refused, units named
    assert main([*args, str(tmp_path / "pulse_cms2.csv")]) == 2
    assert "units" in capsys.readouterr().err
    # a record ten times weaker in cm/s^2, read as g (25 g): it runs with the warning, --strict refuses it
    write_csv(tmp_path / "weak_cms2.csv", record, 10.0)
    assert main([*args, str(tmp_path / "weak_cms2.csv")]) == 0
    captured = capsys.readouterr()
    assert "cm/s^2" in captured.err and f"{10 * 9.81 * pga:.3g} g" in captured.err
    assert main([*args, "--strict", str(tmp_path / "weak_cms2.csv")]) == 2
    assert "--strict" in capsys.readouterr().err


def test_finding5_strict_turns_a_plausibility_warning_into_an_error(capsys):
    args = ["run", *WALL, "--Kd", "30", "--pga", "0.3", PULSE]  # K_d in N/m per m: a unit slip
    assert main(args) == 0
    assert "kN/m per m" in capsys.readouterr().err
    assert main([*args, "--strict"]) == 2
    assert "--strict" in capsys.readouterr().err


def assess(tmp_path, *args):
    """rockingwall assess PULSE ARGS (the record first: --pga takes every number after it)."""
    return main(["assess", PULSE, *map(str, args), "--out", str(tmp_path)])


def test_finding5_collapse_is_a_time_and_a_column_never_a_displacement(tmp_path, capsys):
    assert assess(tmp_path, *WALL, "--kd-values", "20kN/m/m", "--pga", "0.3", "3") == 0
    out = capsys.readouterr().out
    cases = pd.read_csv(tmp_path / "cases.csv")
    fallen = cases[cases.collapsed].iloc[0]
    standing = cases[~cases.collapsed].iloc[0]
    assert np.isnan(fallen.peak_s1_mm) and np.isnan(fallen.s1_over_Delta_u) and fallen.t_collapse_s > 0
    assert standing.peak_s1_mm > 0 and np.isnan(standing.t_collapse_s)
    assert f"collapsed at {fallen.t_collapse_s:.2f} s" in out


def test_finding5_simply_supported_wall_echoes_no_kd_and_titles_name_none(tmp_path, capsys, figures):
    assert assess(tmp_path, *WALL, "--support", "simplySupported", "--pga", "0.2") == 0
    out = capsys.readouterr().out
    assert "K_d" not in out
    ida = next(f for f in figures if f.axes[0].get_ylabel() == "PGA [g]" and f.axes[0].get_title())
    assert "K_d" not in ida.axes[0].get_title()


def test_finding5_ida_title_names_no_unused_kd_and_fits_the_figure(tmp_path, figures):
    assert assess(tmp_path, *WALL, "--kd-values", "20kN/m/m", "200kN/m/m", "--pga", "0.2", "0.3") == 0
    ida = next(f for f in figures if len(f.axes) == 1)
    title = ida.axes[0].title
    assert "1000 kN/m" not in title.get_text()  # the wall's unused default K_d once stood there
    # the scene it ran, as the report names it (the plots named none); K_d: the legend's
    scene = "scene: the paper's: the top spring K_d (per legend) ends at a fixed point"
    assert scene in title.get_text().replace("\n", " ")
    fragility = next(f for f in figures if len(f.axes) > 1)
    assert scene in fragility._suptitle.get_text().replace("\n", " ")
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    renderer = FigureCanvasAgg(ida).get_renderer()
    box, frame = title.get_window_extent(renderer), ida.bbox
    assert frame.x0 <= box.x0 and box.x1 <= frame.x1 and box.y1 <= frame.y1


def test_finding5_no_estimate_names_the_limit_state_not_collapse(tmp_path, capsys):
    assert assess(tmp_path, *WALL, "--kd-values", "20kN/m/m", "--pga", "0.05", "0.1",
                  "--limit", "big: s2 >= 2m") == 0
    out = capsys.readouterr().out
    line = next(x for x in out.splitlines() if x.strip().startswith("K_d = 20 kN/m per m, big"))
    assert "no run reaches big" in line and "collapse or none" not in out


def test_finding5_intervals_print_two_significant_figures_and_unbounded(tmp_path, capsys):
    """'beta 0.76 [0.07, 37222767.96]': two significant figures, and 'unbounded' where resamples have
    no finite beta. Records made to have a share that falls with the intensity in some resamples."""
    from rockingwall import assessment_report
    row = dict(Kd_kN_per_m_per_m=200.0, limit_state="0.6 Delta_u", over="records", records=4, median=0.38729833,
               median_5=0.3, median_95=0.5, beta=0.7573512, beta_5=0.0723, beta_95=np.inf, warnings="")
    line = assessment_report.fragility_line(row, "Kd_kN_per_m_per_m")
    assert "median 0.387 [0.3, 0.5]" in line and "beta 0.76 [0.072, unbounded]" in line


def test_an_interval_printed_to_two_figures_still_holds_its_median(tmp_path, capsys):
    """assess printed 'median 0.514 [0.4, 0.51]': the bootstrap's upper end 0.514, rounded to the
    nearest 0.01, fell below the median printed beside it. The ends are now rounded outward."""
    from rockingwall import assessment_report
    row = dict(Kd_kN_per_m_per_m=200.0, limit_state="collapsed", over="records and parameters", records=2,
               median=0.51386, median_5=0.40472, median_95=0.51386, beta=0.26647, beta_5=0.16951, beta_95=0.26647,
               warnings="")
    line = assessment_report.fragility_line(row, "Kd_kN_per_m_per_m")
    assert "median 0.514 [0.4, 0.52]" in line and "beta 0.27 [0.16, 0.27]" in line


def test_finding5_every_json_the_package_writes_is_strict():
    """json.dump writes NaN, which is not JSON: every writer goes through rockingwall.strict_json
    (json.dumps stays only where the text is hashed, never written: the sweep's run key)."""
    offenders = []
    for path in PACKAGE.rglob("*.py"):
        if path.name == "strict_json.py":
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr in ("dump", "dumps") \
                    and isinstance(node.func.value, ast.Name) and node.func.value.id == "json":
                offenders.append(f"{path.relative_to(PACKAGE)}:{node.lineno}")
    assert offenders == ["sweep/provenance.py:65"]


def test_finding5_run_json_of_a_collapse_parses_strictly(capsys):
    assert main(["run", *WALL, "--Kd", "20kN/m/m", "--pga", "3", PULSE, "--json", "--ensemble", "10"]) == 0
    text = capsys.readouterr().out

    def refuse(name):
        raise ValueError(f"not JSON: {name}")
    data = json.loads(text, parse_constant=refuse)
    run = data["runs"][0]
    assert run["collapsed"] and run["ensemble"]["s1_p84_m"] is None  # inf: a collapsed percentile
    # a collapsed wall's peaks were numbers (its state at the instability point), where the table
    # prints '-': null now, as its s1/Delta_u and tie force
    assert [run[k] for k in ("peak_s1_m", "peak_s2_m", "s1_over_Delta_u", "peak_F_top_N_per_m")] == [None] * 4


def test_finding7_a_report_table_in_markdown_and_result_summary(tmp_path, capsys):
    assert assess(tmp_path, *WALL, "--kd-values", "20kN/m/m", "--pga", "0.2", "3", "--ensemble", "20",
                  "--table", "md", "--sa-period", "0.6") == 0
    out = capsys.readouterr().out.splitlines()
    header = next(i for i, x in enumerate(out) if x.startswith("| record"))
    columns = [c.strip() for c in out[header].strip("|").split("|")]
    assert columns[:2] == ["record", "PGA [g]"] and {"peak s1 [mm]", "s1/0.6Δu", "limit states reached",
                                                      "P(collapse)", "Sa(0.6 s, 5 %) [g]"} <= set(columns)
    rows = [[c.strip() for c in x.strip("|").split("|")] for x in out[header + 2:header + 4]]
    assert rows[0][1] == "0.2" and rows[1][columns.index("peak s1 [mm]")].startswith("collapsed at")
    assert any(x.startswith("scene: the paper's") for x in out[header + 4:])
    wall = rw.Wall.make(b=0.23, h=3.6, W=14904.0, psi=0.2013, Kd=20e3)
    result = rw.simulate(wall, rw.read_record(PULSE).to_pga(0.2), ensemble=20)
    table = result.summary()
    assert "| record | PGA [g] |" in table and f"{result.peak_s1 * 1e3:.1f}" in table
    assert f"{result.peak_s1 / (0.6 * wall.delta_u):.2f}" in table and "scene: the paper's" in table


def test_only_a_plausibility_warning_is_a_strict_error():
    """The commands' plausibility filter caught every warning raised while a wall, a building file
    or a sweep's plan was read, shown 'always' and, with --strict, made an error of: a library's
    deprecation warning there would have refused the user's input. Only a PlausibilityWarning is
    now routed so; any other warning goes on as it came."""
    import argparse
    import warnings
    from rockingwall.commands import common
    from rockingwall.wall import PlausibilityWarning

    def make(*kinds):
        def run():
            for kind in kinds:
                warnings.warn(f"a {kind.__name__}", kind)
            return 42
        return run
    strict = argparse.Namespace(strict=True)
    with pytest.warns(DeprecationWarning, match="a DeprecationWarning"):
        assert common.plausible(make(DeprecationWarning), strict) == 42
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match="a PlausibilityWarning .--strict"):
        common.plausible(make(DeprecationWarning, PlausibilityWarning), strict)


@pytest.mark.parametrize("scene, extra, varied", [
    ("paper", ["--Kd", "20kN/m/m"], "psi 0.1, W 0.05, b 0.03, er 0.05, Kd 0.3, scale 0.05;"),
    ("simply supported", ["--support", "simplySupported"], "psi 0.1, W 0.05, b 0.03, er 0.05, scale 0.05;"),
    ("under a diaphragm with mass", ["--Kd", "20kN/m/m", "--diaphragm-mass", "200kg/m"],
     "psi 0.1, W 0.05, b 0.03, er 0.05, Kd 0.3, scale 0.05, diaphragm_mass 0.2, diaphragm_damping 0.3, tie 1;")])
def test_the_ensemble_names_only_the_spreads_its_scene_has(tmp_path, capsys, scene, extra, varied):
    """assess of a wall in the paper's scene printed 'spreads: ... diaphragm_mass 0.2,
    diaphragm_damping 0.3, tie 1': the scene has no diaphragm mass, damping or tie, and nothing
    perturbed them. The head now lists the inputs the scene's members vary."""
    assert assess(tmp_path, *WALL, *extra, "--pga", "0.2", "--ensemble", "4") == 0
    (line,) = [l for l in capsys.readouterr().out.splitlines() if l.startswith("ensemble:")]
    assert f"spreads: {varied}" in line, (scene, line)


NEAR_TWINS = ["gaussian:0.04,1", "gaussian:0.04,1.5"]  # 'Gaussian D=0.04 m T=1 s at 0.1 g', 'T=1.5 s'


def test_run_prints_every_records_whole_name(capsys):
    """run's table cut the record's name at 27 characters: 'Gaussian D=0.04 m T=1 s at' lost
    the intensity, and two records named alike for 27 characters would be two rows no reader can
    tell apart. The column is now as wide as the longest name."""
    assert main(["run", *WALL, "--Kd", "20kN/m/m", "--pga", "0.1", *NEAR_TWINS]) == 0
    lines = capsys.readouterr().out.splitlines()
    header = next(k for k, line in enumerate(lines) if line.startswith("record"))
    rows = lines[header + 1:header + 3]
    assert [row.split("  ")[0] for row in rows] == ["Gaussian D=0.04 m T=1 s at 0.1 g", "Gaussian D=0.04 m T=1.5 s at 0.1 g"]
    pga_end = lines[header].index("PGA [g]") + len("PGA [g]")
    assert [row[pga_end - 3:pga_end] for row in rows] == ["0.1", "0.1"]  # the PGA column lines up
    assert lines[header] == lines[header].rstrip()


def test_building_prints_every_records_whole_name(capsys):
    """building's table cut the record's name at 25 characters ('Gaussian D=0.04 m T=1 s a')."""
    house = pathlib.Path(__file__).resolve().parents[2] / "examples" / "two-storey-brick.toml"
    assert main(["building", str(house), *NEAR_TWINS, "--pga", "0.1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    names = {line.split("  ")[0] for line in lines if line.startswith("Gaussian")}
    assert names == {"Gaussian D=0.04 m T=1 s at 0.1 g", "Gaussian D=0.04 m T=1.5 s at 0.1 g"}


def fema_record(name):
    """The path of a FEMA P695 far-field component (converted once into the records' cache)."""
    from rockingwall.sweep import suites
    return next(r.path for r in suites.fema_farfield(suites.fema_cache()) if r.name == name)


def test_a_standing_wall_near_collapse_is_said_to_be_one_sample(capsys):
    """The assessor's upper wall under its retrofitted roof (200 kN/m per m, 200 kg/m) and ff07a at
    0.5 g stands with s1 = 171 mm, 0.78 Delta_u, and `run` printed that one number, no more: an
    ensemble of 100 such walls collapses in 30 % of its members. A standing wall past 0.6 Delta_u
    (C8's usable displacement) now gets a line that it is near collapse and how to get the spread;
    with --ensemble the spread is in the table and the line is not printed, and a wall well short
    of it gets none."""
    from rockingwall.building import reports
    args = ["run", *WALL, "--Kd", "200kN/m/m", "--diaphragm-mass", "200kg/m", str(fema_record("ff07a"))]
    assert main([*args, "--pga", "0.5"]) == 0
    near = [l for l in capsys.readouterr().out.splitlines() if l.startswith("near collapse:")]
    assert len(near) == 1 and "ff07a at 0.5 g (s1 = 0.78 Delta_u)" in near[0] and "--ensemble 100" in near[0]
    assert main([*args, "--pga", "0.2"]) == 0
    assert "near collapse" not in capsys.readouterr().out
    wall = rw.Wall.make(b=0.23, h=3.6, W=14904.0, psi=0.2013, Kd=200e3, warn=False)
    from rockingwall.building.description import Diaphragm
    result = rw.simulate(wall, rw.read_at2(fema_record("ff07a")).to_pga(0.5), diaphragm=Diaphragm(200e3, 200.0))
    assert "near collapse: ff07a at 0.5 g (s1 = 0.78 Delta_u)" in result.summary()  # the API's report table too
    assert reports.near_collapse_lines([("a", 0.59), ("b", 0.6)], "x") == [
        "near collapse: b (s1 = 0.60 Delta_u): standing past 0.6 Delta_u, where rocking is chaotic and a small change "
        "of the inputs can turn standing into collapse; one run is one sample of that spread: x"]


def test_the_building_names_its_storeys_near_collapse(tmp_path, capsys):
    """building printed the retrofitted house's upper wall standing at 0.91 Delta_u under ff07a at
    0.5 g with nothing said; the line names the storey and points to assess --building."""
    ff07a = fema_record("ff07a")
    house = pathlib.Path(__file__).resolve().parents[2] / "examples" / "two-storey-brick.toml"
    retrofit = tmp_path / "retrofit.toml"
    retrofit.write_text(house.read_text().replace('stiffness = "20 kN/m/m"', 'stiffness = "200 kN/m/m"'))
    assert main(["building", str(retrofit), str(ff07a), "--pga", "0.5"]) == 0
    near = [l for l in capsys.readouterr().out.splitlines() if l.startswith("near collapse:")]
    assert len(near) == 1 and near[0].startswith("near collapse: ff07a at 0.5 g, storey 2 (s1 = 0.91 Delta_u)")
    assert "assess --building" in near[0]
    # --json says it too, per storey, with its note (programs read no table)
    assert main(["building", str(retrofit), str(ff07a), "--pga", "0.5", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert [s["near_collapse"] for s in out["runs"][0]["storeys"]] == [False, True]
    assert out["notes"]["near_collapse"].startswith("near_collapse: the wall stands with s1 at 0.6 Delta_u")


def test_run_json_marks_a_wall_near_collapse(capsys):
    args = ["run", *WALL, "--Kd", "200kN/m/m", "--diaphragm-mass", "200kg/m", str(fema_record("ff07a")), "--json"]
    assert main([*args, "--pga", "0.5"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["runs"][0]["near_collapse"] is True and "near_collapse" in out["notes"]
    assert main([*args, "--pga", "0.2"]) == 0
    assert json.loads(capsys.readouterr().out)["runs"][0]["near_collapse"] is False


def test_a_gap_of_one_level_says_that_level_is_mixed():
    """assess on the house printed 'no run below 0.1 reaches 0.6 Delta_u and every run above 0.1
    does' for an ensemble where 5 % of the members at 0.1 g reached it: true, but silent on the one
    level that decided the fit. It says how many runs at that level reach it, and where that puts
    the median: 2 of 40 at 0.1 and every run at 0.2 put it between them."""
    from rockingwall.sweep import fragility
    est = fragility.fit_tables(np.array([0.1, 0.2]), np.full((2, 2), 20.0), np.array([[2.0, 20.0], [0.0, 20.0]]),
                               what="0.6 Delta_u")
    said = next(w for w in est.warnings if "overlap" in w)
    assert said.startswith("at 0.1, 2 of 40 runs reach 0.6 Delta_u (fewer than half); no intensity below it was "
                           "run; every run above it does")
    assert said.endswith("the median is anywhere in [0.1, 0.2]")
    assert fragility.gap_message((0.1, 0.2), "collapse").startswith(
        "no run at or below 0.1 reaches collapse and every run at or above 0.2 does")


def test_a_median_above_every_intensity_run_is_not_placed_at_the_highest():
    """assess --building on the house at 0.1 and 0.3 g (ensembles of 20) printed for the ground
    storey 'collapsed (over the records and parameters): median at 0.3, beta 0' where 1 of the 40
    members at 0.3 g collapsed and no higher intensity was run: the data put the median above 0.3
    g, not at it (a report would read a 50 % chance of collapse at 0.3 g where the runs give 2.5 %).
    The line, the warning, fragility.csv and the plot's legend now say 'above 0.3'; where more than
    half reach it at the lowest level run, 'below'; where half do, 'at'."""
    from rockingwall import assessment, assessment_plots, assessment_report
    from rockingwall.sweep import fragility
    levels, n = np.array([0.1, 0.3]), np.full((2, 2), 20.0)
    above = fragility.fit_tables(levels, n, np.array([[0.0, 1.0], [0.0, 0.0]]))
    assert above.fit.gap == (pytest.approx(0.3), np.inf) and above.fit.theta == pytest.approx(0.3)
    assert any(w.startswith("at 0.3, 1 of 40 runs reach collapse (fewer than half); no run below it does; no "
                            "intensity above it was run") and w.endswith("the median is above 0.3")
               for w in above.warnings)
    below = fragility.fit_tables(levels, n, np.array([[19.0, 20.0], [20.0, 20.0]]))
    assert below.fit.gap == (0.0, pytest.approx(0.1)) and fragility.gap_median(below.fit.gap) == "below 0.1"
    half = fragility.fit_tables(levels, n, np.array([[0.0, 20.0], [0.0, 0.0]]))
    assert half.fit.gap == pytest.approx((0.3, 0.3)) and fragility.gap_median(half.fit.gap) == "at 0.3"
    frag = pd.DataFrame([dict(limit_state="collapsed", records=2, median=0.3, median_5=0.3, median_95=0.3, beta=0.0,
                              beta_5=0.0, beta_95=0.0, gap_lo=0.3, gap_hi=np.inf, warnings="",
                              over="records and parameters")])
    line = assessment_report.fragility_line(dict(frag.iloc[0], **{assessment.KD_COLUMN: np.nan}), assessment.KD_COLUMN)
    assert "median above 0.3, beta 0 (not identified)" in line
    fig = assessment_plots.fragility_figure(frag, "PGA [g]")
    assert "median above 0.3" in " ".join(t.get_text() for t in fig.axes[0].get_legend().get_texts())
    (span,) = fig.axes[0].patches
    assert np.isfinite(span.get_extents().x1)


def test_assess_without_ensembles_names_a_standing_wall_near_collapse():
    """`assess ... --ensemble 0` printed the assessor's upper wall under its retrofitted roof (scene
    (b), ff07a at 0.5 g) standing at 0.78 Delta_u with no word that one run is one sample there, as
    `run` says of the same case. It names the case near collapse and where its spread comes from;
    with ensembles the P(collapse) and s1 spread columns say it, and no line is added."""
    from rockingwall import assessment, assessment_report
    cases = pd.DataFrame([dict(record="ff07a", pga_g=pga, collapsed=collapsed, s1_over_Delta_u=ratio,
                               **{assessment.KD_COLUMN: 200.0})
                          for pga, collapsed, ratio in ((0.3, False, 0.55), (0.5, False, 0.778), (0.7, True, np.nan))])
    (line,) = assessment_report.near_collapse_without_ensemble(cases)
    assert line.startswith("near collapse: ff07a at 0.5 g, K_d = 200 kN/m per m (s1 = 0.78 Delta_u): standing past "
                           "0.6 Delta_u")
    assert "--ensemble 100 (the default)" in line
    assert assessment_report.near_collapse_without_ensemble(cases.assign(collapse_probability=0.3)) == []


def test_fragility_head_explains_member_fits_only_where_there_are_some():
    """With --ensemble 0 the fragility's head still explained "'over the records and parameters':
    every ensemble member's run", of fits the report did not have."""
    from rockingwall import assessment_report
    row = dict(limit_state="collapsed", records=2, median=0.3, median_5=0.2, median_95=0.4, beta=0.3, beta_5=0.2,
               beta_95=0.4, gap_lo=np.nan, gap_hi=np.nan, warnings="", storey=1.0)
    head = assessment_report.fragility_lines(pd.DataFrame([dict(row, over="records")]), "PGA [g]", "storey")[0]
    assert head.endswith("90 % bootstrap intervals over the records):")
    both = pd.DataFrame([dict(row, over="records"), dict(row, over="records and parameters")])
    assert "every ensemble member's run" in assessment_report.fragility_lines(both, "PGA [g]", "storey")[0]

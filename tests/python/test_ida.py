"""The analysis of a sweep's results file (rockingwall ida): every good row kept past a damaged
line, a run written twice counted once, garbage in an 'ok' row named with its line, a single K_d
plotted, not a traceback. Each test named after a finding failed on the code before the fix."""
import re
import pandas as pd
import pytest

from rockingwall.commands import ida as ida_command
from rockingwall.sweep import ida
from rockingwall.sweep import rows as result_rows


def synthetic_results(tmp_path):
    """A results file written as sweep.py writes it, without running fmi2sim: 2 records x 2 K_d x
    4 PGAs of wall 1, collapse above 0.3 g."""
    out = []
    for rec in ("r1", "r2"):
        for kd in (5.0, 50.0):
            for pga in (0.1, 0.2, 0.3, 0.4):
                spec = dict(run_id=f"w1|flexibleTop|dohertyHinge|kd{kd:g}|{rec}|pga{pga:g}", wall=1,
                            model="flexibleTop", hinge_law="dohertyHinge", kd_kN=kd, record=rec, record_pga_g=0.3,
                            scale=pga / 0.3, pga_g=pga, key="0" * 16)
                out.append(result_rows.make_row(spec, "ok", peak_s1=0.1 * pga + (kd == 5.0) * 0.01, peak_s2=0.05 * pga,
                                       peak_F_top=10.0, collapsed=pga > 0.3 + 0.05 * (rec == "r2"), impacts=3,
                                       end_time=4.0, steps=100, cpu_s=0.01, elapsed_s=0.02))
    path = tmp_path / "synthetic.csv"
    pd.DataFrame(out, columns=result_rows.COLUMNS).to_csv(path, index=False, lineterminator="\n")
    return path


def test_finding04_analysis_keeps_every_good_row(tmp_path, capsys):
    path = synthetic_results(tmp_path)
    lines = path.read_text().splitlines(keepends=True)
    lines[5] = lines[5].replace(",ok,", ',"ok,', 1)
    path.write_text("".join(lines))
    rows_read = ida.load(path, 1, "flexibleTop", "dohertyHinge")
    assert len(rows_read) == len(lines) - 2
    assert f"{path}:6: " in capsys.readouterr().err


def test_finding16_ida_counts_a_run_once(tmp_path):
    path = synthetic_results(tmp_path)
    lines = path.read_text().splitlines(keepends=True)
    path.write_text("".join(lines + lines[1:4]))  # two sweeps wrote three runs twice
    assert len(ida.load(path, 1, "flexibleTop", "dohertyHinge")) == len(lines) - 1


def test_finding16_garbage_in_an_ok_row_is_named_by_ida(tmp_path, capsys):
    path = synthetic_results(tmp_path)
    lines = path.read_text().splitlines(keepends=True)
    fields = lines[4].split(",")
    fields[result_rows.COLUMNS.index("peak_s1")] = "banana"
    lines[4] = ",".join(fields)
    path.write_text("".join(lines))
    assert ida_command.main([str(path), "--out", str(tmp_path / "plots")]) == 1  # plots made, damage reported
    err = capsys.readouterr().err
    assert f"{path}:5: peak_s1 = 'banana' is not a number" in err
    assert (tmp_path / "plots" / "kd_map.png").exists()
    (tmp_path / "empty.csv").write_text("a,b\n1,2\n")
    assert ida_command.main([str(tmp_path / "empty.csv"), "--out", str(tmp_path / "plots")]) == 2
    assert "not a results file" in capsys.readouterr().err


def test_ida_on_a_single_kd_gives_plots_not_a_traceback(tmp_path):
    path = synthetic_results(tmp_path)
    d = pd.read_csv(path)
    d[d.kd_kN == 5.0].to_csv(path, index=False, lineterminator="\n")
    assert ida_command.main([str(path), "--out", str(tmp_path / "plots")]) == 0
    assert (tmp_path / "plots" / "kd_map.png").exists()


def test_a_building_storey_needs_only_its_name(tmp_path, capsys):
    """A building sweep's rows have the model 'building': the storey chosen with --wall alone was
    refused ('no successful runs of wall ..., flexibleTop'), as --model defaulted to flexibleTop. The
    model and hinge law are now the chosen wall's only ones, and a choice the file does not have is
    answered with the ones it has."""
    path = synthetic_results(tmp_path)
    d = pd.read_csv(path)
    d["wall"], d["model"] = d.kd_kN.map({5.0: "house: storey 1", 50.0: "house: storey 2"}), "building"
    d.to_csv(path, index=False, lineterminator="\n")
    assert ida_command.main([str(path), "--out", str(tmp_path / "plots")]) == 2
    assert "runs of 2 walls (house: storey 1, house: storey 2): choose one with --wall" in capsys.readouterr().err
    assert ida_command.main([str(path), "--wall", "house: storey 2", "--out", str(tmp_path / "plots")]) == 0
    assert len(ida.load(path, "house: storey 2")) == 8 and (tmp_path / "plots" / "fragility.png").exists()
    assert re.search(r"K_d \[kN/m per m\] +median \[g\]", capsys.readouterr().out)  # a stiffness per metre of wall
    assert ida_command.main([str(path), "--wall", "house: storey 2", "--model", "flexibleTop",
                             "--out", str(tmp_path / "plots")]) == 2
    assert "no successful runs with --model flexibleTop (here: building)" in capsys.readouterr().err


def test_a_fragility_the_data_cannot_shape_says_so(tmp_path, capsys):
    """Records that all stand below 0.3 g and all collapse above it leave beta unidentified and the
    median anywhere in the gap. ida printed 'median 0.346 g, beta 0.00' and drew a solid step, as
    if both were known; it now says so in the table, the warnings and the legend (dashed, shaded).
    The warning said 'no run below 0.3 reaches collapse and every run above 0.4 does', of
    intensities that were not run where 0.3 and 0.4 g are the gap's own levels: 'at or below'."""
    path = synthetic_results(tmp_path)  # both records stand at 0.3 g and collapse at 0.4 g for K_d = 5
    assert ida_command.main([str(path), "--ida-kd", "5", "--out", str(tmp_path / "plots")]) == 0
    out = capsys.readouterr().out
    assert "(beta not identified)" in out
    assert "K_d = 5 kN/m per m: no run at or below 0.3 reaches collapse and every run at or above 0.4 does" in out
    assert "only 2 records (fewer than 10)" in out
    fig, fits = ida.fragility_figure(ida.load(path).query("kd_kN == 5"))
    (line,) = fig.axes[0].get_lines()[1:]
    assert line.get_linestyle() == "--" and fits[5.0].gap == (0.3, 0.4)
    assert [t.get_text() for t in fig.axes[0].get_legend().get_texts()] == [
        "K_d = 5 kN/m per m: median anywhere in [0.3, 0.4] g, beta not identified"]


def test_ida_names_the_wall_and_the_scene_its_runs_ran_in(tmp_path, capsys):
    """ida printed a fragility and drew three plots without saying which wall or scene they were of:
    a building storey's fragility read like one of the paper's wall on its massless spring. The
    printout and each plot now name the wall and the scene (and the printout what it leaves out);
    a building's storey is chosen by 'storey 2' or 2 alone, where the whole name
    ('house: storey 2') was needed."""
    path = synthetic_results(tmp_path)
    assert ida_command.main([str(path), "--out", str(tmp_path / "wall")]) == 0
    out = capsys.readouterr().out
    assert "wall: 1 (flexibleTop, dohertyHinge)\nscene: the paper's: the top spring K_d (each run's) ends at a " \
           "fixed point\nleft out: the diaphragm's mass and damping and the floor's motion" in out
    assert "(rockingwall sweep --building FILE: the walls in their building)" in out
    d = pd.read_csv(path)
    d["wall"], d["model"] = d.record.map({"r1": "house: storey 1", "r2": "house: storey 2"}), "building"
    d.to_csv(path, index=False, lineterminator="\n")
    for chosen in ("storey 2", "2"):
        assert ida_command.main([str(path), "--wall", chosen, "--out", str(tmp_path / "house")]) == 0
        out = capsys.readouterr().out
        assert out.startswith("wall: house: storey 2 (building, dohertyHinge)\nscene: the wall in its building")
        assert "left out: the diaphragms' higher modes" in out
        # the results cannot say whether the building's in-plane walls were rigid: it said nothing of them
        assert "the in-plane walls' flexibility where the building file takes them as rigid (its default)" in out
    assert ida_command.main([str(path), "--wall", "3", "--out", str(tmp_path / "house")]) == 2
    assert "no successful runs with --wall 3" in capsys.readouterr().err
    fig, _ = ida.fragility_figure(ida.load(path, "2"))
    assert "wall: house: storey 2; scene: the wall in its building" in fig._suptitle.get_text().replace("\n", " ")


def test_a_gap_of_one_level_is_a_median_at_it(tmp_path):
    """Runs that all stand below 0.3 g, all collapse above it and are mixed at 0.3 g leave beta
    unidentified with the median at 0.3 g: the legend said 'median anywhere in [0.3, 0.3] g'; it
    now says 'median at 0.3 g', as the printed warning does."""
    path = synthetic_results(tmp_path)
    d = pd.read_csv(path)
    d = d[d.kd_kN == 5.0]
    d["collapsed"] = (d.pga_g > 0.3) | ((d.pga_g == 0.3) & (d.record == "r2"))
    d.to_csv(path, index=False, lineterminator="\n")
    fig, fits = ida.fragility_figure(ida.load(path))
    assert fits[5.0].gap == (0.3, 0.3)
    assert [t.get_text() for t in fig.axes[0].get_legend().get_texts()] == [
        "K_d = 5 kN/m per m: median at 0.3 g, beta not identified"]


def test_a_median_above_every_intensity_run_is_said_to_be_above_it(tmp_path, capsys):
    """Three records that all stand below 0.4 g, one of them collapsing at 0.4 g, the highest
    intensity run: ida printed the median as 0.400 g, where half the runs would reach collapse,
    and the warning 'every run above it does' of intensities never run. The data put the median
    above 0.4 g; the table, the warning and the legend say so, and the shading stays on the plot."""
    path = synthetic_results(tmp_path)
    d = pd.read_csv(path)
    d = d[d.kd_kN == 5.0]
    d = pd.concat([d, d[d.record == "r1"].assign(record="r3", run_id=lambda r: r.run_id.str.replace("r1", "r3"))])
    d["collapsed"] = (d.pga_g == 0.4) & (d.record == "r2")
    d.to_csv(path, index=False, lineterminator="\n")
    assert ida_command.main([str(path), "--out", str(tmp_path / "plots")]) == 0
    out = capsys.readouterr().out
    assert re.search(r"\n +5 +above 0.4 +0.00 +12  \(beta not identified\)", out)
    assert ("warning: K_d = 5 kN/m per m: at 0.4, 1 of 3 runs reach collapse (fewer than half); no run below it "
            "does; no intensity above it was run: the data do not overlap, so beta is not identified (0) and the "
            "median is above 0.4 g") in out
    fig, fits = ida.fragility_figure(ida.load(path))
    assert fits[5.0].gap == (pytest.approx(0.4), float("inf"))
    assert [t.get_text() for t in fig.axes[0].get_legend().get_texts()] == [
        "K_d = 5 kN/m per m: median above 0.4 g, beta not identified"]
    (span,) = fig.axes[0].patches
    assert fig.axes[0].get_xlim()[1] < 1.0


def test_a_collapse_is_drawn_right_of_every_standing_peak(tmp_path):
    """ida's IDA curves drew a collapse's cross at the run's peaks, which end at the state the wall
    fell from: on the s2 panel of a building sweep the upper storey's collapses at 0.5 g stood at
    40 and 60 mm, left of standing peaks of 130 mm, as if the wall hardly moved. Collapses are now
    in their own column right of every standing peak, as assess's IDA plot has them."""
    d = ida.load(synthetic_results(tmp_path))
    d.loc[d.collapsed, "peak_s2"] = 0.005  # a collapsed run's s2: whatever the state it fell from
    fig = ida.ida_curves_figure(d)
    for ax in fig.axes:
        points = [line.get_xydata() for line in ax.get_lines()
                  if line.get_marker() == "o" and line.get_label() != "median"]
        crosses = [line.get_xydata() for line in ax.get_lines() if line.get_marker() == "x"]
        standing = max(xy[:, 0].max() for xy in points if len(xy))
        assert crosses and min(xy[:, 0].min() for xy in crosses) > standing


def test_the_kd_maps_colour_scale_reads_in_millimetres(tmp_path):
    """ida on a building sweep (one K_d, the upper storey standing at 0.1 g only) labelled the
    colour scale of its median peaks '3.4 x 10^1' to '4.1 x 10^1': a log scale over less than a
    decade. Its ticks are plain numbers now ('34' ... '41' mm), as on a wall sweep's maps."""
    d = ida.load(synthetic_results(tmp_path))
    d = d[d.kd_kN == 5.0].assign(peak_s1=lambda r: 0.0345 + 0.01 * r.pga_g)
    fig = ida.kd_map_figure(d)
    fig.canvas.draw()
    bars = [ax for ax in fig.axes if ax.get_label() == "<colorbar>"]
    labels = [t.get_text() for bar in bars for t in bar.get_yticklabels(which="both") if t.get_text()]
    assert len(bars) == 2 and labels
    assert all(re.fullmatch(r"\d+(\.\d+)?", t) for t in labels), labels


def test_a_record_standing_at_one_level_only_is_drawn(tmp_path, figures):
    """The IDA curves were lines without markers: a record standing at one intensity and collapsing
    at the next (wall 1 on 500 kN/m per m at 0.2 and 0.5 g) was a line of one point, which draws
    nothing, and so was a median finite at one level only. Each level is a dot now."""
    path = synthetic_results(tmp_path)  # r1 collapses above 0.3 g, r2 above 0.35 g: 0.4 g collapses both
    d = pd.read_csv(path)
    d = d[(d.kd_kN == 5.0) & d.pga_g.isin([0.3, 0.4])]
    d.to_csv(path, index=False, lineterminator="\n")
    assert ida_command.main([str(path), "--out", str(tmp_path / "plots")]) == 0
    curves = next(f for f in figures if f._suptitle.get_text().startswith("IDA curves"))
    ax = curves.axes[0]
    standing = [line for line in ax.get_lines() if line.get_color() == "tab:blue"]
    assert len(standing) == 2 and all(len(line.get_xdata()) == 1 and line.get_marker() == "o" for line in standing)
    (median,) = [line for line in ax.get_lines() if line.get_label() == "median"]
    assert len(median.get_xdata()) == 1 and median.get_marker() == "o"

"""What `rockingwall building --out` writes: each record's time histories (CSV) and plot, the
histories an engineer can paste into a report without reading aliasing as motion."""
import json

import numpy as np
import pandas as pd
import pytest

from rockingwall.cli import main
from test_building_tie_force import HOUSE


@pytest.fixture()
def written(tmp_path, capsys, figures):
    """The assessor's house under El Centro at 0.1 g: (its JSON run, its CSV, its figure)."""
    path = tmp_path / "house.toml"
    path.write_text(HOUSE.format(tie="1e8"))
    assert main(["building", str(path), "elcentro", "--pga", "0.1", "--json", "--out", str(tmp_path / "h")]) == 0
    (run,) = json.loads(capsys.readouterr().out)["runs"]
    (fig,) = figures
    return run, pd.read_csv(tmp_path / "h" / "El_Centro_1940_at_0.1_g.csv"), fig


def test_the_written_histories_are_the_filtered_ones_the_table_reads(written):
    """`building --out` wrote the floor's acceleration raw on its 0.01-s grid, where the tie's ringing
    aliases: the upper floor peaked at 6.4 g in the CSV against 1.0 g in the table (El Centro at
    0.3 g). The CSV now has the floor's acceleration and the tie's force filtered at 25 Hz, from the
    same dense run as the table's peaks: on the 0.01-s grid their peaks are never above the table's
    and at most 5 % below (a 25 Hz band seen every 0.01 s; here 4.2 % for the upper floor)."""
    run, history, _ = written
    assert not any(name.startswith("base_acc") for name in history.columns)
    for i, s in enumerate(run["storeys"], 1):
        floor, tie = history[f"floor_acc_25Hz_m_s2_{i}"].abs().max(), history[f"tie_force_25Hz_N_per_m_{i}"].abs().max()
        for written, table in ((floor, s["base_peak_acc_m_s2"]), (tie, s["tie_force_N_per_m"])):
            assert 0.95 * table <= written <= table * (1 + 1e-9)
    upper = run["storeys"][1]
    assert upper["base_peak_acc_raw_m_s2"] > 3 * upper["base_peak_acc_m_s2"]  # what the raw grid would have shown


def test_the_plot_names_the_scene_it_shows(written, tmp_path):
    """building's plot was titled 'El Centro 1940 at 0.1 g: <the building's name>' only: pasted
    into a report it did not say which scene ran (rigid or flexible in-plane walls, diaphragms with
    mass), where every other plot does. Its title now has the scene's line, as run's plot has."""
    from rockingwall import scenes
    from rockingwall.building import building_file
    _, _, fig = written
    scene = scenes.building(building_file.read(tmp_path / "house.toml")).title
    title = " ".join(fig._suptitle.get_text().split())
    assert title.startswith("El Centro 1940 at 0.1 g: ") and "rigid in-plane walls" in scene
    assert f"scene: {' '.join(scene.split())}" in title


def test_each_storeys_panel_draws_its_wall_and_the_diaphragm_it_is_tied_to(written):
    """One panel per storey, the top storey first: its wall's s1 in blue and the diaphragm on top of
    that storey (the one its wall is tied to) in orange, both as the CSV has them, the same colours
    and labels in every panel, and Delta_u dashed in red."""
    run, history, fig = written
    panels = fig.axes
    assert [ax.get_ylabel() for ax in panels] == ["storey 2", "storey 1"]
    for ax in panels:
        i = int(ax.get_ylabel().split()[-1])
        lines = {line.get_label(): line for line in ax.get_lines()}
        s1, diaphragm = lines["wall s1 (mid-height) [mm]"], lines["diaphragm [mm]"]
        assert (s1.get_color(), diaphragm.get_color()) == ("C0", "C1")
        assert np.allclose(s1.get_ydata(), history[f"s1_m_{i}"] * 1e3)
        assert np.allclose(diaphragm.get_ydata(), history[f"diaphragm_m_{i}"] * 1e3)
        assert np.max(np.abs(diaphragm.get_ydata())) == pytest.approx(run["storeys"][i - 1]["diaphragm_peak_m"] * 1e3,
                                                                   rel=0.02)
        du = next(label for label in lines if label.startswith("Delta_u"))
        assert lines[du].get_color() == "C3" and lines[du].get_linestyle() == "--"
        assert du == f"Delta_u = {run['storeys'][i - 1]['delta_u_m'] * 1e3:.0f} mm"
        legend = [t.get_text() for t in ax.get_legend().get_texts()]
        assert legend == ["wall s1 (mid-height) [mm]", "diaphragm [mm]", du]


def test_a_collapsed_wall_is_drawn_up_to_its_collapse(tmp_path, capsys, figures):
    """After a wall collapses the run holds the state it collapsed at: both plots drew that state on
    to the record's end, a wall leaning at 230 mm for 75 s. The wall's lines now end at the collapse,
    marked with an x in the line's colour; `run`'s plot names the collapse in its legend, last, and
    the scene in its title. The assessor's upper wall at 0.3 g of El Centro, in the house and under
    its roof diaphragm alone."""
    house = tmp_path / "house.toml"
    house.write_text(HOUSE.format(tie="1e8"))
    assert main(["building", str(house), "elcentro", "--pga", "0.3", "--json", "--out", str(tmp_path / "h")]) == 0
    upper = json.loads(capsys.readouterr().out)["runs"][0]["storeys"][1]
    wall = ["--b", "230mm", "--h", "3.6", "--W", "14.904kN/m", "--psi", "0.2013", "--Kd", "20kN/m/m"]
    assert main(["run", *wall, "--diaphragm-mass", "200kg/m", "--pga", "0.3", "elcentro", "--json",
                 "--out", str(tmp_path / "r")]) == 0
    alone = json.loads(capsys.readouterr().out)["runs"][0]
    assert upper["collapsed"] and alone["collapsed"]
    building_fig, run_fig = figures
    panel = building_fig.axes[0]  # the top storey's
    s1, mark = (line for line in panel.get_lines() if line.get_color() == "C0")
    assert s1.get_xdata()[-1] <= upper["t_collapse_s"] < s1.get_xdata()[-1] + 0.011
    assert mark.get_marker() == "x" and mark.get_xdata()[-1] == s1.get_xdata()[-1]
    ax = run_fig.axes[1]
    drawn = [line for line in ax.get_lines() if line.get_label().startswith(("s1", "s2"))]
    assert [line.get_xdata()[-1] <= alone["t_collapse_s"] for line in drawn] == [True, True]
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend[-1] == f"collapsed at {alone['t_collapse_s']:.2f} s" and legend[0] == "s1, mid-height [mm]"
    assert "scene: a wall tied (1e+08 N/m per m) to a diaphragm of 20 kN/m per m, 200 kg/m" in run_fig.get_suptitle()


def test_the_history_columns_carry_their_units(written, tmp_path, capsys):
    """The CSVs named their columns s1_1, floor_acc_25Hz_1: a spreadsheet of them did not say what
    the numbers were (m, m/s2, N/m), as the docs alone did. Each name now carries its unit as the
    JSON's keys do, the storey last; `run`'s CSV too."""
    _, history, _ = written
    assert list(history.columns) == ["time_s"] + [f"{name}_{i}" for i in (1, 2) for name in (
        "s1_m", "s2_m", "diaphragm_m", "floor_acc_25Hz_m_s2", "tie_force_25Hz_N_per_m")]
    assert main(["run", "--wall", "paper1", "--Kd", "50kN/m/m", "--scale", "0.5", "elcentro", "--out",
                 str(tmp_path / "r")]) == 0
    (csv,) = (tmp_path / "r").glob("*.csv")
    assert list(pd.read_csv(csv).columns) == ["time_s", "ag_m_s2", "s1_m", "s2_m"]


def test_a_collapsed_walls_columns_are_empty_after_its_collapse(tmp_path, capsys):
    """`building --out` wrote a collapsed wall's held state on to the record's end: at 1 g of El
    Centro the upper wall's s1 sat at 230 mm (its thickness) from 3.46 s to 80 s, with a tie
    force still written for a wall that pulls on none, where `run` leaves those cells empty and
    the table prints '-'. Now the wall's s1, s2 and tie force are empty after its collapse and
    written up to it; its diaphragm and floor, which still move, are written to the end. The
    assessor's house at 0.3 g, where the upper wall collapses and the lower one stands."""
    house = tmp_path / "house.toml"
    house.write_text(HOUSE.format(tie="1e8"))
    assert main(["building", str(house), "elcentro", "--pga", "0.3", "--json", "--out", str(tmp_path / "h")]) == 0
    lower, upper = json.loads(capsys.readouterr().out)["runs"][0]["storeys"]
    assert upper["collapsed"] and not lower["collapsed"]
    history = pd.read_csv(tmp_path / "h" / "El_Centro_1940_at_0.3_g.csv")
    after = history["time_s"] > upper["t_collapse_s"]
    assert 0 < after.sum() < len(history) - 100
    for name in ("s1_m_2", "s2_m_2", "tie_force_25Hz_N_per_m_2"):
        assert history.loc[after, name].isna().all() and history.loc[~after, name].notna().all()
    for name in ("diaphragm_m_2", "floor_acc_25Hz_m_s2_2", "s1_m_1", "s2_m_1", "diaphragm_m_1", "tie_force_25Hz_N_per_m_1"):
        assert history[name].notna().all()
    assert history.loc[after, "diaphragm_m_2"].abs().max() > 1e-3  # the roof still moves

"""The main job (rockingwall demo): its table as the README shows it, close to the paper where the
paper's wall stands, and a collapse shown as a time in the table and as the end of its lines in
the plot, never as a displacement."""
import re

import pytest

from rockingwall import main_job


@pytest.fixture(scope="module")
def runs():
    return main_job.run()


def test_the_readme_shows_what_the_main_job_prints(runs, repo):
    """The README's block is the current code's table (scripts/update_docs.py copies it from the
    main job's results/main_job.txt): a change to the table that left the README as it was fails."""
    readme = (repo / "README.md").read_text()
    block = re.search(r"<!-- BEGIN main-job -->\n```\n(.*?)```\n<!-- END main-job -->", readme, re.S).group(1)
    assert block.splitlines() == main_job.table(runs, 0.5)


def test_the_pinned_and_the_stiff_diaphragm_cases_are_the_papers_within_5_percent(runs):
    for label, _, _, paper_s1, _ in main_job.CASES[:2]:
        assert not runs[label].collapsed
        assert runs[label].peak_s1 == pytest.approx(paper_s1, rel=0.05)


def test_a_collapse_is_a_time_not_a_displacement(runs, figures):
    """The Kd = 5 kN/m per m case collapses: its row printed peaks of 0.1245 and 0.1371 m beside
    the paper's, which are no displacements (the run stops at the instability point), and the
    plot ended its lines without saying why. Now the row has '-' and the collapse's time, and the
    panel's lines end with an x the legend names, last; the figure names the scene."""
    label = main_job.CASES[3][0]
    run = runs[label]
    assert run.collapsed
    row = next(line for line in main_job.table(runs, 0.5) if line.startswith(label))
    assert row.split()[-4:] == ["collapsed", "at", f"{run.t_collapse:.2f}", "s"]
    assert row[len(label):].split()[:4] == ["-", "0.050", "-", "0.109"]
    fig = main_job.figure(runs, 0.5, "exact")
    panel = fig.axes[-1]
    legend = [t.get_text() for t in panel.get_legend().get_texts()]
    assert legend == ["s1 (mid-height)", "s2 (top)", f"collapsed at {run.t_collapse:.2f} s"]
    assert max(line.get_xdata()[-1] for line in panel.get_lines()) <= run.t_collapse
    assert "scene: the paper's" in fig._suptitle.get_text()

"""The claims docs/scenes.md makes from scripts/study_bouc_wen_split.py ("Bouc-Wen on the exact
engine: the method, measured"), checked on a shorter piece of another record: El Centro 1940's
strong seconds 1 to 4 at 0.5 g, the stiff tie. With the linear part exact and the hysteretic
force a polynomial input fitted by Picard iteration, the step is set by z's smoothness: the
line converges at second order, the quadratic at third or better, each in a few Picard rounds,
against DOP853 at rtol 1e-12 (the study's oracle)."""
import numpy as np
import pytest

import study_bouc_wen_split as study
from rockingwall import records

TIE = 1e8


@pytest.fixture(scope="module")
def piece():
    rec = records.el_centro().to_pga(0.5)
    keep = (rec.t >= 1.0 - 1e-9) & (rec.t <= 4.0 + 1e-9)
    t, ag = np.round(rec.t[keep] - 1.0, 9), rec.ag[keep]
    return t, ag, study.oracle(TIE, t, ag)


@pytest.fixture(scope="module")
def runs(piece):
    """each (step, degree) the tests read, run once: history error, end error, steps, Picard rounds"""
    t, ag, truth = piece
    return {(h, degree): study.errors(TIE, t, ag, h, degree, truth=truth)
            for h in (0.0025, 0.00125) for degree in (1, 2)}


def test_the_diaphragm_yields(piece):
    _, _, (_, grid) = piece
    assert max(abs(v) for v in grid.values()) > 1.5 * study.UY


def test_the_line_converges_at_second_order(runs):
    coarse, fine = runs[0.0025, 1], runs[0.00125, 1]
    assert 3.0 < coarse[0] / fine[0] < 5.0, (coarse, fine)


def test_the_quadratic_converges_at_third_order_or_better(runs):
    coarse, fine = runs[0.0025, 2], runs[0.00125, 2]
    assert coarse[1] / fine[1] > 8.0, (coarse, fine)
    assert fine[0] < 1e-6, fine
    assert coarse[3] < 6.0 and fine[3] < 6.0, (coarse, fine)  # Picard rounds a step


def test_the_quadratic_beats_the_line_at_half_the_steps(runs):
    quadratic, line = runs[0.0025, 2], runs[0.00125, 1]
    assert quadratic[0] < line[0] / 5.0, (quadratic, line)

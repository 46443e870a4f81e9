"""`rockingwall run` in the paper's scene tells the user where its answer flips under a tiny change
of the record, as the building's runs do: the sensitivity check (the record scaled by 1 -/+ 1e-9)
on the exact engine, two more runs of about a millisecond."""
import json

import pytest

import rockingwall as rw
from rockingwall import engine
from rockingwall.cli import main

WALL = rw.Wall.make("paper1", Kd=50e3, warn=False)


@pytest.fixture(scope="module")
def threshold():
    """The PGA [g] of El Centro at which wall 1 on 50 kN/m per m starts to collapse, bracketed to
    a few ulps (bisection on the exact engine)."""
    rec = rw.read_record("elcentro")
    lo, hi = 0.15, 0.30
    assert not engine.run(rec.t, rec.to_pga(lo).ag, **WALL.params).collapsed
    assert engine.run(rec.t, rec.to_pga(hi).ag, **WALL.params).collapsed
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        lo, hi = (lo, mid) if engine.run(rec.t, rec.to_pga(mid).ag, **WALL.params).collapsed else (mid, hi)
    return lo, hi


def test_an_answer_at_the_collapse_threshold_is_flagged(threshold):
    """Run in the paper's scene had no sensitivity check: at the PGA where wall 1 starts to collapse
    it printed 'no' (or a collapse time) as firmly as anywhere else. Both sides of the threshold
    are now flagged (the collapse flips under 1e-9), and a PGA away from it is not."""
    rec = rw.read_record("elcentro")
    for pga in threshold:
        r = rw.simulate(WALL, rec.to_pga(pga))
        assert r.sensitive and r.peak_sensitivity == 1.0
    away = rw.simulate(WALL, rec.to_pga(0.15))
    assert not away.sensitive and away.peak_sensitivity < 1e-6


def test_run_prints_and_writes_the_check(threshold, capsys):
    pga = repr(threshold[0])
    assert main(["run", "--wall", "paper1", "--Kd", "50kN/m/m", "--pga", pga, "elcentro"]) == 0
    out = capsys.readouterr().out
    assert "a change of 1e-09 in the record's scale moves a peak by 100.0% or flips a collapse" in out
    assert "(an ensemble (--ensemble 100) or more records give the spread: docs/robustness.md)" in out
    assert main(["run", "--wall", "paper1", "--Kd", "50kN/m/m", "--pga", pga, "elcentro", "--json"]) == 0
    (run,) = json.loads(capsys.readouterr().out)["runs"]
    assert run["sensitive"] is True and run["peak_sensitivity"] == 1.0

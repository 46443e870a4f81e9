"""scripts/study_house_against_cvodes.py on the set's first record: the comparison it makes, its
summary and exit status, and that it flags an engine that is off (the whole set is a long study:
docs/scenes.md, "Checked")."""
import dataclasses

import numpy as np

import study_house_against_cvodes as study


def test_the_first_run_agrees(capsys):
    assert study.main(["--records", "1", "--pga", "0.2"]) == 0
    assert capsys.readouterr().out.strip().splitlines()[-1] == "1 of 1 runs agree"


def test_an_engine_off_by_1e_5_is_flagged(monkeypatch, capsys):
    run = study.se.run

    def off(spec, t, ag, engine=None, **kw):
        r = run(spec, t, ag, engine=engine, **kw)
        return dataclasses.replace(r, peak_s2=np.asarray(r.peak_s2) * (1 + 1e-5)) if engine == "exact" else r

    monkeypatch.setattr(study.se, "run", off)
    assert study.main(["--records", "1", "--pga", "0.2"]) == 1
    assert capsys.readouterr().out.strip().splitlines()[-1] == "0 of 1 runs agree: ff01a at 0.2 g"

"""The engine's sweep entry point (rw_engine_run_many via rw_engine.run_many) against one run()
per parameter set: the same peaks, collapse and impacts to the last bit (both go through the same
rw_engine_run, so any difference is a bug of the batch layer: a wrong parameter set, scale or
output slot), a bad parameter set failing alone, and threads running calls side by side."""
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from rockingwall import engine as rw_engine
from rwref import inputs

WALL_1 = dict(h=2.5, b=0.15, W=6622.0, psi=0.0, er=0.86, support=3, hingeLaw=4)


@pytest.fixture(scope="module")
def record():
    return inputs.el_centro(1.0)


def one_by_one(sig, scales, kds, t_end):
    rows = []
    for sc, kd in zip(scales, kds):
        r = rw_engine.run(sig.t, sig.a * sc, t_end=t_end, Kd=kd, **WALL_1)
        rows.append((r.peak_s1, r.peak_s2, r.collapsed, r.t_collapse, r.impacts))
    return rows


def test_run_many_equals_run_per_set(record):
    scales = np.array([0.2, 0.5, 0.8, 1.5, 0.5])
    kds = np.array([5e4, 5e4, 5e7, 1e4, 1e9])
    r = rw_engine.run_many(record.t, record.a, scale=scales, t_end=20.0, Kd=kds, **WALL_1)
    assert (r["code"] == 0).all()
    assert r["collapsed"].any() and not r["collapsed"].all()  # both outcomes are exercised
    for i, (p1, p2, col, tc, imp) in enumerate(one_by_one(record, scales, kds, 20.0)):
        assert r["peak_s1"][i] == p1 and r["peak_s2"][i] == p2, i
        assert r["collapsed"][i] == col and r["impacts"][i] == imp, i
        assert (np.isnan(tc) and np.isnan(r["t_collapse"][i])) or r["t_collapse"][i] == tc, i


def test_scalars_broadcast(record):
    r = rw_engine.run_many(record.t, record.a, scale=[0.3, 0.6], t_end=10.0, Kd=5e4, **WALL_1)
    one = rw_engine.run(record.t, record.a * 0.6, t_end=10.0, Kd=5e4, **WALL_1)
    assert r["peak_s1"].shape == (2,) and r["peak_s1"][1] == one.peak_s1


def test_bad_set_fails_alone(record):
    r = rw_engine.run_many(record.t, record.a, scale=0.5, t_end=5.0, Kd=5e4, **dict(WALL_1, b=[0.15, -1.0]))
    assert list(r["code"]) == [0, 2]
    assert np.isfinite(r["peak_s1"][0]) and np.isnan(r["peak_s1"][1])


def test_bad_calls_raise(record):
    with pytest.raises(ValueError):
        rw_engine.run_many(record.t, record.a, scale=[0.5, 1.0, 2.0], Kd=[5e4, 5e5], **WALL_1)
    with pytest.raises(rw_engine.EngineError, match="not finite"):
        rw_engine.run_many(record.t, record.a, scale=[0.5, np.nan], Kd=5e4, **WALL_1)
    with pytest.raises(KeyError):
        rw_engine.run_many(record.t, record.a, scale=0.5, notAParameter=1.0)


def test_threads_match_serial(record):
    scales = np.linspace(0.1, 1.0, 8)
    serial = rw_engine.run_many(record.t, record.a, scale=scales, t_end=10.0, Kd=5e4, **WALL_1)
    with ThreadPoolExecutor(2) as pool:
        parts = list(pool.map(lambda s: rw_engine.run_many(record.t, record.a, scale=s, t_end=10.0, Kd=5e4, **WALL_1),
                              [scales[:4], scales[4:]]))
    assert np.array_equal(np.concatenate([p["peak_s1"] for p in parts]), serial["peak_s1"])
    assert np.array_equal(np.concatenate([p["impacts"] for p in parts]), serial["impacts"])

"""Event-driven (hybrid) integration of the models with scipy's solve_ivp (paper Section 4).

Between events the smooth equations of the current discrete state are integrated (default RK45,
RelTol 1e-5, AbsTol 1e-10 as the paper's ode45).  Every event indicator is located by root finding
(terminal events), the event's map is applied (impact: rates times er; switch; breakpoint;
opening / closing of rigid hinges; collapse) and the integration restarts.

Event indicators are oriented: at the start of every segment each indicator gets an orientation s
(+1/-1) such that s*raw >= 0 in the current region, and the event is "s*raw crosses zero downward".
After a map the orientation of the crossed indicator is flipped, so a restart exactly on the
switching surface never re-triggers it.  If the region is undetermined (raw, its rate and its
acceleration all exactly zero, e.g. a semi-rigid wall at rest), the orientation is a guess marked
uncertain: when such an event fires and the motion never entered the guessed region, it is only
a correction of the guess (no map, nothing recorded).
"""
import collections
import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

from . import inputs as _inputs
from .dynamics import make_model
from .params import Params

_BIAS = 1e-30  # offset of uncertain indicators (rad or N m rad): keeps exact zeros from re-triggering


class ZenoError(RuntimeError):
    pass


class Result:
    """Arrays t, q1, q2, dq1, dq2, s1, s2, F_top, energy (time-ordered; an event contributes the
    state just before and just after its map, at the same t), events [(t, kind)], impacts,
    collapsed, t_collapse, peak_s1, peak_s2 (max |.|, also over 3 dense points inside every step),
    nfev, params."""

    def __repr__(self):
        return (f"Result(support={self.params.support}, law={self.params.hinge_law}, n={self.t.size}, "
                f"peak_s1={self.peak_s1:.5g}, peak_s2={self.peak_s2:.5g}, impacts={self.impacts}, "
                f"collapsed={self.collapsed}, t_collapse={self.t_collapse})")


class _Recorder:
    def __init__(self, model):
        self.m = model
        self.rows = []
        self.peak1 = 0.0
        self.peak2 = 0.0

    def add(self, t, y):
        s1, s2, F = self.m.outputs(t, y)
        self.rows.append((t, y[0], y[1], y[2], y[3], s1, s2, F, self.m.energy(t, y)))
        self.peak1 = max(self.peak1, abs(s1))
        self.peak2 = max(self.peak2, abs(s2))

    def peek(self, t, y):  # peaks only
        s1, s2, _ = self.m.outputs(t, y)
        self.peak1 = max(self.peak1, abs(s1))
        self.peak2 = max(self.peak2, abs(s2))


def _orientation(ev, t, y, dy, st):
    if ev.fixed is not None:
        return ev.fixed, True
    if ev.name in st.pending:
        return st.pending.pop(ev.name)
    r = ev.raw(t, y)
    if r != 0:
        return math.copysign(1.0, r), True
    for d in (ev.drate, ev.dacc):
        if d is not None:
            v = d(y, dy)
            if v != 0:
                return math.copysign(1.0, v), True
    return 1.0, False


def _event_fn(ev, s, bias):
    def f(t, y):
        return s * ev.raw(t, y) + bias
    f.terminal = True
    f.direction = -1
    return f


def _base_uplift_rotation(p, model):
    """The base rotation |q1| where a semi-rigid base leaves its elastic range, as a function of
    q1 (the law's first base breakpoint, of the direction of q1: Delta_1 of the base displacement
    h q1/2 for the simply supported wall and dohertyHinge, theta_y for semiRigidHinge and
    semiRigidPaper); None for rigid hinges."""
    if getattr(model, "rigid", True):
        return None
    dirs = {1.0: p.direction(1), -1.0: p.direction(-1)}
    if p.support == "simplySupported" or p.hinge_law == "dohertyHinge":
        return lambda q1: 2 * dirs[-1.0 if q1 < 0 else 1.0].Delta_1 / p.h
    return lambda q1: dirs[-1.0 if q1 < 0 else 1.0].theta_y


def simulate(p, ag, t_end, u_top=None, q0=(0.0, 0.0), dq0=(0.0, 0.0), method="RK45", rtol=1e-5,
             atol=1e-10, max_step=np.inf, t_out=None, progress=False, rest_dt=1e-3,
             zeno_count=200, zeno_window=1e-6, max_events=200000, stop_at_samples=False,
             exact_peaks=False):
    """Simulate model `p` (a Params) under ground acceleration `ag` (callable t -> m/s^2 or
    inputs.Signal, positive toward +x) and top-spring far-end displacement `u_top` (flexibleTop
    only) from t = 0 to t_end.  Returns a Result (see its docstring).

    rest_dt: while every hinge is closed (rigid rest) the opening test is scanned on a grid with
    this step (for Signal inputs: at every sample, which is exact for piecewise-linear inputs).
    A ZenoError is raised if more than `zeno_count` events occur within `zeno_window` seconds.
    stop_at_samples: integrate from one sample of the Signal inputs to the next (where the input,
    linear between samples, has its kinks), as the FMU's hosts and the exact engine do: slower,
    and more accurate on records than steps that straddle the kinks.
    exact_peaks: the peaks at the extrema of the dense output (a bounded search around every local
    maximum of |s1|, |s2| on the refined grid), not at the grid's points, which miss a peak by up
    to (omega dt / 8)^2 / 2 of it (5e-4 at 2 Hz and a record's 0.02 s samples).
    """
    if not isinstance(p, Params):
        raise TypeError("p must be an rwref.Params")
    if not t_end > 0:
        raise ValueError("t_end must be > 0")
    agf = _inputs.as_function(ag)
    uf = _inputs.as_function(u_top)
    model = make_model(p, agf, uf)
    y, st = model.initial(q0, dq0)
    t = 0.0
    t_out = None if t_out is None else np.sort(np.asarray(t_out, dtype=float))
    rec = _Recorder(model)
    events = []
    impacts = 0
    nfev = 0
    collapsed, t_collapse = False, None
    recent = collections.deque(maxlen=zeno_count)
    bar = None
    if progress:
        from tqdm import tqdm
        bar = tqdm(total=float(t_end), unit="s", leave=False)

    def out_points(ta, tb, sol=None, yconst=None):
        if t_out is None:
            return
        for tt in t_out[(t_out > ta) & (t_out < tb)]:
            rec.add(tt, sol(tt) if sol is not None else yconst)

    # Impacts counted (docs/model.md "Impacts"): every base crossing of rigid hinges; with a
    # semi-rigid law only a crossing after the base passed the end of its elastic range (its first
    # base breakpoint, an event, so a step ends on it) since the previous crossing: before any
    # uplift the base oscillates elastically through q1 = 0, which is no impact.
    uplift_q1 = _base_uplift_rotation(p, model)
    uplifted = uplift_q1 is not None and abs(y[0]) >= uplift_q1(y[0]) * (1 - 1e-6)

    def note_uplift(q1_values):
        nonlocal uplifted
        if uplift_q1 is not None and any(abs(q) >= uplift_q1(q) * (1 - 1e-6) for q in (np.max(q1_values),
                                                                                        np.min(q1_values))):
            uplifted = True

    def note(tt, kinds):
        nonlocal impacts, uplifted
        for k in kinds:
            events.append((tt, k))
            if k == "base_impact":
                impacts += 1 if (uplift_q1 is None or uplifted) else 0
                uplifted = False
        if kinds:
            recent.append(tt)
            if len(recent) == zeno_count and recent[-1] - recent[0] < zeno_window:
                raise ZenoError(f"{zeno_count} events within {recent[-1] - recent[0]:.3g} s around t = {tt:.9g} s "
                                f"(support {p.support}, law {p.hinge_law}): accumulating events; "
                                "increase rest_rate or check the inputs")
            if len(events) > max_events:
                raise ZenoError(f"more than {max_events} events by t = {tt:.9g} s")

    rec.add(t, y)
    y2, kinds = model.resolve(t, y, st)
    if kinds:
        note(t, kinds)
        rec.add(t, y2)
        y = y2
    if model.collapse_now(y, st, t):
        collapsed, t_collapse = True, t
        note(t, ["collapse"])

    stalled, t_last = 0, -1.0
    while t < t_end and not collapsed:
        stalled = stalled + 1 if t == t_last else 0
        t_last = t
        if stalled > 1000:
            raise ZenoError(f"no progress at t = {t:.9g} s after 1000 restarts (support {p.support}, law {p.hinge_law})")
        if model.all_closed(st):  # rigid rest: nothing moves until the opening test fails
            t_open = _scan_rest(model, st, t, t_end, agf, uf, rest_dt)
            t_stop = t_end if t_open is None else t_open
            out_points(t, t_stop, yconst=y)
            rec.add(t_stop, y)
            if bar is not None:
                bar.update(t_stop - t)
            t = t_stop
            if t_open is None:
                break
            y2, kinds = model.resolve(t, y, st)
            if not kinds:  # margin exactly zero: step on
                continue
            note(t, kinds)
            rec.add(t, y2)
            y = y2
            continue

        evs = model.events(st)
        dy0 = model.rhs(t, y, st)
        orient = [_orientation(ev, t, y, dy0, st) for ev in evs]
        st.pending.clear()
        for ev, (s, _) in zip(evs, orient):  # discrete sides follow the oriented indicators
            if ev.name == "base" and not st.base_closed:
                st.side_b = s
            elif ev.name == "mid" and not st.mid_closed:
                st.side_m = s
        fns = [_event_fn(ev, s, 0.0 if certain else _BIAS) for ev, (s, certain) in zip(evs, orient)]
        t_start = t
        t_stop = _next_sample(agf, uf, t, t_end) if stop_at_samples else t_end
        sol = solve_ivp(lambda tt, yy: model.rhs(tt, yy, st), (t, t_stop), y, method=method, rtol=rtol,
                        atol=atol, max_step=max_step, events=fns, dense_output=True)
        nfev += sol.nfev
        if sol.status == -1:
            raise RuntimeError(f"integration failed at t = {sol.t[-1]:.9g} s: {sol.message}")
        ts, ys = sol.t, sol.y
        # dense points inside each step (for the peaks, like ode45's Refine = 4)
        if ts.size > 1:
            frac = np.array([0.25, 0.5, 0.75])
            tin = (ts[:-1, None] + np.diff(ts)[:, None] * frac).ravel()
            yin = sol.sol(tin)
            for k in range(tin.size):
                rec.peek(tin[k], yin[:, k])
            if exact_peaks:
                _refine_peaks(rec, model, sol.sol, np.sort(np.concatenate([ts, tin])))
        out_points(t_start, ts[-1], sol=sol.sol)
        for k in range(1, ts.size):
            rec.add(ts[k], ys[:, k])
        if bar is not None:
            bar.update(ts[-1] - t)
        t, y = float(ts[-1]), ys[:, -1].copy()
        note_uplift(ys[0])
        if sol.status != 1:
            if t < t_end:  # a sample of the inputs: on
                continue
            break
        # which event fired (earliest)
        k_ev = min((i for i in range(len(evs)) if len(sol.t_events[i])), key=lambda i: sol.t_events[i][0])
        ev = evs[k_ev]
        s_old, certain = orient[k_ev]
        if not certain:
            tm = 0.5 * (t_start + t)
            if s_old * ev.raw(tm, sol.sol(tm)) <= 0:  # the guessed region was never entered
                st.pending[ev.name] = (-s_old, False)
                continue
        if ev.kind == "collapse":
            if s_old > 0 and not model.elastic(y):
                collapsed, t_collapse = True, t
                note(t, ["collapse"])
                break
            st.pending[ev.name] = (-s_old, True)  # G < 0 only inside the elastic range: not a collapse
            continue
        y2, kinds = model.handle(ev, t, y, st, s_old)
        y3, kinds2 = model.resolve(t, y2, st)
        kinds = kinds + kinds2
        note(t, kinds)
        rec.add(t, y3)
        y = y3
        if model.collapse_now(y, st, t):
            collapsed, t_collapse = True, t
            note(t, ["collapse"])
    if bar is not None:
        bar.close()

    arr = np.array(rec.rows, dtype=float)
    res = Result()
    res.params = p
    for i, name in enumerate(("t", "q1", "q2", "dq1", "dq2", "s1", "s2", "F_top", "energy")):
        setattr(res, name, arr[:, i].copy())
    res.events = events
    res.impacts = impacts
    res.collapsed = collapsed
    res.t_collapse = t_collapse
    res.peak_s1 = rec.peak1
    res.peak_s2 = rec.peak2
    res.nfev = nfev
    return res


def _refine_peaks(rec, model, dense, tg):
    """Raise rec's peaks to the maxima of |s1| and |s2| between the points tg of one step: a
    bounded search on the dense output around each interior point where the sampled |s| peaks."""
    yg = dense(tg)
    s = np.abs(np.array([model.outputs(tg[k], yg[:, k])[:2] for k in range(tg.size)]))
    for j in range(2):
        v = s[:, j]
        for k in np.flatnonzero((v[1:-1] >= v[:-2]) & (v[1:-1] >= v[2:]) & (v[1:-1] > 0)) + 1:
            r = minimize_scalar(lambda tt: -abs(model.outputs(tt, dense(tt))[j]), bounds=(tg[k - 1], tg[k + 1]),
                                method="bounded", options={"xatol": 1e-13})
            rec.peek(r.x, dense(r.x))


def _next_sample(agf, uf, t, t_end):
    """The first sample time of the Signal inputs after t (t_end if none)."""
    after = [f.knots(t, t_end)[:1] for f in (agf, uf) if isinstance(f, _inputs.Signal)]
    return float(min(np.concatenate(after + [np.array([t_end])])))


def _scan_rest(model, st, t, t_end, agf, uf, rest_dt):
    """First time in (t, t_end] at which the rest opening test fails, or None."""
    def margin(tt):
        return model.rest_margin(tt, st)

    grids = []
    for f in (agf, uf):
        if isinstance(f, _inputs.Signal):
            grids.append(f.knots(t, t_end))
        elif f is not _inputs.zero and not isinstance(f, _inputs.Constant):
            grids.append(np.arange(t + rest_dt, t_end, rest_dt))
    if isinstance(agf, _inputs.Ramp):
        grids.append(np.array([agf.t_start, agf.t_start + agf.t_ramp]))
    grid = np.unique(np.concatenate(grids + [np.array([t_end])]))
    grid = grid[(grid > t) & (grid <= t_end)]
    ta, ma = t, margin(t)
    for tb in grid:
        mb = margin(tb)
        if mb < 0:
            if ma <= 0:
                return ta
            tr = brentq(margin, ta, tb, xtol=1e-15, rtol=4 * np.finfo(float).eps)
            for _ in range(60):  # make sure the test really fails at the returned time
                if margin(tr) < 0 or tr >= tb:
                    break
                tr = min(tb, tr + max(1e-15, abs(tr) * 4e-16))
            return tr if margin(tr) < 0 else tb
        ta, ma = tb, mb
    return None

"""Equations of motion of the three models (docs/model.md), one class per model.

Every model works on the same state vector y = [q1, q2, dq1, dq2] (rad, rad/s); in the 1DOF
models q2 is slaved (simplySupported: q2 = -q1; parapet: q2 = q1).  A model object provides
  rhs(t, y, st)          dy/dt in the current discrete state `st` (a Mode),
  events(st)             the event indicators of that discrete state (see `Event`),
  handle(ev, t, y, st)   the map applied when `ev` crosses (impact, switch, breakpoint, ...),
  resolve(t, y, st)      the opening tests of closed rigid hinges (rest / closed-hinge states),
  rest_margin(t, st)     while everything is closed: min(capacity - |demand|) (>= 0: stays at rest),
  collapse_now(y, st)    the collapse criterion evaluated at a state,
  outputs(t, y)          s1, s2, F_top;  energy(t, y) the spec's energy.
The hybrid integration (event location, restarts) is in solver.py.
"""
import math
from dataclasses import dataclass, field

import numpy as np

from .hinge_laws import make_law, toppling_limit


def _sign(x):
    return 1.0 if x > 0 else (-1.0 if x < 0 else 0.0)


@dataclass
class Mode:
    """Discrete state: hinge sides (+1/-1) and closed flags (rigid hinges / rest)."""
    side_b: float = 1.0
    side_m: float = 1.0
    base_closed: bool = False
    mid_closed: bool = False
    pending: dict = field(default_factory=dict)  # event name -> (orientation, certain), set by maps


@dataclass
class Event:
    """An event indicator.  raw(t, y) changes sign at the event; drate(y, dy) is d raw/dt.
    kind: 'base', 'mid', 'breakpoint', 'open_b', 'open_m', 'collapse'.
    fixed: +1/-1 if the orientation is fixed by the discrete state (opening indicators), else None."""
    name: str
    kind: str
    raw: object
    drate: object = None
    dacc: object = None
    fixed: float = None


class _Base:
    rigid = False

    def __init__(self, p, ag, u):
        self.p, self.ag, self.u = p, ag, u

    def all_closed(self, st):
        return st.base_closed and (st.mid_closed or self.one_dof)

    def resolve(self, t, y, st):
        return y, []

    def elastic(self, y):
        return False

    def outputs(self, t, y):
        h = self.p.h
        return y[0] * h / 2, (y[0] + y[1]) * h / 2, 0.0


# ---------------------------------------------------------------------------------------------
class Parapet(_Base):
    """Housner's rigid block (docs/model.md "Support 1"): theta'' = -p^2 [sin(s a - th) + (ag/g) cos(s a - th)]."""
    one_dof = True
    rigid = True

    def __init__(self, p, ag, u):
        super().__init__(p, ag, u)
        self.alpha, self.p2 = p.alpha, p.p_housner**2
        self.thr = p.g * math.tan(self.alpha)  # uplift threshold |ag| > g tan(alpha)

    def initial(self, q0, dq0):
        th, w = float(q0[0]), float(dq0[0])
        st = Mode()
        if th == 0 and w == 0:
            st.base_closed = True
        else:
            st.side_b = _sign(th) if th != 0 else _sign(w)
            st.pending["base"] = (st.side_b, True)
        return np.array([th, th, w, w]), st

    def rhs(self, t, y, st):
        if st.base_closed:
            return np.zeros(4)
        s = st.side_b
        th = y[0]
        a = -self.p2 * (math.sin(s * self.alpha - th) + self.ag(t) / self.p.g * math.cos(s * self.alpha - th))
        return np.array([y[2], y[3], a, a])

    def events(self, st):
        return [Event("base", "base", lambda t, y: y[0], lambda y, dy: dy[0], lambda y, dy: dy[2]),
                Event("collapse", "collapse", lambda t, y: self.alpha - abs(y[0]), fixed=1.0)]

    def rest_margin(self, t, st):
        return self.thr - abs(self.ag(t))

    def resolve(self, t, y, st):
        if st.base_closed and abs(self.ag(t)) > self.thr:
            st.base_closed = False
            st.side_b = -_sign(self.ag(t))
            st.pending["base"] = (st.side_b, True)
            return y, ["open"]
        return y, []

    def handle(self, ev, t, y, st, s_old):
        y = y.copy()
        if ev.kind == "base":  # impact at theta = 0: theta' *= er
            y[0] = y[1] = 0.0
            y[2] *= self.p.er
            y[3] = y[2]
            rec = ["base_impact"]
            if abs(y[2]) < self.p.rest_rate:
                y[:] = 0.0
                st.base_closed = True
                rec.append("close")
            else:
                st.side_b = -s_old
                st.pending["base"] = (-s_old, -s_old * y[2] > 0)
            return y, rec
        raise AssertionError(ev.kind)

    def collapse_now(self, y, st, t=0.0):
        return abs(y[0]) >= self.alpha

    def outputs(self, t, y):
        return y[0] * self.p.h / 2, y[0] * self.p.h, 0.0

    def energy(self, t, y):
        p = self.p
        th, w = y[0], y[2]
        return 0.5 * (p.W / p.g) * p.inertia_per_mass * w**2 + p.W * p.R * (math.cos(self.alpha - abs(th)) - math.cos(self.alpha))


# ---------------------------------------------------------------------------------------------
class SimplySupported(_Base):
    """Doherty's 1DOF (docs/model.md "Support 2"): (W/3g) D'' = -(W/2g) ag + F(D), D = q1 h/2, q2 = -q1."""
    one_dof = True

    def __init__(self, p, ag, u):
        super().__init__(p, ag, u)
        self.rigid = p.hinge_law == "rigid"
        self.dirs = {1.0: p.direction(1), -1.0: p.direction(-1)}
        # rigid: at rest while -F_r(-1) <= -W ag/(2g) <= F_r(+1), i.e. -thr(+1) <= ag <= thr(-1)
        self.thr = {d: 2 * r.F_r * p.g / p.W for d, r in self.dirs.items()}

    def dir(self, v):
        """The direction of a displacement (or side) v: +1 at zero."""
        return self.dirs[-1.0 if v < 0 else 1.0]

    def initial(self, q0, dq0):
        q1, w = float(q0[0]), float(dq0[0])
        st = Mode()
        if self.rigid and q1 == 0 and w == 0:
            st.base_closed = True
        elif self.rigid:
            st.side_b = _sign(q1) if q1 != 0 else _sign(w)
            st.pending["base"] = (st.side_b, True)
        return np.array([q1, -q1, w, -w]), st

    def force(self, D, st):
        """Resisting force F(D) (N/m) of the direction of D: trilinear (Fig. 5.2, semi-rigid) or
        rigid (on the active side s: -F_r s + (F_r/Delta_u) D)."""
        a = abs(D)
        if self.rigid:
            r = self.dir(st.side_b)
            return -r.F_r * st.side_b + r.F_r / r.Delta_u * D
        r = self.dir(D)
        if a <= r.Delta_1:
            f = r.F_i * a / r.Delta_1
        elif a <= r.Delta_2:
            f = r.F_i
        else:
            f = r.F_r * (1 - a / r.Delta_u)
        return -_sign(D) * f

    def rhs(self, t, y, st):
        if st.base_closed:
            return np.zeros(4)
        p = self.p
        D = y[0] * p.h / 2
        Ddd = (3 * p.g / p.W) * (-(p.W / (2 * p.g)) * self.ag(t) + self.force(D, st))
        a = Ddd * 2 / p.h
        return np.array([y[2], -y[2], a, -a])

    def events(self, st):
        p = self.p
        h2 = p.h / 2
        ev = [Event("base", "base", lambda t, y: y[0], lambda y, dy: dy[0], lambda y, dy: dy[2])]
        if not self.rigid:
            for name, key in (("bp1", "Delta_1"), ("bp2", "Delta_2")):
                ev.append(Event(name, "breakpoint", lambda t, y, k=key: abs(y[0]) * h2 - getattr(self.dir(y[0]), k),
                                lambda y, dy: _sign(y[0]) * dy[0] * h2))
        ev.append(Event("collapse", "collapse", lambda t, y: self.dir(y[0]).Delta_u - abs(y[0]) * h2, fixed=1.0))
        return ev

    def rest_margin(self, t, st):
        a = self.ag(t)
        return min(self.thr[1.0] + a, self.thr[-1.0] - a)

    def resolve(self, t, y, st):
        if self.rigid and st.base_closed and self.rest_margin(t, st) < 0:
            st.base_closed = False
            st.side_b = -_sign(self.ag(t))
            st.pending["base"] = (st.side_b, True)
            return y, ["open"]
        return y, []

    def handle(self, ev, t, y, st, s_old):
        y = y.copy()
        if ev.kind == "base":  # impact at D = 0: dD *= er
            y[0] = y[1] = 0.0
            y[2] *= self.p.er
            y[3] = -y[2]
            rec = ["base_impact"]
            if self.rigid and abs(y[2]) < self.p.rest_rate:  # |dD| < restRate*h/2
                y[:] = 0.0
                st.base_closed = True
                rec.append("close")
            else:
                st.side_b = -s_old
                st.pending["base"] = (-s_old, -s_old * y[2] > 0)
            return y, rec
        if ev.kind == "breakpoint":
            dy = self.rhs(t, y, st)
            st.pending[ev.name] = (-s_old, -s_old * ev.drate(y, dy) > 0)
            return y, ["breakpoint"]
        raise AssertionError(ev.kind)

    def collapse_now(self, y, st, t=0.0):
        return abs(y[0]) * self.p.h / 2 >= self.dir(y[0]).Delta_u

    def outputs(self, t, y):
        return y[0] * self.p.h / 2, 0.0, 0.0

    def potential(self, D):
        """The integral of -F from 0 to D, in the direction of D."""
        r = self.dir(D)
        a = abs(D)
        if self.rigid:
            return r.F_r * (a - a * a / (2 * r.Delta_u))
        d1, d2 = r.Delta_1, r.Delta_2
        if a <= d1:
            return r.F_i * a * a / (2 * d1)
        v = r.F_i * d1 / 2
        if a <= d2:
            return v + r.F_i * (a - d1)
        v += r.F_i * (d2 - d1)
        return v + r.F_r * ((a - d2) - (a * a - d2 * d2) / (2 * r.Delta_u))

    def energy(self, t, y):
        p = self.p
        D, dD = y[0] * p.h / 2, y[2] * p.h / 2
        return 0.5 * p.W / (3 * p.g) * dD**2 + self.potential(D)


# ---------------------------------------------------------------------------------------------
class FlexibleTop(_Base):
    """The paper's 2DOF (docs/model.md "Support 3"): M q'' + K q = p(ag) + f_u(u_top) + Q(q) (Eq. 3.1-3.8)."""
    one_dof = False

    def __init__(self, p, ag, u):
        super().__init__(p, ag, u)
        self.law = make_law(p)
        self.rigid = self.law.set_valued
        self.q_topple = toppling_limit(p)
        (self.m11, self.m12), (_, self.m22) = p.M
        (self.k11, self.k12), (_, self.k22) = p.K
        self.det = self.m11 * self.m22 - self.m12**2
        self.pa1, self.pa2 = p.p_per_ag
        self.fu = p.fu_per_u[0]
        self.cb = {s: p.cap_b_side(s) for s in (1.0, -1.0)}   # the capacities on each side
        self.cm = {s: p.cap_m_side(s) for s in (1.0, -1.0)}
        self.ks = self.k11 + 2 * self.k12 + self.k22
        self.ms = self.m11 + 2 * self.m12 + self.m22

    def initial(self, q0, dq0):
        q1, q2 = map(float, q0)
        v1, v2 = map(float, dq0)
        st = Mode()
        if self.rigid:
            st.base_closed = q1 == 0 and v1 == 0
            st.mid_closed = (q2 - q1) == 0 and (v2 - v1) == 0
        if not st.base_closed and (q1 != 0 or v1 != 0):
            st.side_b = _sign(q1) if q1 != 0 else _sign(v1)
            st.pending["base"] = (st.side_b, True)
        if not st.mid_closed and (q2 - q1 != 0 or v2 - v1 != 0):
            st.side_m = _sign(q2 - q1) if q2 != q1 else _sign(v2 - v1)
            st.pending["mid"] = (st.side_m, True)
        return np.array([q1, q2, v1, v2]), st

    def F(self, t):
        """F = p(ag) + f_u(u_top) (Eq. 3.4 with ag positive toward +x)."""
        a, u = self.ag(t), self.u(t)
        fu = self.fu * u
        return self.pa1 * a + fu, self.pa2 * a + fu

    def Q(self, q1, q2, st):
        """Hinge terms (A_i, B_i of Eq. 3.5-3.8 corrected, with the law's finite stiffness)."""
        return self.law.moments(q1, q2, st.side_b, st.side_m)

    def rhs(self, t, y, st):
        q1, q2, v1, v2 = y
        if self.rigid and st.base_closed and st.mid_closed:
            return np.zeros(4)
        F1, F2 = self.F(t)
        if self.rigid and st.base_closed:  # q1 = dq1 = 0; row 2 alone
            a2 = (F2 - self.k22 * q2 - self.cm[st.side_m] * st.side_m) / self.m22
            return np.array([0.0, v2, 0.0, a2])
        if self.rigid and st.mid_closed:  # q1 = q2 = theta
            a = (F1 + F2 - self.ks * q1 - self.cb[st.side_b] * st.side_b) / self.ms
            return np.array([v1, v1, a, a])
        Q1, Q2 = self.Q(q1, q2, st)
        r1 = F1 - self.k11 * q1 - self.k12 * q2 + Q1
        r2 = F2 - self.k12 * q1 - self.k22 * q2 + Q2
        a1 = (self.m22 * r1 - self.m12 * r2) / self.det
        a2 = (self.m11 * r2 - self.m12 * r1) / self.det
        return np.array([v1, v2, a1, a2])

    # demands on closed rigid hinges (docs/model.md "Rigid hinges")
    def f_b_baseclosed(self, t, y, st):
        F1, F2 = self.F(t)
        q2 = y[1]
        a2 = (F2 - self.k22 * q2 - self.cm[st.side_m] * st.side_m) / self.m22
        return F1 - self.k12 * q2 + self.cm[st.side_m] * st.side_m - self.m12 * a2

    def f_m_midclosed(self, t, y, st):
        F1, F2 = self.F(t)
        th = y[0]
        a = (F1 + F2 - self.ks * th - self.cb[st.side_b] * st.side_b) / self.ms
        return F2 - (self.k12 + self.k22) * th - (self.m12 + self.m22) * a

    @staticmethod
    def margin(f, cap):
        """cbar - |f - delta| of a closed hinge with the capacities cap[+1], cap[-1]: >= 0 while it
        holds (-cap[-1] <= f <= cap[+1]), 0 at either limit."""
        cbar, delta = (cap[1.0] + cap[-1.0]) / 2, (cap[1.0] - cap[-1.0]) / 2
        return cbar - abs(f - delta)

    @staticmethod
    def opening_side(f, cap):
        """The side a closed hinge opens to under the moment f, or 0 if it holds."""
        return 1.0 if f > cap[1.0] else (-1.0 if -f > cap[-1.0] else 0.0)

    def G_t(self, t, y, st):
        """Collapse indicator G(q) = q . (K q - Q(q)) (docs/model.md "Collapse"); the spring counts as
        if the diaphragm held still, so a pushed-but-stable wall (u_top != 0) is not flagged.

        Q(q) is the hinge law as a function of q: sides from the signs of q1 and x = q2 - q1 themselves
        (not the tracked sides), so for the rigid law -q.Q = cap_b(s_b)|q1| + cap_m(s_m)|x| >= 0."""
        q1, q2 = y[0], y[1]
        sb = _sign(q1) or st.side_b
        sm = _sign(q2 - q1) or st.side_m
        Q1, Q2 = self.law.moments(q1, q2, sb, sm)
        return (q1 * (self.k11 * q1 + self.k12 * q2 - Q1)
                + q2 * (self.k12 * q1 + self.k22 * q2 - Q2))

    def elastic(self, y):
        return self.law.elastic(y[0], y[1])

    def toppled(self, y):
        """Past the toppling limit of a body (docs/model.md "Collapse"): a guard."""
        return max(abs(y[0]), abs(y[1])) >= self.q_topple

    def collapse_now(self, y, st, t=0.0):
        return ((not self.elastic(y)) and self.G_t(t, y, st) <= 0) or self.toppled(y)

    def events(self, st):
        base = Event("base", "base", lambda t, y: y[0], lambda y, dy: dy[0], lambda y, dy: dy[2])
        mid = Event("mid", "mid", lambda t, y: y[1] - y[0], lambda y, dy: dy[1] - dy[0], lambda y, dy: dy[3] - dy[2])
        col = [Event("collapse", "collapse", lambda t, y: self.G_t(t, y, st)),
               Event("topple", "collapse", lambda t, y: self.q_topple - max(abs(y[0]), abs(y[1])), fixed=1.0)]
        if self.rigid:
            if st.base_closed:  # mid open
                return [mid, Event("open_b", "open_b", lambda t, y: self.margin(self.f_b_baseclosed(t, y, st), self.cb),
                                   fixed=1.0)] + col
            if st.mid_closed:
                return [base, Event("open_m", "open_m", lambda t, y: self.margin(self.f_m_midclosed(t, y, st), self.cm),
                                    fixed=1.0)] + col
            return [base, mid] + col
        bps = [Event(name, "breakpoint", lambda t, y, f=raw: f(y), rate) for name, raw, rate in self.law.breakpoints()]
        return [base, mid] + bps + col

    def rest_margin(self, t, st):
        F1, F2 = self.F(t)
        return min(self.margin(F1 + F2, self.cb), self.margin(F2, self.cm))

    def resolve(self, t, y, st):
        """Opening tests of closed rigid hinges; repeated until consistent (docs/model.md)."""
        rec = []
        if not self.rigid:
            return y, rec
        y = y.copy()
        for _ in range(4):
            F1, F2 = self.F(t)
            if st.base_closed and st.mid_closed:
                fb, fm = F1 + F2, F2
                sb, sm = self.opening_side(fb, self.cb), self.opening_side(fm, self.cm)
                ob, om = sb != 0, sm != 0
                if not (ob or om):
                    return y, rec
                if ob and om:
                    # base alone if the mid hinge then holds; else mid alone if the base then holds; else both
                    a = (F1 + F2 - self.cb[sb] * sb) / self.ms
                    holds_m = not self.opening_side(F2 - (self.m12 + self.m22) * a, self.cm)
                    a2 = (F2 - self.cm[sm] * sm) / self.m22
                    holds_b = not self.opening_side(F1 + self.cm[sm] * sm - self.m12 * a2, self.cb)
                    ob = holds_m or not holds_b
                    om = (not holds_m)
                if ob:
                    st.base_closed, st.side_b = False, sb
                    st.pending["base"] = (sb, True)
                if om:
                    st.mid_closed, st.side_m = False, sm
                    st.pending["mid"] = (sm, True)
                rec.append("open")
                continue
            if st.base_closed:
                sb = self.opening_side(self.f_b_baseclosed(t, y, st), self.cb)
                if sb:
                    st.base_closed, st.side_b = False, sb
                    st.pending["base"] = (st.side_b, True)
                    rec.append("open")
                    continue
            if st.mid_closed:
                sm = self.opening_side(self.f_m_midclosed(t, y, st), self.cm)
                if sm:
                    st.mid_closed, st.side_m = False, sm
                    st.pending["mid"] = (st.side_m, True)
                    rec.append("open")
                    continue
            return y, rec
        return y, rec

    def handle(self, ev, t, y, st, s_old):
        y = y.copy()
        p = self.p
        if ev.kind == "base":  # impact at q1 = 0: both rates times er
            y[0] = 0.0
            if self.rigid and st.mid_closed:
                y[1] = 0.0
            y[2] *= p.er
            y[3] *= p.er
            rec = ["base_impact"]
            if self.rigid and abs(y[2]) < p.rest_rate:
                y[0] = y[2] = 0.0
                if st.mid_closed:
                    y[1] = y[3] = 0.0
                st.base_closed = True
                rec.append("close")
            else:
                st.side_b = -s_old
                st.pending["base"] = (-s_old, -s_old * y[2] > 0)
            return y, rec
        if ev.kind == "mid":  # mid-hinge switch, no energy loss (paper Section 4)
            y[1] = y[0]
            rec = ["mid_switch"]
            if self.rigid and abs(y[3] - y[2]) < p.rest_rate:
                y[3] = y[2]
                st.mid_closed = True
                rec.append("close")
            else:
                st.side_m = -s_old
                st.pending["mid"] = (-s_old, -s_old * (y[3] - y[2]) > 0)
            return y, rec
        if ev.kind == "breakpoint":
            dy = self.rhs(t, y, st)
            st.pending[ev.name] = (-s_old, -s_old * ev.drate(y, dy) > 0)
            return y, ["breakpoint"]
        if ev.kind == "open_b":  # the demand reached the capacity: the base opens on side sign(f_b)
            st.base_closed, st.side_b = False, _sign(self.f_b_baseclosed(t, y, st)) or 1.0
            st.pending["base"] = (st.side_b, True)
            return y, ["open"]
        if ev.kind == "open_m":
            st.mid_closed, st.side_m = False, _sign(self.f_m_midclosed(t, y, st)) or 1.0
            st.pending["mid"] = (st.side_m, True)
            return y, ["open"]
        raise AssertionError(ev.kind)

    def outputs(self, t, y):
        s1 = y[0] * self.p.h / 2
        s2 = (y[0] + y[1]) * self.p.h / 2
        return s1, s2, self.p.Kd * (s2 - self.u(t))

    def hinge_potential(self, q1, x):
        return self.law.potential(q1, x)

    def energy(self, t, y):
        """E = 1/2 dq'M dq + 1/2 q'K_grav q + 1/2 Kd (s2 - u_top)^2 + V_h(q)  (spec's E when u_top = 0)."""
        q1, q2, v1, v2 = y
        p = self.p
        T = 0.5 * (self.m11 * v1 * v1 + 2 * self.m12 * v1 * v2 + self.m22 * v2 * v2)
        ks = p.Kd * p.h**2 / 4
        Vg = 0.5 * ((self.k11 - ks) * q1 * q1 + 2 * (self.k12 - ks) * q1 * q2 + (self.k22 - ks) * q2 * q2)
        s2 = (q1 + q2) * p.h / 2
        Vs = 0.5 * p.Kd * (s2 - self.u(t)) ** 2
        return T + Vg + Vs + self.hinge_potential(q1, q2 - q1)


def make_model(p, ag, u):
    return {"parapet": Parapet, "simplySupported": SimplySupported, "flexibleTop": FlexibleTop}[p.support](p, ag, u)

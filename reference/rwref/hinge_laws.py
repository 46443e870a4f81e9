"""The 2DOF hinge laws of docs/model.md ("Hinge laws"), one class per law.

Each law gives the generalised hinge moments Q(q) (the A_i, B_i of the paper's Eq. 3.5-3.8,
corrected), its potential V_h (Q = -grad V_h) where it has one, the breakpoints where Q(q) has a
kink (located as events by the solver), and the elastic range (collapse is not tested inside it).
The laws that come from a potential write Q1 = -cap_b mu_b + cap_m mu_m, Q2 = -cap_m mu_m with the
normalised moments mu_b(q1) and mu_m(x), x = q2 - q1, and the capacities of the sides the hinges
turn to. A hinge takes its law's data from a direction of the mid-height's motion: the base
turning to side s from direction s, the mid-height hinge turning to side s from direction -s.
"""


def _sign(x):
    return 1.0 if x > 0 else (-1.0 if x < 0 else 0.0)


def _side(x):
    """The side of a rotation: its sign, +1 at zero (where the moments of these laws vanish)."""
    return -1.0 if x < 0 else 1.0


def _sat(z):
    return max(-1.0, min(1.0, z))


class HingeLaw:
    name = None
    set_valued = False  # rigid hinges: mu = sign, with rest and closed-hinge states

    def __init__(self, p):
        self.p = p
        self.dirs = {1.0: p.direction(1), -1.0: p.direction(-1)}

    def base_dir(self, s):
        return self.dirs[_side(s)]

    def mid_dir(self, s):
        return self.dirs[-_side(s)]

    def from_mu(self, mu_b, mu_m, sb, sm):
        """Q from the normalised moments and the sides sb, sm whose capacities act."""
        cb, cm = self.p.cap_b_side(_side(sb)), self.p.cap_m_side(_side(sm))
        return -cb * mu_b + cm * mu_m, -cm * mu_m

    def breakpoints(self):
        """[(name, raw(y), rate(y, dy))]: raw changes sign at a kink of Q."""
        return []


class Rigid(HingeLaw):
    name = "rigid"
    set_valued = True

    def moments(self, q1, q2, side_b, side_m):
        return self.from_mu(side_b, side_m, side_b, side_m)

    def potential(self, q1, x):
        return self.p.cap_b_side(_side(q1)) * abs(q1) + self.p.cap_m_side(_side(x)) * abs(x)

    def elastic(self, q1, q2):
        return q1 == 0 and q2 == 0


def _abs_event(name, value, rate, limit):
    """|value(y)| = limit(side of value) as an event (the limits of the two sides may differ)."""
    return (name, lambda y: abs(value(y)) - limit(_side(value(y))), lambda y, dy: _sign(value(y)) * rate(dy))


_Q1 = (lambda y: y[0], lambda dy: dy[0])
_X = (lambda y: y[1] - y[0], lambda dy: dy[1] - dy[0])
_Q2 = (lambda y: y[1], lambda dy: dy[1])


class SemiRigidHinge(HingeLaw):
    """Each hinge's moment grows linearly with its own rotation and saturates at its theta_y."""
    name = "semiRigidHinge"

    def ty_b(self, s):
        return self.base_dir(s).theta_y

    def ty_m(self, s):
        return self.mid_dir(s).theta_y

    def moments(self, q1, q2, side_b, side_m):
        x = q2 - q1
        return self.from_mu(_sat(q1 / self.ty_b(q1)), _sat(x / self.ty_m(x)), q1, x)

    @staticmethod
    def _phi(z, ty):
        u = abs(z) / ty
        return ty * (0.5 * u * u if u <= 1 else u - 0.5)

    def potential(self, q1, x):
        return (self.p.cap_b_side(_side(q1)) * self._phi(q1, self.ty_b(q1))
                + self.p.cap_m_side(_side(x)) * self._phi(x, self.ty_m(x)))

    def breakpoints(self):
        return [_abs_event("bp_b", *_Q1, self.ty_b), _abs_event("bp_m", *_X, self.ty_m)]

    def elastic(self, q1, q2):
        x = q2 - q1
        return abs(q1) <= self.ty_b(q1) and abs(x) <= self.ty_m(x)


class SemiRigidPaper(SemiRigidHinge):
    """Fig. 4.1/4.2: A_c min(1, |q1|/ty), B_c min(1, |q2|/ty) with the constants of the condition
    given by the sides; the saturation on q1 of the direction sign(q1), the one on q2 of -sign(q2).
    Not from a potential (its `potential` is semiRigidHinge's, as a measure)."""
    name = "semiRigidPaper"

    def ty_2(self, q2):
        return self.dirs[-_side(q2)].theta_y

    def moments(self, q1, q2, side_b, side_m):
        A = -self.p.cap_b_side(side_b) * side_b + self.p.cap_m_side(side_m) * side_m
        B = -self.p.cap_m_side(side_m) * side_m
        return A * min(1.0, abs(q1) / self.ty_b(q1)), B * min(1.0, abs(q2) / self.ty_2(q2))

    def breakpoints(self):
        return [_abs_event("bp_b", *_Q1, self.ty_b), _abs_event("bp_2", *_Q2, self.ty_2),
                ("bp_q2", lambda y: y[1], lambda y, dy: dy[1])]  # the kink of |q2| at 0

    def elastic(self, q1, q2):
        return abs(q1) <= self.ty_b(q1) and abs(q2) <= self.ty_2(q2)


class DohertyHinge(HingeLaw):
    """Doherty's trilinear shape in each hinge's own mid-height displacement (D = h|q1|/2 at the
    base, D = h|x|/4 at mid-height), with the gravity slope taken out: mu = c_d(D)/F_r(d), with the
    data of the hinge's direction d."""
    name = "dohertyHinge"

    def __init__(self, p):
        super().__init__(p)
        self.c_b, self.c_m = p.h / 2, p.h / 4   # D per unit rotation of each hinge

    @staticmethod
    def c(r, D):
        """Resisting force of the trilinear law of direction r less its gravity part, for D >= 0."""
        k_grav = r.F_r / r.Delta_u
        if D <= r.Delta_1:
            return (r.F_i / r.Delta_1 + k_grav) * D
        if D <= r.Delta_2:
            return r.F_i + k_grav * D
        return r.F_r

    @staticmethod
    def c_integral(r, D):
        """Integral of c from 0 to D >= 0, summed branch by branch."""
        k_grav, d1, d2 = r.F_r / r.Delta_u, r.Delta_1, r.Delta_2
        seg1 = 0.5 * (r.F_i / d1 + k_grav) * min(D, d1) ** 2
        if D <= d1:
            return seg1
        e = min(D, d2)
        seg2 = r.F_i * (e - d1) + 0.5 * k_grav * (e * e - d1 * d1)
        return seg1 + seg2 + (r.F_r * (D - d2) if D > d2 else 0.0)

    def mu(self, r, z, c):
        return _sign(z) * self.c(r, c * abs(z)) / r.F_r

    def moments(self, q1, q2, side_b, side_m):
        x = q2 - q1
        return self.from_mu(self.mu(self.base_dir(q1), q1, self.c_b), self.mu(self.mid_dir(x), x, self.c_m), q1, x)

    def potential(self, q1, x):
        rb, rm = self.base_dir(q1), self.mid_dir(x)
        return (self.p.cap_b_side(_side(q1)) / (self.c_b * rb.F_r) * self.c_integral(rb, self.c_b * abs(q1))
                + self.p.cap_m_side(_side(x)) / (self.c_m * rm.F_r) * self.c_integral(rm, self.c_m * abs(x)))

    def breakpoints(self):
        out = []
        for tag, key in (("1", "Delta_1"), ("2", "Delta_2")):
            out.append(_abs_event("bp_b" + tag, *_Q1, lambda s, k=key: getattr(self.base_dir(s), k) / self.c_b))
            out.append(_abs_event("bp_m" + tag, *_X, lambda s, k=key: getattr(self.mid_dir(s), k) / self.c_m))
        return out

    def elastic(self, q1, q2):
        x = q2 - q1
        return self.c_b * abs(q1) <= self.base_dir(q1).Delta_1 and self.c_m * abs(x) <= self.mid_dir(x).Delta_1


LAWS = {law.name: law for law in (Rigid, SemiRigidPaper, SemiRigidHinge, DohertyHinge)}


def make_law(p):
    return LAWS[p.hinge_law](p)


def toppling_limit(p):
    """2b/h: the rotation at which a body of thickness b and height h/2 has its centre of gravity
    over its pivot (docs/model.md "Collapse")."""
    return 2 * p.b / p.h

"""The 2DOF hinge laws of docs/model.md ("Hinge laws"), one class per law.

Each law gives the generalised hinge moments Q(q) (the A_i, B_i of the paper's Eq. 3.5-3.8,
corrected), its potential V_h (Q = -grad V_h) where it has one, the breakpoints where Q(q) has a
kink (located as events by the solver), and the elastic range (collapse is not tested inside it).
The laws that come from a potential write Q1 = -cap_b mu_b + cap_m mu_m, Q2 = -cap_m mu_m with the
normalised moments mu_b(q1) and mu_m(x), x = q2 - q1.
"""


def _sign(x):
    return 1.0 if x > 0 else (-1.0 if x < 0 else 0.0)


def _sat(z):
    return max(-1.0, min(1.0, z))


class HingeLaw:
    name = None
    set_valued = False  # rigid hinges: mu = sign, with rest and closed-hinge states

    def __init__(self, p):
        self.p = p
        self.cb, self.cm = p.cap_b, p.cap_m

    def from_mu(self, mu_b, mu_m):
        return -self.cb * mu_b + self.cm * mu_m, -self.cm * mu_m

    def breakpoints(self):
        """[(name, raw(y), rate(y, dy))]: raw changes sign at a kink of Q."""
        return []


class Rigid(HingeLaw):
    name = "rigid"
    set_valued = True

    def moments(self, q1, q2, side_b, side_m):
        return self.from_mu(side_b, side_m)

    def potential(self, q1, x):
        return self.cb * abs(q1) + self.cm * abs(x)

    def elastic(self, q1, q2):
        return q1 == 0 and q2 == 0


def _abs_event(name, value, rate, limit):
    """|value(y)| = limit as an event."""
    return (name, lambda y: abs(value(y)) - limit, lambda y, dy: _sign(value(y)) * rate(dy))


_Q1 = (lambda y: y[0], lambda dy: dy[0])
_X = (lambda y: y[1] - y[0], lambda dy: dy[1] - dy[0])
_Q2 = (lambda y: y[1], lambda dy: dy[1])


class SemiRigidHinge(HingeLaw):
    """Each hinge's moment grows linearly with its own rotation and saturates at theta_y."""
    name = "semiRigidHinge"

    def __init__(self, p):
        super().__init__(p)
        self.ty = p.theta_y

    def moments(self, q1, q2, side_b, side_m):
        return self.from_mu(_sat(q1 / self.ty), _sat((q2 - q1) / self.ty))

    def _phi(self, z):
        u = abs(z) / self.ty
        return self.ty * (0.5 * u * u if u <= 1 else u - 0.5)

    def potential(self, q1, x):
        return self.cb * self._phi(q1) + self.cm * self._phi(x)

    def breakpoints(self):
        return [_abs_event("bp_b", *_Q1, self.ty), _abs_event("bp_m", *_X, self.ty)]

    def elastic(self, q1, q2):
        return abs(q1) <= self.ty and abs(q2 - q1) <= self.ty


class SemiRigidPaper(SemiRigidHinge):
    """Fig. 4.1/4.2: A_c min(1, |q1|/ty), B_c min(1, |q2|/ty) with the constants of the condition
    given by the sides. Not from a potential (its `potential` is semiRigidHinge's, as a measure)."""
    name = "semiRigidPaper"

    def moments(self, q1, q2, side_b, side_m):
        A = -self.cb * side_b + self.cm * side_m
        B = -self.cm * side_m
        return A * min(1.0, abs(q1) / self.ty), B * min(1.0, abs(q2) / self.ty)

    def breakpoints(self):
        return [_abs_event("bp_b", *_Q1, self.ty), _abs_event("bp_2", *_Q2, self.ty),
                ("bp_q2", lambda y: y[1], lambda y, dy: dy[1])]  # the kink of |q2| at 0

    def elastic(self, q1, q2):
        return abs(q1) <= self.ty and abs(q2) <= self.ty


class DohertyHinge(HingeLaw):
    """Doherty's trilinear shape in each hinge's own mid-height displacement (D = h|q1|/2 at the
    base, D = h|x|/4 at mid-height), with the gravity slope taken out: mu = c(D)/F_r."""
    name = "dohertyHinge"

    def __init__(self, p):
        super().__init__(p)
        self.c_b, self.c_m = p.h / 2, p.h / 4   # D per unit rotation of each hinge
        self.d1, self.d2 = p.Delta_1, p.Delta_2
        self.k_grav = p.F_r / p.Delta_u

    def c(self, D):
        """Resisting force of the trilinear law less its gravity part, for D >= 0."""
        p = self.p
        if D <= self.d1:
            return (p.F_i / self.d1 + self.k_grav) * D
        if D <= self.d2:
            return p.F_i + self.k_grav * D
        return p.F_r

    def c_integral(self, D):
        """Integral of c from 0 to D >= 0, summed branch by branch."""
        p, d1, d2 = self.p, self.d1, self.d2
        seg1 = 0.5 * (p.F_i / d1 + self.k_grav) * min(D, d1) ** 2
        if D <= d1:
            return seg1
        e = min(D, d2)
        seg2 = p.F_i * (e - d1) + 0.5 * self.k_grav * (e * e - d1 * d1)
        return seg1 + seg2 + (p.F_r * (D - d2) if D > d2 else 0.0)

    def mu(self, z, c):
        return _sign(z) * self.c(c * abs(z)) / self.p.F_r

    def moments(self, q1, q2, side_b, side_m):
        return self.from_mu(self.mu(q1, self.c_b), self.mu(q2 - q1, self.c_m))

    def potential(self, q1, x):
        Fr = self.p.F_r
        return (self.cb / (self.c_b * Fr) * self.c_integral(self.c_b * abs(q1))
                + self.cm / (self.c_m * Fr) * self.c_integral(self.c_m * abs(x)))

    def breakpoints(self):
        out = []
        for tag, lim in (("1", self.d1), ("2", self.d2)):
            out.append(_abs_event("bp_b" + tag, *_Q1, lim / self.c_b))
            out.append(_abs_event("bp_m" + tag, *_X, lim / self.c_m))
        return out

    def elastic(self, q1, q2):
        return self.c_b * abs(q1) <= self.d1 and self.c_m * abs(q2 - q1) <= self.d1


LAWS = {law.name: law for law in (Rigid, SemiRigidPaper, SemiRigidHinge, DohertyHinge)}


def make_law(p):
    return LAWS[p.hinge_law](p)


def toppling_limit(p):
    """2b/h: the rotation at which a body of thickness b and height h/2 has its centre of gravity
    over its pivot (docs/model.md "Collapse")."""
    return 2 * p.b / p.h


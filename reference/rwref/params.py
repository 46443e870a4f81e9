"""Model parameters and derived quantities (docs/model.md "Parameters"; paper Table 5.1, Eq. 3.2-3.4, 5.1-5.2).

Units are SI: N, m, s, rad; loads per metre of wall (W in N/m, Kd in N/m per m).
A side or a direction is +1 or -1: +1 toward +x, the inner face (docs/model.md "Sign convention").
"""
from dataclasses import dataclass, fields

import numpy as np

SUPPORTS = {1: "parapet", 2: "simplySupported", 3: "flexibleTop"}
HINGE_LAWS = {1: "rigid", 2: "semiRigidPaper", 3: "semiRigidHinge", 4: "dohertyHinge"}

# Closed ranges of the parameters (docs/model.md "Parameters"): each keeps the model meaningful.
RANGES = {
    "h": (0.3, 30.0), "b": (0.02, 3.0), "W": (10.0, 1e6), "psi": (0.0, 20.0), "Kd": (0.0, 1e12),
    "er": (0.0, 1.0), "g": (1.0, 30.0), "delta1_ratio": (1e-4, 0.5), "delta2_a": (0.0, 10.0),
    "delta2_b": (0.0, 1.0), "hinge_sat": (0.1, 20.0), "rest_rate": (1e-12, 0.1),
    "pointing": (0.0, 1.5), "e_base_ratio": (0.0, 1.0), "e_hinge_ratio": (0.0, 1.0), "e_top": (-1.5, 1.5),
    "psi_weight_only": (0.0, 20.0),
}


def _name(value, table, what):
    if isinstance(value, (int, np.integer)) and int(value) in table:
        return table[int(value)]
    if value in table.values():
        return value
    raise ValueError(f"{what} must be one of {sorted(table.values())} or {sorted(table)}; got {value!r}")


@dataclass(frozen=True)
class Params:
    """All parameters of the spec, with the spec's defaults (docs/model.md, table "Parameters")."""
    support: str = "flexibleTop"
    hinge_law: str = "dohertyHinge"
    h: float = 2.5
    b: float = 0.15
    W: float = 6622.0
    psi: float = 0.0
    Kd: float = 1e6
    er: float = 0.86
    g: float = 9.81
    delta1_ratio: float = 0.05
    delta2_a: float = 0.92
    delta2_b: float = 0.21
    hinge_sat: float = 2.0
    rest_rate: float = 1e-5
    pointing: float = 0.0          # depth of the pointing recess on each face [m]
    e_base_ratio: float = 1.0      # the base reaction's distance from the centreline over t/2
    e_hinge_ratio: float = 1.0     # the mid-height hinge's reaction's, over t/2
    e_top: float = 0.0             # eccentricity of the overburden Wd, + toward +x [m]
    psi_weight_only: float = 0.0   # weight-only overburden Wo/W1 at the top's centreline

    def __post_init__(self):
        object.__setattr__(self, "support", _name(self.support, SUPPORTS, "support"))
        object.__setattr__(self, "hinge_law", _name(self.hinge_law, HINGE_LAWS, "hinge_law"))
        for name, (lo, hi) in RANGES.items():
            v = float(getattr(self, name))
            if not lo <= v <= hi:  # also refuses NaN
                raise ValueError(f"parameter {name} = {v} is out of range [{lo}, {hi}]")
            object.__setattr__(self, name, v)
        checks = [
            (self.b < self.h, "b < h"),
            (self.pointing < self.b / 2, "pointing < b/2 (an effective thickness t = b - 2 pointing > 0)"),
            (abs(self.e_top) <= self.b / 2, "|e_top| <= b/2 (the top load bears on the wall)"),
        ]
        for ok, what in checks:
            if not ok:
                raise ValueError(f"invalid parameters: need {what}")
        if not all(cap(s) > 0 for cap in (self.cap_b_side, self.cap_m_side) for s in (1, -1)):
            raise ValueError("invalid parameters: need every hinge capacity > 0 on both sides (the wall stands at "
                             "rest; e_base_ratio, e_hinge_ratio, e_top, psi)")
        for d in (1, -1):
            r = self.direction(d)
            if not r.Delta_1 < r.Delta_2 < r.Delta_u:
                raise ValueError("invalid parameters: need Delta_1 < Delta_2 < Delta_u (delta2_a, delta2_b)")
        if not self.hinge_sat * self.delta1_ratio < 1:
            raise ValueError("invalid parameters: need hinge_sat * delta1_ratio < 1 (saturation before Delta_u)")

    def replace(self, **kw):
        d = {f.name: getattr(self, f.name) for f in fields(self)}
        d.update(kw)
        return Params(**d)

    # --- lever arms and weights (docs/model.md "Derived") ---
    @property
    def t(self):
        """Effective thickness b - 2 pointing."""
        return self.b - 2 * self.pointing

    @property
    def e_b(self):
        return self.e_base_ratio * self.t / 2

    @property
    def e_m(self):
        return self.e_hinge_ratio * self.t / 2

    @property
    def W1(self):
        return self.W / 2.0

    @property
    def Wd(self):
        """The overburden: weight and mass at the top."""
        return self.psi * self.W1

    @property
    def Wo(self):
        """The weight-only overburden."""
        return self.psi_weight_only * self.W1

    @property
    def Wt(self):
        """All the weight at the top."""
        return self.Wd + self.Wo

    @property
    def symmetric(self):
        """Does the wall resist the same both ways (no eccentric top load)?"""
        return self.Wd * self.e_top == 0

    # --- hinge capacities on a side s (+1, -1) ---
    def cap_b_side(self, s):
        return (2 * self.W1 + self.Wt) * self.e_b - s * self.Wd * self.e_top

    def cap_m_side(self, s):
        return (self.W1 + self.Wt) * self.e_m - s * self.Wd * self.e_top

    @property
    def cap_b(self):
        """The mean of the base's capacities."""
        return (2 * self.W1 + self.Wt) * self.e_b

    @property
    def cap_m(self):
        return (self.W1 + self.Wt) * self.e_m

    # --- per direction d (+1, -1) of the mid-height's motion: Table 5.1, Eq. 5.1-5.2 ---
    def direction(self, d):
        return Direction(self, d)

    def _symmetric_only(self, name):
        if not self.symmetric:
            raise ValueError(f"{name} depends on the direction on a wall with an eccentric top load: "
                             "use Params.direction(d)")
        return getattr(self.direction(1), name)

    @property
    def Delta_u(self):
        return self._symmetric_only("Delta_u")

    @property
    def F_r(self):
        return self._symmetric_only("F_r")

    @property
    def F0(self):
        return self._symmetric_only("F0")

    @property
    def R_el(self):
        return self._symmetric_only("R_el")

    @property
    def Delta_1(self):
        return self._symmetric_only("Delta_1")

    @property
    def Delta_2(self):
        return self._symmetric_only("Delta_2")

    @property
    def F_i(self):
        return self._symmetric_only("F_i")

    @property
    def theta_y(self):
        return self._symmetric_only("theta_y")

    # --- 2DOF matrices (Eq. 3.2, 3.3, 3.4 with ag positive toward +x) ---
    @property
    def M(self):
        W1, Wd, h, g = self.W1, self.Wd, self.h, self.g
        m11 = (W1 / 3 + Wd / 4) * h**2 / g
        m12 = (W1 / 8 + Wd / 4) * h**2 / g
        m22 = (W1 / 12 + Wd / 4) * h**2 / g
        return np.array([[m11, m12], [m12, m22]])

    @property
    def K(self):
        """Spring minus gravity; the gravity of all the weight at the top, Wt."""
        W1, Wt, h, Kd = self.W1, self.Wt, self.h, self.Kd
        ks = Kd * h**2 / 4
        return np.array([[ks - 0.75 * W1 * h - Wt * h / 2, ks],
                         [ks, ks - W1 * h / 4 - Wt * h / 2]])

    @property
    def p_per_ag(self):
        """p = p_per_ag * ag (Eq. 3.4, sign per docs/model.md: ag positive toward +x)."""
        W1, Wd, h, g = self.W1, self.Wd, self.h, self.g
        return np.array([-(3 * W1 + 2 * Wd) * h / (4 * g), -(W1 + 2 * Wd) * h / (4 * g)])

    @property
    def fu_per_u(self):
        """f_u = fu_per_u * u_top."""
        return np.array([1.0, 1.0]) * self.Kd * self.h / 2

    def conditions(self):
        """A_i, B_i of the four conditions (Eq. 3.5-3.8 as corrected in docs/model.md)."""
        out = {}
        for c, (sb, sm) in {1: (1, -1), 2: (-1, 1), 3: (1, 1), 4: (-1, -1)}.items():
            out[c] = (-self.cap_b_side(sb) * sb + self.cap_m_side(sm) * sm, -self.cap_m_side(sm) * sm)
        return out

    # --- Housner block (parapet): pivot at e_b from the centreline, mass over the full b ---
    @property
    def alpha(self):
        return float(np.arctan(self.e_b / (self.h / 2)))

    @property
    def R(self):
        """Pivot to centroid."""
        return float(np.hypot(self.e_b, self.h / 2))

    @property
    def inertia_per_mass(self):
        """I0/(W/g): the block's inertia about its pivot per unit mass."""
        return ((self.b / 2) ** 2 + (self.h / 2) ** 2) / 3 + self.R**2

    @property
    def p_housner(self):
        return float(np.sqrt(self.g * self.R / self.inertia_per_mass))


class Direction:
    """The quantities of one direction d (+1, -1) of the mid-height's motion (docs/model.md
    "Derived"): the base hinge turns to side d, the mid-height hinge to side -d."""

    def __init__(self, p, d):
        self.d = d
        # (h/2) F_r(d) = cap_b(d) + 2 cap_m(-d); Delta_u = F_r / (gravity slope 4 (W1 + Wt)/h)
        moment = p.cap_b_side(d) + 2 * p.cap_m_side(-d)
        self.F_r = 2 * moment / p.h
        self.Delta_u = moment / (2 * (p.W1 + p.Wt))
        self.F0 = 2 * self.F_r
        self.R_el = 0.75 * self.F0
        self.Delta_1 = p.delta1_ratio * self.Delta_u
        self.Delta_2 = p.delta2_a * self.Delta_1 + p.delta2_b * self.Delta_u
        self.F_i = self.F_r * (1 - self.Delta_2 / self.Delta_u)
        self.theta_y = 2 * p.hinge_sat * self.Delta_1 / p.h


# The paper's set of walls (Section 5.1): b = 0.15 m, h = 2.5 m, W = 6.622 kN/m, psi = 0, 0.5, 1.
WALLS = {1: dict(b=0.15, h=2.5, W=6622.0, psi=0.0),
         2: dict(b=0.15, h=2.5, W=6622.0, psi=0.5),
         3: dict(b=0.15, h=2.5, W=6622.0, psi=1.0)}

# Table 5.1 as printed (kN/m, m).
TABLE_5_1_PAPER = {1: dict(R_el=1.192, Delta_u=0.150, F0_over_W=0.180, Delta_u_over_b=1.000),
                   2: dict(R_el=1.639, Delta_u=0.138, F0_over_W=0.248, Delta_u_over_b=0.917),
                   3: dict(R_el=2.086, Delta_u=0.131, F0_over_W=0.315, Delta_u_over_b=0.875)}


def table_5_1():
    """Table 5.1 from the formulas: {wall: {R_el [kN/m], Delta_u [m], F0_over_W, Delta_u_over_b}}.

    The paper's "F0/W" column is R_el/W (docs/model.md, "Corrections to the paper")."""
    out = {}
    for wall, kw in WALLS.items():
        p = Params(**kw)
        out[wall] = dict(R_el=p.R_el / 1000.0, Delta_u=p.Delta_u, F0_over_W=p.R_el / p.W,
                         Delta_u_over_b=p.Delta_u / p.b)
    return out

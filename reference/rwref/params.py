"""Model parameters and derived quantities (docs/model.md "Parameters"; paper Table 5.1, Eq. 3.2-3.4, 5.1-5.2).

Units are SI: N, m, s, rad; loads per metre of wall (W in N/m, Kd in N/m per m).
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
            (self.Delta_1 < self.Delta_2 < self.Delta_u, "Delta_1 < Delta_2 < Delta_u (delta2_a, delta2_b)"),
            (self.hinge_sat * self.delta1_ratio < 1, "hinge_sat * delta1_ratio < 1 (saturation before Delta_u)"),
        ]
        for ok, what in checks:
            if not ok:
                raise ValueError(f"invalid parameters: need {what}")

    def replace(self, **kw):
        d = {f.name: getattr(self, f.name) for f in fields(self)}
        d.update(kw)
        return Params(**d)

    # --- weights (docs/model.md "Derived") ---
    @property
    def W1(self):
        return self.W / 2.0

    @property
    def Wd(self):
        return self.psi * self.W1

    # --- Doherty / Table 5.1 quantities ---
    @property
    def Delta_u(self):
        return self.b * (1 + 0.75 * self.psi) / (1 + self.psi)

    @property
    def F_r(self):
        return (2 * self.b / self.h) * self.W * (1 + 0.75 * self.psi)

    @property
    def F0(self):
        return 2 * self.F_r

    @property
    def R_el(self):
        return 0.75 * self.F0

    @property
    def Delta_1(self):  # Eq. 5.1
        return self.delta1_ratio * self.Delta_u

    @property
    def Delta_2(self):  # Eq. 5.2
        return self.delta2_a * self.Delta_1 + self.delta2_b * self.Delta_u

    @property
    def F_i(self):
        return self.F_r * (1 - self.Delta_2 / self.Delta_u)

    # --- 2DOF hinge constants ---
    @property
    def theta_y(self):
        return 2 * self.hinge_sat * self.Delta_1 / self.h

    @property
    def cap_b(self):
        return (2 * self.W1 + self.Wd) * self.b / 2

    @property
    def cap_m(self):
        return (self.W1 + self.Wd) * self.b / 2

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
        W1, Wd, h, Kd = self.W1, self.Wd, self.h, self.Kd
        ks = Kd * h**2 / 4
        return np.array([[ks - 0.75 * W1 * h - Wd * h / 2, ks],
                         [ks, ks - W1 * h / 4 - Wd * h / 2]])

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
            out[c] = (-self.cap_b * sb + self.cap_m * sm, -self.cap_m * sm)
        return out

    # --- Housner block (parapet) ---
    @property
    def alpha(self):
        return float(np.arctan((self.b / 2) / (self.h / 2)))

    @property
    def R(self):
        return float(np.hypot(self.b / 2, self.h / 2))

    @property
    def p_housner(self):
        return float(np.sqrt(3 * self.g / (4 * self.R)))


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

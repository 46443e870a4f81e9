"""The elastic spectra of the Italian code NTC 2018 (Par. 3.2.3.2) from the site parameters the
user gives (a_g, F0, T*_C, soil and topography), and the Circolare 2019's floor spectrum
(Par. C7.2.3) for mechanisms above the ground.

Accelerations in m/s^2, displacements in m, periods in s; a_g is given as a fraction of g.
Confirmed against independent public implementations, not the code's text: see docs/codes.md."""
import dataclasses
import math

from .common import G, Ref, choice, number

SOILS = ("A", "B", "C", "D", "E")
TOPOGRAPHIES = {"T1": 1.0, "T2": 1.2, "T3": 1.2, "T4": 1.4}        # S_T, Tab. 3.2.V
# S_S = clamp(intercept - slope F0 a_g/g, low, high) and C_C = factor (T*_C)^power (Tab. 3.2.IV)
SS_RULE = {"A": (1.0, 0.0, 1.0, 1.0), "B": (1.40, 0.40, 1.00, 1.20), "C": (1.70, 0.60, 1.00, 1.50),
           "D": (2.40, 1.50, 0.90, 1.80), "E": (2.00, 1.10, 1.00, 1.60)}
CC_RULE = {"A": (1.0, 0.0), "B": (1.10, -0.20), "C": (1.05, -0.33), "D": (1.25, -0.50), "E": (1.15, -0.40)}
# T_E, above which S_De(T) is no longer Se(T) (T/2 pi)^2 (Tab. 3.2.VIII, recalled)
T_E = {"A": 4.5, "B": 5.0, "C": 6.0, "D": 6.0, "E": 6.0}

REFS = {
    "Se": Ref("Se(T)", "NTC 2018 Par. 3.2.3.2.1, Eq. 3.2.2 with Tab. 3.2.IV (S_S, C_C) and 3.2.V (S_T): "
              "T_C = C_C T*_C, T_B = T_C/3, T_D = 4 a_g/g + 1.6, eta = sqrt(10/(5 + xi)) >= 0.55", "secondary"),
    "SDe": Ref("S_De(T)", "NTC 2018 Par. 3.2.3.2.3: S_De = Se (T/2 pi)^2 for T <= T_E", "secondary"),
    "floor": Ref("floor spectrum", "Circolare 2019 Par. C7.2.3: Sa = alpha S (1 + z/H) a_p / "
                 "(1 + (a_p - 1)(1 - Ta/(a T1))^2) below a T1, alpha S (1 + z/H) a_p up to b T1, the same "
                 "form with b T1 above; (a, b, a_p) = (0.8, 1.4, 5.0), (0.3, 1.2, 4.0), (0.3, 1.0, 2.5) for "
                 "T1 <= 0.5 s, <= 1.0 s, > 1.0 s", "secondary"),
}


@dataclasses.dataclass(frozen=True)
class NtcSite:
    """An Italian site for one limit state: ag [fraction of g], F0 [-], Tc_star [s] (from the
    hazard grid), soil category A-E, topography T1-T4, damping xi [%] (5)."""
    ag: float
    F0: float
    Tc_star: float
    soil: str = "A"
    topography: str = "T1"
    damping: float = 5.0

    def __post_init__(self):
        number("ag", self.ag, 0.0, 1.5, "g", low_open=True)
        number("F0", self.F0, 1.0, 4.0, "")
        number("Tc_star", self.Tc_star, 0.05, 2.0, "s")
        object.__setattr__(self, "soil", choice("soil category", self.soil, SOILS))
        object.__setattr__(self, "topography", choice("topography", self.topography, tuple(TOPOGRAPHIES)))
        number("damping", self.damping, 0.0, 50.0, "%", low_open=True)

    @property
    def S_S(self):
        intercept, slope, low, high = SS_RULE[self.soil]
        return min(high, max(low, intercept - slope * self.F0 * self.ag))

    @property
    def S(self):
        """S = S_S S_T."""
        return self.S_S * TOPOGRAPHIES[self.topography]

    @property
    def T_C(self):
        factor, power = CC_RULE[self.soil]
        return factor * self.Tc_star ** power * self.Tc_star

    @property
    def T_B(self):
        return self.T_C / 3.0

    @property
    def T_D(self):
        return 4.0 * self.ag + 1.6

    @property
    def eta(self):
        return max(0.55, math.sqrt(10.0 / (5.0 + self.damping)))


def elastic_acceleration(site, period):
    """Se(T) [m/s^2], the horizontal elastic acceleration spectrum."""
    t = number("T", period, 0.0, 100.0, "s")
    peak = site.ag * G * site.S * site.eta * site.F0
    if t < site.T_B:
        return site.ag * G * site.S * (1.0 + (site.eta * site.F0 - 1.0) * t / site.T_B)
    if t < site.T_C:
        return peak
    if t < site.T_D:
        return peak * site.T_C / t
    return peak * site.T_C * site.T_D / t ** 2


def elastic_displacement(site, period):
    """S_De(T) [m] = Se(T) (T / 2 pi)^2, for T up to T_E."""
    t = number("T", period, 0.0, 100.0, "s")
    if t > T_E[site.soil]:
        raise ValueError(f"T = {t:g} s is above T_E = {T_E[site.soil]:g} s of soil {site.soil}: the displacement "
                         "spectrum beyond T_E (NTC 2018 Eq. 3.2.13) is not implemented")
    return elastic_acceleration(site, t) * (t / (2.0 * math.pi)) ** 2


def floor_acceleration(site, period, z, H, T1):
    """Sa(Ta) [m/s^2] at height z [m] of a building of height H [m] and fundamental period T1 [s]
    (Circolare 2019 Par. C7.2.3); alpha = a_g/g, S the site's soil and topography factor."""
    ta = number("Ta", period, 0.0, 100.0, "s")
    H = number("H", H, 0.0, 300.0, "m", low_open=True)
    z = number("z", z, 0.0, H, "m")
    T1 = number("T1", T1, 0.0, 10.0, "s", low_open=True)
    a, b, a_p = (0.8, 1.4, 5.0) if T1 <= 0.5 else (0.3, 1.2, 4.0) if T1 <= 1.0 else (0.3, 1.0, 2.5)
    top = site.ag * G * site.S * (1.0 + z / H) * a_p
    if ta < a * T1:
        return top / (1.0 + (a_p - 1.0) * (1.0 - ta / (a * T1)) ** 2)
    if ta <= b * T1:
        return top
    return top / (1.0 + (a_p - 1.0) * (1.0 - ta / (b * T1)) ** 2)


def floor_displacement(site, period, z, H, T1):
    """The floor spectrum as displacement [m]: Sa(Ta, z) (Ta / 2 pi)^2."""
    return floor_acceleration(site, period, z, H, T1) * (period / (2.0 * math.pi)) ** 2

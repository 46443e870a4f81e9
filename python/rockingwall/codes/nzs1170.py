"""The parts spectrum of NZS 1170.5 (2004) Section 8, as NZSEE's C8 uses it for face-loaded
walls: C_p(T_p) = C(0) C_Hi C_i(T_p), with C(0) the site's elastic coefficient at T = 0.

Confirmed against an independent public implementation of NZS 1170.5 (the NZS1170.5 seismic
coefficient functions of engineervsheep.com, github.com/Agent6-6-6/NZS1170.5-Seismic-Coefficient-functions),
not against the standard's text: see docs/codes.md."""
import dataclasses

from .common import Ref, choice, number

SOILS = ("A", "B", "C", "D", "E")
# Spectral shape factor C_h(0) of the modal and numerical-integration spectra (Table 3.1).
SHAPE_AT_ZERO = {"A": 1.0, "B": 1.0, "C": 1.33, "D": 1.12, "E": 1.12}
ZR_CAP = 0.7     # Z R is not taken above 0.7 (Cl. 3.1.1)
CP_CAP = 3.6     # the part's design coefficient is not taken above 3.6 (Cl. 8.5)

REFS = {
    "C(0)": Ref("C(0)", "NZS 1170.5 Cl. 3.1.1: C(T) = C_h(T) Z R N(T,D) at T = 0, Z R <= 0.7; "
                "C_h(0) of Table 3.1 (modal)", "secondary"),
    "C_Hi": Ref("C_Hi", "NZS 1170.5 Cl. 8.3: 1 + h_i/6 (h_i < 12 m), 1 + 10 h_i/h_n (h_i < 0.2 h_n), "
                "3.0 (h_i >= 12 m); the lesser where two apply", "secondary"),
    "C_i": Ref("C_i(Tp)", "NZS 1170.5 Cl. 8.4: 2.0 (Tp <= 0.75 s), 2(1.75 - Tp) (0.75-1.5 s), "
               "0.5 (Tp >= 1.5 s)", "secondary"),
    "Cp": Ref("Cp", "NZS 1170.5 Cl. 8.2 and 8.5: C(0) C_Hi C_i(Tp), times R_p (C_ph = 1), "
              "at most 3.6", "secondary"),
}


@dataclasses.dataclass(frozen=True)
class NzSite:
    """A New Zealand site: Z hazard factor (Table 3.3, 0.13-0.6), soil class A-E, R return period
    factor (Table 3.5; 1.0 for the 500-year ultimate limit state of an importance level 2
    building), N near-fault factor at T = 0 (1.0: N(T,D) = 1 for T <= 1.5 s)."""
    Z: float
    soil: str
    R: float = 1.0
    N: float = 1.0

    def __post_init__(self):
        number("Z", self.Z, 0.0, 0.6, "", low_open=True)
        object.__setattr__(self, "soil", choice("soil class", self.soil, SOILS))
        number("R", self.R, 0.0, 1.8, "", low_open=True)
        number("N", self.N, 1.0, 1.72, "")

    @property
    def C0(self):
        """C(0): the elastic site hazard coefficient at T = 0 [g]."""
        return SHAPE_AT_ZERO[self.soil] * min(self.Z * self.R, ZR_CAP) * self.N


def floor_height_coefficient(h_i, h_n):
    """C_Hi for a part attached at height h_i [m] in a building of height h_n [m] (to its
    uppermost seismic weight). The three rules of Cl. 8.3, the lesser where two apply, are
    together min(1 + h_i/6, 1 + 10 h_i/h_n, 3)."""
    h_n = number("h_n", h_n, 0.0, 300.0, "m", low_open=True)
    h_i = number("h_i", h_i, 0.0, h_n, "m")
    return min(1.0 + h_i / 6.0, 1.0 + 10.0 * h_i / h_n, 3.0)


def part_spectral_shape(tp):
    """C_i(Tp), the part spectral shape coefficient, for the part's period Tp [s]."""
    tp = number("Tp", tp, 0.0, 100.0, "s")
    if tp <= 0.75:
        return 2.0
    if tp >= 1.5:
        return 0.5
    return 2.0 * (1.75 - tp)


def part_coefficient(site, h_i, h_n, tp, rp=1.0):
    """(Cp, capped): the part's horizontal design coefficient C(0) C_Hi C_i(Tp) Rp [g], at most 3.6,
    and whether the cap acted. Rp: the part risk factor (Table 8.1; 1.0 for most parts)."""
    rp = number("Rp", rp, 0.0, 2.0, "", low_open=True)
    cp = site.C0 * floor_height_coefficient(h_i, h_n) * part_spectral_shape(tp) * rp
    return min(cp, CP_CAP), cp > CP_CAP

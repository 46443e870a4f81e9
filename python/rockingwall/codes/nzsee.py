"""NZSEE (2017) "The Seismic Assessment of Existing Buildings", Part C8: the out-of-plane check
of a face-loaded unreinforced-masonry wall (spanning between floors) and of a parapet, with the
parts spectrum of NZS 1170.5 Section 8. %NBS = 100 Delta_m / D_ph.

The procedure assumes the diaphragms are adequately stiff and the walls adequately tied to them:
a flexible diaphragm is outside it, which is what RockingWall's dynamic answer adds."""
import dataclasses
import math

from . import nzs1170
from .common import FAIL, G, PASS, Ref, choice, number, unconfirmed_notes
from .mechanism import DIRECTIONS, FaceLoadedWall, Parapet

C8 = "NZSEE (2017) C8"
USABLE_FRACTION = 0.6   # Delta_m = 0.6 Delta_i

REFS = (
    Ref("scope", f"{C8} out-of-plane procedure for face-loaded walls (after Derakhshan 2011, Griffith et al. "
        "2003; NZS 1170.5 Section 8 parts spectrum); assumes stiff diaphragms and adequate wall-diaphragm "
        "connections", "read"),
    Ref("t", f"{C8}: effective thickness reduced by the mortar pointing depth (taken on each face, "
        "t = b - 2p)", "unconfirmed"),
    Ref("Delta_i", f"{C8}: instability displacement from the statics of the rocking mechanism, with the "
        "eccentricities of the top load, the base and the hinge (virtual work here; equals Doherty's "
        "b(1 + 0.75 psi)/(1 + psi) for a top load at mid-thickness)", "derived"),
    Ref("Delta_m", f"{C8}: maximum usable displacement Delta_m = 0.6 Delta_i", "unconfirmed"),
    Ref("mass", "generalised mass of slender rigid blocks, W/(3g)", "derived"),
    Ref("Tp", f"{C8}: period from the secant stiffness at Delta_t (here 0.6 Delta_i unless chosen) and the "
        "mechanism's mass, Tp = 2 pi sqrt(M/K_s)", "unconfirmed"),
    Ref("gamma", "participation factor sum(m dx)/M of the mechanism (1.5): converts the spectral "
        "displacement to the control point's", "derived"),
    *nzs1170.REFS.values(),
    Ref("D_ph", f"{C8}: displacement demand gamma (Tp/2 pi)^2 Cp g", "unconfirmed"),
    Ref("%NBS", f"{C8}: %NBS = 100 Delta_m / D_ph", "unconfirmed"),
)
PARAPET_REFS = (Ref("Delta_TOP,ins", f"{C8} parapet check: top instability displacement of the block "
                    "rocking on its base, 2 e_b (= t)", "derived"),)


@dataclasses.dataclass(frozen=True)
class NzseeResult:
    """One NZSEE C8 check. Lengths m, period s, coefficients in g, mass kg/m, stiffness N/m per m.
    capacity = Delta_m, demand = D_ph (both at the control point: the hinge of a wall, the top of
    a parapet), nbs = %NBS, verdict 'pass' when %NBS >= 100."""
    element: str
    direction: str
    t: float
    delta_i: float
    delta_m: float
    mass: float
    secant_stiffness: float
    Tp: float
    C0: float
    C_Hi: float
    C_i: float
    Cp: float
    gamma: float
    demand: float
    capacity: float
    nbs: float
    verdict: str
    refs: tuple
    notes: tuple


def check_wall(wall, site, *, h_i, h_n, Rp=1.0, direction="both", secant_fraction=0.6):
    """C8's check of a FaceLoadedWall at an NzSite; h_i [m] the height at which the floor height
    coefficient is taken (NZS 1170.5: the part's attachment; for a wall between two floors say
    which floor you chose), h_n [m] the building's height; direction 'outward', 'inward' or
    'both' (the one with the lower %NBS); secant_fraction: Delta_t / Delta_i for Tp."""
    if not isinstance(wall, FaceLoadedWall):
        raise ValueError(f"check_wall needs a FaceLoadedWall, got {type(wall).__name__}")
    return _governing(wall, site, h_i, h_n, Rp, direction, secant_fraction, "face-loaded wall", REFS)


def check_parapet(parapet, site, *, h_i, h_n, Rp=1.0, direction="both", secant_fraction=0.6):
    """C8's parapet check of a Parapet whose base is at height h_i [m]: as check_wall, with the
    top's instability displacement Delta_TOP,ins and the top's displacement demand."""
    if not isinstance(parapet, Parapet):
        raise ValueError(f"check_parapet needs a Parapet, got {type(parapet).__name__}")
    return _governing(parapet, site, h_i, h_n, Rp, direction, secant_fraction, "parapet", REFS + PARAPET_REFS)


def _governing(element, site, h_i, h_n, rp, direction, secant_fraction, name, refs):
    if not isinstance(site, nzs1170.NzSite):
        raise ValueError(f"site: expected an NzSite, got {type(site).__name__}")
    secant_fraction = number("secant_fraction", secant_fraction, 0.0, 1.0, "", low_open=True, high_open=True)
    direction = choice("direction", direction, DIRECTIONS + ("both",))
    directions = DIRECTIONS if direction == "both" else (direction,)
    results = [_one_direction(element.mechanism(d), element.t, site, h_i, h_n, rp, secant_fraction, name, refs)
               for d in directions]
    worst = min(results, key=lambda r: r.nbs)
    others = tuple(f"{r.direction}: Delta_i = {r.delta_i * 1e3:.1f} mm, %NBS = {r.nbs:.0f}"
                   for r in results if r is not worst)
    return dataclasses.replace(worst, notes=worst.notes + others)


def _one_direction(mech, t, site, h_i, h_n, rp, secant_fraction, name, refs):
    delta_i = mech.delta_i
    delta_m = USABLE_FRACTION * delta_i
    k_s = mech.secant_stiffness(secant_fraction * delta_i)
    tp = 2.0 * math.pi * math.sqrt(mech.mass / k_s)
    cp, capped = nzs1170.part_coefficient(site, h_i, h_n, tp, rp)
    gamma = mech.participation
    demand = gamma * (tp / (2.0 * math.pi)) ** 2 * cp * G
    nbs = 100.0 * delta_m / demand
    notes = unconfirmed_notes(refs) + (
        f"control point: the {mech.control_point}; moving {mech.direction}",
        "the diaphragms are taken as stiff and the wall as tied to them (C8's assumption)",
    )
    if capped:
        notes += ("Cp reached the cap of 3.6 (NZS 1170.5 Cl. 8.5)",)
    if secant_fraction != 0.6:
        notes += (f"Tp from the secant at {secant_fraction:g} Delta_i (chosen)",)
    return NzseeResult(name, mech.direction, t, delta_i, delta_m, mech.mass, k_s, tp, site.C0,
                       nzs1170.floor_height_coefficient(h_i, h_n), nzs1170.part_spectral_shape(tp), cp, gamma,
                       demand, delta_m, nbs, PASS if nbs >= 100.0 else FAIL, refs, notes)

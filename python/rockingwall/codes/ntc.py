"""NTC 2018 with its Circolare 2019, Par. C8.7.1: a local mechanism (the wall spanning between
floors, or a parapet) checked by kinematic analysis, linear (a0* against a_g S / q) and nonlinear
(du* against the displacement spectrum at the secant period Ts), with the confidence factor FC.

The mechanisms' rigid blocks, their statics and their loads are those of codes.mechanism; the
loads at a restrained top carry no horizontal inertia into the mechanism (it goes to the floor),
so they are not counted in sum(P_i) of e* (counting them would raise a0* by (W + P)/W)."""
import dataclasses
import math

from . import ntc_spectrum
from .common import FAIL, G, PASS, Ref, choice, number, unconfirmed_notes, verdict
from .mechanism import DIRECTIONS, FaceLoadedWall, Parapet

CIRC = "Circolare 2019 Par. C8.7.1"
REFS = (
    Ref("alpha0", f"{CIRC}: load multiplier from the principle of virtual work", "unconfirmed"),
    Ref("M*", f"{CIRC}: M* = (sum P_i dx_i)^2 / (g sum P_i dx_i^2)", "unconfirmed"),
    Ref("e*", f"{CIRC}: e* = g M* / sum P_i", "unconfirmed"),
    Ref("a0*", f"{CIRC}: a0* = alpha0 sum P_i / (M* FC) = alpha0 g / (e* FC)", "unconfirmed"),
    Ref("d0*", f"{CIRC}: d0* = d_k0 sum P_i dx_i^2 / (dx_k sum P_i dx_i), d_k0 where alpha vanishes "
        "(the instability displacement of the control point)", "unconfirmed"),
    Ref("linear check", f"{CIRC}: a0* >= a_g S / q, q = 2; above ground the floor spectrum of Par. C7.2.3 "
        "at Ta = 0 over q", "unconfirmed"),
    Ref("du*", f"{CIRC}: du* = 0.4 d0* (life safety, SLV); ds* = 0.4 du*; a*(d*) = a0* (1 - d*/d0*); "
        "Ts = 2 pi sqrt(ds*/a*(ds*))", "unconfirmed"),
    Ref("nonlinear check", f"{CIRC}: du* >= S_De(Ts); above ground also the floor spectrum's displacement "
        "at Ts", "unconfirmed"),
    *ntc_spectrum.REFS.values(),
)


@dataclasses.dataclass(frozen=True)
class NtcResult:
    """Kinematic checks of one mechanism. alpha0 [-], M_star [kg/m], e_star [-], a0_star [m/s^2],
    d0_star, du_star, ds_star [m], Ts [s]. linear_capacity = a0*, linear_demand [m/s^2];
    nonlinear_capacity = du*, nonlinear_demand [m]; verdict 'pass' when both checks pass."""
    element: str
    direction: str
    alpha0: float
    M_star: float
    e_star: float
    a0_star: float
    d0_star: float
    du_star: float
    ds_star: float
    Ts: float
    linear_capacity: float
    linear_demand: float
    linear_verdict: str
    nonlinear_capacity: float
    nonlinear_demand: float
    nonlinear_verdict: str
    verdict: str
    refs: tuple
    notes: tuple


def check_mechanism(element, site, *, FC=1.35, q=2.0, z=None, H=None, T1=None, direction="both"):
    """The kinematic checks of a FaceLoadedWall or Parapet at an NtcSite. FC: confidence factor
    (1.35, 1.20, 1.00 for knowledge levels LC1-LC3); q: behaviour factor of the linear check (2);
    z [m], H [m], T1 [s]: for a mechanism above the ground, the height of the centroid of its
    constraint lines with the rest of the building, the building's height and fundamental period
    (all three, or none for a mechanism at ground level); direction 'outward', 'inward' or 'both'
    (the one with the lower capacity/demand ratio)."""
    if not isinstance(element, (FaceLoadedWall, Parapet)):
        raise ValueError(f"check_mechanism needs a FaceLoadedWall or a Parapet, got {type(element).__name__}")
    if not isinstance(site, ntc_spectrum.NtcSite):
        raise ValueError(f"site: expected an NtcSite, got {type(site).__name__}")
    FC = number("FC", FC, 1.0, 1.35, "")
    q = number("q", q, 1.0, 4.0, "")
    floor = _floor(z, H, T1)
    direction = choice("direction", direction, DIRECTIONS + ("both",))
    directions = DIRECTIONS if direction == "both" else (direction,)
    results = [_one_direction(element.mechanism(d), site, FC, q, floor) for d in directions]
    return min(results, key=lambda r: min(r.linear_capacity / r.linear_demand,
                                          r.nonlinear_capacity / r.nonlinear_demand))


def _floor(z, H, T1):
    given = [v is not None for v in (z, H, T1)]
    if any(given) and not all(given):
        raise ValueError("z, H and T1 go together: give all three for a mechanism above the ground, or none")
    if not any(given):
        return None
    H = number("H", H, 0.0, 300.0, "m", low_open=True)
    return number("z", z, 0.0, H, "m"), H, number("T1", T1, 0.0, 10.0, "s", low_open=True)


def _one_direction(mech, site, FC, q, floor):
    alpha0 = mech.alpha0
    m_star = mech.weight_dx ** 2 / (G * mech.weight_dx2)
    e_star = G * m_star / mech.moving_weight
    a0 = alpha0 * G / (e_star * FC)
    d0 = mech.delta_i * mech.weight_dx2 / mech.weight_dx   # the control point moves 1 per unit D
    du = 0.4 * d0
    ds = 0.4 * du
    ts = 2.0 * math.pi * math.sqrt(ds / (a0 * (1.0 - ds / d0)))
    linear_demand = site.ag * G * site.S / q
    nonlinear_demand = ntc_spectrum.elastic_displacement(site, ts)
    notes = unconfirmed_notes(REFS) + (
        f"control point: the {mech.control_point}; moving {mech.direction}",
        "loads at a restrained top are not counted in sum(P_i) of e*: their horizontal inertia goes to the floor",
        "FC divides a0* only",
    )
    if floor is not None:
        z, H, T1 = floor
        linear_demand = max(linear_demand, ntc_spectrum.floor_acceleration(site, 0.0, z, H, T1) / q)
        nonlinear_demand = max(nonlinear_demand, ntc_spectrum.floor_displacement(site, ts, z, H, T1))
        notes += (f"above ground (z = {z:g} m of H = {H:g} m, T1 = {T1:g} s): the larger of the ground "
                  "and floor spectra",)
    lin, nonlin = verdict(a0, linear_demand), verdict(du, nonlinear_demand)
    return NtcResult(mech.name, mech.direction, alpha0, m_star, e_star, a0, d0, du, ds, ts, a0, linear_demand,
                     lin, du, nonlinear_demand, nonlin, PASS if lin == nonlin == PASS else FAIL, REFS, notes)

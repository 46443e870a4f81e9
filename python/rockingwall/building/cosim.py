"""A building file's scene for co-simulation (`rockingwall couple-building --building FILE`): the
Building FMU's start values from the storeys and one RockingWall FMU per wall, the same physics the
one-integration solver (rockingwall.building.monolithic) runs, so that the two compare.

What the Building FMU does not have is stood in for: rigid in-plane walls (the floors moving with
the ground) by storey springs of RIGID_STOREY_K under floors of RIGID_FLOOR_MASS, critically
damped by their dashpots (an undamped floor mode of 1e4 rad/s would take the Jacobi exchange's
negative damping and grow; damped, the floor follows the ground within nanometres); a diaphragm's
damping ratio by the dashpot beside its spring (cd_i = 2 zeta sqrt(k m)), the in-plane walls' by
cs_i; no Rayleigh damping. The Bouc-Wen shape and pinching are the building's
(description.Building.hysteresis), as the scene solver's, so both run the same law."""
import math

from ..names import SPRING_LAWS
from .scene import Scene, WallSpec

RIGID_STOREY_K = 1e11       # N/m per m: the in-plane walls of a storey taken as rigid
RIGID_FLOOR_MASS = 1000.0   # kg/m: the floor on them (it moves by F/k: nanometres)


def building_start_values(building):
    """(Real, Integer) start values of the Building FMU for a description.Building."""
    n = len(building.storeys)
    real = building.fmu_hysteresis()
    real.update(rayleighMass=0.0, rayleighStiffness=0.0)
    for i, s in enumerate(building.storeys, 1):
        d = s.diaphragm
        if not d.stiffness > 0:
            raise ValueError(f"storey {i}: the Building FMU needs a diaphragm stiffness > 0 (the file gives 0)")
        Fyd, alphad = d.spring_under(building.diaphragm_law)
        real.update({f"md_{i}": d.mass, f"kd_{i}": d.stiffness, f"cd_{i}": d.dashpot, f"Fyd_{i}": Fyd,
                     f"alphad_{i}": alphad})
        p = s.in_plane
        if p is None:
            real.update({f"m_{i}": RIGID_FLOOR_MASS, f"k_{i}": RIGID_STOREY_K,
                         f"cs_{i}": 2.0 * math.sqrt(RIGID_STOREY_K * RIGID_FLOOR_MASS)})
        else:
            real.update({f"m_{i}": p.mass, f"k_{i}": p.stiffness,
                         f"cs_{i}": 2.0 * p.damping * math.sqrt(p.stiffness * p.mass)})
    integer = {"nStoreys": n, "storeyLaw": 0, "diaphragmLaw": SPRING_LAWS[building.diaphragm_law]}
    return real, integer


def scene_of(building, building_fmu=None, wall_fmu=None):
    """The co-simulated Scene of a description.Building: a RockingWall per storey with a wall, tied
    to its diaphragm by the storey's tie (its K_d)."""
    real, integer = building_start_values(building)
    walls = []
    for i in building.walled():
        p = building.wall_parameters(i)
        ints = {"support": int(p.pop("support")), "hingeLaw": int(p.pop("hingeLaw"))}
        walls.append(WallSpec(i + 1, p, ints))
    return Scene(real, integer, walls, building_fmu=building_fmu, wall_fmu=wall_fmu)


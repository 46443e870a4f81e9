"""Which scene answered: every output names the scene that was run and what it leaves out.

    (a) paper      the paper's scene: the top spring K_d ends at a fixed point (a rigid,
                   massless far end); the wall stands on the ground;
    (b) diaphragm  the wall under a diaphragm with mass and damping, tied to it, whose supports
                   (the in-plane walls) move with the ground: a single storey or a top storey;
    (c) building   walls in a multi-storey building, each standing on the floor below and tied
                   to the diaphragm above.
"""
import dataclasses

from .names import SUPPORTS
from .units import format_kd


@dataclasses.dataclass(frozen=True)
class Scene:
    key: str
    title: str
    leaves_out: str

    def text(self):
        """Two lines for a report: the scene, and what it leaves out."""
        return f"scene: {self.title}\nleft out: {self.leaves_out}"

    def to_dict(self):
        return {"name": self.key, "description": self.title, "leaves_out": self.leaves_out}


def paper(params, kd_text=None):
    """The scene of a wall on its own (rockingwall run/assess without a diaphragm mass); kd_text
    names K_d where it is not params["Kd"] alone (a sweep's, run by run)."""
    support = int(params["support"])
    if support == SUPPORTS["parapet"]:
        return Scene("paper", "a parapet (free top) on the ground",
                     "the motion of the floor or roof it stands on (rockingwall building FILE: a wall in its building)")
    if support == SUPPORTS["simplySupported"]:
        return Scene("paper", "a wall pinned at its top to a fixed point (a rigid diaphragm on the ground's motion)",
                     "the diaphragm's flexibility and mass and the floor's motion (give --Kd and --diaphragm-mass)")
    kd_text = kd_text or f"K_d = {format_kd(params['Kd'])}"
    return Scene("paper", f"the paper's: the top spring {kd_text} ends at a fixed point",
                 "the diaphragm's mass and damping and the floor's motion: the diaphragm is a massless spring "
                 "and the wall stands on the ground (give --diaphragm-mass for a diaphragm with mass, "
                 "--building FILE for the wall in its building)")


def diaphragm(diaphragm, tie):
    """Scene (b): the wall under a diaphragm with mass, its supports moving with the ground."""
    d = diaphragm
    law = "" if d.law == "linear" else f" ({d.law}{d.yielding()})"
    return Scene("diaphragm",
                 f"a wall tied ({tie:.3g} N/m per m) to a diaphragm of {format_kd(d.stiffness)}, {d.mass:.4g} kg/m, "
                 f"{100 * d.damping:.3g} % damping{law}, whose supports (the in-plane walls) move with the ground",
                 "the floor's motion below the wall and the in-plane walls' flexibility: right for a single "
                 "storey or a top storey on rigid in-plane walls (a multi-storey building: rockingwall building FILE)")


BUILDING_LEFT_OUT = "the diaphragms' higher modes (one mass per metre of wall at the wall), vertical ground motion"
STACKED = "each wall stands on the floor below and is tied to the diaphragm above"


def coupled_building(n_storeys, storeys_with_walls, wall, diaphragm_law, source=None):
    """Scene (c) as `rockingwall couple-building` builds it from its options: the Building FMU's
    defaults, the paper's wall `wall` in the storeys given, diaphragms of the law numbered as the
    FMU's diaphragmLaw (0 linear, 1 Bouc-Wen, 2 Bouc-Wen pinched, 3 bilinear); or, with `source`,
    the system of that SSP file (wall and diaphragm_law None)."""
    if source is not None:
        return Scene("building", f"walls in a {n_storeys}-storey building (the system of {source}): {STACKED}",
                     BUILDING_LEFT_OUT)
    law = ("linear", "Bouc-Wen", "pinched Bouc-Wen", "bilinear")[diaphragm_law]
    return Scene("building",
                 f"walls in a {n_storeys}-storey building (the Building FMU's defaults; the paper's wall {wall} in "
                 f"storeys {', '.join(map(str, storeys_with_walls))}): {STACKED}; {law} diaphragms with mass and "
                 "damping", BUILDING_LEFT_OUT)


def building(description):
    """Scene (c): the walls of a building (a building.description.Building)."""
    n = len(description.storeys)
    in_plane = "rigid in-plane walls" if description.rigid_in_plane else "flexible in-plane walls"
    return Scene("building",
                 f"walls in a {n}-storey building ({description.name}): {STACKED}; diaphragms with mass and "
                 f"damping, {in_plane}",
                 BUILDING_LEFT_OUT
                 + (", the in-plane walls' flexibility (taken as rigid)" if description.rigid_in_plane else ""))


def swept(model):
    """The scene of a sweep's runs of one model (its results' column): a storey of a building sweep
    (model 'building'), else the wall on its own under each run's K_d."""
    if model == "building":
        # the results do not say whether the file's in-plane walls were rigid (its default), so name both
        return Scene("building", f"the wall in its building (the sweep's building file): {STACKED}; "
                     "diaphragms with mass and damping (K_d: the diaphragm on top of the storey)",
                     f"{BUILDING_LEFT_OUT}, and the in-plane walls' flexibility where the building file takes "
                     "them as rigid (its default)")
    alone = paper({"support": SUPPORTS[model], "Kd": None}, kd_text="K_d (each run's)")
    return dataclasses.replace(alone, leaves_out=alone.leaves_out.split(" (")[0]
                               + " (rockingwall sweep --building FILE: the walls in their building)")

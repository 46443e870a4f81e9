"""A building file as the start values of BuildingWithWalls.fmu (docs/building-with-walls.md): the
walls, ties, diaphragms and floors of a description.Building by the FMU's names, for an FMI tool
or fmpy. The FMU runs the scene the one-integration solver (rockingwall.building.monolithic) runs,
with the same Bouc-Wen shape and pinching (description.Building.hysteresis)."""
from ..names import SPRING_LAWS, hinge_law_code


def start_values(building):
    """{name: value} of every parameter the building sets (the FMU's defaults for the rest)."""
    v = {"nStoreys": len(building.storeys), "rigidInPlane": int(building.rigid_in_plane), "storeyLaw": 0,
         "diaphragmLaw": SPRING_LAWS[building.diaphragm_law], "rayleighMass": 0.0,
         "rayleighStiffness": 0.0, **building.fmu_hysteresis()}
    for i, s in enumerate(building.storeys, 1):
        w, d, wall = s.wall, s.diaphragm, building.wall_parameters(i - 1)
        v.update({f"hasWall_{i}": int(w is not None), f"md_{i}": d.mass, f"kd_{i}": d.stiffness,
                  f"zetad_{i}": d.damping})
        if w is not None:
            v.update({f"h_{i}": s.height, f"b_{i}": w.b, f"W_{i}": w.W, f"psi_{i}": wall["psi"],
                      f"psiWeightOnly_{i}": wall["psiWeightOnly"], f"eTop_{i}": wall["eTop"], f"tie_{i}": s.tie,
                      f"er_{i}": w.e_r, f"hingeLaw_{i}": hinge_law_code(w.hinge_law)})
        if building.diaphragm_law != "linear":
            Fyd, alphad = d.spring_under(building.diaphragm_law)
            v.update({f"Fyd_{i}": Fyd, f"alphad_{i}": alphad})
        if s.in_plane is not None:
            p = s.in_plane
            v.update({f"m_{i}": p.mass, f"k_{i}": p.stiffness, f"zetas_{i}": p.damping})
    return v

"""The names users give supports, hinge laws, the building's spring laws and the paper's walls, and
the codes the FMUs and the engines take (fmu_src/wall/rw_parameters.h: `support`, `hingeLaw`;
fmu_src/models/Building/building_physics.h: `storeyLaw`, `diaphragmLaw`). The one copy of these maps."""

SUPPORTS = {"parapet": 1, "simplySupported": 2, "flexibleTop": 3}
HINGE_LAWS = {"rigid": 1, "semiRigidPaper": 2, "semiRigidHinge": 3, "dohertyHinge": 4}
# the springs of the building (diaphragms; the in-plane walls take all but boucWenPinched)
SPRING_LAWS = {"linear": 0, "boucWen": 1, "boucWenPinched": 2, "bilinear": 3}
SUPPORT_NAMES = {code: name for name, code in SUPPORTS.items()}
HINGE_LAW_NAMES = {code: name for name, code in HINGE_LAWS.items()}

# The three walls of the paper's Table 5.1 (b, h in m, W in N per m of wall, psi = Wd/W1).
PAPER_WALLS = {
    "paper1": dict(b=0.15, h=2.5, W=6622.0, psi=0.0),
    "paper2": dict(b=0.15, h=2.5, W=6622.0, psi=0.5),
    "paper3": dict(b=0.15, h=2.5, W=6622.0, psi=1.0),
}


def support_code(value):
    """'flexibleTop' or 3 -> 3; ValueError naming the known ones otherwise."""
    return _code(value, SUPPORTS, "support")


def hinge_law_code(value):
    """'dohertyHinge' or 4 -> 4; ValueError naming the known ones otherwise."""
    return _code(value, HINGE_LAWS, "hinge law")


def _code(value, table, what):
    if isinstance(value, str) and value in table:
        return table[value]
    if isinstance(value, str) and value.isdigit():
        value = int(value)
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    if isinstance(value, int) and not isinstance(value, bool) and value in table.values():
        return value
    raise ValueError(f"unknown {what} {value!r}; known: {', '.join(f'{n} ({c})' for n, c in table.items())}")


def paper_wall(name):
    """The paper's wall by preset name ('paper1') or number (1)."""
    key = f"paper{name}" if isinstance(name, int) or str(name).isdigit() else str(name)
    if key not in PAPER_WALLS:
        raise ValueError(f"unknown wall preset {name!r}; the paper's walls are {', '.join(PAPER_WALLS)}")
    return dict(PAPER_WALLS[key])

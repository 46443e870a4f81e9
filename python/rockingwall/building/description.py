"""A building as engineers describe it: storeys bottom up, each with its face-loaded wall, the
diaphragm on top of it and the tie between them, values with units (docs/your-building.md). Read
from a TOML file (`read`) or built in code; `Building.spec()` is the scene the solver runs.

    [building]
    name = "two-storey brick, timber floors"
    [[storey]]
    height = "4.0 m"
    wall = { b = "350 mm", W = "25.2 kN/m", overburden = "3.2 kN/m" }   # or unit_weight = "18 kN/m3"
    diaphragm = { stiffness = "60 kN/m/m", mass = "600 kg/m", damping = 0.05 }
    # tie = "1e8 N/m/m"

Everything is per metre of the face-loaded wall, in SI once read."""
import dataclasses
import math

from .. import units
from ..names import hinge_law_code

TIE_DEFAULT = 1e8          # N/m per m: a stiff tie (docs/your-building.md: 1e9 moves peaks by about 1 %)
DAMPING_DEFAULT = 0.05     # of critical, on the diaphragm's own mass and spring
POST_YIELD_DEFAULT = 0.1   # a hysteretic diaphragm's post-yield stiffness ratio when none is given
HINGE_LAW_DEFAULT = "dohertyHinge"
E_R_DEFAULT = 0.86
MAX_STOREYS = 5
# Foliente's pinching (zeta1, zeta2, q) of a boucWenPinched diaphragm when the file gives none: the
# Building FMU's defaults for timber, slack in nailed sheathing (docs/building.md)
PINCHING_TIMBER = {"pinch_size": 0.8, "pinch_width": 0.2, "pinch_centre": 0.1}
NO_PINCHING = {"pinch_size": 0.0, "pinch_width": 1.0, "pinch_centre": 0.0}
BOUC_WEN_SHAPE = {"n_bw": 1.0, "beta": 0.5}  # the loop's shape for both Bouc-Wen laws
# the same quantities by the Building FMUs' parameter names
FMU_HYSTERESIS_NAMES = {"n_bw": "nBW", "beta": "betaBW", "pinch_size": "pinchSize", "pinch_width": "pinchWidth",
                        "pinch_centre": "pinchCentre"}


@dataclasses.dataclass(frozen=True)
class WallLayer:
    """The face-loaded wall of a storey: thickness b [m], weight W [N/m], the overburden it carries
    at its top [N/m] (the floor or roof load on it, weight and mass; the walls above are added as
    weight alone, Building.weight_above) and where it bears, e_top [m] from the centreline, positive
    toward the inner face (the diaphragm's side: joists bearing on the inner leaf; the walls above
    bear on the centreline), the hinge law and the coefficient of restitution."""
    b: float
    W: float
    overburden: float = 0.0
    e_top: float = 0.0
    hinge_law: str = HINGE_LAW_DEFAULT
    e_r: float = E_R_DEFAULT


@dataclasses.dataclass(frozen=True)
class Diaphragm:
    """The diaphragm on top of a storey, at the wall, per metre of wall: stiffness [N/m per m],
    mass [kg/m] and damping ratio; law 'linear', 'boucWen', 'boucWenPinched' or 'bilinear'
    (elastoplastic with kinematic hardening; the hysteretic three with a yield force [N/m] and a
    post-yield stiffness ratio); pinching: Foliente's (pinch_size, pinch_width, pinch_centre) of a
    boucWenPinched law, default PINCHING_TIMBER."""
    stiffness: float
    mass: float
    damping: float = DAMPING_DEFAULT
    law: str = "linear"
    yield_force: float = math.inf
    post_yield: float = 1.0
    pinching: dict = None

    def __post_init__(self):
        if self.pinching is not None and self.law != "boucWenPinched":
            raise ValueError(f"pinching is a property of the boucWenPinched law, not of {self.law!r}")
        if self.law == "boucWenPinched" and self.pinching is None:
            object.__setattr__(self, "pinching", dict(PINCHING_TIMBER))

    def hysteresis(self):
        """The Bouc-Wen shape and pinching the scene solver and the Building FMUs take (scene_engine.Spec's
        names; FMU_HYSTERESIS_NAMES maps them to the FMUs')."""
        return dict(BOUC_WEN_SHAPE, **(self.pinching or NO_PINCHING))

    def spring_under(self, law):
        """(yield force [N/m], post-yield ratio) of this diaphragm run under the building's `law` (the
        solvers and FMUs take one law for every diaphragm): its own under its own law; a linear one
        beside hysteretic ones post-yield 1, so that its force is k d exactly whatever its z does, and
        a yield force of k x 1 m, so that its z (unused) is no stiff state; (1, 1) under the linear law,
        which uses neither."""
        if law == "linear":
            return 1.0, 1.0
        if self.law == law:
            return self.yield_force, self.post_yield
        return (self.stiffness * 1.0 if self.stiffness > 0 else 1.0), 1.0

    def yielding(self):
        """', yield force 1 kN/m, post-yield 0.1 (pinching ...)' of a hysteretic law, '' of a linear one:
        what the echo of the building adds to the law's name."""
        if self.law == "linear":
            return ""
        pinching = (f", pinching {', '.join(f'{k} {v:g}' for k, v in self.pinching.items())}"
                    if self.pinching else "")
        return f", yield force {self.yield_force / 1e3:.4g} kN/m, post-yield {self.post_yield:g}{pinching}"

    @property
    def dashpot(self):
        """c = 2 zeta sqrt(k m) [N s/m per m]."""
        return 2.0 * self.damping * math.sqrt(self.stiffness * self.mass)

    @property
    def period(self):
        """Its own period on its spring, 2 pi sqrt(m/k) [s] (inf for no stiffness)."""
        return 2.0 * math.pi * math.sqrt(self.mass / self.stiffness) if self.stiffness > 0 else math.inf


@dataclasses.dataclass(frozen=True)
class InPlaneWalls:
    """The in-plane walls of a storey when they are not rigid: stiffness [N/m per m], the floor's
    mass they carry [kg/m], damping ratio."""
    stiffness: float
    mass: float
    damping: float = DAMPING_DEFAULT


@dataclasses.dataclass(frozen=True)
class Storey:
    """A storey: its clear height [m], its face-loaded wall (None: a storey without one, an open
    front: the walls above it bear on its beam or frame, not on a wall), the diaphragm on top of it,
    the tie between them [N/m per m] and its in-plane walls."""
    height: float
    wall: WallLayer
    diaphragm: Diaphragm
    tie: float = TIE_DEFAULT
    in_plane: InPlaneWalls = None  # None: rigid in-plane walls (the floor moves with the ground)


@dataclasses.dataclass(frozen=True)
class Building:
    name: str
    storeys: tuple
    source: str = ""

    def __post_init__(self):
        if not 1 <= len(self.storeys) <= MAX_STOREYS:
            raise ValueError(f"a building has 1 to {MAX_STOREYS} storeys, not {len(self.storeys)}")
        if not self.walled():
            raise ValueError("no storey has a face-loaded wall: there is no wall to assess")
        rigid = [s.in_plane is None for s in self.storeys]
        if any(rigid) and not all(rigid):
            raise ValueError("in-plane walls: give them for every storey or for none (none: rigid)")
        laws = {s.diaphragm.law for s in self.storeys} - {"linear"}
        if len(laws) > 1:
            raise ValueError(f"one hysteretic diaphragm law for the whole building (the solvers and the FMUs take "
                             f"one), not {' and '.join(sorted(laws))}; linear diaphragms may stand beside it")
        if len({tuple(sorted(d.hysteresis().items())) for d in self.hysteretic_diaphragms()}) > 1:
            raise ValueError("one pinching for the whole building's diaphragms (the solver and the FMUs take one)")

    def hysteretic_diaphragms(self):
        return [s.diaphragm for s in self.storeys if s.diaphragm.law != "linear"]

    @property
    def diaphragm_law(self):
        """The law every diaphragm runs under: the hysteretic one where a storey has it, else linear
        (a linear diaphragm beside hysteretic ones runs under theirs: Diaphragm.spring_under)."""
        hysteretic = self.hysteretic_diaphragms()
        return hysteretic[0].law if hysteretic else "linear"

    def hysteresis(self):
        """The diaphragms' one Bouc-Wen shape and pinching (Diaphragm.hysteresis): the hysteretic ones'."""
        return (self.hysteretic_diaphragms() or [self.storeys[0].diaphragm])[0].hysteresis()

    def fmu_hysteresis(self):
        """hysteresis() by the Building FMUs' parameter names (FMU_HYSTERESIS_NAMES)."""
        return {FMU_HYSTERESIS_NAMES[k]: v for k, v in self.hysteresis().items()}

    @property
    def rigid_in_plane(self):
        return self.storeys[0].in_plane is None

    def walled(self):
        """The storeys (0-based) that have a face-loaded wall."""
        return [i for i, s in enumerate(self.storeys) if s.wall is not None]

    def weight_above(self, i):
        """The weight [N/m] the walls above storey i (0-based) put on its wall's top: their own
        weights and the overburdens they carry, up to a storey without a wall (the walls above an
        open front bear on its beam or frame)."""
        weight = 0.0
        for s in self.storeys[i + 1:]:
            if s.wall is None:
                break
            weight += s.wall.W + s.wall.overburden
        return weight

    def wall_parameters(self, i):
        """The wall of storey i as the model's parameters (SI), or None for a storey without one:
        tied to its diaphragm (flexibleTop, Kd = the tie), psi from the overburden it carries (weight
        and mass at its top, at eTop) and psiWeightOnly from the weight of the walls above
        (weight_above: their mass is in their own walls, so it is not counted twice)."""
        s = self.storeys[i]
        if s.wall is None:
            return None
        return dict(h=s.height, b=s.wall.b, W=s.wall.W, psi=2.0 * s.wall.overburden / s.wall.W,
                    psiWeightOnly=2.0 * self.weight_above(i) / s.wall.W, eTop=s.wall.e_top, Kd=s.tie,
                    er=s.wall.e_r, support=3, hingeLaw=hinge_law_code(s.wall.hinge_law))

    def _wall_text(self, i):
        """Storey i's wall with units, and the weight of the walls above it."""
        w, above = self.storeys[i].wall, self.weight_above(i)
        return (f"wall b = {w.b * 1e3:g} mm, W = {w.W / 1e3:.4g} kN/m, overburden {w.overburden / 1e3:.4g} kN/m"
                + (f" at {w.e_top * 1e3:g} mm from the centreline (+: toward the inner face)" if w.e_top else "")
                + (f" + walls above {above / 1e3:.4g} kN/m (weight only)" if above else "")
                + f", {w.hinge_law}, e_r = {w.e_r:g}")

    def describe(self):
        """The building with units, storey by storey: what the report echoes."""
        lines = [f"building: {self.name}" + (f" ({self.source})" if self.source else ""),
                 "in-plane walls: " + ("rigid (every floor moves with the ground)" if self.rigid_in_plane
                                       else "flexible")]
        for i, s in enumerate(self.storeys, 1):
            w, d = s.wall, s.diaphragm
            lines.append(f"storey {i}: h = {s.height:g} m; " + (self._wall_text(i - 1) if w else
                         "no face-loaded wall (an open front: the walls above bear on its beam or frame)"))
            lines.append(f"  diaphragm: {d.stiffness / 1e3:.4g} kN/m per m, {d.mass:.4g} kg/m, "
                         f"{100 * d.damping:.3g} % damping ({d.law}{d.yielding()}; own period {d.period:.3g} s)"
                         + (f"; tie {s.tie:.3g} N/m per m" if w else ""))
            if s.in_plane is not None:
                p = s.in_plane
                lines.append(f"  in-plane walls: {p.stiffness / 1e3:.4g} kN/m per m, floor {p.mass:.4g} kg/m, "
                             f"{100 * p.damping:.3g} % damping")
        return "\n".join(lines)


def parse_quantity(value, unit, what):
    """A value with its unit (see rockingwall.units) in SI, finite."""
    v = units.parse(value, unit, what)
    if not math.isfinite(v):
        raise ValueError(f"{what} = {value!r}: must be finite")
    return v

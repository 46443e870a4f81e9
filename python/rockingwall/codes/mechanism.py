"""The statics of the two rocking mechanisms the codes check: a wall spanning vertically between
floors (two rigid blocks hinged at their common crack) and a parapet (one block rocking on its base).

Both are reduced to one coordinate, the displacement D of the control point (the hinge of the
wall, the top of the parapet). Gravity's work on the mechanism, to second order in D, is
V(D) = A D - B D^2, so the restoring force is F(D) = A - 2 B D: F0 = A at rest, zero at the
instability displacement Delta_i = A / (2 B) (derived here by virtual work; for a wall with the
top load at mid-thickness and the reactions on the faces it is Doherty's
Delta_u = b (1 + 0.75 psi) / (1 + psi), psi = 2 P / W). The blocks are slender: their rotary
inertia about their pivots is m h^2 / 3, so the generalised mass is (W_b + W_t) / (3 g).

Lengths in m, weights and loads in N per metre of wall."""
import dataclasses

from .common import G, number

DIRECTIONS = ("outward", "inward")


@dataclasses.dataclass(frozen=True)
class TopLoad:
    """A vertical load at the top of the wall: force [N/m], and its eccentricity [m] from the
    wall's centreline, positive toward the inner face (the side the floor is on: joists bearing
    on the inner face have a positive eccentricity)."""
    force: float
    eccentricity: float = 0.0

    def __post_init__(self):
        number("top load force", self.force, 0.0, 1e7, "N/m")
        number("top load eccentricity", self.eccentricity, -10.0, 10.0, "m")


@dataclasses.dataclass(frozen=True)
class Mechanism:
    """One mechanism in one direction, per unit displacement D of its control point.
    A [N/m], B [N/m^2]: V(D) = A D - B D^2. mass [kg/m]: generalised mass. excitation [kg/m]:
    sum of m_i dx_i (the load of a uniform ground acceleration). weight_dx, weight_dx2 [N/m]:
    sum of W_i dx_i and W_i dx_i^2 over the moving weights (dx_i their centroids' horizontal
    displacements per unit D), and moving_weight [N/m] their sum: the kinematic analysis of the
    Italian code uses these."""
    name: str
    direction: str
    control_point: str
    A: float
    B: float
    mass: float
    excitation: float
    weight_dx: float
    weight_dx2: float
    moving_weight: float

    @property
    def delta_i(self):
        """Instability displacement of the control point [m]: F(Delta_i) = 0."""
        return self.A / (2.0 * self.B)

    def force(self, d):
        """Restoring force F(D) = A - 2 B D [N/m], work-conjugate to D."""
        return self.A - 2.0 * self.B * d

    def secant_stiffness(self, d):
        """F(D) / D [N/m per m]."""
        return self.force(d) / d

    @property
    def participation(self):
        """gamma = sum(m_i dx_i) / generalised mass: D = gamma times the displacement of the
        single-degree-of-freedom oscillator with the same period."""
        return self.excitation / self.mass

    @property
    def alpha0(self):
        """Load multiplier that starts the mechanism: horizontal forces alpha W_i on the moving
        weights do the work A (virtual work at D = 0)."""
        return self.A / self.weight_dx


def _thickness(b, pointing):
    b = number("b", b, 0.02, 3.0, "m")
    pointing = number("pointing depth", pointing, 0.0, b / 2, "m", high_open=True)
    return b - 2.0 * pointing


def _lever(name, value, t):
    """A reaction's distance from the centreline; None is the face of the effective section."""
    return t / 2 if value is None else number(name, value, 0.0, t / 2, "m")


@dataclasses.dataclass(frozen=True)
class FaceLoadedWall:
    """A wall spanning vertically between two floors. h: clear height [m]; b: nominal thickness
    [m]; W: weight [N/m]; pointing: depth of recessed mortar pointing on EACH face [m] (the
    effective thickness is t = b - 2 pointing); e_base, e_hinge: distance from the centreline to
    the reaction at the base and at the hinge [m] (None: the face, t/2); hinge_height: height of
    the hinge above the base [m] (None: h/2); top_loads: TopLoads at the top."""
    h: float
    b: float
    W: float
    top_loads: tuple = ()
    pointing: float = 0.0
    e_base: float = None
    e_hinge: float = None
    hinge_height: float = None

    def __post_init__(self):
        number("h", self.h, 0.3, 30.0, "m")
        number("W", self.W, 10.0, 1e6, "N/m")
        t = self.t
        if t >= self.h:
            raise ValueError(f"b = {self.b:g} m must be less than h = {self.h:g} m")
        _lever("e_base", self.e_base, t)
        _lever("e_hinge", self.e_hinge, t)
        if self.hinge_height is not None:
            number("hinge_height", self.hinge_height, 0.05 * self.h, 0.95 * self.h, "m")
        for load in self.top_loads:
            if not isinstance(load, TopLoad):
                raise ValueError(f"top_loads: expected TopLoad items, got {load!r}")
            if abs(load.eccentricity) > self.b / 2:
                raise ValueError(f"top load eccentricity = {load.eccentricity:g} m lies outside the wall "
                                 f"(allowed: within b/2 = {self.b / 2:g} m of the centreline)")

    @property
    def t(self):
        """Effective thickness [m]."""
        return _thickness(self.b, self.pointing)

    def mechanism(self, direction):
        """The two-block mechanism moving `direction` ('outward' or 'inward'); control point the
        hinge. The base and the top stay put horizontally; the hinge moves D, so the lower block
        turns D/h_b about its base pivot and the upper block D/h_t about the top."""
        t = self.t
        h_b = self.h / 2 if self.hinge_height is None else self.hinge_height
        h_t = self.h - h_b
        w_b, w_t = self.W * h_b / self.h, self.W * h_t / self.h
        e_b, e_m = _lever("e_base", self.e_base, t), _lever("e_hinge", self.e_hinge, t)
        sign = 1.0 if direction == "inward" else -1.0  # a load toward the side the wall moves to is lifted more
        # Rise per unit D (first order) and drop per unit D^2 (second order) of each weight:
        # lower block's centroid: e_b/h_b and 1/(4 h_b); the hinge: (e_b + e_m)/h_b and 1/(2 h_b);
        # upper centroid: the hinge's plus e_m/h_t and 1/(4 h_t); a top load at eccentricity e
        # (toward the motion): the hinge's plus (e + e_m)/h_t and 1/(2 h_t).
        hinge_rise, hinge_drop = (e_b + e_m) / h_b, 1.0 / (2.0 * h_b)
        A = w_b * e_b / h_b + w_t * (hinge_rise + e_m / h_t)
        B = w_b / (4.0 * h_b) + w_t * (hinge_drop + 1.0 / (4.0 * h_t))
        for load in self.top_loads:
            A += load.force * (hinge_rise + (sign * load.eccentricity + e_m) / h_t)
            B += load.force * (hinge_drop + 1.0 / (2.0 * h_t))
        if A <= 0.0:
            raise ValueError(f"the wall cannot stand moving {direction}: the top loads' eccentricity "
                             "turns it over at rest (check the sign: positive is toward the inner face)")
        # Both centroids move D/2 horizontally; the top loads do not move horizontally.
        return Mechanism("two-block wall", direction, "hinge", A, B, mass=self.W / (3.0 * G),
                         excitation=self.W / (2.0 * G), weight_dx=self.W / 2.0,
                         weight_dx2=self.W / 4.0, moving_weight=self.W)


@dataclasses.dataclass(frozen=True)
class Parapet:
    """A free-standing block rocking on its base (a parapet or a cantilever above the top
    restraint). h: height above its base [m]; b, W, pointing and e_base as for FaceLoadedWall."""
    h: float
    b: float
    W: float
    pointing: float = 0.0
    e_base: float = None

    def __post_init__(self):
        number("h", self.h, 0.1, 30.0, "m")
        number("W", self.W, 1.0, 1e6, "N/m")
        if self.t >= self.h:
            raise ValueError(f"b = {self.b:g} m must be less than h = {self.h:g} m")
        _lever("e_base", self.e_base, self.t)

    @property
    def t(self):
        return _thickness(self.b, self.pointing)

    def mechanism(self, direction):
        """The block turning theta = D/h about its base pivot; control point the top. Its
        centroid rises e_b theta - (h/2) theta^2 / 2: A = W e_b / h, B = W / (4 h), so the top's
        instability displacement is 2 e_b (= t with the pivot on the face)."""
        e_b = _lever("e_base", self.e_base, self.t)
        return Mechanism("parapet", direction, "top", self.W * e_b / self.h, self.W / (4.0 * self.h),
                         mass=self.W / (3.0 * G), excitation=self.W / (2.0 * G),
                         weight_dx=self.W / 2.0, weight_dx2=self.W / 4.0, moving_weight=self.W)

"""A wall: the model's parameters by name, in SI units, from a preset of the paper or the user's
own numbers. The parameter table (names, units, defaults, closed ranges) is the C one, read from
the engine library, so the Python side cannot drift from the FMU."""
import dataclasses
import warnings

from . import names, units
from .engine import delta_u, parameter_table, statics

# Values that are valid for the model but unusual for an unreinforced-masonry wall and its
# diaphragm: a value outside is most often a unit slip (kN typed for N). (low, high) in SI.
PLAUSIBLE = {
    "h": (1.5, 12.0, "m"),
    "b": (0.07, 1.2, "m"),
    "W": (1.0e3, 2.0e5, "N/m"),
    "psi": (0.0, 6.0, "1"),
}
# NZSEE C8's statics of the wall: named in describe() when not at their defaults
STATICS = ("pointing", "eBaseRatio", "eHingeRatio", "eTop", "psiWeightOnly")
KD_PLAUSIBLE = (5.0e2, 1.0e10)        # N/m per m: a very flexible timber floor .. rigid
UNIT_WEIGHT_PLAUSIBLE = (10e3, 30e3)  # N/m^3: W/(b h) of masonry (brick, stone, block)


def unit_weight_slip(W, b, h):
    """What W/(b h) says of W's unit where it is not a masonry unit weight, else None."""
    gamma = W / (b * h)
    if UNIT_WEIGHT_PLAUSIBLE[0] <= gamma <= UNIT_WEIGHT_PLAUSIBLE[1]:
        return None
    return (f"W/(b h) = {gamma / 1e3:.3g} kN/m^3 is not a masonry unit weight "
            f"({UNIT_WEIGHT_PLAUSIBLE[0] / 1e3:g}-{UNIT_WEIGHT_PLAUSIBLE[1] / 1e3:g} kN/m^3): "
            "W is the weight per metre of wall in N/m")


class PlausibilityWarning(UserWarning):
    """A value the model accepts but a masonry wall rarely has: check its unit."""


@dataclasses.dataclass(frozen=True)
class Wall:
    """Parameters of one wall and its supports, by the FMU's names and in SI units:
    h [m], b [m], W [N per m of wall], psi [1] (Wd/W1: overburden over the weight of ONE body,
    W1 = W/2), Kd [N/m per m of wall], er [1], support, hingeLaw, NZSEE C8's statics (pointing [m],
    eBaseRatio, eHingeRatio [1], eTop [m], psiWeightOnly [1]), and the rest of
    `rockingwall info`. Unset parameters take the table's defaults."""
    params: dict

    @classmethod
    def make(cls, preset=None, warn=True, **values):
        """A wall from a preset ('paper1'..'paper3', or None for the defaults) and values by name.
        Values may carry units ('30 kN/m per m', '230 mm'); support and hingeLaw take names."""
        table = parameter_table()
        params = {n: row.default for n, row in table.items()}
        if preset is not None:
            params.update(names.paper_wall(preset))
        for key, value in values.items():
            if key not in table:
                raise ValueError(f"unknown parameter {key!r}; known: {', '.join(table)}")
            params[key] = _convert(key, value, table[key])
        wall = cls(params)
        wall.check()
        if warn:
            for message in wall.implausible():
                warnings.warn(message, PlausibilityWarning, stacklevel=2)
        return wall

    def replace(self, **values):
        return Wall.make(**{**self.params, **values})

    def check(self):
        """ValueError with the parameter, value and range when a value is outside the model's range,
        or naming the parameters when they break a rule that ties them together (the C model's)."""
        table = parameter_table()
        for key, value in self.params.items():
            table[key].check(value)
        if not self.params["b"] < self.params["h"]:
            raise ValueError(f"b = {self.params['b']} m must be less than h = {self.params['h']} m")
        self.statics()

    def implausible(self):
        """Messages for values outside the plausible range of masonry walls and diaphragms."""
        p, out = self.params, []
        for key, (low, high, unit) in PLAUSIBLE.items():
            if not low <= p[key] <= high:
                out.append(f"{key} = {p[key]:g} {unit} is outside [{low:g}, {high:g}] {unit}, "
                           "unusual for a masonry wall: is the unit right?")
        kd = p["Kd"]
        if p["support"] == names.SUPPORTS["flexibleTop"] and kd > 0 and not KD_PLAUSIBLE[0] <= kd <= KD_PLAUSIBLE[1]:
            out.append(f"Kd = {kd:g} N/m per m is outside [{KD_PLAUSIBLE[0]:g}, {KD_PLAUSIBLE[1]:g}] N/m per m; "
                       "did you mean kN/m per m (write '30kN/m/m')?")
        slip = unit_weight_slip(p["W"], p["b"], p["h"])
        return out + ([slip] if slip else [])

    def statics(self):
        """The C model's statics: Delta_u and F_r per direction, the hinge capacities per side
        (rockingwall.engine.statics)."""
        return statics(**self.params)

    @property
    def delta_u(self):
        """Delta_u [m]: the mid-height displacement at which the 1DOF's restoring force reaches
        zero (NZSEE C8's Delta_i; b (1 + 0.75 psi)/(1 + psi) for the paper's walls, Table 5.1),
        the smaller of the two directions when an eccentric top load makes them differ."""
        return delta_u(**self.params)

    @property
    def delta_u_by_direction(self):
        """{+1: Delta_u moving toward +x (inward), -1: toward -x (outward)} [m]."""
        return self.statics()["Delta_u"]

    def to_dict(self):
        """The parameters for a JSON report, SI by the FMU's names as `params`, but `support` and
        `hingeLaw` by their names (a code such as 4.0 reads as a number): Wall.make(**d) rebuilds the wall."""
        p = dict(self.params)
        p["support"] = names.SUPPORT_NAMES[int(p["support"])]
        p["hingeLaw"] = names.HINGE_LAW_NAMES[int(p["hingeLaw"])]
        return p

    def describe(self, with_kd=True):
        """One line for titles and reports; with_kd=False leaves K_d out (a study over several)."""
        p, table = self.params, parameter_table()
        statics = "".join(f", {name} = {p[name]:g}" for name in STATICS if p[name] != table[name].default)
        return (f"b = {p['b']:g} m, h = {p['h']:g} m, W = {p['W'] / 1e3:g} kN/m, psi = {p['psi']:g}{statics}, "
                f"e_r = {p['er']:g}, {names.SUPPORT_NAMES[int(p['support'])]}"
                + (f", K_d = {units.format_kd(p['Kd'])}" if with_kd and int(p["support"]) == 3 else "")
                + f", hinge law {names.HINGE_LAW_NAMES[int(p['hingeLaw'])]}")


def _convert(key, value, row):
    if key == "support":
        return names.support_code(value)
    if key == "hingeLaw":
        return names.hinge_law_code(value)
    return units.parse(value, row.unit, key)

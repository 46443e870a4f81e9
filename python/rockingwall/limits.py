"""Limit states an engineer recognises, checked on a run's peaks.

A limit state is 'QUANTITY >= VALUE', named or not: QUANTITY is s1 (mid-height), s2 (top) or
F_top (the tie force on the diaphragm), VALUE a number with a unit ('50mm', '10kN/m') or a
multiple of the wall's Delta_u or b ('0.6*Delta_u'). Collapse (the model's instability) is
always checked as well.

Always checked: s1 >= 0.6 Delta_u, the displacement capacity NZSEE's assessment guideline (C8,
2017) allows for a face-loaded wall (60 % of the instability displacement), and s1 >= Delta_u,
the instability displacement of the simply supported wall; a wall past either has little margin
left even when the model has not (yet) called it collapsed."""
import dataclasses
import re

import numpy as np

from . import units

QUANTITIES = {"s1": ("m", "peak_s1"), "s2": ("m", "peak_s2"), "F_top": ("N/m", "peak_F_top")}
# The largest force threshold [N/m]: 100 MN per metre of wall is beyond any wall-to-floor tie (a
# 10 m masonry wall weighs about 200 kN/m). Displacements are bounded by the wall's height.
MAX_FORCE = 1e8
# NZSEE C8's usable displacement as a share of Delta_u (its Delta_m): a standing wall past it is
# near collapse, where rocking is chaotic and one run is one sample of a spread
USABLE_SHARE = 0.6
NEAR_COLLAPSE_NOTE = (f"near_collapse: the wall stands with s1 at {USABLE_SHARE:g} Delta_u or more (NZSEE C8's usable "
                      "displacement), where rocking is chaotic and a small change of the inputs can turn standing "
                      "into collapse: its peaks are one sample of a spread that an ensemble gives (docs/robustness.md)")
DEFAULTS = ("0.6 Delta_u: s1 >= 0.6*Delta_u", "Delta_u: s1 >= 1.0*Delta_u")
_FORM = re.compile(r"^\s*(?:(?P<name>[^:]+):)?\s*(?P<q>s1|s2|F_top)\s*>=\s*(?P<value>.+?)\s*$")
_MULTIPLE = re.compile(r"^(?P<k>[0-9.eE+-]+)\s*\*\s*(?P<ref>Delta_u|b)$")


def near_collapse(s1_over_delta_u, collapsed):
    """A standing wall at or past the usable displacement (USABLE_SHARE x Delta_u)."""
    return not collapsed and s1_over_delta_u >= USABLE_SHARE


@dataclasses.dataclass(frozen=True)
class LimitState:
    name: str
    quantity: str
    threshold: float   # in the quantity's SI unit, for the wall it was made for
    multiple: float = None   # threshold = multiple x the wall's Delta_u or b (reference), if given so
    reference: str = None

    def exceeded(self, peaks):
        """peaks: a dict with peak_s1, peak_s2 [m], peak_F_top [N/m] and collapsed. A collapsed
        run exceeds every limit state (its peaks stop where the wall fell)."""
        return bool(peaks["collapsed"]) or peaks[QUANTITIES[self.quantity][1]] >= self.threshold

    def exceeded_many(self, peaks, b, delta_u):
        """exceeded() over arrays of runs of walls of thickness b and Delta_u [m] (arrays or
        scalars): a threshold given as a multiple of Delta_u or b is each wall's own."""
        threshold = self.threshold
        if self.multiple is not None:
            threshold = self.multiple * np.asarray(delta_u if self.reference == "Delta_u" else b, dtype=float)
        reached = np.asarray(peaks[QUANTITIES[self.quantity][1]], dtype=float) >= threshold
        return np.asarray(peaks["collapsed"], dtype=bool) | reached

    def describe(self):
        unit = QUANTITIES[self.quantity][0]
        value = f"{self.threshold * 1e3:.1f} mm" if unit == "m" else f"{self.threshold / 1e3:.3g} kN/m"
        return f"{self.name}: {self.quantity} >= {value}"


def ask_tie_force(states):
    """Whether any of the limit states is on F_top (its runs then need their tie forces)."""
    return any(s.quantity == "F_top" for s in states)


def parse(text, wall):
    """A LimitState from 'NAME: s1 >= 0.6*Delta_u' (NAME optional) for this wall."""
    m = _FORM.match(text)
    if not m:
        raise ValueError(f"limit state {text!r}: write 'NAME: QUANTITY >= VALUE' with QUANTITY s1, s2 or F_top "
                         "and VALUE like 50mm, 10kN/m or 0.6*Delta_u")
    quantity, value = m.group("q"), m.group("value")
    multiple = _MULTIPLE.match(value.replace(" ", ""))
    if multiple:
        if quantity == "F_top":
            raise ValueError(f"limit state {text!r}: a force cannot be a multiple of {multiple.group('ref')}")
        reference = multiple.group("ref")
        k = units.parse(multiple.group("k"), "1", f"limit state {text!r}")
        threshold = k * (wall.delta_u if reference == "Delta_u" else wall.params["b"])
    else:
        reference, k = None, None
        threshold = units.parse(value, QUANTITIES[quantity][0], quantity)
    if not threshold > 0:
        raise ValueError(f"limit state {text!r}: the threshold must be > 0")
    check_reachable(text, quantity, threshold, wall)
    return LimitState((m.group("name") or text).strip(), quantity, threshold, k, reference)


def check_reachable(text, quantity, threshold, wall):
    """A threshold no run can reach is a typing error, not a limit state: a displacement beyond the
    wall's height, a force beyond MAX_FORCE."""
    if QUANTITIES[quantity][0] == "m" and threshold > wall.params["h"]:
        raise ValueError(f"limit state {text!r}: {threshold:g} m is beyond the wall's height h = "
                         f"{wall.params['h']:g} m, which no displacement of the wall reaches")
    if QUANTITIES[quantity][0] == "N/m" and threshold > MAX_FORCE:
        raise ValueError(f"limit state {text!r}: {threshold:g} N/m is above {MAX_FORCE:g} N/m, the largest "
                         "force threshold this program accepts")


def parse_all(texts, wall):
    """The default limit states and those given, each name once."""
    states = [parse(t, wall) for t in (*DEFAULTS, *(texts or ()))]
    names = [s.name for s in states]
    if len(set(names)) != len(names):
        raise ValueError(f"limit states need distinct names: {names}")
    return states

"""ASCE/SEI 41-17: the out-of-plane check of an unreinforced-masonry wall by its height-to-thickness
ratio, against the permissible h/t for the wall's storey and the site's S_X1 (Life Safety and
Collapse Prevention). The table is the common reading of the standard, not checked against its
text; its footnotes are not applied."""
import dataclasses

from .common import Ref, choice, number, unconfirmed_notes, verdict

STOREYS = ("one_storey_building", "first_storey", "top_storey", "other_storey")
BANDS = ("S_X1 <= 0.24g", "0.24g < S_X1 <= 0.37g", "S_X1 > 0.37g")
PERMISSIBLE = {
    "one_storey_building": (20, 16, 13),   # walls of one-storey buildings
    "first_storey": (20, 18, 15),          # first-storey walls of multistorey buildings
    "top_storey": (14, 14, 9),             # walls in the top storey of multistorey buildings
    "other_storey": (20, 16, 13),          # all other walls
}
REFS = (Ref("h/t limit", "ASCE/SEI 41-17 Par. 11.3.4 (URM out-of-plane walls), table of permissible h/t "
            "by storey and S_X1 band (recalled as Table 11-5)", "unconfirmed"),)


@dataclasses.dataclass(frozen=True)
class Asce41Result:
    """capacity = the permissible h/t, demand = the wall's h/t; verdict 'pass' when h/t <= limit."""
    h_over_t: float
    limit: float
    band: str
    storey: str
    capacity: float
    demand: float
    verdict: str
    refs: tuple
    notes: tuple


def band_index(s_x1):
    """0, 1 or 2: the S_X1 band [g] of the table's columns."""
    s_x1 = number("S_X1", s_x1, 0.0, 5.0, "g")
    return 0 if s_x1 <= 0.24 else 1 if s_x1 <= 0.37 else 2


def check_wall(h, t, storey, S_X1):
    """h: the wall's unsupported height [m]; t: its thickness [m]; storey: one of STOREYS;
    S_X1: the 1-s spectral acceleration of the hazard level assessed [g]."""
    h = number("h", h, 0.0, 30.0, "m", low_open=True)
    t = number("t", t, 0.0, h, "m", low_open=True)
    storey = choice("storey", storey, STOREYS)
    band = band_index(S_X1)
    limit = float(PERMISSIBLE[storey][band])
    ratio = h / t
    notes = unconfirmed_notes(REFS) + (
        "the table's footnotes (conditions on bracing and on walls in flexible-diaphragm buildings) are not applied",
        "an h/t check assumes the wall is anchored to diaphragms that stay in place",
    )
    return Asce41Result(ratio, limit, BANDS[band], storey, limit, ratio, verdict(limit, ratio), REFS, notes)

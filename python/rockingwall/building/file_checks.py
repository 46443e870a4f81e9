"""What a building file's values say about their units: each storey's wall against the wall
model's ranges (an error: the model cannot run it), and the per-metre numbers against what
masonry buildings have (a warning naming the likely unit slip: a bare number is SI, so
`W = 25.2` is 25.2 N/m and `stiffness = 20` is 20 N/m per m). building_file names the lines."""
from ..wall import KD_PLAUSIBLE, PLAUSIBLE, Wall, unit_weight_slip

MASS_PLAUSIBLE = (10.0, 1e5)  # kg/m per metre of wall: a light roof's strip .. a heavy concrete floor's


def model_error(building, i):
    """Why the wall model cannot take storey i's wall (with the likely slip), or None (also for a
    storey without a wall)."""
    if building.storeys[i].wall is None:
        return None
    try:
        Wall.make(warn=False, **building.wall_parameters(i))
    except ValueError as exc:
        slips = [message for _, message in implausible(building, i)]
        return f"storey {i + 1}.wall: {exc}" + (f" ({'; '.join(slips)})" if slips else "")
    return None


def implausible(building, i):
    """(keys below the storey's table, message) for each of storey i's numbers that masonry
    buildings rarely have."""
    s, out = building.storeys[i], []
    w, d = s.wall, s.diaphragm
    springs = [(["diaphragm", "stiffness"], d.stiffness, "the diaphragm's stiffness")]
    if w is not None:  # a storey without a wall has no tie
        out += _implausible_wall(w, s.height)
        springs.append((["tie"], s.tie, "the tie"))
    for keys, value, what in springs:
        if not KD_PLAUSIBLE[0] <= value <= KD_PLAUSIBLE[1]:
            out.append((keys, f"{what} {value:g} N/m per m is outside [{KD_PLAUSIBLE[0]:g}, {KD_PLAUSIBLE[1]:g}] N/m "
                              "per m: did you mean kN/m per m (\"20 kN/m/m\")?"))
    if not MASS_PLAUSIBLE[0] <= d.mass <= MASS_PLAUSIBLE[1]:
        out.append((["diaphragm", "mass"], f"the diaphragm's mass {d.mass:g} kg/m is outside [{MASS_PLAUSIBLE[0]:g}, "
                                           f"{MASS_PLAUSIBLE[1]:g}] kg/m per metre of wall: is the unit right (\"0.6 t/m\")?"))
    return out


def _implausible_wall(w, height):
    """The wall's numbers that masonry walls rarely have: a unit weight out of range, an overburden
    many times the wall's weight."""
    out = []
    slip = unit_weight_slip(w.W, w.b, height)
    if slip:
        out.append((["wall", "W"], slip + ' unless it has a unit ("25.2 kN/m")'))
    psi_high = PLAUSIBLE["psi"][1]
    if 2.0 * w.overburden / w.W > psi_high:
        out.append((["wall", "overburden"], f"the overburden {w.overburden:g} N/m is over {psi_high / 2:g} times the "
                                            f"wall's weight {w.W:g} N/m: are their units right?"))
    return out

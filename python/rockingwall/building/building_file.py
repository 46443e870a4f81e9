"""The building file (TOML): read into a Building, every value with its unit checked, every error
naming the file, the line and the problem (docs/your-building.md has the contract)."""
import math
import os
import re
import tomllib
import warnings

from .description import (DAMPING_DEFAULT, E_R_DEFAULT, HINGE_LAW_DEFAULT, PINCHING_TIMBER, POST_YIELD_DEFAULT,
                          TIE_DEFAULT, Building, Diaphragm, InPlaneWalls, Storey, WallLayer, parse_quantity)
from ..names import HINGE_LAWS, SPRING_LAWS
from ..wall import PlausibilityWarning
from . import file_checks

BUILDING_KEYS = {"name", "tie"}
NO_WALL = "none"  # wall = "none": a storey without a face-loaded wall
STOREY_KEYS = {"height", "wall", "diaphragm", "tie", "in_plane"}
WALL_KEYS = {"b", "W", "unit_weight", "overburden", "e_top", "hinge_law", "e_r"}
PINCHING_KEYS = ("pinch_size", "pinch_width", "pinch_centre")
DIAPHRAGM_KEYS = {"stiffness", "mass", "damping", "law", "yield_force", "post_yield", *PINCHING_KEYS}
IN_PLANE_KEYS = {"stiffness", "mass", "damping"}
RANGES = {  # what a masonry building's per-metre numbers can be (SI); outside is refused
    "height": (0.5, 30.0), "b": (0.02, 3.0), "W": (10.0, 1e6), "unit_weight": (1e3, 1e5), "overburden": (0.0, 1e7),
    "stiffness": (0.0, 1e12), "mass": (1e-6, 1e7), "damping": (0.0, 2.0), "tie": (1.0, 1e12), "e_r": (0.0, 1.0),
    "e_top": (-1.5, 1.5),
    "yield_force": (1e-3, 1e9), "post_yield": (0.0, 1.0),
    "pinch_size": (0.0, 0.99), "pinch_width": (0.01, 10.0), "pinch_centre": (0.0, 0.99),
}


class BuildingFileError(ValueError):
    """A building file that cannot be used: the message names the file, the line and the problem."""


class _Where:
    """The file and its lines, for messages that name the line a problem is on."""

    def __init__(self, path, lines):
        self.path, self.lines = path, lines

    def error(self, line, message, at=()):
        """The error of a problem in the table whose header is on `line`, at the keys `at` below it
        (the line where the innermost of them that is set is named)."""
        return BuildingFileError(f"{self.path}:{self.line_of(line, at)}: {message}")

    def line_of(self, start, keys):
        """The line (1-based) that sets keys[-1] of the table whose header is on line `start`, found
        key by key (an inline table's keys on its own line, a sub-table's below its header); the
        line of the innermost key found, `start` if none is."""
        line, end = start, self._table_end(start)
        for key in keys:
            found = self._find(key, line, end)
            if found is None:
                break
            line = found
            if re.search(r"=\s*\{", self.lines[line - 1]):  # an inline table: all its keys are on its line
                end = line + 1
        return line

    def _table_end(self, start):
        """The first line after `start` that opens the next storey or the [building] table."""
        header = re.compile(r"^\s*\[(\[\s*storey\s*\]|\s*building\s*)\]")
        return next((n for n in range(start + 1, len(self.lines) + 1) if header.match(self.lines[n - 1])),
                    len(self.lines) + 1)

    def _find(self, key, first, end):
        k = re.escape(key)
        pattern = re.compile(rf'(^|[{{,])\s*(["\']?){k}\2\s*=|^\s*\[\s*[\w.]*\b{k}\s*\]')
        return next((n for n in range(first, end) if pattern.search(self.lines[n - 1])), None)


def _keys(what):
    """The keys below its table that a message's subject names: 'storey 1.diaphragm' -> ['diaphragm']."""
    return what.split(".")[1:]


def _table_lines(text, header):
    """The line numbers (1-based) of every `[[header]]` (or `[header]`) table in the text."""
    pattern = re.compile(r"^\s*\[\[?\s*" + re.escape(header) + r"\s*\]\]?\s*(#.*)?$")
    return [n for n, line in enumerate(text.splitlines(), 1) if pattern.match(line)]


def _check_keys(table, allowed, what, where, line):
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise where.error(line, f"{what}: unknown key(s) {', '.join(unknown)}; known: {', '.join(sorted(allowed))}",
                          _keys(what) + unknown[:1])


def _quantity(table, key, unit, where, line, what, default=None):
    if key not in table:
        if default is None:
            raise where.error(line, f"{what}.{key} is missing", _keys(what))
        return default
    try:
        v = parse_quantity(table[key], unit, f"{what}.{key}")
    except ValueError as exc:
        raise where.error(line, str(exc), _keys(what) + [key]) from None
    low, high = RANGES[key]
    if not low <= v <= high:
        shown = f"{unit}" if unit not in (None, "1") else "(a ratio: 5 % is 0.05 or \"5 %\")"
        raise where.error(line, f"{what}.{key} = {table[key]!r} is outside [{low:g}, {high:g}] {shown}",
                          _keys(what) + [key])
    return v


def _wall(table, height, where, line, what):
    if not isinstance(table, dict):
        raise where.error(line, f"{what} must be a table, e.g. {{ b = \"230 mm\", W = \"14.9 kN/m\" }}", _keys(what))
    _check_keys(table, WALL_KEYS, what, where, line)
    b = _quantity(table, "b", "m", where, line, what)
    if ("W" in table) == ("unit_weight" in table):
        raise where.error(line, f"{what}: give W (weight per metre of wall) or unit_weight, one of the two",
                          _keys(what))
    W = (_quantity(table, "W", "N/m", where, line, what) if "W" in table
         else _quantity(table, "unit_weight", "N/m3", where, line, what) * b * height)
    law = table.get("hinge_law", HINGE_LAW_DEFAULT)
    if law not in HINGE_LAWS:
        raise where.error(line, f"{what}.hinge_law = {law!r}: known {', '.join(HINGE_LAWS)}", _keys(what) + ["hinge_law"])
    e_top = _quantity(table, "e_top", "m", where, line, what, 0.0)
    if not abs(e_top) <= b / 2:
        raise where.error(line, f"{what}.e_top = {table['e_top']!r}: the overburden must bear within the wall, "
                                f"|e_top| <= b/2 = {b / 2 * 1e3:g} mm", _keys(what) + ["e_top"])
    return WallLayer(b=b, W=W, overburden=_quantity(table, "overburden", "N/m", where, line, what, 0.0),
                     e_top=e_top, hinge_law=law, e_r=_quantity(table, "e_r", "1", where, line, what, E_R_DEFAULT))


def _diaphragm(table, where, line, what):
    if not isinstance(table, dict):
        raise where.error(line, f"{what} must be a table, e.g. {{ stiffness = \"20 kN/m/m\", mass = \"200 kg/m\" }}",
                          _keys(what))
    _check_keys(table, DIAPHRAGM_KEYS, what, where, line)
    law = table.get("law", "linear")
    if law not in SPRING_LAWS:
        raise where.error(line, f"{what}.law = {law!r}: known {', '.join(SPRING_LAWS)}", _keys(what) + ["law"])
    hysteretic = law != "linear"
    if hysteretic != ("yield_force" in table):
        hysteretic_laws = ", ".join(law for law in SPRING_LAWS if law != "linear")
        raise where.error(line, f"{what}: yield_force is given with a hysteretic law ({hysteretic_laws}) and only "
                          "with one", _keys(what))
    given = [k for k in PINCHING_KEYS if k in table]
    if given and law != "boucWenPinched":
        raise where.error(line, f"{what}: {', '.join(given)} is the pinching of law = \"boucWenPinched\" only",
                          _keys(what))
    pinching = {k: _quantity(table, k, "1", where, line, what, PINCHING_TIMBER[k]) for k in PINCHING_KEYS}
    return Diaphragm(stiffness=_quantity(table, "stiffness", "N/m2", where, line, what),
                     mass=_quantity(table, "mass", "kg/m", where, line, what),
                     damping=_quantity(table, "damping", "1", where, line, what, DAMPING_DEFAULT), law=law,
                     yield_force=_quantity(table, "yield_force", "N/m", where, line, what, math.inf),
                     post_yield=_quantity(table, "post_yield", "1", where, line, what,
                                          POST_YIELD_DEFAULT if hysteretic else 1.0),
                     pinching=pinching if law == "boucWenPinched" else None)


def _in_plane(table, where, line, what):
    if not isinstance(table, dict):
        raise where.error(line, f"{what} must be a table, e.g. {{ stiffness = \"5 MN/m/m\", mass = \"800 kg/m\" }}",
                          _keys(what))
    _check_keys(table, IN_PLANE_KEYS, what, where, line)
    return InPlaneWalls(stiffness=_quantity(table, "stiffness", "N/m2", where, line, what),
                        mass=_quantity(table, "mass", "kg/m", where, line, what),
                        damping=_quantity(table, "damping", "1", where, line, what, DAMPING_DEFAULT))


def _storey(table, tie, where, line, k):
    what = f"storey {k}"
    if not isinstance(table, dict):
        raise where.error(line, f"{what}: expected a [[storey]] table")
    _check_keys(table, STOREY_KEYS, what, where, line)
    height = _quantity(table, "height", "m", where, line, what)
    if "wall" not in table:
        raise where.error(line, f'{what}.wall is missing: the storey\'s face-loaded wall, or wall = "{NO_WALL}" for a '
                                "storey without one (an open front)")
    if "diaphragm" not in table:
        raise where.error(line, f"{what}.diaphragm is missing")
    wall = _storey_wall(table, height, where, line, what)
    in_plane = _in_plane(table["in_plane"], where, line, f"{what}.in_plane") if "in_plane" in table else None
    return Storey(height=height, wall=wall, diaphragm=_diaphragm(table["diaphragm"], where, line, f"{what}.diaphragm"),
                  tie=_quantity(table, "tie", "N/m2", where, line, what, tie), in_plane=in_plane)


def _storey_wall(table, height, where, line, what):
    """The storey's face-loaded wall, or None for wall = "none": an open front (a shopfront on a
    beam or a frame), whose diaphragm is still there and which no wall above stands on."""
    if table["wall"] == NO_WALL:
        if "tie" in table:
            raise where.error(line, f"{what}: a storey without a wall has no tie to its diaphragm", ["tie"])
        return None
    wall = _wall(table["wall"], height, where, line, f"{what}.wall")
    if not wall.b < height:
        raise where.error(line, f"{what}: the wall's thickness b = {wall.b:g} m must be less than its height {height:g} m",
                          ["wall"])
    return wall


def parse(text, path="<building>"):
    """A Building from the text of a building file."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        found = re.search(r"line (\d+)", str(exc))
        raise BuildingFileError(f"{path}:{found.group(1) if found else 1}: not valid TOML: {exc}") from None
    where = _Where(path, text.splitlines())
    head = _table_lines(text, "building")
    head_line = head[0] if head else 1
    _check_keys(data, {"building", "storey"}, "the file", where, 1)
    building = data.get("building", {})
    if not isinstance(building, dict):
        raise where.error(head_line, "[building] must be a table")
    _check_keys(building, BUILDING_KEYS, "[building]", where, head_line)
    tie = _quantity(building, "tie", "N/m2", where, head_line, "building", TIE_DEFAULT)
    storeys = data.get("storey")
    lines = _table_lines(text, "storey")
    if not isinstance(storeys, list) or not storeys:
        raise where.error(head_line, "no [[storey]] tables: give the storeys, ground storey first")
    parsed = tuple(_storey(s, tie, where, lines[k] if k < len(lines) else head_line, k + 1)
                   for k, s in enumerate(storeys))
    try:
        result = Building(name=str(building.get("name", os.path.basename(path))), storeys=parsed, source=str(path))
    except ValueError as exc:
        raise where.error(head_line, str(exc)) from None
    _check_units(result, where, [lines[k] if k < len(lines) else head_line for k in range(len(parsed))])
    return result


def _check_units(building, where, storey_lines):
    """Each storey's wall as the model takes it (else an error) and its numbers as masonry buildings
    have them (else a PlausibilityWarning naming the line and the likely unit slip)."""
    for i, line in enumerate(storey_lines):
        error = file_checks.model_error(building, i)
        if error:
            raise where.error(line, error, ["wall"])
        for keys, message in file_checks.implausible(building, i):
            warnings.warn(f"{where.path}:{where.line_of(line, keys)}: storey {i + 1}: {message}", PlausibilityWarning,
                          stacklevel=4)


def read(path):
    """A Building from a building file (TOML); BuildingFileError naming the file and the line."""
    path = os.fspath(path)
    try:
        with open(path, "rb") as fh:
            raw = fh.read()
    except OSError as exc:
        raise BuildingFileError(f"{path}: {exc.strerror or exc}") from None
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise BuildingFileError(f"{path}:1: not UTF-8 text ({exc.reason} at byte {exc.start})") from None
    return parse(text, path)

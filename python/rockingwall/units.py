"""Quantities with explicit units: '30kN/m/m', '30 kN/m per m', '14.08 kN/m', '230 mm', '5 %' (a
ratio), or a bare number in the parameter's SI unit (the unit column of `rockingwall info`).

Every parameter has one SI unit (fmu_src/wall/rw_parameters.h); a value given with a unit is converted
to it here, and a unit of the wrong kind (kN/m for a stiffness per metre of wall) is an error."""
import math
import re

# SI unit of a parameter (as the model description writes it) -> accepted spellings and factors
_SPELLINGS = {
    "m": {"m": 1.0, "mm": 1e-3, "cm": 1e-2},
    "N/m": {"n/m": 1.0, "kn/m": 1e3, "mn/m": 1e6},
    "N/m2": {"n/m/m": 1.0, "kn/m/m": 1e3, "mn/m/m": 1e6, "n/mm/m": 1e3},
    "m/s2": {"m/s/s": 1.0},
    "rad/s": {"rad/s": 1.0},
    "kg/m": {"kg/m": 1.0, "t/m": 1e3},
    "N/m3": {"n/m3": 1.0, "kn/m3": 1e3},
    "g": {"g": 1.0, "m/s/s": 1.0 / 9.81},   # an acceleration as a fraction of g (the codes' hazard)
    "s": {"s": 1.0, "ms": 1e-3},
    "1": {"%": 1e-2},                      # a ratio as engineers write a damping ratio: '5 %'
}
_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def _canonical(unit):
    """'kN/m per m', 'kN/m2', 'kN/m^2', 'kN / m / m' -> 'kn/m/m'."""
    u = unit.lower().replace(" per ", "/").replace(" ", "").replace("^", "")
    return re.sub(r"/m2$", "/m/m", re.sub(r"/s2$", "/s/s", u))


def parse(value, si_unit, name="value"):
    """A float in `si_unit` from a number (taken as SI) or a string 'NUMBER [UNIT]'."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return _finite(float(value), value, name)
    m = _NUMBER.match(str(value))
    if not m:
        shown = str(value).lower() if isinstance(value, bool) else repr(value)  # a TOML or JSON true, as written
        raise ValueError(f"{name}: cannot read {shown} as a number with an optional unit")
    number, unit = _finite(float(m.group(1)), value, name), m.group(2)
    if not unit or _canonical(unit) == _canonical(si_unit or "1"):
        return number
    factors = _SPELLINGS.get(si_unit or "1", {})
    factor = factors.get(_canonical(unit))
    if factor is None:
        known = ", ".join(sorted({si_unit or "1", *[_display(k) for k in factors]})) if factors else si_unit or "none"
        raise ValueError(f"{name}: unit {unit!r} is not a unit of {name} (accepted: {known})")
    return number * factor


def _finite(number, text, name):
    """1e999 reads as infinity: no quantity of this program is infinite."""
    if not math.isfinite(number):
        raise ValueError(f"{name}: {text!r} is not a finite number")
    return number


def _display(spelling):
    return spelling.replace("kn", "kN").replace("mn", "MN").replace("n/", "N/")


def format_kd(kd):
    """K_d in N/m per m as engineers write it: '30 kN/m per m'."""
    if not math.isfinite(kd):
        return f"{kd} N/m per m"
    return f"{kd / 1e3:g} kN/m per m"


# The time histories' columns and their units as a column name carries them ('s1' -> 's1_m'), as
# the JSON's keys do ('peak_s1_m'): a CSV opened in a spreadsheet says what its numbers are.
HISTORY_UNITS = {"time": "s", "ag": "m_s2", "s1": "m", "s2": "m", "diaphragm": "m", "F_top": "N_per_m",
                 "floor_acc": "m_s2", "tie_force": "N_per_m"}


def history_column(name, storey=None):
    """A history's column name with its unit, and the storey (1-based) after it if given; a
    filtered history keeps its cut-off before the unit: ('s1', 2) -> 's1_m_2', 'time' -> 'time_s',
    ('floor_acc_25Hz', 1) -> 'floor_acc_25Hz_m_s2_1'."""
    quantity = re.sub(r"_\d+(?:\.\d+)?Hz$", "", name)
    column = f"{name}_{HISTORY_UNITS[quantity]}"
    return column if storey is None else f"{column}_{storey}"

"""What the code checks share: gravity, input validation, and how a formula's source is recorded.

Every check records, for each quantity it reports, the clause it comes from and how sure that is:
  read        the code's own text was read;
  secondary   an independent public account or implementation agrees (not the code's text);
  derived     worked out here from the statics or dynamics of the mechanism;
  unconfirmed the common reading of the method, not checked against the code's text.
Checks say in their notes which of their numbers rest on unconfirmed formulas."""
import dataclasses
import math

G = 9.81  # m/s^2, the value the rest of RockingWall uses
STATUSES = ("read", "secondary", "derived", "unconfirmed")
PASS, FAIL = "pass", "fail"


@dataclasses.dataclass(frozen=True)
class Ref:
    """Where a reported quantity comes from: the clause, and how sure (one of STATUSES)."""
    quantity: str
    clause: str
    status: str

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"Ref status must be one of {STATUSES}, not {self.status!r}")

    def __str__(self):
        return f"{self.quantity}: {self.clause} [{self.status}]"


def unconfirmed_notes(refs):
    """One note per unconfirmed formula, so no result hides one."""
    return tuple(f"UNCONFIRMED: {r.quantity} ({r.clause}) was not checked against the code's text"
                 for r in refs if r.status == "unconfirmed")


def number(name, value, low, high, unit, low_open=False, high_open=False):
    """`value` as a float, or a ValueError naming `name`, its value and the allowed range."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ValueError(f"{name}: expected a number in {unit}, got {value!r}")
    value = float(value)
    too_low = value <= low if low_open else value < low
    too_high = value >= high if high_open else value > high
    if not math.isfinite(value) or too_low or too_high:
        left, right = "(" if low_open else "[", ")" if high_open else "]"
        raise ValueError(f"{name} = {value:g} {unit} is outside the allowed range {left}{low:g}, {high:g}{right} {unit}")
    return value


def choice(name, value, allowed):
    """`value` if it is one of `allowed` (compared without case for strings), else a ValueError."""
    for option in allowed:
        if value == option or (isinstance(value, str) and value.upper() == str(option).upper()):
            return option
    raise ValueError(f"{name} = {value!r} is not one of {', '.join(map(str, allowed))}")


def verdict(capacity, demand):
    return PASS if capacity >= demand else FAIL

"""What the record-format readers share: reading a file's lines, numbers and fixed-width Fortran
fields with the file and line in every error, acceleration units, the checks of a header against
the samples, and the choice of a component."""
import math
import os
import re
import stat

import numpy as np

from .types import G_STD, RecordError

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?"

# acceleration units as the formats write them (lower case, blanks removed) -> m/s^2
UNITS = {"cm/s^2": 0.01, "cm/s2": 0.01, "cm/s/s": 0.01, "cm/sec2": 0.01, "cm/sec^2": 0.01, "cm/sec/sec": 0.01,
         "gal": 0.01, "mm/s^2": 1e-3, "mm/s2": 1e-3, "mm/s/s": 1e-3, "m/s^2": 1.0, "m/s2": 1.0, "m/s/s": 1.0,
         "g": G_STD}


def unit_factor(text, path, lineno):
    """m/s^2 per unit of `text` ('cm/s^2', 'mm/s/s', 'g', ...); anything else is refused."""
    key = re.sub(r"\s+", "", text).lower().rstrip(".")
    if key not in UNITS:
        raise RecordError(f"{path}:{lineno}: acceleration units {text.strip()!r} are not ones this reader "
                          f"converts ({', '.join(sorted(UNITS))})")
    return UNITS[key]


def is_regular_file(path):
    """True for a regular file (symlinks followed): what may be opened without blocking."""
    try:
        return stat.S_ISREG(os.stat(path).st_mode)
    except (OSError, ValueError):
        return False


def text_of(data):
    """Bytes as text: latin-1, so that any byte reads (the numbers and keys are ASCII), without the
    UTF-8 byte-order mark an editor may have put first; UTF-16 when it starts with its byte-order
    mark (a spreadsheet's 'Unicode text')."""
    if data[:2] in (b"\xff\xfe", b"\xfe\xff"):
        return data.decode("utf-16", errors="replace")
    return (data[3:] if data.startswith(b"\xef\xbb\xbf") else data).decode("latin-1")


def head(path, size=4096):
    """The first `size` bytes of a regular file as text ('' for anything else): enough to
    recognise a format, and never blocks on a FIFO or a device."""
    if not is_regular_file(path):
        return ""
    try:
        with open(path, "rb") as f:
            return text_of(f.read(size))
    except OSError:
        return ""


def lines_of(path):
    """The file's lines."""
    try:
        with open(path, "rb") as f:
            return text_of(f.read()).splitlines()
    except OSError as exc:
        raise RecordError(f"{path}: {exc.strerror or exc}") from None


def number(token, path, lineno, what="a number"):
    """A finite float from a token (Fortran 'D' exponents accepted)."""
    try:
        value = float(token.strip().replace("D", "E").replace("d", "e"))
    except ValueError:
        raise RecordError(f"{path}:{lineno}: cannot read {token.strip()!r} as {what}") from None
    if not math.isfinite(value):
        raise RecordError(f"{path}:{lineno}: non-finite value {token.strip()!r}")
    return value


def positive(value, name, path, lineno):
    if not value > 0:
        raise RecordError(f"{path}:{lineno}: {name} must be positive, the file says {value:g}")
    return value


def count(token, name, path, lineno):
    """A positive whole number from a token (a sample count)."""
    value = number(token, path, lineno, name)
    if value != int(value) or value <= 0:
        raise RecordError(f"{path}:{lineno}: {name} must be a positive whole number, the file says {token.strip()!r}")
    return int(value)


def fixed_fields(line, width, path, lineno):
    """The numbers of a line of Fortran fixed-width fields (10F8.1, 8F10.5, ...): read by column,
    since full fields touch ('-11024.7-9733.1'); the line ends after its last number."""
    text = line.rstrip()
    fields = [text[i:i + width] for i in range(0, len(text), width)]
    if not all(f.strip() for f in fields):
        raise RecordError(f"{path}:{lineno}: a blank {width}-character field among the numbers")
    return [number(f, path, lineno) for f in fields]


def fixed_block(lines, first, n_values, per_line, width, path):
    """n_values numbers written per_line to a line from line index `first` (0-based): returns the
    values and the index of the line after the block."""
    n_lines = math.ceil(n_values / per_line)
    if first + n_lines > len(lines):
        raise RecordError(f"{path}:{len(lines)}: the file ends inside a block of {n_values} values "
                          f"({n_lines} lines from line {first + 1})")
    values = []
    for i in range(first, first + n_lines):
        values += fixed_fields(lines[i], width, path, i + 1)
    if len(values) != n_values:
        raise RecordError(f"{path}:{first + n_lines}: the header announces {n_values} values, the "
                          f"{n_lines} lines from line {first + 1} hold {len(values)}")
    return np.array(values), first + n_lines


def last_digit(token):
    """One unit of the last printed digit of a number ('95.640' -> 0.001, '102' -> 1)."""
    mantissa = re.split(r"[EeDd]", token.strip())[0]
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    exponent = int(re.split(r"[EeDd]", token.strip())[1]) if re.search(r"[EeDd]", token.strip()) else 0
    return 10.0 ** (exponent - decimals)


def agrees(value, token, slack=1.0):
    """`value` equals the printed number `token` to `slack` units of its last printed digit."""
    printed = float(token.replace("D", "E").replace("d", "e"))
    return abs(value - printed) <= slack * last_digit(token) + 1e-9 * max(abs(printed), 1.0)


def choose(components, component, path):
    """The index of the chosen component: None is the first; else a name as the file writes it
    (case and '-' ignored: 'ew' is 'E-W') or a position 1, 2, ... in the file."""
    if component is None:
        return 0
    wanted = str(component).strip()
    key = wanted.replace("-", "").lower()
    for i, name in enumerate(components):
        if name.replace("-", "").lower() == key:
            return i
    if wanted.isdigit() and 1 <= int(wanted) <= len(components):
        return int(wanted) - 1
    listed = ", ".join(f"{i + 1} = {name}" for i, name in enumerate(components))
    raise RecordError(f"{path}: no component {wanted!r} in this file; it has {listed}")


def free_values(lines, first, path):
    """Every blank-separated number from line index `first` (0-based) to the end."""
    values = []
    for lineno, line in enumerate(lines[first:], first + 1):
        values += [number(tok, path, lineno) for tok in line.replace(",", " ").split()]
    return np.array(values)


def check_count(found, announced, path, header_line, what="values"):
    """The samples found against the count the header announces (at header_line)."""
    if found != announced:
        raise RecordError(f"{path}:{header_line}: the header announces {announced} {what}, the file holds {found}")


def check_numbers_only(lines, first, n_values, per_line, path, announced_at):
    """The lines a block of n_values numbers will take (from index `first`) hold numbers only: a
    count too large, or lines missing, would otherwise read the next header as numbers."""
    for i in range(first, min(first + math.ceil(n_values / per_line), len(lines))):
        if re.search(r"[A-CF-Za-cf-z]", lines[i]):
            raise RecordError(f"{path}:{i + 1}: text where the {n_values} values announced on line {announced_at} "
                              f"should be: the count is wrong or lines are missing")

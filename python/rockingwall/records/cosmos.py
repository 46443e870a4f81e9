"""COSMOS strong-motion format v01.20 (the COSMOS Virtual Data Center, CESMD; USA), volumes 1 and
2 (uncorrected and corrected acceleration): per channel a text header whose first line says how
many text lines it has, integer and real headers whose first lines give their count and Fortran
format, comment lines, then the accelerations after a line 'N acceleration pts, approx S secs,
units=cm/sec2(04), Format=(8F10.5)' (V2 files then carry velocity and displacement). Real 62
is the time step in ms, real 63 the series' length N x dt [s]. Raw counts (volume 0) are refused."""
import pathlib
import re

import numpy as np

from .types import RecordError
from .format_common import NUMBER, check_numbers_only, choose, count, fixed_block, lines_of, positive, unit_factor

NAME = "COSMOS V1/V2"
FIRST_LINE = re.compile(r"\(Format\s+v\s*[\d.]+\s+with\s+(\d+)\s+text\s+lines\)", re.I)
HEADER = r"^\s*(\d+)\s+{}-header values follow on\s+(\d+)\s+lines\s*,\s*Format\s*=\s*\(\s*(\d+)\s*[A-Za-z](\d+)"
DATA = re.compile(r"^\s*(\d+)\s+(.*?)\s+pts,\s*approx\s+(" + NUMBER + r")\s+secs?,"
                  r"\s*units\s*=\s*(.*?)\s*\(\s*(\d+)\s*\)\s*,?\s*Format\s*=\s*\(\s*(\d+)\s*[A-Za-z](\d+)", re.I)
UNIT_CODES = {2: "g", 4: "cm/s^2"}  # the acceleration units of the format's table of physical units


def recognise(head):
    return bool(FIRST_LINE.search(head.split("\n", 1)[0]))


def read(path, component=None):
    """(t [s] from 0, ag [m/s^2], name, meta) of one channel of a COSMOS file: the first unless
    `component` gives another's position (1, 2, ...)."""
    path = str(path)
    lines = lines_of(path)
    starts = [i for i, line in enumerate(lines) if FIRST_LINE.search(line)]
    if not starts or starts[0] != 0:
        raise RecordError(f"{path}:1: expected a COSMOS first line '... (Format v01.20 with 13 text lines)'")
    names = [str(k + 1) for k in range(len(starts))]
    k = choose(names, component, path)
    t, ag, meta = read_channel(lines, starts[k], path)
    meta.update(component=names[k], components=names)
    name = pathlib.Path(path).stem + (f" chan {names[k]}" if len(starts) > 1 else "")
    return t, ag, name, meta


def read_header(lines, i, label, path):
    """(the values of the integer or real header whose count line is at index i, index after it)."""
    m = re.match(HEADER.format(label), lines[i] if i < len(lines) else "", re.I)
    if not m:
        raise RecordError(f"{path}:{i + 1}: expected 'N {label}-header values follow on M lines, Format= (...)'")
    n, n_lines, per_line, width = (int(g) for g in m.groups())
    values, after = fixed_block(lines, i + 1, n, per_line, width, path)
    if after != i + 1 + n_lines:
        raise RecordError(f"{path}:{i + 1}: {n} values {per_line} to a line take {after - i - 1} lines, not {n_lines}")
    return values, after


def read_channel(lines, start, path):
    n_text = int(FIRST_LINE.search(lines[start]).group(1))
    if "raw" in lines[start][:25].lower():
        raise RecordError(f"{path}:{start + 1}: raw counts (volume 0) are not read: give the V1 or V2 file")
    unknown = re.search(r"unspecified:\s*" + NUMBER + r"\s*,\s*(" + NUMBER + ")", lines[start + n_text - 1])
    null = float(unknown.group(1)) if unknown else -999.0
    _, i = read_header(lines, start + n_text, "Integer", path)
    reals_at = i
    reals, i = read_header(lines, i, "Real", path)
    m = re.match(r"^\s*(\d+)\s+Comment line", lines[i] if i < len(lines) else "", re.I)
    if not m:
        raise RecordError(f"{path}:{i + 1}: expected 'N Comment line(s) follow'")
    i += 1 + int(m.group(1))
    m = DATA.match(lines[i] if i < len(lines) else "")
    if not m:
        raise RecordError(f"{path}:{i + 1}: expected 'N acceleration pts, approx S secs, units=..(NN), Format=(..)'")
    n = count(m.group(1), "the number of points", path, i + 1)
    factor = units(m, path, i + 1)
    if len(reals) < 63 or reals[61] == null:
        raise RecordError(f"{path}:{reals_at + 1}: the real header gives no time step (real 62, in ms)")
    dt = positive(float(reals[61]) / 1000, "real 62 (the time step)", path, reals_at + 1)
    per_line = int(m.group(6))
    check_numbers_only(lines, i + 1, n, per_line, path, i + 1)
    acc, after = fixed_block(lines, i + 1, n, per_line, int(m.group(7)), path)
    if after < len(lines) and re.match(r"^\s*[-+.\d]", lines[after]) and not DATA.match(lines[after]):
        raise RecordError(f"{path}:{after + 1}: more values than the {n} announced on line {i + 1}")
    check_length(n, dt, reals[62], null, float(m.group(3)), path, reals_at, i)
    meta = dict(format=NAME, source=path, dt=dt, npts=n, units=UNIT_CODES[int(m.group(5))],
                kind=lines[start][:25].strip(), station=lines[start + 4].strip() if n_text > 4 else "")
    return np.arange(n) * dt, acc * factor, meta


def units(m, path, lineno):
    """m/s^2 per unit of the data line's units, whose code and text must agree."""
    if "accel" not in m.group(2).lower():
        raise RecordError(f"{path}:{lineno}: the series is {m.group(2).strip()!r}, not acceleration")
    code = int(m.group(5))
    if code not in UNIT_CODES:
        raise RecordError(f"{path}:{lineno}: units code {code:02d} ({m.group(4).strip()}) is not read: "
                          "only accelerations in g (02) or cm/sec2 (04)")
    factor = unit_factor(m.group(4), path, lineno)
    if factor != unit_factor(UNIT_CODES[code], path, lineno):
        raise RecordError(f"{path}:{lineno}: the units {m.group(4).strip()!r} contradict their code ({code:02d})")
    return factor


def check_length(n, dt, length, null, approx, path, reals_at, data_at):
    """Real 63 (the series' length, N x dt; (N - 1) x dt is accepted) and the data line's
    'approx S secs' against N points every real 62: a wrong time step is refused."""
    if length != null and not min(abs(length - n * dt), abs(length - (n - 1) * dt)) <= 1e-6 * max(length, 1.0):
        raise RecordError(f"{path}:{reals_at + 1}: {n} points every {dt:g} s (real 62) last {n * dt:g} s, but real 63 "
                          f"says {length:g} s")
    if abs(approx - n * dt) > 1.0 + dt:
        raise RecordError(f"{path}:{data_at + 1}: {n} points every {dt:g} s (real 62) last {n * dt:g} s, not "
                          f"approx {approx:g} s")

"""GeoNet (GNS Science, New Zealand) V1A and V2A accelerograms: three components in one file, one
block each: 16 text lines, 40 integers (10I8), 60 reals (10F8), then the accelerations in mm/s^2,
10 to a line in 8-character fields (V2A: then the velocities and displacements). Integer 34 is the
number of accelerations (35, 36 of velocities and displacements), real 26 the time step [s]."""
import pathlib
import re

import numpy as np

from .types import RecordError
from .format_common import NUMBER, agrees, check_numbers_only, choose, fixed_block, lines_of, positive

NAME = "GeoNet V1A/V2A"
TEXT_LINES, INT_LINES, REAL_LINES, PER_LINE, WIDTH = 16, 4, 6, 10, 8


def recognise(head):
    first = head.split("\n", 1)[0].lower()
    return "accelerogram" in first and "gns" in first


def read(path, component=None):
    """(t [s] from 0, ag [m/s^2], name, meta) of one component of a GeoNet V1A/V2A file: the
    first in the file (the longitudinal axis) unless `component` names another ('S74E', 'Up')
    or gives its position (1, 2, 3)."""
    path = str(path)
    lines = lines_of(path)
    blocks, start = [], 0
    while start < len(lines) and lines[start].strip():
        block, start = read_block(lines, start, path)
        blocks.append(block)
        while start < len(lines) and not lines[start].strip():
            start += 1
    if start < len(lines) or not blocks:
        raise RecordError(f"{path}:{start + 1}: expected a component's header here")
    names = [b["component"] or str(k + 1) for k, b in enumerate(blocks)]
    k = choose(names, component, path)
    chosen = blocks[k]
    meta = dict(format=NAME, source=path, component=names[k], components=names, dt=chosen["dt"],
                npts=chosen["npts"], units="mm/s/s", corrected=chosen["corrected"], station=chosen["station"])
    return (np.arange(chosen["npts"]) * chosen["dt"], chosen["acc"] * 1e-3,
            f"{pathlib.Path(path).stem} {meta['component']}", meta)


def read_block(lines, start, path):
    """One component's block from line index `start`: its samples and what its header says;
    returns (block, index of the line after it)."""
    text = lines[start:start + TEXT_LINES]
    if not recognise(text[0]):
        raise RecordError(f"{path}:{start + 1}: expected a component's first line ('... accelerogram ... GNS "
                          f"Science'), found {text[0][:60]!r}")
    ints, i = fixed_block(lines, start + TEXT_LINES, 10 * INT_LINES, PER_LINE, WIDTH, path)
    reals, i = fixed_block(lines, i, 10 * REAL_LINES, PER_LINE, WIDTH, path)
    n_acc, n_vel, n_dis = (int(v) for v in ints[33:36])
    ints_line, reals_line = start + TEXT_LINES + 4, start + TEXT_LINES + INT_LINES + 3
    if n_acc <= 0:
        raise RecordError(f"{path}:{ints_line}: integer 34 (the number of accelerations) is {n_acc}")
    dt = positive(float(reals[25]), "real 26 (the time step)", path, reals_line)
    check_numbers_only(lines, i, sum(rows(n) for n in (n_acc, n_vel, n_dis)) * PER_LINE, PER_LINE, path, ints_line)
    acc, i = fixed_block(lines, i, n_acc, PER_LINE, WIDTH, path)
    for n in (n_vel, n_dis):  # the V2A's velocities and displacements, not used
        if n > 0:
            _, i = fixed_block(lines, i, n, PER_LINE, WIDTH, path)
    if i < len(lines) and lines[i].strip() and not recognise(lines[i]):
        raise RecordError(f"{path}:{i + 1}: more values than integers 34-36 (line {ints_line}) announce "
                          f"({n_acc}, {n_vel}, {n_dis}): this line should start the next component")
    corrected = not text[0].lower().lstrip().startswith("uncorrected")
    check_text(text, start, n_acc, dt, acc, corrected, path)
    component = (text[12].split() + ["", ""])[1]  # 'Component S16W  Longitudinal Accelerometer Axis'
    return dict(component=component, npts=n_acc, dt=dt, acc=acc, corrected=corrected,
                station=(text[1].split() + ["", ""])[1]), i


def rows(n):
    """Lines that n values take, 10 to a line."""
    return -(-max(n, 0) // PER_LINE)


def check_text(text, start, n, dt, acc, corrected, path):
    """The text header says the count, duration, time step, units and (V2A) peak again: each that
    is there must agree with the numeric header and the samples."""
    line = start + 10  # 'Number of points  5800    Duration 115.98 sec'
    m = re.search(rf"Number of points\s+(\d+)\s+Duration\s+({NUMBER})", text[9])
    if m and int(m.group(1)) != n:
        raise RecordError(f"{path}:{line}: the text says {m.group(1)} points, integer 34 (line {start + 20}) {n}")
    if m and not agrees((n - 1) * dt, m.group(2)):
        raise RecordError(f"{path}:{line}: {n} points every {dt:g} s (real 26, line {start + 23}) last "
                          f"{(n - 1) * dt:g} s, but the text says a duration of {m.group(2)} s")
    m = re.search(rf"(?:at|intervals of)\s+({NUMBER})\s+s(?:ec)?\b", text[10])
    if m and not agrees(dt, m.group(1)):
        raise RecordError(f"{path}:{start + 11}: the text gives a time step of {m.group(1)} s, real 26 "
                          f"(line {start + 23}) {dt:g} s")
    m = re.search(rf"units of\s+({NUMBER})\s+(\S+)", text[10])
    if m and (float(m.group(1)) != 1.0 or m.group(2) != "mm/s/s"):
        raise RecordError(f"{path}:{start + 11}: readings in units of {m.group(1)} {m.group(2)}: only 1.00 mm/s/s "
                          "is read")
    m = re.search(rf"Acceleration:\s+peak\s+({NUMBER})\s+(\S+)", text[13], re.I)
    if corrected and m:
        peak = float(np.max(np.abs(acc)))
        if m.group(2) != "mm/s/s" or not agrees(peak, m.group(1).lstrip("+-")):
            raise RecordError(f"{path}:{start + 14}: the text gives a peak of {m.group(1)} {m.group(2)}, the "
                              f"samples {peak:g} mm/s/s")

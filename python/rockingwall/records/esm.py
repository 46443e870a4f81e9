"""ESM ASCII, the format of the Engineering Strong-Motion database (Europe) and of ITACA (Italy):
'KEY: value' header lines (64 in the DYNA 1.2 header, EVENT_NAME first), then the samples, one
per line, in the header's UNITS (cm/s^2), every SAMPLING_INTERVAL_S seconds, NDATA of them."""
import pathlib

import numpy as np

from .types import RecordError
from .format_common import agrees, check_count, choose, count, free_values, lines_of, number, positive, unit_factor

NAME = "ESM ASCII"


def recognise(head):
    return head.startswith("EVENT_NAME:")


def header(lines, path):
    """{KEY: (value, line number)} of the leading 'KEY: value' lines, and the index of the first
    data line."""
    keys = {}
    for i, line in enumerate(lines):
        key, colon, value = line.partition(":")
        if not colon:
            return keys, i
        keys[key.strip()] = (value.strip(), i + 1)
    raise RecordError(f"{path}:{len(lines)}: the file ends inside its header: no samples")


def field(keys, key, path, end):
    if key not in keys or not keys[key][0]:
        raise RecordError(f"{path}:{end}: the header (lines 1-{end}) gives no {key}")
    return keys[key]


def read(path, component=None):
    """(t [s] from 0, ag [m/s^2], name, meta) of an ESM ASCII file."""
    path = str(path)
    lines = lines_of(path)
    keys, first = header(lines, path)
    kind, kind_line = keys.get("DATA_TYPE", ("ACCELERATION", 0))
    if kind.upper() != "ACCELERATION":
        raise RecordError(f"{path}:{kind_line}: DATA_TYPE is {kind!r}: only ACCELERATION records are read")
    units, units_line = field(keys, "UNITS", path, first)
    factor = unit_factor(units, path, units_line)
    n_text, n_line = field(keys, "NDATA", path, first)
    dt_text, dt_line = field(keys, "SAMPLING_INTERVAL_S", path, first)
    n = count(n_text, "NDATA", path, n_line)
    dt = positive(number(dt_text, path, dt_line), "SAMPLING_INTERVAL_S", path, dt_line)
    values = free_values(lines, first, path)
    check_count(values.size, n, path, n_line, "samples (NDATA)")
    check_duration(keys, n, dt, path, dt_line)
    check_peak(keys, values, path)
    stream = keys.get("STREAM", ("", 0))[0] or "1"
    choose([stream], component, path)
    stem = pathlib.Path(path).stem
    meta = dict(format=NAME, source=path, component=stream, components=[stream], dt=dt, npts=n, units=units,
                event=keys.get("EVENT_NAME", ("", 0))[0], station=keys.get("STATION_CODE", ("", 0))[0])
    return np.arange(n) * dt, values * factor, f"{stem} {stream}", meta


def check_duration(keys, n, dt, path, dt_line):
    """DURATION_S is NDATA x SAMPLING_INTERVAL_S in the database's files; (NDATA - 1) x dt is
    accepted too. A disagreement means one of the two is wrong: refused."""
    text, line = keys.get("DURATION_S", ("", 0))
    if text and not (agrees(n * dt, text) or agrees((n - 1) * dt, text)):
        raise RecordError(f"{path}:{dt_line}: SAMPLING_INTERVAL_S = {dt:g} s and NDATA = {n} give "
                          f"{n * dt:g} s, but DURATION_S (line {line}) is {text} s")


def check_peak(keys, values, path):
    """PGA_CM/S^2 is the largest |sample| of the file (signed, as printed): a check that every
    sample was read where the header says. Compared only when the samples are in cm/s^2."""
    text, line = keys.get("PGA_CM/S^2", ("", 0))
    units = keys.get("UNITS", ("", 0))[0].replace(" ", "").lower()
    if text and units in ("cm/s^2", "cm/s2") and values.size:
        peak = float(np.max(np.abs(values)))
        if not agrees(peak, text.lstrip("+-")):
            raise RecordError(f"{path}:{line}: PGA_CM/S^2 is {text}, but the largest |sample| is {peak:g}")

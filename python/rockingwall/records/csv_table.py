"""Two-column CSV records: time [s] and acceleration (in g or m/s^2)."""
import codecs
import os
import pathlib
import re

import numpy as np

from .types import FLOAT, G_STD, Record, RecordError, number

CSV_UNITS = {"g": G_STD, "m/s2": 1.0, "cm/s2": 0.01}  # the accelerations' unit -> m/s^2 (g: of g=G_STD)


def read_csv(path, units="g", g=G_STD):
    """Two columns, time [s] and acceleration (comma, semicolon, tab or blank separated); '#'
    lines and one header line are skipped. units: 'g', 'm/s2' or 'cm/s2' (gal)."""
    if units not in CSV_UNITS:
        raise ValueError(f"units must be one of {', '.join(CSV_UNITS)}, got {units!r}")
    path = os.fspath(path)
    times, accs = [], []
    for lineno, line in enumerate(text_lines(path), 1):
        tokens = [x for x in re.split(r"[,;\s]+", line.strip()) if x]
        if not tokens or tokens[0].startswith("#"):
            continue
        if not times and not re.fullmatch(FLOAT, tokens[0]):
            continue  # the header line
        if len(tokens) != 2:
            raise RecordError(f"{path}:{lineno}: expected 2 columns (time, acceleration), found {len(tokens)}")
        t, a = number(tokens[0], path, lineno), number(tokens[1], path, lineno)
        if times and t <= times[-1]:
            raise RecordError(f"{path}:{lineno}: time {t} is not after the previous one ({times[-1]})")
        times.append(t)
        accs.append(a)
    if len(times) < 2:
        raise RecordError(f"{path}: need at least 2 rows of numbers, found {len(times)}")
    factor = g if units == "g" else CSV_UNITS[units]
    return Record(pathlib.Path(path).stem, np.array(times), np.array(accs) * factor, source=path)


def text_lines(path):
    """The lines of a text file in UTF-8 (a BOM allowed) or UTF-16 with its BOM (what spreadsheets
    save as 'Unicode text'); anything else is a RecordError naming the file and line."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as exc:
        raise RecordError(f"{path}: {exc.strerror or exc}") from None
    encoding = "utf-16" if data[:2] in (codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE) else "utf-8-sig"
    try:
        text = data.decode(encoding)
    except UnicodeDecodeError as exc:
        lineno = data[:exc.start].count(b"\n") + 1 if encoding != "utf-16" else 1
        raise RecordError(f"{path}:{lineno}: not UTF-8 (or UTF-16 with a byte-order mark) text: byte "
                          f"0x{data[exc.start]:02x} cannot be decoded; save the file as UTF-8") from None
    return text.replace("\r\n", "\n").replace("\r", "\n").split("\n")

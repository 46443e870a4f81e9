"""PEER NGA `.AT2` files: 4 header lines (the 3rd says the values are in g, the 4th gives NPTS
and DT), then the values in g."""
import os
import pathlib
import re

import numpy as np

from .types import FLOAT, G_STD, Record, RecordError, number

def at2_header(line, path="AT2", lineno=4):
    """NPTS and DT from an AT2 file's 4th header line, in both NGA layouts:
    'NPTS=  2688, DT=  .0100 SEC' and the old '2688  .0100  NPTS, DT'."""
    m_n = re.search(r"NPTS\s*=\s*(\d+)", line, re.I)
    m_dt = re.search(r"DT\s*=\s*(" + FLOAT + ")", line, re.I)
    if m_n and m_dt:
        npts, dt = int(m_n.group(1)), number(m_dt.group(1), path, lineno)
    else:
        tokens = re.split(r"[,\s]+", line.strip())
        try:
            npts, dt = int(tokens[0]), number(tokens[1], path, lineno)
        except (ValueError, IndexError):
            raise RecordError(f"{path}:{lineno}: expected 'NPTS= N, DT= dt SEC', found {line.strip()[:200]!r}") from None
    if npts <= 0 or not dt > 0:
        raise RecordError(f"{path}:{lineno}: need NPTS > 0 and DT > 0, got NPTS={npts}, DT={dt}")
    return npts, dt


def read_at2(path, g=G_STD):
    """A PEER NGA .AT2 file: 4 header lines (the 3rd says the values are in g, the 4th gives NPTS
    and DT), then the values in g. Time starts at 0. Returns a Record in m/s^2."""
    path = os.fspath(path)
    try:
        with open(path, encoding="latin-1") as fh:
            lines = fh.read().splitlines()
    except OSError as exc:
        raise RecordError(f"{path}: {exc.strerror or exc}") from None
    if len(lines) < 4:
        raise RecordError(f"{path}:{len(lines) + 1}: file ends inside the 4-line AT2 header")
    if not re.search(r"\bG\b", lines[2].upper()):
        raise RecordError(f"{path}:3: expected the units line to say the values are in G, got {lines[2].strip()!r}")
    npts, dt = at2_header(lines[3], path)
    values = [number(tok, path, lineno) for lineno, line in enumerate(lines[4:], 5)
              for tok in line.replace(",", " ").split()]
    if len(values) != npts:
        raise RecordError(f"{path}:{len(lines)}: the header (line 4) announces NPTS={npts} "
                          f"but the file has {len(values)} values")
    return Record(pathlib.Path(path).stem, np.arange(npts) * dt, np.array(values) * g, source=path)



"""K-NET and KiK-net ASCII (NIED, Japan): 17 header lines of an 18-character label and a value,
from 'Origin Time' to 'Memo.', then the samples as counts, 8 to a line. One component per file.
Counts times the 'Scale Factor' (num(gal)/denom) are gal; NIED's 'Max. Acc. (gal)' is the peak
after the record's mean is removed, so the mean is removed here too."""
import pathlib
import re

import numpy as np

from .types import RecordError
from .format_common import NUMBER, agrees, choose, free_values, lines_of, number, positive

NAME = "K-NET/KiK-net ASCII"
LABELS = ["Origin Time", "Lat.", "Long.", "Depth. (km)", "Mag.", "Station Code", "Station Lat.", "Station Long.",
          "Station Height(m)", "Record Time", "Sampling Freq(Hz)", "Duration Time(s)", "Dir.", "Scale Factor",
          "Max. Acc. (gal)", "Last Correction", "Memo."]
KIKNET_DIRECTIONS = {"1": "NS1", "2": "EW1", "3": "UD1", "4": "NS2", "5": "EW2", "6": "UD2"}  # 1-3 borehole


def recognise(head):
    return head.startswith("Origin Time")


def header(lines, path):
    """{label: value} of the 17 header lines, each label checked in its place."""
    if len(lines) < len(LABELS):
        raise RecordError(f"{path}:{len(lines)}: the file ends inside the 17-line header")
    values = {}
    for i, label in enumerate(LABELS):
        if not lines[i].startswith(label):
            raise RecordError(f"{path}:{i + 1}: expected the header line {label!r}, found {lines[i][:40]!r}")
        values[label] = lines[i][len(label):].strip()
    return values


def scale_factor(text, path):
    """gal per count from 'num(gal)/denom'."""
    m = re.fullmatch(rf"({NUMBER})\s*\(gal\)\s*/\s*({NUMBER})", text)
    if not m:
        raise RecordError(f"{path}:14: expected the Scale Factor as 'num(gal)/denom', found {text!r}")
    return number(m.group(1), path, 14) / positive(number(m.group(2), path, 14), "the Scale Factor's denominator",
                                                   path, 14)


def sampling(values, path):
    """(dt [s], the number of samples the header implies): Duration Time x Sampling Freq."""
    m = re.fullmatch(rf"({NUMBER})\s*(?:Hz)?", values["Sampling Freq(Hz)"], re.I)
    if not m:
        raise RecordError(f"{path}:11: cannot read the sampling frequency {values['Sampling Freq(Hz)']!r}")
    freq = positive(number(m.group(1), path, 11), "Sampling Freq", path, 11)
    duration = positive(number(values["Duration Time(s)"], path, 12), "Duration Time", path, 12)
    n = duration * freq
    if abs(n - round(n)) > 1e-6 * n:
        raise RecordError(f"{path}:12: Duration Time {duration:g} s at {freq:g} Hz is not a whole number of samples")
    return 1.0 / freq, int(round(n))


def read(path, component=None):
    """(t [s] from 0, ag [m/s^2] with the mean removed, name, meta) of a K-NET/KiK-net file."""
    path = str(path)
    lines = lines_of(path)
    values = header(lines, path)
    dt, n = sampling(values, path)
    counts = free_values(lines, len(LABELS), path)
    if counts.size != n:
        raise RecordError(f"{path}:12: Duration Time x Sampling Freq (lines 11-12) make {n} samples, "
                          f"the file holds {counts.size}")
    gal = counts * scale_factor(values["Scale Factor"], path)
    gal -= gal.mean()
    check_peak(values["Max. Acc. (gal)"], gal, path)
    direction = values["Dir."].strip()
    name = KIKNET_DIRECTIONS.get(direction, direction.replace("-", ""))
    choose([name], component, path)
    meta = dict(format=NAME, source=path, component=name, components=[name], dt=dt, npts=n, units="gal",
                station=values["Station Code"], origin_time_jst=values["Origin Time"], mean_removed=True)
    return np.arange(n) * dt, gal * 0.01, f"{pathlib.Path(path).stem} {name}", meta


def check_peak(text, gal, path):
    """'Max. Acc. (gal)' is the peak |acceleration| after the mean is removed (so in NIED's files):
    a check of the scale factor and of every sample."""
    peak = float(np.max(np.abs(gal))) if gal.size else 0.0
    number(text, path, 15)
    if not agrees(peak, text):
        raise RecordError(f"{path}:15: Max. Acc. is {text} gal, but the samples (counts x Scale Factor, mean "
                          f"removed) peak at {peak:.4g} gal")

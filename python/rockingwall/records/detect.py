"""The record formats engineers download besides PEER AT2 and CSV, recognised by their content:
ESM ASCII (Europe, Italy), GeoNet V1A/V2A (New Zealand), K-NET/KiK-net ASCII (Japan) and COSMOS
V1/V2 (USA). Each reader returns (t [s] from 0, ag [m/s^2], name, meta), its count and time step
checked against the file's header; `detect_format` names a file's format or says which are read."""
import os
import re

from . import cosmos, esm, geonet, knet
from . import format_common as common
from .csv_table import read_csv
from .peer import read_at2
from .types import Record, RecordError

READERS = {"esm": esm, "geonet": geonet, "knet": knet, "cosmos": cosmos}
READ = ("PEER NGA AT2, two-column CSV, ESM ASCII, GeoNet V1A/V2A, K-NET/KiK-net ASCII and COSMOS V1/V2 "
        "(v01.20)")


def recognise(path):
    """'esm', 'geonet', 'knet' or 'cosmos' from the file's first bytes; None for anything else
    (and for what is not a regular file, which is never opened)."""
    head = common.head(path)
    return next((key for key, reader in READERS.items() if reader.recognise(head)), None)


def detect_format(path):
    """The format of a record file from its content, whatever its name: 'esm', 'geonet', 'knet',
    'cosmos', 'at2' or 'csv'. Anything else is a RecordError listing the formats read."""
    path = os.fspath(path)
    found = recognise(path) or looks_like_at2(path) or looks_like_csv(path)
    if found:
        return found
    if not os.path.exists(path):
        raise RecordError(f"{path}: not a record: no such file; give a record file ({READ}), 'elcentro' or "
                          "'gaussian[:D,T]'")
    if not common.is_regular_file(path):
        raise RecordError(f"{path}: not a record: not a regular file")
    raise RecordError(f"{path}:1: not a record in a format this program reads ({READ})")


def looks_like_at2(path):
    """An NGA AT2 header: the units line (3rd) says G, the 4th gives NPTS and DT."""
    lines = common.head(path).splitlines()
    ok = (len(lines) > 4 and re.search(r"\bG\b", lines[2].upper()) is not None
          and all(k in lines[3].upper() for k in ("NPTS", "DT")))
    return "at2" if ok else None


def looks_like_csv(path):
    """Two numbers on the first line that is not blank, a '#' comment or the one header line."""
    rows = [ln for ln in common.head(path).splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    for row in rows[:2]:
        tokens = [x for x in re.split(r"[,;\s]+", row.strip()) if x]
        if all(re.fullmatch(common.NUMBER, tok) for tok in tokens):
            return "csv" if len(tokens) == 2 else None
    return None


def read(path, component=None):
    """(t, ag [m/s^2], name, meta) of an ESM, GeoNet, K-NET or COSMOS file, the format found from
    the content. component: a name as the file writes it ('S74E', 'EW') or a position (1, 2, 3);
    default the file's first component."""
    path = os.fspath(path)
    key = recognise(path)
    if key is None:
        raise RecordError(f"{path}:1: not an ESM, GeoNet, K-NET or COSMOS record (formats read: {READ})")
    return READERS[key].read(path, component)


def split_spec(spec):
    """(path, component) from 'FILE' or 'FILE:COMPONENT' (a whole spec naming a file is the file)."""
    text = os.fspath(spec)
    if os.path.exists(text):
        return text, None
    base, colon, component = text.rpartition(":")
    return (base, component) if colon and base and os.path.exists(base) else (text, None)


def read_record(spec):
    """A Record from 'FILE' or 'FILE:COMPONENT' when FILE is in one of this package's formats;
    None otherwise (the caller then reads AT2 and CSV as before)."""
    path, component = split_spec(spec)
    if recognise(path) is None:
        return None
    t, ag, name, meta = read(path, component)
    return Record(name, t, ag, source=meta["source"])


def read_by_content(spec, units="g"):
    """A Record from a file whose name does not say its format (no .AT2 or .csv suffix), read as
    its content says; else the RecordError that lists the formats read. units: of a CSV file."""
    path, component = split_spec(spec)
    kind = detect_format(path)
    if kind in READERS:
        t, ag, name, meta = READERS[kind].read(path, component)
        return Record(name, t, ag, source=meta["source"])
    if component is not None:
        raise RecordError(f"{path}: an {kind.upper()} file holds one series: ':{component}' chooses a component only "
                          "in GeoNet, K-NET, ESM or COSMOS files")
    return read_at2(path) if kind == "at2" else read_csv(path, units=units)

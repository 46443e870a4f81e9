"""A record from what a user types: a name ('elcentro', 'gaussian[:D,T]') or a file, its format
found from its suffix (.AT2, .csv) or else its content."""
import os
import pathlib

from .builtin import el_centro, gaussian
from .csv_table import read_csv
from .detect import read_by_content, read_record
from .peer import read_at2

def load(spec, units="g"):
    """A record from what a user types: 'elcentro', 'gaussian' or 'gaussian:D,T' (m, s), or a path
    to an .AT2 or a .csv file (CSV in `units`), or to an ESM, GeoNet, K-NET or COSMOS file
    ('FILE:COMPONENT' picks a component)."""
    text = os.fspath(spec)
    if text.lower() in ("elcentro", "el-centro", "el_centro"):
        return el_centro()
    if text.lower().startswith("gaussian"):
        _, _, args = text.partition(":")
        values = [float(v) for v in args.split(",") if v.strip()] if args else []
        return gaussian(*values)
    found = read_record(text)  # an ESM, GeoNet, K-NET or COSMOS file, whatever its name
    if found is not None:
        return found
    suffix = pathlib.Path(text).suffix.lower()
    if suffix == ".at2":
        return read_at2(text)
    if suffix in (".csv", ".txt", ".dat"):
        return read_csv(text, units=units)
    return read_by_content(text, units)  # else the error that lists the formats read

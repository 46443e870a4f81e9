"""A record from what a user types: a name ('elcentro', 'gaussian[:D,T]') or a file, its format
found from its suffix (.AT2, .csv) or else its content."""
import os
import pathlib

from .builtin import el_centro, gaussian
from .csv_table import read_csv
from .detect import read_by_content, read_record, split_spec
from .peer import read_at2
from .types import RecordError

def load(spec, units="g"):
    """A record from what a user types: 'elcentro', 'gaussian' or 'gaussian:D,T' (m, s), or a path
    to an .AT2 or a .csv file (CSV in `units`), or to an ESM, GeoNet, K-NET or COSMOS file
    ('FILE:COMPONENT' picks a component)."""
    text = os.fspath(spec)
    is_file = os.path.exists(split_spec(text)[0])  # a path that exists is a file, whatever its name
    if not is_file and text.lower() in ("elcentro", "el-centro", "el_centro"):
        return el_centro()
    if not is_file and (text.lower() == "gaussian" or text.lower().startswith("gaussian:")):
        return gaussian(*gaussian_arguments(text))
    found = read_record(text)  # an ESM, GeoNet, K-NET or COSMOS file, whatever its name
    if found is not None:
        return found
    suffix = pathlib.Path(text).suffix.lower()
    if suffix == ".at2":
        return read_at2(text)
    if suffix in (".csv", ".txt", ".dat"):
        return read_csv(text, units=units)
    return read_by_content(text, units)  # else the error that lists the formats read


def gaussian_arguments(text):
    """(D [m], T [s]) of 'gaussian:D,T' (either may be left out: 'gaussian', 'gaussian:0.03')."""
    _, _, args = text.partition(":")
    values = [v.strip() for v in args.split(",")] if args else []
    try:
        numbers = [float(v) for v in values]
    except ValueError:
        numbers = []
    if len(values) > 2 or len(numbers) != len(values) or not all(v > 0 and v < float("inf") for v in numbers):
        raise RecordError(f"{text}: expected gaussian:D,T with the impulse's displacement D [m] and duration "
                          "T [s], finite numbers > 0 (e.g. gaussian:0.04,1)")
    return numbers

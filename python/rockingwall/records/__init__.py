"""Ground-motion records: PEER NGA `.AT2` files, two-column CSV files, the formats engineers
download besides (ESM ASCII, GeoNet V1A/V2A, K-NET/KiK-net, COSMOS V1/V2, recognised by their
content), El Centro 1940 and the paper's Gaussian displacement impulse, all as a Record in m/s^2."""
from .builtin import el_centro, gaussian
from .csv_table import CSV_UNITS, read_csv
from .detect import READ as FORMATS_READ, detect_format, recognise, split_spec
from .detect import read as read_format
from .loading import load
from .peer import at2_header, read_at2
from .types import FLOAT, G_STD, Record, RecordError

__all__ = ["CSV_UNITS", "FLOAT", "FORMATS_READ", "G_STD", "Record", "RecordError", "at2_header", "detect_format", "el_centro",
           "gaussian", "load", "read_at2", "read_csv", "read_format", "recognise", "split_spec"]

"""JSON that other programs can parse: every non-finite number (NaN, inf) written as null, and
numpy scalars as plain numbers (json's own output writes NaN, which is not JSON)."""
import json
import math

import numpy as np


def clean(obj):
    """The same structure with plain Python numbers and None for every non-finite float."""
    if isinstance(obj, dict):
        return {str(k): clean(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [clean(v) for v in obj]
    if isinstance(obj, (np.integer, np.bool_)):
        return obj.item()
    if isinstance(obj, (float, np.floating)):
        return float(obj) if math.isfinite(obj) else None
    return obj


def dump(obj, fh):
    """Writes obj as strict JSON (indented) and a newline."""
    json.dump(clean(obj), fh, indent=1, allow_nan=False)
    fh.write("\n")


def write(obj, path):
    """dump() into the file `path` (for outputs.write_atomic's temporary file)."""
    with open(path, "w") as fh:
        dump(obj, fh)

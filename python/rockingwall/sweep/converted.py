"""A sweep's records in the formats of rockingwall.records (ESM, GeoNet, K-NET, COSMOS):
found in a suite folder by their content, each (its first component) converted once into an AT2
file of the cache, named by the hash of its text, which fmi2sim and the exact engine then read
like any AT2 record (values in g with every digit, so the samples are those `rockingwall run`
reads)."""
import hashlib
import os
import pathlib
import tempfile

from .. import records
from ..records import G_STD


def cache_dir():
    """$RW_RECORDS_CACHE/converted (default ~/.cache/rockingwall/converted)."""
    root = os.environ.get("RW_RECORDS_CACHE", pathlib.Path.home() / ".cache" / "rockingwall")
    return pathlib.Path(root).resolve() / "converted"


def recognised(folder):
    """The files of a folder in a format of rockingwall.records, sorted by name (only
    regular files are looked into)."""
    return sorted(p for p in pathlib.Path(folder).iterdir() if records.recognise(p))


def at2_text(ag, name, meta, path):
    """An NGA-style AT2 file of the samples: 4 header lines, then the values in g, 5 to a line,
    each with the digits that give back the same double."""
    lines = [f"{name}: converted by rockingwall from the {meta['format']} file {pathlib.Path(path).name}",
             f"component {meta['component']} of {', '.join(meta['components'])}",
             "ACCELERATION TIME SERIES IN UNITS OF G",
             f"NPTS= {len(ag)}, DT= {float(meta['dt'])!r} SEC"]
    acc_g = [repr(float(v)) for v in ag / G_STD]
    lines += ["  ".join(acc_g[i:i + 5]) for i in range(0, len(acc_g), 5)]
    return "\n".join(lines) + "\n"


def to_at2(path):
    """(the record's name, the cached AT2 file) of a record file in one of the other formats;
    a RecordError names the file, line and problem. The file is written beside its final name
    and renamed into place, so a reader never sees half of it."""
    _, ag, name, meta = records.read_format(path)
    text = at2_text(ag, name, meta, path)
    cache = cache_dir()
    target = cache / f"{hashlib.sha256(text.encode()).hexdigest()[:16]}.AT2"
    if not target.is_file():
        cache.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=".converting.", dir=cache)
        try:
            with os.fdopen(fd, "w") as f:
                f.write(text)
            os.replace(tmp, target)
        finally:
            if os.path.exists(tmp):
                os.unlink(tmp)
    return name, target

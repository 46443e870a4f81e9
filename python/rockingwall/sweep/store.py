"""The results file of a sweep: one CSV, one row per run, appended and flushed as runs finish, so
that an interrupted sweep keeps what it did.

Reading (resume, ida.py) goes line by line: the writer puts every row on one line, so a damaged
line (an unmatched quote, a byte that is not UTF-8, a garbage number, a row cut off by a kill)
costs that line only. Such lines are never dropped silently: a resume moves them, with the rows it
will compute again (stale or killed), into a backup file next to the results
(FILE.set-aside-<UTC time>) and names each line. The file itself is only ever appended to, or
replaced whole by a complete temporary file renamed over it, so no crash leaves it half written."""
import csv
import dataclasses
import math
import os
import pathlib
import stat
import sys
import tempfile
import time
from collections import Counter

from . import provenance
from .lock import FileLock
from .rows import BUILDING_MODEL, COLUMNS, OK, RETRIED, STATUSES

LEGACY_COLUMNS = COLUMNS[:COLUMNS.index("key")]  # files written before the key was recorded
_FLOATS = ["kd_kN", "record_pga_g", "scale", "pga_g", "end_time", "cpu_s", "elapsed_s"]
_PEAKS = ["peak_s1", "peak_s2", "peak_F_top"]
_INTS = ["impacts", "steps"]


class ResultsError(ValueError):
    """The file cannot be used as a results file at all (not one, or not a regular file)."""


def warn(message):
    print(message, file=sys.stderr)


@dataclasses.dataclass
class Line:
    number: int          # 1-based line number in the file
    raw: bytes           # the line as it is in the file, end of line included when present
    row: dict = None     # the parsed row, when the line is good
    problem: str = ""    # why it is not, when it is not
    cut: bool = False    # the last line, cut off by a kill: expected after an interruption, not damage


def check_target(path):
    """A results path that can be appended to: absent, or a regular file."""
    path = pathlib.Path(path)
    if path.exists() and not path.is_file():
        kind = "a folder" if path.is_dir() else "not a regular file"
        raise ResultsError(f"{path}: the results file is {kind}; give --out a file name such as {path / 'sweep.csv'}"
                           if path.is_dir() else f"{path}: the results file is {kind}")
    if path.parent.exists() and not path.parent.is_dir():
        raise ResultsError(f"{path.parent}: not a folder")


def _number(text, name, integer=False):
    try:
        value = int(text) if integer else float(text)
    except ValueError:
        raise ValueError(f"{name} = {text!r} is not {'an integer' if integer else 'a number'}") from None
    return value


def check_row(row):
    """'' for a sound row, else the problem. An 'ok' row must have every number a result needs."""
    if not row["run_id"]:
        return "empty run_id"
    if row["status"] not in STATUSES:
        return f"status {row['status']!r} is not one of {', '.join(STATUSES)}"
    if row["status"] != OK:
        return ""
    try:
        for name in _FLOATS:
            _number(row[name], name)
        for name in _INTS:
            _number(row[name], name, integer=True)
        for name in _PEAKS:
            if name == "peak_F_top" and row[name] == "" and row["model"] == BUILDING_MODEL:
                continue  # not computed in a building sweep (engine_task): NaN in load_frame
            v = _number(row[name], name)
            if not (math.isfinite(v) and v >= 0):
                return f"{name} = {row[name]!r} is not a finite peak >= 0"
    except ValueError as exc:
        return str(exc)
    if row["collapsed"] not in ("True", "False"):
        return f"collapsed = {row['collapsed']!r} is not True or False"
    return ""


def _parse(raw, columns):
    """(row, problem) of one line."""
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        return None, f"byte 0x{raw[exc.start]:02x} at column {exc.start + 1} is not UTF-8"
    if not text.endswith("\n"):
        return None, "cut off (no end of line): a write that was interrupted"
    fields = next(csv.reader([text.rstrip("\r\n")], strict=True), None) if text.strip() else []
    if len(fields) != len(columns):
        return None, f"{len(fields)} fields, expected {len(columns)} (a damaged row, e.g. an unmatched quote)"
    row = dict(zip(columns, fields))
    row.update({c: "" for c in COLUMNS if c not in row})
    return row, check_row(row)


def _read_header(path, first):
    try:
        names = next(csv.reader([first.decode("utf-8").rstrip("\r\n")]))
    except (UnicodeDecodeError, csv.Error, StopIteration):
        names = None
    if names == COLUMNS or names == LEGACY_COLUMNS:
        return names
    raise ResultsError(f"{path}:1: not a results file of this sweep (the header differs); "
                       "move it away or choose another --out")


def read(path):
    """(columns, header bytes, [Line]) of a results file; ([], b'', []) when it is absent or empty.
    Only a file that is not a results file at all raises; damaged lines come back with a problem."""
    path = pathlib.Path(path)
    check_target(path)
    if not path.exists() or path.stat().st_size == 0:
        return [], b"", []
    with open(path, "rb") as f:
        header = f.readline(64 * 1024)  # a header is short: never read a whole odd file
        columns = _read_header(path, header)
        lines = []
        for number, raw in enumerate(f, start=2):
            if not raw.strip():
                continue  # an empty line carries nothing
            try:
                row, problem = _parse(raw, columns)
            except csv.Error as exc:
                row, problem = None, f"not a CSV row ({exc})"
            lines.append(Line(number, raw, row if not problem else None, problem, cut=not raw.endswith(b"\n")))
    return columns, header, lines


def mark_repeats(lines):
    """A run_id on several good lines (two sweeps on one file, before the lock): the last line
    counts, the others get a problem."""
    last = {ln.row["run_id"]: ln.number for ln in lines if ln.row}
    for ln in lines:
        if ln.row and last[ln.row["run_id"]] != ln.number:
            ln.problem = f"run {ln.row['run_id']} again on line {last[ln.row['run_id']]}, which counts"
            ln.row = None


def report_bad(path, lines, action):
    bad = [ln for ln in lines if ln.problem]
    for ln in bad[:20]:
        warn(f"{path}:{ln.number}: {ln.problem}: {action}")
    if len(bad) > 20:
        warn(f"{path}: ... and {len(bad) - 20} more lines like these")
    return bad


def _set_aside_path(path):
    stamp = time.strftime("%Y%m%dT%H%M%SZ", time.gmtime())
    candidate = path.with_name(f"{path.name}.set-aside-{stamp}")
    n = 1
    while candidate.exists():
        n += 1
        candidate = path.with_name(f"{path.name}.set-aside-{stamp}-{n}")
    return candidate


def _write_whole(path, chunks, mode_of=None):
    """Write a file as a temporary file in the same folder, then rename it into place: readers see
    the old file or the new one, never half of one. It gets the permissions of mode_of (default:
    the file it replaces), not mkstemp's private 0600."""
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            for chunk in chunks:
                f.write(chunk)
            f.flush()
            os.fsync(f.fileno())
        like = pathlib.Path(mode_of or path)
        if like.exists():
            os.chmod(tmp, stat.S_IMODE(like.stat().st_mode))
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def _raw_row(row):
    """A row as one CSV line in the current columns."""
    out = []

    class _Sink:
        def write(self, s):
            out.append(s)
    csv.DictWriter(_Sink(), fieldnames=COLUMNS, lineterminator="\n").writerow(row)
    return "".join(out).encode("utf-8")


def _header_bytes():
    return (",".join(COLUMNS) + "\n").encode()


@dataclasses.dataclass
class Resume:
    done: set                 # run_ids whose row is reused
    stale: Counter            # reason -> rows of planned runs computed from other inputs
    retried: int              # killed or timed-out rows run again
    bad: int                  # damaged lines set aside (not counting a last line cut off by a kill)
    set_aside: pathlib.Path = None


class ResultsFile:
    """Use as a context manager: holds the file's lock for the whole sweep."""

    def __init__(self, path):
        # the real file: a symlinked results file stays a symlink when the file is replaced
        # whole, and two sweeps reaching one file by two names share one lock
        self.path = pathlib.Path(os.path.realpath(path))
        self._f = None
        self._w = None
        self._lock = FileLock(self.path)

    def __enter__(self):
        check_target(self.path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._lock.acquire()
        return self

    def __exit__(self, *exc):
        try:
            self.close()
        finally:
            self._lock.release()

    def resume(self, planned):
        """planned: run_id -> the provenance columns (key, hashes) the run would have now. Sorts
        the file's lines into reused rows, rows to compute again, damaged lines and rows of other
        runs (kept as they are); rewrites the file without the second and third kind, which go
        to a backup file; returns what it did."""
        columns, header, lines = read(self.path)
        mark_repeats(lines)
        keep, aside, done, stale, retried = [], [], set(), Counter(), 0
        for ln in lines:
            want = planned.get(ln.row["run_id"]) if ln.row else None
            if ln.problem:
                aside.append(ln)
            elif want is None:
                keep.append(ln)                       # a run of another plan: not ours to judge
            elif ln.row["status"] in RETRIED:
                retried += 1
                ln.problem = f"{ln.row['status']}: run again"
                aside.append(ln)
            elif ln.row["key"] != want["key"]:
                reason = provenance.why_stale(ln.row, want)
                stale[reason] += 1
                ln.problem = f"computed from other inputs ({reason}): run again"
                aside.append(ln)
            else:
                keep.append(ln)
                done.add(ln.row["run_id"])
        res = Resume(done, stale, retried, sum(1 for ln in aside if ln.row is None and not ln.cut))
        if aside or (columns and columns != COLUMNS):
            res.set_aside = self._rewrite(header, keep, aside, legacy=columns != COLUMNS)
        return res

    def _rewrite(self, header, keep, aside, legacy):
        backup = None
        if aside:
            report_bad(self.path, aside, "set aside")
            backup = _set_aside_path(self.path)
            _write_whole(backup, [header] + [ln.raw if ln.raw.endswith(b"\n") else ln.raw + b"\n" for ln in aside],
                         mode_of=self.path)
        if legacy:  # an older header: the rows gain the new (empty) provenance columns
            body = [_raw_row(ln.row) for ln in keep]
        else:
            body = [ln.raw for ln in keep]
        _write_whole(self.path, [_header_bytes()] + body)
        return backup

    def append(self, row):
        if self._f is None:
            new = not self.path.exists() or self.path.stat().st_size == 0
            self._f = open(self.path, "a", newline="", encoding="utf-8")
            self._w = csv.DictWriter(self._f, fieldnames=COLUMNS, lineterminator="\n")
            if new:
                self._w.writeheader()
        self._w.writerow(row)
        self._f.flush()

    def close(self):
        if self._f is not None:
            try:
                self._f.flush()
                os.fsync(self._f.fileno())
            finally:
                self._f.close()
                self._f = None


_NUMERIC = ["kd_kN", "record_pga_g", "scale", "pga_g", "peak_s1", "peak_s2", "peak_F_top", "impacts",
            "end_time", "steps", "cpu_s", "elapsed_s"]


def load_frame(path):
    """load_rows as a DataFrame with numbers as numbers and `collapsed` as bool. Every 'ok' row's
    numbers were checked; the empty ones of other rows become NaN. attrs['damaged_lines'] counts
    the lines left out."""
    import pandas as pd
    rows, damaged = load_rows(path, count=True)
    d = pd.DataFrame(rows, columns=COLUMNS)
    d.attrs["damaged_lines"] = damaged
    d[_NUMERIC] = d[_NUMERIC].apply(pd.to_numeric, errors="coerce")
    d["collapsed"] = d.collapsed == "True"
    return d


def load_rows(path, count=False):
    """The good rows of a results file for analysis (ida.py), the last one of each run_id; damaged
    lines are named with their line number and left out, the file is not changed. With count:
    (rows, number of lines left out)."""
    _, _, lines = read(path)
    mark_repeats(lines)
    bad = report_bad(path, lines, "left out")
    rows = [ln.row for ln in lines if ln.row]
    return (rows, len(bad)) if count else rows

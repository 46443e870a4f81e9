"""The results file of a sweep: one CSV, one row per finished run, appended and flushed as runs
finish, so that an interrupted sweep keeps what it did. On resume the file is read back, a last row
cut off by the interruption is dropped, and the run_ids present are the runs not to repeat."""
import csv
import io
import pathlib

from .runner import COLUMNS


class ResultsFile:
    def __init__(self, path):
        self.path = pathlib.Path(path)
        self._f = None
        self._w = None

    def finished(self):
        """run_id -> status of the complete rows already in the file; repairs a cut-off tail."""
        if not self.path.exists() or self.path.stat().st_size == 0:
            return {}
        text = self.path.read_text()
        complete = text if text.endswith("\n") else text[:text.rfind("\n") + 1]
        rows = list(csv.reader(io.StringIO(complete)))
        if not rows or rows[0] != COLUMNS:
            raise ValueError(f"{self.path}: not a results file of this sweep (header differs); "
                             "move it away or choose another --out")
        good = [r for r in rows[1:] if len(r) == len(COLUMNS)]
        if complete != text or len(good) != len(rows) - 1:
            self._rewrite([rows[0]] + good)  # a cut-off last row is run again
        return {r[0]: r[COLUMNS.index("status")] for r in good}

    def _rewrite(self, rows):
        tmp = self.path.with_suffix(self.path.suffix + ".tmp")
        with open(tmp, "w", newline="") as f:
            csv.writer(f, lineterminator="\n").writerows(rows)
        tmp.replace(self.path)

    def append(self, row):
        if self._f is None:
            new = not self.path.exists() or self.path.stat().st_size == 0
            self.path.parent.mkdir(parents=True, exist_ok=True)
            self._f = open(self.path, "a", newline="")
            self._w = csv.DictWriter(self._f, fieldnames=COLUMNS, lineterminator="\n")
            if new:
                self._w.writeheader()
        self._w.writerow(row)
        self._f.flush()

    def close(self):
        if self._f is not None:
            self._f.close()
            self._f = None

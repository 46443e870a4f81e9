"""An output folder whose contents are one run's: the files of a run are written into a staging
folder beside them (.rockingwall-staging-<pid>), and swapped in at the end under a manifest.

`manifest.json` lists the files the program wrote, with their SHA-256, and says whether the run
completed ("complete": true only after the last file is in place). At the swap the files the
previous manifest listed and this run does not write are removed, but only those still as the
program wrote them (same SHA-256): a file the user put there or edited is never deleted. A run that
fails or is killed while it writes leaves the previous run's files as they were (the staging
folder, named with the dead process's id, is removed by the next run); one killed during the
swap leaves a manifest that says "complete": false."""
import hashlib
import json
import os
import pathlib
import shutil
import sys

from . import outputs, scratch, strict_json

MANIFEST = "manifest.json"
STAGING = ".rockingwall-staging-"


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def read_manifest(folder):
    """{name: sha256} of the files the previous run's manifest lists ({} without one, or with one
    that is damaged: then nothing is removed)."""
    try:
        data = json.loads((folder / MANIFEST).read_text())
        files = data["files"]
        return {str(k): str(v) for k, v in files.items() if pathlib.PurePath(k).name == k}
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return {}


class OutputFolder:
    """with OutputFolder(path, command) as folder: folder.write(name, write) ...; the swap happens
    when the block ends without an exception (else the staged files are dropped)."""

    def __init__(self, path, command):
        self.path = pathlib.Path(path)
        self.command = command
        self.stage = self.path / f"{STAGING}{os.getpid()}"
        self.written = {}  # name -> sha256, in the order written

    def check(self, names):
        """Before the run: none of these outputs (nor the manifest) is an input."""
        outputs.check_targets([self.path / n for n in (*names, MANIFEST)], "--out")

    def __enter__(self):
        scratch.reclaim(self.path, STAGING)  # what killed runs of this program left in this folder
        shutil.rmtree(self.stage, ignore_errors=True)
        try:
            self.stage.mkdir()
        except OSError as exc:
            raise OSError(exc.errno, f"cannot write into the folder: {exc.strerror}", str(self.path)) from None
        return self

    def write(self, name, write):
        """write(tmp_path) for the output `name` (a file name in the folder), staged."""
        if pathlib.PurePath(name).name != name or name in (MANIFEST, "") or name.startswith(STAGING):
            raise ValueError(f"{name!r}: not a name for an output file of {self.path}")
        outputs.check_target(self.path / name, "--out")
        try:
            staged = outputs.write_atomic(self.stage / name, write)
        except OSError as exc:
            raise OSError(exc.errno, exc.strerror, str(self.path / name)) from None
        self.written[name] = sha256(staged)

    def __exit__(self, kind, exc, tb):
        try:
            if kind is None:
                self._swap()
        finally:
            shutil.rmtree(self.stage, ignore_errors=True)

    def _manifest(self, files, complete):
        manifest = {"command": self.command, "complete": complete, "files": files}
        outputs.write_atomic(self.path / MANIFEST, lambda tmp: strict_json.write(manifest, tmp), "--out")

    def _swap(self):
        earlier = read_manifest(self.path)
        self._manifest({**earlier, **self.written}, complete=False)  # a kill from here on is visible
        for name, digest in earlier.items():
            if name not in self.written:
                remove_if_ours(self.path / name, digest)
        for name in self.written:
            place(self.stage / name, self.path / name)
        self._manifest(self.written, complete=True)


def place(staged, target):
    """Move a staged file over its target (keeping the target's mode if it has one)."""
    outputs.check_target(target, "--out")
    try:
        try:
            os.chmod(staged, outputs.mode_for(target))
        except OSError:
            pass
        os.replace(staged, target)
    except OSError as exc:
        raise OSError(exc.errno, f"cannot write: {exc.strerror}", str(target)) from None


def remove_if_ours(path, digest):
    """Remove a file of the previous run, unless it is no longer what the program wrote."""
    try:
        if path.is_symlink() or not path.is_file():
            return
        if sha256(path) != digest:
            print(f"rockingwall: note: {path} was changed since the previous run wrote it: kept", file=sys.stderr)
            return
        path.unlink()
    except OSError as exc:
        print(f"rockingwall: note: {outputs.describe_os_error(exc, path)}: kept", file=sys.stderr)

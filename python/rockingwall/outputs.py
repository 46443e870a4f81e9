"""Writing a command's output files: never over one of its inputs, whole or not at all, with the
permissions a plain file gets.

A command registers every file it reads (`protect`: records, FMUs, SSP archives, results and
config files) inside `session()`, which the command line opens around each command; every output
then goes through `write_atomic`, which refuses a target that is one of them: the same path, a
symlink to it or a hard link of it (the same device and inode). A command that knows its targets
before its (long) runs checks them first with `check_targets`. The write goes into a temporary
file beside the target, renamed over it only when complete: a full disk or a kill leaves the
earlier file as it was, and the error names the target."""
import contextlib
import os
import pathlib
import stat
import sys
import tempfile

_PROTECTED = {}  # (device, inode) -> (what, path) of every input of the current command


class OutputError(ValueError):
    """An output that would overwrite an input, or two outputs that are one file."""


@contextlib.contextmanager
def session():
    """The scope of one command's inputs (the command line opens one per command)."""
    saved = dict(_PROTECTED)
    _PROTECTED.clear()
    try:
        yield
    finally:
        _PROTECTED.clear()
        _PROTECTED.update(saved)


def _identity(path):
    try:
        st = os.stat(path)  # symlinks followed: a link to an input is the input
    except (OSError, ValueError):
        return None
    return (st.st_dev, st.st_ino)


def protect(path, what="input"):
    """Register `path` (a file the command reads) as an input its outputs never replace."""
    if path is None:
        return
    key = _identity(path)
    if key is not None:
        _PROTECTED[key] = (what, os.fspath(path))


def _input_at(path, inputs=()):
    """(what, path) of the input `path` is (by device and inode): a registered one or one of
    `inputs` ((path, what) pairs), or None. A registered input that is gone, or whose path now
    names another file, no longer counts (inodes are reused)."""
    key = _identity(path)
    if key is None:
        return None
    for original, what in inputs:
        if _identity(original) == key:
            return what, os.fspath(original)
    if key not in _PROTECTED:
        return None
    what, original = _PROTECTED[key]
    return (what, original) if _identity(original) == key else None


def check_targets(targets, label="output"):
    """Refuse, before any work, targets that are inputs or that name one file twice."""
    seen = {}
    for target in targets:
        check_target(target, label)
        key = os.path.normcase(os.path.abspath(os.fspath(target)))
        ident = _identity(target) or key
        if ident in seen or key in seen:
            raise OutputError(f"{label} {target}: written twice by this command (also as {seen.get(ident, seen.get(key))}): "
                              "two results with one file name; rename an input")
        seen[ident] = seen[key] = target


def check_target(target, label="output", inputs=()):
    """Refuse `target` when it is an input (registered, or one of `inputs`: (path, what) pairs)."""
    found = _input_at(target, inputs)
    if found:
        what, original = found
        same = "" if os.path.abspath(original) == os.path.abspath(os.fspath(target)) else f" (the same file as {original})"
        raise OutputError(f"{label} {target} is {what} {original}{same}: refusing to overwrite an input; "
                          "choose another output folder or file")


def current_umask():
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def mode_for(path):
    """The permissions a plain open() leaves `path` with: an existing file's own, else 0666 less
    the umask."""
    try:
        return stat.S_IMODE(os.stat(path).st_mode)
    except OSError:
        return 0o666 & ~current_umask()


def describe_os_error(exc, path=None):
    """'PATH: what went wrong' from an OSError (the path it names, else `path`)."""
    name = exc.filename if exc.filename is not None else path
    reason = exc.strerror or str(exc)
    return f"{name}: {reason}" if name is not None else reason


def write_atomic(path, write, label="output", inputs=()):
    """write(tmp_path) into a temporary file beside `path`, renamed into place when it succeeded;
    refused when `path` is an input (registered, or one of `inputs`: (path, what) pairs). The
    file gets the mode a plain open() would give it: an existing target's, else 0666 less the
    umask (not mkstemp's private 0600). An OSError names `path`."""
    path = pathlib.Path(path)
    check_target(path, label, inputs)
    mode = mode_for(path)
    try:
        # the suffix kept: writers that pick the format from the name (PIL) see the target's
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=path.suffix, dir=path.parent)
        os.close(fd)
    except OSError as exc:
        raise OSError(exc.errno, f"cannot write into its folder: {exc.strerror}", str(path)) from None
    try:
        write(tmp)
        os.chmod(tmp, mode)
        check_target(path, label, inputs)  # an input may have appeared at the path during the write
        os.replace(tmp, path)
    except OSError as exc:
        raise OSError(exc.errno, f"cannot write: {exc.strerror or exc}", str(path)) from None
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
    return path


def write_png(fig, path, label="output", dpi=110):
    """A matplotlib figure as a PNG at path, through write_atomic (whole or not at all)."""
    return write_atomic(path, lambda tmp: fig.savefig(tmp, dpi=dpi, format="png"), label)


class NamedStream:
    """A text stream whose write errors name it ('standard output: No space left on device'):
    an OSError of print() carries no file name of its own. A closed pipe stays BrokenPipeError."""

    def __init__(self, stream, name):
        self._stream, self._name = stream, name

    def _named(self, call, *args):
        try:
            return call(*args)
        except BrokenPipeError:
            raise
        except OSError as exc:
            raise OSError(exc.errno, exc.strerror or str(exc), self._name) from None

    def write(self, text):
        return self._named(self._stream.write, text)

    def flush(self):
        return self._named(self._stream.flush)

    def __getattr__(self, name):
        return getattr(self._stream, name)


@contextlib.contextmanager
def named_stdout():
    """sys.stdout as a NamedStream for the duration; on a failed write what is still buffered is
    dropped (standard output pointed at /dev/null), so the interpreter's flush at exit is quiet."""
    original = sys.stdout
    sys.stdout = NamedStream(original, "standard output")
    try:
        yield
        sys.stdout.flush()  # here, not at exit: a full disk behind standard output is named
    except OSError as exc:
        if exc.filename == "standard output" and not isinstance(exc, BrokenPipeError):
            os.dup2(os.open(os.devnull, os.O_WRONLY), original.fileno())
        raise
    finally:
        sys.stdout = original

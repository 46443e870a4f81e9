"""Temporary folders of this program, named with the id of the process that made them
(`rw_simulate_<pid>_xxxxxxxx`), so that what a killed process leaves (an unpacked FMU, a sweep's
scratch space) is removed by the next one: `reclaim` removes a folder only when its name has one
of our prefixes followed by a process id, it is a real folder (not a symlink) owned by this user,
and no process with that id exists."""
import contextlib
import os
import shutil
import stat
import tempfile

# the prefixes of the package's temporary folders (each followed by '<pid>_')
KINDS = ("rw_fmi2sim_", "rw_simulate_", "rw_sweep_", "rw_sweep_run_", "rw_ssp_", "rw_couple_", "rw_couple_me_",
         "rw_couple_result_", "rw_jacobi_")
_RECLAIMED = set()  # folders already swept by this process


def alive(pid):
    """Whether a process with this id exists (one of another user's counts: it is not ours to judge)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, ValueError):
        return True
    return True


def owner_pid(name, prefix):
    """The process id in `name` (prefix, digits, then '_' or the end), or None."""
    if not name.startswith(prefix):
        return None
    rest = name[len(prefix):]
    digits = rest.split("_", 1)[0]
    if not digits.isdigit() or len(digits) > 9 or (len(rest) > len(digits) and rest[len(digits)] != "_"):
        return None
    return int(digits)


def reclaim(folder, prefixes=KINDS):
    """Remove, inside `folder`, the folders of dead processes of this program (see the module's
    docstring for what is checked); never raises."""
    prefixes = (prefixes,) if isinstance(prefixes, str) else tuple(prefixes)
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return
    for entry in entries:
        pid = next((p for p in (owner_pid(entry.name, k) for k in prefixes) if p is not None), None)
        if pid is None or pid == os.getpid() or alive(pid):
            continue
        try:
            st = entry.stat(follow_symlinks=False)
        except OSError:
            continue
        if stat.S_ISDIR(st.st_mode) and st.st_uid == os.getuid():
            shutil.rmtree(entry.path, ignore_errors=True)


def make(kind, parent=None):
    """A new temporary folder `<kind><pid>_xxxxxxxx` in `parent` (default: the system's temporary
    folder), after removing what dead processes of this program left there (once per process)."""
    if kind not in KINDS:
        raise ValueError(f"{kind!r} is not a temporary-folder kind of this package ({', '.join(KINDS)})")
    parent = os.fspath(parent or tempfile.gettempdir())
    reclaim_once(parent)
    return tempfile.mkdtemp(prefix=f"{kind}{os.getpid()}_", dir=parent)


def reclaim_once(parent=None):
    """reclaim() in `parent` (default: the system's temporary folder), once per process: every
    command calls it as it starts, so what a killed run left goes at the next run of any kind."""
    parent = os.fspath(parent or tempfile.gettempdir())
    if parent not in _RECLAIMED:
        _RECLAIMED.add(parent)
        reclaim(parent)


@contextlib.contextmanager
def folder(kind, parent=None):
    """make(), removed with everything in it when the block ends."""
    path = make(kind, parent)
    try:
        yield path
    finally:
        shutil.rmtree(path, ignore_errors=True)

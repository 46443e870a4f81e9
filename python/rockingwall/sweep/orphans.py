"""The fmi2sim processes a sweep leaves behind when its workers are gone (a worker killed in the
middle of a run leaves its fmi2sim running): found in /proc by their command line, which names
one of the sweep's run folders (fmi2sim_task.command puts the run's summary file there), rather
than from a pid the worker wrote down, which a worker killed just after it started a run had not
always written."""
import os
import pathlib
import signal
import time

from . import fmi2sim_task

PF_KTHREAD = 0x00200000  # /proc/PID/stat's flags: a kernel thread, whose command line is always empty
EXEC_GRACE_S = 2.0       # how long a process may show no command line before it is left alone
POLL_S = 0.01


def _read(path):
    try:
        return path.read_bytes()
    except OSError:
        return None  # gone meanwhile


def _mid_exec(proc_dir):
    """Is this process between exec and its new command line? Linux closes the exec'ing process's
    close-on-exec files (so Popen returns in its parent) before it sets the new arguments: for that
    moment /proc/PID/cmdline reads empty. Kernel threads and zombies read empty for good."""
    stat = _read(proc_dir / "stat")
    if not stat:
        return False
    fields = stat[stat.rindex(b")") + 2:].split()
    return fields[0] not in (b"Z", b"X") and not int(fields[6]) & PF_KTHREAD


def _kill_if_marked(proc_dir, mark):
    """SIGKILL the process if its command line holds mark: True if done (killed, gone, or not one of
    ours), False if its command line is not there yet"""
    cmdline = _read(proc_dir / "cmdline")
    if cmdline is None:
        return True
    if not cmdline:
        return not _mid_exec(proc_dir)
    if mark in cmdline:
        try:
            os.kill(int(proc_dir.name), signal.SIGKILL)
        except OSError:
            pass  # finished meanwhile
    return True


def stop_orphans(tmp_root, proc=pathlib.Path("/proc")):
    """SIGKILL every process whose command line names one of the run folders under tmp_root. A
    process caught between exec and its command line is looked at again until it shows one (at
    most EXEC_GRACE_S): an orphan started just before the sweep ended is not missed."""
    mark = os.path.join(str(tmp_root), fmi2sim_task.RUN_PREFIX).encode()
    pending = [d for d in proc.glob("[0-9]*") if not _kill_if_marked(d, mark)]
    deadline = time.monotonic() + EXEC_GRACE_S
    while pending and time.monotonic() < deadline:
        time.sleep(POLL_S)
        pending = [d for d in pending if not _kill_if_marked(d, mark)]

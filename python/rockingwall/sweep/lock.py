"""One sweep per results file: an exclusive flock(2) on FILE.lock, held while the sweep runs, and
one on the results file itself when it exists (its inode: two hard-linked names of one file are
one file, which the lock files of the two names alone would not see). The kernel drops the locks
when the process dies however it dies, so a killed sweep never blocks the next one; the lock file
names the holder for the message a second sweep gets."""
import fcntl
import os
import socket
import time


class Busy(Exception):
    """Another process holds the lock."""


def _holder(fd):
    os.lseek(fd, 0, os.SEEK_SET)
    text = os.read(fd, 4096).decode("utf-8", errors="replace").strip()
    return text or "a process that has not written its name yet"


def lock_the_file(target):
    """An exclusive flock on the results file itself (None when it does not exist yet): another
    name of the same file (a hard link) takes another lock file but meets this lock."""
    try:
        fd = os.open(target, os.O_RDONLY | os.O_NONBLOCK)
    except OSError:
        return None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        os.close(fd)
        raise Busy(f"{target} is in use by another sweep, which writes the same file by another name (a hard "
                   "link): wait for it to finish or choose another --out") from None
    return fd


class FileLock:
    def __init__(self, target):
        self.target = str(target)
        self.path = self.target + ".lock"
        self._fd = None
        self._file_fd = None

    def acquire(self):
        while True:
            fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o644)
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                holder = _holder(fd)
                os.close(fd)
                raise Busy(f"{self.target} is in use by another sweep ({holder}; lock {self.path}): "
                           "wait for it to finish or choose another --out") from None
            # the previous holder may have removed the file between our open and our lock: then
            # this lock is on a file nobody else will see, so take the one now at the path
            try:
                same = os.fstat(fd).st_ino == os.stat(self.path).st_ino
            except FileNotFoundError:
                same = False
            if same:
                break
            os.close(fd)
        try:
            self._file_fd = lock_the_file(self.target)
        except Busy:
            os.close(fd)
            raise
        os.ftruncate(fd, 0)
        os.write(fd, f"pid {os.getpid()} on {socket.gethostname()} since "
                     f"{time.strftime('%Y-%m-%d %H:%M:%S %Z')}\n".encode())
        self._fd = fd

    def release(self):
        if self._file_fd is not None:
            os.close(self._file_fd)
            self._file_fd = None
        if self._fd is None:
            return
        try:
            os.unlink(self.path)  # while still locked: a waiting sweep then re-checks the inode
        except FileNotFoundError:
            pass
        os.close(self._fd)
        self._fd = None

    def __enter__(self):
        self.acquire()
        return self

    def __exit__(self, *exc):
        self.release()

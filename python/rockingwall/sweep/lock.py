"""One sweep per results file: an exclusive flock(2) on FILE.lock, held while the sweep runs. The
kernel drops the lock when the process dies however it dies, so a killed sweep never blocks the
next one; the lock file names the holder for the message a second sweep gets."""
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


class FileLock:
    def __init__(self, target):
        self.target = str(target)
        self.path = self.target + ".lock"
        self._fd = None

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
        os.ftruncate(fd, 0)
        os.write(fd, f"pid {os.getpid()} on {socket.gethostname()} since "
                     f"{time.strftime('%Y-%m-%d %H:%M:%S %Z')}\n".encode())
        self._fd = fd

    def release(self):
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

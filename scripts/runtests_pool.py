"""runtests_pool: instance numbers for runtests, free across runners of every user, and their SysV keys."""

import ctypes
import errno
import fcntl
import os
import queue
import re
import sys
import tempfile

# the launcher's package (built into lib/python) holds the one Python copy of the key formula
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.realpath(__file__))),
                                "lib", "python"))
from openemc_launcher.sysv import instance_key  # noqa: E402

SHM_KEYS = ((0x00000064, "Emc motion"), (0x48414C32, "Hal"), (0x48484C34, "UUID"),
            (0x90280A48, "Rtapi"), (0x130CF406, "Hal scope"), (0x434C522B, "Classicladder"),
            (1001, "NML emcCommand"), (1002, "NML emcStatus"), (1003, "NML emcError"),
            (0x00544F4C, "Tool data"))
SHARED_LOCKDIR = "openemc-instance-locks"
FIFO_NAME = re.compile(r"/\.rtapi_fifo(?:\.(\d+))?$")


def shm_segments():
    """Map key -> (shmid, nattch) of every SysV shared-memory segment."""
    segs = {}
    try:
        with open("/proc/sysvipc/shm") as f:
            next(f)
            for line in f:
                col = line.split()
                segs[int(col[0]) & 0xFFFFFFFF] = (int(col[1]), int(col[6]))
    except OSError:
        pass
    return segs


def instance_keys(instance):
    """The watched keys of one instance as (key, use name)."""
    return [(instance_key(base, instance), use) for base, use in SHM_KEYS]



def remove_segment(shmid):
    """shmctl(IPC_RMID) a segment."""
    libc = ctypes.CDLL(None, use_errno=True)
    libc.shmctl(ctypes.c_int(shmid), ctypes.c_int(0), None)


def listening_instances():
    """Instances whose default rtapi_app socket (@$HOME/.rtapi_fifo[.N]) exists, for any user."""
    found = set()
    try:
        with open("/proc/net/unix") as f:
            for line in f:
                col = line.split()
                match = FIFO_NAME.search(col[-1]) if len(col) >= 8 and col[-1].startswith("@") else None
                if match:
                    found.add(int(match.group(1) or 0))
    except OSError:
        pass
    return found


def user_lockdir():
    """This user's own lock directory, used where the shared one cannot hold a lock file."""
    path = os.path.join(tempfile.gettempdir(), "%s-%d" % (SHARED_LOCKDIR, os.getuid()))
    os.makedirs(path, mode=0o700, exist_ok=True)
    return path


def open_lock(directory, instance):
    """Open (creating when needed) the lock file of an instance read-only; None when not possible.
    flock() needs no write access, so a lock file made by another user still serves everyone."""
    path = os.path.join(directory, "%d.lock" % instance)
    try:
        return os.open(path, os.O_RDONLY)
    except FileNotFoundError:
        pass
    except OSError:
        return None
    try:
        fd = os.open(path, os.O_RDONLY | os.O_CREAT, 0o666)
    except OSError:
        return None
    try:
        os.fchmod(fd, 0o666)
    except OSError:
        pass
    return fd


def shared_lockdir():
    """The lock directory shared by all users (mode 1777), or None when it is unusable."""
    path = os.path.join(tempfile.gettempdir(), SHARED_LOCKDIR)
    try:
        os.mkdir(path)
        os.chmod(path, 0o1777)
    except FileExistsError:
        pass
    except OSError:
        return None
    return path if os.path.isdir(path) else None


class InstancePool:
    """Instance numbers 1..255 held with flock()ed lock files, skipping instances in use by anyone
    (shared memory present or an rtapi_app socket listening), so concurrent runners never share one."""
    def __init__(self, count):
        self.shared, self.own = shared_lockdir(), None
        self.fds, self.free = [], queue.Queue()
        busy = listening_instances()
        segs = shm_segments()
        for inst in range(1, 256):
            if len(self.fds) == count:
                break
            if inst in busy or any(key in segs for key, _use in instance_keys(inst)):
                continue
            fd = self.lock(inst)
            if fd is not None:
                self.fds.append(fd)
                self.free.put(inst)
        if len(self.fds) < count:
            sys.stderr.write("runtests: only %d free OpenEMC instances for -j %d\n"
                             % (len(self.fds), count))
            sys.exit(1)
        self.instances = list(self.free.queue)

    def lock(self, inst):
        """Lock an instance in the shared directory, else in this user's own; return the fd or None."""
        fd = open_lock(self.shared, inst) if self.shared else None
        if fd is None:
            self.own = self.own or user_lockdir()
            fd = open_lock(self.own, inst)
        if fd is None:
            return None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as e:
            os.close(fd)
            if e.errno not in (errno.EWOULDBLOCK, errno.EAGAIN):
                raise
            return None
        return fd

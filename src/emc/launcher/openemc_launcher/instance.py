"""instance: which OPENEMC_INSTANCE a launch uses, held with a lock so two launches never share one.

A launch holds an flock()ed file <tmp>/openemc-linuxcnc-locks/<N>.lock for its whole life (the
lock goes away with the process, so a crash never leaves a stale lock). The file records
"<launcher pid> <INI>"; it is emptied on a clean exit, so a non-empty file under a free lock
names a launcher that died without cleaning up, whose processes and segments are then removed.
"""
import errno
import fcntl
import os
import signal
import tempfile
import time

from . import sysv
from .errors import LaunchError

MAX_INSTANCE = 16777215
LOCK_DIR = "openemc-linuxcnc-locks"
LOCK_BASE = "/tmp"                    # fixed, so launches with different TMPDIRs still meet
POOL_DIR = "openemc-instance-locks"   # the test runners' pool; auto-picked instances take it too
SESSION_VAR = "OPENEMC_LAUNCHER_PID"


def lock_dir(name, base=None):
    """A lock directory shared by all users (mode 1777), else this user's own one."""
    base = base or tempfile.gettempdir()
    path = os.path.join(base, name)
    try:
        os.mkdir(path)
        os.chmod(path, 0o1777)
    except FileExistsError:
        pass
    except OSError:
        path = os.path.join(base, "%s-%d" % (name, os.getuid()))
        os.makedirs(path, mode=0o700, exist_ok=True)
    return path


def open_lock(directory, instance):
    """Open (creating) a lock file, read-write when allowed; (fd, writable) or (None, False)."""
    path = os.path.join(directory, "%d.lock" % instance)
    for flags, writable in ((os.O_RDWR | os.O_CREAT, True), (os.O_RDONLY, False)):
        try:
            fd = os.open(path, flags, 0o666)
        except OSError:
            continue
        try:
            os.fchmod(fd, 0o666)
        except OSError:
            pass
        return fd, writable
    return None, False


def try_lock(directory, instance):
    """flock a lock file without waiting; (fd, writable), or (None, False) when it is held."""
    fd, writable = open_lock(directory, instance)
    if fd is None:
        return None, False
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError as e:
        os.close(fd)
        if e.errno in (errno.EWOULDBLOCK, errno.EAGAIN):
            return None, False
        raise
    return fd, writable


def read_owner(fd):
    """The "pid ini" text a lock file holds ('' when empty)."""
    try:
        return os.pread(fd, 4096, 0).decode(errors="replace").strip()
    except OSError:
        return ""


def owner_of(instance):
    """The "pid ini" text of the launcher holding an instance (for messages)."""
    fd, _ = open_lock(lock_dir(LOCK_DIR, LOCK_BASE), instance)
    if fd is None:
        return ""
    text = read_owner(fd)
    os.close(fd)
    return text


def busy_reason(instance):
    """Why an instance is in use by something other than a linuxcnc launch, or None."""
    if instance in sysv.listening_instances():
        return "an rtapi_app answers in it"
    pids = sysv.rtapi_app_pids(instance)
    if pids:
        return "rtapi_app (pid %s) runs in it" % ", ".join(map(str, pids))
    return None


def session_processes(instance, launcher_pid):
    """Processes started by a given launcher in an instance (marked by SESSION_VAR)."""
    want = ("%s=%d" % (SESSION_VAR, launcher_pid)).encode()
    found = []
    for name in os.listdir("/proc"):
        if not name.isdigit() or int(name) == os.getpid():
            continue
        try:
            with open("/proc/%s/environ" % name, "rb") as f:
                env = f.read().split(b"\0")
        except OSError:
            continue
        if want in env and sysv.process_instance(int(name)) == instance:
            found.append(int(name))
    return found


def pid_alive(pid):
    """True when pid exists."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def kill_processes(pids, grace_s=2.0):
    """SIGTERM pids, then SIGKILL whatever still lives after grace_s."""
    for sig, wait in ((signal.SIGTERM, grace_s), (signal.SIGKILL, 1.0)):
        pids = [p for p in pids if pid_alive(p)]
        for pid in pids:
            try:
                os.kill(pid, sig)
            except OSError:
                pass
        deadline = time.monotonic() + wait
        while time.monotonic() < deadline and any(pid_alive(p) for p in pids):
            time.sleep(0.05)


def clear_leftovers(instance, owner, say):
    """Remove what a launcher that died without cleaning up left in an instance."""
    words = owner.split(None, 1)
    if words and words[0].isdigit() and not pid_alive(int(words[0])):
        pids = session_processes(instance, int(words[0]))
        if pids:
            say("linuxcnc: stopping processes left in OPENEMC_INSTANCE=%d by a linuxcnc that "
                "ended without cleaning up (%s): pid %s" % (instance, owner, pids))
            kill_processes(pids)
    remove_idle_segments(instance, say)


def remove_idle_segments(instance, say, extra_bases=()):
    """Remove the instance's segments nobody is attached to; returns those still attached."""
    left = {}
    for key, (shmid, nattch) in sysv.instance_segments(instance, extra_bases).items():
        if nattch == 0 and sysv.remove_segment(shmid):
            say("linuxcnc: removed stale shared memory key 0x%08x of OPENEMC_INSTANCE=%d"
                % (key, instance))
        else:
            left[key] = nattch
    return left


class InstanceLease:
    """The instance a launch runs in, with the locks that reserve it."""

    def __init__(self, number, fds, writable_fd):
        """number: the instance; fds: lock descriptors held; writable_fd: where the owner goes."""
        self.number, self.fds, self.writable_fd = number, fds, writable_fd

    def record(self, ini_path):
        """Write "<pid> <ini>" into the lock file (names this launch to others)."""
        if self.writable_fd is None:
            return
        os.ftruncate(self.writable_fd, 0)
        os.pwrite(self.writable_fd, ("%d %s\n" % (os.getpid(), ini_path)).encode(), 0)

    def release(self):
        """Empty the lock file (a clean exit) and drop the locks."""
        if self.writable_fd is not None:
            try:
                os.ftruncate(self.writable_fd, 0)
            except OSError:
                pass
        for fd in self.fds:
            os.close(fd)
        self.fds, self.writable_fd = [], None


def parse_instance(text):
    """OPENEMC_INSTANCE as a number 0..MAX_INSTANCE, or a LaunchError."""
    if not text.isdigit() or len(text) > 8 or int(text) > MAX_INSTANCE:
        raise LaunchError("linuxcnc: OPENEMC_INSTANCE='%s' is not a number from 0 to %d"
                          % (text, MAX_INSTANCE))
    return int(text)


def claim_explicit(instance, say):
    """The instance named by OPENEMC_INSTANCE: refused while in use, cleaned when left over."""
    fd, writable = try_lock(lock_dir(LOCK_DIR, LOCK_BASE), instance)
    if fd is None:
        raise LaunchError("linuxcnc: OPENEMC_INSTANCE=%d is in use by another linuxcnc (%s); "
                          "stop it first or choose another OPENEMC_INSTANCE"
                          % (instance, owner_of(instance) or "owner unknown"))
    owner = read_owner(fd)
    if owner:
        clear_leftovers(instance, owner, say)
    reason = busy_reason(instance)
    if reason:
        os.close(fd)
        raise LaunchError("linuxcnc: realtime is already running in OPENEMC_INSTANCE=%d (%s) "
                          "but not for a linuxcnc; stop it with 'halrun -U' in that instance "
                          "or choose another OPENEMC_INSTANCE" % (instance, reason))
    remove_idle_segments(instance, say)
    return InstanceLease(instance, [fd], fd if writable else None)


def instance_free(instance):
    """No socket, no rtapi_app and no segments of this instance exist."""
    return busy_reason(instance) is None and not sysv.instance_segments(instance)


def claim_free():
    """The first free instance from 0 up, with the launcher lock and the test-pool lock held."""
    launch_dir, pool_dir = lock_dir(LOCK_DIR, LOCK_BASE), lock_dir(POOL_DIR)
    for instance in range(MAX_INSTANCE + 1):
        fd, writable = try_lock(launch_dir, instance)
        if fd is None:
            continue
        pool_fd, _ = try_lock(pool_dir, instance)
        if pool_fd is not None and not read_owner(fd) and instance_free(instance):
            return InstanceLease(instance, [fd, pool_fd], fd if writable else None)
        os.close(fd)
        if pool_fd is not None:
            os.close(pool_fd)
    raise LaunchError("linuxcnc: no free OPENEMC_INSTANCE (0..%d are all in use)" % MAX_INSTANCE)


def acquire(environ, say):
    """Claim the instance for this launch: OPENEMC_INSTANCE if set, else the first free one."""
    text = environ.get("OPENEMC_INSTANCE", "")
    if text != "":
        return claim_explicit(parse_instance(text), say)
    return claim_free()

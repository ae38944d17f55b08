"""sysv: SysV shared-memory segments, rtapi_app sockets and processes, seen per instance."""
import ctypes
import os
import re

# Base keys of the segments a session may leave (instance_key() gives each instance's own).
HAL_KEYS = (0x48414C32, 0x90280A48, 0x48484C34)      # HAL, RTAPI, id counter
OTHER_KEYS = (0x130CF406, 0x434C522B, 0x00544F4C)    # halscope, classicladder, tool data
FIFO_NAME = re.compile(r"/\.rtapi_fifo(?:\.(\d+))?$")
IPC_RMID = 0


def instance_key(base, instance):
    """The key an instance uses for a base key: instances 0..255 XOR their number into the top
    byte, larger ones XOR (number << 8 | 0xA5), as rtapi_instance_key() does."""
    if instance <= 255:
        return (base ^ (instance << 24)) & 0xFFFFFFFF
    return (base ^ (instance << 8 | 0xA5)) & 0xFFFFFFFF


def segments():
    """key -> (shmid, nattch) of every SysV shared-memory segment on the machine."""
    found = {}
    try:
        with open("/proc/sysvipc/shm") as f:
            next(f)
            for line in f:
                col = line.split()
                found[int(col[0]) & 0xFFFFFFFF] = (int(col[1]), int(col[6]))
    except (OSError, StopIteration):
        pass
    return found


def remove_segment(shmid):
    """Mark a segment for removal (it goes when the last process detaches); True on success."""
    libc = ctypes.CDLL(None, use_errno=True)
    return libc.shmctl(ctypes.c_int(shmid), ctypes.c_int(IPC_RMID), None) == 0


def listening_instances():
    """Instances whose rtapi_app socket (@<home>/.rtapi_fifo[.N]) exists, for any user."""
    found = set()
    try:
        with open("/proc/net/unix") as f:
            for line in f:
                col = line.split()
                if len(col) >= 8 and col[-1].startswith("@"):
                    match = FIFO_NAME.search(col[-1])
                    if match:
                        found.add(int(match.group(1) or 0))
    except OSError:
        pass
    return found


def process_instance(pid):
    """The OPENEMC_INSTANCE a process runs in (0 when unset), or None if unreadable."""
    try:
        with open("/proc/%d/environ" % pid, "rb") as f:
            env = f.read().split(b"\0")
    except OSError:
        return None
    for item in env:
        if item.startswith(b"OPENEMC_INSTANCE="):
            text = item.split(b"=", 1)[1].decode(errors="replace")
            return int(text) if text.isdigit() else 0
    return 0


def rtapi_app_pids(instance):
    """Live rtapi_app processes of an instance (only those whose environment we may read)."""
    pids = []
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open("/proc/%s/comm" % name) as f:
                if f.read().strip() != "rtapi_app":
                    continue
        except OSError:
            continue
        if process_instance(int(name)) == instance:
            pids.append(int(name))
    return pids


def instance_segments(instance, extra_bases=()):
    """key -> (shmid, nattch) of the segments an instance holds (HAL, RTAPI, others, extra)."""
    segs = segments()
    bases = HAL_KEYS + OTHER_KEYS + tuple(extra_bases)
    keys = {instance_key(b, instance) for b in bases}
    return {k: v for k, v in segs.items() if k in keys}

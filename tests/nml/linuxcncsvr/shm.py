#!/usr/bin/env python3
"""shm.py: SysV helper for the linuxcncsvr test: exists/create/remove KEY, key BASE (this instance)."""
import ctypes
import os
import sys

libc = ctypes.CDLL(None, use_errno=True)


def instance_key(base):
    """The key this instance uses for a base key (base ^ instance << 24)."""
    inst = int(os.environ.get("OPENEMC_INSTANCE", "0"))
    if inst > 255:
        inst = 1 + inst % 255
    return base ^ (inst << 24)


def main():
    """Dispatch one command."""
    cmd, key = sys.argv[1], int(sys.argv[2], 0)
    if cmd == "key":
        print("0x%08x" % instance_key(key))
        return 0
    key = instance_key(key)
    shmid = libc.shmget(ctypes.c_int(key - (1 << 32) if key >= 1 << 31 else key), 0, 0o600)
    if cmd == "exists":
        print("0x%08x %s" % (key, "exists" if shmid >= 0 else "absent"))
    elif cmd == "create":
        shmid = libc.shmget(ctypes.c_int(key - (1 << 32) if key >= 1 << 31 else key), 4096,
                            0o1000 | 0o600)
        print("created foreign segment" if shmid >= 0 else "create failed")
    elif cmd == "remove" and shmid >= 0:
        libc.shmctl(shmid, 0, None)
    return 0


sys.exit(main())

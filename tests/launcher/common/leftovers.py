#!/usr/bin/env python3
"""leftovers.py [INSTANCE...]: print 'clean' when an instance has no rtapi_app, no test-double or
task process and no HAL/NML/motion segment left, else list what remains (exit 1)."""
import os
import sys

from openemc_launcher import sysv

NML_KEYS = (1001, 1002, 1003, 100, 0x544F4C)


SESSION_PROGRAMS = ("launcher_test_task", "linuxcncsvr", "linuxcnc", "rtapi_app",
                    "hal_manualtoolchange")


def explicit_instance(pid):
    """The OPENEMC_INSTANCE in a process's environment, or None when it has none."""
    try:
        with open("/proc/%d/environ" % pid, "rb") as f:
            for item in f.read().split(b"\0"):
                if item.startswith(b"OPENEMC_INSTANCE="):
                    text = item.split(b"=", 1)[1]
                    return int(text) if text.isdigit() else None
    except OSError:
        pass
    return None


def processes(instance):
    """Session programs (by program name, not text) still running in an instance."""
    found = []
    for name in os.listdir("/proc"):
        if not name.isdigit() or int(name) == os.getpid():
            continue
        try:
            with open("/proc/%s/cmdline" % name, "rb") as f:
                argv = [a.decode(errors="replace") for a in f.read().split(b"\0") if a]
        except OSError:
            continue
        programs = {os.path.basename(a) for a in argv[:2]}
        if programs & set(SESSION_PROGRAMS) and explicit_instance(int(name)) == instance:
            found.append("%s %s" % (name, " ".join(argv)))
    return found


def main(argv):
    """Check each instance given (default: $OPENEMC_INSTANCE)."""
    instances = [int(a) for a in argv] or [int(os.environ.get("OPENEMC_INSTANCE", "0"))]
    left = []
    for instance in instances:
        left += processes(instance)
        left += ["segment 0x%08x" % k
                 for k in sysv.instance_segments(instance, NML_KEYS)]
    print("clean" if not left else "left over:\n  " + "\n  ".join(left))
    return 0 if not left else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

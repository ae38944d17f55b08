#!/usr/bin/env python3
"""leftovers.py [INSTANCE...]: print 'clean' when an instance has no rtapi_app, no test-double or
task process and no HAL/NML/motion segment left, else list what remains (exit 1)."""
import os
import sys

from openemc_launcher import sysv

NML_KEYS = (1001, 1002, 1003, 100, 0x544F4C)


def processes(instance):
    """Launcher-session processes still running in an instance."""
    found = []
    for name in os.listdir("/proc"):
        if not name.isdigit() or int(name) == os.getpid():
            continue
        try:
            with open("/proc/%s/cmdline" % name, "rb") as f:
                cmd = f.read().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        if sysv.process_instance(int(name)) != instance:
            continue
        if any(word in cmd for word in ("launcher_test_task", "linuxcncsvr", "bin/linuxcnc ",
                                        "rtapi_app", "hal_manualtoolchange")):
            found.append("%s %s" % (name, cmd.strip()))
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

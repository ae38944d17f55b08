"""taskui: helpers the task tests' display scripts share (connect, wait, home, report)."""
import sys
import time

import linuxcnc

c = linuxcnc.command()
s = linuxcnc.stat()
e = linuxcnc.error_channel()
OUT = open("ui.out", "w")


def say(*words):
    """One line of the test's result."""
    print(*words, file=OUT, flush=True)


def errors():
    """Every message waiting on the error channel, as text."""
    got = []
    while True:
        m = e.poll()
        if not m:
            return got
        got.append(m[1].strip())


def wait(cond, timeout=10.0, what="condition"):
    """Poll status until cond(s) holds; fail the test on timeout."""
    end = time.time() + timeout
    while time.time() < end:
        s.poll()
        if cond(s):
            return
        time.sleep(0.01)
    say("TIMEOUT waiting for", what, "pos", pos(), "state", s.task_state, "mode", s.task_mode,
        "interp", s.interp_state, "exec", s.exec_state, "rcs", s.state, "errors", errors())
    sys.exit(1)


def machine_on():
    c.state(linuxcnc.STATE_ESTOP_RESET)
    c.wait_complete()
    c.state(linuxcnc.STATE_ON)
    c.wait_complete()
    wait(lambda st: st.task_state == linuxcnc.STATE_ON, what="machine on")


def home_all():
    c.mode(linuxcnc.MODE_MANUAL)
    c.wait_complete()
    c.home(-1)
    c.wait_complete()
    wait(lambda st: all(st.homed[:st.joints]), timeout=30, what="homing")


def mdi(text, timeout=10):
    """Run one MDI command to completion; its wait_complete result."""
    s.poll()
    if s.task_mode != linuxcnc.MODE_MDI:
        c.mode(linuxcnc.MODE_MDI)
        c.wait_complete()
    c.mdi(text)
    return c.wait_complete(timeout)


def pos(axes=3):
    s.poll()
    return tuple(round(v, 4) for v in s.position[:axes])

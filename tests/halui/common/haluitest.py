"""haluitest.py: helpers of the halui tests: pin access, button presses that wait until halui
has seen them, and waits on task's status (never a fixed sleep)."""
import sys
import time

import hal
import linuxcnc

stat = linuxcnc.stat()
command = linuxcnc.command()
errors = linuxcnc.error_channel()
TIMEOUT_S = 20.0


def fail(what):
    """End the test with a message."""
    print("FAIL: %s" % what)
    sys.exit(1)


def get(name):
    """Value of a pin."""
    return hal.get_value(name)


def setp(name, value):
    """Set an input pin as halcmd setp does."""
    hal.set_p(name, str(value))


def wait_for(cond, what):
    """Poll cond() (the status is polled first) until it holds; fail after TIMEOUT_S."""
    end = time.time() + TIMEOUT_S
    while time.time() < end:
        stat.poll()
        if cond():
            return
        time.sleep(0.005)
    fail("timed out waiting for " + what)


_beat = [0]


def sync():
    """Return once halui has run at least one whole cycle after this call. halui copies
    halui.axis.jog-speed-angular to halui.gui.jog-rate-angular in the middle of each cycle
    (the test machine has no angular axis, so the value is not used); seeing two new values
    arrive proves a complete cycle in between."""
    for _ in range(2):
        _beat[0] = 1 + (_beat[0] % 1000)
        value = float(_beat[0])
        setp("halui.axis.jog-speed-angular", value)
        wait_for(lambda: get("halui.gui.jog-rate-angular") == value, "a halui cycle")


def press(name):
    """A button press halui is sure to see: high for a cycle, then low for a cycle."""
    setp(name, 1)
    sync()
    setp(name, 0)
    sync()


def hold(name, value):
    """Set a level input and wait until halui has seen it."""
    setp(name, value)
    sync()


def messages():
    """Every message waiting on the error channel."""
    out = []
    while True:
        m = errors.poll()
        if not m:
            return out
        out.append(m[1].strip())


def show(*pins):
    """Print pins as name=value (after a halui cycle, so they show the latest status)."""
    sync()
    print(" ".join("%s=%s" % (p.replace("halui.", ""), fmt(get(p))) for p in pins))


def fmt(v):
    """Stable text of a pin value."""
    if isinstance(v, bool):
        return str(v)
    if isinstance(v, float):
        return "%.4f" % v
    return str(v)

"""spindle_test.py: halui's spindle pins; without an S word start/forward/reverse use 500 rpm."""
import linuxcnc
from haluitest import stat, press, show, wait_for


def speed(n):
    return stat.spindle[n]["speed"]


def state(n):
    """The spindle pins of spindle n."""
    p = "halui.spindle.%d." % n
    show(p + "is-on", p + "runs-forward", p + "runs-backward", p + "brake-is-on")


press("halui.estop.reset")
press("halui.machine.on")
wait_for(lambda: stat.task_state == linuxcnc.STATE_ON, "machine on")
state(0)
for pin, want in (("forward", 500), ("increase", 600), ("increase", 700), ("decrease", 600),
                  ("reverse", -500), ("decrease", -400), ("stop", 0), ("start", 500)):
    press("halui.spindle.0." + pin)
    wait_for(lambda: speed(0) == want, "spindle 0 at %d rpm after %s" % (want, pin))
    print("%s: %d rpm" % (pin, speed(0)))
    state(0)
print("== spindle 1 is separate")
press("halui.spindle.1.reverse")
wait_for(lambda: speed(1) == -500, "spindle 1 reverse")
state(0)
state(1)
press("halui.spindle.1.stop")
press("halui.spindle.0.stop")
wait_for(lambda: speed(0) == 0 and speed(1) == 0, "both stopped")
print("== brake")
press("halui.spindle.0.brake-off")
wait_for(lambda: stat.spindle[0]["brake"] == 0, "brake released")
state(0)
press("halui.spindle.0.brake-on")
wait_for(lambda: stat.spindle[0]["brake"] == 1, "brake engaged")
state(0)

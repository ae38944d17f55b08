"""overrides_test.py: halui's feed, rapid, spindle and max-velocity override knobs."""
from haluitest import stat, press, hold, show, wait_for, get


def settle(attr, value):
    """Wait until the status attribute shows value, then print the knob's value pin."""
    wait_for(lambda: abs(attr() - value) < 1e-9, "override %.4f" % value)


def feed():
    return stat.feedrate


print("== feed override: scale 0.1, limits 0..1.5 ([DISPLAY]MAX_FEED_OVERRIDE)")
hold("halui.feed-override.scale", 0.1)
for step, want in (("increase", 1.1), ("increase", 1.2), ("decrease", 1.1)):
    press("halui.feed-override." + step)
    settle(feed, want)
    show("halui.feed-override.value")
for _ in range(6):
    press("halui.feed-override.increase")
settle(feed, 1.5)
show("halui.feed-override.value")
press("halui.feed-override.reset")
settle(feed, 1.0)
show("halui.feed-override.value")
print("== counts, relative")
hold("halui.feed-override.counts", -3)
settle(feed, 0.7)
show("halui.feed-override.value")
hold("halui.feed-override.count-enable", 0)
hold("halui.feed-override.counts", -20)
show("halui.feed-override.value")
hold("halui.feed-override.count-enable", 1)
hold("halui.feed-override.counts", -18)
settle(feed, 0.9)
show("halui.feed-override.value")
hold("halui.feed-override.counts", -100)
settle(feed, 0.0)
show("halui.feed-override.value")
print("== counts, direct value")
hold("halui.feed-override.scale", 0.01)
hold("halui.feed-override.direct-value", 1)
hold("halui.feed-override.counts", 75)
settle(feed, 0.75)
show("halui.feed-override.value")
hold("halui.feed-override.counts", 400)
settle(feed, 1.5)
show("halui.feed-override.value")

print("== rapid override: limit 1.0")
hold("halui.rapid-override.scale", 0.25)
press("halui.rapid-override.decrease")
settle(lambda: stat.rapidrate, 0.75)
show("halui.rapid-override.value")
press("halui.rapid-override.increase")
press("halui.rapid-override.increase")
settle(lambda: stat.rapidrate, 1.0)
show("halui.rapid-override.value")

print("== spindle 1 override: limits 0.5..1.2")
hold("halui.spindle.1.override.scale", 0.3)
press("halui.spindle.1.override.decrease")
settle(lambda: stat.spindle[1]["override"], 0.7)
press("halui.spindle.1.override.decrease")
settle(lambda: stat.spindle[1]["override"], 0.5)
show("halui.spindle.0.override.value", "halui.spindle.1.override.value")
hold("halui.spindle.1.override.counts", 1)
settle(lambda: stat.spindle[1]["override"], 0.8)
press("halui.spindle.1.override.reset")
settle(lambda: stat.spindle[1]["override"], 1.0)
show("halui.spindle.0.override.value", "halui.spindle.1.override.value")

print("== max velocity: limit [TRAJ]MAX_LINEAR_VELOCITY 5, no reset pin")
hold("halui.max-velocity.scale", 2.0)
press("halui.max-velocity.decrease")
settle(lambda: stat.max_velocity, 3.0)
show("halui.max-velocity.value")
hold("halui.max-velocity.direct-value", 1)
hold("halui.max-velocity.counts", 1)
settle(lambda: stat.max_velocity, 2.0)
hold("halui.max-velocity.counts", 10)
settle(lambda: stat.max_velocity, 5.0)
show("halui.max-velocity.value")

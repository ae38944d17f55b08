"""jog_test.py: halui's joint and axis jog pins (speeds in machine units per minute)."""
import linuxcnc
from haluitest import stat, press, hold, show, wait_for, get, messages, sync


def pos(i):
    """Axis position i (feedback)."""
    return stat.actual_position[i]


def settles(i):
    """Wait until axis i stops moving (two polls a few halui cycles apart agree)."""
    def still():
        before = pos(i)
        sync()
        stat.poll()
        return abs(pos(i) - before) < 1e-9
    wait_for(still, "axis %d to stop" % i)


press("halui.estop.reset")
press("halui.machine.on")
wait_for(lambda: stat.task_state == linuxcnc.STATE_ON, "machine on")

print("== joint jogs before homing (joint mode)")
show("halui.mode.is-joint", "halui.mode.is-teleop")
hold("halui.joint.jog-speed", 60.0)
hold("halui.joint.1.plus", 1)
wait_for(lambda: stat.joint_position[1] > 0.05, "joint 1 to move +")
hold("halui.joint.1.plus", 0)
settles(1)
print("joint 1 moved plus:", stat.joint_position[1] > 0.05)
start = stat.joint_position[1]
hold("halui.joint.1.minus", 1)
wait_for(lambda: stat.joint_position[1] < start - 0.05, "joint 1 to move -")
hold("halui.joint.1.minus", 0)
settles(1)
print("joint 1 moved minus:", stat.joint_position[1] < start)
print("== joint analog and deadband")
hold("halui.joint.jog-deadband", 0.2)
start = stat.joint_position[2]
hold("halui.joint.2.analog", 0.5)
wait_for(lambda: stat.joint_position[2] > start + 0.05, "joint 2 analog jog")
hold("halui.joint.2.analog", 0.1)
settles(2)
print("joint 2 analog 0.5 moved, 0.1 (inside the deadband) stopped")
print("== selected joint")
hold("halui.joint.0.select", 1)
hold("halui.joint.0.select", 0)
show("halui.joint.selected", "halui.joint.0.is-selected", "halui.joint.1.is-selected")
start = stat.joint_position[0]
hold("halui.joint.selected.plus", 1)
wait_for(lambda: stat.joint_position[0] > start + 0.05, "selected joint 0 to move")
hold("halui.joint.selected.plus", 0)
settles(0)
print("selected joint 0 moved")
print("== axis jog in joint mode is not sent")
start = pos(0)
hold("halui.axis.jog-speed", 60.0)
hold("halui.axis.x.increment", 0.5)
press("halui.axis.x.increment-plus")
print("x unchanged:", abs(pos(0) - start) < 1e-9, "messages:", messages())

print("== home, teleop")
press("halui.home-all")
wait_for(lambda: all(stat.homed[:3]), "homing")
press("halui.mode.manual")
press("halui.mode.teleop")
wait_for(lambda: stat.motion_mode == linuxcnc.TRAJ_MODE_TELEOP, "teleop")
show("halui.mode.is-joint", "halui.mode.is-teleop")
print("== axis increments")
hold("halui.axis.jog-speed", 120.0)
hold("halui.axis.y.increment", 0.25)
press("halui.axis.y.increment-plus")
wait_for(lambda: abs(pos(1) - 0.25) < 1e-6, "y at 0.25")
show("halui.axis.y.pos-feedback", "halui.axis.y.pos-commanded", "halui.axis.y.pos-relative")
press("halui.axis.y.increment-minus")
wait_for(lambda: abs(pos(1)) < 1e-6, "y at 0")
show("halui.axis.y.pos-feedback")
print("== axis plus/minus and analog")
hold("halui.axis.x.plus", 1)
wait_for(lambda: pos(0) > 0.05, "x to move +")
hold("halui.axis.x.plus", 0)
settles(0)
print("x moved plus:", pos(0) > 0.05)
hold("halui.axis.jog-deadband", 0.1)
start = pos(2)
hold("halui.axis.z.analog", -0.5)
wait_for(lambda: pos(2) < start - 0.05, "z analog jog -")
hold("halui.axis.z.analog", 0.0)
settles(2)
print("z moved minus:", pos(2) < start)
print("== selected axis")
hold("halui.axis.z.select", 1)
hold("halui.axis.z.select", 0)
show("halui.axis.selected", "halui.axis.x.is-selected", "halui.axis.z.is-selected")
start = pos(2)
hold("halui.axis.selected.increment", 0.5)
press("halui.axis.selected.increment-plus")
wait_for(lambda: abs(pos(2) - (start + 0.5)) < 1e-6, "z +0.5")
print("z moved by 0.5")
print("== joint jog in teleop mode is not sent")
start = stat.joint_position[1]
hold("halui.joint.1.plus", 1)
hold("halui.joint.1.plus", 0)
print("joint 1 unchanged:", abs(stat.joint_position[1] - start) < 1e-9, "messages:", messages())

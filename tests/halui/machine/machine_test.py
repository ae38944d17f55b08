"""machine_test.py: halui's machine, E-stop, mode, coolant, program-flag, abort and homing pins."""
import linuxcnc
from haluitest import stat, command, press, show, wait_for, get, messages

print("== start")
show("halui.estop.is-activated", "halui.machine.is-on", "halui.machine.units-per-mm")

print("== estop reset, machine on")
press("halui.estop.reset")
wait_for(lambda: stat.task_state == linuxcnc.STATE_ESTOP_RESET, "ESTOP_RESET")
show("halui.estop.is-activated", "halui.machine.is-on")
press("halui.machine.on")
wait_for(lambda: stat.task_state == linuxcnc.STATE_ON, "STATE_ON")
wait_for(lambda: get("halui.machine.is-on"), "machine.is-on")
show("halui.estop.is-activated", "halui.machine.is-on")

print("== machine off, E-stop")
press("halui.machine.off")
wait_for(lambda: stat.task_state == linuxcnc.STATE_ESTOP_RESET, "machine off")
wait_for(lambda: not get("halui.machine.is-on"), "machine.is-on FALSE")
show("halui.estop.is-activated", "halui.machine.is-on")
press("halui.estop.activate")
wait_for(lambda: stat.task_state == linuxcnc.STATE_ESTOP, "ESTOP")
wait_for(lambda: get("halui.estop.is-activated"), "estop.is-activated")
show("halui.estop.is-activated", "halui.machine.is-on")
press("halui.estop.reset")
press("halui.machine.on")
wait_for(lambda: get("halui.machine.is-on"), "machine on again")

print("== modes")
for pin, mode, out in (("halui.mode.mdi", linuxcnc.MODE_MDI, "halui.mode.is-mdi"),
                       ("halui.mode.auto", linuxcnc.MODE_AUTO, "halui.mode.is-auto"),
                       ("halui.mode.manual", linuxcnc.MODE_MANUAL, "halui.mode.is-manual")):
    press(pin)
    wait_for(lambda: stat.task_mode == mode and get(out), pin)
    show("halui.mode.is-manual", "halui.mode.is-auto", "halui.mode.is-mdi", "halui.mode.is-joint",
         "halui.mode.is-teleop")

print("== coolant")
for pin, attr, value in (("halui.mist.on", "mist", 1), ("halui.flood.on", "flood", 1),
                         ("halui.mist.off", "mist", 0), ("halui.flood.off", "flood", 0)):
    press(pin)
    wait_for(lambda: getattr(stat, attr) == value, pin)
    show("halui.mist.is-on", "halui.flood.is-on")

print("== optional stop and block delete")
for pin, attr, value in (("halui.program.optional-stop.off", "optional_stop", 0),
                         ("halui.program.block-delete.off", "block_delete", 0),
                         ("halui.program.optional-stop.on", "optional_stop", 1),
                         ("halui.program.block-delete.on", "block_delete", 1)):
    press(pin)
    wait_for(lambda: getattr(stat, attr) == value, pin)
    show("halui.program.optional-stop.is-on", "halui.program.block-delete.is-on")
show("halui.program.is-idle", "halui.program.is-running", "halui.program.is-paused")

print("== homing")
press("halui.joint.0.home")
wait_for(lambda: stat.homed[0] and get("halui.joint.0.is-homed"), "joint 0 homed")
show("halui.joint.0.is-homed", "halui.joint.1.is-homed", "halui.joint.2.is-homed")
press("halui.home-all")
wait_for(lambda: all(stat.homed[:3]) and get("halui.joint.2.is-homed"), "all homed")
show("halui.joint.0.is-homed", "halui.joint.1.is-homed", "halui.joint.2.is-homed")
press("halui.mode.joint")
wait_for(lambda: stat.motion_mode == linuxcnc.TRAJ_MODE_FREE and get("halui.mode.is-joint"), "joint mode")
press("halui.joint.2.select")
press("halui.joint.selected.unhome")
wait_for(lambda: not stat.homed[2] and not get("halui.joint.2.is-homed"), "joint 2 unhomed")
show("halui.joint.selected", "halui.joint.2.is-selected", "halui.joint.selected.is-homed",
     "halui.joint.2.is-homed")

print("== abort and program stop end an MDI dwell")
press("halui.home-all")
wait_for(lambda: all(stat.homed[:3]), "all homed")
command.mode(linuxcnc.MODE_MDI)
command.wait_complete()
for pin in ("halui.abort", "halui.program.stop"):
    command.mdi("G4 P30")
    wait_for(lambda: stat.interp_state != linuxcnc.INTERP_IDLE, "the dwell to start")
    show("halui.program.is-idle", "halui.program.is-running")
    press(pin)
    wait_for(lambda: stat.interp_state == linuxcnc.INTERP_IDLE and get("halui.program.is-idle"), pin)
    show("halui.program.is-idle", "halui.program.is-running")
print("messages:", messages())

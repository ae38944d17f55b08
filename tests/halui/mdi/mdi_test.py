"""mdi_test.py: halui's MDI command pins against the responder."""
import linuxcnc
from haluitest import stat, command, press, hold, show, wait_for, get, messages


def mode():
    return {linuxcnc.MODE_MANUAL: "MANUAL", linuxcnc.MODE_MDI: "MDI", linuxcnc.MODE_AUTO: "AUTO"}[stat.task_mode]


print("== machine off: not run")
press("halui.mdi-command-00")
show("halui.halui-mdi-is-running")
stat.poll()
print("mode", mode(), "x %.3f" % stat.actual_position[0])

press("halui.estop.reset")
press("halui.machine.on")
press("halui.home-all")
wait_for(lambda: all(stat.homed[:3]), "homing")
print("== from MANUAL: G0 X1, back to MANUAL")
press("halui.mdi-command-00")
wait_for(lambda: abs(stat.actual_position[0] - 1) < 1e-6, "x at 1")
wait_for(lambda: stat.task_mode == linuxcnc.MODE_MANUAL and not get("halui.halui-mdi-is-running"),
         "return to manual")
show("halui.halui-mdi-is-running", "halui.mode.is-manual")
print("== a dwell: MDI mode and is-running while it runs")
hold("halui.mdi-command-01", 1)
wait_for(lambda: stat.interp_state != linuxcnc.INTERP_IDLE, "the dwell")
show("halui.halui-mdi-is-running", "halui.mode.is-mdi")
hold("halui.mdi-command-01", 0)
wait_for(lambda: stat.task_mode == linuxcnc.MODE_MANUAL and not get("halui.halui-mdi-is-running"),
         "return to manual after the dwell")
show("halui.halui-mdi-is-running", "halui.mode.is-manual")
print("== from MDI mode: stays in MDI")
command.mode(linuxcnc.MODE_MDI)
command.wait_complete()
press("halui.mdi-command-02")
wait_for(lambda: abs(stat.actual_position[0]) < 1e-6 and stat.interp_state == linuxcnc.INTERP_IDLE,
         "x at 0")
show("halui.halui-mdi-is-running", "halui.mode.is-mdi")
print("messages:", messages())

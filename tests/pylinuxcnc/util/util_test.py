"""util_test.py: linuxcnc_util helpers against a running machine (hallib.md sec. 3)."""
import linuxcnc
import linuxcnc_util

lc = linuxcnc_util.LinuxCNC()
print("startup:", lc.wait_for_linuxcnc_startup())
lc.command.state(linuxcnc.STATE_ESTOP_RESET)
lc.command.state(linuxcnc.STATE_ON)
lc.command.mode(linuxcnc.MODE_MANUAL)
lc.command.home(-1)
print("homed:", lc.wait_for_home([1, 1, 1, 0, 0, 0, 0, 0, 0]))
print("all_joints_homed:", lc.all_joints_homed([1, 1, 1, 0, 0, 0, 0, 0, 0]))
lc.command.mode(linuxcnc.MODE_MANUAL)
lc.command.wait_complete()
lc.jog_axis("x", 0.3, vel=2.0)
lc.status.poll()
print("x past target:", lc.status.position[0] > 0.3)
lc.command.jog(linuxcnc.JOG_INCREMENT, 0, 1, 2.0, 0.25)
print(lc.wait_for_axis_to_stop_at("y", 0.25))
print("interp idle:", lc.wait_for_interp_state(linuxcnc.INTERP_IDLE))
print("tool in spindle:", lc.wait_for_tool_in_spindle(0, timeout=1))
for call in (lambda: lc.wait_for_interp_state(linuxcnc.INTERP_PAUSED, timeout=0.2),
             lambda: lc.wait_for_tool_in_spindle(7, timeout=0.3),
             lambda: lc.wait_for_axis_to_stop_at("z", 5.0, timeout=0.3),
             lambda: linuxcnc_util.axis_index("q")):
    try:
        call()
    except Exception as e:  # noqa: BLE001 - prints the class the helper raises
        print(type(e).__name__ + ":", str(e).split("\n")[0])
print("exception class:", issubclass(linuxcnc_util.LinuxCNC_Exception, Exception))

#!/usr/bin/env python3
import os
import sys
import time
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import hal  # noqa: E402
from taskui import c, s, say, errors, wait, machine_on, home_all, mdi, pos, linuxcnc  # noqa: E402

# refused while in E-stop: a command that needs the machine on
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()
c.spindle(linuxcnc.SPINDLE_FORWARD, 100)
say("spindle in estop", c.wait_complete(), errors())
c.state(linuxcnc.STATE_ON)
c.wait_complete()
s.poll()
say("on while estop ->", s.task_state)
c.state(linuxcnc.STATE_ESTOP_RESET)
c.wait_complete()
s.poll()
say("reset ->", s.task_state, "user-enable-out", hal.get_value("iocontrol.0.user-enable-out"))
machine_on()
say("on ->", s.task_state, "enabled", s.enabled)

# MDI before homing
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()
c.mdi("G0 X1")
say("mdi unhomed", c.wait_complete(), errors())
c.mode(linuxcnc.MODE_MANUAL)
c.wait_complete()
c.home(-1)
c.mdi("G0 X1")
say("mdi while homing", c.wait_complete(), errors())
wait(lambda st: all(st.homed[:3]), timeout=30, what="homing")
say("homed", s.homed[:3], "pos", pos())
# a home command stays executing until its homing ends: wait_complete() returns homed
c.teleop_enable(0)
c.wait_complete()
c.unhome(-1)
c.wait_complete()
say("unhomed", s.poll() or s.homed[:3])
c.home(-1)
say("home + wait_complete", c.wait_complete(15), s.poll() or s.homed[:3], errors())

# MDI queue: three moves sent at once run in order
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()
for t in ("G0 X1 Y1", "G4 P0.2", "G1 X2 Y0.5 F600"):
    c.mdi(t)
s.poll()
say("queued", s.queued_mdi_commands >= 1, "interp", s.interp_state)
wait(lambda st: st.interp_state == linuxcnc.INTERP_IDLE and st.queued_mdi_commands == 0 and st.state == linuxcnc.RCS_DONE,
     what="mdi queue")
say("after queue", pos(), "command", repr(s.command))
r = mdi("G1 X1 F0")
s.poll()
say("bad gcode", r, errors(), "errcode", s.interpreter_errcode)
say("m2 in mdi", mdi("M2"), errors())
say("comment", mdi("(just a comment)"))

# mode change refused while a program reads: nothing here; plain mode switches
c.mode(linuxcnc.MODE_MANUAL)
c.wait_complete()
s.poll()
say("manual ->", s.task_mode, "motion_mode", s.motion_mode)
c.jog(linuxcnc.JOG_INCREMENT, False, 0, 5.0, 0.5)
c.wait_complete()
wait(lambda st: abs(st.position[0] - 2.5) < 1e-6 and st.inpos, what="jog")
say("jog X+0.5 ->", pos())
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()
say("jog in MDI accepted", c.wait_complete())
c.home(0)
say("home in MDI", c.wait_complete(), errors())

# overrides, coolant, spindle
c.feedrate(0.5)
c.maxvel(4.0)
c.flood(linuxcnc.FLOOD_ON)
c.mist(linuxcnc.MIST_ON)
c.spindle(linuxcnc.SPINDLE_FORWARD, 1200)
c.wait_complete()
time.sleep(0.05)
s.poll()
say("feedrate", s.feedrate, "max_velocity", s.max_velocity, "flood", s.flood, "mist", s.mist,
    "coolant pin", hal.get_value("iocontrol.0.coolant-flood"))
say("spindle", s.spindle[0]["speed"], s.spindle[0]["direction"], "pin", hal.get_value("spindle.0.speed-out"))
c.spindle(linuxcnc.SPINDLE_OFF)
c.flood(linuxcnc.FLOOD_OFF)
c.wait_complete()
s.poll()
say("spindle off", s.spindle[0]["direction"], "flood", s.flood)

# E-stop: machine off, program state reset, joints stay homed
c.state(linuxcnc.STATE_ESTOP)
c.wait_complete()
s.poll()
say("estop ->", s.task_state, "enabled", s.enabled, "homed", s.homed[:3], "mode", s.task_mode)
say("errors left", errors())

#!/usr/bin/env python3
import os
import sys
import time
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import hal  # noqa: E402
from taskui import c, s, say, errors, wait, machine_on, home_all, mdi, pos, linuxcnc  # noqa: E402

s.poll()
say("startup code G64 P:", s.settings[3])
machine_on()
home_all()
say("M101 P3 Q4.5", mdi("M101 P3 Q4.5"))
say("M102 (none)", mdi("M102"), errors())
say("M66 timeout", mdi("M66 P0 L3 Q0.2"), mdi("(DEBUG, #5399)"), errors())
hal.set_p("motion.digital-in-00", "1")
say("M66 high", mdi("M66 P0 L3 Q1"), mdi("(DEBUG, #5399)"), errors())
say("M66 E0 immediate", mdi("M66 E0 L0"), mdi("(DEBUG, #5399)"), errors())
# an immediate output shows in the status as soon as the MDI command is acknowledged
for cmd in ("M64 P1", "M68 E1 Q2.5", "M65 P1"):
    c.mdi(cmd)
    s.poll()
    say(cmd, "dout1", s.dout[1], "aout1", round(s.aout[1], 3))
c.wait_complete()
say("G38.3 no contact", mdi("G38.3 Z-0.5 F30"), mdi("(DEBUG, #5070 #5063)"), errors(), pos())
r = mdi("G38.2 Z-1 F30")
time.sleep(0.1)
say("G38.2 no contact", r, errors())
hal.set_p("motion.probe-input", "1")
wait(lambda st: st.probe_val == 1, what="probe input")
r = mdi("G38.2 Z-1.5 F30")
time.sleep(0.5)
say("G38.2 tripped", r, errors(), pos())
hal.set_p("motion.probe-input", "0")
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()
c.mdi("G4 P5")
time.sleep(0.2)
c.abort()
c.wait_complete()
time.sleep(0.1)
say("abort during G4", errors())
c.mdi("G1 X5 F60")
time.sleep(0.3)
hal.set_p("joint.0.pos-lim-sw-in", "1")
wait(lambda st: st.task_state != linuxcnc.STATE_ON, what="limit fault")
time.sleep(0.1)
say("limit switch: state", s.task_state, "interp", s.interp_state, errors())

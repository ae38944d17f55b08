#!/usr/bin/env python3
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from taskui import c, s, say, errors, wait, linuxcnc  # noqa: E402

c.state(linuxcnc.STATE_ESTOP_RESET)
c.state(linuxcnc.STATE_ON)
c.mode(linuxcnc.MODE_AUTO)
c.wait_complete()
c.program_open("part.ngc")
c.auto(linuxcnc.AUTO_RUN, 0)
wait(lambda st: st.interp_state == linuxcnc.INTERP_IDLE and st.state == linuxcnc.RCS_DONE, what="program")
c.mode(linuxcnc.MODE_MANUAL)
c.wait_complete()
c.jog(linuxcnc.JOG_INCREMENT, True, 0, 2.0, 0.5)
c.jog(linuxcnc.JOG_CONTINUOUS, False, 1, -1.5)
c.jog(linuxcnc.JOG_STOP, False, 1)
c.home(0)
c.unhome(-1)
c.feedrate(0.5)
c.rapidrate(0.25)
c.maxvel(3.0)
c.state(linuxcnc.STATE_OFF)
c.wait_complete()
say("errors", errors())

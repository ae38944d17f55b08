#!/usr/bin/env python3
"""Feed hold with a full queue: 10000 short moves start under motion.feed-inhibit. Task fills the
planner and then waits for room (the moves motion cannot take stay in task's list; they must not
fill the command ring and fail with 'not queued'), however long the hold; released, the program
runs to its end at the programmed end point."""
import math
import os
import sys
import time
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import hal  # noqa: E402
import linuxcnc  # noqa: E402
from taskui import c, s, say, errors, wait, machine_on, pos  # noqa: E402

MOVES = 10000
with open("prog.ngc", "w") as f:
    f.write("G21 G90 G64 F9999\nG0 X1 Y0 Z0\n")
    for i in range(1, MOVES + 1):
        a = 2 * math.pi * i / MOVES
        f.write("G1 X%.5f Y%.5f\n" % (math.cos(a), math.sin(a)))
    f.write("G0 X0 Y0\nM2\n")

machine_on()
hal.set_p("motion.feed-inhibit", "1")
c.mode(linuxcnc.MODE_AUTO)
c.wait_complete()
c.program_open(os.path.abspath("prog.ngc"))
c.auto(linuxcnc.AUTO_RUN, 0)
time.sleep(3.0)                      # well past [EMCMOT]COMM_TIMEOUT
s.poll()
say("held 3 s: queue filled", s.queue > 1000, "program still running",
    s.interp_state != linuxcnc.INTERP_IDLE, "errors", errors())
hal.set_p("motion.feed-inhibit", "0")
wait(lambda st: st.interp_state == linuxcnc.INTERP_IDLE and st.queue == 0, timeout=120,
     what="the program's end")
say("released: ended at", pos(2), "errors", errors())
os.remove("prog.ngc")
c.state(linuxcnc.STATE_OFF)
c.wait_complete()

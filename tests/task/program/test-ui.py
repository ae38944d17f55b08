#!/usr/bin/env python3
import os
import sys
import time
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from taskui import c, s, say, errors, wait, machine_on, home_all, pos, linuxcnc  # noqa: E402

IDLE = linuxcnc.INTERP_IDLE


def run(name, line=0):
    c.program_open(name)
    c.auto(linuxcnc.AUTO_RUN, line)


machine_on()
home_all()
c.mode(linuxcnc.MODE_AUTO)
c.wait_complete()

# optional stop on: the program pauses at M1, resume finishes it
c.set_optional_stop(True)
run("square.ngc")
wait(lambda st: st.paused and st.interp_state == linuxcnc.INTERP_PAUSED, what="M1 pause")
say("at M1", pos(), "task_paused", s.task_paused, "read_line", s.read_line, "file", os.path.basename(s.file))
c.mode(linuxcnc.MODE_MDI)
say("mode change while paused", c.wait_complete(0.2), errors())
c.auto(linuxcnc.AUTO_RESUME)
wait(lambda st: st.interp_state == IDLE, what="program end")
say("done", pos(), "read_line", s.read_line, "motion_line", s.motion_line, "rcs", s.state)

# optional stop off: straight through
c.set_optional_stop(False)
run("square.ngc")
wait(lambda st: st.interp_state == IDLE, what="program end 2")
say("no optional stop", pos(), errors())

# pause in the middle of a move, then resume
run("long.ngc")
wait(lambda st: st.position[0] > 0.5, what="moving")
c.auto(linuxcnc.AUTO_PAUSE)
c.wait_complete()
time.sleep(0.3)
s.poll()
x = s.position[0]
time.sleep(0.2)
s.poll()
say("paused", s.interp_state == linuxcnc.INTERP_PAUSED, "stopped", abs(s.position[0] - x) < 1e-9, "velocity", round(s.current_vel, 6))
c.auto(linuxcnc.AUTO_RESUME)
c.wait_complete()
wait(lambda st: st.position[0] > x + 0.1, what="resumed")
say("resumed", True)

# abort: everything stops, interpreter idle
c.abort()
c.wait_complete()
s.poll()
say("aborted interp", s.interp_state, "exec", s.exec_state, "paused", s.task_paused, "read_line", s.read_line, "motion_line", s.motion_line)
time.sleep(0.3)
p1 = pos()
time.sleep(0.2)
say("stays put", pos() == p1)

# step from idle: paused before anything moves; steps advance
run("square.ngc")
c.abort()
c.wait_complete()
c.program_open("square.ngc")
c.auto(linuxcnc.AUTO_STEP)
c.wait_complete()
s.poll()
say("step start", s.interp_state == linuxcnc.INTERP_PAUSED, s.task_paused)
c.abort()
c.wait_complete()

# run from line 7 (G1 Y0): earlier moves are not executed
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()
c.mdi("G0 X2 Y2")
c.wait_complete()
c.mode(linuxcnc.MODE_AUTO)
c.wait_complete()
run("square.ngc", 7)
lines = set()
end = time.time() + 10
while time.time() < end:
    s.poll()
    if s.motion_line:
        lines.add(s.motion_line)
    if s.interp_state == IDLE:
        break
    time.sleep(0.002)
say("from line 7", pos(), "motion lines", sorted(lines), errors())

# a G-code error in AUTO: the program stops, the error is reported, the machine stays on
run("bad.ngc")
wait(lambda st: st.interp_state == IDLE, what="error stop")
time.sleep(0.1)
s.poll()
say("error", errors(), "pos", pos(), "state", s.task_state, "mode", s.task_mode, "errcode", s.interpreter_errcode)

# opening a missing file
c.program_open("missing.ngc")
say("open missing", c.wait_complete(), errors())

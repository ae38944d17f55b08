#!/usr/bin/env python3
"""The display of the cycle-count test: run $CYCLES_PROGRAM (default cut.ngc) with the motion queue filled before motion
starts (feed inhibit held until the interpreter is done), sample every servo cycle, write the
number of cycles from the first to the last one that moved to real-cycles.txt."""
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.environ["EMC2_HOME"], "tests", "task", "lib"))
from taskui import c, s, say, wait, machine_on, home_all, linuxcnc  # noqa: E402


def halcmd(*words):
    subprocess.run(["halcmd"] + list(words), check=True)


def motion_cycles(path):
    """Samples from the first whose position changed to the last one that changed."""
    rows = []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if len(parts) == 4:
                rows.append((int(parts[0]), tuple(parts[1:])))
    tags = [t for t, _ in rows]
    if any(b != a + 1 for a, b in zip(tags, tags[1:])):
        return "lost samples"
    moved = [k for k in range(1, len(rows)) if rows[k][1] != rows[k - 1][1]]
    return moved[-1] - moved[0] + 1 if moved else 0


program = os.path.abspath(os.environ.get("CYCLES_PROGRAM", "cut.ngc"))
with open(program) as f:
    last_move = sum(1 for _ in f) - 1      # the line before the closing M2

machine_on()
home_all()
c.mode(linuxcnc.MODE_AUTO)
c.wait_complete()
halcmd("setp", "motion.feed-inhibit", "1")
out = open("samples.txt", "w")
sampler = subprocess.Popen(["halsampler", "-t"], stdout=out)
time.sleep(0.2)
c.program_open(program)
c.auto(linuxcnc.AUTO_RUN, 0)
wait(lambda st: st.read_line >= last_move or st.interp_state == linuxcnc.INTERP_WAITING, what="program read")
time.sleep(0.3)
halcmd("setp", "motion.feed-inhibit", "0")
wait(lambda st: st.interp_state == linuxcnc.INTERP_IDLE and st.inpos, timeout=20, what="program end")
time.sleep(0.3)
sampler.terminate()
sampler.wait()
out.close()
with open("real-cycles.txt", "w") as f:
    print(motion_cycles("samples.txt"), file=f)
say("program ran")
c.state(linuxcnc.STATE_ESTOP)
c.wait_complete()

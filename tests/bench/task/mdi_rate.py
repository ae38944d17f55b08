#!/usr/bin/env python3
"""mdi_rate.py: MDI commands per second through command.mdi() + wait_complete() on the sim mill."""
import time
import linuxcnc

c = linuxcnc.command()
s = linuxcnc.stat()
c.state(linuxcnc.STATE_ESTOP_RESET)
c.state(linuxcnc.STATE_ON)
c.mode(linuxcnc.MODE_MANUAL)
c.home(-1)
end = time.time() + 30
while time.time() < end:
    s.poll()
    if all(s.homed[:3]):
        break
    time.sleep(0.01)
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()


def rate(texts, n):
    t = time.perf_counter()
    for i in range(n):
        c.mdi(texts[i % len(texts)])
        if c.wait_complete(5) != linuxcnc.RCS_DONE:
            raise SystemExit("MDI %r did not complete" % texts[i % len(texts)])
    return n / (time.perf_counter() - t)


settings = rate(["G90", "G91", "F100", "G17"], 400)
moves = rate(["G0 X0.001", "G0 X0"], 200)
print("task: MDI %.0f commands/s without motion (G90/F...), %.0f commands/s with a 0.001 in G0 each"
      " (mdi() + wait_complete(), 1 ms task cycle)" % (settings, moves))

"""logger_test.py: linuxcnc.positionlogger sampling a jog in a thread."""
import struct
import threading
import time
import linuxcnc

s = linuxcnc.stat()
c = linuxcnc.command()
colors = [(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (1, 2, 3, 4), (5, 6, 7, 8), (9, 9, 9, 9)]
log = linuxcnc.positionlogger(s, *colors, "XYZ")
print("colors:", log.get_colors() == tuple(colors))
print("empty:", log.npts, log.last(), log.points()[1:])
thread = threading.Thread(target=log.start, args=(0.005,))
thread.start()

c.state(linuxcnc.STATE_ESTOP_RESET)
c.state(linuxcnc.STATE_ON)
c.mode(linuxcnc.MODE_MANUAL)
c.home(-1)
while s.poll() or s.homed[:3] != (1, 1, 1):
    time.sleep(0.01)
c.mode(linuxcnc.MODE_MANUAL)
c.wait_complete()
c.jog(linuxcnc.JOG_INCREMENT, 0, 0, 2.0, 0.2)
while s.poll() or s.position[0] < 0.2:
    time.sleep(0.01)
c.jog(linuxcnc.JOG_INCREMENT, 0, 1, 2.0, 0.1)
while s.poll() or s.position[1] < 0.1:
    time.sleep(0.01)
time.sleep(0.1)
log.stop()
thread.join(5)
print("stopped:", not thread.is_alive())

data, npts, xyuv = log.points()
records = [struct.unpack("4B3f", data[i:i + 16]) for i in range(0, len(data), 16)]
print("records:", len(data) == 16 * npts, npts >= 3, xyuv)
print("straight runs merged:", npts < 20)
print("last:", tuple(round(v, 6) for v in log.last()))
print("first point at origin:", tuple(round(v, 6) for v in records[0][4:]))
print("only jog and traverse colours:", {r[:4] for r in records} <= {(255, 0, 0, 255), (0, 255, 0, 255)})
log.set_colors(*colors[::-1])
print("set_colors:", log.get_colors()[0])
log.clear()
print("cleared:", log.npts, log.last())
try:
    log.call()
except linuxcnc.error as e:
    print("call without OpenGL:", e)

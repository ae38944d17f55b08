"""waiter.py: a Python component that waits for SIGTERM and reports KeyboardInterrupt."""
import time

import hal

c = hal.component("pywait")
c.newpin("level", hal.HAL_FLOAT, hal.HAL_OUT)
c.newparam("gain", hal.HAL_FLOAT, hal.HAL_RW)
c.level = 1.5
c.ready()
try:
    while True:
        time.sleep(0.01)
except KeyboardInterrupt:
    c.level = 1.5 * c.gain
    print("interrupted, gain %g level %g" % (c.gain, c.level), flush=True)

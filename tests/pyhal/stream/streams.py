"""streams.py: exercises hal.stream on a private stream and on streamer/sampler streams."""
import subprocess
import time

import hal
from pyhal_test import show


c = hal.component("pystream")
print("== private stream")
own = hal.stream(c, 0x4F450001, 4, "fbsulk")
show("repr", lambda: repr(own))
show("types", lambda: (own.element_types, own.maxdepth, own.depth, own.writable, own.readable))
for n in range(1, 4):
    own.write((n / 2, n % 2, -n, n, -(2 ** 40) * n, 2 ** 63 + n))
show("write when full", lambda: own.write((0, 0, 0, 0, 0, 0)))
show("after writes", lambda: (own.depth, own.writable, own.num_overruns))
show("too few", lambda: own.write((1, 2)))
show("too many", lambda: own.write((1, 2, 3, 4, 5, 6, 7)))
show("bad value", lambda: own.write(("x", 0, 0, 0, 0, 0)))
reader = hal.stream(c, 0x4F450001, "fbsulk")
show("reader repr", lambda: repr(reader))
for n in range(4):
    show("read", lambda: (reader.read(), reader.sampleno))
show("after reads", lambda: (own.depth, reader.readable, reader.num_underruns))
show("attach wrong types", lambda: hal.stream(c, 0x4F450001, "bb"))
show("attach missing", lambda: hal.stream(c, 0x4F450099))

print("== through streamer and sampler")
writer = hal.stream(c, hal.streamer_base, "fbsulk")
for n in range(1, 4):
    writer.write((n * 1.25, n == 2, 100 * n, 7 * n, -n, n))
show("streamer depth", lambda: writer.depth)
c.ready()
sampled = hal.stream(c, hal.sampler_base)
subprocess.run(["halcmd", "start"], check=True)
for n in range(3):
    polls = 0
    while not sampled.readable and polls < 5000:
        time.sleep(0.002)
        polls += 1
    show("sampled", lambda: sampled.read())
show("signal info", lambda: [(d["NAME"], d["DRIVER"], d["TYPE"]) for d in hal.get_info_signals()])
show("pin_has_writer", lambda: (hal.pin_has_writer("sampler.0.pin.0"),
                                hal.pin_has_writer("streamer.0.clock")))
show("pin_has_writer nosuch", lambda: hal.pin_has_writer("nosuch"))

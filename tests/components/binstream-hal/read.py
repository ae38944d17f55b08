# read.py: wait for the histogram records of both streams and print them with the latched statistics.
import time
import hal

c = hal.component("binreader")
c.ready()
histo = hal.stream(c, 4711, "u")
lat = hal.stream(c, 4712, "u")


def records(s, n):
    """The next n records of stream s (waits at most 10 s)."""
    out = []
    deadline = time.time() + 10
    while len(out) < n and time.time() < deadline:
        r = s.read()
        if r is None:
            time.sleep(0.01)
        else:
            out.append(r[0])
    return out


print("histogram (below, bins 0..3, above):", records(histo, 6))
for p in ("nsamples", "mean", "variance", "input-min", "input-max", "stream-error"):
    print(p, hal.get_value("histobinstream.0." + p))
# latencies depend on the machine: check the shape (2 x 2 + 3 records, one count per sample)
lrec = records(lat, 7)
print("latency records:", len(lrec), "counts:", sum(lrec))
lo, hi = hal.get_value("latencybinstream.0.latency-min"), hal.get_value("latencybinstream.0.latency-max")
avg = hal.get_value("latencybinstream.0.latency-avg")
print("min <= avg <= max:", lo <= avg <= hi, "stream-error", hal.get_value("latencybinstream.0.stream-error"))
c.exit()

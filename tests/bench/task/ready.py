#!/usr/bin/env python3
"""ready.py: the benchmark's display: record when the launcher started it (machine ready) and exit."""
import time
with open("ready.time", "w") as f:
    f.write("%.6f\n" % time.time())

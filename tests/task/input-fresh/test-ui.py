#!/usr/bin/env python3
"""M66 reads inputs sampled after it was issued: set a HAL input, M66 at once, #5399 shows it."""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import hal  # noqa: E402
from taskui import say, errors, machine_on, mdi  # noqa: E402

machine_on()
for v in ("1", "0", "1"):
    hal.set_p("motion.digital-in-00", v)
    say("digital in", v, "M66 P0 L0", mdi("M66 P0 L0"), mdi("(DEBUG, #5399)"), errors())
for v in ("2.5", "-1.25"):
    hal.set_p("motion.analog-in-00", v)
    say("analog in", v, "M66 E0 L0", mdi("M66 E0 L0"), mdi("(DEBUG, #5399)"), errors())

#!/usr/bin/env python3
"""Machine B: moves elsewhere and reports (its instance first)."""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import taskui  # noqa: E402

taskui.OUT = open("b.out", "w")
taskui.say(os.environ.get("OPENEMC_INSTANCE"))
taskui.machine_on()
taskui.home_all()
taskui.say("B G0 X-3", taskui.mdi("G0 X-3 Y2"), taskui.pos())

#!/usr/bin/env python3
"""Machine A: starts machine B in another instance, both move, neither sees the other's."""
import os
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from taskui import say, errors, machine_on, home_all, mdi, pos  # noqa: E402

env = dict(os.environ)
env.pop("OPENEMC_INSTANCE")
b = subprocess.Popen(["linuxcnc", "-r", "b.ini"], env=env, stdout=open("b.log", "w"), stderr=subprocess.STDOUT)
machine_on()
home_all()
say("A G0 X1", mdi("G0 X1 Y1"), pos())
say("B exit status", b.wait(timeout=60))
with open("b.out") as f:
    lines = f.read().split("\n")
say("B instance differs", lines[0] != os.environ["OPENEMC_INSTANCE"])
for line in lines[1:]:
    if line:
        say(line)
say("A still at", pos(), "errors", errors())

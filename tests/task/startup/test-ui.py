#!/usr/bin/env python3
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import hal  # noqa: E402
from taskui import s, say, linuxcnc  # noqa: E402

s.poll()
say("state", s.task_state, "mode", s.task_mode, "interp", s.interp_state, "exec", s.exec_state, "rcs", s.state)
say("joints", s.joints, "axis_mask", s.axis_mask, "linear_units", round(s.linear_units, 5),
    "spindles", s.spindles, "motion_mode", s.motion_mode)
say("max_velocity", s.max_velocity, "homed", s.homed[:3], "estop", s.estop)
say("tool_in_spindle", s.tool_in_spindle, "pocket_prepped", s.pocket_prepped)
for t in s.tool_table[:4]:
    say("tool", t.id, t.diameter, t.zoffset)
say("toolinfo 3", s.toolinfo(3)["comment"])
say("ini.traj_max_velocity", hal.get_value("ini.traj_max_velocity"))
say("ini.0.home_offset", hal.get_value("ini.0.home_offset"), "ini.z.min_limit", hal.get_value("ini.z.min_limit"),
    "ini.a.max_velocity", hal.get_value("ini.a.max_velocity"))
say("user-enable-out", hal.get_value("iocontrol.0.user-enable-out"), "tool-number", hal.get_value("iocontrol.0.tool-number"))
say("program_units", s.program_units, "gcodes", s.gcodes[1:12], "mcodes", s.mcodes[2:9])
say("ini_filename", os.path.basename(s.ini_filename))
beat = s.taskbeat
import time  # noqa: E402
time.sleep(0.05)
s.poll()
say("taskbeat advances", s.taskbeat > beat)

#!/bin/bash
# The gcode module: parse() into a Python canon (next_line, moves, arcs and arc_to_segments, comments,
# tool change), errors with strerror(), check_abort() stopping a long program, canon exceptions raised;
# a Python remap (INI_FILE_NAME) runs inside the Python program and its canon calls reach the same canon.
export PYTHONDONTWRITEBYTECODE=1
python3 preview.py 2>&1

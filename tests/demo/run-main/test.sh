#!/bin/bash
# make run's demo: the sim mill must home, run configs/demo/demo.ngc to the end, follow the
# programmed path within 0.1 mm, change one tool, report no operator error and write a PNG.
set -e
"$EMC2_HOME/scripts/run-main" "$PWD/toolpath.png" > demo.out
grep -q '^homed; running configs/demo/demo.ngc' demo.out && echo "homed and started"
grep -q '\[##############################\] 100%  line  28/28' demo.out && echo "progress reached 100%"
awk '/tool changes/ { print "tool changes", $3 }
     /path deviation/ { print "path within 0.1 mm:", ($3 < 0.1 ? "yes" : "no " $3) }
     /operator messages/ { print "operator messages", $3 }
     /cycle time/ { print "samples > 500:", ($8 + 0 > 500 ? "yes" : "no") }' demo.out
python3 - toolpath.png <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
w, h = struct.unpack(">II", data[16:24])
print("png", data[:8] == b"\x89PNG\r\n\x1a\n", w, h)
PY
rm -f toolpath.png

#!/bin/bash
# motmod's pins and parameters: names, types and directions (values left out); named I/O with
# numbered leftovers, unlock pins for unlock_joints_mask, posthome-cmd for extra joints, and
# motion.switchkins-type only with switchable kinematics.
log=$(mktemp)
trap 'halrun -U >/dev/null 2>&1; rm -f "$log"' EXIT
halrun -U >/dev/null 2>&1
list() {
    halcmd -s show pin | awk '$1 == "motmod" { print "pin", $2, $3, $5 }' | sort -k4
    halcmd -s show param | awk '$1 == "motmod" { print "param", $2, $3, $5 }' | sort -k4
}
halcmd loadrt trivkins kinstype=both >>"$log" 2>&1
halcmd -f ../common/planner.hal >>"$log" 2>&1
halcmd loadrt motmod num_joints=2 num_extrajoints=1 unlock_joints_mask=0x2 names_din=a,b names_dout=o names_ain=level names_misc_errors=door >>"$log" 2>&1 || cat "$log"
echo "== trivkins both, 2 joints (joint 1 extra, unlockable), named I/O"
list
halrun -U >/dev/null 2>&1
halcmd loadrt xyzac-trt-kins >"$log" 2>&1
halcmd -f ../common/planner.hal >>"$log" 2>&1
halcmd loadrt motmod num_joints=5 num_spindles=2 >>"$log" 2>&1 || cat "$log"
echo "== switchable kinematics: motion.switchkins-type, two spindles"
list | grep -E "switchkins|spindle.1.on$|kinstype"

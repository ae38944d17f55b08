#!/bin/bash
# Screw compensation: corrections interpolated by the commanded position in the column of the
# direction of travel, first/last row outside the table, BACKLASH ignored with a table; rows that
# do not increase and a 257th row are refused with their messages.
trap 'rm -f rows.inj' EXIT
for i in $(seq 0 256); do echo "SET_JOINT_COMP joint=1 comp_nominal=$i comp_forward=0 comp_reverse=0"; done >rows.inj
exec halrun -f comp.hal

#!/bin/bash
# [HAL]TWOPASS through the launcher: loadrt of one module in several files (.hal and .tcl) is
# merged into one load before any net runs; .tcl files see ::tp::passnumber 0 then 1; TPMOD
# and HOMEMOD loaded by the launcher are not merged again.
export PATH=$PATH:$(cd ../doubles && pwd)
linuxcnc -r test.ini > run.out 2> run.err
echo "exit status $?"
grep -hv -e "^Note: " -e "^$" -e "^Waiting for component" run.out run.err | \
    sed -e "s|$PWD/||g" -e "s|$PWD|<dir>|g"
python3 ../common/leftovers.py

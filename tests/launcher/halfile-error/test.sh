#!/bin/bash
# A failing HAL file (.hal or .tcl) or one that cannot be found stops the launch: its error
# names file and line, the launcher says which HALFILE failed, everything is cleaned up and the
# exit status is 1. With -k the launch goes on.
export PATH=$PATH:$(cd ../doubles && pwd)
run() {
    echo "== linuxcnc $*"
    linuxcnc -r "$@" > run.out 2> run.err
    echo "exit status $?"
    grep -hv -e "^Note: " -e "^$" -e "^Waiting for component" run.out run.err | sed -e "s|$PWD/||g" -e "s|$PWD|<dir>|g" -e "s|$EMC2_HOME|<top>|g"
    python3 ../common/leftovers.py
}
run test.ini
run tcl.ini
run missing.ini
run -k test.ini

#!/bin/bash
# Task contract: a task that exits before creating a ready inihal stops the launch (exit 1,
# nothing left); one that never publishes ini.traj_max_velocity gets a warning after 10 s and
# the display still starts.
export PATH=$PATH:$(cd ../doubles && pwd)
for ini in test silent; do
    echo "== $ini.ini"
    linuxcnc -r $ini.ini > run.out 2> run.err
    echo "exit status $?"
    grep -hv -e "^Note: " -e "^$" -e "^Waiting for component" -e "^\.*$" run.out run.err | \
        sed -e "s|$PWD/||g" -e "s|$PWD|<dir>|g" -e "s|$EMC2_HOME|<top>|g"
    python3 ../common/leftovers.py
done

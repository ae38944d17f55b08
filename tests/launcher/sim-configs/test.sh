#!/bin/bash
# The configs/sim machines start with the real motion modules and their LIB: HAL files; the
# task program is the launcher-test stand-in (no milltask needed) and halui is left out. Each
# session's signals and thread functions are dumped for checkresult.
export PATH=$PATH:$(cd ../doubles && pwd)
rm -f *.sigs *.threads run-*.ini run-*_cmds.hal
for ini in mill/mill mill/mill_mm lathe/lathe corexy/corexy gantry/gantry xyzac-trt/xyzac-trt; do
    name=$(basename $ini)
    src=$EMC2_HOME/configs/sim/$ini.ini
    sed -e 's|^TASK = milltask$|TASK = launcher_test_task|' -e '/^HALUI = /d' \
        -e "s|^DISPLAY = dummy$|DISPLAY = $PWD/probe.sh|" \
        -e "s|^TOOL_TABLE = |TOOL_TABLE = $(dirname $src)/|" "$src" > run-$name.ini
    linuxcnc -r run-$name.ini > run.out 2> run.err
    status=$?
    echo "$name: exit status $status"
    [ $status -eq 0 ] || cat run.err
done
python3 ../common/leftovers.py

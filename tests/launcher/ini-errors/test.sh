#!/bin/bash
# INI problems stop the launch before anything starts: each gives "<ini>: error: ..." naming
# the key (and its line), exit status 1, and nothing left running.
export PATH=$PATH:$(cd ../doubles && pwd)
for ini in no-kins joints-range joints-text bad-coordinates units ranges version no-task \
           no-display syntax missing-file; do
    echo "== $ini"
    linuxcnc -r $ini.ini > run.out 2> run.err < /dev/null
    echo "exit status $?"
    sed -e "s|$PWD/||g" run.err
done
python3 ../common/leftovers.py
echo "== linuxcnc_check_ini: warnings alone pass, -e makes them fatal"
linuxcnc_check_ini warn-only.ini 2>&1 | sed -e "s|$PWD/||g"; echo "exit status ${PIPESTATUS[0]}"
linuxcnc_check_ini -e warn-only.ini > /dev/null 2>&1; echo "-e exit status $?"
echo "== OPENEMC_INSTANCE out of range"
OPENEMC_INSTANCE=16777216 linuxcnc -r ../startup-order/test.ini > run.out 2> run.err
echo "exit status $?"; cat run.err

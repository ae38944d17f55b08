#!/bin/bash
# Bad .nml files: linuxcncsvr --list names file, line and what is wrong, and exits 1;
# an unknown option is only a warning. The shipped default file parses cleanly.
export LC_ALL=C
for f in *.nml; do
    echo "== $f"
    linuxcncsvr -nml "$f" --list >/dev/null 2>out.txt
    echo "exit $?"
    cat out.txt
done
rm -f out.txt
echo "== missing files"
linuxcncsvr -nml nosuch.nml --list 2>&1; echo "exit $?"
linuxcncsvr -ini nosuch.ini --list 2>&1; echo "exit $?"
linuxcncsvr --list 2>&1; echo "exit $?"
echo "== default"
linuxcncsvr -nml "$EMC2_HOME/configs/common/linuxcnc.nml" --list 2>&1 | sed 's/0x[0-9a-f]\{2\}/0xII/'
echo "exit ${PIPESTATUS[0]}"

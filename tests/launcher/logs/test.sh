#!/bin/bash
# Without -r and without a terminal on stdin the session's output goes to temporary logs:
# nothing reaches stdout/stderr on success; on failure the logs are kept as
# ~/linuxcnc_print.txt and ~/linuxcnc_debug.txt and one line says so. -l and '-' start the
# configuration named by ~/.linuxcncrc [PICKCONFIG]LAST_CONFIG.
export PATH=$PATH:$(cd ../doubles && pwd)
export HOME=$PWD/home
rm -rf home tmp; mkdir home tmp
clean() { sed -e "s|$PWD/||g" -e "s|$PWD|<dir>|g"; }

TMPDIR=$PWD/tmp linuxcnc test.ini > run.out 2> run.err < /dev/null
echo "success: exit status $?, $(cat run.out run.err | wc -l) lines of output"
ls home

TMPDIR=$PWD/tmp linuxcnc broken.ini > run.out 2> run.err < /dev/null
echo "failure: exit status $?"
clean < run.err
grep -h -e "display output" -e "broken.hal:2" -e "error:" home/linuxcnc_print.txt home/linuxcnc_debug.txt | clean
echo "temporary logs left: $(ls tmp | grep -c '^linuxcnc\.')"

linuxcnc -r -l > run.out 2> run.err
echo "-l without ~/.linuxcncrc: exit status $?"; clean < run.err
printf '[PICKCONFIG]\nLAST_CONFIG = %s/test.ini\n' "$PWD" > home/.linuxcncrc
linuxcnc -r - > run.out 2> run.err
echo "- with LAST_CONFIG: exit status $?"; grep -h -e "display output" -e "configuration file" run.out | clean
python3 ../common/leftovers.py

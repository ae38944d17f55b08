#!/bin/bash
# halrun with a .tcl HAL file (haltcl): hal command, INI arrays via -i, errors inside Tcl.
cd "$(dirname "$0")"
halrun -i test.ini test.tcl 2>&1 | grep -v '^Note: '
echo "exit ${PIPESTATUS[0]}"
printf 'hal newsig s1 bit\nputs [hal stype s1]\nhal frob\n' | halrun -T 2>&1 | grep -v '^Note: '
echo "exit ${PIPESTATUS[0]}"

#!/bin/bash
# haltcl: HAL commands as Tcl commands, expr values, INI lists, `show` prints, errors name file:line.
cd "$(dirname "$0")"
realtime start 2>/dev/null || exit 1
haltcl -i test.ini cmds.tcl one two 2>&1 | grep -v '^Note: '
echo "exit ${PIPESTATUS[0]}"
halcmd unload all
realtime stop

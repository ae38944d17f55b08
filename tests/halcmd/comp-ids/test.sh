#!/bin/bash
# Component id numbering (hal.md §4) as shown by show comp/pin, incl. failed loads and loadusr.
cd "$(dirname "$0")"
realtime start 2> /dev/null || exit 1
halcmd -k -f ids.hal 2>&1 | grep -c 'insmod for nosuchmodule failed'
halcmd show comp | grep -v ' halcmd[0-9]'
halcmd -s show comp | grep -v ' halcmd[0-9]'
halcmd show pin '*.out'
realtime stop

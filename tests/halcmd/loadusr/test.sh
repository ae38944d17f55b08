#!/bin/bash
# loadusr -w/-i/-W/-n, exec failures, waitusr, unloadusr, loadrt failures and unload errors.
cd "$(dirname "$0")"
realtime start 2> /dev/null || exit 1
halcmd -k -f 2>&1 <<'HAL' | sed "s|$EMC2_HOME|EMC2_HOME|g"
loadusr -w ./say.sh one two
loadusr -w ./exit3.sh
loadusr -w -i ./exit3.sh
loadusr -w ./killself.sh
loadusr -w /nonexistent/prog
loadusr
loadusr -W false
loadusr -Wn mycomp true
waitusr nosuch
unloadusr nosuch
unloadusr all
loadrt and2
waitusr and2
unloadrt nosuch
unloadusr and2
unload nosuch
loadrt nosuchmodule
loadrt and2
list comp and2
unloadrt and2
list pin
loadrt and2 count=2
list pin
unload all
list pin
HAL
echo "exit ${PIPESTATUS[0]}"
echo "> tilde expansion"
echo 'loadusr -w ~/say.sh tilde ~ ~x' | HOME=$PWD halcmd -f 2>&1 | sed "s|$PWD|TESTDIR|"
realtime stop

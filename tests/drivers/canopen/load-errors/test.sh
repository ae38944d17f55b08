#!/bin/bash
# load-errors: loadrt cia402 without a configuration, with a faulty one (file:line messages through
# the realtime master) and with an interface that cannot be used; nothing is left loaded.
D=$(mktemp -d)
log=$D/master.log
trap 'realtime stop > /dev/null 2>&1; rm -rf "$D"' EXIT
cd "$D" || exit 1
realtime start > "$log" 2>&1 || exit 1
seen=$(wc -l < "$log")
# load ARGS...: loadrt cia402 ARGS, then its status and the master's new messages.
load() {
    echo "== loadrt cia402 ${*//$D\//}"
    halcmd loadrt cia402 "$@" > /dev/null 2>&1
    echo "status $?"
    tail -n +$((seen + 1)) "$log" | sed "s|$D/||"
    seen=$(wc -l < "$log")
}
load
load config=
load config="$D/missing.ini"
printf '[CIA402]\nINTERFACE = can0\n[CIA402_DRIVE_0]\nNODE_ID = 0\nSDO = 1A00:01 u32 0\n' > bad.ini
load config="$D/bad.ini"
printf '[CIA402_DRIVE_0]\nNODE_ID = 1\nINTERFACE = nosuchcan0\n' > noif.ini
echo "== loadrt cia402 config=noif.ini"
halcmd loadrt cia402 config="$D/noif.ini" > /dev/null 2>&1
echo "status $?"
# Without SocketCAN the socket fails, with it the interface is missing: either way the
# message names the interface.
tail -n +$((seen + 1)) "$log" | grep -q '^cia402: .*nosuchcan0 (' && echo "message names the interface"
echo "components: [$(halcmd list comp cia402)]"

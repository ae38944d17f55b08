#!/bin/bash
# classicladder_rt in a realtime thread: pins, module parameters, loading, reloading and
# refusing projects with the classicladder loader, and the PLC scan seen through HAL pins.
cd "$(dirname "$0")"
log=$(mktemp)
trap 'realtime stop >/dev/null 2>&1; rm -f "$log"' EXIT
realtime start 2>"$log" || exit 1

# Poll (no time limit asserted) until pin $1 reads $2.
wait_pin() {
    for i in $(seq 1 3000); do
        [ "$(halcmd getp "$1")" = "$2" ] && { echo "$1 = $2"; return; }
        sleep 0.01
    done
    echo "$1 stuck at $(halcmd getp "$1"), expected $2"
}

echo "== bad module parameters"
halcmd loadrt classicladder_rt numRungs=0 2>/dev/null; echo "exit $?"
halcmd loadrt classicladder_rt numPhysInputs=5000 2>/dev/null; echo "exit $?"
echo "== loader without the module"
classicladder --nogui plc.clp 2>&1; echo "exit $?"
echo "== pins"
halcmd loadrt classicladder_rt numPhysInputs=2 numPhysOutputs=2 numS32in=1 numS32out=1 \
    numFloatIn=1 numFloatOut=1 || exit 1
halcmd show pin classicladder | awk 'NR>2 && NF {print $2, $3, $5}'
halcmd show funct | grep -o 'classicladder.0.refresh'
halcmd loadrt threads name1=plc period1=1000000
halcmd addf classicladder.0.refresh plc
halcmd start
echo "== no project: stopped, outputs stay 0"
halcmd setp classicladder.0.in-01 0
halcmd getp classicladder.0.plc-stopped
halcmd getp classicladder.0.out-01
echo "== load plc.clp"
halcmd loadusr -w classicladder --nogui plc.clp; echo "exit $?"
wait_pin classicladder.0.plc-stopped FALSE
wait_pin classicladder.0.out-01 TRUE
halcmd setp classicladder.0.in-00 1
halcmd setp classicladder.0.in-01 1
wait_pin classicladder.0.out-00 TRUE
wait_pin classicladder.0.out-01 FALSE
halcmd setp classicladder.0.s32in-00 21
wait_pin classicladder.0.s32out-00 42
halcmd setp classicladder.0.floatin-00 2.5
wait_pin classicladder.0.floatout-00 3
echo "== a bad project is refused and the running one stays"
classicladder --nogui bad.clp 2>&1; echo "exit $?"
halcmd setp classicladder.0.in-00 0
wait_pin classicladder.0.out-00 FALSE
echo "== usage errors"
classicladder 2>&1 | head -1
classicladder --bogus plc.clp 2>&1 | head -1
echo "== Modbus options are ignored: inverted.clp"
classicladder --modmaster --nogui inverted.clp 2>&1; echo "exit $?"
wait_pin classicladder.0.out-00 TRUE
halcmd setp classicladder.0.in-00 1
wait_pin classicladder.0.out-00 FALSE
echo "== reload without --nogui: plc.clp"
classicladder plc.clp 2>&1; echo "exit $?"
wait_pin classicladder.0.out-00 TRUE
halcmd setp classicladder.0.in-00 0
wait_pin classicladder.0.out-00 FALSE
echo "== unload"
halcmd stop
halcmd unload all
classicladder --nogui plc.clp 2>&1; echo "exit $?"
echo "== module messages"
grep '^CLASSICLADDER' "$log"

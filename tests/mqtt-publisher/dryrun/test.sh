#!/bin/bash
# dryrun: mqtt-publisher --dryrun prints one JSON message per period (at once, then every
# period seconds as the pin says), stops while enable is FALSE, reports a missing key once and
# updates lastpublish; bad command lines are refused.
realtime start 2> /dev/null || exit 1
out=$(mktemp)
trap 'halcmd unloadusr mqtt-publisher; sleep 0.5; realtime stop; rm -f "$out" "$out.err"' EXIT
halcmd newsig s1 float
halcmd sets s1 2.5
halcmd loadrt and2 count=1
halcmd setp and2.0.in0 1
mqtt-publisher --dryrun keys=s1,and2.0.in0,no.such.pin > "$out" 2> "$out.err" &
# wait (no time limit assertion) for the component and its first message
for i in $(seq 1 300); do [ -s "$out" ] && break; sleep 0.05; done
halcmd show pin mqtt-publisher | awk 'NR > 2 && NF {print $2, $3, $5}'
[ "$(halcmd getp mqtt-publisher.lastpublish)" -gt 1600000000 ] && echo "lastpublish is a time"
halcmd setp mqtt-publisher.period 1
for i in $(seq 1 300); do [ "$(wc -l < "$out")" -ge 3 ] && break; sleep 0.05; done
halcmd setp mqtt-publisher.enable 0
sleep 0.3
count=$(wc -l < "$out")
[ "$count" -ge 3 ] && echo "a message each period"
sleep 1.5
[ "$(wc -l < "$out")" = "$count" ] && echo "no messages while disabled"
sort -u "$out"
cat "$out.err"
echo "> bad command lines"
mqtt-publisher --dryrun 2>&1; echo "exit $?"
mqtt-publisher --dryrun keys=s1 --bogus 2>&1; echo "exit $?"
mqtt-publisher keys=s1 --mqtt-port=http 2>&1; echo "exit $?"

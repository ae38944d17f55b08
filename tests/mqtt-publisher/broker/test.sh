#!/bin/bash
# broker: mqtt-publisher connects to an MQTT broker (a small stand-in that logs the packets) with
# user and password and publishes the JSON message on the --mqtt-prefix topic each period.
realtime start 2> /dev/null || exit 1
log=$(mktemp)
trap 'halcmd unloadusr mqtt-publisher; sleep 0.5; realtime stop; kill $broker 2>/dev/null; rm -f "$log" "$log.port"' EXIT
python3 fake_broker.py "$log" > "$log.port" &
broker=$!
for i in $(seq 1 200); do [ -s "$log.port" ] && break; sleep 0.05; done
halcmd newsig s1 s32
halcmd sets s1 -7
halcmd loadusr -W mqtt-publisher --mqtt-broker=127.0.0.1 --mqtt-port="$(cat "$log.port")" \
    --mqtt-user=me --mqtt-password=secret --mqtt-prefix=shop/mill keys=s1
halcmd setp mqtt-publisher.period 1
for i in $(seq 1 300); do [ "$(grep -c PUBLISH "$log")" -ge 2 ] && break; sleep 0.05; done
sort -u "$log"
echo "messages: $([ "$(grep -c PUBLISH "$log")" -ge 2 ] && echo 2 or more)"
echo "> unreachable broker"
mqtt-publisher --mqtt-broker=127.0.0.1 --mqtt-port=1 keys=s1 2>&1 | sed 's/: \[Errno.*//'; echo "exit ${PIPESTATUS[0]}"

#!/bin/bash
# inner.sh: the part of vm-vcan that runs inside the VM (as root).
T=/tmp/cia402
mkdir -p $T
log=$T/master.log
trap 'realtime stop > /dev/null 2>&1; kill $sim $dump 2> /dev/null' EXIT
ip link add vcan0 type vcan && ip link set vcan0 up || exit 1
candump -L vcan0 > $T/frames.log &
dump=$!
mkfifo $T/sim.in
cia402-sim --interface vcan0 --node 1 --node 2 --log $T/sim.log < $T/sim.in > $T/sim.out 2>&1 &
sim=$!
exec 3> $T/sim.in
cat > $T/drives.ini <<'INI'
# timeouts are generous: under emulation (TCG) on a loaded host the simulator may stall for a second
[CIA402]
INTERFACE = vcan0
HEARTBEAT_MS = 100
HEARTBEAT_TIMEOUT_MS = 5000
PDO_TIMEOUT_MS = 5000
SDO_TIMEOUT_MS = 3000
ENABLE_TIMEOUT_MS = 5000
[CIA402_DRIVE_0]
NODE_ID = 1
POSITION_SCALE = 1000
SDO = 2000:01 u32 77
[CIA402_DRIVE_1]
NODE_ID = 2
HEARTBEAT_TIMEOUT_MS = 3000
PDO_TIMEOUT_MS = 60000
INI

# wait_for WHAT COMMAND...: polls COMMAND for up to 30 s.
wait_for() {
    local what=$1 n=0
    shift
    until "$@"; do
        n=$((n + 1))
        if [ $n -gt 300 ]; then echo "timed out: $what"; return 1; fi
        sleep 0.1
    done
    echo "ok: $what"
}
pin_is() { [ "$(halcmd getp "$1")" = "$2" ]; }
near() { awk -v v="$(halcmd getp "$1")" -v w="$2" 'BEGIN { exit !(v - w < 0.0005 && w - v < 0.0005) }'; }
# pins N NAME...: one line with drive N's pins (one halcmd call).
pins() {
    local n=$1
    shift
    halcmd -s show pin "cia402.$n." | awk -v n="$n" -v want="$*" '
        { value[substr($5, length("cia402." n ".") + 1)] = $4 }
        END { k = split(want, w, " "); line = "drive " n ":"
              for (i = 1; i <= k; i++) line = line " " w[i] "=" value[w[i]]; print line }'
}
seen=0
# new_messages: what the realtime master printed since the last call (times in ms blanked).
new_messages() {
    tail -n +$((seen + 1)) "$log" | grep -av "^Note\|isolated CPU\|realtime delay\|only display once\|Latency Test" |
        sed 's/for [0-9]* ms/for N ms/'
    seen=$(wc -l < "$log")
}
# frames PATTERN: how many logged frames match the candump pattern (ID#DATA, regex).
frames() { grep -c " vcan0 $1" $T/frames.log; }

until grep -q ready $T/sim.out; do sleep 0.1; done
realtime start > "$log" 2>&1 || { cat "$log"; exit 1; }
{
    echo "loadrt threads name1=servo period1=4000000"
    echo "loadrt cia402 config=$T/drives.ini"
    echo "addf cia402.read servo"; echo "addf cia402.write servo"; echo start
} | halcmd -f || { cat "$log"; exit 1; }
halcmd list pin cia402 | tr -s ' ' '\n' | grep -v '\.time$' | grep . | paste -sd' '
wait_for "both drives set up and operational" eval 'pin_is cia402.0.ready TRUE && pin_is cia402.1.ready TRUE'
new_messages
grep "node 1: sdo write 2000:01\|node 1: nmt" $T/sim.log
pins 0 state nmt-state fault enabled
echo "== enable drive 0 and move it to 0.5"
halcmd setp cia402.0.enable 1
wait_for "drive 0 enabled" pin_is cia402.0.enabled TRUE
halcmd setp cia402.0.position-cmd 0.5
wait_for "drive 0 at 0.5" near cia402.0.position-fb 0.5
pins 0 state statusword controlword fault enabled
echo "frames: SYNC $( [ $(frames '080#$') -gt 100 ] && echo yes) NMT start $(frames '000#0101') \
SDO requests to node 1 $( [ $(frames '601#') -ge 27 ] && echo '>= 27') answers $( [ $(frames '581#60') -ge 27 ] && echo '>= 27') \
heartbeats $( [ $(frames '701#05') -ge 1 ] && echo yes) RPDO1 cw 0x0F target 500 $( [ $(frames '201#0F00F4010000') -ge 1 ] && echo yes) \
TPDO1 statusword 0x0637 position 500 $( [ $(frames '181#3706F4010000') -ge 1 ] && echo yes)"
echo "== EMCY 0x2310 from node 1"
echo "emcy 1 0x2310" >&3
wait_for "drive 0 faulted" pin_is cia402.0.fault TRUE
sleep 0.2
pins 0 fault-code error-code state controlword enabled
new_messages
echo "RPDO1 with Disable operation after the EMCY: $(sed -n '/ 081#1023/,$p' $T/frames.log | grep -c ' 201#0700')" |
    sed 's/: [1-9][0-9]*$/: yes/'
halcmd setp cia402.0.fault-reset 1; sleep 0.1; halcmd setp cia402.0.fault-reset 0
wait_for "drive 0 enabled again" pin_is cia402.0.enabled TRUE
pins 0 fault-code error-code state
new_messages
echo "== node 2 goes silent"
echo "silence 2" >&3
wait_for "drive 1 faulted" pin_is cia402.1.fault TRUE
pins 1 fault-code ready
new_messages
echo "resume 2" >&3
sleep 0.5
halcmd setp cia402.1.fault-reset 1; sleep 0.1; halcmd setp cia402.1.fault-reset 0
wait_for "drive 1 ready again" pin_is cia402.1.ready TRUE
new_messages
echo "== malformed TPDO1 and heartbeat from node 1"
echo "bad 1 tpdo" >&3; echo "bad 1 tpdo" >&3; echo "bad 1 heartbeat" >&3
wait_for "three bad frames counted" pin_is cia402.0.bad-frames 3
pins 0 fault enabled
new_messages
echo "== node 1 reboots"
echo "reboot 1" >&3
wait_for "drive 0 faulted" pin_is cia402.0.fault TRUE
pins 0 fault-code enabled
new_messages
halcmd setp cia402.0.enable 0; sleep 0.1; halcmd setp cia402.0.enable 1
wait_for "drive 0 set up again and enabled by the enable edge" pin_is cia402.0.enabled TRUE
wait_for "drive 0 back at 0.5" near cia402.0.position-fb 0.5
new_messages
echo "== a set-up write the drive refuses"
halcmd stop
halcmd unload cia402
sed -i 's/^SDO = 2000:01 u32 77/SDO = 2001:00 u32 5/' $T/drives.ini
{ echo "loadrt cia402 config=$T/drives.ini"; echo "addf cia402.read servo"; echo "addf cia402.write servo"; echo start; } | halcmd -f
wait_for "drive 0 faulted" pin_is cia402.0.fault TRUE
pins 0 fault-code ready
new_messages | sed "s|$T/||"
echo "== unload with drive 1 enabled: it is shut down and made pre-operational"
halcmd setp cia402.1.enable 1
wait_for "drive 1 enabled" pin_is cia402.1.enabled TRUE
halcmd stop
halcmd unload all
sleep 0.5
tail -n 2 $T/sim.log
echo quit >&3
wait $sim
echo "simulator exit status $?"

#!/bin/bash
# inner.sh: the part of vm-sim that runs inside the VM (as root, gpio-sim loaded).
log=/tmp/master.log
trap 'realtime stop > /dev/null 2>&1; kill $holder 2> /dev/null' EXIT
CFG=/sys/kernel/config/gpio-sim
# sim_chip NAME LINE...: a gpio-sim chip whose lines carry the given names; prints its chip name.
sim_chip() {
    local c=$CFG/$1 i=0
    shift
    mkdir -p "$c/bank0"
    echo $# > "$c/bank0/num_lines"
    for name in "$@"; do
        mkdir "$c/bank0/line$i"; echo "$name" > "$c/bank0/line$i/name"; i=$((i + 1))
    done
    echo 1 > "$c/live"
}
# line CHIPDIR N: the simulated line's sysfs folder.
line() { echo "/sys/devices/platform/$(cat $CFG/$1/dev_name)/$(cat $CFG/$1/bank0/chip_name)/sim_gpio$2"; }
# level CHIPDIR N: what the driven line reads.
level() { cat "$(line "$1" "$2")/value"; }
# pull CHIPDIR N up|down: the simulated outside world pulls an input.
pull() { echo "pull-$3" > "$(line "$1" "$2")/pull"; }
# info CHIPDIR: gpioinfo's lines of one chip, blanks squeezed.
info() { gpioinfo "$(cat $CFG/$1/bank0/chip_name)" | tail -n +2 | tr -s ' \t' ' '; }
# new_messages: what the realtime master printed since the last call.
seen=0
new_messages() {
    tail -n +$((seen + 1)) "$log" |
        grep -av "^Note\|isolated CPU\|realtime delay\|only display once\|Latency Test"
    seen=$(wc -l < "$log")
}
# pins NAME...: the values of hal_gpio pins NAME-in / NAME-out.
pins() { for p in "$@"; do echo "getp hal_gpio.$p"; done | halcmd -f | paste -sd' '; }

sim_chip a in-a in-b out-a out-b out-c step led
sim_chip b in-c out-d busy
realtime start > "$log" 2>&1 || { cat "$log"; exit 1; }

echo "== a line held by another program"
gpioset --mode=signal "$(cat $CFG/b/bank0/chip_name)" 2=1 &
holder=$!
sleep 0.3
halcmd loadrt hal_gpio outputs=out-d,busy 2> /dev/null
echo "status $?"
new_messages > /tmp/msgs
sed "s/gpiochip[0-9]*/CHIP/" /tmp/msgs
kill $holder; wait $holder 2> /dev/null

echo "== load"
halcmd loadrt hal_gpio inputs=in-a,in-b,in-c outputs=out-a,out-b,out-c,step,led,out-d \
    invert=led reset=step opendrain=out-c pullup=in-b pulldown=in-a biasdisable=out-b || { cat "$log"; exit 1; }
new_messages
halcmd list pin hal_gpio | tr -s ' ' | sed 's/ $//'
halcmd list param hal_gpio | tr -s ' ' | sed 's/ $//'
halcmd list funct hal_gpio | tr -s ' ' | sed 's/ $//'
info a; info b
echo "outputs at load: out-a $(level a 2) out-b $(level a 3) out-c $(level a 4) step $(level a 5) led $(level a 6) out-d $(level b 1)"
echo "inputs before the first read: $(pins in-a-in in-a-in-not in-b-in in-b-in-not)"
pull a 0 up; pull a 1 down; pull b 0 up
{
    echo "loadrt threads name1=fast period1=1000000"
    echo "addf hal_gpio.read fast"; echo "addf hal_gpio.write fast"; echo "addf hal_gpio.reset fast"
    echo "setp hal_gpio.out-a-out 1"; echo "setp hal_gpio.out-d-out 1"; echo "setp hal_gpio.step-out 1"
    echo "setp hal_gpio.reset_ns 300000"; echo start
} | halcmd -f
sleep 0.2
echo "inputs in-a in-a-not in-b in-b-not in-c: $(pins in-a-in in-a-in-not in-b-in in-b-in-not in-c-in)"
pull a 0 down; pull a 1 up; pull b 0 down
sleep 0.2
echo "after the pulls change: $(pins in-a-in in-a-in-not in-b-in in-b-in-not in-c-in)"
echo "reset_ns 300000 at a 1 ms period reads back $(halcmd getp hal_gpio.reset_ns)"
{ echo "setp hal_gpio.led-out 1"; echo "setp hal_gpio.out-b-out 1"; echo "setp hal_gpio.out-a-out 0"; } | halcmd -f
sleep 0.2
halcmd stop
echo "outputs: out-a $(level a 2) out-b $(level a 3) led $(level a 6) out-d $(level b 1); step (reset) $(level a 5)"
{ echo "delf hal_gpio.reset fast"; echo start; } | halcmd -f
sleep 0.2
halcmd stop
echo "step without the reset function: $(level a 5)"
halcmd unload all
new_messages
echo "after unload:"
info a; info b

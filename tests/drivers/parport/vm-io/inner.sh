#!/bin/bash
# inner.sh: the part of vm-io that runs inside the VM (as root, two ports at 0x378 and 0x278).
. "$EMC2_HOME/tests/drivers/vm-lib.sh"
vm_modprobe parport_pc ppdev || exit 1
log=/tmp/master.log
trap 'realtime stop > /dev/null 2>&1' EXIT
realtime start > "$log" 2>&1 || { cat "$log"; exit 1; }
# Linux numbers the ports in its own order: find each one's base address.
base0=$(awk '{print $1}' /proc/sys/dev/parport/parport0/base-addr)
base1=$(awk '{print $1}' /proc/sys/dev/parport/parport1/base-addr)

# reg ADDR [MASK]: the byte at I/O port ADDR (and-ed with MASK) in hex.
reg() {
    local v
    v=$(dd if=/dev/port bs=1 skip=$(($1)) count=1 2> /dev/null | od -An -tu1)
    printf '%02x' $((v & ${2:-0xff}))
}
# data_pins P BYTE: setp lines for parport.P.pin-02-out .. pin-09-out from the bits of BYTE.
data_pins() {
    for bit in 0 1 2 3 4 5 6 7; do
        echo "setp parport.$1.pin-0$((bit + 2))-out $(( ($2 >> bit) & 1 ))"
    done
}
# inputs P PIN...: prints the -in and -in-not pins of port P.
inputs() {
    local p=$1 n values
    shift
    values=($(for n in "$@"; do echo "getp parport.$p.pin-$n-in"; echo "getp parport.$p.pin-$n-in-not"; done | halcmd -f))
    echo -n "port $p inputs (in/in-not):"
    for n in "$@"; do
        echo -n " $n=${values[0]}/${values[1]}"
        values=("${values[@]:2}")
    done
    echo
}
# new_messages: what the realtime master printed since the last call.
seen=0
new_messages() {
    tail -n +$((seen + 1)) "$log" |
        grep -av "^Note\|isolated CPU\|realtime delay\|only display once\|Latency Test"
    seen=$(wc -l < "$log")
}
# names KIND PREFIX: the HAL names of one kind under PREFIX on one line.
names() { halcmd list "$1" "$2" | tr -s ' ' | sed 's/ $//'; }
# cycles: lets the 1 ms thread run a while.
cycles() { sleep 0.1; }

echo "== cfg=\"0 out parport1 in\" (ppdev ioctls)"
halcmd loadrt hal_parport cfg="0 out parport1 in" || { cat "$log"; exit 1; }
new_messages
names pin parport.0; names param parport.0; names pin parport.1
echo "params of parport.1: [$(names param parport.1)]"
names funct parport
inputs 0 10 11 12 13 15
{
    echo "loadrt threads name1=fast period1=1000000"
    echo "addf parport.read-all fast"; echo "addf parport.write-all fast"; echo "addf parport.0.reset fast"
    echo "setp parport.0.pin-01-out-invert 1"; data_pins 0 0xA5
    echo "setp parport.0.pin-14-out 1"; echo "setp parport.0.pin-16-out 1"; echo start
} | halcmd -f
cycles
echo "parport0 data register: $(reg $base0) (pins 2 4 7 9 set: a5)"
echo "parport0 control lines: $(reg $((base0 + 2)) 0x0f) (strobe inverted, 14 and 16 set: 0c)"
inputs 0 10 11 12 13 15
inputs 1 02 03 04 05 06 07 08 09 10 11 12 13 15
echo "parport1 direction bit: $(reg $((base1 + 2)) 0x20)"
halcmd setp parport.0.pin-14-out-invert 1
cycles
echo "parport0 control lines after inverting 14: $(reg $((base0 + 2)) 0x0f)"
# strobe 'O' then 'K' to the emulated printer (nStrobe active low: pin-01-out TRUE with invert)
for ch in 0x4F 0x4B; do
    data_pins 0 $ch | halcmd -f; cycles
    halcmd setp parport.0.pin-01-out 1; cycles
    halcmd setp parport.0.pin-01-out 0; cycles
done
halcmd setp parport.0.reset-time 300000
cycles
echo "reset-time 300000 at a 1 ms period reads back $(halcmd getp parport.0.reset-time)"
{ echo "setp parport.0.reset-time 20000"; data_pins 0 0x21; echo "setp parport.0.pin-01-out-reset 1"; } | halcmd -f
cycles
halcmd setp parport.0.pin-01-out 1
sleep 0.05
halcmd setp parport.0.pin-01-out 0
cycles
halcmd stop
halcmd unload hal_parport
new_messages

echo "== cfg=\"0x378 x 0x3bc\" (raw port I/O)"
halcmd loadrt hal_parport cfg="0x378 x 0x3bc" || { cat "$log"; exit 1; }
new_messages
names pin parport.0; names param parport.0
{
    echo "addf parport.read-all fast"; echo "addf parport.write-all fast"; data_pins 0 0x3C; echo start
} | halcmd -f
cycles
echo "0x378 data register: $(reg 0x378) (3c)"
echo "0x378 control lines: $(reg 0x37a 0x2f) (all released high: 04)"
inputs 0 01 14 16 17
halcmd stop
halcmd unload all
new_messages

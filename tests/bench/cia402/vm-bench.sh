#!/bin/bash
# vm-bench.sh: inside the VM, cia402.read/write time per 1 ms cycle with two simulated drives on vcan0.
T=/tmp/cia402-bench
mkdir -p $T
trap 'realtime stop > /dev/null 2>&1; kill $sim 2> /dev/null' EXIT
ip link add vcan0 type vcan && ip link set vcan0 up || exit 1
mkfifo $T/sim.in
cia402-sim --interface vcan0 --node 1 --node 2 --log $T/sim.log < $T/sim.in > $T/sim.out 2>&1 &
sim=$!
exec 3> $T/sim.in
printf '[CIA402]\nINTERFACE = vcan0\nHEARTBEAT_TIMEOUT_MS = 5000\nPDO_TIMEOUT_MS = 5000\n' > $T/drives.ini
printf '[CIA402_DRIVE_0]\nNODE_ID = 1\nPOSITION_SCALE = 1000\n[CIA402_DRIVE_1]\nNODE_ID = 2\n' >> $T/drives.ini
until grep -q ready $T/sim.out; do sleep 0.1; done
realtime start > $T/master.log 2>&1 || exit 1
{
    echo "loadrt threads name1=servo period1=1000000"
    echo "loadrt cia402 config=$T/drives.ini"
    echo "loadrt sampler depth=20000 cfg=ss"
    echo "net tread cia402.read.time => sampler.0.pin.0"
    echo "net twrite cia402.write.time => sampler.0.pin.1"
    echo "setp sampler.0.enable 0"
    echo "addf cia402.read servo"; echo "addf cia402.write servo"; echo "addf sampler.0 servo"
    echo "setp cia402.0.enable 1"; echo "start"
} | halcmd -f || exit 1
for i in $(seq 1 300); do
    [ "$(halcmd getp cia402.0.enabled)" = TRUE ] && [ "$(halcmd getp cia402.1.ready)" = TRUE ] && break
    sleep 0.1
done
halcmd setp cia402.0.position-cmd 1000
halcmd setp sampler.0.enable 1
timeout 120 halsampler -n 10000 > $T/times
for col in 1 2; do
    name=$([ $col = 1 ] && echo cia402.read || echo cia402.write)
    awk -v c=$col '{ print $c }' $T/times | sort -n | awk -v name="$name" '
        { v[NR] = $1 }
        END { if (NR == 0) { print "cia402: no samples"; exit }
              printf "cia402: %s per 1 ms cycle with socket I/O, 2 drives on vcan0 (VM, TCG emulation), %d cycles: p50 %d ns, p99 %d ns, max %d ns\n",
                     name, NR, v[int(NR * 0.5) + 1], v[int(NR * 0.99) + 1], v[NR] }'
done
echo quit >&3

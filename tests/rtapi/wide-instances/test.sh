#!/bin/bash
# wide-instances: instance numbers above 255 are sessions of their own. A and A+256 (which a
# key with only 8 bits for the instance would fold together) and 7 each run a master; a pin made
# in one is seen in no other, and stopping one leaves the others running. A test harness may
# number instances from its pid (tp-bench does), so these are taken from ours.
a=$((100000 + ($$ % 40000) * 4)); b=$((a + 256)); c=$((a + 512))
cleanup() { for i in $a $b $c; do OPENEMC_INSTANCE=$i realtime stop >/dev/null 2>&1; done; }
trap cleanup EXIT
cleanup
for i in $a $b $c; do
    OPENEMC_INSTANCE=$i realtime start >/dev/null 2>&1 || echo "start failed in the instance $((i - a)) above A"
done
OPENEMC_INSTANCE=$a halcmd loadrt and2 names=in_a
OPENEMC_INSTANCE=$b halcmd loadrt or2 names=in_b
for i in $a $b $c; do
    echo "A+$((i - a)): $(OPENEMC_INSTANCE=$i halcmd -s show pin | awk '{print $5}' | grep -E '^in_.*out$' | tr '\n' ' ')"
done
OPENEMC_INSTANCE=$a realtime stop >/dev/null 2>&1
for i in $b $c; do
    OPENEMC_INSTANCE=$i realtime status >/dev/null 2>&1; echo "A+$((i - a)) after A stopped: status $?"
done
echo "B still has: $(OPENEMC_INSTANCE=$b halcmd -s show pin | awk '{print $5}' | grep -E '^in_.*out$')"
# the Python side computes the same keys as rtapi (the launcher's cleanup relies on it)
PYTHONPATH="$EMC2_HOME/lib/python" python3 -c "
from openemc_launcher.sysv import instance_key
keys = {instance_key(0x48414C32, i) for i in (0, 7, 255, 256, 511, $a, $b, $c, 16777215)}
print('distinct HAL keys:', len(keys), 'of 9')"

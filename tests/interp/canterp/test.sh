#!/bin/bash
# The canterp plugin replays printed canon calls; loaded by bare name, relative and absolute path.
rs274 -p canterp.so -g calls.txt | awk '{$1=""; print}'
s1=${PIPESTATUS[0]}
rs274 -p ./canterp.so -g calls.txt | awk '{$1=""; print}' | tail -n 1
s2=${PIPESTATUS[0]}
rs274 -p "$EMC2_HOME/lib/canterp.so" -g calls.txt | awk '{$1=""; print}' | tail -n 1
s3=${PIPESTATUS[0]}
printf 'BOGUS_CALL(1)\n' > bad.txt
rs274 -p canterp.so -g bad.txt 2>&1 | tail -n 2
s4=${PIPESTATUS[0]}
rm -f bad.txt
echo "status $s1 $s2 $s3 $s4"

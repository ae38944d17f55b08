#!/bin/bash
# lock/unlock levels, status output and which commands each level blocks.
realtime start 2> /dev/null || exit 1
halcmd -k -f 2>&1 <<'HAL' | sed 's|shared memory: .*|shared memory: (used/total)|'
status lock
loadrt and2
newsig a bit
lock tune
status lock
newsig b bit
net a and2.0.in0
loadrt or2
loadusr true
setp and2.0.in1 1
getp and2.0.in1
sets a 1
gets a
lock
status
unlock tune
status lock
start
unlock
status lock
lock frob
status lock
lock all
unlock none
status lock
net a and2.0.in0
list sig
HAL

echo "exit ${PIPESTATUS[0]}"
realtime stop

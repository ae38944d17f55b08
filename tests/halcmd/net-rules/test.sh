#!/bin/bash
# net/linkps/linksp/unlinkp: validation order, type mismatches, writers, I/O pins, value inheritance.
realtime start 2> /dev/null || exit 1
halcmd -k -f 2>&1 <<'HAL'
loadrt and2 count=3
loadrt sum2
loadrt toggle count=3
net a and2.0.out and2.1.in0
net a => and2.2.in0
net a and2.0.out
net a and2.1.out
net b and2.1.out and2.2.out
net f sum2.0.in0 and2.2.in1
net a sum2.0.in1
net c and2.0.in0 nosuch.pin
net d and2.0.out
net and2.0.in1
net and2.0.in1 and2.1.in1
net
net io1 toggle.0.out toggle.1.out and2.0.in1
net io1 and2.2.out
net io2 and2.1.out toggle.2.out
list sig
setp and2.1.in1 TRUE
newsig e bit
sets e TRUE
linkps and2.1.in1 => e
gets e
getp and2.1.in1
setp sum2.0.in1 2.5
net g sum2.0.in1 <= sum2.0.out
gets g
linksp e and2.2.in1
linkps nosuch e
linkps sum2.0.out e
linksp e toggle.0.in
unlinkp and2.2.in1
unlinkp nosuch
getp and2.1.in1
sets e FALSE
unlinkp and2.1.in1
getp and2.1.in1
show pin and2
show sig
HAL
echo "exit $?"
realtime stop

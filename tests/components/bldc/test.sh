#!/bin/bash
# bldc: Hall trapezoidal, open loop sinusoidal, absolute encoder with bit outputs, alignment homing,
# emulated Hall and Gray outputs, bad tag combinations; each case loads one module in the fake HAL.
run() { "$EMC2_HOME/objects/unit/comptest" | grep -v '^hal_init\|^rtapi_app_main'; }
echo "== cfg=h: pattern 25, the first call only starts; sectors and trapezoidal phase values"
run <<'S'
load bldc cfg=h
functs bldc.0
set bldc.0.value 0.5
cycle 1
get bldc.0.in-type bldc.0.out-type
set bldc.0.hall3 1
cycle 1
get bldc.0.rotor-angle bldc.0.phase-angle bldc.0.A-value bldc.0.B-value bldc.0.C-value bldc.0.hall-error
set bldc.0.hall2 1
cycle 1
get bldc.0.rotor-angle bldc.0.A-value bldc.0.B-value bldc.0.C-value bldc.0.hall-error
echo a jump across sectors sets hall-error, a pattern change clears it
set bldc.0.hall1 1
set bldc.0.hall2 0
set bldc.0.hall3 0
cycle 1
get bldc.0.rotor-angle bldc.0.hall-error
set bldc.0.pattern 24
cycle 1
get bldc.0.hall-error
echo pattern 48 is refused and reset to 0
set bldc.0.pattern 48
cycle 1
get bldc.0.pattern
echo rev turns the phase the other way
set bldc.0.rev 1
cycle 1
get bldc.0.out bldc.0.out-dir bldc.0.out-abs
S
echo "== cfg=n: open loop at 1 rev/s, 100 ms periods, sinusoidal values"
run <<'S'
load bldc cfg=n
functs bldc.0
period 100000000
set bldc.0.frequency 1
set bldc.0.value 2
cycle 1
trace 3 bldc.0.phase-angle bldc.0.A-value bldc.0.B-value bldc.0.C-value
S
echo "== cfg=aB: absolute encoder, 512 counts, 4 poles: rotor from counts, bit outputs"
run <<'S'
load bldc cfg=aB
functs bldc.0
set bldc.0.value 1
cycle 1
set bldc.0.rawcounts 64
cycle 1
set bldc.0.rawcounts 64
cycle 1
get bldc.0.rotor-angle bldc.0.phase-angle bldc.0.A-on bldc.0.B-on bldc.0.C-on
set bldc.0.encoder-offset 64
cycle 1
get bldc.0.rotor-angle
S
echo "== cfg=q: alignment homing takes 2.4 s (100 ms periods), then runs as an absolute encoder"
run <<'S'
load bldc cfg=q
functs bldc.0
period 100000000
set bldc.0.value 1
cycle 1
set bldc.0.rawcounts 100
set bldc.0.init 1
trace 25 bldc.0.init-done bldc.0.in-type bldc.0.phase-angle
get bldc.0.offset-measured
S
echo "== cfg=hH and cfg=fF: emulated Hall and Gray outputs"
run <<'S'
load bldc cfg=hH
functs bldc.0
cycle 1
set bldc.0.hall1 1
cycle 1
get bldc.0.hall1-out bldc.0.hall2-out bldc.0.hall3-out
S
run <<'S'
load bldc cfg=fF
functs bldc.0
cycle 1
set bldc.0.C1 1
set bldc.0.C2 1
cycle 1
get bldc.0.rotor-angle bldc.0.C1-out bldc.0.C2-out bldc.0.C4-out bldc.0.C8-out
S
echo "== bad combinations are reported once"
run <<'S'
load bldc cfg=ha,aq,i,hi,ai,fh
functs bldc.0 bldc.1 bldc.2 bldc.3 bldc.4 bldc.5
cycle 3
get bldc.0.in-type bldc.1.in-type bldc.2.in-type bldc.3.in-type bldc.4.in-type bldc.5.in-type
S
echo "== no cfg: the tags are listed and nothing is made"
echo "load bldc" | "$EMC2_HOME/objects/unit/comptest"

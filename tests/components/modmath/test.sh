#!/bin/bash
# modmath: shorter direction on a ring (wrap) and in a plain range, on-target flags.
"$EMC2_HOME/objects/unit/comptest" <<'SCRIPT'
load modmath count=1
show
functs modmath.0
set modmath.0.min-num 1
set modmath.0.max-num 8
echo actual desired -> up down on-target on-target-max on-target-min
set modmath.0.actual 2
set modmath.0.desired 7
cycle
get modmath.0.up modmath.0.down modmath.0.on-target modmath.0.on-target-max modmath.0.on-target-min
set modmath.0.desired 5
cycle
get modmath.0.up modmath.0.down modmath.0.on-target modmath.0.on-target-max modmath.0.on-target-min
set modmath.0.desired 6
cycle
get modmath.0.up modmath.0.down modmath.0.on-target modmath.0.on-target-max modmath.0.on-target-min
set modmath.0.actual 8
set modmath.0.desired 1
cycle
get modmath.0.up modmath.0.down modmath.0.on-target modmath.0.on-target-max modmath.0.on-target-min
set modmath.0.desired 8
cycle
get modmath.0.up modmath.0.down modmath.0.on-target modmath.0.on-target-max modmath.0.on-target-min
echo no wrap
set modmath.0.wrap 0
set modmath.0.desired 1
cycle
get modmath.0.up modmath.0.down modmath.0.on-target modmath.0.on-target-max modmath.0.on-target-min
set modmath.0.actual 1
cycle
get modmath.0.up modmath.0.down modmath.0.on-target modmath.0.on-target-max modmath.0.on-target-min
echo empty range
set modmath.0.max-num 0
cycle
get modmath.0.up modmath.0.down modmath.0.on-target modmath.0.on-target-max modmath.0.on-target-min
SCRIPT

#!/bin/bash
# modmath: shorter direction on a ring (wrap) and in a plain range, on-target flags.
# step PIN=VALUE...: comptest lines setting the pins, running one cycle and reading every output
step() {
    local a
    for a in "$@"; do echo "set modmath.0.${a%%=*} ${a#*=}"; done
    echo cycle
    echo "get modmath.0.up modmath.0.down modmath.0.on-target modmath.0.on-target-max" \
         "modmath.0.on-target-min"
}
# script: the whole comptest session on stdout
script() {
    cat <<'SCRIPT'
load modmath count=1
show
functs modmath.0
set modmath.0.min-num 1
set modmath.0.max-num 8
echo actual desired -> up down on-target on-target-max on-target-min
SCRIPT
    step actual=2 desired=7
    step desired=5
    step desired=6
    step actual=8 desired=1
    step desired=8
    echo "echo no wrap"
    step wrap=0 desired=1
    step actual=1
    echo "echo empty range"
    step max-num=0
}
script | "$EMC2_HOME/objects/unit/comptest"

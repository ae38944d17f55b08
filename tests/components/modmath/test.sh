#!/bin/bash
# modmath: instances from mod_dir=, folding with C's remainder, ties on an even ring, no wrap, empty range.
# step PIN=VALUE...: comptest lines setting the pins, running one cycle and reading every output
step() {
    local a
    for a in "$@"; do echo "set mod-dir.0.${a%%=*} ${a#*=}"; done
    echo cycle
    echo "get mod-dir.0.up mod-dir.0.down mod-dir.0.on-target"
}
# script: the whole comptest session on stdout
script() {
    cat <<'SCRIPT'
echo mod_dir=0 loads without instances
load modmath
show
unload
load modmath mod_dir=1
show
functs mod-dir.0
echo ring 0..15: actual desired -> up down on-target
SCRIPT
    step actual=2 desired=7
    echo "echo half the ring goes up, minus half goes down"
    step desired=10
    step actual=10 desired=2
    step actual=15 desired=0
    step actual=3 desired=3
    echo "echo 17 folds to 1; -1 stays -1 so 15 (16 away) counts as on target"
    step actual=17 desired=1
    step actual=-1 desired=0
    step desired=15
    echo "echo s32 extremes fold without overflow"
    step actual=-2147483648 desired=2147483647
    echo "echo no wrap"
    step wrap=0 actual=15 desired=0
    step wrap=1 min-num=1 max-num=7 actual=1 desired=5
    echo "echo max-num below min-num: plain sign"
    step min-num=5 max-num=4 actual=1 desired=3
    cat <<'SCRIPT'
unload
echo a negative mod_dir is refused
load modmath mod_dir=-1
SCRIPT
}
script | "$EMC2_HOME/objects/unit/comptest"

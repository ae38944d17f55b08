#!/bin/bash
# A user's copy of the userkins template builds out of tree with halcompile and works as kinematics.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed 's/^component userkins /component mykins /; s/"userkins"/"mykins"/g' \
    "$EMC2_HOME/src/hal/components/userkins.comp" > "$tmp/mykins.comp"
cd "$tmp" || exit 1
halcompile --compile mykins.comp > build.log 2>&1 || { cat build.log; exit 1; }
nm -D --defined-only mykins.so | awk '{print $3}' | grep -E '^kin' | sort
RTLIB_DIR=$tmp "$EMC2_HOME/objects/unit/comptest" <<'S'
load mykins
ktype
show
set mykins.in 5
kfwd 1 2 3
kinv 3 1 2 3.5
get mykins.out
S
